// What a front end shows while a film renders: told of each film from
// start to finish (orb-render draws its progress line from it), and the
// estimate of how far the render is and when it ends.
#pragma once

#include <string>

#include "orb/render/progressive.h"

namespace orb::job {

// What a front end shows of each film as it renders (orb-render: its
// progress line on stderr). Told of every film, from start() to finish().
class FilmProgress {
public:
    virtual ~FilmProgress() = default;
    // A film of `pixels` pixels starts rendering; `label` ("frame 12: ", or
    // "") starts what is shown of it.
    virtual void start(const std::string& label, double pixels) = 0;
    virtual void on_pass(const render::ProgressState& state) = 0;
    // A checkpoint is in place at `output` (as messages name it).
    virtual void on_checkpoint(const render::ProgressState& state, const std::string& output) = 0;
    virtual void finish(const render::ProgressState& final_state) = 0;
};

// How far a render is, and when it ends.
struct ProgressEstimate {
    double fraction = 1;     // of the samples per pixel it heads for, 0 ... 1 (1 without a target)
    double eta_seconds = 0;  // until it ends; infinity while no pass has a rate
};

// This run's samples per pixel per second (over `pixels` pixels) give the
// time to the target; a time limit (`time_limit` > 0 seconds) ends the
// render sooner when it comes first.
ProgressEstimate estimate_progress(const render::ProgressState& state, double pixels, double time_limit);

}  // namespace orb::job
