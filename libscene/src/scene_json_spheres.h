// The "spheres" array of the JSON form, written directly rather than through
// JSON values: the same bytes format_json would make, at a fraction of the
// cost, since a million spheres are the normal case for point clouds and
// orb-render hashes the JSON of every scene it renders.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "orb/scene/scene.h"

namespace orb::detail {

// What a sphere's line of the array takes, at most in practice (90-140
// bytes): the writers reserve text by it.
inline constexpr std::size_t kSphereLineBytes = 140;

// Receives the JSON text in order, piece by piece.
using JsonSink = std::function<void(std::string_view)>;

// "[]", or "[\n    { ... },\n    { ... }\n  ]" at the top level's depth,
// handed to `sink` 16384 spheres at a time (the next piece formatted on a
// second thread meanwhile), so that ten million spheres are hashed without
// 1.4 GB of text in memory at once.
void write_spheres_json(const std::vector<Sphere>& spheres, const JsonSink& sink);

}  // namespace orb::detail
