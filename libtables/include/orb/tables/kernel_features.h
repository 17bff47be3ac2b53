/* The kernels' build-time features: ONE table of the preprocessor symbols
 * that choose what a program of the kernels contains (its traversal, the
 * code a scene needs, tuning constants, development checks). It gives
 *   - the kernels' defaults: every row's "#ifndef NAME / #define NAME default
 *     / #endif", which the host writes at the head of every program
 *     (kernel_feature_defaults() below, prepended by librender's
 *     program_source), since a macro table cannot expand to directives;
 *   - the host's typed struct orb::device::KernelFeatures, one member per
 *     row initialised to its default;
 *   - the build options (kernel_feature_options): "-DNAME=value" for every
 *     member that differs from its default, in table order, so a program
 *     built with default features gets none and the binary cache's key
 *     (librender/src/program_build.cpp, a hash of source and options)
 *     changes with every feature that changes.
 * Kernel files test the symbols (#if NAME) and define no defaults of their
 * own. Adding a feature is adding a row here (docs/design/kernel-features.md,
 * "How the table is used").
 *
 * ORB_KERNEL_FEATURES(FEATURE): FEATURE(NAME, member, Type, default, meaning)
 *   NAME     the symbol the kernels read
 *   member   its KernelFeatures member
 *   Type     Bool (0 or 1; bool on the host), Int (int), Uint (uint32_t,
 *            written with a u suffix), Float (float, written with an f
 *            suffix), Token (a word of OpenCL C pasted as it is, such as an
 *            address space; std::string on the host)
 *   default  as both languages spell it (a Token: the word itself)
 *   meaning  one line, for readers (docs/design/kernel-features.md)
 *
 * Like film_channels.h this file is one text for both compilers: the OpenCL
 * program has it before device_types.h (kernels/CMakeLists.txt), where it
 * only checks the values; the host includes it as C++20. OpenCL C 1.2 has
 * no variadic macros, so every row has exactly five arguments. */
#ifndef ORB_TABLES_KERNEL_FEATURES_H
#define ORB_TABLES_KERNEL_FEATURES_H

