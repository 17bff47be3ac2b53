// Adaptive sampling's decision on the device (docs/design/adaptive-sampling.md):
// the film stays where it was rendered, and only DecisionTotals come back.
// A program of its own (ORB_DECISION_KERNEL_FILES), built without the
// render program's relaxed math: every step is the host reference's
// (libfilm: pixel_error.cpp, stopping_rule.cpp) in the same double-precision
// operations, so the device keeps and stops the very pixels the host would.
//
// One decision is four launches of ORB_DECISION_GROUP work-items a group:
//   estimate_pixel_errors  every pixel: its relMSE, whether it is noisy,
//                          and each group's sum of the relMSEs;
//   count_still_sampling   every candidate (a pixel still sampling): how
//                          many of each group's keep sampling;
//   sum_decision           one group: the groups' offsets into the new
//                          list (a prefix sum of those counts) and the totals;
//   compact_still_sampling every candidate: those that keep sampling, written
//                          to the new list in the candidates' order.
// The list stays ascending and its order depends on nothing but the film,
// so renders are reproducible. list_every_pixel starts a frame's list.

// Exactly the host's arithmetic: no fused multiply-adds.
#pragma OPENCL FP_CONTRACT OFF

// std::max(0.0, x) of the host: 0 for a NaN as well.
double at_least_zero(double x) { return 0.0 < x ? x : 0.0; }

// The value of a Fixed sum (film_channels.h): its units times 2^-ORB_FILM_FIXED_BITS, exactly.
double fixed_sum_value(long sum) { return (double)sum * (1.0 / (double)(1 << ORB_FILM_FIXED_BITS)); }

// The expected relMSE of one pixel's mean (orb::film::pixel_relmse): over
// R, G, B the variance of the mean over (A^2 + epsilon), A^2 estimated as
// mean^2 - Var[mean]; infinity with fewer than two samples.
double pixel_relmse(__global const long* radiance, __global const long* radiance_sq, uint pixel, double n)
{
    if (n < 2.0) return (double)INFINITY;
    double sum = 0.0;
    for (uint c = 0; c < 3; ++c) {
        const double mean = fixed_sum_value(radiance[pixel * 3 + c]) / n;
        const double mean_sq = fixed_sum_value(radiance_sq[pixel * 3 + c]) / n;
        const double variance_of_mean = at_least_zero(mean_sq - mean * mean) / (n - 1.0);
        const double converged_sq = at_least_zero(mean * mean - variance_of_mean);
        sum += variance_of_mean / (converged_sq + ORB_RELMSE_EPSILON);
    }
    return sum / 3.0;
}

// values[0] = the sum of values[0 .. ORB_DECISION_GROUP), added pairwise:
// the halves, then their halves (orb::film::frame_relmse adds the same way).
// Every work-item of the group calls it.
void sum_pairwise(__local double* values)
{
    const uint l = (uint)get_local_id(0);
    // (`half` is a type in OpenCL C.)
    for (uint stride = ORB_DECISION_GROUP / 2; stride > 0; stride >>= 1) {
        barrier(CLK_LOCAL_MEM_FENCE);
        if (l < stride) values[l] += values[l + stride];
    }
    barrier(CLK_LOCAL_MEM_FENCE);
}

// The exclusive prefix sum of `value` over the group (Hillis and Steele's
// scan, in two halves of `scratch`, 2 * ORB_DECISION_GROUP entries); `total`
// gets the group's sum. Every work-item of the group calls it.
uint exclusive_scan(uint value, __local uint* scratch, uint* total)
{
    const uint l = (uint)get_local_id(0);
    uint in = 0;
    scratch[l] = value;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint offset = 1; offset < ORB_DECISION_GROUP; offset <<= 1) {
        const uint out = ORB_DECISION_GROUP - in;
        scratch[out + l] = scratch[in + l] + (l >= offset ? scratch[in + l - offset] : 0u);
        barrier(CLK_LOCAL_MEM_FENCE);
        in = out;
    }
    const uint inclusive = scratch[in + l];
    *total = scratch[in + ORB_DECISION_GROUP - 1];
    barrier(CLK_LOCAL_MEM_FENCE);  // the next call may write `scratch` again
    return inclusive - value;
}

// Whether the pixel keeps sampling (orb::film::pixels_still_sampling): it or
// one of its eight neighbours is noisy.
bool keeps_sampling(__global const uchar* noisy, uint pixel, int width, int height)
{
    const int x = (int)(pixel % (uint)width);
    const int y = (int)(pixel / (uint)width);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < width && ny < height && noisy[ny * width + nx]) return true;
        }
    return false;
}

// The candidate at list entry `entry`: the entry itself when every pixel is one.
uint candidate_pixel(__global const uint* candidates, uint entry, int every_pixel)
{
    return every_pixel ? entry : candidates[entry];
}

