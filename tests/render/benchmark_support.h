#pragma once
// What the development benchmarks (orb-bvh-benchmark, orb-bvh-refit-benchmark,
// orb-render-benchmark, orb-film-transfer-benchmark here, orb-trace-benchmark
// in dev/) share: reading a scene file of any format orb-import reads, wall
// time, and the development knobs as orb-render reads them.
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "orb/cli/development_knobs.h"
#include "orb/import/import.h"

namespace orb::bench {

// The development knobs from the environment (ORB_SIMD_LANES and the rest,
// docs/rendering.md), as orb-render reads them; a malformed one ends the
// benchmark with its message and exit status 2. Links orb_cli_development_knobs.
inline render::DevelopmentKnobs development_knobs_or_exit(const char* benchmark)
{
    try {
        return cli::development_knobs_from_environment();
    } catch (const std::exception& error) {
        std::cerr << benchmark << ": error: " << error.what() << "\n";
        std::exit(2);
    }
}

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
