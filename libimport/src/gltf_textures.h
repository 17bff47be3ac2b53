// Reading glTF textures into sphere materials (docs/gltf.md, "Textures"):
// a sphere is one flat material, so each texture a material reads is
// averaged over the sphere's own triangles, through their TEXCOORD_n. An
// atlas (a texture constant over each sphere) gives each sphere its cell's
// value exactly; anything else its area-weighted average, with a warning.
// Nothing here is public API.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "gltf_internal.h"
#include "orb/import/image_decoder.h"

namespace orb::gltf {

using Uv = std::array<double, 2>;

// A texture counts as constant over a sphere when every texel sampled there
// lies within this much (of full scale) of every other in each channel read:
// one step of an 8-bit texture, where atlases live.
inline constexpr double kConstantTexelTolerance = 1.0 / 255.0;

// The triangles of one sphere, as the textures see them.
struct SpherePatch {
    struct Triangle {
        double area = 0.0;  // the sample weight: textures are averaged over the surface
        int material = -1;  // glTF material of the primitive the triangle came from
        std::vector<std::pair<int, std::array<Uv, 3>>> texcoords;  // (n, TEXCOORD_n of its corners)
    };
    std::vector<Triangle> triangles;
    // Adds triangle `corners` (indices into `points`); `texcoords` holds its
    // primitive's TEXCOORD_n sets, indexed by corner index minus `first_vertex`.
    void add(const std::vector<AnimVec3>& points, const std::array<std::uint32_t, 3>& corners, int material,
             const std::map<int, std::vector<Uv>>& texcoords, std::uint32_t first_vertex);
};

// What a material's textures give one sphere: each multiplies its factor.
struct TextureValues {
    std::optional<Vec3> base_color;   // linear (decoded from sRGB)
    std::optional<double> roughness;  // green channel
    std::optional<double> metallic;   // blue channel
    std::optional<Vec3> emission;     // linear (decoded from sRGB)
    bool varies = false;              // some texture is not constant over the sphere: averages
    bool any() const { return base_color || roughness || metallic || emission; }
};

class TextureReader {
public:
    TextureReader(const tinygltf::Model& model, const ImageDecoder& decoder, Diagnostics& diagnostics)
        : model_(model), decoder_(decoder), diagnostics_(diagnostics) {}
    // Whether textures are read at all (the importer was given a decoder).
    bool active() const { return bool(decoder_); }
    // The TEXCOORD_n sets that glTF material `material`'s read textures use.
    std::set<int> texcoord_sets(int material) const;
    // The material's textures averaged over the patch's triangles of that
    // material (all of them when none is). Empty values where a texture
    // cannot be read (warned once).
    TextureValues sample(int material, const SpherePatch& patch);

private:
    struct Texture;
    std::optional<Texture> texture(const tinygltf::TextureInfo& info, const std::string& label);
    const DecodedImage* image(int index, const std::string& label);
    std::string_view image_bytes(const tinygltf::Image& image, const std::string& label);
    void lossy_once(const std::string& message);

    const tinygltf::Model& model_;
    const ImageDecoder& decoder_;
    Diagnostics& diagnostics_;
    std::map<int, std::optional<DecodedImage>> images_;  // by glTF image; nullopt: unreadable (warned)
    std::set<std::string> said_;
};

// TEXCOORD_`set` of a primitive as (u, v) pairs; empty when it has none.
std::vector<Uv> read_texcoords(const tinygltf::Model& model, const tinygltf::Primitive& primitive, int set,
                               std::size_t vertex_count, const std::string& what, const Diagnostics& diagnostics);

// Names the spheres whose textures were averaged, for one warning.
class AveragedTextures {
public:
    void add(const std::string& sphere, const std::string& material);
    void report(Diagnostics& diagnostics) const;

private:
    std::vector<std::string> spheres_;
    std::set<std::string> materials_;
};

}  // namespace orb::gltf
