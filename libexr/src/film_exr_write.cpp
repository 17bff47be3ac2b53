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

#include <climits>
#include <cstring>
#include <fstream>
#include <list>
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
        case ExrCompression::Zip: return Imf::ZIP_COMPRESSION;
        case ExrCompression::Piz: return Imf::PIZ_COMPRESSION;
    }
    return Imf::ZIP_COMPRESSION;
}

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
    Imf::addWorldToCamera(header, to_imath(m.world_to_camera));
    Imf::addWorldToNDC(header, to_imath(m.world_to_ndc));
}

// OpenEXR's output stream over a growing string: the file is encoded in
// memory and the caller writes it, checking every step (orb::cli::OutputFile).
class MemoryStream final : public Imf::OStream {
public:
    MemoryStream() : Imf::OStream("<memory>") {}
    void write(const char c[], int n) override {
        const auto end = position_ + static_cast<std::uint64_t>(n);
        if (end > bytes_.size()) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
        position_ = end;
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
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

std::string encode_film_exr(const render::Film& film, const ExrMetadata& metadata, const ExrWriteOptions& options) {
    if (film.width <= 0 || film.height <= 0) throw std::invalid_argument("cannot write an empty film");
    if (options.passes.empty()) throw std::invalid_argument("no passes to write");
    use_all_cores_for_compression();

    const std::vector<detail::Plane> planes = detail::film_to_planes(film, options.passes);

    Imf::Header header(film.width, film.height);
    header.compression() = to_imf(options.compression);
    // Noisy float mantissas barely compress harder at higher levels, and a
    // checkpoint written while rendering must be quick: the fastest level.
    header.zipCompressionLevel() = 1;
    add_metadata(header, film, metadata, options.passes);

    // OpenEXR's writer does not convert pixel types, so HALF channels get
    // their own rounded copies (std::list: the buffers must not move).
    Imf::FrameBuffer frame;
    std::list<std::vector<Imath::half>> half_copies;
    const auto width = static_cast<std::size_t>(film.width);
    for (const detail::Plane& plane : planes) {
        if (options.half && !plane.always_float) {
            auto& copy = half_copies.emplace_back(plane.values.begin(), plane.values.end());
            header.channels().insert(plane.name, Imf::Channel(Imf::HALF));
            frame.insert(plane.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(copy.data()), sizeof(Imath::half),
                                                sizeof(Imath::half) * width));
        } else {
            header.channels().insert(plane.name, Imf::Channel(Imf::FLOAT));
            frame.insert(plane.name,
                         Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(plane.values.data())),
                                    sizeof(float), sizeof(float) * width));
        }
    }

    MemoryStream stream;
    try {
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(film.height);
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("cannot encode the EXR: ") + e.what());
    }
    return stream.take();
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
