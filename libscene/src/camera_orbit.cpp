#include "orb/scene/camera_orbit.h"

#include <cmath>
#include <numbers>

namespace orb {
namespace {

// sin and cos of an angle in degrees, exact at whole quarter turns (where
// sin(pi/2) in radians would leave cos at 6e-17 and move the camera off its
// axis by that much).
void sin_cos_degrees(double degrees, double& sine, double& cosine) {
    double turn = std::fmod(degrees, 360.0);
    if (turn < 0) turn += 360.0;
    const int quadrant = static_cast<int>(turn / 90.0) % 4;
    const double rest = (turn - 90.0 * quadrant) * std::numbers::pi / 180.0;
    const double s = rest == 0 ? 0.0 : std::sin(rest), c = rest == 0 ? 1.0 : std::cos(rest);
    switch (quadrant) {
        case 0: sine = s, cosine = c; break;
        case 1: sine = c, cosine = -s; break;
        case 2: sine = -s, cosine = -c; break;
        default: sine = -c, cosine = s; break;
    }
}

}  // namespace

Camera orbit_camera(const Camera& camera, double degrees) {
    const Vec3& u = camera.up;
    const double length = std::hypot(u[0], u[1], u[2]);
    const Vec3 k{u[0] / length, u[1] / length, u[2] / length};
    const Vec3 v = vec3::sub(camera.position, camera.target);
    double sine = 0, cosine = 1;
    sin_cos_degrees(degrees, sine, cosine);
    // Rodrigues' rotation formula: v cos + (k x v) sin + k (k . v)(1 - cos).
    const Vec3 k_cross_v = vec3::cross(k, v);
    const double k_dot_v = vec3::dot(k, v);
    Camera turned = camera;
    for (int c = 0; c < 3; ++c)
        turned.position[c] =
            camera.target[c] + v[c] * cosine + k_cross_v[c] * sine + k[c] * k_dot_v * (1.0 - cosine);
    return turned;
}

double orbit_angle_deg(double degrees, long frame, long first, long last) {
    return degrees * static_cast<double>(frame - first) / static_cast<double>(last - first + 1);
}

}  // namespace orb
