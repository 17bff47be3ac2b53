// Whether a display image on disk is current: the one rule orb-tonemap's
// --skip-existing follows (and with it orb-farm, which tonemaps through
// orb-tonemap). An image is current only when
//   1. it reads whole (every pixel decodes),
//   2. it carries the record orb-tonemap keeps in what it writes
//      (display_record.h, record_carrier.h), of this orb-tonemap's version,
//   3. it was made with the settings asked for now (display_settings.h), and
//   4. it was made from the file now at the source path (source_identity.h).
// A source that is gone cannot have changed: an image that passes 1-3 is
// current (there is nothing to make it again from). A source that is not a
// file (standard input, a FIFO) has no identity, so nothing can be judged
// current against it.
#pragma once

#include <string>

#include "orb/image/display_settings.h"

namespace orb::image {

struct DisplayImageVerdict {
    enum class Kind {
        Current,      // leave it alone
        Absent,       // no regular file there (or a device, a FIFO, stdout): make it, nothing to say
        Damaged,      // it does not read whole: make it again, and warn (something broke it after it was written)
        Stale,        // it reads, but is not current: make it again
        CannotJudge,  // the source has no identity: make it
    };
    Kind kind = Kind::Absent;
    // Why, for one message line: for Damaged the read error; for Stale and
    // CannotJudge a phrase such as "its source f.0007.exr changed since it was made".
    std::string reason;
};

// Never decodes the source: it looks at the source's metadata and header and
// reads the output whole. `asked` must be resolved as the image would be made
// (display and view defaults filled, format normalised, bits resolved).
DisplayImageVerdict judge_display_image(const std::string& output, const std::string& source,
                                        const DisplaySettings& asked);

}  // namespace orb::image
