#include "orb/scene/error.h"

namespace orb {

void throw_at(const std::string& source, int line, int column, const std::string& message) {
    throw InputError(source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message);
}

}  // namespace orb
