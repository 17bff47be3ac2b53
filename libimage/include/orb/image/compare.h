// Comparing one pass of two images: brings both into the comparison space
// and computes every metric orb-diff reports.
//
// Comparison space: colour passes of float (scene-linear) images are compared
// in scene-linear, with HDR-FLIP; colour passes of 8/16-bit (display-encoded)
// images are compared as encoded, with LDR-FLIP. With a display/view, float
// images go through that OCIO view first and LDR-FLIP is used. Normals,
// depth, ids, variance and other data passes are compared as stored, without FLIP.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "orb/image/color_config.h"
#include "orb/image/display_transform.h"
#include "orb/image/flip.h"
#include "orb/image/load.h"
#include "orb/image/metrics.h"
#include "orb/image/passes.h"

namespace orb::image {

struct CompareSettings {
    const ColorConfig* config = nullptr;
    bool through_display = false;   // compare what a viewer sees
    DisplayView view;               // display, view, look: already resolved (input_space is ignored)
    std::string input_space;        // --input-space for float images ("" = scene_linear)
    double ppd = 0;                 // FLIP pixels per degree (0 = default)
    std::vector<Tolerance> thresholds; // for "% of pixels over threshold"
    bool want_heatmap = false;
    // The test image's pass, when it is not the reference's (a denoised
    // layer against a converged beauty); "" = the same pass. Both must be of
    // one kind.
    std::string test_pass;
};

struct PassComparison {
    std::string pass;
    PassKind kind = PassKind::Data;
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::string space;              // "scene-linear", "display-encoded", "display: sRGB / Standard", "data"
    ErrorStats stats;
    std::optional<FlipResult> flip;
    std::vector<double> percent_over;  // parallel to CompareSettings::thresholds
    std::optional<Image> heatmap;
};

// Throws InputError (sizes differ, mixed display/scene inputs without a view, ...)
// and PassMissing when either image lacks the pass.
PassComparison compare_pass(const LoadedImage& reference, const LoadedImage& test, const std::string& pass,
                            const CompareSettings& settings);

}  // namespace orb::image
