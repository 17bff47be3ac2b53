#include "orb/scene/content_hash.h"

#include <cstdio>

namespace orb {

std::string ContentHash::hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
    return text;
}

std::string content_hash_hex(std::string_view bytes) {
    ContentHash hash;
    hash.add(bytes);
    return hash.hex();
}

}  // namespace orb
