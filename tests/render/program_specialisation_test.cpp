// A scene's program carries only the code the scene needs (material kinds
// and rough glass: build options from layout_scene). Leaving
// code out must change nothing but speed: the specialised program renders
// the image the program with every kind renders.
#include <gtest/gtest.h>

#include <string>

#include "render_test_support.h"
#include "scene_layout.h"

using namespace orb;
using namespace orb::render;
using namespace orb::render::test;

namespace {

constexpr std::uint32_t bit(MaterialType kind) { return 1u << static_cast<int>(kind); }

// A white room seen from inside one huge sphere, a lamp, and one ball of
// each given kind.
Scene room_with(std::initializer_list<MaterialType> kinds, double glass_roughness = 0.0) {
    Scene scene;
    scene.camera.position = {0.0, 1.0, 4.0};
    scene.camera.target = {0.0, 1.0, 0.0};
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.camera.vfov_deg = 50.0;
    add_sphere(scene, {0.0, 0.0, 0.0}, 50.0, add_material(scene, MaterialType::Diffuse, {0.7, 0.7, 0.7}));
    add_sphere(scene, {0.0, 4.0, 0.0}, 0.8, add_material(scene, MaterialType::Diffuse, {0, 0, 0}, {8.0, 8.0, 8.0}));
    double x = -1.5;
    for (MaterialType kind : kinds) {
        const std::uint32_t material = add_material(scene, kind, {0.8, 0.6, 0.4});
        if (kind == MaterialType::Dielectric) scene.materials[material].roughness = glass_roughness;
        if (kind == MaterialType::Pbr) {
            scene.materials[material].roughness = 0.4;
            scene.materials[material].metallic = 0.5;
        }
        add_sphere(scene, {x, 0.6, 0.0}, 0.5, material);
        x += 1.0;
    }
    return scene;
}

Film render_with_options(const Scene& scene, const std::string& options) {
    return render_with_cl_options(scene, small_config(40, 30, 3), {4}, options.c_str());
}

// Every kind, rough glass and the environment built in (the later -D wins):
// the options that turn a program built without them into one built with
// them, which are the defaults.
std::string everything_built_in() {
    device::KernelFeatures without;
    without.material_kinds = 0;
    without.rough_dielectric = false;
    without.environment = false;
    return device::kernel_feature_options(device::KernelFeatures{}, without);
}

std::string only_diffuse() {
    device::KernelFeatures diffuse;
    diffuse.material_kinds = 1u << static_cast<int>(device::MaterialKind::Diffuse);
    return device::kernel_feature_options(diffuse);
}

}  // namespace

TEST(ProgramSpecialisation, TheLayoutNamesWhatTheSceneUses) {
    const SceneLayout cornell_like = layout_scene(room_with({MaterialType::Mirror, MaterialType::Dielectric}));
    EXPECT_EQ(cornell_like.material_kinds,
              bit(MaterialType::Diffuse) | bit(MaterialType::Mirror) | bit(MaterialType::Dielectric));
    EXPECT_FALSE(cornell_like.rough_dielectric);
    EXPECT_EQ(cornell_like.environment.width, 0);

    const SceneLayout rough = layout_scene(room_with({MaterialType::Dielectric, MaterialType::Pbr}, 0.3));
    EXPECT_EQ(rough.material_kinds,
              bit(MaterialType::Diffuse) | bit(MaterialType::Dielectric) | bit(MaterialType::Pbr));
    EXPECT_TRUE(rough.rough_dielectric);

    // A material no sphere uses needs no code.
    Scene unused = room_with({});
    add_material(unused, MaterialType::Mirror, {1, 1, 1});
    EXPECT_EQ(layout_scene(unused).material_kinds, bit(MaterialType::Diffuse));

    Scene lit = room_with({});
    lit.environment.kind = EnvironmentKind::Color;
    lit.environment.color = {0.5, 0.5, 0.5};
    EXPECT_GT(layout_scene(lit).environment.width, 0);
}

// Exact equality: the cases left out are never taken, so both programs run
// the same arithmetic on every path (PoCL, same seed, every channel).
TEST(ProgramSpecialisation, LeavingCodeOutChangesNoPixel) {
    for (const Scene& scene : {room_with({MaterialType::Mirror, MaterialType::Dielectric}),
                               room_with({MaterialType::Pbr}), room_with({MaterialType::Dielectric}, 0.3)}) {
        const Film specialised = render_with_options(scene, "");
        const Film everything = render_with_options(scene, everything_built_in());
        EXPECT_EQ(specialised.radiance, everything.radiance);
        EXPECT_EQ(specialised.albedo, everything.albedo);
        EXPECT_EQ(specialised.direct, everything.direct);
        EXPECT_EQ(specialised.indirect, everything.indirect);
    }
}

// The option does take effect: a program built for diffuse only renders the
// mirror and the glass ball as diffuse ones.
TEST(ProgramSpecialisation, AKindLeftOutIsRenderedAsDiffuse) {
    const Scene scene = room_with({MaterialType::Mirror, MaterialType::Dielectric});
    EXPECT_NE(render_with_options(scene, only_diffuse()).radiance, render_with_options(scene, "").radiance);
}

// A run that writes only some layers computes only their channels
// (RenderConfig::film_channels, from --passes): those are exactly what the
// program with every channel gives, and the others stay at their clear values.
TEST(ProgramSpecialisation, ChannelsLeftOutStayClearAndTheRestIsUnchanged) {
    const Scene scene = room_with({MaterialType::Mirror, MaterialType::Dielectric, MaterialType::Pbr});
    const Film everything = test::render(scene, small_config(40, 30, 3), {4});
    const std::vector<film::Layer> layer_sets[] = {
        {film::Layer::Beauty}, {film::Layer::Variance}, {film::Layer::Albedo, film::Layer::Depth}};
    for (const std::vector<film::Layer>& layers : layer_sets) {
        RenderConfig config = small_config(40, 30, 3);
        config.film_channels = film::channels_for(layers);
        const Film some = test::render(scene, config, {4});
        for (const film::ChannelInfo& c : film::kChannels) {
            SCOPED_TRACE(c.name);
            if (config.film_channels & film::channel_bit(c.channel)) {
                EXPECT_EQ(channel_bytes(some, c.channel), channel_bytes(everything, c.channel));
            } else {
                EXPECT_TRUE(channel_is_clear(some, c.channel));
            }
        }
    }
    // The variance needs the mean it is the variance of.
    EXPECT_EQ(film::channels_for(std::vector{film::Layer::Variance}),
              film::channel_bit(film::Channel::radiance_sq) | film::channel_bit(film::Channel::radiance));
}
