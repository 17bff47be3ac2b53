// glTF 2.0 -> the canonical Orb scene: walks the selected scene's node
// hierarchy and turns sphere-shaped content, lights and a camera into Orb
// objects; animated nodes become the scene's animation section.
// Every rule is in docs/gltf.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "gltf_internal.h"
#include "gltf_textures.h"
#include "orb/scene/error.h"
#include "orb/import/gltf.h"
#include "orb/scene/scene_json.h"

namespace orb::gltf {

// ---- diagnostics and extension values ----

void Diagnostics::fail(const std::string& message) const { throw InputError(source_ + ": " + message); }

// Every warning names the asset: several may be imported at once (a farm's
// log, orb-frames), and a warning without its file is a riddle.
void Diagnostics::warn(const std::string& message) { warnings_.push_back(source_ + ": " + message); }

void Diagnostics::lossy(const std::string& message) {
    if (strict_) fail(message + " (an error because of --strict)");
    warn(message);
}

std::optional<double> number_at(const tinygltf::Value& object, const std::string& key) {
    if (!object.IsObject() || !object.Has(key)) return std::nullopt;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsNumber()) return std::nullopt;
    return v.GetNumberAsDouble();
}

std::optional<int> index_at(const tinygltf::Value& object, const std::string& key) {
    const std::optional<double> v = number_at(object, key);
    // Checked in double so that a huge value never reaches an int conversion.
    if (!v || !(*v >= 0) || *v > double(std::numeric_limits<int>::max()) || *v != std::floor(*v)) return std::nullopt;
    return int(*v);
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const std::string& name) {
    auto it = extensions.find(name);
    return it == extensions.end() ? nullptr : &it->second;
}

namespace {

// More spheres than this is refused up front rather than exhausting memory
// (instances x points can multiply a small file into billions).
constexpr std::size_t kMaxSpheres = std::size_t(1) << 24;
// Two axis scales closer than this (relative) count as uniform.
constexpr double kUniformScaleTolerance = 1e-6;
// Default sizes relative to the diagonal of the scene's bounds.
constexpr double kDefaultLightRadiusFraction = 0.01;
constexpr double kDefaultPointRadiusFraction = 0.01;
// A directional light becomes a sphere this many scene diagonals away,
// whose radius is this fraction of that distance (2.9 degrees across).
constexpr double kDistantLightDistance = 100.0;
constexpr double kDistantLightRadiusFraction = 0.025;

std::string node_label(const tinygltf::Model& model, int index) {
    const std::string& name = model.nodes[std::size_t(index)].name;
    return name.empty() ? "node " + std::to_string(index) : "node '" + name + "'";
}

Matrix4 local_rest_matrix(const tinygltf::Node& node, const std::string& label, const Diagnostics& diagnostics) {
    if (node.matrix.size() == 16) {
        Matrix4 m{};
        std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
        return m;
    }
    if (!node.matrix.empty()) diagnostics.fail(label + ": matrix must have 16 numbers");
    if (!node.translation.empty() && node.translation.size() != 3)
        diagnostics.fail(label + ": translation must have 3 numbers");
    if (!node.rotation.empty() && node.rotation.size() != 4) diagnostics.fail(label + ": rotation must have 4 numbers");
    if (!node.scale.empty() && node.scale.size() != 3) diagnostics.fail(label + ": scale must have 3 numbers");
    AnimVec3 t{0, 0, 0}, s{1, 1, 1};
    Quaternion r{0, 0, 0, 1};
    if (!node.translation.empty()) std::copy(node.translation.begin(), node.translation.end(), t.begin());
    if (!node.rotation.empty()) std::copy(node.rotation.begin(), node.rotation.end(), r.begin());
    if (!node.scale.empty()) std::copy(node.scale.begin(), node.scale.end(), s.begin());
    return detail::trs_matrix(t, r, s);
}

// Finds a glTF object by index ("2") or by name.
template <typename T>
std::optional<int> find_by_index_or_name(const std::vector<T>& items, const std::string& key) {
    if (!key.empty() && std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        if (key.size() > 9) return std::nullopt;
        const int index = std::stoi(key);
        if (std::size_t(index) < items.size()) return index;
        return std::nullopt;
    }
    for (std::size_t i = 0; i < items.size(); ++i)
        if (items[i].name == key) return int(i);
    return std::nullopt;
}

// One sphere-shaped piece of a mesh, in the mesh's own coordinates.
struct MeshSphere {
    FittedSphere shape;
    int material = -1;
    AnimVec3 color_scale{1, 1, 1};
    bool vertex_colors = false;
    TextureValues textures;  // the material's textures averaged over this sphere
};

struct MeshPoints {
    std::vector<AnimVec3> positions;
    std::vector<double> radii;    // empty: no _RADIUS attribute
    std::vector<AnimVec3> colors;  // empty: no COLOR_0
    int material = -1;
};

// What a mesh contributes, worked out once however many nodes use it.
struct MeshContent {
    std::vector<MeshSphere> spheres;
    std::vector<MeshPoints> points;
    bool has_non_spheres = false;     // parts that are not spheres (skipped under Skip)
};

class Importer {
public:
    Importer(const tinygltf::Model& model, const GltfImportOptions& options, Diagnostics& diagnostics)
        : model_(model), options_(options), diagnostics_(diagnostics), materials_(model, scene_, diagnostics),
          textures_(model, options.image_decoder, diagnostics) {}

