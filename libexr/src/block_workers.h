// The threads that fill and compress EXR blocks, shared by every encode in
// the process: a frame batch encodes several frames at once (one per writer
// thread of orb-render --frames), and each frame's blocks spread over the
// cores besides. Threads started per encode would put cores × frames
// threads on the cores at once, and the render thread, which must start the
// device's next frame on time, would wait among them; these are one fewer
// than the cores, and each encoding thread works on its own blocks too.
#pragma once

#include <functional>

namespace orb::exr::detail {

// Runs job(index) once for each index of [0, count) on the calling thread
// and on the shared workers (the oldest encode's blocks first); returns once
// all have run. After a job throws, no other job of this call starts, and
// the first error is thrown here.
void run_blocks(int count, const std::function<void(int)>& job);

}  // namespace orb::exr::detail
