// glTF textures averaged over each sphere (docs/gltf.md, "Textures").
#include "gltf_textures.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include "srgb.h"

namespace orb::gltf {
namespace {

// Samples per triangle side: a triangle is cut into k x k similar pieces,
// each sampled at its centroid, with k its longest side in texels (so every
// texel it covers is seen), at most this many.
constexpr int kMaxSubdivision = 32;
// Texel samples per sphere and texture at most: bounds the work a hostile
// file (millions of triangles, each across the whole texture) can ask for.
constexpr double kMaxSamplesPerSphere = 4.0e6;

// glTF's base-colour and emissive textures are sRGB-encoded, their factors linear.
using detail::srgb_to_linear;

// Wraps a texture coordinate into [0, 1] as the sampler says.
double wrap(double t, int mode) {
    if (!std::isfinite(t)) return 0.0;
    if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return std::clamp(t, 0.0, 1.0);
    if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) {
        const double period = t - 2.0 * std::floor(t / 2.0);
        return period > 1.0 ? 2.0 - period : period;
    }
    return t - std::floor(t);  // REPEAT, glTF's default
}

int texel_index(double t, int size) {
    const double scaled = std::floor(t * double(size));
    return int(std::clamp(scaled, 0.0, double(size - 1)));
}

std::string texture_kind_label(const std::string& material, const char* kind) {
    return material + " " + kind + " texture";
}

}  // namespace

struct TextureReader::Texture {
    const DecodedImage* image = nullptr;
    int wrap_s = TINYGLTF_TEXTURE_WRAP_REPEAT;
    int wrap_t = TINYGLTF_TEXTURE_WRAP_REPEAT;
    int set = 0;  // TEXCOORD_n
    // KHR_texture_transform as u' = m[0] . (u, v, 1), v' = m[1] . (u, v, 1).
    std::array<std::array<double, 3>, 2> transform{{{1, 0, 0}, {0, 1, 0}}};

    Uv apply(const Uv& uv) const {
        return {transform[0][0] * uv[0] + transform[0][1] * uv[1] + transform[0][2],
                transform[1][0] * uv[0] + transform[1][1] * uv[1] + transform[1][2]};
    }
    // Channel c (0 red, 1 green, 2 blue) of the texel under `uv`; grey
    // images give their one value to all three.
    double fetch(const Uv& uv, int c) const {
        const int x = texel_index(wrap(uv[0], wrap_s), image->width);
        const int y = texel_index(wrap(uv[1], wrap_t), image->height);  // v = 0 is the top row, as in glTF
        const int channel = image->channels >= 3 ? c : 0;
        return image->texels[(std::size_t(y) * std::size_t(image->width) + std::size_t(x)) *
                                 std::size_t(image->channels) +
                             std::size_t(channel)];
    }
};

