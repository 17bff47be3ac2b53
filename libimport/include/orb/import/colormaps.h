// Colour maps for colouring spheres by a property (orb/import/sphere_styling.h):
// tabulated display colours of published maps (their sources are cited in
// colormap_tables.cpp and docs/orb-import.md), interpolated linearly.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace orb {

enum class Colormap { Viridis, Magma, Plasma, Inferno, Cividis, Coolwarm, Greys };

// "viridis", ...: the names --colormap takes.
const char* colormap_name(Colormap map);
std::optional<Colormap> colormap_from_name(std::string_view name);
// "viridis, magma, plasma, inferno, cividis, coolwarm, greys", for messages and help.
std::string colormap_names();

// The map's display (sRGB-encoded) colour at t, t clamped to [0, 1] (NaN: 0),
// linearly interpolated between the table's entries.
std::array<float, 3> colormap_display_color(Colormap map, double t);

// Tableau 10, the qualitative palette for categories: entry index % 10 (display colours).
std::array<float, 3> qualitative_display_color(std::size_t index);

}  // namespace orb
