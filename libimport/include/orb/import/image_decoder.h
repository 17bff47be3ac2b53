// The seam through which importers read texture images: libscene knows no
// image format (docs/design/texture-decoding.md), so a caller that wants
// textures hands the importer a decoder; the tools pass one backed by
// OpenImageIO (orb/image/texture_decoder.h).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace orb {

// Texels as the file stores them, each channel normalised to [0, 1]
// (8-bit 255 -> 1), no colour conversion: an sRGB-encoded texture stays
// encoded. Rows top first, channels interleaved.
struct DecodedImage {
    int width = 0;
    int height = 0;
    int channels = 0;  // 1 (grey) .. 4 (RGBA)
    std::vector<float> texels;  // width * height * channels
};

// Decodes the encoded bytes of an image (PNG, JPEG, ...). `mime_type` is the
// glTF mimeType (may be empty) and `name` names the image in messages.
// Throws (any std::exception, with a message that names `name`) when the
// bytes are not an image it can read.
using ImageDecoder =
    std::function<DecodedImage(std::string_view bytes, const std::string& mime_type, const std::string& name)>;

}  // namespace orb
