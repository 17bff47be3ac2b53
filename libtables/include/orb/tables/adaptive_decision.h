/* Adaptive sampling's decision, defined once for both sides
 * (docs/design/adaptive-sampling.md): the constants of the error estimate
 * and the layout of what the device's decision (kernels/adaptive.cl) hands
 * back. The host's reference of the same decision is libfilm's
 * (orb/film/pixel_error.h, orb/film/stopping_rule.h), which reads these.
 *
 * Like device_types.h one text for both compilers: the decision program
 * starts with it (kernels/CMakeLists.txt, ORB_DECISION_KERNEL_FILES), and
 * the host includes it as C++20 (namespace orb::device). The decision
 * computes in double precision on both sides (the device needs
 * cl_khr_fp64), so that the device decides exactly as the host would. */
#ifndef ORB_TABLES_ADAPTIVE_DECISION_H
#define ORB_TABLES_ADAPTIVE_DECISION_H

/* relMSE's floor in the denominator, (B - A)^2 / (A^2 + epsilon) (Rousselle
 * et al. 2011): below it an error counts absolutely, so dark pixels need no
 * endless samples. orb-diff's metric and adaptive sampling's estimate read
 * this one. */
#define ORB_RELMSE_EPSILON 0.01

/* The decision kernels' work-group size, and the width of the pairwise
 * sums that make the frame's estimate: pixels are added in groups of this
 * many, pairwise (a tree), then the groups' sums in this many strided
 * running sums, pairwise again. The host's reference adds in the same order
 * (orb::film::frame_relmse), so both give the same bits. A power of two. */
#define ORB_DECISION_GROUP 256

#ifdef __OPENCL_VERSION__

#pragma OPENCL EXTENSION cl_khr_fp64 : enable

#else

#include <cstdint>

namespace orb::device {
using uint = std::uint32_t;
#endif

/* What one decision reads back: the sum of every pixel's estimated relMSE
 * (the frame's estimate is it over the pixel count) and how many of the
 * candidates keep sampling (the length of the new list of active pixels). */
typedef struct DecisionTotals {
    double error_sum;
    uint still_sampling;
    uint pad0;
} DecisionTotals;

#ifndef __OPENCL_VERSION__
static_assert(sizeof(DecisionTotals) == 16 && alignof(DecisionTotals) == 8, "DecisionTotals: 16 bytes on both sides");
static_assert((ORB_DECISION_GROUP & (ORB_DECISION_GROUP - 1)) == 0, "ORB_DECISION_GROUP is a power of two");
}  // namespace orb::device
#endif

#endif /* ORB_TABLES_ADAPTIVE_DECISION_H */
