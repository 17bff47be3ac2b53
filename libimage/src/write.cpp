#include "orb/image/write.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "orb/image/quantize.h"
#include "orb/image/record_carrier.h"
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

namespace {

// Drops alpha for formats that cannot store it (JPEG, Radiance HDR, PNM, ...:
// RGB rather than an error) and premultiplies it for those that store
// associated alpha.
Image prepared_for(const Image& source, const WriteOptions& options, bool format_has_alpha) {
    if (source.channels() != 4) return source;
    if (!format_has_alpha) return select_channels(source, {0, 1, 2}, {"R", "G", "B"});
    Image image = source;
    if (options.premultiply_alpha)
        for (size_t p = 0; p < image.pixel_count(); ++p)
            for (int c = 0; c < 3; ++c) image.pixels[p * 4 + c] *= image.pixels[p * 4 + 3];
    return image;
}

// Writes through `out`, already opened on a file or an in-memory proxy.
void write_pixels(OIIO::ImageOutput& out, const Image& image, OIIO::TypeDesc type, const WriteOptions& options) {
    bool ok;
    if (type == OIIO::TypeDesc::UINT8) {
        const auto codes = options.dither ? quantize_8bit_dithered(image) : quantize_8bit(image);
        ok = out.write_image(OIIO::TypeDesc::UINT8, codes.data());
    } else if (type == OIIO::TypeDesc::UINT16) {
        const auto codes = quantize_16bit(image);
        ok = out.write_image(OIIO::TypeDesc::UINT16, codes.data());
    } else {
        ok = out.write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
    if (!ok) throw InputError("cannot encode the image: " + out.geterror());
    if (!out.close()) throw InputError("cannot encode the image: " + out.geterror());
}

// For the few OIIO writers that only write named files: a private temporary
// folder, the file read back whole, and decoded once to prove it complete
// (a writer that ignores a short write must not pass as a good image).
std::string encode_through_file(OIIO::ImageOutput& out, const OIIO::ImageSpec& spec, const Image& image,
                                OIIO::TypeDesc type, const WriteOptions& options) {
    namespace fs = std::filesystem;
    std::string folder_template = (fs::temp_directory_path() / "orb-encode-XXXXXX").string();
    if (!::mkdtemp(folder_template.data())) throw InputError("cannot create a temporary folder to encode the image");
    const fs::path folder(folder_template);
    const std::string file = (folder / ("image." + options.format)).string();
    std::error_code ec;
    try {
        if (!out.open(file, spec)) throw InputError("cannot encode the image: " + out.geterror());
        write_pixels(out, image, type, options);
        auto check = OIIO::ImageInput::open(file);
        std::vector<float> pixels(image.pixel_count() * static_cast<size_t>(spec.nchannels));
        if (!check || !check->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
            throw InputError("the encoded image does not read back: " + OIIO::geterror());
        check->close();
        std::ifstream in(file, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (in.bad()) throw InputError("cannot read back the encoded image");
        fs::remove_all(folder, ec);
        return bytes;
    } catch (...) {
        fs::remove_all(folder, ec);
        throw;
    }
}

}  // namespace

std::string encode_image(const Image& source, const WriteOptions& options) {
    auto out = OIIO::ImageOutput::create(options.format);
    if (!out) throw InputError("cannot write '" + options.format + "' images: " + OIIO::geterror());
    // OIIO can write BMP's 32-bit alpha, but most readers ignore it: BMP stays RGB, as it always was.
    const Image image = prepared_for(source, options, out->supports("alpha") && options.format != "bmp");
    const int n = image.channels();

    const bool is_float = options.format == "exr" || options.bits == 32;
    OIIO::TypeDesc type = options.bits == 8    ? OIIO::TypeDesc::UINT8
                          : options.bits == 16 ? (is_float ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT16)
                                               : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(image.width, image.height, n, type);
    spec.channelnames = {};
    for (const std::string& name : image.channel_names) spec.channelnames.push_back(name);
    if (n == 4) spec.alpha_channel = 3;
    // Straight (unassociated) colour as it is: without this OpenImageIO's PNG
    // and TIFF writers take colour for premultiplied and divide it by alpha.
    if (n == 4 && !options.premultiply_alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
    if (options.format == "exr") spec.attribute("compression", "zip");
    if (const std::string carrier = record_attribute_for(options.format); !carrier.empty() && !options.record.empty())
        spec.attribute(carrier, options.record);

    if (!out->supports("ioproxy")) return encode_through_file(*out, spec, image, type, options);
    std::vector<unsigned char> buffer;
    OIIO::Filesystem::IOVecOutput proxy(buffer);
    if (!out->set_ioproxy(&proxy) || !out->open("memory." + options.format, spec))
        throw InputError("cannot encode the image: " + out->geterror());
    write_pixels(*out, image, type, options);
    return std::string(buffer.begin(), buffer.end());
}

}  // namespace orb::image
