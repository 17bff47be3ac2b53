// Magic numbers, first lines and extensions of the 3D, point-cloud,
// image and archive formats people most often hand to Orb by mistake. The
// signatures are the formats' own (each noted beside it), as the file(1)
// magic database also lists them.
#include "foreign_formats.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "orb/import/importers.h"
#include "text_start.h"

namespace orb::detail {
namespace {

using namespace std::string_view_literals;  // magic numbers hold NUL bytes

struct Magic {
    std::string_view bytes;  // at offset 0
    const char* name;
};

// Binary signatures, checked at the very start of the input.
const Magic kMagics[] = {
    {"Kaydara FBX Binary"sv, "FBX (binary)"},                        // Autodesk FBX binary header
    {"BLENDER"sv, "Blender (.blend)"},                               // "BLENDER-v300" / "BLENDER_V..."
    {"PXR-USDC"sv, "USD (binary crate)"},                            // Pixar USD crate file
    {"#usda"sv, "USD (text)"},                                       // "#usda 1.0"
    {"Ogawa"sv, "Alembic"},                                          // Alembic's Ogawa back end
    {"\x89HDF\r\n\x1a\n"sv, "HDF5 (an Alembic or other HDF5 file)"}, // HDF5 superblock signature
    {"#VRML"sv, "VRML"},                                             // "#VRML V2.0 utf8"
    {"#X3D"sv, "X3D (classic encoding)"},                            // "#X3D V3.0 utf8"
    {"LASF"sv, "LAS point cloud"},                                   // ASPRS LAS file signature
    {"ASTM-E57"sv, "E57 point cloud"},                               // ASTM E2807 file signature
    {"DRACO"sv, "Draco compressed mesh"},                            // Draco bitstream header
    {"VOX "sv, "MagicaVoxel VOX"},                                   // MagicaVoxel chunk id
    {"v/1\x01"sv, "OpenEXR image"},                                  // 76 2F 31 01
    {"\x89PNG\r\n\x1a\n"sv, "PNG image"},                            // PNG signature
    {"\xFF\xD8\xFF"sv, "JPEG image"},                                // SOI marker + next marker
    {"#?RADIANCE"sv, "Radiance HDR image"},                          // Radiance picture header
    {"#?RGBE"sv, "Radiance HDR image"},
    {"II*\0"sv, "TIFF image"},                                       // little-endian TIFF
    {"MM\0*"sv, "TIFF image"},                                       // big-endian TIFF
    {"PK\x03\x04"sv, "ZIP archive (USDZ, 3MF, KMZ, ...)"},          // ZIP local file header
    {"\x1F\x8B"sv, "gzip-compressed data"},                          // gzip member header
    {"\x28\xB5\x2F\xFD"sv, "Zstandard-compressed data"},            // zstd frame (compressed .blend too)
    {"\xFD" "7zXZ\0"sv, "xz-compressed data"},                       // xz stream header
    {"BZh"sv, "bzip2-compressed data"},                              // bzip2 stream header
    {"7z\xBC\xAF\x27\x1C"sv, "7-Zip archive"},                       // 7z signature
};

std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

// Up to `count` lines of the text after a byte-order mark, blank lines and
// (when `comment` is set) lines starting with it left out.
std::vector<std::string_view> leading_lines(std::string_view text, std::size_t count, char comment) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    std::vector<std::string_view> lines;
    while (!text.empty() && lines.size() < count) {
        const std::string_view line = first_line(text);
        const std::size_t next = text.find('\n');
        text = next == std::string_view::npos ? std::string_view{} : text.substr(next + 1);
        const std::vector<std::string_view> words = words_of(line);
        if (words.empty() || (comment && words[0].front() == comment)) continue;
        lines.push_back(line);
    }
    return lines;
}

bool is_count(std::string_view word) {
    return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::uint32_t little_endian_u32(std::string_view bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
    return value;
}

// Wavefront OBJ: the first statement (after '#' comments) is a vertex, face,
// group, object, smoothing or material statement.
const char* obj_kind(std::string_view text) {
    const std::vector<std::string_view> lines = leading_lines(text, 1, '#');
    if (lines.empty()) return nullptr;
    const std::string_view keyword = words_of(lines[0])[0];
    for (std::string_view obj : {"v", "vn", "vt", "vp", "f", "l", "p", "o", "g", "s", "mtllib", "usemtl"})
        if (keyword == obj) return "Wavefront OBJ";
    if (keyword == "newmtl") return "Wavefront OBJ material library (.mtl)";
    return nullptr;
}

}  // namespace

std::string foreign_format_by_content(std::string_view bytes) {
    for (const Magic& magic : kMagics)
        if (bytes.starts_with(magic.bytes)) return magic.name;
    // Binary STL: an 80-byte header, a little-endian triangle count and 50
    // bytes per triangle, nothing else (its header may even start "solid").
    if (bytes.size() >= 84 && bytes.size() == 84 + 50 * std::uint64_t(little_endian_u32(bytes, 80)))
        return "STL (binary)";
    // 3D Studio: a main chunk 0x4D4D whose length is the file's.
    if (bytes.size() >= 6 && bytes.starts_with("\x4D\x4D") && little_endian_u32(bytes, 2) == bytes.size())
        return "3D Studio (.3ds)";

    const std::vector<std::string_view> start = leading_lines(bytes, 1, 0);
    if (start.empty()) return "";
    const std::string_view line = start[0];
    const std::string_view word = words_of(line)[0];
    if (word == "solid" && (bytes.find("facet") != std::string_view::npos || bytes.find("endsolid") != std::string_view::npos))
        return "STL (text)";
    if (line.starts_with("; FBX")) return "FBX (text)";
    if (word.starts_with("<")) {
        const std::string_view head = bytes.substr(0, 4096);
        if (head.find("<COLLADA") != std::string_view::npos) return "COLLADA";
        if (head.find("<X3D") != std::string_view::npos) return "X3D";
        return "XML";
    }
    // OFF and its variants; some writers run the counts into the keyword ("OFF8 6 12").
    for (std::string_view off : {"OFF", "COFF", "NOFF", "CNOFF", "STOFF", "STCOFF", "4OFF", "nOFF"})
        if (word.starts_with(off) && (word.size() == off.size() || is_count(word.substr(off.size())))) return "OFF";
    if (line.starts_with("# .PCD") || word == "VERSION") return "PCD (Point Cloud Library)";
    if (const char* obj = obj_kind(bytes)) return obj;
    return "";
}

std::string foreign_format_by_extension(const std::string& path) {
    if (is_importer_extension(path)) return "";  // an importer has come for it since it was listed here
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    struct Named {
        std::string_view extension;
        const char* name;
    };
    static const Named kExtensions[] = {
        {".obj", "Wavefront OBJ"},
        {".mtl", "Wavefront OBJ material library (.mtl)"},
        {".stl", "STL"},
        {".fbx", "FBX"},
        {".dae", "COLLADA"},
        {".3ds", "3D Studio (.3ds)"},
        {".blend", "Blender (.blend)"},
        {".usd", "USD"},
        {".usda", "USD (text)"},
        {".usdc", "USD (binary crate)"},
        {".usdz", "USD (zipped)"},
        {".abc", "Alembic"},
        {".off", "OFF"},
        {".x3d", "X3D"},
        {".wrl", "VRML"},
        {".pcd", "PCD (Point Cloud Library)"},
        {".las", "LAS point cloud"},
        {".laz", "LAZ point cloud"},
        {".e57", "E57 point cloud"},
        {".3mf", "3MF"},
        {".vox", "MagicaVoxel VOX"},
        {".drc", "Draco compressed mesh"},
        {".splat", "Gaussian splats (.splat)"},
        {".spz", "Gaussian splats (.spz)"},
        {".exr", "OpenEXR image"},
        {".hdr", "Radiance HDR image"},
        {".png", "PNG image"},
        {".jpg", "JPEG image"},
        {".jpeg", "JPEG image"},
        {".tif", "TIFF image"},
        {".tiff", "TIFF image"},
    };
    for (const Named& named : kExtensions)
        if (extension == named.extension) return named.name;
    return "";
}

}  // namespace orb::detail
