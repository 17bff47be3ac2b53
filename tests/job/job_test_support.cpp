#include "job_test_support.h"

#include <algorithm>
#include <fstream>

#include "orb/job/output_film.h"
#include "orb/tables/film_channels.h"

namespace orb::job::test {

PlanOptions still_options(const Scene& scene, int width, int height, std::uint64_t spp, std::uint64_t seed) {
    PlanOptions options;
    options.given.width = width;
    options.given.height = height;
    options.given.spp = spp;
    options.given.seed = seed;
    options.settings = resolve_settings(options.given, &scene.render);
    return options;
}

render::DevelopmentKnobs one_sample_passes() {
    render::DevelopmentKnobs knobs;
    knobs.pass_spp = 1;
    return knobs;
}

RenderPlan JobTest::plan(const Scene& scene, PlanOptions options, const render::DevelopmentKnobs& knobs) {
    options.messages = [this](MessageKind, const std::string& message) { messages_.push_back(message); };
    return make_render_plan(options, SceneInput{scene, path("scene.json"), nullptr}, knobs);
}

FilmOutcome JobTest::run(RenderPlan& plan, std::optional<int> stop_after) {
    render::Renderer renderer(plan.scene, plan.config);
    start_film(plan, renderer);
    std::atomic<bool> stop{false};
    FilmRun run;
    run.cancel = &stop;
    run.on_pass = [&](const render::ProgressState& state) {
        if (stop_after && state.pass >= *stop_after) stop = true;
    };
    FilmOutcome outcome = job::render_film(renderer, plan, std::move(run));
    if (outcome.rendered) outcome.image.wait_for_film();
    return outcome;
}

std::string JobTest::save(FilmOutcome& outcome, const std::string& name) {
    const std::string file = path(name);
    std::ofstream(file, std::ios::binary) << outcome.image.encode();
    return file;
}

void expect_same_film(const Film& a, const Film& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    EXPECT_EQ(a.samples_per_pixel, b.samples_per_pixel);
    EXPECT_EQ(a.sample_ranges.format(), b.sample_ranges.format());
    for (const film::ChannelInfo& info : film::kChannels) {
        const auto bytes_a = a.bytes(info.channel);
        const auto bytes_b = b.bytes(info.channel);
        ASSERT_EQ(bytes_a.size(), bytes_b.size()) << info.name;
        EXPECT_TRUE(std::equal(bytes_a.begin(), bytes_a.end(), bytes_b.begin())) << "channel " << info.name << " differs";
    }
}

}  // namespace orb::job::test
