#include "orb/cli/camera_options.h"

#include <charconv>
#include <cmath>
#include <functional>

#include "orb/cli/number_checks.h"
#include "orb/scene/auto_framing.h"
#include "orb/scene/camera_frame.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace orb::cli {
namespace {

const CLI::Validator kPoint(
    [](std::string& text) -> std::string {
        if (parse_point(text)) return {};
        return "expected three finite numbers X,Y,Z (each of magnitude at most 1e18), got '" + text + "'";
    },
    "X,Y,Z");

// Shortest round-trip form, so the message shows the numbers as typed.
std::string format_point(const Vec3& v) {
    std::string out;
    for (int c = 0; c < 3; ++c) {
        char digits[32];
        const auto [end, error] = std::to_chars(digits, digits + sizeof digits, v[c]);
        out.append(c ? "," : "").append(digits, error == std::errc{} ? end : digits);
    }
    return out;
}

void add_point_option(CLI::App& app, const std::string& name, std::optional<Vec3>& target, const std::string& help) {
    app.add_option_function<std::string>(
           name, [&target](const std::string& text) { target = parse_point(text); }, help)
        ->check(kPoint)
        ->option_text("X,Y,Z")
        ->group("Camera");
}

}  // namespace

std::optional<Vec3> parse_point(const std::string& text) {
    Vec3 point{};
    std::size_t start = 0;
    for (int c = 0; c < 3; ++c) {
        const std::size_t comma = text.find(',', start);
        if ((c < 2) != (comma != std::string::npos)) return std::nullopt;
        const std::optional<double> value = parse_number(text.substr(start, comma - start));
        if (!value || !std::isfinite(*value) || std::fabs(*value) > kMaxSceneMagnitude) return std::nullopt;
        point[c] = *value;
        start = comma + 1;
    }
    return point;
}

void add_camera_options(CLI::App& app, CameraOptions& o) {
    add_point_option(app, "--camera-position", o.position, "Where the camera stands (default: the scene's)");
    add_point_option(app, "--look-at", o.look_at, "The point the camera looks at (default: the scene's target)");
    add_point_option(app, "--up", o.up, "The camera's up direction (default: the scene's)");
    app.add_option("--vfov", o.vfov_deg, "Vertical field of view in degrees, in (0, 180) (default: the scene's)")
        ->check(finite_number_where([](double v) { return v > 0 && v < 180; }, "degrees in (0, 180)"))
        ->option_text("DEGREES")
        ->group("Camera");
    app.add_option("--aperture", o.aperture, "Lens diameter; 0 is a pinhole (default: the scene's)")
        ->check(finite_number_where([](double v) { return v >= 0 && v <= kMaxSceneMagnitude; }, "a lens diameter >= 0"))
        ->option_text("D")
        ->group("Camera");
    app.add_option("--focus-distance", o.focus_distance,
                   "Distance from the lens to the plane in focus (default: the scene's)")
        ->check(finite_number_where([](double v) { return v >= kMinScenePositive && v <= kMaxSceneMagnitude; },
                             "a distance > 0"))
        ->option_text("D")
        ->group("Camera");
    CLI::Option* orthographic =
        app.add_option("--orthographic", o.orthographic_height,
                       "An orthographic camera whose view is HEIGHT scene units high (default: the scene's)")
            ->check(finite_number_where([](double v) { return v >= kMinScenePositive && v <= kMaxSceneMagnitude; },
                                 "a height > 0 in scene units"))
            ->option_text("HEIGHT")
            ->group("Camera");
    // The way back from a scene whose camera is orthographic (height 0 is the
    // scene format's perspective camera).
    app.add_flag_callback("--perspective", [&o] { o.orthographic_height = 0.0; },
                          "A perspective camera, even where the scene's is orthographic")
        ->excludes(orthographic)
        ->group("Camera");
    app.add_flag("--auto-camera", o.auto_camera,
                 "Frame the scene's spheres anew for this image (stray points left out), from the camera's "
                 "direction; --camera-position, --look-at and --focus-distance still win")
        ->group("Camera");
}

void apply_camera_options(const CameraOptions& o, Scene& scene, int width, int height, const std::string& source) {
    if (!o.auto_camera) return apply_camera_options(o, scene.camera, source);
    CameraOptions lens;
    lens.up = o.up;
    lens.vfov_deg = o.vfov_deg;
    lens.aperture = o.aperture;
    lens.orthographic_height = o.orthographic_height;
    apply_camera_options(lens, scene.camera, source);

    Camera& camera = scene.camera;
    const FramingView view{{camera.position[0] - camera.target[0], camera.position[1] - camera.target[1],
                            camera.position[2] - camera.target[2]},
                           camera.up, camera.vfov_deg, width, height};
    // Lights placed around the scene (a PLY cloud's, a glTF sun) are not what is to be seen.
    const auto emits = [&scene](std::size_t i) {
        const Vec3& e = scene.materials[scene.spheres[i].material].emission;
        return e[0] > 0 || e[1] > 0 || e[2] > 0;
    };
    std::optional<Framing> framing = frame_spheres(scene.spheres, view, emits);
    if (!framing) framing = frame_spheres(scene.spheres, view);
    if (framing) {
        camera.position = framing->position;
        camera.target = framing->target;
        camera.focus_distance = framing->distance;
    }

    CameraOptions placed;
    placed.position = o.position;
    placed.look_at = o.look_at;
    placed.focus_distance = o.focus_distance;
    apply_camera_options(placed, camera, source);
}

void apply_camera_options(const CameraOptions& o, Camera& camera, const std::string& source) {
    if (o.position) camera.position = *o.position;
    if (o.look_at) camera.target = *o.look_at;
    if (o.up) camera.up = *o.up;
    if (o.vfov_deg) camera.vfov_deg = *o.vfov_deg;
    if (o.aperture) camera.aperture = *o.aperture;
    if (o.focus_distance) camera.focus_distance = *o.focus_distance;
    if (o.orthographic_height) camera.orthographic_height = *o.orthographic_height;
    if (!o.position && !o.look_at && !o.up) return;  // the scene's own view stands (it was checked on reading)

    const Vec3& p = camera.position;
    const Vec3& t = camera.target;
    const Vec3 forward{t[0] - p[0], t[1] - p[1], t[2] - p[2]};
    const double forward_length = std::hypot(forward[0], forward[1], forward[2]);
    if (!(forward_length > 0)) {
        const std::string where = format_point(p);
        const std::string why = o.position && o.look_at ? "--camera-position and --look-at are the same point " + where
                                : o.look_at ? "--look-at " + where + " is where the scene's camera stands; give --camera-position too"
                                            : "--camera-position " + where + " is the point the scene's camera looks at; give --look-at too";
        throw InputError(source + ": " + why + " (the camera needs a direction to look in)");
    }
    const Vec3& u = camera.up;
    const double up_length = std::hypot(u[0], u[1], u[2]);
    if (!(up_length > 0)) throw InputError(source + ": --up must not be the zero vector");
    // The scene loader's own test, so an option refuses what a scene file would.
    if (!(view_up_sine(forward, u) > kMinViewUpSine)) {
        const std::string view = "the view direction " + format_point(forward);
        const std::string why = o.up ? "--up " + format_point(u) + " is parallel to " + view
                                     : view + " (from " + std::string(o.position ? "--camera-position" : "the scene's position") +
                                           " to " + (o.look_at ? "--look-at" : "the scene's target") +
                                           ") is parallel to the scene's up " + format_point(u) + "; give --up";
        throw InputError(source + ": " + why + " (the camera's roll is undefined)");
    }
}

}  // namespace orb::cli
