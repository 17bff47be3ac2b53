// glTF animation channels on node translation/rotation/scale -> Orb
// animation channels (docs/gltf.md, "Animation").
#include <cmath>
#include <set>

#include "gltf_internal.h"
#include "orb/scene/error.h"

namespace orb::gltf {
namespace {

std::optional<AnimationPath> path_of(const std::string& name) {
    if (name == "translation") return AnimationPath::Translation;
    if (name == "rotation") return AnimationPath::Rotation;
    if (name == "scale") return AnimationPath::Scale;
    return std::nullopt;
}

std::optional<Interpolation> interpolation_of(const std::string& name) {
    if (name.empty() || name == "LINEAR") return Interpolation::Linear;
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    return std::nullopt;
}

void read_channel(const tinygltf::Model& model, const tinygltf::Animation& animation, std::size_t c,
                  const std::string& label, Diagnostics& diagnostics,
                  std::map<int, std::vector<AnimationChannel>>& channels, std::set<std::string>& ignored);

}  // namespace

std::string animation_label(const tinygltf::Model& model, std::size_t clip) {
    const std::string& name = model.animations[clip].name;
    return "animation " + std::to_string(clip) + (name.empty() ? "" : " '" + name + "'");
}

std::map<int, std::vector<AnimationChannel>> read_animation_channels(const tinygltf::Model& model, std::size_t clip,
                                                                    Diagnostics& diagnostics) {
    std::map<int, std::vector<AnimationChannel>> channels;
    std::set<std::string> ignored;
    const tinygltf::Animation& animation = model.animations[clip];
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
        const std::string label = animation_label(model, clip) + " channel " + std::to_string(c);
        // A broken channel costs its motion, not the whole scene (--strict: an error).
        try {
            read_channel(model, animation, c, label, diagnostics, channels, ignored);
        } catch (const InputError& e) {
            std::string message = e.what();
            const std::string prefix = diagnostics.source() + ": ";
            if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
            diagnostics.lossy(message + "; the channel is ignored");
        }
    }
    for (const std::string& what : ignored) diagnostics.lossy("animation " + what + " are not supported and were ignored");
    return channels;
}

namespace {

void read_channel(const tinygltf::Model& model, const tinygltf::Animation& animation, std::size_t c,
                  const std::string& label, Diagnostics& diagnostics,
                  std::map<int, std::vector<AnimationChannel>>& channels, std::set<std::string>& ignored) {
    const tinygltf::AnimationChannel& channel = animation.channels[c];
    const std::optional<AnimationPath> path = path_of(channel.target_path);
    if (!path) {
        ignored.insert("'" + channel.target_path + "' targets");
        return;
    }
    if (channel.target_node < 0) {
        ignored.insert("channels without a target node");
        return;
    }
    if (std::size_t(channel.target_node) >= model.nodes.size())
        diagnostics.fail(label + ": target node " + std::to_string(channel.target_node) + " does not exist");
    if (channel.sampler < 0 || std::size_t(channel.sampler) >= animation.samplers.size())
        diagnostics.fail(label + ": sampler " + std::to_string(channel.sampler) + " does not exist");
    const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(channel.sampler)];
    const std::optional<Interpolation> interpolation = interpolation_of(sampler.interpolation);
    if (!interpolation)
        diagnostics.fail(label + ": unknown interpolation '" + sampler.interpolation +
                         "' (expected LINEAR, STEP or CUBICSPLINE)");

    AnimationChannel out;
    out.path = *path;
    out.interpolation = *interpolation;
    const AccessorValues times =
        read_accessor(model, sampler.input, {TINYGLTF_TYPE_SCALAR}, label + " input", diagnostics);
    if (times.count == 0) diagnostics.fail(label + ": input has no keyframes");
    out.times = times.values;
    for (std::size_t k = 1; k < out.times.size(); ++k)
        if (!(out.times[k] > out.times[k - 1]))
            diagnostics.fail(label + ": keyframe times must increase strictly (key " + std::to_string(k) +
                             ": " + std::to_string(out.times[k]) + " after " +
                             std::to_string(out.times[k - 1]) + ")");
    const int type = *path == AnimationPath::Rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
    const AccessorValues values = read_accessor(model, sampler.output, {type}, label + " output", diagnostics);
    const std::size_t per_key = *interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (values.count != times.count * per_key)
        diagnostics.fail(label + ": output has " + std::to_string(values.count) + " values, expected " +
                         std::to_string(times.count * per_key) + " (" + std::to_string(per_key) +
                         " per keyframe)");
    out.values.resize(values.count);
    for (std::size_t i = 0; i < values.count; ++i)
        for (int k = 0; k < values.components; ++k) out.values[i][std::size_t(k)] = values.element(i)[k];
    if (*path == AnimationPath::Rotation)
        for (std::size_t k = 0; k < times.count; ++k) {
            const auto& q = out.values[k * per_key + (per_key == 3 ? 1 : 0)];
            if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 0))
                diagnostics.fail(label + ": rotation keyframe " + std::to_string(k) + " is a zero quaternion");
        }

    std::vector<AnimationChannel>& node_channels = channels[channel.target_node];
    bool duplicate = false;
    for (const AnimationChannel& existing : node_channels) duplicate = duplicate || existing.path == out.path;
    if (duplicate) {
        diagnostics.warn(label + ": node " + std::to_string(channel.target_node) + " already has a '" +
                         channel.target_path + "' channel; this one is ignored");
        return;
    }
    const tinygltf::Node& node = model.nodes[std::size_t(channel.target_node)];
    if (node.matrix.size() == 16)
        diagnostics.fail(label + ": node " + std::to_string(channel.target_node) +
                         " has a matrix; animated nodes must use translation/rotation/scale");
    node_channels.push_back(std::move(out));
}

}  // namespace

}  // namespace orb::gltf
