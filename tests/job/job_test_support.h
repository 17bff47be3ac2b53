// Shared set-up for the render job's contract tests: a scratch folder per
// test, the small scene of the command-line tests, and plans rendered with
// the library alone (no orb-render), in passes of one sample so that a test
// can stop between them.
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "cli_fixture.h"
#include "orb/cli/output_file_image.h"
#include "orb/job/render_film.h"
#include "orb/job/render_plan.h"
#include "orb/scene/scene.h"

namespace orb::job::test {

// orb-render's kind of output, opened as -o opens it.
struct FileOutput final : cli::OutputFileImage {
    explicit FileOutput(const std::string& path) : cli::OutputFileImage(cli::OutputFile(path, "-o")) {}
};

// The options of `orb-render scene.json --width W --height H --spp SPP --seed SEED`.
PlanOptions still_options(const Scene& scene, int width, int height, std::uint64_t spp, std::uint64_t seed);

// Passes of one sample after the first (ORB_PASS_SPP=1), so that a render
// stopped after pass n holds n samples per pixel.
render::DevelopmentKnobs one_sample_passes();

class JobTest : public orb::test::RenderCli {
protected:
    // A plan of `scene` as the library makes it, its messages kept in messages_.
    RenderPlan plan(const Scene& scene, PlanOptions options,
                    const render::DevelopmentKnobs& knobs = one_sample_passes());
    // Renders the plan from its first sample (or its resumed film) with the
    // library's film loop, stopping after `stop_after` passes when given
    // (the cancel flag set in the pass callback, as a signal handler would).
    FilmOutcome run(RenderPlan& plan, std::optional<int> stop_after = std::nullopt);
    // Encodes the outcome's image into `name` in the scratch folder; returns its path.
    std::string save(FilmOutcome& outcome, const std::string& name);

    std::vector<std::string> messages_;
};

// The film's sums and counts, bit for bit.
void expect_same_film(const Film& a, const Film& b);

}  // namespace orb::job::test
