#include <fstream>
#include <iterator>
#include <stdexcept>

#include "scn_test_util.h"

namespace orb::test {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open test file " + path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace orb::test