    Scene run() {
        if (const std::optional<std::size_t> clip = choose_animation())
            channels_ = read_animation_channels(model_, *clip, diagnostics_);
        link_parents();
        walk(scene_roots());
        for (int node : order_) add_node_content(node);
        // Everything after this is a light's stand-in, which shows nothing of the asset.
        const std::size_t content_spheres = scene_.spheres.size();
        const double diagonal = scene_diagonal();
        for (const auto& [node, light] : lights_) add_light(node, light, diagonal);
        choose_camera();
        report_non_spheres();
        report_scales();
        averaged_textures_.report(diagnostics_);
        report_ignored();
        if (content_spheres == 0) no_spheres_ = why_no_spheres(scene_.spheres.size());
        return std::move(scene_);
    }

    // Set by run() when nothing in the asset became a sphere: what was left out and why.
    const std::string& no_spheres() const { return no_spheres_; }

private:
    // ---- structure ----

    // One clip plays: the one --animation names, else the first (clips are
    // alternatives, like "Walk" and "Run", that would fight over the nodes).
    std::optional<std::size_t> choose_animation() {
        const auto& clips = model_.animations;
        if (!options_.animation.empty()) {
            const std::optional<int> found = find_by_index_or_name(clips, options_.animation);
            if (!found) {
                std::string names;
                for (std::size_t i = 0; i < clips.size(); ++i)
                    names += (i ? ", " : ": ") + animation_label(model_, i);
                diagnostics_.fail("--animation " + options_.animation + ": no such animation (there are " +
                                  std::to_string(clips.size()) + names + ")");
            }
            return std::size_t(*found);
        }
        if (clips.empty()) return std::nullopt;
        if (clips.size() > 1) {
            std::string others;
            for (std::size_t i = 1; i < clips.size(); ++i) others += (i > 1 ? ", " : "") + animation_label(model_, i);
            diagnostics_.lossy(animation_label(model_, 0) + " is imported; the other clips are left out: " + others +
                               " (--animation NAME|INDEX picks one)");
        }
        return 0;
    }

    // glTF nodes form a forest: every node has at most one parent.
    void link_parents() {
        const std::size_t count = model_.nodes.size();
        parent_.assign(count, -1);
        for (std::size_t i = 0; i < count; ++i)
            for (int child : model_.nodes[i].children) {
                if (child < 0 || std::size_t(child) >= count)
                    diagnostics_.fail(node_label(model_, int(i)) + ": child " + std::to_string(child) + " does not exist");
                if (std::size_t(child) == i) diagnostics_.fail(node_label(model_, child) + " is its own child");
                if (parent_[std::size_t(child)] >= 0)
                    diagnostics_.fail(node_label(model_, child) + " has two parents (" +
                                      node_label(model_, parent_[std::size_t(child)]) + " and " +
                                      node_label(model_, int(i)) + ")");
                parent_[std::size_t(child)] = int(i);
            }
    }

    std::vector<int> scene_roots() {
        if (model_.scenes.empty()) {
            if (!options_.scene.empty()) diagnostics_.fail("--scene " + options_.scene + ": the asset has no scenes");
            std::vector<int> roots;
            for (std::size_t i = 0; i < parent_.size(); ++i)
                if (parent_[i] < 0) roots.push_back(int(i));
            if (!roots.empty()) diagnostics_.warn("the asset has no scenes; all root nodes are imported");
            return roots;
        }
        int chosen = 0;
        if (!options_.scene.empty()) {
            const std::optional<int> found = find_by_index_or_name(model_.scenes, options_.scene);
            if (!found)
                diagnostics_.fail("--scene " + options_.scene + ": no such scene (there are " +
                                  std::to_string(model_.scenes.size()) + ")");
            chosen = *found;
        } else if (model_.defaultScene >= 0) {
            if (std::size_t(model_.defaultScene) >= model_.scenes.size())
                diagnostics_.fail("default scene " + std::to_string(model_.defaultScene) + " does not exist");
            chosen = model_.defaultScene;
        }
        std::vector<int> roots;
        for (int node : model_.scenes[std::size_t(chosen)].nodes) {
            if (node < 0 || std::size_t(node) >= model_.nodes.size())
                diagnostics_.fail("scene " + std::to_string(chosen) + ": node " + std::to_string(node) +
                                  " does not exist");
            if (parent_[std::size_t(node)] >= 0)
                diagnostics_.fail("scene " + std::to_string(chosen) + ": " + node_label(model_, node) +
                                  " is listed as a root but is a child of " +
                                  node_label(model_, parent_[std::size_t(node)]));
            if (std::find(roots.begin(), roots.end(), node) != roots.end())
                diagnostics_.fail("scene " + std::to_string(chosen) + ": " + node_label(model_, node) +
                                  " is listed twice");
            roots.push_back(node);
        }
        return roots;
    }

    // Rest-pose world matrices, parents before children. Roots have no
    // parent and every node at most one, so each node is reached once.
    void walk(const std::vector<int>& roots) {
        world_.assign(model_.nodes.size(), kIdentityMatrix);
        moves_.assign(model_.nodes.size(), false);
        std::vector<int> stack(roots.rbegin(), roots.rend());
        while (!stack.empty()) {
            const int node = stack.back();
            stack.pop_back();
            const tinygltf::Node& n = model_.nodes[std::size_t(node)];
            const Matrix4 local = local_rest_matrix(n, node_label(model_, node), diagnostics_);
            const int parent = parent_[std::size_t(node)];
            world_[std::size_t(node)] = parent >= 0 ? detail::multiply(world_[std::size_t(parent)], local) : local;
            auto it = channels_.find(node);
            moves_[std::size_t(node)] =
                (parent >= 0 && moves_[std::size_t(parent)]) || (it != channels_.end() && !it->second.empty());
            order_.push_back(node);
            for (auto child = n.children.rbegin(); child != n.children.rend(); ++child) stack.push_back(*child);
        }
    }

