// Photometric conversions for KHR_lights_punctual (docs/gltf.md, "Lights").
//
// Units: glTF gives point/spot intensity in candela (lm/sr) and directional
// illuminance in lux (lm/m^2). With LightUnits::Photometric (the default)
// they become radiant quantities through 683 lm/W, the factor Blender's glTF
// importer and exporter use (PBR_WATTS_TO_LUMENS): a Blender point lamp of
// power P W has intensity P / 4pi W/sr, so its glTF intensity is
// P / 4pi * 683 cd, and a sun of S W/m^2 is S * 683 lux. Emissive
// materials are taken as radiance unchanged, as Blender imports them, so a
// scene keeps Blender's balance between lamps and glowing surfaces.
// LightUnits::Radiometric takes 1 cd as 1 W/sr and 1 lux as 1 W/m^2.
#include <numbers>

#include "gltf_internal.h"

namespace orb::gltf {

double watts_per_lumen(LightUnits units) { return units == LightUnits::Photometric ? 1.0 / kLumensPerWatt : 1.0; }

// A sphere of radius r with uniform radiance L shows a disc of area pi r^2
// from every direction, so its intensity is I = L pi r^2 everywhere (and its
// power 4 pi I = 4 pi^2 r^2 L, the power of a Blender point lamp of radius r).
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
