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
 *   CHANNEL(name, components, clear, accumulate, units, merge, layer, stored_as, paired, (exr channel names))
 *   The EXR names are one parenthesised argument, so that every callback has
 *   exactly ten parameters: OpenCL C 1.2 has no variadic macros (NVIDIA's
 *   compiler refuses them; PoCL's accepts them).
 *     components  values per pixel: 3 (a colour or a vector) or 1
 *     clear       the value of a pixel that holds no sample
 *     accumulate  Sum: every sample adds its value;
 *                 CentreRay: written once, by the first pass of a film, from
 *                 the ray through the pixel centre (the same for every sample)
 *     units       what the film holds per component (docs/design/exact-film-sums.md):
 *                 a Sum channel's sum is a 64-bit integer, so that adding
 *                 samples is exact and gives the same bits in any grouping
 *                 (passes, devices, resumed runs, merged slices):
 *                 Fixed: whole units of 2^-ORB_FILM_FIXED_BITS; a sample's
 *                   value is clamped to [0, ORB_FILM_FIXED_MAX] and rounded
 *                   to the nearest unit once; sums saturate (reported,
 *                   never wrapped: see below);
 *                 SignedFixed: the same units for a value in [-1, 1] (a
 *                   unit vector's component), whose sum cannot overflow
 *                   (below film::kMaxSamplesPerPixel samples per pixel);
 *                 Count: whole numbers (a sample adds 0 or 1), saturating;
 *                 Float: a CentreRay channel's value, a float
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
#ifndef ORB_TABLES_FILM_CHANNELS_H
#define ORB_TABLES_FILM_CHANNELS_H

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
#define ORB_FILM_CHANNELS(CHANNEL)                                                                                                \
    CHANNEL(radiance, 3, 0.0f, Sum, Fixed, Sum, Beauty, Mean, none, ("R", "G", "B"))                                              \
    CHANNEL(alpha, 1, 0.0f, Sum, Count, Sum, Beauty, Mean, none, ("A"))                                                           \
    CHANNEL(direct, 3, 0.0f, Sum, Fixed, Sum, Direct, Mean, none, ("direct.R", "direct.G", "direct.B"))                           \
    CHANNEL(indirect, 3, 0.0f, Sum, Fixed, Sum, Indirect, Mean, none, ("indirect.R", "indirect.G", "indirect.B"))                 \
    CHANNEL(emission, 3, 0.0f, Sum, Fixed, Sum, Emission, Mean, none, ("emission.R", "emission.G", "emission.B"))                 \
    CHANNEL(albedo, 3, 0.0f, Sum, Fixed, Sum, Albedo, Mean, none, ("albedo.R", "albedo.G", "albedo.B"))                           \
    CHANNEL(normal, 3, 0.0f, Sum, SignedFixed, Sum, Normal, UnitVector, none, ("N.X", "N.Y", "N.Z", "orb.normalLength"))          \
    CHANNEL(depth, 1, ORB_FILM_INFINITY, CentreRay, Float, Same, Depth, Value, none, ("Z"))                                       \
    CHANNEL(radiance_sq, 3, 0.0f, Sum, Fixed, Sum, Variance, VarianceOfMean, radiance, ("variance.R", "variance.G", "variance.B")) \
    CHANNEL(object_id, 1, -1.0f, CentreRay, Float, Same, Id, Value, none, ("id"))                                                 \
    CHANNEL(background, 3, 0.0f, Sum, Fixed, Sum, Background, Mean, none, ("background.R", "background.G", "background.B"))       \
    CHANNEL(sample_count, 1, 0.0f, Sum, Count, Sum, Samples, Value, none, ("samples.count"))

/* The units of Fixed and SignedFixed sums: 2^-24, so that a sample is
 * rounded by at most 2^-25 (3e-8) and a pixel's sum holds up to 2^62 units,
 * 2^38 (2.7e11), within the documented range (docs/design/exact-film-sums.md
 * says why 24). A sample's Fixed value is clamped to ORB_FILM_FIXED_MAX
 * (2^38), which converts to 2^62 units: a sum at or above that may hold a
 * clamped sample and is reported (film::saturated_sums), and additions stop
 * at the largest int64 instead of wrapping. A pixel holds at most
 * film::kMaxSamplesPerPixel samples (2^39), below which a SignedFixed sum
 * of values in [-1, 1] cannot overflow. */
#define ORB_FILM_FIXED_BITS 24
#define ORB_FILM_FIXED_MAX 274877906944.0f

#ifdef __OPENCL_VERSION__

#define ORB_FILM_INFINITY INFINITY

/* Channel k of the table is bit k of a channel mask. A program computes only
 * the channels in ORB_FILM_CHANNELS_BUILT (the host passes those of the
 * layers a run writes, film::channels_for); the others stay at their clear
 * value. */
#define ORB_FILM_CHANNEL_INDEX(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    FilmChannel_##name,
enum FilmChannelIndex { ORB_FILM_CHANNELS(ORB_FILM_CHANNEL_INDEX) FilmChannel_count };
#undef ORB_FILM_CHANNEL_INDEX

#ifndef ORB_FILM_CHANNELS_BUILT
#define ORB_FILM_CHANNELS_BUILT 0xffffffffu
#endif
#define ORB_FILM_BUILT(name) (((((uint)(ORB_FILM_CHANNELS_BUILT)) >> FilmChannel_##name) & 1u) != 0u)

/* A channel's buffer element by its `accumulate` column: a Sum channel's
 * sums are 64-bit integers, a CentreRay channel's values floats. */
#define ORB_FILM_ELEMENT_Sum long
#define ORB_FILM_ELEMENT_CentreRay float

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
enum class Units { Fixed, SignedFixed, Count, Float };
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
    Units units;
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
#define ORB_FILM_CHANNEL_INFO(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ChannelInfo{Channel::name,            #name,                                                                   \
                components,               clear,                                                                   \
                Accumulation::accumulate, Units::units,                                                            \
                MergeRule::merge,         Layer::layer,                                                            \
                StoredAs::stored_as,      Channel::paired,                                                         \
                detail::exr_names names,  detail::exr_name_count names},
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
            // A sum of squares in the units of its channel's sum.
            if (p.units != Units::Fixed || c.units != Units::Fixed) return false;
        }
        // A centre-ray value is the same in every slice; a sum adds up, in integer units.
        if ((c.accumulation == Accumulation::Sum) != (c.merge == MergeRule::Sum)) return false;
        if ((c.accumulation == Accumulation::Sum) != (c.units != Units::Float)) return false;
        if (c.accumulation == Accumulation::Sum && c.clear != 0.0f) return false;  // a sum of no samples
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

