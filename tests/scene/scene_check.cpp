// Loads one Orb scene file with the real loader: exit 0 if it is valid,
// 1 with the loader's message if not. Used by the schema agreement test.
#include <fstream>
#include <iostream>
#include <iterator>

#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

int main(int argc, char** argv) {
    if (argc != 2 && argc != 3) {
        std::cerr << "usage: scene_check FILE.json [REWRITTEN.json]\n";
        return 2;
    }
    std::ifstream in(argv[1], std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
        orb::Scene scene = orb::load_scene_json(text, argv[1]);
        // Whatever the loader accepts must also survive its own writer.
        const std::string rewritten = orb::write_scene_json(scene);
        if (argc == 3) std::ofstream(argv[2], std::ios::binary) << rewritten;
        if (orb::load_scene_json(rewritten, "rewritten") != scene) {
            std::cerr << argv[1] << ": does not round-trip\n";
            return 3;
        }
    } catch (const orb::InputError& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    return 0;
}