#define ORB_KERNEL_FEATURES(FEATURE)                                                                                  \
    FEATURE(ORB_SCENE_SPACE, scene_space, Token, __constant,                                                          \
            "address space of the scene tables: __constant while they fit the constant buffers, else __global")      \
    FEATURE(ORB_SCALAR_TRAVERSAL, scalar_traversal, Bool, 0,                                                          \
            "1 on GPUs: each work-item tests one sphere at a time (intersect.cl); 0: packets of four as float4")      \
    FEATURE(ORB_DRAW_ALL_NUMBERS, draw_all_numbers, Bool, 0,                                                          \
            "1 on GPUs: a vertex draws all its random numbers before branching, so lanes hash together")             \
    FEATURE(ORB_BVH, bvh, Bool, 1, "the tree traversal's code; 0 for a scene without a tree")                         \
    FEATURE(ORB_BVH_LEAF_RUNS, bvh_leaf_runs, Bool, 1,                                                                \
            "a node whose children are all leaves tests their packets at once; off with the scalar traversal")      \
    FEATURE(ORB_WARP_VOTE, warp_vote, Int, 0,                                                                         \
            "speculative traversal's warp vote: 0 none, 1 NVIDIA's PTX vote, 2 every lane votes yes (tests on CPUs)")  \
    FEATURE(ORB_UNIFORM_LIGHTS, uniform_lights, Bool, 0,                                                              \
            "every light has the same power: pick lights uniformly without reading the alias table")                 \
    FEATURE(ORB_MATERIAL_KINDS, material_kinds, Uint, 0xffffffffu,                                                    \
            "bit k: MaterialKind k's code is in the program (material_kinds.h)")                                      \
    FEATURE(ORB_ROUGH_DIELECTRIC, rough_dielectric, Bool, 1, "rough glass's code; 0 when every glass is smooth")      \
    FEATURE(ORB_ENVIRONMENT, environment, Bool, 1, "the environment map's code; 0 for a scene without one")           \
    FEATURE(ORB_SPHERE_COLORS, sphere_colors, Bool, 0,                                                                \
            "1: every sphere's colour is its own (SphereRecord::color), not its material's; 0: the material's")      \
    FEATURE(ORB_CASTER_SHARE, caster_share, Float, 0.25f,                                                             \
            "share of continuations aimed at caustic casters; 0 leaves the aiming code out")                         \
    FEATURE(ORB_SAMPLER_SOBOL, sampler_sobol, Bool, 1, "1: scrambled Sobol points (sampler.cl); 0: independent numbers") \
    FEATURE(ORB_SOBOL_BLOCKS, sobol_blocks, Int, 3, "blocks (camera, scattering events) [0, this) draw Sobol points")  \
    FEATURE(RR_START_EVENT, rr_start_event, Int, 2, "Russian roulette applies from this scattering event on")         \
    FEATURE(RR_THRESHOLD, rr_threshold, Float, 0.25f,                                                                 \
            "a path with at least this throughput survives the roulette for sure")                                  \
    FEATURE(ORB_FILM_CHANNELS_BUILT, film_channels_built, Uint, 0xffffffffu,                                          \
            "bit k: the film channel k is computed (film_channels.h); the others stay at their clear value")          \
    FEATURE(ORB_LANES, lanes, Int, 1,                                                                                 \
            "camera paths per work-item: 1, or 4, 8 or 16 vector lanes on CPUs (lanes.cl)")                         \
    FEATURE(ORB_ACTIVE_PIXELS, active_pixels, Bool, 0,                                                                \
            "adaptive sampling: work-items take their pixels from the list of those still sampling; 0: one a pixel")  \
    FEATURE(ORB_TRACE_KERNEL, trace_kernel, Bool, 0, "the trace_rays kernel (trace_rays.cl, ray casting alone)")      \
    FEATURE(ORB_BVH_CHECK, bvh_check, Bool, 0,                                                                        \
            "development: check every index the traversal reads and printf the first violation")                     \
    FEATURE(ORB_BVH_CHECK_STACK, bvh_check_stack, Int, 0,                                                             \
            "development: the stack limit ORB_BVH_CHECK checks against; 0 is the traversal's own stack size")        \
    FEATURE(ORB_BVH_COUNT, bvh_count, Bool, 0, "development: printf the nodes and leaves each traversal visits")

#ifdef __OPENCL_VERSION__

#ifndef ORB_KERNEL_FEATURE_DEFAULTS
#error "the program lacks the kernel features' defaults: prepend orb::device::kernel_feature_defaults() (librender's program_source does)"
#endif

#else

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace orb::device {

enum class FeatureType { Bool, Int, Uint, Float, Token };

namespace feature_detail {
template <FeatureType>
struct HostType;
template <>
struct HostType<FeatureType::Bool> {
    using type = bool;
};
template <>
struct HostType<FeatureType::Int> {
    using type = int;
};
template <>
struct HostType<FeatureType::Uint> {
    using type = std::uint32_t;
};
template <>
struct HostType<FeatureType::Float> {
    using type = float;
};
template <>
struct HostType<FeatureType::Token> {
    using type = std::string;
};

// A row's default as a host value: the word itself for a Token.
#define ORB_FEATURE_HOST_DEFAULT_Bool(value) ((value) != 0)
#define ORB_FEATURE_HOST_DEFAULT_Int(value) (value)
#define ORB_FEATURE_HOST_DEFAULT_Uint(value) (value)
#define ORB_FEATURE_HOST_DEFAULT_Float(value) (value)
#define ORB_FEATURE_HOST_DEFAULT_Token(value) (#value)

// The value as OpenCL C reads it in a -D option or a #define.
inline std::string opencl_text(bool value) { return value ? "1" : "0"; }
inline std::string opencl_text(int value) { return std::to_string(value); }
inline std::string opencl_text(std::uint32_t value) { return std::to_string(value) + "u"; }
inline std::string opencl_text(float value)
{
    // The shortest text that reads back as the same float, made a floating
    // literal: "0" would be an int, "0f" no literal at all.
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof text, value);
    if (error != std::errc() || !std::isfinite(value))
        throw std::invalid_argument("a kernel feature's float must be finite");
    std::string literal(text, end);
    if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
    return literal + "f";
}
inline std::string opencl_text(const std::string& token)
{
    const bool word = !token.empty() && token.find_first_of(" \t\r\n\"'=\\") == std::string::npos;
    if (!word) throw std::invalid_argument("a kernel feature's token must be one word, got \"" + token + "\"");
    return token;
}
}  // namespace feature_detail

