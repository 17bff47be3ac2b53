// --legend FILE.png: the image that says what --color-by's colours mean
// (orb/image/legend.h), for every tool that takes --color-by. It is drawn by
// the module <dir of executable>/../lib/orb/orb_legend.so, loaded only when
// a legend is asked for, so that the tools do not link OpenImageIO (as the
// texture decoder, docs/design/texture-decoding.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "orb/cli/output_file.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/sphere_style_options.h"
#include "orb/import/sphere_styling.h"

namespace orb::cli {

class LegendOutput {
public:
    // None without --legend. The file is prepared now, before any work, so
    // an unwritable path is an error (orb::InputError) before the scene is
    // read; naming an input is a usage error. (--legend without --color-by
    // and a name without .png are usage errors of sphere_style_options.)
    static std::optional<LegendOutput> prepare(const SphereStyleArguments& arguments,
                                               const std::vector<NamedPath>& inputs);

    // Draws the legend of `styled` (what apply_sphere_styling returned for
    // the scene that fixes the colours: frame 1 of a trajectory) and writes it.
    // `frames_differ`: a trajectory's later frames take their own range (or
    // categories), which the message then says. Throws orb::InputError
    // when the module cannot be loaded or the file cannot be written.
    void write(const SphereStyleResult& styled, const std::string& source, bool frames_differ = false);

private:
    LegendOutput(OutputFile file, bool horizontal) : file_(std::move(file)), horizontal_(horizontal) {}
    OutputFile file_;
    bool horizontal_ = false;
};

}  // namespace orb::cli
