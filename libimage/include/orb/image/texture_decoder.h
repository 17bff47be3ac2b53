// The image decoder the tools hand to the scene importers (glTF textures),
// backed by OpenImageIO: PNG and JPEG from memory, no temporary files.
#pragma once

#include "orb/import/image_decoder.h"

namespace orb::image {

// Decodes PNG or JPEG bytes (told apart by their signature, else by the
// mime type) into texels as stored. Throws InputError naming the image for
// bytes that are not such an image, are corrupt or truncated, or whose
// header claims more than kMaxTexturePixels pixels.
DecodedImage decode_texture(std::string_view bytes, const std::string& mime_type, const std::string& name);

inline constexpr long long kMaxTexturePixels = 1LL << 26;  // 8192 x 8192

// decode_texture as an ImageDecoder.
ImageDecoder texture_decoder();

}  // namespace orb::image
