// Rendering any slice of the sample sequence, on any renderer, in any order,
// gives the film of their union; a renderer takes new scenes and seeds
// without building its kernels again.
#include <gtest/gtest.h>

#include "device_session.h"
#include "render_test_support.h"

namespace orb::render::test {
namespace {

Scene cornell() { return load_scene_file(std::string(ORB_SCENES_DIR) + "/cornell.scn"); }

RenderConfig cornell_config(std::uint64_t seed = 42) { return small_config(24, 18, seed); }

TEST(SampleSlices, SlicesRenderedApartAddUpToTheWholeRender)
{
    const Film whole = render(cornell(), cornell_config(), {8});
    Renderer first(cornell(), cornell_config());
    first.render_samples(0, 3);
    Renderer second(cornell(), cornell_config());
    second.render_samples(3, 5);
    EXPECT_EQ(second.read_film().sample_ranges.format(), "3:5");

    Film merged = second.read_film();  // the later slice first: the order does not matter
    merged.accumulate(first.read_film());
    EXPECT_EQ(merged.sample_ranges.format(), "0:8");
    expect_same_films(merged, whole);
}

TEST(SampleSlices, OneRendererTakesSlicesInAnyOrder)
{
    const Film whole = render(cornell(), cornell_config(), {8});
    Renderer renderer(cornell(), cornell_config());
    renderer.render_samples(5, 3);
    renderer.render_samples(0, 5);
    EXPECT_EQ(renderer.samples_per_pixel(), 8u);
    EXPECT_EQ(renderer.next_sample(), 5u);
    const Film film = renderer.read_film();
    EXPECT_EQ(film.sample_ranges.format(), "0:8");
    expect_same_films(film, whole);
}

TEST(SampleSlices, SamplesAlreadyInTheFilmAreRefused)
{
    Renderer renderer(cornell(), cornell_config());
    renderer.render_samples(0, 4);
    EXPECT_THROW(renderer.render_samples(2, 4), std::invalid_argument);
    EXPECT_EQ(renderer.samples_per_pixel(), 4u);
    renderer.clear(10);  // an empty film whose passes start at sample 10
    renderer.render_pass(2);
    EXPECT_EQ(renderer.sample_ranges().format(), "10:2");
}

TEST(SampleSlices, ALoadedFilmContinuesAfterItsLastSample)
{
    Renderer slice(cornell(), cornell_config());
    slice.clear(16);
    slice.render_pass(4);
    Renderer resumed(cornell(), cornell_config());
    resumed.load_film(slice.read_film());
    EXPECT_EQ(resumed.next_sample(), 20u);
    resumed.render_pass(4);
    EXPECT_EQ(resumed.read_film().sample_ranges.format(), "16:8");
}

TEST(SampleSlices, ANewSceneOrSeedReusesTheBuiltProgramAndGivesTheFreshImage)
{
    Scene moved = cornell();
    moved.spheres[7].center[0] += 2.0;  // the next frame of an animation, say
    const Film fresh = render(moved, cornell_config(), {2, 3});
    const Film fresh_seed = render(moved, cornell_config(43), {2, 3});

    Renderer renderer(cornell(), cornell_config());
    renderer.render_pass(4);
    EXPECT_EQ(renderer.programs_built(), 1);
    renderer.set_scene(moved);
    EXPECT_EQ(renderer.samples_per_pixel(), 0u);
    renderer.render_pass(2);
    renderer.render_pass(3);
    EXPECT_EQ(renderer.programs_built(), 1);  // the same build options: no new build
    const Film film = renderer.read_film();
    // Same scene, seed and passes: the very same sums.
    EXPECT_EQ(film.radiance, fresh.radiance);
    EXPECT_EQ(film.depth, fresh.depth);
    EXPECT_EQ(film.object_id, fresh.object_id);

    renderer.set_seed(43);
    renderer.render_pass(2);
    renderer.render_pass(3);
    EXPECT_EQ(renderer.read_film().radiance, fresh_seed.radiance);
}

TEST(SampleSlices, RenderersOfOneDeviceShareItsSession)
{
    const DeviceInfo device = choose_device("");
    const std::shared_ptr<DeviceSession> a = DeviceSession::open(device, {});
    const std::shared_ptr<DeviceSession> b = DeviceSession::open(device, {});
    EXPECT_EQ(a.get(), b.get());
    SessionOptions uncached;
    uncached.use_binary_cache = false;
    EXPECT_NE(DeviceSession::open(device, uncached).get(), a.get());
    // A program is built once per set of options, then handed out again.
    EXPECT_EQ(&a->program("-cl-std=CL1.2"), &b->program("-cl-std=CL1.2"));
    EXPECT_EQ(a->programs_built(), b->programs_built());
}

}  // namespace
}  // namespace orb::render::test
