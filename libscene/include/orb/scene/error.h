// Bad input is reported by throwing InputError with a message that already
// names where the problem is: "file:line:column: what was expected" for text
// formats, "file: json.path: what was expected" for JSON.
#pragma once

#include <stdexcept>
#include <string>

namespace orb {

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "name:line:column: message"
[[noreturn]] void throw_at(const std::string& source, int line, int column, const std::string& message);

}  // namespace orb
