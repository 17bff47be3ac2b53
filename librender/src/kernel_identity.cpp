#include "orb/render/kernel_identity.h"

#include "orb/scene/content_hash.h"
#include "program_source.h"

namespace orb::render {

std::string kernel_identity(const DevelopmentKnobs& knobs) {
    ContentHash hash;
    // Each part's length first, so that text moving from one part to the next changes the hash.
    for (const std::string& part : {program_source(knobs.kernel_dir), decision_program_source(knobs.kernel_dir),
                                    knobs.cl_options}) {
        hash.add_uint32(static_cast<std::uint32_t>(part.size()));
        hash.add(part);
    }
    return hash.hex();
}

}  // namespace orb::render
