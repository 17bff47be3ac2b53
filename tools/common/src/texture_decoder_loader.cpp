#include "orb/cli/texture_decoder_loader.h"

#include <string>

#include "orb/cli/runtime_module.h"
#include "orb/scene/error.h"

namespace orb::cli {
namespace {

using DecodeEntry = bool (*)(std::string_view, const std::string&, const std::string&, DecodedImage&, std::string&);

}  // namespace

ImageDecoder texture_decoder() { return texture_decoder_in(tools_module_folder()); }

ImageDecoder texture_decoder_in(const std::string& module_folder) {
    return [module_folder](std::string_view bytes, const std::string& mime_type, const std::string& name) {
        const RuntimeModule& m = runtime_module(module_folder, "orb_texture_decoder.so", "orb_decode_texture_v1");
        if (!m.entry)
            throw InputError(name + ": textures cannot be decoded here: the texture decoder (OpenImageIO) did not load (" +
                             m.why_not + ")");
        DecodedImage decoded;
        std::string error;
        if (!reinterpret_cast<DecodeEntry>(m.entry)(bytes, mime_type, name, decoded, error)) throw InputError(error);
        return decoded;
    };
}

}  // namespace orb::cli