    // ---- animation nodes ----

    // Index of the animation node standing for glTF node `node`, creating it
    // and its ancestors on first use.
    std::uint32_t animation_node(int node) {
        auto found = animation_index_.find(node);
        if (found != animation_index_.end()) return found->second;
        const int parent = parent_[std::size_t(node)];
        const std::int32_t parent_index = parent >= 0 ? std::int32_t(animation_node(parent)) : -1;
        const tinygltf::Node& n = model_.nodes[std::size_t(node)];
        AnimationNode out;
        out.name = n.name.empty() ? "node " + std::to_string(node) : n.name;
        out.parent = parent_index;
        if (n.matrix.size() == 16) {
            out.has_matrix = true;
            std::copy(n.matrix.begin(), n.matrix.end(), out.matrix.begin());
        } else {
            if (n.translation.size() == 3) std::copy(n.translation.begin(), n.translation.end(), out.translation.begin());
            if (n.rotation.size() == 4) std::copy(n.rotation.begin(), n.rotation.end(), out.rotation.begin());
            out.rotation = detail::normalized(out.rotation);  // a zero quaternion means no rotation, as when placing
            if (n.scale.size() == 3) std::copy(n.scale.begin(), n.scale.end(), out.scale.begin());
            auto it = channels_.find(node);
            if (it != channels_.end()) out.channels = it->second;
        }
        const auto index = std::uint32_t(scene_.animation.nodes.size());
        scene_.animation.nodes.push_back(std::move(out));
        animation_index_.emplace(node, index);
        return index;
    }

    // ---- spheres ----

    // Adds a sphere given in the coordinates of `node` after `instance`.
    void add_sphere(const std::string& name, int node, const Matrix4& instance, const FittedSphere& local,
                    std::uint32_t material) {
        const Matrix4 world = detail::multiply(world_[std::size_t(node)], instance);
        const AnimVec3 scales = detail::axis_scales(world);
        const double largest = std::max({scales[0], scales[1], scales[2]});
        const double smallest = std::min({scales[0], scales[1], scales[2]});
        if (largest - smallest > kUniformScaleTolerance * largest) non_uniform_.insert(node_label(model_, node));
        Sphere sphere;
        sphere.name = name;
        sphere.center = detail::transform_point(world, local.center);
        sphere.radius = local.radius * largest;
        sphere.material = material;
        if (!(sphere.radius > 0) || !std::isfinite(sphere.radius)) {
            diagnostics_.warn(name + ": radius " + std::to_string(sphere.radius) + " after transforms; left out");
            ++collapsed_spheres_;
            return;
        }
        if (moves_[std::size_t(node)]) {
            SphereBinding binding;
            binding.sphere = std::uint32_t(scene_.spheres.size());
            binding.node = animation_node(node);
            binding.center = detail::transform_point(instance, local.center);
            binding.radius = local.radius * detail::largest_axis_scale(instance);
            scene_.animation.spheres.push_back(binding);
        }
        scene_.spheres.push_back(std::move(sphere));
    }

    std::vector<Matrix4> instances_of(int node) {
        const tinygltf::Node& n = model_.nodes[std::size_t(node)];
        const tinygltf::Value* ext = extension(n.extensions, "EXT_mesh_gpu_instancing");
        if (!ext || !ext->IsObject() || !ext->Has("attributes")) return {kIdentityMatrix};
        const tinygltf::Value& attributes = ext->Get("attributes");
        const std::string label = node_label(model_, node) + " EXT_mesh_gpu_instancing";
        std::optional<AccessorValues> t, r, s;
        if (auto i = index_at(attributes, "TRANSLATION"))
            t = read_accessor(model_, *i, {TINYGLTF_TYPE_VEC3}, label + " TRANSLATION", diagnostics_);
        if (auto i = index_at(attributes, "ROTATION"))
            r = read_accessor(model_, *i, {TINYGLTF_TYPE_VEC4}, label + " ROTATION", diagnostics_);
        if (auto i = index_at(attributes, "SCALE"))
            s = read_accessor(model_, *i, {TINYGLTF_TYPE_VEC3}, label + " SCALE", diagnostics_);
        std::optional<std::size_t> count;
        for (const auto* a : {&t, &r, &s})
            if (a->has_value()) {
                if (count && *count != (*a)->count)
                    diagnostics_.fail(label + ": attributes have different counts");
                count = (*a)->count;
            }
        if (!count) return {kIdentityMatrix};
        std::vector<Matrix4> instances;
        instances.reserve(*count);
        for (std::size_t i = 0; i < *count; ++i) {
            AnimVec3 tv{0, 0, 0}, sv{1, 1, 1};
            Quaternion rv{0, 0, 0, 1};
            if (t) std::copy_n(t->element(i), 3, tv.begin());
            if (r) std::copy_n(r->element(i), 4, rv.begin());
            if (s) std::copy_n(s->element(i), 3, sv.begin());
            instances.push_back(detail::trs_matrix(tv, rv, sv));
        }
        return instances;
    }

    std::vector<AnimVec3> read_positions(int accessor, const std::string& what) {
        const AccessorValues values = read_accessor(model_, accessor, {TINYGLTF_TYPE_VEC3}, what, diagnostics_);
        std::vector<AnimVec3> points(values.count);
        for (std::size_t i = 0; i < values.count; ++i) std::copy_n(values.element(i), 3, points[i].begin());
        return points;
    }

