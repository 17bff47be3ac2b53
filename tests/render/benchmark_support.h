#pragma once
// What the development benchmarks in tests/render (orb-bvh-benchmark,
// orb-bvh-refit-benchmark, orb-trace-benchmark)
// share: reading a scene file of any format orb-import reads, and wall time.
#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "orb/scene/import.h"

namespace orb::bench {

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The canonical scene of the file at `path` (relative references resolve
// against the working directory, as the benchmarks always ran).
inline Scene import_scene_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return import_scene(bytes.str(), path, ".").scene;
}

}  // namespace orb::bench
