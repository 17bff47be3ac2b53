#include "orb/image/write.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>

#include "orb/image/quantize.h"
#include "orb/scene/error.h"

namespace OIIO = OIIO_NAMESPACE;

namespace orb::image {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

WriteOptions checked_write_options(WriteOptions options) {
    std::string& f = options.format;
    for (char& c : f) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (f == "jpeg") f = "jpg";
    if (f == "tiff") f = "tif";
    if (f.empty()) throw InputError("cannot tell the output format: give the file an extension or use --format");
    if (options.bits != 0 && options.bits != 8 && options.bits != 16 && options.bits != 32)
        throw InputError("--bits must be 8, 16 or 32");
    if (f == "jpg" && options.bits > 8) throw InputError("JPEG holds only 8 bits per channel");
    if (f == "png" && options.bits == 32) throw InputError("PNG holds 8 or 16 bits per channel");
    if (f == "exr" && options.bits == 8) throw InputError("EXR holds 16-bit half or 32-bit float, not 8 bits");
    auto probe = OIIO::ImageOutput::create(f);
    if (!probe) throw InputError("cannot write '" + f + "' images: " + OIIO::geterror());
    if (options.bits == 0) options.bits = f == "exr" ? 16 : 8;
    return options;
}

void write_image_file(const std::string& filename, const Image& source, const WriteOptions& options) {
    Image image = source;
    int n = image.channels();
    const bool has_alpha = n == 4;
    // Formats whose writer cannot store alpha (JPEG, Radiance HDR, PNM, ...)
    // get RGB rather than an error. OIIO can write BMP's 32-bit alpha, but most
    // readers ignore it, so BMP stays RGB as it always was.
    const auto writer = OIIO::ImageOutput::create(options.format);
    const bool holds_alpha = writer && writer->supports("alpha") && options.format != "bmp";
    if (has_alpha && !holds_alpha) {
        image = select_channels(source, {0, 1, 2}, {"R", "G", "B"});
        n = 3;
    } else if (has_alpha && options.premultiply_alpha) {
        for (size_t p = 0; p < image.pixel_count(); ++p)
            for (int c = 0; c < 3; ++c) image.pixels[p * 4 + c] *= image.pixels[p * 4 + 3];
    }

    const bool is_float = options.format == "exr" || options.bits == 32;
    OIIO::TypeDesc type = options.bits == 8    ? OIIO::TypeDesc::UINT8
                          : options.bits == 16 ? (is_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT16)
                                               : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(image.width, image.height, n, type);
    spec.channelnames = {};
    for (const std::string& name : image.channel_names) spec.channelnames.push_back(name);
    if (n == 4) spec.alpha_channel = 3;
    if (options.format == "exr") spec.attribute("compression", "zip");

    auto out = OIIO::ImageOutput::create(options.format);
    if (!out) throw InputError("cannot write '" + options.format + "' images: " + OIIO::geterror());
    if (!out->open(filename, spec)) throw InputError("cannot write image: " + out->geterror());
    bool ok;
    if (type == OIIO::TypeDesc::UINT8) {
        const auto codes = options.dither ? quantize_8bit_dithered(image) : quantize_8bit(image);
        ok = out->write_image(OIIO::TypeDesc::UINT8, codes.data());
    } else if (type == OIIO::TypeDesc::UINT16) {
        const auto codes = quantize_16bit(image);
        ok = out->write_image(OIIO::TypeDesc::UINT16, codes.data());
    } else {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
    if (!ok) throw InputError("cannot write image: " + out->geterror());
    if (!out->close()) throw InputError("cannot write image: " + out->geterror());
}

}  // namespace orb::image
