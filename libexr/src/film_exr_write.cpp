#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <Imath/half.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <thread>
#include <variant>

#include "block_workers.h"
#include "exr_header_attributes.h"
#include "exr_scanline_writer.h"
#include "film_channels.h"
#include "orb/exr/film_exr.h"
#include "orb/exr/codec_threads.h"

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


void add_attributes(Imf::Header& header, const std::vector<detail::HeaderAttribute>& attributes) {
    for (const detail::HeaderAttribute& a : attributes) {
        if (const int* value = std::get_if<int>(&a.value)) {
            header.insert(a.name, Imf::IntAttribute(*value));
        } else if (const double* value = std::get_if<double>(&a.value)) {
            header.insert(a.name, Imf::DoubleAttribute(*value));
        } else if (const std::string* value = std::get_if<std::string>(&a.value)) {
            header.insert(a.name, Imf::StringAttribute(*value));
        } else {
            header.insert(a.name, Imf::M44fAttribute(to_imath(std::get<Matrix44>(a.value))));
        }
    }
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

// Fills every pixel of `planes` on every core: a post layer is computed from
// the whole image before any block is written.
void fill_all_planes(const Film& film, const detail::PlaneSet& set, const std::vector<detail::Plane>& planes) {
    const auto width = static_cast<std::size_t>(film.width);
    const auto rows = static_cast<std::size_t>(film.height);
    const std::size_t parts = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, rows);
    detail::run_blocks(static_cast<int>(parts), [&](int part) {
        const auto p = static_cast<std::size_t>(part);
        detail::fill_planes(film, set, planes, rows * p / parts * width, rows * (p + 1) / parts * width);
    });
}

}  // namespace

const StoredImage::Channel* StoredImage::find(std::string_view name) const {
    for (const Channel& channel : channels_)
        if (channel.name == name) return &channel;
    return nullptr;
}

float StoredImage::value(const Channel& channel, std::size_t i) {
    const float v = channel.values[i];
    return channel.half ? static_cast<float>(Imath::half(v)) : v;
}

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

const char* adaptive_stop_name(AdaptiveStop stop) { return stop == AdaptiveStop::Noise ? "noise" : "error"; }

std::optional<AdaptiveStop> parse_adaptive_stop(const std::string& name) {
    if (name == "noise") return AdaptiveStop::Noise;
    if (name == "error") return AdaptiveStop::Error;
    return std::nullopt;
}

ExrCompression parse_compression(const std::string& name) {
    for (const NamedCompression& c : kCompressions)
        if (name == c.name) return c.compression;
    std::string choices;
    for (const NamedCompression& c : kCompressions) choices += std::string(choices.empty() ? "" : ", ") + c.name;
    throw std::invalid_argument("unknown EXR compression '" + name + "' (expected " + choices + ")");
}

struct ExrEncoding::Buffers {
    std::vector<float> planes;         // the stored values, one plane after another
    std::vector<float> post_planes;    // the post layers' values, the same way
    std::vector<Imath::half> halfs;    // their HALF copies under --half (OpenEXR's C++ writer)
    detail::ScanlineBuffers scanlines;  // the blocks of the scanline writer
};

ExrEncoding::ExrEncoding() : buffers_(std::make_unique<Buffers>()) {}
ExrEncoding::~ExrEncoding() = default;
ExrEncoding::ExrEncoding(ExrEncoding&&) noexcept = default;
ExrEncoding& ExrEncoding::operator=(ExrEncoding&&) noexcept = default;

// Fills an ExrEncoding (a class so that ExrEncoding can name it a friend).
class ExrEncoder {
public:
    static void encode(const Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                       ExrEncoding& into, std::span<const PostLayerPlanes> post);

private:
    static void add_post_layers(const Film& film, bool half, std::span<const PostLayerPlanes> post,
                                std::vector<detail::Plane>& planes, std::vector<float>& storage,
                                std::vector<detail::HeaderAttribute>& attributes);
};

