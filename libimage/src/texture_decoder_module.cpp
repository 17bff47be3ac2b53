// The texture decoder as a module the tools load only when a scene has
// textures (orb/cli/texture_decoder_loader.h), so that orb-render and
// orb-import do not link OpenImageIO: a bare render node runs them with
// OpenEXR alone, and only a textured glTF asset needs OpenImageIO there.
// The entry point takes C++ types: the module is built and installed with
// the tools from the same source, never mixed with another build.
#include <exception>
#include <string>
#include <string_view>

#include "orb/image/texture_decoder.h"

extern "C" __attribute__((visibility("default"))) bool orb_decode_texture_v1(std::string_view bytes,
                                                                           const std::string& mime_type,
                                                                           const std::string& name,
                                                                           orb::DecodedImage& decoded,
                                                                           std::string& error) noexcept {
    try {
        decoded = orb::image::decode_texture(bytes, mime_type, name);
        return true;
    } catch (const std::exception& e) {
        error = e.what();
    } catch (...) {
        error = name + ": the image decoder failed";
    }
    return false;
}
