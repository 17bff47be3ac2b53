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
#include "orb/cli/output_file.h"
#include "orb/job/image_output.h"
#include "orb/job/render_film.h"
#include "orb/job/render_plan.h"
#include "orb/scene/scene.h"

namespace orb::job::test {

// orb-render's kind of output (tools/render/render_outputs.h): an
// orb::cli::OutputFile, staged beside its target and renamed into place.
class FileOutput final : public ImageOutput {
public:
    explicit FileOutput(const std::string& path) : file_(path, "-o") {}
    void stage(std::string_view bytes) override { file_.stage(bytes); }
    void commit(std::string_view bytes) override { file_.commit(bytes); }
    std::string display_name() const override { return file_.display_name(); }
    std::string path() const override { return file_.path(); }

private:
    cli::OutputFile file_;
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