// Computes the post layers from the filled planes and appends their planes
// (laid out in `storage`) and attributes.
void ExrEncoder::add_post_layers(const Film& film, bool half, std::span<const PostLayerPlanes> post,
                                 std::vector<detail::Plane>& planes, std::vector<float>& storage,
                                 std::vector<detail::HeaderAttribute>& attributes) {
    const std::size_t pixels = static_cast<std::size_t>(film.width) * static_cast<std::size_t>(film.height);
    std::size_t post_plane_count = 0;
    for (const PostLayerPlanes& layer : post)
        post_plane_count += static_cast<std::size_t>(film::info(layer.layer).exr_name_count);
    if (storage.size() < post_plane_count * pixels) storage.resize(post_plane_count * pixels);

    std::vector<StoredImage::Channel> channels;
    for (const detail::Plane& plane : planes)
        if (!plane.exact_sum) channels.push_back({plane.name, plane.values, half && !plane.always_float});
    const StoredImage stored(film.width, film.height, std::move(channels));

    std::size_t next = 0;
    for (const PostLayerPlanes& layer : post) {
        const film::PostLayerInfo& info = film::info(layer.layer);
        const auto count = static_cast<std::size_t>(info.exr_name_count);
        std::vector<std::span<float>> channels_out;
        for (std::size_t c = 0; c < count; ++c) channels_out.emplace_back(storage.data() + (next + c) * pixels, pixels);
        layer.compute(stored, channels_out);
        for (std::size_t c = 0; c < count; ++c, ++next) planes.push_back({info.exr_names[c], false, false, channels_out[c]});
        for (const auto& [name, value] : layer.attributes) attributes.push_back({name, value});
    }
}

void ExrEncoder::encode(const Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                        ExrEncoding& into, std::span<const PostLayerPlanes> post) {
    if (film.width <= 0 || film.height <= 0) throw std::invalid_argument("cannot write an empty film");
    if (options.passes.empty()) throw std::invalid_argument("no passes to write");
    if (film.samples_per_pixel == 0) throw std::invalid_argument("the film holds no samples");
    if (options.exact_sums && options.half)
        throw std::invalid_argument("exact sums are written beside FLOAT values only, not with HALF");
    ExrEncoding::Buffers& buffers = *into.buffers_;
    std::vector<detail::HeaderAttribute> attributes = detail::header_attributes(film, metadata, options);
    const detail::PlaneSet set{options.passes, options.exact_sums};
    std::vector<detail::Plane> planes = detail::plane_layout(film, set, buffers.planes);
    const auto width = static_cast<std::size_t>(film.width);
    const std::size_t pixels = width * static_cast<std::size_t>(film.height);
    // Post layers need the whole image first; without them the scanline
    // writer fills each block as it packs it.
    const bool filled = !post.empty();
    if (filled) {
        fill_all_planes(film, set, planes);
        add_post_layers(film, options.half, post, planes, buffers.post_planes, attributes);
    }
    if (detail::scanline_writer_handles(options.compression)) {
        detail::write_scanline_exr(film, set, planes, filled, options.half, options.compression,
                                   attributes, buffers.scanlines, into.bytes_, into.size_);
        return;
    }

    // RLE and PIZ through OpenEXR's C++ writer, which compresses blocks on its thread pool.
    use_all_cores_for_codecs();
    if (!filled) detail::fill_planes(film, set, planes, 0, pixels);
    Imf::Header header(film.width, film.height);
    header.compression() = to_imf(options.compression);
    add_attributes(header, attributes);

    // OpenEXR's writer does not convert pixel types, so HALF channels get
    // rounded copies, one plane after another like the float planes.
    Imf::FrameBuffer frame;
    if (options.half && buffers.halfs.size() < planes.size() * pixels) buffers.halfs.resize(planes.size() * pixels);
    for (std::size_t p = 0; p < planes.size(); ++p) {
        const detail::Plane& plane = planes[p];
        if (plane.exact_sum) {
            header.channels().insert(plane.name, Imf::Channel(Imf::UINT));
            frame.insert(plane.name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(plane.values.data()),
                                                sizeof(std::uint32_t), sizeof(std::uint32_t) * width));
        } else if (options.half && !plane.always_float) {
            Imath::half* copy = buffers.halfs.data() + p * pixels;
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

void encode_film_exr(const Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                     ExrEncoding& into, std::span<const PostLayerPlanes> post) {
    ExrEncoder::encode(film, metadata, options, into, post);
}

std::string encode_film_exr(const Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options,
                            std::span<const PostLayerPlanes> post) {
    ExrEncoding encoding;
    encode_film_exr(film, metadata, options, encoding, post);
    return std::string(encoding.bytes());
}

std::uint64_t encoding_bytes(const std::vector<Pass>& passes, bool exact_sums, std::uint64_t pixels) {
    return detail::plane_count(detail::PlaneSet{passes, exact_sums}) * pixels * sizeof(float);
}

void write_film_exr(const std::string& path, const Film& film, const ExrMetadata& metadata,
                    const ExrWriteOptions& options) {
    const std::string bytes = encode_film_exr(film, metadata, options);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw std::runtime_error(path + ": cannot write EXR");
}

}  // namespace orb::exr
