/* The film's channels and the EXR layers they are stored in: ONE table, read
 * by the kernels (render_pass's film arguments, its per-pixel sums and what it
 * stores), by librender (Film's members, the device buffers, how films of
 * sample slices, resumed runs and devices combine), by libexr (which EXR
 * channels each layer writes and how a sum becomes a pixel value and back,
 * orb-merge's rule for each channel) and by libimage (the layers' names and
 * how to show them). Adding a pass is adding rows here; only what a channel
 * holds per sample is written by hand (film_add_sample in integrator.cl).
 *
 * Like device_types.h this file is one text for both compilers: the OpenCL
 * program starts with it (kernels/CMakeLists.txt lists it first), and the
 * host includes it as C++20, where it also defines the table as constexpr
 * data (namespace orb::film). It includes nothing on the OpenCL side.
 *
 * ORB_FILM_LAYERS(LAYER): the layers ("passes") of orb-render's EXR, in the
 * order they are documented, accepted by --passes and written:
 *   LAYER(Enumerator, name, kind)
 *     kind  how image tools show and compare it: Color (colour-managed),
 *           Normal (unit vectors), Depth (distances), Id (integer labels),
 *           Variance (per-channel variance), Count (a whole number per
 *           pixel, shown as data)
 *
 * ORB_FILM_CHANNELS(CHANNEL): the film's per-pixel buffers, in the order of
 * render_pass's film arguments:
 *   CHANNEL(name, components, clear, accumulate, merge, layer, stored_as, paired, (exr channel names))
 *   The EXR names are one parenthesised argument, so that every callback has
 *   exactly nine parameters: OpenCL C 1.2 has no variadic macros (NVIDIA's
 *   compiler refuses them; PoCL's accepts them).
 *     components  floats per pixel: 3 (a colour or a vector) or 1
 *     clear       the value of a pixel that holds no sample
 *     accumulate  Sum: every sample adds its value;
 *                 CentreRay: written once, by the first pass of a film, from
 *                 the ray through the pixel centre (the same for every sample)
 *     merge       how films of disjoint sample slices combine (passes,
 *                 resumed runs, devices, orb-merge): Sum: added;
 *                 Same: equal in every slice, since it depends on no sample;
 *                 the slice holding the lowest sample index is kept
 *     layer       the LAYER it is written to
 *     stored_as   what the EXR holds for the sum S over n samples:
 *                 Mean: S / n per component;
 *                 UnitVector: the mean normalised (0 where it is 0), with
 *                   the mean's length in one more, always FLOAT, channel, so
 *                   that the sum comes back exactly: S = unit * length * n;
 *                 VarianceOfMean: the variance of the mean of `paired`, of
 *                   which this is the sum of squares:
 *                   (S/n - mean^2) * n/(n-1) / n, clamped at 0; 0 for n = 1;
 *                 Value: the value itself, always FLOAT
 *     paired      the channel a VarianceOfMean is the square of; none otherwise
 *     exr names   the channel names, one per component (UnitVector: then
 *                 the length channel)
 *
 * docs/rendering.md ("The film's channels") says what each one means. */
#ifndef ORB_KERNELS_FILM_CHANNELS_H
#define ORB_KERNELS_FILM_CHANNELS_H

#define ORB_FILM_LAYERS(LAYER)          \
    LAYER(Beauty, beauty, Color)        \
    LAYER(Direct, direct, Color)        \
    LAYER(Indirect, indirect, Color)    \
    LAYER(Emission, emission, Color)    \
    LAYER(Albedo, albedo, Color)        \
    LAYER(Normal, normal, Normal)       \
    LAYER(Depth, depth, Depth)          \
    LAYER(Variance, variance, Variance) \
    LAYER(Id, id, Id)                   \
    LAYER(Background, background, Color) \
    LAYER(Samples, samples, Count)

