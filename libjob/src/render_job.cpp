#include "orb/job/render_job.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "orb/denoise/exr_memory_streams.h"
#include "orb/job/benchmarks.h"
#include "orb/job/output_film.h"
#include "orb/job/render_film.h"
#include "orb/job/render_plan.h"
#include "orb/render/device.h"
#include "orb/scene/scene_json.h"

namespace orb::job {
namespace {

// What orb-render's command line would say for these settings: the ones
// given, the rest from the scene's render block (as request::resolve_request).
PlanOptions plan_options(const Scene& scene, const StillSettings& s) {
    PlanOptions o;
    if (s.width > 0) o.given.width = s.width;
    if (s.height > 0) o.given.height = s.height;
    if (s.spp > 0) o.given.spp = s.spp;
    o.given.seed = s.seed;
    if (!s.mode.empty()) o.given.mode = s.mode;
    if (!s.sampler.empty()) o.given.sampler = s.sampler;
    o.given.max_depth = s.max_depth;
    o.given.passes = s.passes;
    o.given.half = s.half;
    o.settings = resolve_settings(o.given, &scene.render);
    o.noise_threshold = s.noise_threshold;
    o.target_error = s.target_error;
    o.device = s.device == "default" ? "" : s.device;
    o.denoise = s.denoise;
    o.checkpoints_or_time_limit = s.time_limit.has_value();
    o.messages = s.on_message;
    return o;
}

}  // namespace

RenderedImage render_still(const Scene& scene, const StillSettings& settings, const ProgressCallback& progress,
                           const std::atomic<bool>* cancel) {
    validate_scene(scene, settings.label);
    if (!scene_has_light(scene))
        say(settings.on_message, MessageKind::Warning,
            settings.label + ": the scene has no light (no sphere emits and there is no environment); it renders black");
    const PlanOptions options = plan_options(scene, settings);
    RenderPlan plan = make_render_plan(options, SceneInput{scene, settings.label, nullptr}, render::DevelopmentKnobs{});
    const ReadyRenderer ready = make_ready_renderer(plan);
    render::Renderer& renderer = *ready.renderer;
    start_film(plan, renderer);

    // The caller's flag and the callback's answer both stop the loop after the pass in flight.
    std::atomic<bool> stop{cancel && cancel->load()};
    FilmRun run;
    run.time_limit = settings.time_limit;
    run.cancel = &stop;
    run.on_pass = [&](const render::ProgressState& state) {
        if (cancel && cancel->load()) stop = true;
        if (!progress) return;
        const PreviewAccess preview([&renderer](Film& into) { renderer.read_film(into); });
        const Progress now{state.pass, state.spp, state.target_spp, state.elapsed_seconds, state.samples_per_second};
        if (!progress(now, preview)) stop = true;
    };
    if (settings.on_snapshot) {
        run.checkpoint = settings.snapshot_seconds > 0 ? std::optional<double>(settings.snapshot_seconds) : std::nullopt;
        run.checkpoint_passes = settings.snapshot_seconds > 0 ? 0 : std::max(settings.snapshot_passes, 1);
        run.on_checkpoint = [&](FinalImage& checkpoint, const render::ProgressState& state) {
            RenderedImage snapshot;
            snapshot.film = std::move(checkpoint.film);
            snapshot.metadata = std::move(checkpoint.metadata);
            snapshot.options = checkpoint.options;  // a checkpoint's: exact sums, so that it can be continued
            snapshot.denoiser = plan.denoiser;      // the same layers as the final image
            snapshot.snapshot = true;
            snapshot.stats = renderer_stats(renderer);
            snapshot.stats.passes = state.pass;
            snapshot.stats.seconds = state.elapsed_seconds;
            snapshot.stats.samples_per_second = state.samples_per_second;
            settings.on_snapshot(std::move(snapshot));
        };
    }
    FilmOutcome outcome = render_film(renderer, plan, std::move(run));
    if (!outcome.rendered) throw std::runtime_error("stopped before the first pass finished; there is no image");
    outcome.image.wait_for_film();  // warns of sums out of range, as orb-render's final write does

    RenderedImage image;
    image.film = std::move(outcome.image.film);
    image.metadata = std::move(outcome.image.metadata);
    image.options = outcome.image.options;
    image.denoiser = outcome.image.denoiser;
    image.stopped = outcome.reason == render::StopReason::Interrupted ||
                    outcome.reason == render::StopReason::ReachedTime;
    image.stats = outcome.stats;
    return image;
}

std::string RenderedImage::encode_exr() const { return encode_exr(options.compression); }

std::string RenderedImage::encode_exr(exr::ExrCompression compression) const {
    exr::ExrWriteOptions write = options;
    write.compression = compression;
    return exr::encode_film_exr(film, metadata, write, denoised_layer(denoiser, nullptr));
}

void RenderedImage::save_exr(const std::string& path) const {
    const std::string bytes = encode_exr();
    // Beside the target, then renamed: a reader never sees half a file.
    const std::string temporary = path + ".orb-partial";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw std::runtime_error(path + ": cannot write");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        const std::string why = ec.message();  // before removing the temporary file resets `ec`
        std::filesystem::remove(temporary, ec);
        throw std::runtime_error(path + ": cannot write: " + why);
    }
}

std::vector<Layer> RenderedImage::layers() const {
    const std::string bytes = encode_exr(exr::ExrCompression::None);  // the same values, quicker to read back
    denoise::MemoryInput stream(bytes, "<rendered image>");
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;

    // The passes as orb-render wrote them, then the post layers (`denoised`)
    // the file holds, each with its channels in the film table's order.
    std::vector<Layer> layers;
    for (exr::Pass pass : options.passes)
        layers.push_back(Layer{exr::pass_name(pass), exr::pass_channels(pass), width, height, {}});
    for (const film::PostLayerInfo& post : film::kPostLayers) {
        if (!file.header().channels().findChannel(post.exr_names[0])) continue;
        layers.push_back(Layer{post.name, {}, width, height, {}});
        for (int c = 0; c < post.exr_name_count; ++c) layers.back().channels.push_back(post.exr_names[c]);
    }

    Imf::FrameBuffer buffer;
    for (Layer& layer : layers) {
        const std::size_t stride = layer.channels.size();
        layer.pixels.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * stride, 0.0f);
        for (std::size_t c = 0; c < stride; ++c) {
            char* origin = reinterpret_cast<char*>(layer.pixels.data() + c) -
                           (static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width) *
                               static_cast<std::ptrdiff_t>(stride * sizeof(float));
            buffer.insert(layer.channels[c], Imf::Slice(Imf::FLOAT, origin, stride * sizeof(float),
                                                        stride * sizeof(float) * static_cast<std::size_t>(width)));
        }
    }
    file.setFrameBuffer(buffer);
    file.readPixels(window.min.y, window.max.y);
    return layers;
}

std::vector<DeviceListing> list_devices() {
    std::vector<DeviceListing> listing;
    for (const render::DeviceInfo& d : render::list_devices())
        listing.push_back({d.index, d.is_gpu ? "gpu" : d.is_cpu ? "cpu" : "other", d.compute_units,
                           d.global_memory_bytes, d.platform, d.name, d.vendor, d.version});
    return listing;
}

}  // namespace orb::job
