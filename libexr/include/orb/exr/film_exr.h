// Writing a Film as one multi-pass OpenEXR file, and reading it back
// for --resume. Channel names, attributes and the resume rules are documented
// in docs/orb-render.md.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "orb/exr/camera_matrices.h"
#include "orb/exr/passes.h"
#include "orb/film/film.h"
#include "orb/tables/film_channels.h"
#include "orb/tables/render_names.h"

namespace orb::exr {

// Version of the channel layout and attribute meanings below; bumped when a
// change would make a file resume or merge wrongly in another version.
// 2 added orb:sampleRanges; a version 1 file (no ranges) holds the samples
// [0, orb:spp) and is still read.
inline constexpr int kFilmFormatVersion = 2;
inline constexpr int kOldestReadableFilmFormat = 1;

// The frame of an animation a render is (orb-render --frame/--frames).
struct FrameInfo {
    long number = 0;  // orb:frame
    double fps = 0;   // orb:fps; the scene time is number / fps
    bool operator==(const FrameInfo&) const = default;
};

// What ended an adaptive render before its target samples per pixel.
enum class AdaptiveStop { Noise, Error };
const char* adaptive_stop_name(AdaptiveStop stop);  // "noise", "error"
std::optional<AdaptiveStop> parse_adaptive_stop(const std::string& name);

// What a render was made from; stored as orb:* header attributes.
// The sample count and the sample indices are the film's own (orb:spp,
// orb:sampleRanges).
struct ExrMetadata {
    std::uint64_t target_spp = 0;  // orb:targetSpp, where an interrupted render was heading
    std::uint64_t seed = 0;        // orb:seed (a decimal string: 64 bits do not fit an int attribute)
    int max_depth = 0;             // orb:maxDepth
    std::string mode;              // orb:mode, a name of orb/tables/render_names.h's kIntegratorModeNames
    // orb:sampler, a name of kSamplerNames (absent: independent, the only one before)
    std::string sampler{device::kSamplerNames.front().name};
    std::string device;            // orb:device
    double render_seconds = 0;     // orb:renderSeconds, summed over resumed runs
    std::string scene_file;        // orb:sceneFile
    std::string scene_hash;        // orb:sceneHash, orb::scene_content_hash()
    std::string version;           // orb:version
    double scene_time = 0;         // orb:sceneTime, the animation time rendered (--time-at)
    Matrix44 world_to_camera{};    // worldToCamera (standard attribute)
    Matrix44 world_to_ndc{};       // worldToNDC (standard attribute)
    std::optional<FrameInfo> frame;  // orb:frame and orb:fps, present only for frames of an animation
    // orb:environmentSeen (1 or 0): whether camera rays that miss every sphere
    // see radiance. With 0, RGB is the spheres' colour premultiplied by A;
    // with 1 it holds the environment too where A < 1 (the background layer
    // takes it out). Files without it count as 1.
    bool environment_seen = true;
    // Adaptive sampling (orb-render --noise-threshold, --target-error): what
    // the render stopped on, absent without it; what --resume continues with.
    std::optional<double> noise_threshold;  // orb:noiseThreshold
    std::optional<double> target_error;     // orb:targetError
    // orb:adaptiveStop ("noise" or "error"): the render ended on its
    // adaptive rule, every pixel below the noise threshold or the frame's
    // estimate below the target error, before orb:targetSpp; it is
    // finished (render_request.h). Absent: it did not (yet).
    std::optional<AdaptiveStop> adaptive_stop;
    // orb:kernel: which kernels rendered it (orb/render/kernel_identity.h),
    // so that the samples of different kernels are never combined. Empty:
    // not known (a file an older Orb wrote, or a tool that renders nothing).
    std::string kernel;
};

// Only lossless compressions: a resumed or merged render rebuilds the
// film's sums from the stored values, which must come back as written.
enum class ExrCompression { None, Rle, Zips, Zip, Piz };

const std::vector<std::string>& compression_names();  // "zip", "zips", "piz", "rle", "none"
const char* compression_name(ExrCompression compression);
// Throws std::invalid_argument naming the choices.
ExrCompression parse_compression(const std::string& name);

// The encoding of the exact sums (orb:exactSums): each Sum channel's 64-bit
// sums in their units (film_channels.h) as two UINT channels, orb.sum.NAME.lo
// and .hi (exact_sum_channel_name). A file of a later encoding is refused.
inline constexpr int kExactSumsEncoding = 1;

struct ExrWriteOptions {
    bool half = false;  // HALF for colour layers; Z, id and orb.* stay FLOAT
    std::vector<Pass> passes = image_passes();
    ExrCompression compression = ExrCompression::Zip;
    // The film's exact sums beside its values, so that the file continues
    // (--resume, --skip-existing) and merges (orb-merge) bit for bit as if
    // it had never been written: for every file that may be continued or
    // merged (docs/orb-render.md, "Exact sums"). Not with `half`.
    bool exact_sums = false;
};

// Memory an encoder keeps from one image to the next: a frame loop that
// encodes 1920x1080 frames would otherwise fault in tens of fresh megabytes
// a frame (about as long as encoding them). Not shared between threads.
class ExrEncoding {
public:
    ExrEncoding();
    ~ExrEncoding();
    ExrEncoding(ExrEncoding&&) noexcept;
    ExrEncoding& operator=(ExrEncoding&&) noexcept;

