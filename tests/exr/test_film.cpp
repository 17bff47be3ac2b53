#include "test_film.h"

#include "orb/scene/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include <unistd.h>

namespace orb::exr::testing {

Film synthetic_film(int width, int height, std::uint64_t spp, unsigned seed) {
    Film film;
    film.resize(width, height);
    film.samples_per_pixel = spp;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double n = static_cast<double>(spp);
    const auto fixed = [](double value) { return film::sum_units(film::Units::Fixed, value); };
    for (std::size_t i = 0; i < film.pixel_count(); ++i) {
        const bool miss = i % 7 == 3;
        film.alpha[i] = miss ? 0 : static_cast<film::Sum>(spp / (i % 5 == 0 ? 2 : 1));
        film.depth[i] = miss ? std::numeric_limits<float>::infinity() : 1.0f + 10.0f * static_cast<float>(unit(rng));
        film.object_id[i] = miss ? -1.0f : static_cast<float>(i % 4);
        film.sample_count[i] = static_cast<film::Sum>(spp);
        for (int c = 0; c < 3; ++c) {
            const std::size_t k = i * 3 + c;
            if (miss) continue;
            film.direct[k] = fixed(n * unit(rng));
            film.indirect[k] = fixed(n * 0.3 * unit(rng));
            film.emission[k] = (i % 11 == 0) ? fixed(n * 5.0) : 0;
            film.radiance[k] = film.direct[k] + film.indirect[k] + film.emission[k];
            const double mean = film::sum_value(film::Units::Fixed, film.radiance[k]) / n;
            film.radiance_sq[k] = fixed(n * mean * mean * (1.0 + unit(rng)));
            film.albedo[k] = fixed(n * unit(rng));
            film.normal[k] = film::sum_units(film::Units::SignedFixed, n * (unit(rng) - 0.5));
            film.background[k] = 0;
        }
    }
    return film;
}

ExrMetadata synthetic_metadata() {
    ExrMetadata m;
    m.target_spp = 64;
    m.seed = 18446744073709551557ull;  // needs all 64 bits
    m.max_depth = 6;
    m.mode = "direct";
    m.device = "Test Device (Test Platform)";
    m.render_seconds = 12.5;
    m.scene_file = "scenes/cornell.json";
    m.scene_hash = "0123456789abcdef";
    m.version = "0.1.0";
    m.scene_time = 0.25;
    m.kernel = "5f3a9c0e1d2b4a68";
    orb::Camera camera;
    m.world_to_camera = world_to_camera(camera);
    m.world_to_ndc = world_to_ndc(camera, 8, 6);
    return m;
}

std::string scratch_path(const std::string& name) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("orb-exr-tests-" + std::to_string(::getpid())) /
                                (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

bool within_float_rounding(double a, double b, double ulps) {
    if (std::isinf(a) || std::isinf(b)) return a == b;
    const double scale = std::max({std::fabs(a), std::fabs(b), 1e-30});
    return std::fabs(a - b) <= ulps * std::numeric_limits<float>::epsilon() * scale;
}

std::string message_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const orb::InputError& e) {
        return e.what();
    }
    return "(no orb::InputError thrown)";
}

}  // namespace orb::exr::testing
