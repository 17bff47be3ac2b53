// Helpers for the image tests: scratch folders, running the tools, writing
// synthetic images and reading results back.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "orb/image/image.h"

namespace orb::image::test {

struct CommandResult {
    int exit_code = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

// Runs a shell command line, capturing stdout and stderr.
CommandResult run(const std::string& command_line);

// Single-quotes a string for the shell.
std::string quote(const std::string& s);

// A fresh scratch folder per test, removed afterwards.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    std::string path(const std::string& name) const { return (root_ / name).string(); }

private:
    std::filesystem::path root_;
};

// Synthetic, deterministic scene-like RGB content (values up to ~`peak`),
// with `noise` adding a hash-based perturbation of that amplitude.
Image make_scene(int width, int height, float peak, float noise = 0.0f, unsigned seed = 1);

// Writes channels as named, as float/half EXR or 8-bit PNG (values clamped).
void write_exr(const std::string& path, const Image& image, bool half = false);
void write_png(const std::string& path, const Image& image);

// Reads any image as float.
Image read_image(const std::string& path);

// An orb-render style multi-pass EXR built from a scene image.
Image make_multipass(int width, int height);

// The reference FLIP tool, installed on demand (fails the test if impossible).
std::string flip_evaluator();

std::string tonemap_exe();
std::string diff_exe();
std::string ocio_config();

}  // namespace orb::image::test