/* ORB_POST_LAYERS(LAYER): layers that a tool adds to a finished render's EXR
 * from its other layers. No kernel computes them and they hold no sums, so
 * --passes does not take them and --resume and orb-merge drop them (they
 * would no longer match the samples); image tools show and compare them as
 * they do the film's layers:
 *   LAYER(Enumerator, name, kind, (exr channel names))
 *     Denoised  orb-denoise's (and --denoise's) image: the beauty's R,G,B
 *               denoised by Intel Open Image Denoise, guided by albedo and
 *               normal (docs/orb-denoise.md) */
#define ORB_POST_LAYERS(LAYER) LAYER(Denoised, denoised, Color, ("denoised.R", "denoised.G", "denoised.B"))

/* radiance     the sample's radiance L
 * alpha        1 when the camera ray hit a sphere, 0 for a miss
 * direct       light of paths with exactly one diffuse vertex
 * indirect     light of paths with two or more diffuse vertices
 * emission     light of paths with no diffuse vertex (emitters seen directly or through specular chains)
 * albedo       specular tints times the reflectance of the first diffuse vertex
 * normal       world normal at the first hit, facing the camera ray; 0 for a miss
 * depth        distance along the pixel-centre ray to the first hit, +inf for a miss
 * radiance_sq  L^2 per component, for the variance of the pixel mean
 * object_id    the scene index of the sphere the pixel-centre ray hits, -1 for none
 * background   the environment's radiance brought by a camera ray that hits no sphere (0 for one that hits):
 *              the part of `radiance` that `alpha` does not cover, so radiance - background is the
 *              spheres' colour premultiplied by alpha (docs/design/background-and-alpha.md)
 * sample_count the samples the pixel holds: with adaptive sampling pixels hold different counts, and every
 *              Mean, UnitVector and VarianceOfMean of a film that has this channel is over the pixel's own
 *              count instead of the film's samples_per_pixel (docs/design/adaptive-sampling.md) */
#define ORB_FILM_CHANNELS(CHANNEL)                                                                                    \
    CHANNEL(radiance, 3, 0.0f, Sum, Sum, Beauty, Mean, none, ("R", "G", "B"))                                           \
    CHANNEL(alpha, 1, 0.0f, Sum, Sum, Beauty, Mean, none, ("A"))                                                        \
    CHANNEL(direct, 3, 0.0f, Sum, Sum, Direct, Mean, none, ("direct.R", "direct.G", "direct.B"))                        \
    CHANNEL(indirect, 3, 0.0f, Sum, Sum, Indirect, Mean, none, ("indirect.R", "indirect.G", "indirect.B"))              \
    CHANNEL(emission, 3, 0.0f, Sum, Sum, Emission, Mean, none, ("emission.R", "emission.G", "emission.B"))              \
    CHANNEL(albedo, 3, 0.0f, Sum, Sum, Albedo, Mean, none, ("albedo.R", "albedo.G", "albedo.B"))                        \
    CHANNEL(normal, 3, 0.0f, Sum, Sum, Normal, UnitVector, none, ("N.X", "N.Y", "N.Z", "orb.normalLength"))             \
    CHANNEL(depth, 1, ORB_FILM_INFINITY, CentreRay, Same, Depth, Value, none, ("Z"))                                    \
    CHANNEL(radiance_sq, 3, 0.0f, Sum, Sum, Variance, VarianceOfMean, radiance, ("variance.R", "variance.G",           \
            "variance.B"))                                                                                             \
    CHANNEL(object_id, 1, -1.0f, CentreRay, Same, Id, Value, none, ("id"))                                              \
    CHANNEL(background, 3, 0.0f, Sum, Sum, Background, Mean, none, ("background.R", "background.G", "background.B")) \
    CHANNEL(sample_count, 1, 0.0f, Sum, Sum, Samples, Value, none, ("samples.count"))

#ifdef __OPENCL_VERSION__

#define ORB_FILM_INFINITY INFINITY

/* Channel k of the table is bit k of a channel mask. A program computes only
 * the channels in ORB_FILM_CHANNELS_BUILT (the host passes those of the
 * layers a run writes, film::channels_for); the others stay at their clear
 * value. */
