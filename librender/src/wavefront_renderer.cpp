#include "wavefront_renderer.h"

#include <array>
#include <chrono>
#include <stdexcept>

#include "device_renderer.h"

namespace orb::render {
namespace {

constexpr cl_uint kFirstOwnArg = static_cast<cl_uint>(PassArg::count);
constexpr std::size_t kGroup = 128;  // four warps on NVIDIA
// counts[] of kernels/wavefront.cl: two path queues, then the shadow queue.
constexpr int kShadowCount = 2;
constexpr int kCounts = 3;

template <typename... Args>
void bind_own(cl::Kernel& kernel, const Args&... args)
{
    cl_uint index = kFirstOwnArg;
    (kernel.setArg(index++, args), ...);
}

}  // namespace

WavefrontRenderer::WavefrontRenderer(std::shared_ptr<DeviceSession> session, const SceneLayout& scene,
                                     const device::CameraParams& camera, const RenderConfig& config,
                                     int paths_per_pixel, const std::string& extra_options)
    : session_(std::move(session)),
      pixels_(config.width * config.height),
      paths_per_pixel_(paths_per_pixel),
      max_depth_(config.max_depth),
      film_(session_->context(), 1, 1)
{
    if (config.mode != IntegratorMode::Global)
        throw std::invalid_argument("the wavefront renderer has global mode only");
    if (config.width <= 0 || config.height <= 0 || paths_per_pixel <= 0)
        throw std::invalid_argument("the wavefront renderer needs a positive size and paths per pixel");
    std::string options = render_program_options(*session_, scene, config, 0) + " -DORB_WAVEFRONT=1";
    if (!extra_options.empty()) options += " " + extra_options;
    const cl::Program& program = session_->program(options);
    const std::size_t paths = static_cast<std::size_t>(pixels_) * paths_per_pixel_;
    global_size_ = cl::NDRange((paths + kGroup - 1) / kGroup * kGroup);
    try {
        // The float4 words per path and per shadow ray (kernels/wavefront.cl).
        cl::Kernel words_kernel(program, "wavefront_record_words");
        cl::Buffer words(session_->context(), CL_MEM_WRITE_ONLY, 2 * sizeof(cl_int));
        words_kernel.setArg(0, words);
        cl::CommandQueue& queue = session_->queue();
        queue.enqueueTask(words_kernel);
        std::array<cl_int, 2> record_words{};
        queue.enqueueReadBuffer(words, CL_TRUE, 0, sizeof(record_words), record_words.data());

        const cl::Context& context = session_->context();
        // Each array of words spans the launches' global size (wavefront.cl's WAVEFRONT_WORD).
        const std::size_t slots = global_size_[0];
        path_bytes_ = slots * static_cast<std::uint64_t>(record_words[0]) * sizeof(cl_float4);
        paths_ = cl::Buffer(context, CL_MEM_READ_WRITE, path_bytes_);
        for (cl::Buffer& q : queues_) q = cl::Buffer(context, CL_MEM_READ_WRITE, paths * sizeof(cl_int));
        counts_ = cl::Buffer(context, CL_MEM_READ_WRITE, kCounts * sizeof(cl_int));
        hits_ = cl::Buffer(context, CL_MEM_READ_WRITE, paths * 2 * sizeof(cl_int));
        shadow_rays_ = cl::Buffer(context, CL_MEM_READ_WRITE,
                                  slots * static_cast<std::size_t>(record_words[1]) * sizeof(cl_float4));
        radiance_ = cl::Buffer(context, CL_MEM_READ_WRITE, paths * 4 * sizeof(cl_float));

        scene_buffers_ = upload_scene(context, scene.tables);
        begin_ = cl::Kernel(program, "wavefront_begin");
        intersect_ = cl::Kernel(program, "wavefront_intersect");
        shade_ = cl::Kernel(program, "wavefront_shade");
        shadow_ = cl::Kernel(program, "wavefront_shadow");
        bind_buffers(begin_, film_, scene_buffers_, 3);
        bind_buffers(intersect_, film_, scene_buffers_, 5);
        bind_buffers(shade_, film_, scene_buffers_, 9);
        bind_buffers(shadow_, film_, scene_buffers_, 3);
        bind_own(begin_, paths_, queues_[0], paths_per_pixel_);
        bind_own(shadow_, shadow_rays_, counts_, radiance_);

        device::RenderSettings& settings = params_.settings;
        settings.width = config.width;
        settings.height = config.height;
        settings.max_depth = config.max_depth;
        settings.mode = static_cast<int>(config.mode);
        settings.seed_lo = static_cast<device::uint>(config.seed & 0xffffffffu);
        settings.seed_hi = static_cast<device::uint>(config.seed >> 32);
        params_.camera = camera;
        params_.scene = scene.counts;
        params_.environment = scene.environment;
        for (cl::Kernel* kernel : {&begin_, &intersect_, &shade_, &shadow_}) bind_params(*kernel, params_);
    } catch (const cl::Error& error) {
        fail(error, "setting up the wavefront kernels");
    }
    clear();
}

void WavefrontRenderer::fail(const cl::Error& error, const std::string& what) const
{
    throw std::runtime_error(what + " on " + session_->info().name + " failed: " + describe_cl_error(error));
}

void WavefrontRenderer::clear()
{
    try {
        session_->queue().enqueueFillBuffer(radiance_, cl_float(0), 0,
                                            static_cast<std::size_t>(pixels_) * paths_per_pixel_ * 4 * sizeof(cl_float));
    } catch (const cl::Error& error) {
        fail(error, "clearing the radiance");
    }
}

void WavefrontRenderer::enqueue_wave(std::uint64_t first_sample, WaveProfile* profile)
{
    cl::CommandQueue& queue = session_->queue();
    auto start = std::chrono::steady_clock::now();
    // Without a profile, nothing waits; with one, each step is timed to its end.
    const auto timed = [&](double* seconds) {
        if (!profile) return;
        queue.finish();
        const auto now = std::chrono::steady_clock::now();
        *seconds += std::chrono::duration<double>(now - start).count();
        start = now;
    };
    const auto read_count = [&](int slot, std::vector<int>& into) {
        if (!profile) return;
        cl_int count = 0;
        queue.enqueueReadBuffer(counts_, CL_TRUE, slot * sizeof(cl_int), sizeof(cl_int), &count);
        into.push_back(count);
        start = std::chrono::steady_clock::now();
    };
    const cl_int paths = pixels_ * paths_per_pixel_;
    params_.pass.first_sample_lo = static_cast<device::uint>(first_sample & 0xffffffffu);
    params_.pass.first_sample_hi = static_cast<device::uint>(first_sample >> 32);
    bind_params(begin_, params_);
    if (profile) queue.finish(), start = std::chrono::steady_clock::now();
    queue.enqueueFillBuffer(counts_, paths, 0, sizeof(cl_int));
    queue.enqueueNDRangeKernel(begin_, cl::NullRange, global_size_, cl::NDRange(kGroup));
    timed(profile ? &profile->begin : nullptr);
    // The ray leaving scattering event max_depth is still cast, for the
    // emission it may hit: max_depth + 1 casts at most.
    for (int event = 0; event <= max_depth_; ++event) {
        const int in = event % 2, out = 1 - in;
        if (profile) read_count(in, profile->paths);
        bind_own(intersect_, paths_, queues_[in], counts_, in, hits_);
        queue.enqueueNDRangeKernel(intersect_, cl::NullRange, global_size_, cl::NDRange(kGroup));
        timed(profile ? &profile->intersect : nullptr);
        queue.enqueueFillBuffer(counts_, cl_int(0), out * sizeof(cl_int), sizeof(cl_int));
        queue.enqueueFillBuffer(counts_, cl_int(0), kShadowCount * sizeof(cl_int), sizeof(cl_int));
        bind_own(shade_, paths_, queues_[in], queues_[out], counts_, in, out, hits_, shadow_rays_, radiance_);
        queue.enqueueNDRangeKernel(shade_, cl::NullRange, global_size_, cl::NDRange(kGroup));
        timed(profile ? &profile->shade : nullptr);
        if (profile) read_count(kShadowCount, profile->shadow_rays);
        queue.enqueueNDRangeKernel(shadow_, cl::NullRange, global_size_, cl::NDRange(kGroup));
        timed(profile ? &profile->shadow : nullptr);
    }
}

WavefrontRenderer::WaveProfile WavefrontRenderer::profile_wave(std::uint64_t first_sample)
{
    WaveProfile profile;
    try {
        enqueue_wave(first_sample, &profile);
    } catch (const cl::Error& error) {
        fail(error, "a profiled wave");
    }
    return profile;
}

void WavefrontRenderer::enqueue(std::uint64_t first_sample, int waves)
{
    try {
        for (int w = 0; w < waves; ++w)
            enqueue_wave(first_sample + static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(paths_per_pixel_));
        session_->queue().flush();
    } catch (const cl::Error& error) {
        fail(error, "a wave");
    }
}

void WavefrontRenderer::finish()
{
    try {
        session_->queue().finish();
    } catch (const cl::Error& error) {
        fail(error, "waiting for the waves");
    }
}

std::vector<float> WavefrontRenderer::radiance_sums()
{
    const std::size_t paths = static_cast<std::size_t>(pixels_) * paths_per_pixel_;
    std::vector<float> per_path(paths * 4);
    try {
        session_->queue().enqueueReadBuffer(radiance_, CL_TRUE, 0, per_path.size() * sizeof(float), per_path.data());
    } catch (const cl::Error& error) {
        fail(error, "reading the radiance");
    }
    // Path p is pixel p % pixels; a pixel's paths hold its samples in turn.
    std::vector<float> sums(static_cast<std::size_t>(pixels_) * 3, 0.0f);
    for (std::size_t p = 0; p < paths; ++p)
        for (int c = 0; c < 3; ++c) sums[(p % pixels_) * 3 + c] += per_path[p * 4 + c];
    return sums;
}

}  // namespace orb::render
