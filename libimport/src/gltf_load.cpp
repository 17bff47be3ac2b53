// Parsing .gltf/.glb through tinygltf (Debian's shared build), fenced in:
// the GLB container and the JSON nesting depth are checked before tinygltf
// sees them, external files are read only from inside the asset's directory
// (through our own file-system callbacks, never the network), and images are
// never decoded here: their bytes are kept for the importer's ImageDecoder
// (gltf_textures.cpp), so stb never sees them.
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "gltf_internal.h"
#include "orb/scene/error.h"

namespace orb::gltf {
namespace {

namespace fs = std::filesystem;

// Deeper JSON than this is refused: tinygltf converts "extras" recursively
// and a hostile file could exhaust the stack. Real assets nest < 15 levels.
constexpr int kMaxJsonDepth = 64;
// External buffers larger than this are refused rather than read.
constexpr std::uintmax_t kMaxExternalFileBytes = std::uintmax_t(1) << 31;

struct Sandbox {
    fs::path root;  // canonical directory that external files must be inside
};

bool inside(const fs::path& root, const fs::path& candidate) {
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(candidate, ec);
    if (ec) return false;
    auto r = root.begin();
    auto c = resolved.begin();
    for (; r != root.end(); ++r, ++c)
        if (c == resolved.end() || *r != *c) return false;
    return true;
}

bool sandbox_file_exists(const std::string& path, void* user) {
    const auto* sandbox = static_cast<const Sandbox*>(user);
    std::error_code ec;
    return !sandbox->root.empty() && inside(sandbox->root, path) && fs::is_regular_file(path, ec);
}

std::string sandbox_expand(const std::string& path, void*) { return path; }

bool sandbox_read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const auto* sandbox = static_cast<const Sandbox*>(user);
    if (!sandbox_file_exists(path, user)) {
        if (err) *err = "not a file inside " + sandbox->root.string();
        return false;
    }
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec || size > kMaxExternalFileBytes) {
        if (err) *err = ec ? ec.message() : "file is larger than 2 GiB";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(std::size_t(size));
    if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        if (err) *err = "read failed";
        return false;
    }
    return true;
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "writing is disabled";
    return false;
}

// Keeps the encoded bytes of an image given by a data: URI or an external
// file (tinygltf read them into a buffer of exactly `size` bytes). Images in
// a bufferView are left alone: tinygltf hands those over without checking
// the view against its buffer, so gltf_textures.cpp reads them itself.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    image->as_is = true;  // encoded bytes, not pixels
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

// Largest nesting of arrays/objects, ignoring brackets inside strings.
int json_depth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char ch : text) {
        if (in_string) {
            if (escaped) escaped = false;
            else if (ch == '\\') escaped = true;
            else if (ch == '"') in_string = false;
            continue;
        }
        if (ch == '"') in_string = true;
        else if (ch == '{' || ch == '[') deepest = std::max(deepest, ++depth);
        else if (ch == '}' || ch == ']') --depth;
    }
    return deepest;
}

std::uint32_t read_u32(std::string_view bytes, std::size_t offset) {
    std::uint32_t value;
    std::memcpy(&value, bytes.data() + offset, 4);  // GLB is little-endian, like every host we build for
    return value;
}

// Checks the GLB container strictly and returns its JSON chunk; `length` is
// the declared total length (bytes after it are ignored).
std::string_view check_glb(std::string_view bytes, const std::string& source, std::uint32_t& length) {
    auto fail = [&](const std::string& message) -> void { throw InputError(source + ": invalid GLB: " + message); };
    if (bytes.size() < 20) fail("shorter than the 20-byte header and chunk header");
    const std::uint32_t version = read_u32(bytes, 4);
    if (version != 2) fail("container version " + std::to_string(version) + ", expected 2");
    length = read_u32(bytes, 8);
    if (length > bytes.size())
        fail("header says " + std::to_string(length) + " bytes, the file has " + std::to_string(bytes.size()));
    if (length < 20) fail("header length " + std::to_string(length) + " is too small");
    const std::uint64_t json_length = read_u32(bytes, 12);
    if (read_u32(bytes, 16) != 0x4E4F534Au) fail("the first chunk is not JSON");
    if (json_length == 0 || 20 + json_length > length) fail("the JSON chunk runs past the end of the file");
    std::uint64_t offset = 20 + json_length;
    if (offset < length) {
        if (offset + 8 > length) fail("truncated chunk header after the JSON chunk");
        const std::uint64_t bin_length = read_u32(bytes, std::size_t(offset));
        if (offset + 8 + bin_length > length) fail("the BIN chunk runs past the end of the file");
    }
    return bytes.substr(20, std::size_t(json_length));
}

}  // namespace

tinygltf::Model load_model(std::string_view bytes, const std::string& source, const std::string& base_dir) {
    if (bytes.size() > (std::size_t(1) << 31)) throw InputError(source + ": file larger than 2 GiB");
    const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
    std::uint32_t glb_length = 0;
    const std::string_view json_text = binary ? check_glb(bytes, source, glb_length) : bytes;
    if (json_depth(json_text) > kMaxJsonDepth)
        throw InputError(source + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    refuse_undecodable_extensions(json_text, source);

    // No base directory: no external file is ever read (fuzzing, embedded use).
    Sandbox sandbox;
    if (!base_dir.empty()) {
        std::error_code ec;
        sandbox.root = fs::weakly_canonical(fs::absolute(fs::path(base_dir), ec), ec);
        if (ec) sandbox.root.clear();
    }

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&sandbox_file_exists, &sandbox_expand, &sandbox_read, &refuse_write, &sandbox});
    loader.SetImageLoader(&keep_image_bytes, nullptr);
    loader.SetStoreOriginalJSONForExtrasAndExtensions(false);

    tinygltf::Model model;
    std::string error, warning;
    const std::string dir = sandbox.root.string();
    bool ok;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                  reinterpret_cast<const unsigned char*>(bytes.data()), glb_length, dir)
                    : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                                 static_cast<unsigned int>(bytes.size()), dir);
    } catch (const std::exception& e) {
        // tinygltf lets some nlohmann exceptions through (e.g. on bad UTF-8).
        ok = false;
        error = e.what();
    }
    if (!ok) {
        if (error.empty()) error = warning;
        if (error.empty()) error = "an object lacks a required property (tinygltf gives no detail)";
        while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
        for (char& ch : error)
            if (ch == '\n') ch = ';';
        // The parsers quote what they read, which may be any byte of the input.
        throw InputError(source + ": not a valid glTF 2.0 asset: " + printable(error));
    }
    return model;
}

}  // namespace orb::gltf
