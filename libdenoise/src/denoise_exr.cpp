#include "orb/denoise/denoise_exr.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "denoise_inputs.h"
#include "orb/denoise/exr_memory_streams.h"
#include "orb/exr/codec_threads.h"
#include "orb/tables/film_channels.h"
#include "orb/scene/error.h"

namespace orb::denoise {
namespace {

using detail::denoised_names;
using detail::Names;
using detail::names_of;

// Guards the allocations below against a hostile header, as libexr's reader does.
constexpr long long kMaxPixels = 1LL << 28;

// OpenEXR decodes and encodes blocks on this many threads: a 1920x1080 frame
// of the guided layers takes seconds on one.
int codec_threads() { return std::max(1, exr::use_all_cores_for_codecs()); }

// Every channel is kept in 4 bytes a pixel whatever its type, read and
// written back in that type, so the input's values travel bit for bit.
struct Plane {
    std::string name;
    Imf::PixelType type = Imf::FLOAT;
    std::vector<char> bytes;
};

const Plane* find(const std::vector<Plane>& planes, const char* name) {
    for (const Plane& plane : planes)
        if (plane.name == name) return &plane;
    return nullptr;
}

// The layer's three channels interleaved into `out`; every value must be finite.
void interleave(const std::vector<Plane>& planes, const Names& names, int width, const std::string& source,
                const char* layer, float* out) {
    const std::size_t pixels = static_cast<std::size_t>(width) * (planes.front().bytes.size() / 4 / width);
    std::array<const Plane*, 3> channels{};
    for (std::size_t c = 0; c < 3; ++c) {
        channels[c] = find(planes, names[c]);
        if (channels[c]->type == Imf::UINT)
            throw InputError(source + ": channel " + channels[c]->name + " of the " + layer +
                             " layer holds integers (UINT), expected HALF or FLOAT");
    }
    detail::interleave_into(out, pixels, width, names, layer, source, [&](int c, std::size_t i) {
        const Plane& plane = *channels[static_cast<std::size_t>(c)];
        if (plane.type == Imf::FLOAT) {
            float value = 0;
            std::memcpy(&value, plane.bytes.data() + 4 * i, sizeof value);
            return value;
        }
        Imath::half h;
        std::memcpy(&h, plane.bytes.data() + 4 * i, sizeof h);
        return static_cast<float>(h);
    });
}

struct DecodedImage {
    Imf::Header header;
    std::vector<Plane> planes;  // every channel but an old denoised layer's
    int width = 0;
    int height = 0;
    bool had_denoised = false;
};

DecodedImage decode(std::string_view exr, const std::string& source) {
    static constexpr char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
    if (exr.size() < 4 || std::memcmp(exr.data(), kMagic, 4) != 0)
        throw InputError(source + ": not an OpenEXR file (expected an orb-render EXR with beauty, albedo and normal)");
    try {
        MemoryInput stream(exr, source);
        Imf::MultiPartInputFile file(stream, codec_threads());
        if (file.parts() != 1)
            throw InputError(source + ": has " + std::to_string(file.parts()) +
                             " parts; orb-denoise reads single-part EXRs (as orb-render writes)");
        DecodedImage image;
        image.header = file.header(0);
        if (image.header.hasType() && Imf::isDeepData(image.header.type()))
            throw InputError(source + ": is a deep EXR; orb-denoise reads flat images");
        const Imath::Box2i window = image.header.dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (width <= 0 || height <= 0 || width * height > kMaxPixels)
            throw InputError(source + ": a data window of " + std::to_string(width) + "x" + std::to_string(height) +
                             " pixels");
        image.width = static_cast<int>(width);
        image.height = static_cast<int>(height);
        const Names old = denoised_names();
        Imf::FrameBuffer buffer;
        for (auto it = image.header.channels().begin(); it != image.header.channels().end(); ++it) {
            const std::string name = it.name();
            if (std::find(old.begin(), old.end(), name) != old.end()) {
                image.had_denoised = true;
                continue;
            }
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
                throw InputError(source + ": channel " + name + " is subsampled; orb-denoise reads full-resolution channels");
            image.planes.push_back({name, it.channel().type, std::vector<char>(static_cast<std::size_t>(width * height) * 4)});
        }
        for (Plane& plane : image.planes)
            buffer.insert(plane.name, Imf::Slice::Make(plane.type, plane.bytes.data(), window, 4,
                                                        static_cast<std::size_t>(width) * 4));
        Imf::InputPart part(file, 0);
        part.setFrameBuffer(buffer);
        part.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(source + ": not a readable OpenEXR image (" + e.what() + ")");
    }
}

std::string encode(DecodedImage& image, std::span<const float> denoised, const std::string& description) {
    const Names names = denoised_names();
    const Imf::PixelType type = find(image.planes, names_of(film::Channel::radiance)[0])->type;
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    for (int c = 0; c < 3; ++c) {
        Plane plane{names[c], type, std::vector<char>(pixels * 4)};
        for (std::size_t i = 0; i < pixels; ++i) {
            const float value = denoised[3 * i + c];
            if (type == Imf::HALF) {
                const Imath::half h(value);
                std::memcpy(plane.bytes.data() + 4 * i, &h, sizeof h);
            } else {
                std::memcpy(plane.bytes.data() + 4 * i, &value, sizeof value);
            }
        }
        image.planes.push_back(std::move(plane));
    }

    Imf::Header header = image.header;
    // Written as scanlines, whatever the input's layout was.
    if (header.hasTileDescription()) header.erase("tiles");
    if (header.hasType()) header.setType(Imf::SCANLINEIMAGE);
    if (header.lineOrder() == Imf::RANDOM_Y) header.lineOrder() = Imf::INCREASING_Y;
    Imf::ChannelList channels;
    for (const Plane& plane : image.planes) channels.insert(plane.name, Imf::Channel(plane.type));
    header.channels() = channels;
    header.insert(kDenoisedAttribute, Imf::StringAttribute(description));

    const Imath::Box2i window = header.dataWindow();
    Imf::FrameBuffer buffer;
    for (Plane& plane : image.planes)
        buffer.insert(plane.name, Imf::Slice::Make(plane.type, plane.bytes.data(), window, 4,
                                                    static_cast<std::size_t>(image.width) * 4));
    std::string bytes;
    MemoryOutput stream(bytes);
    Imf::OutputFile file(stream, header, codec_threads());
    file.setFrameBuffer(buffer);
    file.writePixels(image.height);
    return bytes;
}

}  // namespace

std::string add_denoised_layer(std::string_view exr, const std::string& source, Denoiser& denoiser) {
    DecodedImage image = decode(exr, source);
    detail::require_layers([&](const char* name) { return find(image.planes, name) != nullptr; }, source);
    Denoiser::Job job = denoiser.begin(image.width, image.height);
    interleave(image.planes, names_of(film::Channel::radiance), image.width, source, "beauty", job.color());
    job.send(Denoiser::Job::Input::Color);
    interleave(image.planes, names_of(film::Channel::albedo), image.width, source, "albedo", job.albedo());
    job.send(Denoiser::Job::Input::Albedo);
    interleave(image.planes, names_of(film::Channel::normal), image.width, source, "normal", job.normal());
    const std::span<const float> denoised = job.run();
    try {
        return encode(image, denoised, denoiser.description());
    } catch (const std::exception& e) {
        throw std::runtime_error(source + ": cannot encode the denoised image: " + e.what());
    }
}

}  // namespace orb::denoise
