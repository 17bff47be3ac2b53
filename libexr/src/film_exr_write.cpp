#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <Imath/half.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "exr_attributes.h"
#include "film_channels.h"
#include "orb/exr/film_exr.h"

namespace orb::exr {
namespace {

Imath::M44f to_imath(const Matrix44& m) {
    Imath::M44f r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = m[i][j];
    return r;
}

Imf::Compression to_imf(ExrCompression compression) {
    switch (compression) {
        case ExrCompression::None: return Imf::NO_COMPRESSION;
        case ExrCompression::Rle: return Imf::RLE_COMPRESSION;
        case ExrCompression::Zips: return Imf::ZIPS_COMPRESSION;
        case ExrCompression::Zip: return Imf::ZIP_COMPRESSION;
        case ExrCompression::Piz: return Imf::PIZ_COMPRESSION;
    }
    return Imf::ZIP_COMPRESSION;
}

struct NamedCompression {
    ExrCompression compression;
    const char* name;
};
constexpr NamedCompression kCompressions[] = {{ExrCompression::Zip, "zip"},
                                               {ExrCompression::Zips, "zips"},
                                               {ExrCompression::Piz, "piz"},
                                               {ExrCompression::Rle, "rle"},
                                               {ExrCompression::None, "none"}};

int checked_int(std::uint64_t value, const char* what) {
    if (value > static_cast<std::uint64_t>(INT_MAX))
        throw std::invalid_argument(std::string(what) + " does not fit the EXR int attribute");
    return static_cast<int>(value);
}

void add_metadata(Imf::Header& header, const render::Film& film, const ExrMetadata& m,
                  const std::vector<Pass>& passes) {
    header.insert(attr::kFilmFormat, Imf::IntAttribute(kFilmFormatVersion));
    header.insert(attr::kSpp, Imf::IntAttribute(checked_int(film.samples_per_pixel, "orb:spp")));
    header.insert(attr::kSampleRanges, Imf::StringAttribute(film.held_ranges().format()));
    header.insert(attr::kTargetSpp, Imf::IntAttribute(checked_int(m.target_spp, "orb:targetSpp")));
    header.insert(attr::kSeed, Imf::StringAttribute(std::to_string(m.seed)));
    header.insert(attr::kMaxDepth, Imf::IntAttribute(m.max_depth));
    header.insert(attr::kMode, Imf::StringAttribute(m.mode));
    header.insert(attr::kSampler, Imf::StringAttribute(m.sampler));
    header.insert(attr::kDevice, Imf::StringAttribute(m.device));
    header.insert(attr::kRenderSeconds, Imf::DoubleAttribute(m.render_seconds));
    header.insert(attr::kSceneFile, Imf::StringAttribute(m.scene_file));
    header.insert(attr::kSceneHash, Imf::StringAttribute(m.scene_hash));
    header.insert(attr::kSceneTime, Imf::DoubleAttribute(m.scene_time));
    header.insert(attr::kVersion, Imf::StringAttribute(m.version));
    header.insert(attr::kPasses, Imf::StringAttribute(format_passes(passes)));
    if (m.frame) {
        if (m.frame->number < INT_MIN || m.frame->number > INT_MAX)
            throw std::invalid_argument("orb:frame does not fit the EXR int attribute");
        header.insert(attr::kFrame, Imf::IntAttribute(static_cast<int>(m.frame->number)));
        header.insert(attr::kFps, Imf::DoubleAttribute(m.frame->fps));
    }
    Imf::addWorldToCamera(header, to_imath(m.world_to_camera));
    Imf::addWorldToNDC(header, to_imath(m.world_to_ndc));
}

// OpenEXR's output stream over a string that is kept from file to file:
// only its first `size` bytes are this file, and it grows (never shrinks)
// without clearing what it will overwrite anyway.
class MemoryStream final : public Imf::OStream {
public:
    MemoryStream(std::string& bytes, std::size_t& size) : Imf::OStream("<memory>"), bytes_(bytes), size_(size) {
        size_ = 0;
    }
    void write(const char c[], int n) override {
        const auto end = position_ + static_cast<std::uint64_t>(n);
        if (end > bytes_.size()) bytes_.resize(std::max<std::uint64_t>(end, 2 * bytes_.size()));
        std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
        position_ = end;
        size_ = std::max<std::size_t>(size_, end);
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }

private:
    std::string& bytes_;
    std::size_t& size_;
    std::uint64_t position_ = 0;
};

// OpenEXR compresses scanline blocks on its own thread pool; once is enough.
void use_all_cores_for_compression() {
    static const bool configured = [] {
        const unsigned cores = std::thread::hardware_concurrency();
        Imf::setGlobalThreadCount(cores > 1 ? static_cast<int>(cores) : 0);
        return true;
    }();
    (void)configured;
}

}  // namespace

const std::vector<std::string>& compression_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const NamedCompression& c : kCompressions) all.push_back(c.name);
        return all;
    }();
    return names;
}