// One work-item a pixel. `sample_count`: the film's per-pixel counts, read
// when `per_pixel_counts` (adaptive sampling's film); else every pixel holds
// `uniform_samples`. A pixel is noisy when its relMSE is at least
// `noisy_from` (the noise threshold squared; no threshold: never, and
// `noisy` is not written).
__kernel __attribute__((reqd_work_group_size(ORB_DECISION_GROUP, 1, 1))) void estimate_pixel_errors(
    __global const long* radiance, __global const long* radiance_sq, __global const long* sample_count,
    int per_pixel_counts, double uniform_samples, uint pixel_count, double noisy_from, int mark_noisy,
    __global uchar* noisy, __global double* group_error_sums)
{
    __local double errors[ORB_DECISION_GROUP];
    const uint pixel = (uint)get_global_id(0);
    double error = 0.0;  // past the image: adds nothing
    if (pixel < pixel_count) {
        const double n = per_pixel_counts ? (double)sample_count[pixel] : uniform_samples;
        error = pixel_relmse(radiance, radiance_sq, pixel, n);
        if (mark_noisy) noisy[pixel] = error >= noisy_from ? 1 : 0;
    }
    errors[get_local_id(0)] = error;
    sum_pairwise(errors);
    if (get_local_id(0) == 0) group_error_sums[get_group_id(0)] = errors[0];
}

// One work-item a candidate: each group's count of candidates that keep sampling.
__kernel __attribute__((reqd_work_group_size(ORB_DECISION_GROUP, 1, 1))) void count_still_sampling(
    __global const uint* candidates, uint candidate_count, int every_pixel, __global const uchar* noisy, int width,
    int height, __global uint* group_counts)
{
    __local uint kept;
    if (get_local_id(0) == 0) kept = 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    const uint entry = (uint)get_global_id(0);
    if (entry < candidate_count && keeps_sampling(noisy, candidate_pixel(candidates, entry, every_pixel), width, height))
        atomic_inc(&kept);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (get_local_id(0) == 0) group_counts[get_group_id(0)] = kept;
}

// One group. The exclusive prefix sum of the `count_groups` counts into
// `group_offsets`, and the totals: the candidates kept, and the sum of the
// `error_groups` sums of relMSE, each work-item adding every
// ORB_DECISION_GROUP-th in turn, then pairwise.
__kernel __attribute__((reqd_work_group_size(ORB_DECISION_GROUP, 1, 1))) void sum_decision(
    __global const double* group_error_sums, uint error_groups, __global const uint* group_counts, uint count_groups,
    __global uint* group_offsets, __global DecisionTotals* totals)
{
    __local uint scratch[2 * ORB_DECISION_GROUP];
    __local double sums[ORB_DECISION_GROUP];
    const uint l = (uint)get_local_id(0);
    uint carried = 0;
    for (uint first = 0; first < count_groups; first += ORB_DECISION_GROUP) {
        const uint g = first + l;
        const uint count = g < count_groups ? group_counts[g] : 0u;
        uint chunk = 0;
        const uint offset = exclusive_scan(count, scratch, &chunk);
        if (g < count_groups) group_offsets[g] = carried + offset;
        carried += chunk;
    }
    double running = 0.0;
    for (uint g = l; g < error_groups; g += ORB_DECISION_GROUP) running += group_error_sums[g];
    sums[l] = running;
    sum_pairwise(sums);
    if (l == 0) {
        totals->error_sum = sums[0];
        totals->still_sampling = carried;
        totals->pad0 = 0;
    }
}

// One work-item a candidate: those that keep sampling, at their group's
// offset plus their rank among the group's kept ones.
__kernel __attribute__((reqd_work_group_size(ORB_DECISION_GROUP, 1, 1))) void compact_still_sampling(
    __global const uint* candidates, uint candidate_count, int every_pixel, __global const uchar* noisy, int width,
    int height, __global const uint* group_offsets, __global uint* still_sampling)
{
    __local uint scratch[2 * ORB_DECISION_GROUP];
    const uint entry = (uint)get_global_id(0);
    uint pixel = 0;
    uint keep = 0;
    if (entry < candidate_count) {
        pixel = candidate_pixel(candidates, entry, every_pixel);
        keep = keeps_sampling(noisy, pixel, width, height) ? 1u : 0u;
    }
    uint group_kept = 0;
    const uint rank = exclusive_scan(keep, scratch, &group_kept);
    if (keep) still_sampling[group_offsets[get_group_id(0)] + rank] = pixel;
}

// One work-item a pixel: the list of every pixel, 0, 1, ..., pixel_count - 1
// (a frame's first list, made where it is read rather than uploaded).
__kernel __attribute__((reqd_work_group_size(ORB_DECISION_GROUP, 1, 1))) void list_every_pixel(
    __global uint* list, uint pixel_count)
{
    const uint pixel = (uint)get_global_id(0);
    if (pixel < pixel_count) list[pixel] = pixel;
}
