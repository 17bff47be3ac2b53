// Development knobs: settings for measuring, tuning and debugging the
// renderer, never needed to render an image. The library reads them only
// from here (RenderConfig::development); the tools fill them in from the
// environment variables named below, in one place at their boundary
// (tools/common: orb/cli/development_knobs.h), so that a script can set one
// without a command-line option for it. docs/design/development-knobs-and-dev.md,
// "The knobs", lists them with examples.
#pragma once

#include <memory>
#include <optional>
#include <string>

namespace orb::render {

// Development code watching each render pass as it is launched (the pass
// capture in dev/): defined in librender/src/pass_observer.h, which only
// code built against librender's internals includes.
class PassObserver;

// A work-group's shape in work-items, x by y.
struct LocalSize {
    unsigned x = 0;
    unsigned y = 0;
    bool operator==(const LocalSize&) const = default;
};

struct DevelopmentKnobs {
    // ORB_KERNEL_DIR (orb-render's --kernel-dir wins over it): read the
    // kernels' source from this folder instead of the embedded copy, to try
    // an edited kernel without rebuilding. "" = the embedded kernels.
    std::string kernel_dir;
    // ORB_CL_OPTIONS: appended, last, to the build options of every program,
    // so that its -D definitions win over the renderer's (variants such as
    // -DORB_SCALAR_TRAVERSAL=1 on a CPU, register caps, debug counters).
    std::string cl_options;
    // ORB_SIMD_LANES: render_pass's camera paths per work-item on CPUs
    // (ORB_LANES), 4, 8 or 16, or 0 for one, as on GPUs. Unset: the
    // device's native float vector width. GPUs always run one.
    std::optional<int> simd_lanes;
    // ORB_LOCAL_SIZE=XxY: render_pass's work-group shape, for tuning
    // (halved while it exceeds what the kernel allows on the device). Unset:
    // 16x8 on GPUs, 8x1 on CPUs, 1x1 with lanes.
    std::optional<LocalSize> local_size;
    // ORB_PASS_SPP: every pass after the first takes this many samples per
    // pixel (fewer where the target or a decision comes sooner) instead of
    // what fits the pass length aimed at: for tests that render one image
    // in passes of other sizes (the image is the same bits). Unset: passes
    // sized from the measured speed.
    std::optional<int> pass_spp;
    // ORB_REFIT_COST_LIMIT: an animation keeps refitting its BVH while the
    // tree's SAH cost stays within this multiple of its built cost, whatever
    // the frames cost (0: never refit); replaces the rule that weighs the
    // refit against a new build (animation_tree.h). Unset: that rule.
    std::optional<double> refit_cost_limit;
    // ORB_SHOW_BUILD_LOG=1: print the compiler's log (remarks, register
    // counts with -cl-nv-verbose) on stderr for every program built from
    // source; a program loaded from the binary cache has none.
    bool show_build_log = false;
    // ORB_DEVICE_DECISIONS: where adaptive sampling decides. 1: on the
    // device wherever it can (a CPU's OpenCL too); 0: on the host, from the
    // film read back (libfilm's reference). Unset: on the device except on
    // CPU devices, whose film is in the host's memory already and whose
    // cores run the host's decision faster (Renderer::decides_on_device).
    std::optional<bool> device_decisions;
    // Not from the environment: development code called around each render
    // pass (dev/pass_capture). Null: none.
    std::shared_ptr<PassObserver> pass_observer;
};

}  // namespace orb::render
