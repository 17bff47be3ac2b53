// The --help text of every Orb tool, in the shape of GNU tools' and
// orb-farm's: each option's names, a value placeholder a reader understands
// (N, X, FILE, START:COUNT, global|direct, ...) and its description, without
// CLI11's parser details (type names, ranges, defaults, Needs:/Excludes:).
// It formats whatever options a tool registers, so an option added later
// needs nothing here; a tool that wants another placeholder gives it with
// ->option_text("WORD").
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace orb::cli {

class HelpFormatter : public CLI::Formatter {
public:
    std::string make_option_name(const CLI::Option* option, bool is_positional) const override;
    std::string make_option_opts(const CLI::Option* option) const override;
    std::string make_option_usage(const CLI::Option* option) const override;
};

// The placeholder for an option's value ("" for a flag), as the help shows it.
std::string value_placeholder(const CLI::Option& option);

}  // namespace orb::cli
