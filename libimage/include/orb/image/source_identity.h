// What a display image was made from, told apart without decoding it.
//
// A source is identified by its size and modification time in nanoseconds
// (both from one stat of the file, following symbolic links) and, for an
// orb-render EXR, by what its header says it holds: the scene's hash and
// time, the samples taken (orb:spp, orb:sampleRanges), the seed, the mode
// and the depth. Writing a file again (orb-render renames a new file into
// place) changes its modification time, so size and time catch every
// rewrite on a file system that keeps nanoseconds; the header catches a
// render made again within one tick of a coarse clock (FAT, some NFS
// servers, files unpacked from an archive that keeps whole seconds) and lets
// the message say what changed. A content hash would be surer still, but it
// would read every source in full on every run, which is what
// --skip-existing is there to avoid. Copying a source (cp without -p) gives
// it a new time, and so counts as a change: conservative, never stale.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace orb::image {

struct SourceIdentity {
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;  // since the Unix epoch
    // orb-render's header attributes (name, value as text), in a fixed order; empty for other images.
    std::vector<std::pair<std::string, std::string>> render;

    bool operator==(const SourceIdentity&) const = default;
};

struct SourceLookup {
    enum class State {
        File,      // a regular file: `identity` tells it apart
        Missing,   // nothing at that path
        NotAFile,  // standard input ("-"), a FIFO, a device, a folder: it has no identity to record
    };
    State state = State::NotAFile;
    SourceIdentity identity;
};

// Looks at the file's metadata and, for an EXR, its header; never its pixels.
SourceLookup identify_source(const std::string& path);

// The attribute names identify_source reads from an orb-render EXR header.
const std::vector<std::string>& render_identity_attributes();

}  // namespace orb::image
