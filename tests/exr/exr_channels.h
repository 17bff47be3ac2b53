// Reading an EXR's raw channels and header with OpenEXR, independently of
// libexr's reader, so tests check what is really in the file.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace orb::exr::testing {

struct RawExr {
    int width = 0;
    int height = 0;
    std::map<std::string, std::vector<float>> channels;  // every channel, read as FLOAT
    std::map<std::string, std::string> channel_types;     // "HALF", "FLOAT", "UINT"
    std::map<std::string, std::string> attribute_types;   // attribute name -> OpenEXR type name
};

RawExr read_raw_exr(const std::string& path);

// Every channel of two images equal bit for bit (two renders of the same
// samples), with gtest failures naming the channel.
void expect_same_pixels(const RawExr& a, const RawExr& b);

}  // namespace orb::exr::testing
