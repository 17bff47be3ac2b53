// A scene that uses every part of the model, for binary round trips.
#pragma once

#include <cmath>

#include "orb/scene/scene.h"

namespace orb::test {

inline Scene every_feature_scene() {
    Scene scene;
    scene.camera.position = {0.1, 2.000000000000001, 9};
    scene.camera.target = {0, 1, -1e-300};
    scene.camera.up = {0, 1, 0.25};
    scene.camera.vfov_deg = 33.3;
    scene.camera.aperture = 0.2;
    scene.camera.focus_distance = 7.5;
    scene.render = {320, 200, 17, 9};
    scene.materials = {{"white", MaterialType::Diffuse, {0.8, 0.8, 0.8}, {0, 0, 0}, 1.5},
                       {"glass \"clear\"", MaterialType::Dielectric, {1, 1, 1}, {0, 0, 0}, 1.33},
                       {"lamp", MaterialType::Diffuse, {0, 0, 0}, {12, 11.5, 1e6}, 1.5},
                       {"", MaterialType::Mirror, {0.999, 0.5, 0}, {0, 0, 0}, 1.5},
                       {"gold", MaterialType::Pbr, {1, 0.78, 0.34}, {0, 0, 0}, 1.5, 0.1 + 0.2, 1},
                       {"frosted", MaterialType::Dielectric, {1, 1, 1}, {0, 0, 0}, 1.5, 0.35, 0}};
    for (int i = 0; i < 50; ++i) {
        Sphere s;
        s.name = i % 3 == 0 ? "" : "sphère " + std::to_string(i);
        s.center = {std::sin(i) * 1e5, std::cos(i) / 3, -0.0 + i * 0.1};
        s.radius = 1e-9 + i * std::sqrt(2.0);
        s.material = static_cast<std::uint32_t>(i % 6);
        scene.spheres.push_back(s);
    }
    AnimationNode node;
    node.name = "spin";
    node.channels.push_back({AnimationPath::Rotation, Interpolation::Linear, {0, 1}, {{0, 0, 0, 1}, {0, 0.6, 0, 0.8}}});
    scene.animation.nodes.push_back(node);
    scene.animation.spheres.push_back({3, 0, {1, 2, 3}, 0.5});
    scene.animation.camera_node = 0;
    scene.environment.kind = EnvironmentKind::Map;
    scene.environment.map = "../skies/dusk \"1\".exr";
    scene.environment.intensity = 0.3;
    scene.environment.rotation_deg = -123.456;
    return scene;
}

}  // namespace orb::test
