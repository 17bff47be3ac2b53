// Python keyword arguments as the tools' command-line options: load(path,
// color_by="temperature", radius=0.01) is `--color-by temperature --radius
// 0.01`, parsed by the same CLI11 options the tools declare, so each option
// has one name, one check and one message wherever it is given.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace orb::python {

// A keyword's name with `_` (color_by) and its value as the command line
// writes it ("0,0.1,0"); no value: a flag given (cell=True).
using KeywordOption = std::pair<std::string, std::optional<std::string>>;
using KeywordOptions = std::vector<KeywordOption>;

// Parses `options` into `app`'s options. A name `app` lacks raises TypeError
// ("load() got an unexpected keyword argument 'colour_by'"), as Python does
// for a function's unknown keyword; a bad value raises ValueError with the
// tools' message (CLI::Error, errors.h).
void parse_keyword_options(CLI::App& app, const KeywordOptions& options, const std::string& function);

}  // namespace orb::python
