#include "environment_exr_writer.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <Imath/half.h>

namespace orb::exr::testing {

void write_map_exr(const std::string& path, const MapFile& map) {
    const Imath::Box2i window({map.origin_x, map.origin_y},
                              {map.origin_x + map.width - 1, map.origin_y + map.height - 1});
    Imf::Header header(window, window);
    const Imf::PixelType type = map.half ? Imf::HALF : Imf::FLOAT;
    for (const std::string& name : map.channels) header.channels().insert(name, Imf::Channel(type));
    if (map.cube_map) Imf::addEnvmap(header, Imf::ENVMAP_CUBE);
    const std::size_t count = map.channels.size();
    std::vector<float> floats(map.values);
    std::vector<half> halves(floats.begin(), floats.end());
    const std::size_t element = map.half ? sizeof(half) : sizeof(float);
    char* base = map.half ? reinterpret_cast<char*>(halves.data()) : reinterpret_cast<char*>(floats.data());
    const std::ptrdiff_t x_stride = std::ptrdiff_t(element * count), y_stride = x_stride * map.width;
    const std::ptrdiff_t origin = -(std::ptrdiff_t(map.origin_x) * x_stride + std::ptrdiff_t(map.origin_y) * y_stride);
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < count; ++c)
        frame.insert(map.channels[c], Imf::Slice(type, base + origin + c * element, x_stride, y_stride));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(map.height);
}

MapFile gradient_map(int width, int height, float scale) {
    MapFile map;
    map.width = width;
    map.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (float v : {float(x), float(y), 0.5f}) map.values.push_back(v * scale);
    return map;
}

}  // namespace orb::exr::testing