void SpherePatch::add(const std::vector<AnimVec3>& points, const std::array<std::uint32_t, 3>& corners, int material,
                      const std::map<int, std::vector<Uv>>& texcoords, std::uint32_t first_vertex) {
    Triangle triangle;
    const AnimVec3 &a = points[corners[0]], &b = points[corners[1]], &c = points[corners[2]];
    const AnimVec3 ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const AnimVec3 cross{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
    triangle.area = 0.5 * detail::length3(cross);
    if (!std::isfinite(triangle.area)) triangle.area = 0.0;
    triangle.material = material;
    for (const auto& [set, uvs] : texcoords) {
        std::array<Uv, 3> corner_uvs{};
        for (int k = 0; k < 3; ++k) corner_uvs[std::size_t(k)] = uvs[corners[std::size_t(k)] - first_vertex];
        triangle.texcoords.emplace_back(set, corner_uvs);
    }
    triangles.push_back(std::move(triangle));
}

std::vector<Uv> read_texcoords(const tinygltf::Model& model, const tinygltf::Primitive& primitive, int set,
                               std::size_t vertex_count, const std::string& what, const Diagnostics& diagnostics) {
    auto it = primitive.attributes.find("TEXCOORD_" + std::to_string(set));
    if (it == primitive.attributes.end()) return {};
    const AccessorValues values =
        read_accessor(model, it->second, {TINYGLTF_TYPE_VEC2}, what + " " + it->first, diagnostics);
    if (values.count != vertex_count)
        diagnostics.fail(what + ": " + it->first + " has " + std::to_string(values.count) + " entries for " +
                         std::to_string(vertex_count) + " vertices");
    std::vector<Uv> uvs(values.count);
    for (std::size_t i = 0; i < values.count; ++i) uvs[i] = {values.element(i)[0], values.element(i)[1]};
    return uvs;
}

void TextureReader::lossy_once(const std::string& message) {
    if (said_.insert(message).second) diagnostics_.lossy(message);
}

// The texture a material refers to, with its sampler, image and transform.
std::optional<TextureReader::Texture> TextureReader::texture(const tinygltf::TextureInfo& info,
                                                             const std::string& label) {
    if (info.index < 0) return std::nullopt;
    if (std::size_t(info.index) >= model_.textures.size())
        diagnostics_.fail(label + ": texture " + std::to_string(info.index) + " does not exist (there are " +
                          std::to_string(model_.textures.size()) + ")");
    const tinygltf::Texture& t = model_.textures[std::size_t(info.index)];
    Texture out;
    if (t.sampler >= 0) {
        if (std::size_t(t.sampler) >= model_.samplers.size())
            diagnostics_.fail(label + ": sampler " + std::to_string(t.sampler) + " does not exist");
        out.wrap_s = model_.samplers[std::size_t(t.sampler)].wrapS;
        out.wrap_t = model_.samplers[std::size_t(t.sampler)].wrapT;
    }
    if (t.source < 0) {
        lossy_once(label + ": texture " + std::to_string(info.index) +
                   " has no PNG or JPEG source (only an extension's image format); ignored");
        return std::nullopt;
    }
    if (std::size_t(t.source) >= model_.images.size())
        diagnostics_.fail(label + ": image " + std::to_string(t.source) + " does not exist (there are " +
                          std::to_string(model_.images.size()) + ")");
    out.image = image(t.source, label);
    if (!out.image) return std::nullopt;
    out.set = info.texCoord;
    if (const tinygltf::Value* transform = extension(info.extensions, "KHR_texture_transform")) {
        // glTF: T * R * S, with R = [[cos, sin], [-sin, cos]] (rotation counter-clockwise in UV space).
        double offset[2] = {0, 0}, scale[2] = {1, 1};
        for (const auto& [key, target] : {std::pair{"offset", offset}, std::pair{"scale", scale}})
            if (transform->IsObject() && transform->Has(key) && transform->Get(key).IsArray() &&
                transform->Get(key).ArrayLen() == 2)
                for (int k = 0; k < 2; ++k)
                    if (transform->Get(key).Get(k).IsNumber()) target[k] = transform->Get(key).Get(k).GetNumberAsDouble();
        const double rotation = number_at(*transform, "rotation").value_or(0.0);
        const double c = std::cos(rotation), s = std::sin(rotation);
        out.transform = {{{c * scale[0], s * scale[1], offset[0]}, {-s * scale[0], c * scale[1], offset[1]}}};
        if (const std::optional<int> set = index_at(*transform, "texCoord")) out.set = *set;
    }
    return out;
}

std::string_view TextureReader::image_bytes(const tinygltf::Image& image, const std::string& label) {
    if (image.bufferView < 0) {
        if (image.image.empty())
            lossy_once(label + (image.uri.empty() ? std::string(": has no bytes")
                                                  : ": '" + image.uri + "' could not be read (it must be a file "
                                                                        "inside the asset's folder)") +
                       "; the textures that use it are ignored");
        return {reinterpret_cast<const char*>(image.image.data()), image.image.size()};
    }
    // tinygltf does not check an image's view against its buffer.
    if (std::size_t(image.bufferView) >= model_.bufferViews.size())
        diagnostics_.fail(label + ": bufferView " + std::to_string(image.bufferView) + " does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[std::size_t(image.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size())
        diagnostics_.fail(label + ": buffer " + std::to_string(view.buffer) + " does not exist");
    const std::vector<unsigned char>& data = model_.buffers[std::size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        diagnostics_.fail(label + ": bufferView " + std::to_string(image.bufferView) + " runs past the end of its buffer");
    return {reinterpret_cast<const char*>(data.data()) + view.byteOffset, view.byteLength};
}

const DecodedImage* TextureReader::image(int index, const std::string& material_label) {
    auto found = images_.find(index);
    if (found != images_.end()) return found->second ? &*found->second : nullptr;
    std::optional<DecodedImage>& slot = images_[index];
    const tinygltf::Image& source = model_.images[std::size_t(index)];
    const std::string label = "image " + std::to_string(index) +
                              (source.name.empty() ? std::string() : " '" + source.name + "'") + " (" +
                              material_label + ")";
    const std::string_view bytes = image_bytes(source, label);
    if (bytes.empty()) return nullptr;
    try {
        DecodedImage decoded = decoder_(bytes, source.mimeType, label);
        const bool consistent = decoded.width > 0 && decoded.height > 0 && decoded.channels >= 1 &&
                                decoded.channels <= 4 &&
                                decoded.texels.size() == std::size_t(decoded.width) * std::size_t(decoded.height) *
                                                             std::size_t(decoded.channels);
        if (!consistent) throw std::runtime_error(label + ": the decoder returned no usable texels");
        slot = std::move(decoded);
    } catch (const std::exception& e) {
        lossy_once(std::string(e.what()) + "; the textures that use it are ignored");
        return nullptr;
    }
    return &*slot;
}

std::set<int> TextureReader::texcoord_sets(int material) const {
    std::set<int> sets;
    if (!active() || material < 0 || std::size_t(material) >= model_.materials.size()) return sets;
    const tinygltf::Material& m = model_.materials[std::size_t(material)];
    for (const tinygltf::TextureInfo* info :
         {&m.pbrMetallicRoughness.baseColorTexture, &m.pbrMetallicRoughness.metallicRoughnessTexture,
          &m.emissiveTexture}) {
        if (info->index < 0) continue;
        int set = info->texCoord;
        if (const tinygltf::Value* transform = extension(info->extensions, "KHR_texture_transform"))
            set = index_at(*transform, "texCoord").value_or(set);
        sets.insert(set);
    }
    return sets;
}

namespace {

// Encoded texel range and (decoded) weighted sum of the red, green, blue
// channels over a sphere.
struct TexelStats {
    std::array<double, 3> sum{0, 0, 0};
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    std::array<double, 3> hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};
    double weight = 0.0;
    bool constant(int c) const { return hi[std::size_t(c)] - lo[std::size_t(c)] <= kConstantTexelTolerance + 1e-6; }
    // A constant channel's value is its texel (the middle of the range, for
    // noise within the tolerance), not a weighted mean whose rounding would
    // tell apart two spheres on one atlas cell; anything else its average.
    double value(int c, bool srgb) const {
        const auto i = std::size_t(c);
        if (!constant(c)) return sum[i] / weight;
        const double texel = 0.5 * (lo[i] + hi[i]);
        return srgb ? srgb_to_linear(texel) : texel;
    }
};

}  // namespace

TextureValues TextureReader::sample(int material, const SpherePatch& patch) {
    TextureValues values;
    if (!active() || material < 0 || std::size_t(material) >= model_.materials.size()) return values;
    const tinygltf::Material& m = model_.materials[std::size_t(material)];
    const std::string label = "material '" + (m.name.empty() ? std::to_string(material) : m.name) + "'";
    // The sphere's triangles in this material; all of them when a sphere
    // spans primitives and none is in it (it takes its first one's material).
    std::vector<const SpherePatch::Triangle*> triangles;
    for (const auto& t : patch.triangles)
        if (t.material == material) triangles.push_back(&t);
    if (triangles.empty())
        for (const auto& t : patch.triangles) triangles.push_back(&t);
    if (triangles.empty()) return values;
    const int max_k = int(std::clamp(std::floor(std::sqrt(kMaxSamplesPerSphere / double(triangles.size()))), 1.0,
                                     double(kMaxSubdivision)));

    // Averages one texture over the triangles; nothing when it cannot be read.
    auto average = [&](const tinygltf::TextureInfo& info, const char* kind, bool srgb) -> std::optional<TexelStats> {
        const std::string texture_label = texture_kind_label(label, kind);
        const std::optional<Texture> texture = this->texture(info, texture_label);
        if (!texture) return std::nullopt;
        TexelStats stats;
        for (const SpherePatch::Triangle* t : triangles) {
            auto uvs = std::find_if(t->texcoords.begin(), t->texcoords.end(),
                                    [&](const auto& entry) { return entry.first == texture->set; });
            if (uvs == t->texcoords.end()) {
                lossy_once(texture_label + ": the mesh has no TEXCOORD_" + std::to_string(texture->set) +
                           "; the texture is ignored there");
                return std::nullopt;
            }
            std::array<Uv, 3> uv{};
            for (int k = 0; k < 3; ++k) uv[std::size_t(k)] = texture->apply(uvs->second[std::size_t(k)]);
            double side = 0.0;  // longest side in texels
            for (int k = 0; k < 3; ++k) {
                const Uv& p = uv[std::size_t(k)];
                const Uv& q = uv[std::size_t((k + 1) % 3)];
                side = std::max({side, std::fabs(q[0] - p[0]) * texture->image->width,
                                 std::fabs(q[1] - p[1]) * texture->image->height});
            }
            const int n = std::isfinite(side) ? std::clamp(int(std::ceil(side)), 1, max_k) : 1;
            const double weight = t->area / double(n * n);
            // Centroids of the n^2 pieces: upright ones at (i + 1/3, j + 1/3) / n, the
            // upside-down ones between them at (i + 2/3, j + 2/3) / n.
            auto visit = [&](double b1, double b2) {
                const Uv p{uv[0][0] + b1 * (uv[1][0] - uv[0][0]) + b2 * (uv[2][0] - uv[0][0]),
                           uv[0][1] + b1 * (uv[1][1] - uv[0][1]) + b2 * (uv[2][1] - uv[0][1])};
                for (int c = 0; c < 3; ++c) {
                    const double encoded = texture->fetch(p, c);
                    const auto i = std::size_t(c);
                    stats.lo[i] = std::min(stats.lo[i], encoded);
                    stats.hi[i] = std::max(stats.hi[i], encoded);
                    stats.sum[i] += weight * (srgb ? srgb_to_linear(encoded) : encoded);
                }
                stats.weight += weight;
            };
            for (int i = 0; i < n; ++i)
                for (int j = 0; i + j < n; ++j) {
                    visit((i + 1.0 / 3.0) / n, (j + 1.0 / 3.0) / n);
                    if (i + j + 1 < n) visit((i + 2.0 / 3.0) / n, (j + 2.0 / 3.0) / n);
                }
        }
        if (!(stats.weight > 0)) return std::nullopt;  // a sphere of zero area: nothing to average
        return stats;
    };

    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    if (const auto stats = average(pbr.baseColorTexture, "base-colour", true)) {
        values.base_color = Vec3{stats->value(0, true), stats->value(1, true), stats->value(2, true)};
        values.varies = values.varies || !stats->constant(0) || !stats->constant(1) || !stats->constant(2);
    }
    if (const auto stats = average(pbr.metallicRoughnessTexture, "metallic-roughness", false)) {
        values.roughness = stats->value(1, false);
        values.metallic = stats->value(2, false);
        values.varies = values.varies || !stats->constant(1) || !stats->constant(2);
    }
    if (const auto stats = average(m.emissiveTexture, "emissive", true)) {
        values.emission = Vec3{stats->value(0, true), stats->value(1, true), stats->value(2, true)};
        values.varies = values.varies || !stats->constant(0) || !stats->constant(1) || !stats->constant(2);
    }
    return values;
}

void AveragedTextures::add(const std::string& sphere, const std::string& material) {
    spheres_.push_back(sphere);
    materials_.insert(material);
}

void AveragedTextures::report(Diagnostics& diagnostics) const {
    if (spheres_.empty()) return;
    constexpr std::size_t kShown = 5;
    std::string names;
    for (std::size_t i = 0; i < std::min(spheres_.size(), kShown); ++i) names += (i ? ", " : "") + spheres_[i];
    if (spheres_.size() > kShown) names += ", ...";
    std::string materials;
    for (const std::string& name : materials_) materials += (materials.empty() ? "" : ", ") + name;
    diagnostics.lossy("textures vary over " + std::to_string(spheres_.size()) +
                      (spheres_.size() == 1 ? " sphere (" : " spheres (") + names + "; " + materials +
                      "): each takes its textures' area-weighted average (a sphere has one flat material)");
}

}  // namespace orb::gltf
