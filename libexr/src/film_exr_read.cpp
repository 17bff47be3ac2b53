#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTestFile.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <utility>

#include "exr_attributes.h"
#include "film_channels.h"
#include "orb/exr/film_exr.h"
#include "orb/exr/codec_threads.h"
#include "orb/scene/error.h"
#include "orb/tables/render_names.h"

namespace orb::exr {
namespace {

// Guards the allocation below against a hostile header; 2^28 pixels is far
// beyond any image Orb renders in one piece.
constexpr long long kMaxPixels = 1LL << 28;

[[noreturn]] void fail(const std::string& path, const std::string& message) {
    throw InputError(path + ": " + message);
}

std::string format_names(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ",") + name;
    return text;
}

template <typename Attribute>
const Attribute& required(const Imf::Header& header, const char* name, const std::string& path) {
    const Attribute* attribute = header.findTypedAttribute<Attribute>(name);
    if (!attribute) fail(path, std::string("missing or mistyped header attribute ") + name);
    return *attribute;
}

Matrix44 from_imath(const Imath::M44f& m) {
    Matrix44 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = m[i][j];
    return r;
}

std::uint64_t parse_seed(const std::string& text, const std::string& path) {
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (text.empty() || used != text.size() || text[0] == '-')
        fail(path, std::string(attr::kSeed) + " is not an unsigned integer: '" + text + "'");
    return value;
}

void check_readable(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
    if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, expected an EXR file");
    std::ifstream probe(path, std::ios::binary);
    if (!probe) fail(path, std::string("cannot open: ") + std::strerror(errno));
    bool tiled = false, deep = false, multipart = false;
    if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multipart)) fail(path, "not an OpenEXR file");
    if (deep) fail(path, "is a deep EXR, not an orb-render image");
}

// The samples the file holds: orb:sampleRanges (format 2 on), which must
// count orb:spp samples; a format 1 file holds the first orb:spp.
SampleRanges read_sample_ranges(const Imf::Header& header, int format, int spp, const std::string& path) {
    if (format < 2) return SampleRanges(SampleRange{0, static_cast<std::uint64_t>(spp)});
    const std::string& text = required<Imf::StringAttribute>(header, attr::kSampleRanges, path).value();
    SampleRanges ranges;
    try {
        ranges = SampleRanges::parse(text);
    } catch (const std::invalid_argument& e) {
        fail(path, std::string(attr::kSampleRanges) + ": " + e.what());
    }
    if (ranges.total() != static_cast<std::uint64_t>(spp))
        fail(path, std::string(attr::kSampleRanges) + " " + text + " holds " + std::to_string(ranges.total()) +
                       " samples per pixel but orb:spp is " + std::to_string(spp));
    return ranges;
}

ExrMetadata read_metadata(const Imf::Header& header, const std::string& path) {
    ExrMetadata m;
    m.target_spp = static_cast<std::uint64_t>(std::max(0, required<Imf::IntAttribute>(header, attr::kTargetSpp, path).value()));
    m.seed = parse_seed(required<Imf::StringAttribute>(header, attr::kSeed, path).value(), path);
    m.max_depth = required<Imf::IntAttribute>(header, attr::kMaxDepth, path).value();
    m.mode = required<Imf::StringAttribute>(header, attr::kMode, path).value();
    if (!device::value_in(device::kIntegratorModeNames, m.mode))
        fail(path, std::string(attr::kMode) + " must be " + device::choices_in(device::kIntegratorModeNames) +
                       ", got '" + m.mode + "'");
    // Files from before there was a choice were rendered with independent numbers.
    const auto* sampler = header.findTypedAttribute<Imf::StringAttribute>(attr::kSampler);
    m.sampler = sampler ? sampler->value() : std::string(device::name_in(device::kSamplerNames, device::SamplerKind::Independent));
    if (!device::value_in(device::kSamplerNames, m.sampler))
        fail(path, std::string(attr::kSampler) + " must be " + device::choices_in(device::kSamplerNames) + ", got '" +
                       m.sampler + "'");
    m.device = required<Imf::StringAttribute>(header, attr::kDevice, path).value();
    m.render_seconds = required<Imf::DoubleAttribute>(header, attr::kRenderSeconds, path).value();
    m.scene_file = required<Imf::StringAttribute>(header, attr::kSceneFile, path).value();
    m.scene_hash = required<Imf::StringAttribute>(header, attr::kSceneHash, path).value();
    m.scene_time = required<Imf::DoubleAttribute>(header, attr::kSceneTime, path).value();
    m.version = required<Imf::StringAttribute>(header, attr::kVersion, path).value();
    if (!Imf::hasWorldToCamera(header)) fail(path, "missing header attribute worldToCamera");
    if (!Imf::hasWorldToNDC(header)) fail(path, "missing header attribute worldToNDC");
    m.world_to_camera = from_imath(Imf::worldToCamera(header));
    m.world_to_ndc = from_imath(Imf::worldToNDC(header));
    if (const auto* seen = header.findTypedAttribute<Imf::IntAttribute>(attr::kEnvironmentSeen))
        m.environment_seen = seen->value() != 0;
    for (auto [name, value] : {std::pair{attr::kNoiseThreshold, &m.noise_threshold}, std::pair{attr::kTargetError, &m.target_error}})
        if (const auto* given = header.findTypedAttribute<Imf::DoubleAttribute>(name)) {
            if (!(given->value() > 0) || !std::isfinite(given->value()))
                fail(path, std::string(name) + " must be a positive number, got " + std::to_string(given->value()));
            *value = given->value();
        }
    if (const auto* stop = header.findTypedAttribute<Imf::StringAttribute>(attr::kAdaptiveStop)) {
        m.adaptive_stop = parse_adaptive_stop(stop->value());
        if (!m.adaptive_stop)
            fail(path, std::string(attr::kAdaptiveStop) + " must be noise or error, got '" + stop->value() + "'");
    }
    if (const auto* kernel = header.findTypedAttribute<Imf::StringAttribute>(attr::kKernel)) m.kernel = kernel->value();
    if (const auto* frame = header.findTypedAttribute<Imf::IntAttribute>(attr::kFrame)) {
        const auto& fps = required<Imf::DoubleAttribute>(header, attr::kFps, path);
        m.frame = FrameInfo{frame->value(), fps.value()};
    }
    return m;
}

