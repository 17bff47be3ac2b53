// Reading an EXR's raw channels and header with OpenEXR, independently of
// libexr's reader, so tests check what is really in the file; and writing
// such a file back, changed, to make files Orb would not write.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace orb::exr::testing {

struct RawExr {
    int width = 0;
    int height = 0;
    std::map<std::string, std::vector<float>> channels;  // every channel, read as FLOAT
    std::map<std::string, std::vector<std::uint32_t>> uints;  // the UINT channels as stored
    std::map<std::string, std::string> channel_types;     // "HALF", "FLOAT", "UINT"
    std::map<std::string, std::string> attribute_types;   // attribute name -> OpenEXR type name
    std::map<std::string, int> int_attributes;           // written over the header's by write_raw_exr
    std::shared_ptr<const void> header;                   // the file's Imf::Header, for write_raw_exr
};

RawExr read_raw_exr(const std::string& path);

// Writes `raw` as an uncompressed EXR: its header with `int_attributes` set,
// its FLOAT and HALF channels from `channels`, its UINT channels from `uints`.
void write_raw_exr(const std::string& path, const RawExr& raw);

// Every channel of two images equal bit for bit (two renders of the same
// samples), with gtest failures naming the channel.
void expect_same_pixels(const RawExr& a, const RawExr& b);

}  // namespace orb::exr::testing
