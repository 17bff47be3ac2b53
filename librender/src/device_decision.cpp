#include "device_decision.h"

#include <algorithm>
#include <stdexcept>

#include "orb/tables/adaptive_decision.h"

namespace orb::render {
namespace {

constexpr std::size_t kGroup = ORB_DECISION_GROUP;

std::size_t groups_of(std::size_t count) { return (count + kGroup - 1) / kGroup; }

// A launch of `count` work-items, rounded up to whole groups (at least one).
void launch(cl::CommandQueue& queue, const cl::Kernel& kernel, std::size_t count)
{
    const std::size_t groups = std::max<std::size_t>(1, groups_of(count));
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(groups * kGroup), cl::NDRange(kGroup));
}

const cl::Buffer& film_buffer(const DeviceFilm& film, film::Channel channel)
{
    return film.buffers()[static_cast<std::size_t>(channel)];
}

}  // namespace

std::unique_ptr<DeviceDecision> DeviceDecision::make(DeviceSession& session, int width, int height)
{
    const cl::Program* program = session.decision_program();
    if (!program) return nullptr;
    return std::make_unique<DeviceDecision>(session.context(), *program, width, height);
}

DeviceDecision::DeviceDecision(const cl::Context& context, const cl::Program& program, int width, int height)
    : width_(width),
      height_(height),
      estimate_(program, "estimate_pixel_errors"),
      count_(program, "count_still_sampling"),
      sum_(program, "sum_decision"),
      compact_(program, "compact_still_sampling"),
      every_(program, "list_every_pixel")
{
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    const std::size_t groups = std::max<std::size_t>(1, groups_of(pixels));
    noisy_ = cl::Buffer(context, CL_MEM_READ_WRITE, pixels);
    group_error_sums_ = cl::Buffer(context, CL_MEM_READ_WRITE, groups * sizeof(double));
    group_counts_ = cl::Buffer(context, CL_MEM_READ_WRITE, groups * sizeof(cl_uint));
    group_offsets_ = cl::Buffer(context, CL_MEM_READ_WRITE, groups * sizeof(cl_uint));
    totals_ = cl::Buffer(context, CL_MEM_READ_WRITE, sizeof(device::DecisionTotals));
}

void DeviceDecision::list_every_pixel(cl::CommandQueue& queue, cl::Buffer& list)
{
    const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    every_.setArg(0, list);
    every_.setArg(1, static_cast<cl_uint>(pixels));
    launch(queue, every_, pixels);
}

void DeviceDecision::prepare(cl::CommandQueue& queue, const DeviceFilm& film)
{
    // Over no pixel and no candidate: each kernel runs one group that adds
    // and keeps nothing. PoCL makes a kernel's work-group code at its first
    // launch (seconds for a program not in its cache).
    DecisionInput nothing;
    nothing.noisy_from = 1.0;
    nothing.candidates = &noisy_;
    nothing.still_sampling = &noisy_;
    run(queue, film, nothing, 0, true);
    every_.setArg(0, noisy_);
    every_.setArg(1, cl_uint{0});
    launch(queue, every_, 0);
    queue.finish();
}

DecisionOutput DeviceDecision::decide(cl::CommandQueue& queue, const DeviceFilm& film, const DecisionInput& input)
{
    const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    if (input.noisy_from && (!input.still_sampling || (!input.every_pixel && !input.candidates) ||
                             input.candidate_count > pixels))
        throw std::invalid_argument("a device decision with a noise threshold needs its candidates and a list to fill");
    return run(queue, film, input, pixels, false);
}

DecisionOutput DeviceDecision::run(cl::CommandQueue& queue, const DeviceFilm& film, const DecisionInput& input,
                                   std::size_t pixels, bool every_kernel)
{
    const bool threshold = input.noisy_from.has_value();
    const cl_int per_pixel_counts = film.computes(film::Channel::sample_count) ? 1 : 0;
    const std::size_t candidates = threshold ? input.candidate_count : 0;

    cl_uint arg = 0;
    estimate_.setArg(arg++, film_buffer(film, film::Channel::radiance));
    estimate_.setArg(arg++, film_buffer(film, film::Channel::radiance_sq));
    estimate_.setArg(arg++, film_buffer(film, film::Channel::sample_count));
    estimate_.setArg(arg++, per_pixel_counts);
    estimate_.setArg(arg++, input.uniform_samples);
    estimate_.setArg(arg++, static_cast<cl_uint>(pixels));
    estimate_.setArg(arg++, input.noisy_from.value_or(0.0));
    estimate_.setArg(arg++, static_cast<cl_int>(threshold ? 1 : 0));
    estimate_.setArg(arg++, noisy_);
    estimate_.setArg(arg++, group_error_sums_);
    launch(queue, estimate_, pixels);

    // Without candidates the list kernels have nothing to do: only the sum runs.
    const cl::Buffer& candidate_list = input.candidates ? *input.candidates : noisy_;  // never read when every_pixel
    const auto list_args = [&](cl::Kernel& kernel) {
        cl_uint a = 0;
        kernel.setArg(a++, candidate_list);
        kernel.setArg(a++, static_cast<cl_uint>(candidates));
        kernel.setArg(a++, static_cast<cl_int>(input.every_pixel ? 1 : 0));
        kernel.setArg(a++, noisy_);
        kernel.setArg(a++, static_cast<cl_int>(width_));
        kernel.setArg(a++, static_cast<cl_int>(height_));
        return a;
    };
    if (candidates > 0 || every_kernel) {
        const cl_uint a = list_args(count_);
        count_.setArg(a, group_counts_);
        launch(queue, count_, candidates);
    }

    arg = 0;
    sum_.setArg(arg++, group_error_sums_);
    sum_.setArg(arg++, static_cast<cl_uint>(std::max<std::size_t>(1, groups_of(pixels))));
    sum_.setArg(arg++, group_counts_);
    sum_.setArg(arg++, static_cast<cl_uint>(groups_of(candidates)));
    sum_.setArg(arg++, group_offsets_);
    sum_.setArg(arg++, totals_);
    queue.enqueueNDRangeKernel(sum_, cl::NullRange, cl::NDRange(kGroup), cl::NDRange(kGroup));

    if (candidates > 0 || every_kernel) {
        const cl_uint a = list_args(compact_);
        compact_.setArg(a, group_offsets_);
        compact_.setArg(a + 1, *input.still_sampling);
        launch(queue, compact_, candidates);
    }

    device::DecisionTotals totals{};
    queue.enqueueReadBuffer(totals_, CL_TRUE, 0, sizeof totals, &totals);
    return {totals.error_sum, totals.still_sampling};
}

}  // namespace orb::render