// Everything the header says, checked: an orb-render image of a format this
// Orb reads, a plausible size, consistent sample ranges.
ExrFilmSummary read_summary(const Imf::Header& header, const std::string& path) {
    const auto* spp = header.findTypedAttribute<Imf::IntAttribute>(attr::kSpp);
    if (!spp)
        fail(path, "not an orb-render image (no orb:spp header attribute); --resume needs an EXR written by orb-render");
    const auto& format = required<Imf::IntAttribute>(header, attr::kFilmFormat, path);
    if (format.value() < kOldestReadableFilmFormat || format.value() > kFilmFormatVersion)
        fail(path, "film format " + std::to_string(format.value()) + " is not one this Orb reads (" +
                       std::to_string(kOldestReadableFilmFormat) + " to " + std::to_string(kFilmFormatVersion) + ")");
    if (spp->value() < 1) fail(path, "orb:spp must be at least 1, got " + std::to_string(spp->value()));

    ExrFilmSummary summary;
    summary.sample_ranges = read_sample_ranges(header, format.value(), spp->value(), path);
    summary.samples_per_pixel = static_cast<std::uint64_t>(spp->value());
    const Imath::Box2i window = header.dataWindow();
    if (window != header.displayWindow() || window.min.x != 0 || window.min.y != 0)
        fail(path, "data window differs from the display window at the origin; not an orb-render image");
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    if (width < 1 || height < 1 || width * height > kMaxPixels) fail(path, "implausible image size");
    summary.width = static_cast<int>(width);
    summary.height = static_cast<int>(height);
    summary.metadata = read_metadata(header, path);
    try {
        summary.passes = parse_passes(required<Imf::StringAttribute>(header, attr::kPasses, path).value());
    } catch (const std::invalid_argument& e) {
        fail(path, std::string(attr::kPasses) + ": " + e.what());
    }
    for (Pass pass : summary.passes)
        for (const std::string& name : pass_channels(pass)) {
            const Imf::Channel* channel = header.channels().findChannel(name);
            if (channel && channel->type == Imf::HALF) summary.half = true;
        }
    if (const auto* exact = header.findTypedAttribute<Imf::IntAttribute>(attr::kExactSums)) {
        if (exact->value() != kExactSumsEncoding)
            fail(path, std::string(attr::kExactSums) + " " + std::to_string(exact->value()) +
                           " is an encoding of exact sums this Orb does not read (" +
                           std::to_string(kExactSumsEncoding) + "); a later Orb wrote it");
        summary.exact_sums = true;
    }
    return summary;
}

}  // namespace

ExrFilmSummary read_film_exr_header(const std::string& path) {
    check_readable(path);
    try {
        Imf::InputFile file(path.c_str(), use_all_cores_for_codecs());
        ExrFilmSummary summary = read_summary(file.header(), path);
        if (!file.isComplete()) fail(path, "truncated EXR (some scanlines are missing)");
        return summary;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, std::string("unreadable or truncated EXR: ") + e.what());
    }
}

