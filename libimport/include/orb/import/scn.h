// David Bucciarelli's SmallptGPU scene format (.scn).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/scene.h"

namespace orb {

// Throws InputError("source:line:column: ...") on malformed input.
Scene parse_scn(std::string_view text, const std::string& source);

struct ScnWriteResult {
    std::string text;
    std::vector<std::string> lossy;  // what .scn could not express, one line each
};

// Writes the .scn form; `lossy` lists what was dropped or approximated.
ScnWriteResult write_scn(const Scene& scene);

}  // namespace orb