    std::vector<AnimVec3> read_colors(const tinygltf::Primitive& primitive, std::size_t vertex_count,
                                      const std::string& what) {
        auto it = primitive.attributes.find("COLOR_0");
        if (it == primitive.attributes.end()) return {};
        const AccessorValues values =
            read_accessor(model_, it->second, {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, what + " COLOR_0", diagnostics_);
        if (values.count != vertex_count)
            diagnostics_.fail(what + ": COLOR_0 has " + std::to_string(values.count) + " entries for " +
                              std::to_string(vertex_count) + " vertices");
        std::vector<AnimVec3> colors(values.count);
        for (std::size_t i = 0; i < values.count; ++i) std::copy_n(values.element(i), 3, colors[i].begin());
        return colors;
    }

    static AnimVec3 mean_color(const std::vector<AnimVec3>& colors) {
        if (colors.empty()) return {1, 1, 1};
        AnimVec3 sum{0, 0, 0};
        for (const AnimVec3& c : colors)
            for (int k = 0; k < 3; ++k) sum[k] += c[k];
        for (double& v : sum) v /= double(colors.size());
        return sum;
    }

    const MeshContent& mesh_content(int mesh_index) {
        auto cached = mesh_cache_.find(mesh_index);
        if (cached != mesh_cache_.end()) return cached->second;
        const tinygltf::Mesh& mesh = model_.meshes[std::size_t(mesh_index)];
        const std::string mesh_name = mesh.name.empty() ? "mesh " + std::to_string(mesh_index) : "mesh '" + mesh.name + "'";
        MeshContent content;

        struct Surface {
            std::vector<AnimVec3> points;  // referenced vertices only
            std::vector<std::array<std::uint32_t, 3>> triangles;
            std::vector<AnimVec3> colors;
            std::map<int, std::vector<Uv>> texcoords;  // TEXCOORD_n that the material's textures read
            int material = -1;
        };
        std::vector<Surface> surfaces;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::string what = mesh_name + " primitive " + std::to_string(p);
            auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) {
                diagnostics_.warn(what + " has no POSITION; left out");
                ++primitives_without_position_;
                continue;
            }
            const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
            if (mode > TINYGLTF_MODE_TRIANGLE_FAN) diagnostics_.fail(what + ": unknown mode " + std::to_string(mode));
            std::vector<AnimVec3> positions = read_positions(position->second, what + " POSITION");
            std::vector<AnimVec3> colors = read_colors(primitive, positions.size(), what);
            std::map<int, std::vector<Uv>> texcoords;
            for (int set : textures_.texcoord_sets(primitive.material))
                if (auto uvs = read_texcoords(model_, primitive, set, positions.size(), what, diagnostics_); !uvs.empty())
                    texcoords.emplace(set, std::move(uvs));
            const std::vector<std::uint32_t> indices = read_indices(model_, primitive, positions.size(), what, diagnostics_);
            if (mode == TINYGLTF_MODE_POINTS) {
                if (!textures_.texcoord_sets(primitive.material).empty())
                    diagnostics_.lossy(what + ": POINTS take their material's factors; its textures are not read");
                MeshPoints points;
                points.material = primitive.material;
                auto radius = primitive.attributes.find("_RADIUS");
                std::vector<double> radii;
                if (radius != primitive.attributes.end()) {
                    const AccessorValues r =
                        read_accessor(model_, radius->second, {TINYGLTF_TYPE_SCALAR}, what + " _RADIUS", diagnostics_);
                    if (r.count != positions.size())
                        diagnostics_.fail(what + ": _RADIUS has " + std::to_string(r.count) + " entries for " +
                                          std::to_string(positions.size()) + " vertices");
                    radii = r.values;
                }
                for (std::uint32_t i : indices) {
                    points.positions.push_back(positions[i]);
                    if (!radii.empty()) points.radii.push_back(radii[i]);
                    if (!colors.empty()) points.colors.push_back(colors[i]);
                }
                content.points.push_back(std::move(points));
                continue;
            }
            // Keep only the vertices the primitive uses, renumbered.
            Surface surface;
            surface.material = primitive.material;
            std::vector<std::uint32_t> remap(positions.size(), std::numeric_limits<std::uint32_t>::max());
            std::vector<std::uint32_t> local_indices;
            local_indices.reserve(indices.size());
            for (std::uint32_t i : indices) {
                if (remap[i] == std::numeric_limits<std::uint32_t>::max()) {
                    remap[i] = std::uint32_t(surface.points.size());
                    surface.points.push_back(positions[i]);
                    if (!colors.empty()) surface.colors.push_back(colors[i]);
                    for (const auto& [set, uvs] : texcoords) surface.texcoords[set].push_back(uvs[i]);
                }
                local_indices.push_back(remap[i]);
            }
            if (mode >= TINYGLTF_MODE_TRIANGLES) surface.triangles = triangles_of(mode, local_indices);
            if (!surface.points.empty()) surfaces.push_back(std::move(surface));
        }

