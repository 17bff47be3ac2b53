// OpenEXR compresses and decompresses blocks on its own thread pool, which
// has no threads until it is given some: without them a 1920x1080 film of
// a few layers took seconds to read or write on one core.
#pragma once

namespace orb::exr {

// Gives OpenEXR's pool a thread per core of the host (once; later calls
// only read it) and returns that count, the numThreads an Imf file takes.
int use_all_cores_for_codecs();

}  // namespace orb::exr
