// The --help text of every Orb tool, in the shape of GNU tools' and
// orb-farm's: each option's names, a value placeholder a reader understands
// (N, X, FILE, START:COUNT, global|direct, ...) and its description, without
// CLI11's parser details (type names, ranges, defaults, Needs:/Excludes:).
// It formats whatever options a tool registers, so an option added later
// needs nothing here; a tool that wants another placeholder gives it with
// ->option_text("WORD"). Every line is wrapped to a width (orb/cli/help_wrapping.h:
// the terminal's, else 80).
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

namespace orb::cli {

class HelpFormatter : public CLI::Formatter {
public:
    // `width`: the columns every line fits in (help_width(): the terminal's, else 80).
    explicit HelpFormatter(std::size_t width);

    std::string make_option(const CLI::Option* option, bool is_positional) const override;
    std::string make_description(const CLI::App* app) const override;
    std::string make_footer(const CLI::App* app) const override;
    std::string make_option_name(const CLI::Option* option, bool is_positional) const override;
    std::string make_option_opts(const CLI::Option* option) const override;
    std::string make_option_usage(const CLI::Option* option) const override;

private:
    std::size_t width_;
};

// The placeholder for an option's value ("" for a flag), as the help shows it.
std::string value_placeholder(const CLI::Option& option);

}  // namespace orb::cli
