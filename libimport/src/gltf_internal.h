// Pieces of the glTF importer, shared between its source files (gltf_*.cpp).
// Nothing here is public API.
#pragma once

#include <tiny_gltf.h>

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/detail/animation_math.h"
#include "orb/import/gltf.h"
#include "orb/scene/scene.h"

namespace orb::gltf {

// ---- loading (gltf_load.cpp) ----

// Parses .gltf or .glb bytes. External files are read only from inside
// `base_dir`; images are never decoded. Throws InputError.
tinygltf::Model load_model(std::string_view bytes, const std::string& source, const std::string& base_dir);

// Throws InputError when the asset's extensionsRequired names a geometry
// compression Orb cannot decode (gltf_required.cpp); called on the JSON
// text before tinygltf sees it.
void refuse_undecodable_extensions(std::string_view json_text, const std::string& source);

// ---- messages (gltf_import.cpp) ----

class Diagnostics {
public:
    Diagnostics(std::string source, bool strict) : source_(std::move(source)), strict_(strict) {}
    [[noreturn]] void fail(const std::string& message) const;
    // A warning, named by the asset's file.
    void warn(const std::string& message);
    // A warning that loses information: an error under --strict.
    void lossy(const std::string& message);
    const std::string& source() const { return source_; }
    std::vector<std::string> take_warnings() { return std::move(warnings_); }

private:
    std::string source_;
    bool strict_;
    std::vector<std::string> warnings_;
};

// ---- an asset without light (gltf_default_light.cpp) ----

// Gives a scene that has no light the default light (kDefaultEnvironmentRadiance,
// kDefaultKeyIrradiance), with a notice naming --no-default-light.
// It loses nothing, so it is a notice, not a warning that --strict refuses.
void add_default_light(Scene& scene, const std::string& source, std::vector<std::string>& notices);

// ---- what Orb drops (gltf_ignored.cpp) ----

// Counts what the imported content uses that Orb does not render, for one
// warning per asset ("ignored: 3 base-colour textures, ...").
class IgnoredFeatures {
public:
    // A glTF material that imported content uses: its textures and the
    // material extensions Orb does not read. `textures_read`: the importer
    // reads base-colour, metallic-roughness and emissive textures (it has an
    // image decoder), so only the others are ignored.
    void add_material(const tinygltf::Material& material, bool textures_read);
    void add_spot_cone() { ++spot_cones_; }
    void add_range() { ++ranges_; }
    // "ignored: ..." naming everything counted plus the asset's extensions
    // that Orb does not read; empty when nothing is dropped.
    std::string summary(const tinygltf::Model& model) const;

private:
    // baseColor, metallicRoughness, normal, occlusion, emissive: references.
    static constexpr std::size_t kCoreTextureKinds = 5;
    std::array<std::size_t, kCoreTextureKinds> core_textures_{};
    std::map<std::string, std::size_t> extension_textures_;   // "kind texture|extension" -> references
    std::map<std::string, std::size_t> material_extensions_;  // name -> materials
    bool unread_for_want_of_decoder_ = false;  // textures Orb reads with a decoder were ignored
    std::size_t spot_cones_ = 0;
    std::size_t ranges_ = 0;
};

// ---- accessors (gltf_accessor.cpp) ----

// An accessor's elements as doubles, `components` per element, normalised
// integers converted as the glTF spec says. Every offset is bounds-checked.
struct AccessorValues {
    std::size_t count = 0;
    int components = 0;
    std::vector<double> values;  // count * components
    const double* element(std::size_t i) const { return values.data() + i * std::size_t(components); }
};

// `what` names the accessor in messages ("mesh 'Ball' POSITION").
// `allowed_types` lists TINYGLTF_TYPE_* values that are acceptable.
AccessorValues read_accessor(const tinygltf::Model& model, int index, std::initializer_list<int> allowed_types,
                             const std::string& what, const Diagnostics& diagnostics);

// Vertex indices of a primitive (all vertices when it has none), checked
// against `vertex_count`.
std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                        std::size_t vertex_count, const std::string& what,
                                        const Diagnostics& diagnostics);

// ---- geometry (gltf_geometry.cpp) ----

struct FittedSphere {
    AnimVec3 center{};
    double radius = 0.0;
};

// The sphere that all `points` lie on within `tolerance` (relative to the
// radius), if the triangles also cover it like a tessellated sphere does:
// closely (no coarse faces) and all the way round (closed, or wrapping the
// full solid angle), so that bands and hemispheres are not spheres.
std::optional<FittedSphere> fit_sphere(const std::vector<AnimVec3>& points,
                                       const std::vector<std::array<std::uint32_t, 3>>& triangles, double tolerance);

// One connected piece of a triangle surface, after welding vertices that
// share a position (within 1e-6 of the surface's size).
struct SurfacePart {
    std::vector<AnimVec3> points;                         // welded vertices
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into points
    std::vector<std::uint32_t> source_vertices;           // the input vertices that belong to this part
};