#define ORB_FILM_CHANNEL_INDEX(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    FilmChannel_##name,
enum FilmChannelIndex { ORB_FILM_CHANNELS(ORB_FILM_CHANNEL_INDEX) FilmChannel_count };
#undef ORB_FILM_CHANNEL_INDEX

#ifndef ORB_FILM_CHANNELS_BUILT
#define ORB_FILM_CHANNELS_BUILT 0xffffffffu
#endif
#define ORB_FILM_BUILT(name) (((((uint)(ORB_FILM_CHANNELS_BUILT)) >> FilmChannel_##name) & 1u) != 0u)

#else

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

#define ORB_FILM_INFINITY (std::numeric_limits<float>::infinity())

namespace orb::film {

enum class Layer : int {
#define ORB_FILM_LAYER_ENUMERATOR(Enumerator, name, kind) Enumerator,
    ORB_FILM_LAYERS(ORB_FILM_LAYER_ENUMERATOR)
#undef ORB_FILM_LAYER_ENUMERATOR
};

// Named like Film's members (film.radiance is channel Channel::radiance).
enum class Channel : int {
#define ORB_FILM_CHANNEL_ENUMERATOR(name, ...) name,
    ORB_FILM_CHANNELS(ORB_FILM_CHANNEL_ENUMERATOR)
#undef ORB_FILM_CHANNEL_ENUMERATOR
    none = -1,  // the `paired` of a channel that has no pair
};

enum class LayerKind { Color, Normal, Depth, Id, Variance, Count };
enum class Accumulation { Sum, CentreRay };
enum class MergeRule { Sum, Same };
enum class StoredAs { Mean, UnitVector, VarianceOfMean, Value };

struct LayerInfo {
    Layer layer;
    const char* name;  // as --passes spells it
    LayerKind kind;
};

inline constexpr std::size_t kMaxExrNames = 4;

struct ChannelInfo {
    Channel channel;
    const char* name;
    int components;
    float clear;
    Accumulation accumulation;
    MergeRule merge;
    Layer layer;
    StoredAs stored_as;
    Channel paired;
    std::array<const char*, kMaxExrNames> exr_names;
    int exr_name_count;

