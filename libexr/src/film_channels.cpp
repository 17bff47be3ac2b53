#include "film_channels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace orb::exr::detail {
namespace {

using Sums = std::vector<float>;

// Means are computed in double and rounded once, so mean * n gives the sum
// back within a float rounding or two.
std::vector<float> mean_channel(const Sums& sums, int components, int component, double n) {
    const std::size_t pixels = sums.size() / components;
    std::vector<float> out(pixels);
    for (std::size_t i = 0; i < pixels; ++i)
        out[i] = static_cast<float>(static_cast<double>(sums[i * components + component]) / n);
    return out;
}

void add_mean_planes(std::vector<Plane>& planes, const std::vector<std::string>& names, const Sums& sums,
                     double n) {
    const int components = static_cast<int>(names.size());
    for (int c = 0; c < components; ++c) planes.push_back({names[c], false, mean_channel(sums, components, c, n)});
}

// Variance of the pixel mean: the unbiased sample variance divided by n,
// (sum_sq/n - mean^2) * n/(n-1) / n. Zero with fewer than two samples,
// where it is unknown (and where sum_sq = mean^2 recovers exactly).
std::vector<float> variance_channel(const render::Film& film, int component, std::uint64_t n) {
    std::vector<float> out(film.pixel_count(), 0.0f);
    if (n < 2) return out;
    const double nd = static_cast<double>(n);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double mean = static_cast<double>(film.radiance[i * 3 + component]) / nd;
        const double mean_sq = static_cast<double>(film.radiance_sq[i * 3 + component]) / nd;
        out[i] = static_cast<float>(std::max(0.0, mean_sq - mean * mean) / (nd - 1.0));
    }
    return out;
}

void add_normal_planes(std::vector<Plane>& planes, const render::Film& film, double n) {
    const std::size_t pixels = film.pixel_count();
    Plane x{"N.X", false, std::vector<float>(pixels)}, y{"N.Y", false, std::vector<float>(pixels)},
        z{"N.Z", false, std::vector<float>(pixels)}, length{"orb.normalLength", true, std::vector<float>(pixels)};
    for (std::size_t i = 0; i < pixels; ++i) {
        const double m[3] = {film.normal[i * 3] / n, film.normal[i * 3 + 1] / n, film.normal[i * 3 + 2] / n};
        const double l = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        const double scale = l > 0 ? 1.0 / l : 0.0;
        x.values[i] = static_cast<float>(m[0] * scale);
        y.values[i] = static_cast<float>(m[1] * scale);
        z.values[i] = static_cast<float>(m[2] * scale);
        length.values[i] = static_cast<float>(l);
    }
    planes.push_back(std::move(x));
    planes.push_back(std::move(y));
    planes.push_back(std::move(z));
    planes.push_back(std::move(length));
}

const std::vector<float>& plane(const std::map<std::string, std::vector<float>>& planes, const std::string& name) {
    auto it = planes.find(name);
    if (it == planes.end()) throw std::logic_error("channel " + name + " was not read");
    return it->second;
}

void recover_sums(const std::map<std::string, std::vector<float>>& planes, const std::vector<std::string>& names,
                  double n, Sums& sums) {
    const std::size_t components = names.size();
    for (std::size_t c = 0; c < components; ++c) {
        const auto& means = plane(planes, names[c]);
        for (std::size_t i = 0; i < means.size(); ++i)
            sums[i * components + c] = static_cast<float>(static_cast<double>(means[i]) * n);
    }
}

}  // namespace

std::vector<Plane> film_to_planes(const render::Film& film, const std::vector<Pass>& passes) {
    if (film.samples_per_pixel == 0) throw std::invalid_argument("the film holds no samples");
    const double n = static_cast<double>(film.samples_per_pixel);
    std::vector<Plane> planes;
    for (Pass pass : passes) {
        switch (pass) {
            case Pass::Beauty: {
                add_mean_planes(planes, {"R", "G", "B"}, film.radiance, n);
                planes.push_back({"A", false, mean_channel(film.alpha, 1, 0, n)});
                break;
            }
            case Pass::Direct: add_mean_planes(planes, pass_channels(pass), film.direct, n); break;
            case Pass::Indirect: add_mean_planes(planes, pass_channels(pass), film.indirect, n); break;
            case Pass::Emission: add_mean_planes(planes, pass_channels(pass), film.emission, n); break;
            case Pass::Albedo: add_mean_planes(planes, pass_channels(pass), film.albedo, n); break;
            case Pass::Normal: add_normal_planes(planes, film, n); break;
            case Pass::Depth: planes.push_back({"Z", true, film.depth}); break;
            case Pass::Variance: {
                const auto names = pass_channels(pass);
                for (int c = 0; c < 3; ++c) planes.push_back({names[c], false, variance_channel(film, c, film.samples_per_pixel)});
                break;
            }
            case Pass::Id: planes.push_back({"id", true, film.object_id}); break;
        }
    }
    return planes;
}

void planes_to_film(const std::map<std::string, std::vector<float>>& planes, const std::vector<Pass>& passes,
                    render::Film& film) {
    const std::uint64_t count = film.samples_per_pixel;
    const double n = static_cast<double>(count);
    for (Pass pass : passes) {
        switch (pass) {
            case Pass::Beauty:
                recover_sums(planes, {"R", "G", "B"}, n, film.radiance);
                recover_sums(planes, {"A"}, n, film.alpha);
                break;
            case Pass::Direct: recover_sums(planes, pass_channels(pass), n, film.direct); break;
            case Pass::Indirect: recover_sums(planes, pass_channels(pass), n, film.indirect); break;
            case Pass::Emission: recover_sums(planes, pass_channels(pass), n, film.emission); break;
            case Pass::Albedo: recover_sums(planes, pass_channels(pass), n, film.albedo); break;
            case Pass::Normal: {
                const auto& length = plane(planes, "orb.normalLength");
                const std::string names[3] = {"N.X", "N.Y", "N.Z"};
                for (int c = 0; c < 3; ++c) {
                    const auto& unit = plane(planes, names[c]);
                    for (std::size_t i = 0; i < unit.size(); ++i)
                        film.normal[i * 3 + c] = static_cast<float>(static_cast<double>(unit[i]) * length[i] * n);
                }
                break;
            }
            case Pass::Depth: film.depth = plane(planes, "Z"); break;
            case Pass::Variance: {
                // sum_sq = n ((n-1) var + mean^2), from the stored mean; needs beauty.
                if (!contains(passes, Pass::Beauty)) break;
                const std::string mean_names[3] = {"R", "G", "B"};
                const auto names = pass_channels(pass);
                for (int c = 0; c < 3; ++c) {
                    const auto& variance = plane(planes, names[c]);
                    const auto& mean = plane(planes, mean_names[c]);
                    for (std::size_t i = 0; i < variance.size(); ++i) {
                        const double m = mean[i];
                        film.radiance_sq[i * 3 + c] =
                            static_cast<float>(n * ((n - 1.0) * static_cast<double>(variance[i]) + m * m));
                    }
                }
                break;
            }
            case Pass::Id: film.object_id = plane(planes, "id"); break;
        }
    }
}

}  // namespace orb::exr::detail
