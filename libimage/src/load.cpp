#include "orb/image/load.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <random>

#include "orb/scene/error.h"

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

namespace orb::image {
namespace {

// Guard against headers that claim absurd sizes: a malformed file must give
// an error, not an allocation of hundreds of gigabytes.
constexpr size_t kMaxValues = size_t(1) << 30;

std::string slurp_stdin() {
    std::string data;
    char buffer[1 << 16];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, stdin)) > 0) data.append(buffer, n);
    if (std::ferror(stdin)) throw InputError("<stdin>: read error");
    return data;
}

// OIIO picks a reader by extension first, so give stdin's bytes a fitting one.
std::string extension_for_magic(const std::string& bytes) {
    auto starts = [&](const char* magic, size_t n) { return bytes.size() >= n && bytes.compare(0, n, magic, n) == 0; };
    if (starts("\x76\x2f\x31\x01", 4)) return ".exr";
    if (starts("\x89PNG", 4)) return ".png";
    if (starts("\xff\xd8\xff", 3)) return ".jpg";
    if (starts("II*\0", 4) || starts("MM\0*", 4)) return ".tif";
    if (starts("#?", 2)) return ".hdr";
    if (starts("BM", 2)) return ".bmp";
    if (starts("P1", 2) || starts("P2", 2) || starts("P3", 2) || starts("P4", 2) || starts("P5", 2) ||
        starts("P6", 2))
        return ".ppm";
    return ".img";
}

// A temporary copy of stdin that is removed when this goes out of scope.
struct StdinFile {
    fs::path path;
    explicit StdinFile(const std::string& bytes) {
        std::random_device rd;
        path = fs::temp_directory_path() /
               ("orb-stdin-" + std::to_string(rd()) + "-" + std::to_string(rd()) + extension_for_magic(bytes));
        std::ofstream out(path, std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out) throw InputError("<stdin>: cannot buffer input in " + path.string());
    }
    ~StdinFile() {
        std::error_code ec;
        fs::remove(path, ec);
    }
};

bool is_float_type(OIIO::TypeDesc t) {
    return t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::HALF ||
           t.basetype == OIIO::TypeDesc::DOUBLE;
}

// OIIO's messages can span lines (one per library layer); the first says it.
std::string clean_error(std::string message) {
    if (const auto newline = message.find('\n'); newline != std::string::npos && newline > 0)
        message.erase(newline);
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    return message.empty() ? "unknown error" : message;
}

// Reads one subimage's pixels as float, checking the result.
std::vector<float> read_subimage(OIIO::ImageInput& in, int subimage, const OIIO::ImageSpec& spec,
                                 const std::string& name) {
    const size_t values = static_cast<size_t>(spec.width) * spec.height * spec.nchannels;
    std::vector<float> data(values);
    if (!in.read_image(subimage, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()))
        throw InputError(name + ": cannot read pixels (truncated or corrupt file?): " + clean_error(in.geterror()));
    if (in.has_error()) throw InputError(name + ": " + clean_error(in.geterror()));
    return data;
}

}  // namespace

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

LoadedImage load_image(const std::string& path) {
    const std::string name = display_name(path);
    std::unique_ptr<StdinFile> stdin_copy;
    std::string filename = path;
    if (path == "-") {
        std::string bytes = slurp_stdin();
        if (bytes.empty()) throw InputError("<stdin>: no image data (empty input)");
        stdin_copy = std::make_unique<StdinFile>(bytes);
        filename = stdin_copy->path.string();
    } else {
        std::error_code ec;
        if (!fs::exists(path, ec)) throw InputError(name + ": no such file");
        if (fs::is_directory(path, ec)) throw InputError(name + ": is a directory, expected an image");
        if (fs::file_size(path, ec) == 0) throw InputError(name + ": empty file, expected an image");
    }

    auto in = OIIO::ImageInput::open(filename);
    if (!in) throw InputError(name + ": not a readable image: " + clean_error(OIIO::geterror()));

    LoadedImage result;
    result.source = path;
    result.format_name = in->format_name();
    const OIIO::ImageSpec spec0 = in->spec();
    if (spec0.width <= 0 || spec0.height <= 0 || spec0.nchannels <= 0)
        throw InputError(name + ": image has no pixels");
    if (spec0.depth > 1) throw InputError(name + ": volume images are not supported");
    if (static_cast<size_t>(spec0.width) * spec0.height * spec0.nchannels > kMaxValues)
        throw InputError(name + ": image too large (" + std::to_string(spec0.width) + "x" +
                         std::to_string(spec0.height) + "x" + std::to_string(spec0.nchannels) + ")");
    result.color_space = spec0.get_string_attribute("oiio:ColorSpace");
    result.display_referred = !is_float_type(spec0.format) && result.format_name != "openexr";
    result.orb_passes = spec0.get_string_attribute("orb:passes");
    result.environment_seen = spec0.get_int_attribute("orb:environmentSeen", 1) != 0;

    Image& image = result.image;
    image.width = spec0.width;
    image.height = spec0.height;
    image.channel_names.assign(spec0.channelnames.begin(), spec0.channelnames.end());
    for (int c = 0; c < spec0.nchannels; ++c)
        if (image.channel_names[c].empty()) image.channel_names[c] = "channel" + std::to_string(c);
    image.pixels = read_subimage(*in, 0, spec0, name);

    // Multi-part EXRs keep passes in further parts; merge the ones of equal
    // size, prefixing part names where the channels carry none.
    for (int sub = 1; in->seek_subimage(sub, 0); ++sub) {
        const OIIO::ImageSpec spec = in->spec();
        if (spec.width != image.width || spec.height != image.height || spec.x != spec0.x || spec.y != spec0.y)
            continue;
        if (static_cast<size_t>(image.width) * image.height * (image.channels() + spec.nchannels) > kMaxValues)
            throw InputError(name + ": image too large");
        const std::string part = spec.get_string_attribute("name", "part" + std::to_string(sub));
        std::vector<float> data = read_subimage(*in, sub, spec, name);
        const int old_n = image.channels();
        const int add_n = spec.nchannels;
        for (int c = 0; c < add_n; ++c) {
            std::string ch = spec.channelnames[c];
            if (ch.find('.') == std::string::npos) ch = part + "." + ch;
            image.channel_names.push_back(ch);
        }
        std::vector<float> merged(image.pixel_count() * (old_n + add_n));
        for (size_t p = 0; p < image.pixel_count(); ++p) {
            std::copy_n(&image.pixels[p * old_n], old_n, &merged[p * (old_n + add_n)]);
            std::copy_n(&data[p * add_n], add_n, &merged[p * (old_n + add_n) + old_n]);
        }
        image.pixels = std::move(merged);
    }
    in->close();
    return result;
}

}  // namespace orb::image
