// How the libraries' errors reach Python (docs/python.md, "Errors"): what
// ends a tool with exit status 1 (bad input, orb::InputError; no such
// device; a file that cannot be written) raises orb.Error, a RuntimeError;
// a bad option or argument (the tools' usage errors, exit status 2) raises
// ValueError; a missing file raises FileNotFoundError; pybind11's own
// (TypeError for a wrong type, KeyError) and MemoryError stay what they are.
// The message is the tools' own.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace orb::python {

// Adds orb.Error to `module` and translates the libraries' exceptions.
void register_errors(pybind11::module_& module);

// Raise ValueError / FileNotFoundError with `message` (thrown as C++ exceptions
// that pybind11 turns into the Python ones).
[[noreturn]] void throw_value_error(const std::string& message);
[[noreturn]] void throw_file_not_found(const std::string& message);

}  // namespace orb::python
