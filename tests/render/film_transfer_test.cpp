// Only the channels a run computes (RenderConfig::film_channels) live on the
// device at the film's size and travel between host and device; the host
// film's other channels are empty, whatever the film passed in held before.
#include <gtest/gtest.h>

#include <vector>

#include "render_test_support.h"

namespace orb::render::test {
namespace {

Scene cornell() { return load_scene_file(std::string(ORB_SCENES_DIR) + "/cornell.scn"); }

RenderConfig beauty_config()
{
    RenderConfig config = small_config(24, 18, 42);
    config.film_channels = film::channels_for(std::vector{film::Layer::Beauty});
    return config;
}

bool computed(const RenderConfig& config, film::Channel channel)
{
    return (config.film_channels & film::channel_bit(channel)) != 0;
}

// The channels the config computes equal `expected`'s, bit for bit; the
// others are empty.
void expect_computed_equal_and_rest_clear(const Film& film, const Film& expected, const RenderConfig& config)
{
    ASSERT_EQ(film.width, expected.width);
    ASSERT_EQ(film.height, expected.height);
    for (const film::ChannelInfo& c : film::kChannels) {
        SCOPED_TRACE(c.name);
        if (computed(config, c.channel)) {
            ASSERT_EQ(film.entries(c.channel), film.pixel_count() * static_cast<std::size_t>(c.components));
            EXPECT_EQ(channel_bytes(film, c.channel), channel_bytes(expected, c.channel));
        } else {
            EXPECT_EQ(film.entries(c.channel), 0u);
        }
    }
}

// A film of the renderer's size whose every channel holds something else
// than the renderer would write: a render of another seed with all channels,
// then 42 everywhere.
Film stale_film()
{
    Film film = render(cornell(), small_config(24, 18, 5), {2});
    for (const film::ChannelInfo& c : film::kChannels) fill_channel(film, c.channel, 42);
    return film;
}

TEST(FilmTransfer, BeautyOnlyGivesTheBeautyOfEveryChannel)
{
    const Film everything = render(cornell(), small_config(24, 18, 42), {3, 5});
    const Film beauty = render(cornell(), beauty_config(), {3, 5});
    EXPECT_EQ(beauty.samples_per_pixel, 8u);
    expect_computed_equal_and_rest_clear(beauty, everything, beauty_config());
}

TEST(FilmTransfer, AReusedFilmKeepsNothingOfWhatItHeld)
{
    const Film expected = render(cornell(), beauty_config(), {4});
    Renderer renderer(cornell(), beauty_config());
    renderer.render_pass(4);
    Film reused = stale_film();
    renderer.read_film(reused);
    EXPECT_EQ(reused.samples_per_pixel, 4u);
    expect_computed_equal_and_rest_clear(reused, expected, beauty_config());

    // Frame after frame into the same film: the next frame's values only.
    Scene moved = cornell();
    moved.spheres[7].center[0] += 2.0;
    const Film next_expected = render(moved, beauty_config(), {2});
    renderer.set_scene(moved);
    renderer.render_pass(2);
    const film::Sum* memory = reused.radiance.data();
    renderer.read_film(reused);
    EXPECT_EQ(reused.radiance.data(), memory);  // the same memory, no fresh pages
    expect_computed_equal_and_rest_clear(reused, next_expected, beauty_config());
}

TEST(FilmTransfer, AFilmOfAnotherSizeIsMadeAnew)
{
    Renderer renderer(cornell(), beauty_config());
    renderer.render_pass(2);
    Film other_size = render(cornell(), small_config(8, 8, 5), {1});
    renderer.read_film(other_size);
    expect_computed_equal_and_rest_clear(other_size, render(cornell(), beauty_config(), {2}), beauty_config());
}

// A resumed beauty-only render continues exactly: the same passes give the
// same sums, whatever the loaded film held in the channels not computed.
TEST(FilmTransfer, ResumingABeautyOnlyFilmContinuesExactly)
{
    const Film uninterrupted = render(cornell(), beauty_config(), {3, 5});
    Film checkpoint = render(cornell(), beauty_config(), {3});
    for (film::Channel channel : {film::Channel::direct, film::Channel::depth, film::Channel::object_id})
        fill_channel(checkpoint, channel, 42);  // never uploaded
    Renderer resumed(cornell(), beauty_config());
    resumed.load_film(checkpoint);
    resumed.render_pass(5);
    const Film finished = resumed.read_film();
    EXPECT_EQ(finished.samples_per_pixel, 8u);
    expect_computed_equal_and_rest_clear(finished, uninterrupted, beauty_config());

    // Channels it does not compute need not even be there.
    checkpoint.albedo.clear();
    Renderer from_partial(cornell(), beauty_config());
    from_partial.load_film(checkpoint);
    from_partial.render_pass(5);
    expect_computed_equal_and_rest_clear(from_partial.read_film(), uninterrupted, beauty_config());
}

TEST(FilmTransfer, ALoadedFilmMustHoldTheComputedChannels)
{
    Film checkpoint = render(cornell(), beauty_config(), {1});
    checkpoint.alpha.pop_back();
    Renderer renderer(cornell(), beauty_config());
    EXPECT_THROW(renderer.load_film(checkpoint), std::invalid_argument);
}

// Channels not computed take a placeholder of one pixel on the device.
TEST(FilmTransfer, DeviceMemoryHoldsOnlyTheComputedChannels)
{
    const RenderConfig config = beauty_config();
    const Renderer every(cornell(), small_config(24, 18, 42));
    const Renderer beauty(cornell(), config);
    std::uint64_t saved = 0;
    for (const film::ChannelInfo& c : film::kChannels)
        if (!computed(config, c.channel))
            saved += (24u * 18u - 1u) * film::pixel_bytes(c);
    EXPECT_EQ(every.device_memory_bytes() - beauty.device_memory_bytes(), saved);
}

// A film read later is the film read at once, though the renderer has gone
// on meanwhile: cleared, given the next frame's scene and seed, and rendered
// that frame before the first one's film is waited for.
TEST(FilmTransfer, AFilmReadLaterIsTheFilmOfItsFrame)
{
    for (const RenderConfig& config : {beauty_config(), small_config(24, 18, 42)}) {
        const Film expected = render(cornell(), config, {3, 2});
        Scene moved = cornell();
        moved.spheres[7].center[0] += 2.0;
        const Film next_expected = render(moved, config, {4});

        Renderer renderer(cornell(), config);
        renderer.render_pass(3);
        renderer.render_pass(2);
        PendingFilm arriving = renderer.read_film_later();
        renderer.set_scene(moved);
        renderer.render_pass(4);
        PendingFilm also = renderer.read_film_later();
        Film moved_first = stale_film();  // memory that held other values: reused, and overwritten
        arriving.wait(moved_first);
        Film second;
        also.wait(second);
        EXPECT_EQ(moved_first.samples_per_pixel, 5u);
        EXPECT_EQ(moved_first.sample_ranges.format(), "0:5");
        expect_computed_equal_and_rest_clear(moved_first, expected, config);
        expect_computed_equal_and_rest_clear(second, next_expected, config);
    }
}

}  // namespace
}  // namespace orb::render::test
