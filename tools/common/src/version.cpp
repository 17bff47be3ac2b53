#include "orb/cli/version.h"

#include "build_revision.h"
#include "built_with.h"
#include "orb/cli/paths.h"

namespace orb::cli {

std::string source_revision() { return build::kRevision; }

std::string version_text(const std::string& tool_name) {
    // kBuiltWith is known when CMake configures (tools/common/CMakeLists.txt):
    // the versions of the headers and libraries found then.
    return tool_name + " (Orb) " + version_string() + "\n" + "revision: " + source_revision() + "\n" +
           "built with:\n" + build::kBuiltWith;
}

}  // namespace orb::cli
