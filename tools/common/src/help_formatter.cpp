#include "orb/cli/help_formatter.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

#include "orb/cli/help_wrapping.h"

namespace orb::cli {
namespace {

// A description with less room than this beside its option's names (a
// narrow terminal) goes on the lines below them, indented kNarrowIndent.
constexpr std::size_t kNarrowestDescription = 20;
constexpr std::size_t kNarrowIndent = 6;

// CLI11's own type names and its built-in checks' adjectives ("NOT" prefixes
// a negated check): a validator description that is one of these says nothing
// a placeholder could use.
bool is_parser_type_name(std::string_view word) {
    for (std::string_view type :
         {"INT", "UINT", "FLOAT", "TEXT", "BOOLEAN", "CHAR", "ENUM", "NUMBER", "NOT", "POSITIVE", "NONNEGATIVE"})
        if (word == type) return true;
    return false;
}

// A word that already reads as a placeholder: capitals, perhaps joined by ':'
// or ',' ("START:COUNT", "X,Y,Z"), as a validator's name may give it.
bool reads_as_placeholder(std::string_view text) {
    if (text.empty() || is_parser_type_name(text)) return false;
    bool word_start = true;
    for (char c : text) {
        if (std::isupper(static_cast<unsigned char>(c)) || (!word_start && c == '_')) {
            word_start = false;
        } else if ((c == ':' || c == ',') && !word_start) {
            word_start = true;
        } else {
            return false;
        }
    }
    return !word_start;
}

// CLI::IsMember describes itself as "{a,b,c}"; a short set reads best as the
// choices themselves ("global|direct"), a long one is left to the description.
std::string choices_placeholder(std::string_view validators) {
    const size_t open = validators.find('{');
    const size_t close = validators.find('}', open);
    if (open == std::string_view::npos || close == std::string_view::npos) return {};
    std::string choices(validators.substr(open + 1, close - open - 1));
    if (choices.empty() || choices.size() > 32 || choices.find_first_of("{}[] ") != std::string::npos) return {};
    std::replace(choices.begin(), choices.end(), ',', '|');
    return choices;
}

bool ends_with(std::string_view text, std::string_view end) {
    return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

// A text value named after its option, as GNU tools do ("--view VIEW"); the
// names that hold paths read FILE or DIR.
std::string name_placeholder(const CLI::Option& option) {
    std::string name = !option.get_lnames().empty()   ? option.get_lnames().front()
                       : !option.get_snames().empty() ? option.get_snames().front()
                                                      : option.get_name(true, false);
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (name == "o" || name == "output" || name == "input" || name == "i") return "FILE";
    for (std::string_view end : {"json", "image", "config", "file", "log", "path", "exr", "png"})
        if (ends_with(name, end)) return "FILE";
    for (std::string_view end : {"dir", "directory", "folder"})
        if (ends_with(name, end)) return "DIR";
    std::string word;
    for (char c : name) word += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return word;
}

// One value of a given CLI11 type: N for whole numbers, X for real ones.
std::string type_placeholder(std::string_view type, const CLI::Option& option) {
    if (type == "INT" || type == "UINT") return "N";
    if (type == "FLOAT" || type == "NUMBER") return "X";
    if (type == "BOOLEAN") return "true|false";
    if (type == "CHAR") return "C";
    return name_placeholder(option);
}

std::string join(const std::vector<std::string>& words, char separator) {
    std::string out;
    for (size_t i = 0; i < words.size(); ++i) out += (i == 0 ? "" : std::string(1, separator)) + words[i];
    return out;
}

// Several values given together ("--camera X Y Z"): coordinates when they are
// two or three reals, else the one placeholder repeated.
std::string several(const std::string& one, int count, char separator) {
    static const char* const kAxes[] = {"X", "Y", "Z"};
    std::vector<std::string> words;
    for (int i = 0; i < count; ++i) words.push_back(one == "X" && count <= 3 ? kAxes[i] : one);
    return join(words, separator);
}

}  // namespace

std::string value_placeholder(const CLI::Option& option) {
    if (!option.get_option_text().empty()) {
        std::string text = option.get_option_text();
        text.erase(0, text.find_first_not_of(' '));
        return text;
    }
    if (option.get_items_expected_max() == 0) return {};  // a flag

    const std::string full = option.get_type_name();  // "UINT:UINT in [1 - 2147483647]", "TEXT:{a,b}"
    const size_t colon = full.find(':');
    const std::string type = full.substr(0, colon);
    const std::string validators = colon == std::string::npos ? std::string() : full.substr(colon + 1);

    std::string one;
    if (const size_t end = validators.find_first_of("<>( "); end != std::string::npos && end > 0 &&
        reads_as_placeholder(std::string_view(validators).substr(0, end)))
        one = validators.substr(0, end);  // "SECONDS>0", "PATH(existing)": the word; the rest is the description's
    else if (reads_as_placeholder(validators))
        one = validators;
    else if (std::string choices = choices_placeholder(validators); !choices.empty())
        one = choices;
    else if (type.size() > 2 && type.front() == '[' && type.back() == ']')
        one = type_placeholder(type.substr(1, type.find(',') - 1), option);  // a tuple: "[FLOAT,FLOAT,FLOAT]"
    else
        one = type_placeholder(type, option);

    const char separator = option.get_delimiter() != '\0' ? option.get_delimiter() : ' ';
    const int count = std::max(option.get_type_size_max(), 1) * std::max(option.get_expected_min(), 1);
    std::string text = count > 1 ? several(one, count, separator) : one;
    if (option.get_expected_max() >= CLI::detail::expected_max_vector_size) text += " ...";
    return text;
}

// The names column: room for "-o, --output FILE" and most options with their placeholders.
HelpFormatter::HelpFormatter(std::size_t width) : width_(width) { column_width(34); }

std::string HelpFormatter::make_option(const CLI::Option* option, bool is_positional) const {
    const std::string names = "  " + make_option_name(option, is_positional) + make_option_opts(option);
    const std::string description = make_option_desc(option);
    if (description.empty()) return names + "\n";
    const std::vector<std::string> paragraphs = CLI::detail::split(description, '\n');
    std::size_t longest_word = 0;
    for (const std::string& paragraph : paragraphs)
        for (const std::string& word : wrap_words(paragraph, 0)) longest_word = std::max(longest_word, word.size());
    // Beside the names while the column leaves room for the description and its longest word.
    const bool beside = width_ >= column_width_ + std::max(kNarrowestDescription, longest_word);
    const std::size_t column = beside ? column_width_ : kNarrowIndent;
    const std::string indent(column, ' ');
    std::vector<std::string> lines;
    for (const std::string& paragraph : paragraphs)
        for (std::string& line : wrap_words(paragraph, width_ > column ? width_ - column : 1))
            lines.push_back(std::move(line));
    std::string text = names;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        // Two spaces at least part the names from the description beside them, as readers of --help expect.
        if (i == 0 && names.size() + 2 <= column)
            text += std::string(column - names.size(), ' ');
        else
            text += "\n" + indent;
        text += lines[i];
    }
    return text + "\n";
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
    const std::string text = CLI::Formatter::make_description(app);
    return text.empty() ? text : wrap_help_text(text.substr(0, text.size() - 1), width_) + "\n";
}

std::string HelpFormatter::make_footer(const CLI::App* app) const {
    const std::string footer = app->get_footer();
    return footer.empty() ? footer : wrap_help_text(footer, width_) + "\n";
}

std::string HelpFormatter::make_option_name(const CLI::Option* option, bool is_positional) const {
    // Built from the names alone: CLI11's own form adds flag defaults ("{false}").
    if (is_positional) return option->get_name(true, false);
    std::vector<std::string> names;
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    if (names.empty()) names.push_back(option->get_name(true, false));
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : ", ") + names[i];
    return out;
}

std::string HelpFormatter::make_option_opts(const CLI::Option* option) const {
    if (!option->nonpositional()) return {};  // a positional: its name is the placeholder
    const std::string placeholder = value_placeholder(*option);
    return placeholder.empty() ? std::string() : " " + placeholder;
}

std::string HelpFormatter::make_option_usage(const CLI::Option* option) const {
    std::string usage = option->get_name(true, false);
    if (option->get_expected_max() >= CLI::detail::expected_max_vector_size) usage += "...";
    return usage;
}

}  // namespace orb::cli
