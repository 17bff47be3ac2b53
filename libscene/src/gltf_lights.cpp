// Photometric conversions for KHR_lights_punctual (docs/gltf.md, "Lights").
//
// Units: glTF gives point/spot intensity in candela (lm/sr) and directional
// illuminance in lux (lm/m^2). Orb's radiance is taken in the same
// photometric-style units without the 683 lm/W factor: 1 cd becomes a
// radiant intensity of 1 W/sr, so an emission of 1 in Orb corresponds to a
// glTF luminance of 1 cd/m^2 (nit).
#include <numbers>

#include "gltf_internal.h"

namespace orb::gltf {

// A sphere of radius r with uniform radiance L shows a disc of area pi r^2
// from every direction, so its intensity is I = L pi r^2 everywhere.
Vec3 point_light_radiance(const Vec3& intensity, double radius) {
    const double area = std::numbers::pi * radius * radius;
    return {intensity[0] / area, intensity[1] / area, intensity[2] / area};
}

// A sphere of radius r and radiance L seen at distance d subtends a cone of
// half-angle a with sin a = r/d; a surface facing it receives
// E = L pi sin^2 a (exact, as long as the cone is above the horizon).
Vec3 distant_light_radiance(const Vec3& illuminance, double radius, double distance) {
    const double sine = radius / distance;
    const double factor = std::numbers::pi * sine * sine;
    return {illuminance[0] / factor, illuminance[1] / factor, illuminance[2] / factor};
}

}  // namespace orb::gltf
