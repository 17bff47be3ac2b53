// What Scene.render and Scene.render_progressive share: orb-render's
// settings of a still from Python's arguments, the scene as orb-render has
// it once read, and the rendered image with its layers as Python holds it.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orb/job/render_job.h"
#include "orb/scene/scene.h"

namespace orb::python {

// The rendered image and its layers as the EXR holds them; numpy arrays of
// the layers point into `layers` and keep this alive through their base.
struct RenderedLayers {
    job::RenderedImage image;
    std::vector<job::Layer> layers;
};

// `image` with its layers read out (the GIL is released meanwhile).
std::shared_ptr<RenderedLayers> with_layers(job::RenderedImage image);

// orb-render --width --height --spp --seed --device --passes --denoise
// --target-error --noise-threshold --time; a pass it does not know raises
// ValueError with its message.
job::StillSettings still_settings(int width, int height, std::uint64_t spp, std::uint64_t seed,
                                  const std::string& device, const std::vector<std::string>& passes, bool denoise,
                                  std::optional<double> target_error, std::optional<double> noise_threshold,
                                  std::optional<double> time_limit);

// `posed` as orb-render has a scene once read: itself, or, when it has an
// environment map, a copy in `with_map` with the map's texels loaded (from
// the current directory, where Python resolves paths).
const Scene& scene_to_render(const Scene& posed, Scene& with_map);

}  // namespace orb::python
