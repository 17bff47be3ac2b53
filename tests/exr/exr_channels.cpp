#include "exr_channels.h"

#include <gtest/gtest.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>

namespace orb::exr::testing {

RawExr read_raw_exr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const auto window = header.dataWindow();
    RawExr raw;
    raw.width = window.max.x - window.min.x + 1;
    raw.height = window.max.y - window.min.y + 1;
    const std::size_t pixels = static_cast<std::size_t>(raw.width) * raw.height;
    Imf::FrameBuffer frame;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        auto& values = raw.channels[it.name()];
        values.assign(pixels, 0.0f);
        frame.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                           sizeof(float) * raw.width));
        const auto type = it.channel().type;
        raw.channel_types[it.name()] = type == Imf::HALF ? "HALF" : type == Imf::FLOAT ? "FLOAT" : "UINT";
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    // The UINT channels again, as stored (a float holds 24 of their 32 bits).
    Imf::FrameBuffer exact;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        if (it.channel().type != Imf::UINT) continue;
        auto& values = raw.uints[it.name()];
        values.assign(pixels, 0u);
        exact.insert(it.name(), Imf::Slice(Imf::UINT, reinterpret_cast<char*>(values.data()), sizeof(std::uint32_t),
                                           sizeof(std::uint32_t) * raw.width));
    }
    if (!raw.uints.empty()) {
        file.setFrameBuffer(exact);
        file.readPixels(window.min.y, window.max.y);
    }
    for (auto it = header.begin(); it != header.end(); ++it) raw.attribute_types[it.name()] = it.attribute().typeName();
    raw.header = std::make_shared<const Imf::Header>(header);
    return raw;
}

void write_raw_exr(const std::string& path, const RawExr& raw) {
    Imf::Header header = *static_cast<const Imf::Header*>(raw.header.get());
    header.compression() = Imf::NO_COMPRESSION;
    for (const auto& [name, value] : raw.int_attributes) header.insert(name, Imf::IntAttribute(value));
    std::map<std::string, std::vector<Imath::half>> halves;
    Imf::FrameBuffer frame;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        const std::string name = it.name();
        if (it.channel().type == Imf::UINT) {
            frame.insert(name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(const_cast<std::uint32_t*>(raw.uints.at(name).data())),
                                          sizeof(std::uint32_t), sizeof(std::uint32_t) * raw.width));
        } else if (it.channel().type == Imf::HALF) {
            std::vector<Imath::half>& copy = halves[name];
            const std::vector<float>& values = raw.channels.at(name);
            copy.assign(values.begin(), values.end());
            frame.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(copy.data()), sizeof(Imath::half),
                                          sizeof(Imath::half) * raw.width));
        } else {
            frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(raw.channels.at(name).data())),
                                          sizeof(float), sizeof(float) * raw.width));
        }
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(raw.height);
}

void expect_same_pixels(const RawExr& a, const RawExr& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels.size(), b.channels.size());
    for (const auto& [name, values] : a.channels) {
        ASSERT_TRUE(b.channels.count(name)) << name;
        EXPECT_EQ(values, b.channels.at(name)) << "channel " << name;
    }
    EXPECT_EQ(a.uints, b.uints);
}

}  // namespace orb::exr::testing
