#include "scene_layout.h"

#include "alias_table.h"
#include "environment_layout.h"
#include "sphere_bvh.h"

#include "orb/scene/camera_frame.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <stdexcept>
#include <string>

namespace orb::render {
namespace {

// Spheres through which light reaches surfaces only along BSDF-sampled paths:
// materials without a density (kernels/caustic_casters.cl). Roughness exactly
// 0 rather than the kernels' smoothness threshold: any set of casters keeps
// the estimator unbiased, so the rule only has to pick the spheres worth
// aiming at.
// Each kind's rule is the CASTER_RULE column of ORB_MATERIAL_TABLE.
bool is_caustic_caster(const device::MaterialRecord& m)
{
    switch (static_cast<device::MaterialKind>(m.kind)) {
#define ORB_CASTER_CASE(member, value, name, scn_word, prefix, caster_rule) \
    case device::MaterialKind::member: return caster_rule(m.roughness, m.metallic);
        ORB_MATERIAL_TABLE(ORB_CASTER_CASE)
#undef ORB_CASTER_CASE
    }
    return false;
}

// The scene model's MaterialType and the device's MaterialKind are two enums
// generated from the same table; the record carries the value, so each row
// must give both the table's value.
#define ORB_SAME_KIND_VALUE(member, value, name, scn_word, prefix, caster_rule)                  \
    static_assert(static_cast<int>(MaterialType::member) == (value) &&                           \
                      static_cast<int>(device::MaterialKind::member) == (value),                 \
                  "MaterialType::" #member " and device::MaterialKind::" #member " differ");
ORB_MATERIAL_TABLE(ORB_SAME_KIND_VALUE)
#undef ORB_SAME_KIND_VALUE

device::MaterialKind device_kind(MaterialType type) { return static_cast<device::MaterialKind>(static_cast<int>(type)); }

float f(double value) { return static_cast<float>(value); }

device::float4 to_float4(const Vec3& a, double w) { return {f(a[0]), f(a[1]), f(a[2]), f(w)}; }

// Lane `lane` of a packet's or a node's float4 or int4.
template <typename Vector>
auto& lane_of(Vector& v, std::size_t lane)
{
    decltype(&v.x) lanes[4] = {&v.x, &v.y, &v.z, &v.w};
    return *lanes[lane];
}

device::MaterialRecord material_record(const Material& material)
{
    device::MaterialRecord record{};
    record.color = to_float4(material.color, 0.0);
    record.emission = to_float4(material.emission, 0.0);
    record.ior = f(material.ior);
    record.kind = static_cast<int>(device_kind(material.type));
    record.roughness = f(material.roughness);
    record.metallic = f(material.metallic);
    return record;
}

}  // namespace

namespace {

void check_sphere(const Scene& scene, std::size_t i) {
    const Sphere& sphere = scene.spheres[i];
    const std::string which = "sphere " + std::to_string(i) + (sphere.name.empty() ? "" : " ('" + sphere.name + "')");
    if (!(sphere.radius > 0.0) || !std::isfinite(sphere.radius))
        throw std::runtime_error(which + " has radius " + std::to_string(sphere.radius) +
                                 "; a positive, finite radius is required");
    if (sphere.material >= scene.materials.size())
        throw std::runtime_error(which + " uses material " + std::to_string(sphere.material) + " but the scene has " +
                                 std::to_string(scene.materials.size()) + " materials");
}

// A node with every lane empty: an inverted box (sphere_bvh.h, device_types.h),
// and a child no ray reaches (a harmless leaf, were one ever to).
device::BvhNodeRecord empty_node_record() {
    device::BvhNodeRecord record{};
    constexpr float big = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        record.bounds[axis] = {big, big, big, big};
        record.bounds[axis + 3] = {-big, -big, -big, -big};
    }
    record.child = {-1, -1, -1, -1};
    record.leaf_run = {-1, 0, 0, 0};
    return record;
}

}  // namespace

std::uint32_t pack_sphere_color(float red, float green, float blue)
{
    auto root = [](float component, std::uint32_t max) {
        const float clamped = std::clamp(component, 0.0f, 1.0f);  // validate_scene keeps them there; NaN -> 0
        return static_cast<std::uint32_t>(std::lround(std::sqrt(clamped) * static_cast<float>(max)));
    };
    return root(red, ORB_SPHERE_COLOR_RED_MAX) | root(green, ORB_SPHERE_COLOR_GREEN_MAX) << ORB_SPHERE_COLOR_GREEN_SHIFT |
           root(blue, ORB_SPHERE_COLOR_BLUE_MAX) << ORB_SPHERE_COLOR_BLUE_SHIFT;
}

SphereBvh scene_bvh(const Scene& scene, bool use_bvh)
{
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) check_sphere(scene, i);
    BvhSettings settings;
    if (!use_bvh) settings.min_spheres_for_tree = std::numeric_limits<std::size_t>::max();
    return build_sphere_bvh(scene.spheres, settings);
}

