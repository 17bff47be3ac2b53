// PNG and JPEG texture bytes -> texels, through OpenImageIO reading from
// memory (an IOMemReader proxy), so that images embedded in a .glb or a
// data: URI never touch the disk. No colour conversion: the importer knows
// which textures are sRGB-encoded.
#include "orb/image/texture_decoder.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "orb/scene/error.h"

namespace OIIO = OIIO_NAMESPACE;

namespace orb::image {
namespace {

// OIIO picks its reader by the file name's extension: PNG and JPEG are told
// by their signatures (glTF allows only these two without an extension), a
// mime type decides for anything else OIIO reads.
std::string extension_for(std::string_view bytes, const std::string& mime_type) {
    if (bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) return "png";
    if (bytes.substr(0, 3) == std::string_view("\xff\xd8\xff", 3)) return "jpg";
    if (mime_type.rfind("image/", 0) == 0 && mime_type.size() > 6) return mime_type.substr(6);
    return "";
}

std::string first_line(std::string message) {
    if (const auto newline = message.find('\n'); newline != std::string::npos) message.erase(newline);
    while (!message.empty() && message.back() == ' ') message.pop_back();
    return message.empty() ? "unknown error" : message;
}

}  // namespace

DecodedImage decode_texture(std::string_view bytes, const std::string& mime_type, const std::string& name) {
    if (bytes.empty()) throw InputError(name + ": no image bytes");
    const std::string extension = extension_for(bytes, mime_type);
    if (extension.empty())
        throw InputError(name + ": not a PNG or JPEG image" +
                         (mime_type.empty() ? std::string() : " (mime type " + mime_type + ")"));
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::open("texture." + extension, nullptr, &memory);
    if (!in) throw InputError(name + ": not a readable image: " + first_line(OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
        throw InputError(name + ": the image has no pixels");
    if (static_cast<long long>(spec.width) * spec.height > kMaxTexturePixels)
        throw InputError(name + ": image too large (" + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + ", at most " + std::to_string(kMaxTexturePixels) + " pixels)");
    DecodedImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = std::min(spec.nchannels, 4);  // R, G, B, A; further channels mean nothing to glTF
    image.texels.resize(std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels));
    if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.texels.data()) || in->has_error())
        throw InputError(name + ": cannot read its pixels (truncated or corrupt?): " + first_line(in->geterror()));
    for (float& v : image.texels)
        if (!std::isfinite(v)) v = 0.0f;
    return image;
}

ImageDecoder texture_decoder() { return &decode_texture; }

}  // namespace orb::image
