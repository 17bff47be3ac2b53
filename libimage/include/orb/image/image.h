// A plain float image with interleaved, named channels: the currency between
// loading, colour management, metrics and writing.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace orb::image {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::string> channel_names;  // size() == number of channels
    std::vector<float> pixels;               // width * height * channels, row-major, interleaved

    Image() = default;
    Image(int w, int h, std::vector<std::string> names, float fill = 0.0f);

    int channels() const { return static_cast<int>(channel_names.size()); }
    size_t pixel_count() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
    float& at(int x, int y, int c) { return pixels[index(x, y, c)]; }
    float at(int x, int y, int c) const { return pixels[index(x, y, c)]; }
    size_t index(int x, int y, int c) const {
        return (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) *
                   static_cast<size_t>(channels()) +
               static_cast<size_t>(c);
    }
    // Index of a channel by exact name, or -1.
    int find_channel(const std::string& name) const;
};

// A copy holding only the listed channels (by index), renamed.
Image select_channels(const Image& source, const std::vector<int>& indices, std::vector<std::string> names);

}  // namespace orb::image