// The features a program is built with; default-constructed, the program
// the kernels give without options.
struct KernelFeatures {
#define ORB_FEATURE_MEMBER(NAME, member, Type, value, meaning)                   \
    feature_detail::HostType<FeatureType::Type>::type member = ORB_FEATURE_HOST_DEFAULT_##Type(value);
    ORB_KERNEL_FEATURES(ORB_FEATURE_MEMBER)
#undef ORB_FEATURE_MEMBER

    bool operator==(const KernelFeatures&) const = default;
};

struct KernelFeatureInfo {
    const char* name;    // the kernels' symbol
    const char* member;  // KernelFeatures' member
    FeatureType type;
    const char* meaning;
};

inline constexpr std::array kKernelFeatures{
#define ORB_FEATURE_INFO(NAME, member, Type, value, meaning) KernelFeatureInfo{#NAME, #member, FeatureType::Type, meaning},
    ORB_KERNEL_FEATURES(ORB_FEATURE_INFO)
#undef ORB_FEATURE_INFO
};

// Calls visit(info, value, base_value) for every row, in table order.
template <typename Visit>
void for_each_kernel_feature(const KernelFeatures& features, const KernelFeatures& base, Visit&& visit)
{
    std::size_t row = 0;
#define ORB_FEATURE_VISIT(NAME, member, Type, value, meaning) \
    visit(kKernelFeatures[row++], features.member, base.member);
    ORB_KERNEL_FEATURES(ORB_FEATURE_VISIT)
#undef ORB_FEATURE_VISIT
}

// "-DNAME=value" for every feature that differs from its default, in table
// order, separated by single spaces ("" for the defaults). Each name at most
// once. Throws std::invalid_argument for a token that is not one word or a
// float that is not finite. With `base`: the features that differ from
// base's, which turn a program built with `base` into one with `features`
// when they follow its options (the development knob ORB_CL_OPTIONS).
inline std::string kernel_feature_options(const KernelFeatures& features, const KernelFeatures& base = {})
{
    std::string options;
    for_each_kernel_feature(features, base, [&](const KernelFeatureInfo& info, const auto& value, const auto& fallback) {
        if (value == fallback) return;
        if (!options.empty()) options += ' ';
        options += std::string("-D") + info.name + "=" + feature_detail::opencl_text(value);
    });
    return options;
}

// The kernels' defaults as OpenCL C, written at the head of every program:
// "#ifndef NAME / #define NAME default / #endif" per row, and
// ORB_KERNEL_FEATURE_DEFAULTS, which kernel_features.h's OpenCL side
// requires.
inline std::string kernel_feature_defaults()
{
    std::string text = "#define ORB_KERNEL_FEATURE_DEFAULTS 1\n";
    for_each_kernel_feature(KernelFeatures{}, KernelFeatures{}, [&](const KernelFeatureInfo& info, const auto& value, const auto&) {
        text += std::string("#ifndef ") + info.name + "\n#define " + info.name + " " +
                feature_detail::opencl_text(value) + "\n#endif\n";
    });
    return text;
}

}  // namespace orb::device

#endif

#endif /* ORB_TABLES_KERNEL_FEATURES_H */
