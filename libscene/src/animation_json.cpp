// The "animation" section of the canonical scene JSON (docs/scene-format.md).
#include "animation_json.h"

#include <cmath>

#include "json_reader.h"
#include "float_limits.h"
#include "orb/scene/detail/json_text.h"
#include "orb/scene/error.h"

namespace orb::detail {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

const char* path_name(AnimationPath path) {
    switch (path) {
        case AnimationPath::Translation: return "translation";
        case AnimationPath::Rotation: return "rotation";
        case AnimationPath::Scale: return "scale";
    }
    return "translation";
}

const char* interpolation_name(Interpolation interpolation) {
    switch (interpolation) {
        case Interpolation::Linear: return "LINEAR";
        case Interpolation::Step: return "STEP";
        case Interpolation::CubicSpline: return "CUBICSPLINE";
    }
    return "LINEAR";
}

// Keyframe and rest values end up in the renderer's floats once posed, so
// they keep to the scene's coordinate limit (the posed scene is checked
// again by whoever poses it, since products of scales can still grow).
template <std::size_t N>
void require_magnitude(const JsonReader& r, const std::array<double, N>& values, const std::string& path) {
    for (double d : values)
        if (!std::isfinite(d)) r.fail(path, "expected finite numbers");
    for (double d : values)
        if (!within_magnitude(d)) r.fail(path, magnitude_rule() + kFloatReason + format_number(d));
}

std::size_t component_count(AnimationPath path) { return path == AnimationPath::Rotation ? 4 : 3; }

ordered_json numbers(const double* values, std::size_t count) {
    ordered_json array = ordered_json::array();
    for (std::size_t i = 0; i < count; ++i) array.push_back(values[i]);
    return array;
}

using Reader = JsonReader;

std::string at(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

AnimationChannel read_channel(const Reader& r, const json& value, const std::string& path) {
    r.object(value, path);
    r.only_keys(value, path, {"path", "interpolation", "times", "values"});
    AnimationChannel channel;
    const std::string target = r.string(r.member(value, path, "path"), path + ".path");
    if (target == "translation") channel.path = AnimationPath::Translation;
    else if (target == "rotation") channel.path = AnimationPath::Rotation;
    else if (target == "scale") channel.path = AnimationPath::Scale;
    else r.fail(path + ".path", "expected \"translation\", \"rotation\" or \"scale\", got \"" + target + "\"");
    const std::string mode =
        value.contains("interpolation") ? r.string(value["interpolation"], path + ".interpolation") : "LINEAR";
    if (mode == "LINEAR") channel.interpolation = Interpolation::Linear;
    else if (mode == "STEP") channel.interpolation = Interpolation::Step;
    else if (mode == "CUBICSPLINE") channel.interpolation = Interpolation::CubicSpline;
    else r.fail(path + ".interpolation", "expected \"LINEAR\", \"STEP\" or \"CUBICSPLINE\", got \"" + mode + "\"");
    const json& times = r.array(r.member(value, path, "times"), path + ".times");
    for (std::size_t i = 0; i < times.size(); ++i) channel.times.push_back(r.number(times[i], at(path + ".times", i)));
    const json& values = r.array(r.member(value, path, "values"), path + ".values");
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::string value_path = at(path + ".values", i);
        if (channel.path == AnimationPath::Rotation) {
            channel.values.push_back(r.numbers<4>(values[i], value_path));
        } else {
            const auto v = r.numbers<3>(values[i], value_path);
            channel.values.push_back({v[0], v[1], v[2], 0.0});
        }
    }
    return channel;
}

AnimationNode read_node(const Reader& r, const json& value, const std::string& path) {
    r.object(value, path);
    r.only_keys(value, path, {"name", "parent", "matrix", "translation", "rotation", "scale", "channels"});
    AnimationNode node;
    if (value.contains("name")) node.name = r.string(value["name"], path + ".name");
    if (value.contains("parent")) {
        const std::int64_t parent = r.integer(value["parent"], path + ".parent");
        if (parent < -1 || parent > INT32_MAX) r.fail(path + ".parent", "out of range");
        node.parent = std::int32_t(parent);
    }
    if (value.contains("matrix")) {
        for (const char* key : {"translation", "rotation", "scale", "channels"})
            if (value.contains(key))
                r.fail(path + "." + key, "a node with \"matrix\" cannot also have \"" + std::string(key) + "\"");
        node.has_matrix = true;
        node.matrix = r.numbers<16>(value["matrix"], path + ".matrix");
    }
    if (value.contains("translation")) node.translation = r.numbers<3>(value["translation"], path + ".translation");
    if (value.contains("rotation")) node.rotation = r.numbers<4>(value["rotation"], path + ".rotation");
    if (value.contains("scale")) node.scale = r.numbers<3>(value["scale"], path + ".scale");
    if (value.contains("channels")) {
        const json& channels = r.array(value["channels"], path + ".channels");
        for (std::size_t i = 0; i < channels.size(); ++i)
            node.channels.push_back(read_channel(r, channels[i], at(path + ".channels", i)));
    }
    return node;
}

SphereBinding read_binding(const Reader& r, const json& value, const std::string& path) {
    r.object(value, path);
    r.only_keys(value, path, {"sphere", "node", "center", "radius"});
    SphereBinding binding;
    const std::int64_t sphere = r.integer(r.member(value, path, "sphere"), path + ".sphere");
    const std::int64_t node = r.integer(r.member(value, path, "node"), path + ".node");
    if (sphere < 0 || sphere > UINT32_MAX) r.fail(path + ".sphere", "must be a sphere index >= 0");
    if (node < 0 || node > UINT32_MAX) r.fail(path + ".node", "must be a node index >= 0");
    binding.sphere = std::uint32_t(sphere);
    binding.node = std::uint32_t(node);
    binding.center = r.numbers<3>(r.member(value, path, "center"), path + ".center");
    binding.radius = r.number(r.member(value, path, "radius"), path + ".radius");
    return binding;
}

}  // namespace

