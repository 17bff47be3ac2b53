// Helpers shared by the .scn tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "orb/scene/error.h"
#include "orb/import/scn.h"

namespace orb::test {

// The message of the InputError that parsing `text` throws, or a failure if it does not throw.
inline std::string scn_error(std::string_view text, const std::string& source = "t.scn") {
    try {
        parse_scn(text, source);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected an InputError for:\n" << text;
    return {};
}

std::string read_file(const std::string& path);

}  // namespace orb::test