// The connected parts of `triangles` (indices into `points`), in the order
// of their first triangles (gltf_parts.cpp).
std::vector<SurfacePart> connected_parts(const std::vector<AnimVec3>& points,
                                         const std::vector<std::array<std::uint32_t, 3>>& triangles);
// Every edge of a non-degenerate triangle is shared by exactly two of them.
bool is_closed(const std::vector<std::array<std::uint32_t, 3>>& triangles);
// Sum of the solid angles that the triangles subtend from `center`: 4 pi
// when they wrap all the way round it.
double solid_angle_seen_from(const AnimVec3& center, const std::vector<AnimVec3>& points,
                             const std::vector<std::array<std::uint32_t, 3>>& triangles);

// Centre of the bounding box and the largest distance from it to a point.
FittedSphere bounding_sphere(const std::vector<AnimVec3>& points);

// Triangles of a TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN index list.
std::vector<std::array<std::uint32_t, 3>> triangles_of(int mode, const std::vector<std::uint32_t>& indices);

// ---- materials (gltf_materials.cpp) ----

struct TextureValues;  // gltf_textures.h

class MaterialTable {
public:
    MaterialTable(const tinygltf::Model& model, Scene& scene, Diagnostics& diagnostics)
        : model_(model), scene_(scene), diagnostics_(diagnostics) {}
    // Index in scene.materials of glTF material `index` (-1: the default
    // material) with its base colour multiplied by `color_scale`.
    // `vertex_colors`: the primitive has COLOR_0, which then colours a
    // primitive without a material on its own (white base, as glTF says).
    // `textures`: what the material's textures give one sphere, multiplying
    // the factors; each distinct result is one Orb material, "NAME #k".
    std::uint32_t get(int index, const AnimVec3& color_scale = {1.0, 1.0, 1.0}, bool vertex_colors = false,
                      const TextureValues* textures = nullptr);
    // A black emitter of radiance `emission` (lights).
    std::uint32_t emitter(const std::string& name, const Vec3& emission);
    // glTF material indices that imported content uses.
    const std::set<int>& used() const { return used_; }

private:
    std::uint32_t add(Material material);
    void note_volume(const tinygltf::Material& m, const std::string& label);
    const tinygltf::Model& model_;
    Scene& scene_;
    Diagnostics& diagnostics_;
    std::map<std::string, std::uint32_t> by_key_;
    std::map<int, std::map<std::string, std::uint32_t>> textured_;  // glTF material -> values -> index
    std::set<int> used_;
};

// ---- extension values (gltf_import.cpp) ----

// Number at `key` of a tinygltf::Value object, if present and a number.
std::optional<double> number_at(const tinygltf::Value& object, const std::string& key);
// Non-negative integer index at `key`, if present and an integer in range.
std::optional<int> index_at(const tinygltf::Value& object, const std::string& key);
const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const std::string& name);

// ---- cameras and lights (gltf_camera.cpp, gltf_lights.cpp) ----

// Orb camera from a glTF perspective or orthographic camera and its node's world matrix;
// `scene_center` sets how far away the target point is.
void convert_camera(const tinygltf::Camera& camera, const std::string& name, const Matrix4& world,
                    const AnimVec3& scene_center, Scene& scene, Diagnostics& diagnostics);
// Frames the spheres from +z looking down -z (orb::frame_spheres: outliers
// left out, fitted to the image's aspect ratio), leaving out the spheres
// listed in `distant` (directional-light emitters, far away).
void automatic_camera(Scene& scene, const std::set<std::size_t>& distant);

// Luminous efficacy that turns lumens into watts: 683 lm/W, the SI
// definition of the candela and Blender's PBR_WATTS_TO_LUMENS.
constexpr double kLumensPerWatt = 683.0;
// Factor from glTF light units (cd, lux) to Orb's radiant units (W/sr, W/m^2).
double watts_per_lumen(LightUnits units);
// Radiance of a sphere of radius `radius` whose radiant intensity in every
// direction is `intensity` (per colour channel): L = I / (pi r^2).
Vec3 point_light_radiance(const Vec3& intensity, double radius);
// Radiance of a sphere of radius `radius` at `distance` that gives
// irradiance `illuminance` on a surface facing it: L = E / (pi (r/d)^2).
Vec3 distant_light_radiance(const Vec3& illuminance, double radius, double distance);

// Animated node channels of glTF animation (clip) `clip` (gltf_animation.cpp),
// keyed by glTF node index.
std::map<int, std::vector<AnimationChannel>> read_animation_channels(const tinygltf::Model& model, std::size_t clip,
                                                                    Diagnostics& diagnostics);
// "animation 2 'Walk'"
std::string animation_label(const tinygltf::Model& model, std::size_t clip);

}  // namespace orb::gltf