nlohmann::ordered_json animation_to_json(const Animation& animation) {
    if (animation.empty()) return nullptr;
    ordered_json nodes = ordered_json::array();
    for (const AnimationNode& node : animation.nodes) {
        ordered_json n = ordered_json::object();
        if (!node.name.empty()) n["name"] = node.name;
        if (node.parent >= 0) n["parent"] = node.parent;
        if (node.has_matrix) {
            n["matrix"] = numbers(node.matrix.data(), 16);
        } else {
            n["translation"] = numbers(node.translation.data(), 3);
            n["rotation"] = numbers(node.rotation.data(), 4);
            n["scale"] = numbers(node.scale.data(), 3);
        }
        if (!node.channels.empty()) {
            ordered_json channels = ordered_json::array();
            for (const AnimationChannel& channel : node.channels) {
                ordered_json c = ordered_json::object();
                c["path"] = path_name(channel.path);
                c["interpolation"] = interpolation_name(channel.interpolation);
                c["times"] = numbers(channel.times.data(), channel.times.size());
                ordered_json values = ordered_json::array();
                for (const auto& v : channel.values) values.push_back(numbers(v.data(), component_count(channel.path)));
                c["values"] = std::move(values);
                channels.push_back(std::move(c));
            }
            n["channels"] = std::move(channels);
        }
        nodes.push_back(std::move(n));
    }
    ordered_json document = ordered_json::object();
    document["nodes"] = std::move(nodes);
    if (!animation.spheres.empty()) {
        ordered_json spheres = ordered_json::array();
        for (const SphereBinding& b : animation.spheres) {
            ordered_json s = ordered_json::object();
            s["sphere"] = b.sphere;
            s["node"] = b.node;
            s["center"] = numbers(b.center.data(), 3);
            s["radius"] = b.radius;
            spheres.push_back(std::move(s));
        }
        document["spheres"] = std::move(spheres);
    }
    if (animation.camera_node >= 0) document["camera"] = ordered_json{{"node", animation.camera_node}};
    return document;
}

Animation animation_from_json(const nlohmann::json& value, const std::string& path, const std::string& source) {
    const Reader r(source);
    Animation animation;
    if (value.is_null()) return animation;
    r.object(value, path);
    r.only_keys(value, path, {"nodes", "spheres", "camera"});
    const json& nodes = r.array(r.member(value, path, "nodes"), path + ".nodes");
    for (std::size_t i = 0; i < nodes.size(); ++i) animation.nodes.push_back(read_node(r, nodes[i], at(path + ".nodes", i)));
    if (value.contains("spheres")) {
        const json& spheres = r.array(value["spheres"], path + ".spheres");
        for (std::size_t i = 0; i < spheres.size(); ++i)
            animation.spheres.push_back(read_binding(r, spheres[i], at(path + ".spheres", i)));
    }
    if (value.contains("camera")) {
        const std::string camera_path = path + ".camera";
        const json& camera = r.object(value["camera"], camera_path);
        r.only_keys(camera, camera_path, {"node"});
        const std::int64_t node = r.integer(r.member(camera, camera_path, "node"), camera_path + ".node");
        if (node < 0 || node > INT32_MAX) r.fail(camera_path + ".node", "must be a node index >= 0");
        animation.camera_node = std::int32_t(node);
    }
    return animation;
}