        // Lines (and triangle primitives without a whole triangle) are never spheres.
        auto not_a_sphere = [&](const std::vector<AnimVec3>& points, const MeshSphere& look) {
            content.has_non_spheres = true;
            if (options_.non_spheres == NonSpherePolicy::Error)
                diagnostics_.fail(mesh_name + " is not a sphere (--non-spheres error)");
            if (options_.non_spheres != NonSpherePolicy::Bound) return;
            MeshSphere bound = look;
            bound.shape = bounding_sphere(points);
            content.spheres.push_back(bound);
        };
        // All triangles of the mesh together, split into connected parts: one
        // sphere may span primitives (e.g. hemispheres in two materials) and
        // one primitive may hold several spheres.
        Surface all;
        std::vector<std::size_t> owner;  // surface of each point of `all`
        std::vector<std::uint32_t> first_point(surfaces.size(), 0);  // of each surface in `all`
        bool any_colors = false;
        for (std::size_t i = 0; i < surfaces.size(); ++i) {
            const Surface& s = surfaces[i];
            if (s.triangles.empty()) {
                not_a_sphere(s.points, {{}, s.material, mean_color(s.colors), !s.colors.empty(), {}});
                continue;
            }
            const auto offset = std::uint32_t(all.points.size());
            first_point[i] = offset;
            all.points.insert(all.points.end(), s.points.begin(), s.points.end());
            owner.insert(owner.end(), s.points.size(), i);
            for (auto t : s.triangles) all.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
            // Vertices without COLOR_0 count as white in the mean.
            if (s.colors.empty()) all.colors.insert(all.colors.end(), s.points.size(), AnimVec3{1, 1, 1});
            else all.colors.insert(all.colors.end(), s.colors.begin(), s.colors.end());
            any_colors = any_colors || !s.colors.empty();
        }
        const std::vector<SurfacePart> parts = connected_parts(all.points, all.triangles);
        // Each part's triangles of textured materials with their texture coordinates.
        std::vector<SpherePatch> patches(parts.size());
        if (textures_.active()) {
            std::vector<std::size_t> part_of(all.points.size(), parts.size());
            for (std::size_t k = 0; k < parts.size(); ++k)
                for (std::uint32_t v : parts[k].source_vertices) part_of[v] = k;
            std::vector<bool> textured(surfaces.size());
            for (std::size_t i = 0; i < surfaces.size(); ++i)
                textured[i] = !textures_.texcoord_sets(surfaces[i].material).empty();
            for (const auto& t : all.triangles) {
                const std::size_t o = owner[t[0]];
                if (part_of[t[0]] == parts.size() || !textured[o]) continue;
                patches[part_of[t[0]]].add(all.points, t, surfaces[o].material, surfaces[o].texcoords, first_point[o]);
            }
        }
        for (std::size_t part_index = 0; part_index < parts.size(); ++part_index) {
            const SurfacePart& part = parts[part_index];
            // The part takes the material of its first primitive.
            std::set<std::size_t> owners;
            AnimVec3 color_sum{0, 0, 0};
            for (std::uint32_t v : part.source_vertices) {
                owners.insert(owner[v]);
                for (int c = 0; c < 3; ++c) color_sum[c] += all.colors[v][c];
            }
            const Surface& first = surfaces[*owners.begin()];
            AnimVec3 color{1, 1, 1};
            if (any_colors)
                for (int c = 0; c < 3; ++c) color[c] = color_sum[c] / double(part.source_vertices.size());
            const MeshSphere look{{}, first.material, color, any_colors,
                                  textures_.sample(first.material, patches[part_index])};
            std::optional<FittedSphere> fit = fit_sphere(part.points, part.triangles, options_.sphere_tolerance);
            if (!fit) {
                not_a_sphere(part.points, look);
                continue;
            }
            for (std::size_t o : owners)
                if (surfaces[o].material != first.material) {
                    diagnostics_.warn(mesh_name + " is one sphere in several materials; the first material is used");
                    break;
                }
            MeshSphere sphere = look;
            sphere.shape = *fit;
            content.spheres.push_back(sphere);
        }
        return mesh_cache_.emplace(mesh_index, std::move(content)).first->second;
    }

    void add_mesh(int node, int mesh_index) {
        if (std::size_t(mesh_index) >= model_.meshes.size())
            diagnostics_.fail(node_label(model_, node) + ": mesh " + std::to_string(mesh_index) + " does not exist");
        const MeshContent& content = mesh_content(mesh_index);
        const tinygltf::Mesh& mesh = model_.meshes[std::size_t(mesh_index)];
        const tinygltf::Node& n = model_.nodes[std::size_t(node)];
        const std::string base = !n.name.empty() ? n.name : !mesh.name.empty() ? mesh.name : "node " + std::to_string(node);
        if (content.has_non_spheres && options_.non_spheres == NonSpherePolicy::Skip) {
            non_sphere_meshes_.emplace(mesh_index, mesh.name.empty() ? "mesh " + std::to_string(mesh_index) : mesh.name);
            non_spheres_.insert((mesh.name.empty() ? "mesh " + std::to_string(mesh_index) : "'" + mesh.name + "'") +
                                " (" + node_label(model_, node) + ")");
        }
        const std::vector<Matrix4> instances = instances_of(node);
        std::size_t per_instance = content.spheres.size();
        for (const MeshPoints& points : content.points) per_instance += points.positions.size();
        if (per_instance > 0 && (scene_.spheres.size() >= kMaxSpheres ||
                                 instances.size() > (kMaxSpheres - scene_.spheres.size()) / per_instance))
            diagnostics_.fail(node_label(model_, node) + ": " + std::to_string(instances.size()) + " instances of " +
                              std::to_string(per_instance) + " spheres exceed the limit of " +
                              std::to_string(kMaxSpheres) + " spheres");
        for (std::size_t i = 0; i < instances.size(); ++i) {
            const std::string instance_name = instances.size() > 1 ? base + "#" + std::to_string(i) : base;
            for (std::size_t k = 0; k < content.spheres.size(); ++k) {
                const MeshSphere& s = content.spheres[k];
                const std::string name =
                    content.spheres.size() > 1 ? instance_name + "." + std::to_string(k) : instance_name;
                const std::uint32_t material = materials_.get(s.material, s.color_scale, s.vertex_colors, &s.textures);
                add_sphere(name, node, instances[i], s.shape, material);
                if (s.textures.varies) averaged_textures_.add(name, scene_.materials[material].name);
            }
            for (const MeshPoints& points : content.points) add_points(instance_name, node, instances[i], points);
        }
    }