SceneLayout layout_scene(const Scene& scene, bool use_bvh) { return layout_scene(scene, scene_bvh(scene, use_bvh)); }

SceneLayout layout_scene(const Scene& scene, const SphereBvh& bvh)
{
    SceneLayout layout;
    SceneTables& tables = layout.tables;
    const std::size_t sphere_count = scene.spheres.size();
    for (std::size_t i = 0; i < sphere_count; ++i) check_sphere(scene, i);

    // Slots: the outside spheres packed four to a packet, then one packet per leaf.
    const std::size_t outside_packets = (bvh.outside.size() + 3) / 4;
    std::size_t leaves = 0;
    for (const BvhNode& node : bvh.nodes)
        for (std::uint32_t k = 0; k < node.child_count; ++k) leaves += node.children[k].leaf();
    const std::size_t packet_count = std::max<std::size_t>(outside_packets + leaves, sphere_count ? 1 : 0);
    // Unused lanes: radius^2 = -1 makes the discriminant negative, so they never hit.
    const device::float4 empty_lanes{0.0f, 0.0f, 0.0f, -1.0f};
    tables.packets.assign(packet_count, device::SpherePacket{{}, {}, {}, empty_lanes});
    device::SphereRecord unused{};
    unused.scene_index = -1;
    tables.spheres.assign(packet_count * 4, unused);
    tables.materials.reserve(scene.materials.size());
    for (const Material& material : scene.materials) tables.materials.push_back(material_record(material));

    for (const Sphere& sphere : scene.spheres) {
        const device::MaterialRecord& material = tables.materials[sphere.material];
        layout.material_kinds |= 1u << material.kind;
        layout.rough_dielectric |= material.kind == static_cast<int>(device::MaterialKind::Dielectric) && material.roughness > 0.0f;
    }

    // Colours for every sphere or for none (validate_scene); the renderer does not assume it.
    if (!scene.sphere_attributes.colors.empty()) {
        if (scene.sphere_attributes.colors.size() != 3 * sphere_count)
            throw std::runtime_error("the scene has " + std::to_string(scene.sphere_attributes.colors.size() / 3) +
                                     " sphere colours for " + std::to_string(sphere_count) + " spheres");
        layout.sphere_colors = true;
    }
    std::vector<int> slot_of(sphere_count, -1);
    auto place = [&](std::uint32_t scene_index, std::size_t slot) {
        const Sphere& sphere = scene.spheres[scene_index];
        device::SpherePacket& packet = tables.packets[slot / 4];
        const std::size_t lane = slot % 4;
        lane_of(packet.centre_x, lane) = f(sphere.center[0]);
        lane_of(packet.centre_y, lane) = f(sphere.center[1]);
        lane_of(packet.centre_z, lane) = f(sphere.center[2]);
        lane_of(packet.radius2, lane) = f(sphere.radius * sphere.radius);
        device::SphereRecord& record = tables.spheres[slot];
        record.centre_radius = to_float4(sphere.center, sphere.radius);
        record.material = static_cast<int>(sphere.material);
        record.scene_index = static_cast<int>(scene_index);
        if (layout.sphere_colors) {
            const float* rgb = &scene.sphere_attributes.colors[3 * std::size_t{scene_index}];
            record.color = pack_sphere_color(rgb[0], rgb[1], rgb[2]);
        }
        slot_of[scene_index] = static_cast<int>(slot);
    };
    for (std::size_t k = 0; k < bvh.outside.size(); ++k) place(bvh.outside[k], k);

    // The kernels' stack holds what this tree can defer (checked, not assumed).
    if (bvh_stack_bound(bvh) > ORB_BVH_STACK_SIZE)
        throw std::logic_error("BVH traversal would need " + std::to_string(bvh_stack_bound(bvh)) +
                               " stack entries; the device has " + std::to_string(ORB_BVH_STACK_SIZE));
    // A node's leaves get consecutive packets, in node order, so the spheres
    // a node's visit may test next lie together.
    tables.bvh_nodes.reserve(bvh.nodes.size());
    std::size_t next_leaf_packet = outside_packets;
    for (const BvhNode& node : bvh.nodes) {
        device::BvhNodeRecord record = empty_node_record();
        bool only_leaves = node.child_count > 0;
        for (std::uint32_t k = 0; k < node.child_count; ++k) only_leaves = only_leaves && node.children[k].leaf();
        if (only_leaves) record.leaf_run = {static_cast<int>(next_leaf_packet), static_cast<int>(node.child_count), 0, 0};
        for (std::uint32_t k = 0; k < node.child_count; ++k) {
            const BvhChild& child = node.children[k];
            for (int axis = 0; axis < 3; ++axis) {
                lane_of(record.bounds[axis], k) = child.lo[axis];
                lane_of(record.bounds[axis + 3], k) = child.hi[axis];
            }
            if (child.leaf()) {
                const std::size_t packet = next_leaf_packet++;
                for (std::uint32_t lane = 0; lane < child.count; ++lane)
                    place(bvh.order[child.first + lane], packet * 4 + lane);
                lane_of(record.child, k) = -1 - static_cast<int>(packet);
            } else {
                lane_of(record.child, k) = static_cast<int>(child.first);
            }
        }
        tables.bvh_nodes.push_back(record);
    }

    EnvironmentLayout environment = layout_environment(scene.environment);
    tables.environment_texels = std::move(environment.texels);
    tables.environment_cdf = std::move(environment.cdf);
    layout.environment = environment.params;

    // Sphere lights are picked by power, Phi = pi * area * radiance, with the
    // mean of the three channels as radiance (constants cancel in the shares).
    std::vector<double> weight;
    double sphere_power = 0;
    for (std::size_t i = 0; i < sphere_count; ++i) {
        const Sphere& sphere = scene.spheres[i];
        const Vec3& e = scene.materials[sphere.material].emission;
        if (!(e[0] > 0.0 || e[1] > 0.0 || e[2] > 0.0)) continue;
        tables.lights.push_back({slot_of[i], 0.0f, 1.0f, 0});
        weight.push_back(sphere.radius * sphere.radius * (e[0] + e[1] + e[2]));
        sphere_power += weight.back();
    }
    // The environment is the last light, with its fixed share of the picks.
    if (environment.emits) {
        const double share = weight.empty() ? 1.0 : kEnvironmentLightShare;
        for (double& w : weight) w *= (1.0 - share) / sphere_power;
        tables.lights.push_back({-1, 0.0f, 1.0f, 0});
        weight.push_back(share);
    }
    if (!weight.empty()) {
        const AliasTable pick = build_alias_table(weight);
        for (std::size_t k = 0; k < tables.lights.size(); ++k) {
            device::LightRecord& light = tables.lights[k];
            light.probability = pick.probability[k];
            light.alias_threshold = pick.slots[k].threshold;
            light.alias = static_cast<int>(pick.slots[k].alias);
            if (light.sphere >= 0)
                tables.spheres[static_cast<std::size_t>(light.sphere)].light_probability = light.probability;
            else
                layout.environment.light_probability = light.probability;
            layout.uniform_lights = layout.uniform_lights && light.probability == pick.probability[0];
        }
    }
    layout.counts.packet_count = static_cast<int>(packet_count);
    layout.counts.sphere_count = static_cast<int>(packet_count * 4);
    layout.counts.light_count = static_cast<int>(tables.lights.size());
    layout.counts.outside_packet_count = static_cast<int>(outside_packets);
    layout.counts.bvh_node_count = static_cast<int>(tables.bvh_nodes.size());

    for (const Sphere& sphere : scene.spheres)
        if (is_caustic_caster(tables.materials[sphere.material]))
            tables.casters.push_back({to_float4(sphere.center, sphere.radius)});
    if (tables.casters.size() > kMaxCausticCasters) tables.casters.clear();
    layout.counts.caster_count = static_cast<int>(tables.casters.size());
    return layout;
}

device::CameraParams layout_camera(const Camera& camera, int width, int height)
{
    // One frame, view and lens for the image and the EXR's camera matrices (orb/scene/camera_frame.h).
    const CameraFrame frame = camera_frame(camera);
    const ViewExtents view = view_extents(camera, width, height);
    const CameraLens lens = camera_lens(camera, frame);

    device::CameraParams params{};
    params.origin = to_float4(camera.position, 0.0);
    params.right = to_float4(frame.right, 0.0);
    params.up = to_float4(frame.up, 0.0);
    params.forward = to_float4(frame.forward, 0.0);
    params.half_width = f(view.half_width);
    params.half_height = f(view.half_height);
    params.lens_radius = f(lens.radius);
    params.focus_distance = f(lens.focus_distance);
    params.projection = static_cast<int>(view.orthographic ? device::CameraProjection::Orthographic
                                                           : device::CameraProjection::Perspective);
    return params;
}

}  // namespace orb::render
