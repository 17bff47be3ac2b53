// Writing a render::Film as one multi-pass OpenEXR file, and reading it back
// for --resume. Channel names, attributes and the resume rules are documented
// in docs/orb-render.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "orb/exr/camera_matrices.h"
#include "orb/exr/passes.h"
#include "orb/render/film.h"

namespace orb::exr {

// Version of the channel layout and attribute meanings below; bumped when a
// change would make a file resume or merge wrongly in another version.
// 2 added orb:sampleRanges; a version 1 file (no ranges) holds the samples
// [0, orb:spp) and is still read.
inline constexpr int kFilmFormatVersion = 2;
inline constexpr int kOldestReadableFilmFormat = 1;

// What a render was made from; stored as orb:* header attributes.
// The sample count and the sample indices are the film's own (orb:spp,
// orb:sampleRanges).
struct ExrMetadata {
    std::uint64_t target_spp = 0;  // orb:targetSpp, where an interrupted render was heading
    std::uint64_t seed = 0;        // orb:seed (a decimal string: 64 bits do not fit an int attribute)
    int max_depth = 0;             // orb:maxDepth
    std::string mode;              // orb:mode, "global" or "direct"
    std::string sampler = "sobol"; // orb:sampler, "sobol" or "independent" (absent: independent, the only one before)
    std::string device;            // orb:device
    double render_seconds = 0;     // orb:renderSeconds, summed over resumed runs
    std::string scene_file;        // orb:sceneFile
    std::string scene_hash;        // orb:sceneHash, orb::scene_content_hash()
    std::string version;           // orb:version
    double scene_time = 0;         // orb:sceneTime, the animation time rendered (--time-at)
    Matrix44 world_to_camera{};    // worldToCamera (standard attribute)
    Matrix44 world_to_ndc{};       // worldToNDC (standard attribute)
};

enum class ExrCompression { None, Zip, Piz };

struct ExrWriteOptions {
    bool half = false;  // HALF for colour layers; Z, id and orb.* stay FLOAT
    std::vector<Pass> passes = all_passes();
    ExrCompression compression = ExrCompression::Zip;
};

// The film as the bytes of an EXR file, encoded in memory so that the caller
// writes them safely (tools use orb::cli::OutputFile). Throws
// std::invalid_argument for an empty film.
std::string encode_film_exr(const render::Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options);

// Writes `path` directly, for tests and simple callers. Throws
// std::runtime_error on I/O errors and std::invalid_argument for an empty film.
void write_film_exr(const std::string& path, const render::Film& film, const ExrMetadata& metadata,
                    const ExrWriteOptions& options);

struct ExrFilm {
    render::Film film;         // sums recovered for the passes present, other channels cleared; sample ranges set
    ExrMetadata metadata;
    std::vector<Pass> passes;  // from orb:passes, every one checked present
    bool half = false;         // some recovered channel is stored as HALF
};

// Reads an orb-render EXR. Throws orb::InputError naming `path` for a missing,
// unreadable, truncated, non-EXR or non-Orb file, or one missing a channel.
ExrFilm read_film_exr(const std::string& path);

// Throws orb::InputError saying why `file` cannot continue to an output with
// `wanted` passes within float rounding (HALF data, a pass it lacks, variance
// without beauty).
void require_resumable(const ExrFilm& file, const std::vector<Pass>& wanted, const std::string& path);

}  // namespace orb::exr