const char* compression_name(ExrCompression compression) {
    for (const NamedCompression& c : kCompressions)
        if (c.compression == compression) return c.name;
    return "?";
}

ExrCompression parse_compression(const std::string& name) {
    for (const NamedCompression& c : kCompressions)
        if (name == c.name) return c.compression;
    std::string choices;
    for (const NamedCompression& c : kCompressions) choices += std::string(choices.empty() ? "" : ", ") + c.name;
    throw std::invalid_argument("unknown EXR compression '" + name + "' (expected " + choices + ")");
}

// Fills an ExrEncoding (a class so that ExrEncoding can name it a friend).
class ExrEncoder {
public:
    static void encode(const render::Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                       ExrEncoding& into);
};

void ExrEncoder::encode(const render::Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                        ExrEncoding& into) {
    if (film.width <= 0 || film.height <= 0) throw std::invalid_argument("cannot write an empty film");
    if (options.passes.empty()) throw std::invalid_argument("no passes to write");
    use_all_cores_for_compression();

    const std::vector<detail::Plane> planes = detail::film_to_planes(film, options.passes, into.planes_);

    Imf::Header header(film.width, film.height);
    header.compression() = to_imf(options.compression);
    // Noisy float mantissas barely compress harder at higher levels, and a
    // checkpoint written while rendering must be quick: the fastest level.
    header.zipCompressionLevel() = 1;
    add_metadata(header, film, metadata, options.passes);

    // OpenEXR's writer does not convert pixel types, so HALF channels get
    // rounded copies, one plane after another like the float planes.
    Imf::FrameBuffer frame;
    const auto width = static_cast<std::size_t>(film.width);
    const std::size_t pixels = width * static_cast<std::size_t>(film.height);
    if (options.half && into.halfs_.size() < planes.size() * pixels) into.halfs_.resize(planes.size() * pixels);
    static_assert(sizeof(Imath::half) == sizeof(std::uint16_t));
    auto* halfs = reinterpret_cast<Imath::half*>(into.halfs_.data());
    for (std::size_t p = 0; p < planes.size(); ++p) {
        const detail::Plane& plane = planes[p];
        if (options.half && !plane.always_float) {
            Imath::half* copy = halfs + p * pixels;
            std::copy(plane.values.begin(), plane.values.end(), copy);
            header.channels().insert(plane.name, Imf::Channel(Imf::HALF));
            frame.insert(plane.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(copy), sizeof(Imath::half),
                                                sizeof(Imath::half) * width));
        } else {
            header.channels().insert(plane.name, Imf::Channel(Imf::FLOAT));
            frame.insert(plane.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(plane.values.data()), sizeof(float),
                                                sizeof(float) * width));
        }
    }

    MemoryStream stream(into.bytes_, into.size_);
    try {
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(film.height);
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("cannot encode the EXR: ") + e.what());
    }
}

void encode_film_exr(const render::Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                     ExrEncoding& into) {
    ExrEncoder::encode(film, metadata, options, into);
}

std::string encode_film_exr(const render::Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options) {
    ExrEncoding encoding;
    encode_film_exr(film, metadata, options, encoding);
    return std::string(encoding.bytes());
}

void write_film_exr(const std::string& path, const render::Film& film, const ExrMetadata& metadata,
                    const ExrWriteOptions& options) {
    const std::string bytes = encode_film_exr(film, metadata, options);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw std::runtime_error(path + ": cannot write EXR");
}

}  // namespace orb::exr
