// Times the steps between a scene file and a scene in memory, each the best
// of a few runs: reading the bytes, importing (any format, validated),
// writing the binary and JSON forms, and the content hash orb-render takes.
//   orb_scene_load_bench FILE...        (scripts/bench-scene-load.sh)
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "orb/import/import.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"

namespace {

double best_seconds(int runs, const std::function<void()>& step) {
    double best = 1e300;
    for (int i = 0; i < runs; ++i) {
        const auto start = std::chrono::steady_clock::now();
        step();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: orb_scene_load_bench FILE...\n");
        return 2;
    }
    for (int a = 1; a < argc; ++a) {
        const std::string path = argv[a];
        std::string bytes;
        const double read = best_seconds(3, [&] { bytes = read_file(path); });
        orb::Scene scene;
        std::string format;
        const double import = best_seconds(3, [&] {
            orb::ImportResult imported = orb::import_scene(bytes, path, ".");
            scene = std::move(imported.scene);
            format = imported.format;
        });
        const double validate = best_seconds(3, [&] { orb::validate_scene(scene, path); });
        std::string binary, json;
        const double write_binary = best_seconds(3, [&] { binary = orb::write_scene_binary(scene); });
        const double write_json = best_seconds(1, [&] { json = orb::write_scene_json(scene); });
        const double hash = best_seconds(1, [&] { (void)orb::scene_content_hash(scene); });
        std::printf("%s: %zu spheres, %zu materials, %.1f MB\n", path.c_str(), scene.spheres.size(),
                    scene.materials.size(), bytes.size() / 1e6);
        std::printf("  read file        %8.3f s\n  import+validate  %8.3f s  (%s)\n", read, import,
                    format.c_str());
        std::printf("  of which validate_scene %8.3f s\n", validate);
        std::printf("  write .orb       %8.3f s  (%.1f MB)\n  write JSON       %8.3f s  (%.1f MB)\n", write_binary,
                    binary.size() / 1e6, write_json, json.size() / 1e6);
        std::printf("  content hash     %8.3f s  (orb-render hashes every scene it renders)\n", hash);
    }
    return 0;
}
