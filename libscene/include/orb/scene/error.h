// Bad input is reported by throwing InputError with a message that already
// names where the problem is: "file:line:column: what was expected" for text
// formats, "file: json.path: what was expected" for JSON.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace orb {

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "name:line:column: message"
[[noreturn]] void throw_at(const std::string& source, int line, int column, const std::string& message);

// `text` safe to print: valid UTF-8 and line breaks and tabs kept, every
// other control byte, DEL and every byte of an invalid UTF-8 sequence
// written as \xNN. For messages that quote what a parser saw in the input
// (a library's message about a file of random bytes would otherwise put
// those bytes on the terminal).
std::string printable(std::string_view text);

}  // namespace orb