    // EXR channels a viewer shows (UnitVector's length channel is not one of them).
    int shown_exr_names() const { return stored_as == StoredAs::UnitVector ? components : exr_name_count; }
};

namespace detail {
template <typename... Names>
constexpr std::array<const char*, kMaxExrNames> exr_names(Names... names)
{
    static_assert(sizeof...(Names) >= 1 && sizeof...(Names) <= kMaxExrNames, "1 to 4 EXR channel names per row");
    return {names...};
}
template <typename... Names>
constexpr int exr_name_count(Names...)
{
    return static_cast<int>(sizeof...(Names));
}
}  // namespace detail

inline constexpr std::array kLayers{
#define ORB_FILM_LAYER_INFO(Enumerator, name, kind) LayerInfo{Layer::Enumerator, #name, LayerKind::kind},
    ORB_FILM_LAYERS(ORB_FILM_LAYER_INFO)
#undef ORB_FILM_LAYER_INFO
};

inline constexpr std::array kChannels{
#define ORB_FILM_CHANNEL_INFO(name, components, clear, accumulate, merge, layer, stored_as, paired, names)             \
    ChannelInfo{Channel::name,           #name,                                                                    \
                components,              clear,                                                                    \
                Accumulation::accumulate, MergeRule::merge,                                                        \
                Layer::layer,            StoredAs::stored_as,                                                      \
                Channel::paired,         detail::exr_names names,                                           \
                detail::exr_name_count names},
    ORB_FILM_CHANNELS(ORB_FILM_CHANNEL_INFO)
#undef ORB_FILM_CHANNEL_INFO
};

enum class PostLayer : int {
#define ORB_FILM_POST_LAYER_ENUMERATOR(Enumerator, name, kind, names) Enumerator,
    ORB_POST_LAYERS(ORB_FILM_POST_LAYER_ENUMERATOR)
#undef ORB_FILM_POST_LAYER_ENUMERATOR
};

struct PostLayerInfo {
    PostLayer layer;
    const char* name;
    LayerKind kind;
    std::array<const char*, kMaxExrNames> exr_names;
    int exr_name_count;
};

inline constexpr std::array kPostLayers{
#define ORB_FILM_POST_LAYER_INFO(Enumerator, name, kind, names) \
    PostLayerInfo{PostLayer::Enumerator, #name, LayerKind::kind, detail::exr_names names, detail::exr_name_count names},
    ORB_POST_LAYERS(ORB_FILM_POST_LAYER_INFO)
#undef ORB_FILM_POST_LAYER_INFO
};

constexpr const PostLayerInfo& info(PostLayer layer) { return kPostLayers[static_cast<std::size_t>(layer)]; }

// One name is one layer: a post layer is named like no film layer.
constexpr bool post_layers_are_distinct()
{
    for (const PostLayerInfo& post : kPostLayers)
        for (const LayerInfo& layer : kLayers)
            if (std::string_view(post.name) == layer.name) return false;
    return true;
}
static_assert(post_layers_are_distinct(), "ORB_POST_LAYERS repeats a name of ORB_FILM_LAYERS");

inline constexpr int kChannelCount = static_cast<int>(kChannels.size());
inline constexpr int kLayerCount = static_cast<int>(kLayers.size());

constexpr const ChannelInfo& info(Channel channel) { return kChannels[static_cast<std::size_t>(channel)]; }
constexpr const LayerInfo& info(Layer layer) { return kLayers[static_cast<std::size_t>(layer)]; }

// The rules the table must keep, checked when the host compiles.
constexpr bool table_is_consistent()
{
    for (int i = 0; i < kChannelCount; ++i) {
        const ChannelInfo& c = kChannels[i];
        if (static_cast<int>(c.channel) != i) return false;
        if (c.components != 1 && c.components != 3) return false;
        const int names = c.components + (c.stored_as == StoredAs::UnitVector ? 1 : 0);
        if (c.exr_name_count != names) return false;
        if ((c.stored_as == StoredAs::VarianceOfMean) != (c.paired != Channel::none)) return false;
        if (c.paired != Channel::none) {
            const ChannelInfo& p = info(c.paired);
            if (p.components != c.components || p.stored_as != StoredAs::Mean || p.accumulation != Accumulation::Sum)
                return false;
        }
        // A centre-ray value is the same in every slice; a sum adds up.
        if ((c.accumulation == Accumulation::Sum) != (c.merge == MergeRule::Sum)) return false;
        if (c.accumulation == Accumulation::CentreRay && c.stored_as != StoredAs::Value) return false;
    }
    for (int i = 0; i < kLayerCount; ++i)
        if (static_cast<int>(kLayers[i].layer) != i) return false;
    return true;
}
static_assert(table_is_consistent(), "ORB_FILM_CHANNELS breaks a rule listed at the top of film_channels.h");
static_assert(kChannelCount <= 32, "one bit per channel in a channel mask");

inline constexpr std::uint32_t kAllChannels = (kChannelCount == 32) ? ~0u : (1u << kChannelCount) - 1u;

constexpr std::uint32_t channel_bit(Channel channel) { return 1u << static_cast<int>(channel); }

// The channels that writing `layers` needs: each layer's own, and the
// channel a VarianceOfMean is the square of (its mean enters the variance).
template <typename Layers>
constexpr std::uint32_t channels_for(const Layers& layers)
{
    std::uint32_t mask = 0;
    for (const ChannelInfo& c : kChannels)
        for (Layer layer : layers)
            if (c.layer == layer) mask |= channel_bit(c.channel) | (c.paired != Channel::none ? channel_bit(c.paired) : 0u);
    return mask;
}

}  // namespace orb::film

#endif

#endif /* ORB_KERNELS_FILM_CHANNELS_H */
