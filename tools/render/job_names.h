// The render job's names (orb/job/) as orb-render's front end uses them.
#pragma once

#include "orb/job/background_writer.h"
#include "orb/job/frame_claim.h"
#include "orb/job/frame_jobs.h"
#include "orb/job/render_film.h"
#include "orb/job/render_plan.h"
#include "orb/job/run_stats.h"
#include "orb/job/seconds_since.h"

namespace orb::render_cli {

using job::BackgroundWriter;
using job::Clock;
using job::FilmOutcome;
using job::FinalImage;
using job::FrameClaim;
using job::Job;
using job::PosePrefetch;
using job::RenderPlan;
using job::RunStats;
using job::seconds_since;

}  // namespace orb::render_cli
