// What an EXR at a path is: missing, unreadable, or an orb-render image
// whose header says what it holds. Whether that is the render a command asks
// for is render_request.h's judge_output, which reads the file through this.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "orb/exr/film_exr.h"

namespace orb::exr {

// How closely to look. Both check the header as read_film_exr() does; they
// differ in how they find a file that is cut short or damaged:
//   Structure: every block's offset and size lie inside the file (reads the
//              header, the offset table and the block headers: milliseconds
//              for any size, so a farm can check a whole sequence at once);
//   Pixels:    every block decodes (reads and decompresses the whole image,
//              about a second for a 1920x1080 frame of all passes; catches
//              damage inside a block too). orb-render uses it before it
//              skips or continues a frame.
enum class RenderCheck { Structure, Pixels };

struct RenderStatus {
    bool exists = false;    // a file (or something) is at the path
    bool readable = false;  // an orb-render EXR whose header and blocks pass the check
    std::string reason;     // why not readable: "no such file", "not an OpenEXR file", ...
    std::optional<ExrFilmSummary> summary;  // everything the header says, when readable
};

// Never throws for a bad file; `reason` says what is wrong.
RenderStatus inspect_render(const std::string& path, RenderCheck check = RenderCheck::Structure);

}  // namespace orb::exr