ExrFilmSummary read_film_exr_summary(const std::string& path) {
    check_readable(path);
    try {
        Imf::InputFile file(path.c_str(), use_all_cores_for_codecs());
        ExrFilmSummary summary = read_summary(file.header(), path);
        if (!file.isComplete()) fail(path, "truncated EXR (some scanlines are missing)");
        // isComplete() only sees the offset table: a file cut short or
        // damaged inside shows when its blocks are decoded. One channel's
        // slice is enough for OpenEXR to decode every block.
        const Imf::ChannelList& channels = file.header().channels();
        if (channels.begin() == channels.end()) fail(path, "has no channels");
        const Imath::Box2i window = file.header().dataWindow();
        std::vector<float> values(static_cast<std::size_t>(summary.width) * summary.height);
        Imf::FrameBuffer frame;
        frame.insert(channels.begin().name(),
                     Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                sizeof(float) * static_cast<std::size_t>(summary.width)));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return summary;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, std::string("unreadable or truncated EXR: ") + e.what());
    }
}

ExrFilm read_film_exr(const std::string& path) {
    check_readable(path);
    try {
        Imf::InputFile file(path.c_str(), use_all_cores_for_codecs());
        const Imf::Header& header = file.header();
        const ExrFilmSummary summary = read_summary(header, path);
        const long long width = summary.width, height = summary.height;
        const Imath::Box2i window = header.dataWindow();

        ExrFilm result;
        result.metadata = summary.metadata;
        result.passes = summary.passes;
        result.exact = summary.exact_sums;

        // Every channel the listed passes need, read as FLOAT whatever it is
        // stored as, and their exact sums as UINT.
        detail::ReadPlanes planes;
        Imf::FrameBuffer frame;
        const std::size_t pixels = static_cast<std::size_t>(width * height);
        const std::size_t row = static_cast<std::size_t>(width);
        const auto find = [&](const std::string& name, Pass pass) {
            const Imf::Channel* channel = header.channels().findChannel(name);
            if (!channel) fail(path, "channel " + name + " of pass " + pass_name(pass) + " is missing");
            if (channel->xSampling != 1 || channel->ySampling != 1) fail(path, "channel " + name + " is subsampled");
            return channel;
        };
        for (Pass pass : result.passes) {
            std::vector<std::string> names = pass_channels(pass);
            for (const auto& helper : pass_resume_channels(pass)) names.push_back(helper);
            for (const std::string& name : names) {
                const Imf::Channel* channel = find(name, pass);
                if (channel->type == Imf::HALF) result.half = true;
                if (channel->type == Imf::UINT) fail(path, "channel " + name + " is UINT, expected FLOAT or HALF");
                auto& values = planes.values[name];
                values.assign(pixels, 0.0f);
                frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                              sizeof(float) * row));
            }
            if (!result.exact) continue;
            for (const std::string& name : pass_exact_sum_channels(pass)) {
                if (find(name, pass)->type != Imf::UINT) fail(path, "channel " + name + " is not UINT");
                auto& halves = planes.exact[name];
                halves.assign(pixels, 0u);
                frame.insert(name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(halves.data()),
                                              sizeof(std::uint32_t), sizeof(std::uint32_t) * row));
            }
        }
        if (!file.isComplete()) fail(path, "truncated EXR (some scanlines are missing)");
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);

        Film& film = result.film;
        film.resize(static_cast<int>(width), static_cast<int>(height));
        film.samples_per_pixel = summary.samples_per_pixel;
        film.sample_ranges = summary.sample_ranges;
        try {
            detail::planes_to_film(planes, detail::PlaneSet{result.passes, result.exact}, film);
        } catch (const std::invalid_argument& e) {
            fail(path, e.what());
        }
        return result;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, std::string("unreadable or truncated EXR: ") + e.what());
    }
}

void require_resumable(const ExrFilm& file, const std::vector<Pass>& wanted, const std::string& path) {
    if (file.half)
        fail(path, "was written with --half; resuming within float rounding needs FLOAT channels (render without --half to resume)");
    for (Pass pass : wanted)
        // A file without per-pixel counts holds orb:spp samples in every pixel (planes_to_film fills them in).
        if (!contains(file.passes, pass) && pass != film::Layer::Samples)
            fail(path, std::string("has no ") + pass_name(pass) + " pass to continue (it holds " +
                           format_passes(file.passes) + ")");
    // A variance is continued from its sum of squares, which needs the mean it is the variance of.
    for (Pass pass : wanted)
        for (const film::ChannelInfo* channel : pass_film_channels(pass)) {
            if (channel->stored_as != film::StoredAs::VarianceOfMean) continue;
            const Pass needed = film::info(channel->paired).layer;
            if (!contains(file.passes, needed))
                fail(path, std::string("the ") + pass_name(pass) + " pass cannot be continued without the " +
                               pass_name(needed) + " pass (" + format_names(pass_channels(needed)) +
                               ") in the same file");
        }
}

}  // namespace orb::exr
