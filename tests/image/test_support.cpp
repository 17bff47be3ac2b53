#include "test_support.h"
#include "orb/image/hash.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

namespace orb::image::test {
namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

CommandResult run(const std::string& command_line) {
    static int counter = 0;
    const fs::path base = fs::temp_directory_path() /
                          ("orb-image-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    const std::string out = base.string() + ".out", err = base.string() + ".err";
    const std::string full = "(" + command_line + ") >" + quote(out) + " 2>" + quote(err);
    const int status = std::system(full.c_str());
    CommandResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    fs::remove(out);
    fs::remove(err);
    return r;
}

ScratchDir::ScratchDir() {
    std::random_device rd;
    root_ = fs::temp_directory_path() / ("orb-image-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
    fs::create_directories(root_);
}

ScratchDir::~ScratchDir() {
    std::error_code ec;
    fs::remove_all(root_, ec);
}

Image make_scene(int width, int height, float peak, float noise, unsigned seed) {
    Image img(width, height, {"R", "G", "B"});
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u = (x + 0.5f) / width, v = (y + 0.5f) / height;
            const bool check = ((x / 12) + (y / 12)) % 2 == 0;
            // A sky-like gradient, a checker floor and a hot spot above 1.
            const float spot = std::exp(-((u - 0.7f) * (u - 0.7f) + (v - 0.3f) * (v - 0.3f)) * 40.0f);
            float rgb[3] = {0.05f + 0.6f * u * (check ? 1.0f : 0.4f), 0.1f + 0.5f * v, 0.3f + 0.4f * (1.0f - u) * v};
            for (int c = 0; c < 3; ++c) {
                rgb[c] += peak * spot * (c == 0 ? 1.0f : c == 1 ? 0.8f : 0.5f);
                if (noise > 0) {
                    const uint32_t h = orb::image::hash32(seed * 0x9e3779b9U ^ orb::image::hash32(static_cast<uint32_t>((y * width + x) * 3 + c)));
                    rgb[c] = std::max(0.0f, rgb[c] + noise * ((h >> 8) / 16777216.0f - 0.5f) * 2.0f);
                }
                img.at(x, y, c) = rgb[c];
            }
        }
    return img;
}

void write_exr(const std::string& path, const Image& image, bool half) {
    OIIO::ImageSpec spec(image.width, image.height, image.channels(), half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    spec.channelnames.assign(image.channel_names.begin(), image.channel_names.end());
    auto out = OIIO::ImageOutput::create(path);
    if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !out->close())
        throw std::runtime_error("cannot write " + path);
}

void write_png(const std::string& path, const Image& image) {
    std::vector<uint8_t> codes(image.pixels.size());
    for (size_t i = 0; i < codes.size(); ++i)
        codes[i] = static_cast<uint8_t>(std::lround(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f));
    OIIO::ImageSpec spec(image.width, image.height, image.channels(), OIIO::TypeDesc::UINT8);
    auto out = OIIO::ImageOutput::create(path);
    if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, codes.data()) || !out->close())
        throw std::runtime_error("cannot write " + path);
}

Image read_image(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read " + path + ": " + OIIO::geterror());
    const auto& spec = in->spec();
    Image img(spec.width, spec.height, std::vector<std::string>(spec.channelnames.begin(), spec.channelnames.end()));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
        throw std::runtime_error("cannot read pixels of " + path);
    return img;
}

Image make_multipass(int width, int height) {
    const Image beauty = make_scene(width, height, 6.0f);
    const std::vector<std::string> names = {"R", "G", "B", "A", "direct.R", "direct.G", "direct.B", "indirect.R",
                                            "indirect.G", "indirect.B", "emission.R", "emission.G", "emission.B",
                                            "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z",
                                            "variance.R", "variance.G", "variance.B", "id"};
    Image img(width, height, names);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            auto set = [&](const char* name, float v) { img.at(x, y, img.find_channel(name)) = v; };
            const float r = beauty.at(x, y, 0), g = beauty.at(x, y, 1), b = beauty.at(x, y, 2);
            set("R", r), set("G", g), set("B", b), set("A", 1.0f);
            set("direct.R", 0.6f * r), set("direct.G", 0.6f * g), set("direct.B", 0.6f * b);
            set("indirect.R", 0.4f * r), set("indirect.G", 0.4f * g), set("indirect.B", 0.4f * b);
            set("emission.R", 0), set("emission.G", 0), set("emission.B", 0);
            set("albedo.R", 0.7f), set("albedo.G", 0.5f), set("albedo.B", 0.3f);
            const float nx = (x - width / 2.0f) / width, ny = (y - height / 2.0f) / height;
            const float nz = std::sqrt(std::max(0.0f, 1.0f - nx * nx - ny * ny));
            set("N.X", nx), set("N.Y", ny), set("N.Z", nz);
            set("Z", 1.0f + x * 0.05f);
            set("variance.R", 0.01f * r), set("variance.G", 0.01f * g), set("variance.B", 0.01f * b);
            set("id", static_cast<float>((x / 16) + 1));
        }
    return img;
}

std::string flip_evaluator() {
    if (const char* env = std::getenv("ORB_FLIP_EVALUATOR"); env && *env && fs::exists(env)) return env;
    const std::string exe = std::string(ORB_FLIP_VENV) + "/bin/flip";
    if (!fs::exists(exe)) {
        // Normally the CTest fixture has installed it; running the test binary by hand gets here.
        const auto r = run("sh " + quote(ORB_ENSURE_FLIP_SCRIPT) + " " + quote(ORB_FLIP_VENV));
        if (r.exit_code != 0)
            ADD_FAILURE() << "cannot install the reference FLIP (pip install flip-evaluator): " << r.err;
    }
    return exe;
}

std::string tonemap_exe() { return ORB_TONEMAP_EXE; }
std::string diff_exe() { return ORB_DIFF_EXE; }
std::string ocio_config() { return ORB_BUILD_OCIO_CONFIG; }

}  // namespace orb::image::test
