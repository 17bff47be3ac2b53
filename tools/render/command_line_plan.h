// orb-render's command line turned into the render job's plan
// (orb/job/render_plan.h): the scene read as orb-import reads it, styled,
// its legend written, and the options converted into the job's plain ones.
#pragma once

#include "orb/job/messages.h"
#include "orb/job/output_film.h"
#include "orb/job/render_plan.h"
#include "orb/render/development_knobs.h"
#include "render_options.h"

namespace orb::render_cli {

// The job's messages as orb-render's others: warnings (and errors) always,
// notes unless -q (orb::cli::warning, orb::cli::info).
job::MessageSink command_line_messages();

// How each film renders into its output: --time, --checkpoint, stopped by
// SIGINT/SIGTERM/SIGHUP (interrupt.h), its progress shown by `progress`.
job::OutputRun output_run(const RenderOptions& options, job::FilmProgress& progress);

// Throws orb::InputError for bad input or a resume that would not continue
// the same render, orb::cli::UsageError for a bad --orbit.
job::RenderPlan make_render_plan(const RenderOptions& options, const render::DevelopmentKnobs& knobs);

}  // namespace orb::render_cli