void validate_animation(const Animation& animation, std::size_t sphere_count, const std::string& source) {
    const Reader r(source);
    if (animation.empty()) {
        if (!animation.spheres.empty() || animation.camera_node >= 0)
            r.fail("animation.nodes", "bindings need at least one node");
        return;
    }
    const std::size_t node_count = animation.nodes.size();
    for (std::size_t i = 0; i < node_count; ++i) {
        const AnimationNode& node = animation.nodes[i];
        const std::string path = at("animation.nodes", i);
        if (node.parent < -1 || (node.parent >= 0 && std::size_t(node.parent) >= i))
            r.fail(path + ".parent", "must be -1 or the index of an earlier node, got " + std::to_string(node.parent));
        require_magnitude(r, node.matrix, path + ".matrix");
        require_magnitude(r, node.translation, path + ".translation");
        require_magnitude(r, node.scale, path + ".scale");
        require_magnitude(r, node.rotation, path + ".rotation");
        double norm = 0;
        for (double d : node.rotation) norm += d * d;
        if (!(norm > 0)) r.fail(path + ".rotation", "expected a non-zero finite quaternion");
        if (node.has_matrix && !node.channels.empty())
            r.fail(path + ".channels", "a node with a matrix cannot be animated");
        bool seen[3] = {false, false, false};
        for (std::size_t c = 0; c < node.channels.size(); ++c) {
            const AnimationChannel& channel = node.channels[c];
            const std::string channel_path = at(path + ".channels", c);
            const int slot = int(channel.path);
            if (seen[slot]) r.fail(channel_path + ".path", std::string("a second \"") + path_name(channel.path) + "\" channel");
            seen[slot] = true;
            if (channel.times.empty()) r.fail(channel_path + ".times", "needs at least one keyframe");
            for (std::size_t k = 0; k < channel.times.size(); ++k) {
                if (!std::isfinite(channel.times[k])) r.fail(at(channel_path + ".times", k), "expected a finite number");
                if (k > 0 && !(channel.times[k] > channel.times[k - 1]))
                    r.fail(at(channel_path + ".times", k), "times must increase strictly");
            }
            const std::size_t per_key = channel.interpolation == Interpolation::CubicSpline ? 3 : 1;
            if (channel.values.size() != channel.times.size() * per_key)
                r.fail(channel_path + ".values", "expected " + std::to_string(channel.times.size() * per_key) +
                                                     " values (" + std::to_string(per_key) + " per keyframe), got " +
                                                     std::to_string(channel.values.size()));
            for (std::size_t k = 0; k < channel.values.size(); ++k)
                require_magnitude(r, channel.values[k], at(channel_path + ".values", k));
        }
    }
    for (std::size_t i = 0; i < animation.spheres.size(); ++i) {
        const SphereBinding& b = animation.spheres[i];
        const std::string path = at("animation.spheres", i);
        if (b.sphere >= sphere_count)
            r.fail(path + ".sphere", "index " + std::to_string(b.sphere) + " is out of range (there are " +
                                         std::to_string(sphere_count) + " spheres)");
        if (b.node >= node_count)
            r.fail(path + ".node", "index " + std::to_string(b.node) + " is out of range (there are " +
                                       std::to_string(node_count) + " nodes)");
        require_magnitude(r, b.center, path + ".center");
        if (!(b.radius > 0) || !std::isfinite(b.radius)) r.fail(path + ".radius", "must be > 0");
        if (!positive_in_range(b.radius)) r.fail(path + ".radius", positive_rule() + kFloatReason + format_number(b.radius));
    }
    if (animation.camera_node >= 0 && std::size_t(animation.camera_node) >= node_count)
        r.fail("animation.camera.node", "index " + std::to_string(animation.camera_node) + " is out of range (there are " +
                                            std::to_string(node_count) + " nodes)");
}

}  // namespace orb::detail
