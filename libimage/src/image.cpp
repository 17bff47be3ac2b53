#include "orb/image/image.h"

#include <utility>

namespace orb::image {

Image::Image(int w, int h, std::vector<std::string> names, float fill)
    : width(w), height(h), channel_names(std::move(names)) {
    pixels.assign(pixel_count() * channel_names.size(), fill);
}

int Image::find_channel(const std::string& name) const {
    for (size_t i = 0; i < channel_names.size(); ++i)
        if (channel_names[i] == name) return static_cast<int>(i);
    return -1;
}

Image select_channels(const Image& source, const std::vector<int>& indices, std::vector<std::string> names) {
    Image out(source.width, source.height, std::move(names));
    const int n = out.channels();
    const int src_n = source.channels();
    const size_t count = source.pixel_count();
    for (size_t p = 0; p < count; ++p)
        for (int c = 0; c < n; ++c) out.pixels[p * n + c] = source.pixels[p * src_n + indices[c]];
    return out;
}

}  // namespace orb::image
