// Building the OpenCL program, through a per-device binary cache.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "opencl.h"
#include "slow_build_notice.h"
#include "orb/tables/kernel_features.h"

namespace orb::render {

// The language version and the math every program of the kernels is built
// with. Unsafe math (reassociation, fast division) gave +8% on an H100 and
// nothing measurable on PoCL; the analytic tests pass with it.
inline constexpr const char* kKernelLanguageOptions =
    "-cl-std=CL1.2 -cl-mad-enable -cl-unsafe-math-optimizations";

// Adaptive sampling's decision program (kernels/adaptive.cl) is built with
// exact math: no contraction, no reassociation, correctly rounded division,
// so that it decides as the host's reference does, bit for bit.
inline constexpr const char* kDecisionLanguageOptions = "-cl-std=CL1.2";

// What a program of the kernels is built with, typed: the kernel features
// (orb/tables/kernel_features.h) and NVIDIA's register cap, a compiler
// option rather than a define.
struct ProgramOptions {
    device::KernelFeatures features;
    int nvidia_max_registers = 0;  // -cl-nv-maxrregcount; 0 leaves it to the compiler
};

// The compiler's option string: kKernelLanguageOptions, the features that
// differ from their defaults (kernel_feature_options, in table order), the
// register cap. The development knob ORB_CL_OPTIONS goes after all of them
// (with_development_options in device_renderer.h), so its -D's win.
std::string program_options_text(const ProgramOptions& options);

// The binary cache's key of a program: a 128-bit hash of the source (which
// starts with the features' defaults), the option string (the features that
// differ from them), the device and its driver. A feature that changes
// changes the key.
std::string program_cache_key(const cl::Device& device, const std::string& source, const std::string& options);

// Directory of the binary cache: $XDG_CACHE_HOME/orb, else $HOME/.cache/orb;
// empty if neither variable is set.
std::string binary_cache_dir();

struct ProgramBuild {
    cl::Program program;
    bool loaded_from_cache = false;
    // A build from source: its time so far, still running, for the caller
    // to finish() once the kernel's first launch has run (null when loaded).
    std::unique_ptr<SlowBuildNotice> building;
};

// Builds `source` for `device`. With `use_cache`, first tries a cached binary
// keyed by a hash of source, options, device and driver; a missing, corrupt or
// rejected binary falls back to a build from source, and the cache is
// refreshed (atomically, failures ignored). A failed source build throws
// std::runtime_error carrying the compiler's build log. With
// `show_build_log` (the development knob ORB_SHOW_BUILD_LOG), a source
// build's log goes to stderr. `on_slow_build`, when set, is called once a
// build from source has run for a second (slow_build_notice.h).
ProgramBuild build_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                           const std::string& options, bool use_cache, bool show_build_log = false,
                           const std::function<void()>& on_slow_build = {});

}  // namespace orb::render