    void add_points(const std::string& name, int node, const Matrix4& instance, const MeshPoints& points) {
        const Matrix4 world = detail::multiply(world_[std::size_t(node)], instance);
        const double scale = detail::largest_axis_scale(world);
        double default_radius = options_.point_radius;
        if (!(default_radius > 0)) {
            // 1% of the primitive's world-space bounding-box diagonal.
            AnimVec3 lo{}, hi{};
            for (std::size_t i = 0; i < points.positions.size(); ++i) {
                const AnimVec3 p = detail::transform_point(world, points.positions[i]);
                for (int c = 0; c < 3; ++c) {
                    lo[c] = i == 0 ? p[c] : std::min(lo[c], p[c]);
                    hi[c] = i == 0 ? p[c] : std::max(hi[c], p[c]);
                }
            }
            const double diagonal = detail::length3({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
            default_radius = diagonal > 0 ? kDefaultPointRadiusFraction * diagonal : kDefaultPointRadiusFraction;
        }
        for (std::size_t i = 0; i < points.positions.size(); ++i) {
            FittedSphere local;
            local.center = points.positions[i];
            // _RADIUS is in the node's units; the default is in world units.
            local.radius = points.radii.empty() ? (scale > 0 ? default_radius / scale : 0.0) : points.radii[i];
            const AnimVec3 color = points.colors.empty() ? AnimVec3{1, 1, 1} : points.colors[i];
            add_sphere(name + ".point" + std::to_string(i), node, instance, local,
                       materials_.get(points.material, color, !points.colors.empty()));
        }
    }

    // KHR_implicit_shapes: the shapes live at the top level; nodes reference
    // them directly or through a KHR_physics_rigid_bodies collider/trigger.
    void add_implicit_shape(int node) {
        const tinygltf::Node& n = model_.nodes[std::size_t(node)];
        std::optional<int> shape;
        if (const tinygltf::Value* ext = extension(n.extensions, "KHR_implicit_shapes")) shape = index_at(*ext, "shape");
        if (const tinygltf::Value* ext = extension(n.extensions, "KHR_physics_rigid_bodies"); ext && !shape)
            for (const char* role : {"collider", "trigger"})
                if (ext->IsObject() && ext->Has(role) && ext->Get(role).Has("geometry") && !shape)
                    shape = index_at(ext->Get(role).Get("geometry"), "shape");
        if (!shape) return;
        const tinygltf::Value* shapes_ext = extension(model_.extensions, "KHR_implicit_shapes");
        if (!shapes_ext || !shapes_ext->IsObject() || !shapes_ext->Has("shapes") ||
            !shapes_ext->Get("shapes").IsArray() || std::size_t(*shape) >= shapes_ext->Get("shapes").ArrayLen())
            diagnostics_.fail(node_label(model_, node) + ": implicit shape " + std::to_string(*shape) + " does not exist");
        const tinygltf::Value& desc = shapes_ext->Get("shapes").Get(*shape);
        const std::string type = desc.Has("type") && desc.Get("type").IsString() ? desc.Get("type").Get<std::string>() : "";
        if (type != "sphere") {
            non_sphere_shapes_.push_back(type.empty() ? std::string("untyped") : type);
            non_spheres_.insert("implicit " + (type.empty() ? std::string("shape") : type) + " (" +
                                node_label(model_, node) + ")");
            return;
        }
        FittedSphere local;
        local.radius = desc.Has("sphere") ? number_at(desc.Get("sphere"), "radius").value_or(0.5) : 0.5;
        // Shapes carry no material: they get the default grey.
        add_sphere(n.name.empty() ? "shape " + std::to_string(*shape) : n.name, node, kIdentityMatrix, local,
                   materials_.get(-1));
    }

    void add_node_content(int node) {
        const tinygltf::Node& n = model_.nodes[std::size_t(node)];
        if (n.mesh >= 0) add_mesh(node, n.mesh);
        add_implicit_shape(node);
        if (const tinygltf::Value* ext = extension(n.extensions, "KHR_lights_punctual")) {
            const std::optional<int> light = index_at(*ext, "light");
            if (!light || std::size_t(*light) >= model_.lights.size())
                diagnostics_.fail(node_label(model_, node) + ": KHR_lights_punctual light does not exist");
            lights_.emplace_back(node, *light);
        }
        if (n.camera >= 0) {
            if (std::size_t(n.camera) >= model_.cameras.size())
                diagnostics_.fail(node_label(model_, node) + ": camera " + std::to_string(n.camera) + " does not exist");
            cameras_.emplace_back(node, n.camera);
        }
    }

    // ---- lights ----

    double scene_diagonal() const {
        AnimVec3 lo{}, hi{};
        bool any = false;
        auto add = [&](const AnimVec3& p, double r) {
            for (int c = 0; c < 3; ++c) {
                lo[c] = any ? std::min(lo[c], p[c] - r) : p[c] - r;
                hi[c] = any ? std::max(hi[c], p[c] + r) : p[c] + r;
            }
            any = true;
        };
        for (const Sphere& s : scene_.spheres) add(s.center, s.radius);
        for (const auto& [node, light] : lights_) add(detail::transform_point(world_[std::size_t(node)], {0, 0, 0}), 0);
        const double diagonal = any ? detail::length3({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) : 0.0;
        return diagonal > 0 && std::isfinite(diagonal) ? diagonal : 1.0;
    }

    void add_light(int node, int light_index, double diagonal) {
        const tinygltf::Light& light = model_.lights[std::size_t(light_index)];
        const std::string name = !light.name.empty() ? light.name : "light " + std::to_string(light_index);
        const std::string label = "light '" + name + "'";
        Vec3 color{1, 1, 1};
        if (light.color.size() == 3) std::copy(light.color.begin(), light.color.end(), color.begin());
        for (double c : color)
            if (!(c >= 0) || !std::isfinite(c)) diagnostics_.fail(label + ": color must be finite and >= 0");
        if (!(light.intensity >= 0) || !std::isfinite(light.intensity))
            diagnostics_.fail(label + ": intensity must be finite and >= 0");
        // Radiant intensity (W/sr) for point/spot lights, irradiance (W/m^2) for directional ones.
        const double radiant = light.intensity * watts_per_lumen(options_.light_units);
        const Vec3 power{color[0] * radiant, color[1] * radiant, color[2] * radiant};
        const Matrix4& world = world_[std::size_t(node)];

        if (light.type == "directional") {
            if (!options_.directional_lights) {
                diagnostics_.lossy(label + " is directional and was left out (--directional-lights adds a distant emitter)");
                return;
            }
            // Light travels down the node's -z: the emitter sits up its +z, far away.
            AnimVec3 toward = detail::transform_direction(world, {0, 0, 1});
            const double length = detail::length3(toward);
            if (!(length > 0)) diagnostics_.fail(label + ": its node's transform collapses its direction");
            for (double& c : toward) c /= length;
            const double distance = kDistantLightDistance * diagonal;
            const double radius = kDistantLightRadiusFraction * distance;
            AnimVec3 center = scene_center();
            for (int c = 0; c < 3; ++c) center[c] += toward[c] * distance;
            Sphere sphere;
            sphere.name = name;
            sphere.center = center;
            sphere.radius = radius;
            sphere.material = materials_.emitter(name, distant_light_radiance(power, radius, distance));
            if (moves_[std::size_t(node)]) diagnostics_.lossy(label + ": directional lights do not follow animation");
            distant_.insert(scene_.spheres.size());
            scene_.spheres.push_back(std::move(sphere));
            return;
        }
        if (light.type != "point" && light.type != "spot")
            diagnostics_.fail(label + ": unknown type '" + light.type + "'");
        // Spot lights shine every way; range is ignored (light falls off with the inverse square).
        if (light.type == "spot") ignored_.add_spot_cone();
        if (light.range > 0) ignored_.add_range();
        const double radius = options_.light_radius > 0 ? options_.light_radius : kDefaultLightRadiusFraction * diagonal;
        // The radius is in world units whatever the node's scale.
        const double scale = detail::largest_axis_scale(world);
        if (!(scale > 0)) {
            diagnostics_.warn(label + ": its node has zero scale; left out");
            return;
        }
        FittedSphere local;
        local.radius = radius / scale;
        add_sphere(name, node, kIdentityMatrix, local, materials_.emitter(name, point_light_radiance(power, radius)));
    }

    // Centre of the bounds of the scene's spheres, leaving out the distant
    // directional-light emitters (they would drag it 100 diagonals away).
    AnimVec3 scene_center() const {
        AnimVec3 lo{}, hi{};
        bool any = false;
        for (std::size_t i = 0; i < scene_.spheres.size(); ++i) {
            if (distant_.count(i)) continue;
            const Sphere& s = scene_.spheres[i];
            for (int c = 0; c < 3; ++c) {
                lo[c] = any ? std::min(lo[c], s.center[c] - s.radius) : s.center[c] - s.radius;
                hi[c] = any ? std::max(hi[c], s.center[c] + s.radius) : s.center[c] + s.radius;
            }
            any = true;
        }
        if (!any) return {0, 0, 0};
        return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    }

    // ---- camera ----

    void choose_camera() {
        std::optional<std::pair<int, int>> chosen;  // node, camera
        if (!options_.camera.empty()) {
            const std::optional<int> camera = find_by_index_or_name(model_.cameras, options_.camera);
            for (const auto& candidate : cameras_) {
                const bool by_camera = camera && candidate.second == *camera;
                const bool by_node = !camera && model_.nodes[std::size_t(candidate.first)].name == options_.camera;
                if (by_camera || by_node) {
                    chosen = candidate;
                    break;
                }
            }
            if (!chosen)
                diagnostics_.fail("--camera " + options_.camera + ": no camera with that index or name (camera or node) "
                                  "is placed in the scene (it has " + std::to_string(cameras_.size()) + " camera nodes)");
        } else if (!cameras_.empty()) {
            chosen = cameras_.front();
        }
        if (!chosen) {
            automatic_camera(scene_, distant_);
            return;
        }
        const auto [node, camera_index] = *chosen;
        const tinygltf::Camera& camera = model_.cameras[std::size_t(camera_index)];
        const std::string name = !camera.name.empty() ? camera.name : "camera " + std::to_string(camera_index);
        convert_camera(camera, name, world_[std::size_t(node)], scene_center(), scene_, diagnostics_);
        if (moves_[std::size_t(node)]) scene_.animation.camera_node = std::int32_t(animation_node(node));
    }

    // ---- summaries ----

    void report_non_spheres() {
        if (non_spheres_.empty()) return;
        std::string list;
        std::size_t shown = 0;
        for (const std::string& name : non_spheres_) {
            if (shown++ == 10) {
                list += ", ... (" + std::to_string(non_spheres_.size()) + " in all)";
                break;
            }
            list += (list.empty() ? "" : ", ") + name;
        }
        diagnostics_.lossy("not spheres, left out (--non-spheres bound|error to change): " + list);
    }

    // What an asset that gave no sphere of its own left out, and why:
    // "3 meshes are not spheres (Suzanne, Cube, Cone)".
    std::string why_no_spheres(std::size_t light_spheres) const {
        auto counted = [](std::size_t n, const char* one, const char* many) {
            return std::to_string(n) + " " + (n == 1 ? one : many);
        };
        auto some_names = [](const auto& names) {
            std::string list;
            std::size_t shown = 0;
            for (const std::string& name : names) {
                if (shown++ == 5) return list + ", ...";
                list += (list.empty() ? "" : ", ") + name;
            }
            return list;
        };
        std::vector<std::string> reasons;
        if (!non_sphere_meshes_.empty()) {
            std::vector<std::string> names;
            for (const auto& [index, name] : non_sphere_meshes_) names.push_back(name);
            reasons.push_back(counted(names.size(), "mesh is not a sphere", "meshes are not spheres") + " (" +
                              some_names(names) + ")");
        }
        if (!non_sphere_shapes_.empty())
            reasons.push_back(counted(non_sphere_shapes_.size(), "implicit shape is not a sphere",
                                      "implicit shapes are not spheres") + " (" + some_names(non_sphere_shapes_) + ")");
        if (primitives_without_position_ > 0)
            reasons.push_back(counted(primitives_without_position_, "primitive has", "primitives have") + " no POSITION");
        if (collapsed_spheres_ > 0)
            reasons.push_back(counted(collapsed_spheres_, "sphere has", "spheres have") +
                              " no size after its node's transforms");
        if (reasons.empty()) {
            if (model_.meshes.empty()) reasons.push_back("the asset has no meshes");
            else
                reasons.push_back("the imported scene uses none of the asset's " +
                                  counted(model_.meshes.size(), "mesh", "meshes"));
        }
        std::string text;
        for (const std::string& reason : reasons) text += (text.empty() ? "" : "; ") + reason;
        if (light_spheres > 0)
            text += "; only the stand-ins of " + counted(light_spheres, "light", "lights") + " are left";
        return text;
    }

    void report_ignored() {
        for (int material : materials_.used())
            ignored_.add_material(model_.materials[std::size_t(material)], textures_.active());
        const std::string summary = ignored_.summary(model_);
        if (!summary.empty()) diagnostics_.lossy(summary);
    }

    void report_scales() {
        if (non_uniform_.empty()) return;
        std::string list;
        for (const std::string& name : non_uniform_) list += (list.empty() ? "" : ", ") + name;
        diagnostics_.lossy("non-uniform scale on spheres under " + list + "; the largest axis sets the radius");
    }

    const tinygltf::Model& model_;
    const GltfImportOptions& options_;
    Diagnostics& diagnostics_;
    Scene scene_;
    MaterialTable materials_;
    std::map<int, std::vector<AnimationChannel>> channels_;
    std::vector<int> parent_;
    std::vector<Matrix4> world_;
    std::vector<bool> moves_;
    std::vector<int> order_;
    std::map<int, std::uint32_t> animation_index_;
    std::map<int, MeshContent> mesh_cache_;
    std::vector<std::pair<int, int>> lights_;
    std::vector<std::pair<int, int>> cameras_;
    std::set<std::string> non_spheres_;
    std::map<int, std::string> non_sphere_meshes_;  // mesh index -> name, for the no-spheres reason
    std::vector<std::string> non_sphere_shapes_;    // KHR_implicit_shapes types other than sphere
    std::size_t primitives_without_position_ = 0;
    std::size_t collapsed_spheres_ = 0;  // radius 0 (or not finite) after transforms
    std::string no_spheres_;
    std::set<std::string> non_uniform_;
    IgnoredFeatures ignored_;
    TextureReader textures_;
    AveragedTextures averaged_textures_;
    std::set<std::size_t> distant_;  // scene_.spheres indices of directional-light emitters
};

}  // namespace
}  // namespace orb::gltf

namespace orb {

GltfImportResult import_gltf(std::string_view bytes, const std::string& source, const std::string& base_dir,
                             const GltfImportOptions& options) {
    if (!(options.sphere_tolerance >= 0) || !std::isfinite(options.sphere_tolerance))
        throw InputError(source + ": the sphere tolerance must be a finite number >= 0");
    gltf::Diagnostics diagnostics(source, options.strict);
    const tinygltf::Model model = gltf::load_model(bytes, source, base_dir);
    GltfImportResult result;
    gltf::Importer importer(model, options, diagnostics);
    result.scene = importer.run();
    result.no_spheres = importer.no_spheres();
    if (options.default_light) gltf::add_default_light(result.scene, source, result.notices);
    // The same checks the JSON loader applies: an importer never hands on
    // a scene that could not be written and read back.
    validate_scene(result.scene, source);
    result.warnings = diagnostics.take_warnings();
    return result;
}

}  // namespace orb
