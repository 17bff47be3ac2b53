#include "orb/exr/environment_map.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfTestFile.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include "orb/exr/codec_threads.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace orb::exr {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw InputError(path + ": " + message); }

void check_readable(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) fail(path, "no such file");
    if (fs::is_directory(path, ec)) fail(path, "is a directory, expected an OpenEXR file");
    std::ifstream probe(path, std::ios::binary);
    if (!probe) fail(path, std::string("cannot open: ") + std::strerror(errno));
    bool tiled = false, deep = false, multipart = false;
    if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multipart))
        fail(path, "not an OpenEXR file (environment maps are read as EXR)");
    if (deep) fail(path, "is a deep EXR; an environment map is a flat RGB image");
}

// The channels that hold the colour: R, G, B, or Y alone (grey).
std::vector<std::string> colour_channels(const Imf::Header& header, const std::string& path) {
    const Imf::ChannelList& channels = header.channels();
    if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B")) return {"R", "G", "B"};
    if (channels.findChannel("Y")) return {"Y", "Y", "Y"};
    std::string names;
    for (auto it = channels.begin(); it != channels.end(); ++it) names += std::string(names.empty() ? "" : ", ") + it.name();
    fail(path, "has no R, G, B (or Y) channels to read as radiance (it has: " + (names.empty() ? "none" : names) + ")");
}

}  // namespace

EnvironmentImage read_environment_exr(const std::string& path) {
    check_readable(path);
    try {
        Imf::InputFile file(path.c_str(), use_all_cores_for_codecs());
        const Imf::Header& header = file.header();
        if (Imf::hasEnvmap(header) && Imf::envmap(header) == Imf::ENVMAP_CUBE)
            fail(path, "is a cube map (envmap attribute); Orb reads latitude-longitude maps");
        const Imath::Box2i window = header.dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (width < 1 || height < 1) fail(path, "has an empty data window");
        if (width * height > kMaxEnvironmentTexels)
            fail(path, "has " + std::to_string(width) + "x" + std::to_string(height) + " texels, more than the " +
                           std::to_string(kMaxEnvironmentTexels) + " Orb accepts for an environment map");
        const std::vector<std::string> names = colour_channels(header, path);
        for (const std::string& name : names) {
            const Imf::Channel* channel = header.channels().findChannel(name);
            if (channel->xSampling != 1 || channel->ySampling != 1)
                fail(path, "channel " + name + " is subsampled; an environment map needs full-resolution RGB");
        }

        EnvironmentImage image;
        image.width = static_cast<int>(width);
        image.height = static_cast<int>(height);
        image.rgb.assign(static_cast<std::size_t>(width * height) * 3, 0.0f);
        // The slices address pixel (x, y) of the data window at
        // base + x * xStride + y * yStride, so the base is shifted back by
        // the window's origin, computed in integers before it becomes a pointer.
        const std::ptrdiff_t x_stride = 3 * sizeof(float), y_stride = x_stride * static_cast<std::ptrdiff_t>(width);
        const std::ptrdiff_t origin = -(static_cast<std::ptrdiff_t>(window.min.x) * x_stride +
                                        static_cast<std::ptrdiff_t>(window.min.y) * y_stride);
        // A frame buffer holds each channel once: grey (Y) is read into R and copied.
        const bool grey = names[0] == names[1];
        Imf::FrameBuffer frame;
        for (int c = 0; c < (grey ? 1 : 3); ++c) {
            char* first = reinterpret_cast<char*>(image.rgb.data() + c);
            frame.insert(names[c], Imf::Slice(Imf::FLOAT, first + origin, x_stride, y_stride));
        }
        if (!file.isComplete()) fail(path, "truncated EXR (some scanlines or tiles are missing)");
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (grey)
            for (std::size_t i = 0; i < image.rgb.size(); i += 3) image.rgb[i + 1] = image.rgb[i + 2] = image.rgb[i];
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, std::string("unreadable or truncated EXR: ") + e.what());
    }
}

void load_environment_map(Scene& scene, const std::string& scene_dir, const std::string& source) {
    Environment& environment = scene.environment;
    if (environment.kind != EnvironmentKind::Map) return;
    const fs::path written(environment.map);
    const std::string resolved = written.is_absolute() ? written.string() : (fs::path(scene_dir) / written).string();
    try {
        environment.image = std::make_shared<const EnvironmentImage>(read_environment_exr(resolved));
    } catch (const InputError& e) {
        throw InputError(source + ": environment.map: " + e.what());
    }
    // The texels' values, with the JSON path of the map.
    validate_scene(scene, source);
}

}  // namespace orb::exr
