// The start of a text input, for recognising formats by their first bytes.
#pragma once

#include <string_view>

namespace orb::detail {

// `bytes` after a UTF-8 byte-order mark and leading white space (space, tab, CR, LF).
inline std::string_view skip_bom_and_space(std::string_view bytes) {
    if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
    while (!bytes.empty() && (bytes.front() == ' ' || bytes.front() == '\t' || bytes.front() == '\r' ||
                              bytes.front() == '\n'))
        bytes.remove_prefix(1);
    return bytes;
}

}  // namespace orb::detail
