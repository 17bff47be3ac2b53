#include "orb/scene/scene.h"

#include <cmath>
#include <numbers>

namespace orb {

double smallptgpu_vfov_deg() { return 2.0 * std::atan(std::numbers::pi / 8.0) * 180.0 / std::numbers::pi; }

bool has_roughness(MaterialType type) { return type == MaterialType::Dielectric || type == MaterialType::Pbr; }

bool has_metallic(MaterialType type) { return type == MaterialType::Pbr; }

}  // namespace orb
