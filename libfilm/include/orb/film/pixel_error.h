// How far a film's means are expected to be from the converged image,
// estimated from the film's own samples: the quantity adaptive sampling
// stops on (docs/design/adaptive-sampling.md). The error is orb-diff's
// relMSE (docs/orb-diff.md): per colour channel (B - A)^2 / (A^2 + epsilon),
// averaged, where A is the converged value and B the mean. The expected
// (B - A)^2 of an unbiased mean is its variance, Var[B] = sample variance / n,
// which the film's radiance_sq channel gives; A is taken as B.
#pragma once

#include <cstddef>
#include <vector>

#include "orb/film/film.h"
#include "orb/tables/adaptive_decision.h"

namespace orb::film {

// relMSE's floor in the denominator (Rousselle et al. 2011): below it
// an error counts absolutely, so dark pixels need no endless samples.
// orb-diff (libimage's metrics) reads this one; the device's decision
// (kernels/adaptive.cl) the same definition.
inline constexpr double kRelMseEpsilon = ORB_RELMSE_EPSILON;

// The samples pixel `pixel` holds: its sample_count where the film has that
// channel (adaptive sampling), else the film's samples_per_pixel.
double pixel_samples(const Film& film, std::size_t pixel);

// The expected relMSE of one pixel's mean: the mean over R, G, B of
// Var[mean] / (A^2 + kRelMseEpsilon), with Var[mean] = (S2/n - mean^2) / (n - 1)
// and A^2 = max(0, mean^2 - Var[mean]), since E[mean^2] = A^2 + Var[mean]:
// with the mean's own square a firefly's large mean would cancel its large
// variance, and the pixel would pass for converged.
// Infinity with fewer than two samples (nothing is known). Needs the
// radiance and radiance_sq channels (std::invalid_argument otherwise).
double pixel_relmse(const Film& film, std::size_t pixel);

// Every pixel's, row-major.
std::vector<double> pixel_relmse(const Film& film);

// The frame's: the mean of the pixels' (what orb-diff's relmse of this film
// against a converged one is expected to be, up to the estimate's own noise).
// Added in the order the device's decision adds them (kernels/adaptive.cl,
// sum_pairwise and sum_decision), so that both give the same bits: pairwise
// within each group of ORB_DECISION_GROUP pixels, the groups' sums in
// ORB_DECISION_GROUP running sums (the k-th of every group from k on, in
// turn), those pairwise.
double frame_relmse(const std::vector<double>& pixel_errors);

}  // namespace orb::film
