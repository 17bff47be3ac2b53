#include "orb/cli/texture_decoder_loader.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <string>

#include "orb/cli/paths.h"
#include "orb/scene/error.h"

namespace orb::cli {
namespace {

using DecodeEntry = bool (*)(std::string_view, const std::string&, const std::string&, DecodedImage&, std::string&);

struct LoadedModule {
    DecodeEntry decode = nullptr;
    std::string path;
    std::string why_not;  // set when decode is null
};

// Loaded once per process and never unloaded: decoded texels and OpenImageIO's
// own state may outlive any one import.
const LoadedModule& module() {
    static LoadedModule loaded;
    static std::once_flag once;
    std::call_once(once, [] {
        const std::filesystem::path bin = std::filesystem::path(executable_path()).parent_path();
        loaded.path = (bin.parent_path() / "lib" / "orb" / "orb_texture_decoder.so").string();
        void* handle = dlopen(loaded.path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* error = dlerror();
            loaded.why_not = error ? error : "dlopen failed";
            return;
        }
        loaded.decode = reinterpret_cast<DecodeEntry>(dlsym(handle, "orb_decode_texture_v1"));
        if (!loaded.decode) loaded.why_not = loaded.path + ": no entry point orb_decode_texture_v1";
    });
    return loaded;
}

}  // namespace

ImageDecoder texture_decoder() {
    return [](std::string_view bytes, const std::string& mime_type, const std::string& name) {
        const LoadedModule& m = module();
        if (!m.decode)
            throw InputError(name + ": textures cannot be decoded here: the texture decoder (OpenImageIO) did not load (" +
                             m.why_not + ")");
        DecodedImage decoded;
        std::string error;
        if (!m.decode(bytes, mime_type, name, decoded, error)) throw InputError(error);
        return decoded;
    };
}

}  // namespace orb::cli