// A Sum channel's sum: a whole number of units (the `units` column).
using Sum = std::int64_t;

// The value of one unit of a sum: 2^-ORB_FILM_FIXED_BITS for Fixed and
// SignedFixed, 1 for Count (and for a Float channel, which holds values).
constexpr double unit_value(Units units)
{
    return units == Units::Fixed || units == Units::SignedFixed ? 1.0 / static_cast<double>(1ull << ORB_FILM_FIXED_BITS)
                                                                : 1.0;
}

// Units a Fixed sum reaches only past the documented range (a sample at
// ORB_FILM_FIXED_MAX converts to this many): a sum at or above it may have
// been clamped, and is reported (film::saturated_sums).
inline constexpr Sum kSumRangeEnd = Sum{1} << 62;

// Bytes of one entry of a channel's buffer (a sum or a float), and of one pixel.
constexpr std::size_t entry_bytes(const ChannelInfo& c)
{
    return c.accumulation == Accumulation::Sum ? sizeof(Sum) : sizeof(float);
}
constexpr std::size_t pixel_bytes(const ChannelInfo& c) { return entry_bytes(c) * static_cast<std::size_t>(c.components); }

// The most samples a pixel may hold: a SignedFixed sum of values in
// [-1, 1] stays below 2^63 units up to here.
inline constexpr std::uint64_t kMaxSamplesPerPixel = std::uint64_t{1} << 39;

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

#endif /* ORB_TABLES_FILM_CHANNELS_H */
