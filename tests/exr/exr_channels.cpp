#include "exr_channels.h"

#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

namespace orb::exr::testing {

RawExr read_raw_exr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const auto window = header.dataWindow();
    RawExr raw;
    raw.width = window.max.x - window.min.x + 1;
    raw.height = window.max.y - window.min.y + 1;
    Imf::FrameBuffer frame;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        auto& values = raw.channels[it.name()];
        values.assign(static_cast<std::size_t>(raw.width) * raw.height, 0.0f);
        frame.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                           sizeof(float) * raw.width));
        const auto type = it.channel().type;
        raw.channel_types[it.name()] = type == Imf::HALF ? "HALF" : type == Imf::FLOAT ? "FLOAT" : "UINT";
    }
    for (auto it = header.begin(); it != header.end(); ++it) raw.attribute_types[it.name()] = it.attribute().typeName();
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return raw;
}

void expect_same_pixels(const RawExr& a, const RawExr& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels.size(), b.channels.size());
    for (const auto& [name, values] : a.channels) {
        ASSERT_TRUE(b.channels.count(name)) << name;
        EXPECT_EQ(values, b.channels.at(name)) << "channel " << name;
    }
}

}  // namespace orb::exr::testing