    std::string_view bytes() const { return {bytes_.data(), size_}; }  // the last file encoded

private:
    friend class ExrEncoder;
    struct Buffers;                     // the stored values and blocks (film_exr_write.cpp)
    std::unique_ptr<Buffers> buffers_;
    std::string bytes_;                 // capacity kept; only the first size_ bytes are the file
    std::size_t size_ = 0;
};

// The channels of an image being encoded, as the file will store them: what
// a reader of the file gets back. A post layer is computed from these.
class StoredImage {
public:
    struct Channel {
        std::string_view name;
        std::span<const float> values;  // one per pixel, row-major, top row first
        bool half = false;              // stored as HALF: values() rounds to it
    };
    StoredImage(int width, int height, std::vector<Channel> channels)
        : width_(width), height_(height), channels_(std::move(channels)) {}
    int width() const { return width_; }
    int height() const { return height_; }
    // The channel `name`, or nullptr when the file has none.
    const Channel* find(std::string_view name) const;
    // Pixel `i` of `channel` as a reader of the file gets it back (rounded
    // to HALF where the file holds HALF).
    static float value(const Channel& channel, std::size_t i);

private:
    int width_ = 0;
    int height_ = 0;
    std::vector<Channel> channels_;
};

// A post layer (ORB_POST_LAYERS in film_channels.h, such as `denoised`)
// written by the same encode as the film's layers, so a render that adds
// one encodes its file once. Its channels are stored like the colour
// layers (HALF under --half).
struct PostLayerPlanes {
    film::PostLayer layer = film::PostLayer::Denoised;
    // Fills the layer's channels from the stored image: one span per
    // channel of the layer, in its names' order, each width * height floats,
    // rows from the top (planes of the encoder's own memory, reused frame
    // after frame, so that a layer costs no allocation). What it throws, the
    // encode throws.
    std::function<void(const StoredImage&, std::span<const std::span<float>>)> compute;
    // String header attributes that say how the layer was made (orb:denoised).
    std::vector<std::pair<std::string, std::string>> attributes;
};

// The film as the bytes of an EXR file, encoded in memory so that the caller
// writes them safely (tools use orb::cli::OutputFile), into `into` (its
// bytes() until the next call), with the `post` layers beside the film's.
// Throws std::invalid_argument for an empty film or a post layer of the
// wrong size, std::runtime_error if OpenEXR fails.
void encode_film_exr(const Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                     ExrEncoding& into, std::span<const PostLayerPlanes> post = {});
// The same into fresh memory, for a single image.
std::string encode_film_exr(const Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                            std::span<const PostLayerPlanes> post = {});

// The bytes of the values an encode of `pixels` pixels of these layers
// fills (with their exact sums, when asked) before compressing them: what a
// tool must find room for beside the film (the compressed blocks take about
// as much again at most).
std::uint64_t encoding_bytes(const std::vector<Pass>& passes, bool exact_sums, std::uint64_t pixels);

// Writes `path` directly, for tests and simple callers. Throws
// std::runtime_error on I/O errors and std::invalid_argument for an empty film.
void write_film_exr(const std::string& path, const Film& film, const ExrMetadata& metadata,
                    const ExrWriteOptions& options);

struct ExrFilm {
    Film film;         // sums recovered for the passes present, other channels cleared; sample ranges set
    ExrMetadata metadata;
    std::vector<Pass> passes;  // from orb:passes, every one checked present
    bool half = false;         // some recovered channel is stored as HALF
    // The sums came from the file's exact sums (ExrWriteOptions::exact_sums),
    // checked against its values: continuing or merging it is bit for bit.
    // Otherwise they were rebuilt from its means, within float rounding.
    bool exact = false;
};

// What a tool says of a file it continues or merges without exact sums.
inline constexpr const char* kMeansOnly =
    "holds means only, no exact sums (a finished render, or one an older Orb wrote): its sums are rebuilt "
    "from them, so the result equals an uninterrupted render within float rounding, not bit for bit";

// What read_film_exr() learns from the header, checked the same way, and
// that every block of pixels decodes (a file cut short or damaged inside is
// an error), without keeping the pixels: enough to tell whether a frame is
// finished (--skip-existing).
struct ExrFilmSummary {
    int width = 0;
    int height = 0;
    std::uint64_t samples_per_pixel = 0;  // orb:spp
    SampleRanges sample_ranges;   // orb:sampleRanges
    ExrMetadata metadata;
    std::vector<Pass> passes;
    bool half = false;  // some channel of `passes` is stored as HALF (not resumable within float rounding)
    bool exact_sums = false;  // the file carries its exact sums (orb:exactSums)
};

// Throws orb::InputError as read_film_exr() does, "truncated" included.
ExrFilmSummary read_film_exr_summary(const std::string& path);

// The same header checks without decoding any pixels (milliseconds for any
// size of image); the offset table must be whole, but a file cut short
// inside its last blocks passes. orb::exr::inspect_render (render_status.h)
// adds the check that every block lies inside the file.
ExrFilmSummary read_film_exr_header(const std::string& path);

// Reads an orb-render EXR. Throws orb::InputError naming `path` for a missing,
// unreadable, truncated, non-EXR or non-Orb file, or one missing a channel.
ExrFilm read_film_exr(const std::string& path);

// Throws orb::InputError saying why `file` cannot continue to an output with
// `wanted` passes within float rounding (HALF data, a pass it lacks, variance
// without beauty).
void require_resumable(const ExrFilm& file, const std::vector<Pass>& wanted, const std::string& path);

}  // namespace orb::exr
