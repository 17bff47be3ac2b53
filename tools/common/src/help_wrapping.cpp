#include "orb/cli/help_wrapping.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>

namespace orb::cli {
namespace {

constexpr std::size_t kDefaultWidth = 80;
// Continuation lines of an example (its comment, the rest of a long command)
// are indented this much past the example's own indentation.
constexpr std::size_t kExampleContinuation = 4;

std::string joined_lines(const std::vector<std::string>& lines, std::string_view indent) {
    std::string text;
    for (const std::string& line : lines) {
        if (!text.empty()) text += '\n';
        text += indent;
        text += line;
    }
    return text;
}

std::size_t leading_spaces(std::string_view line) {
    const std::size_t first = line.find_first_not_of(' ');
    return first == std::string_view::npos ? line.size() : first;
}

// A command too long for its line, continued as a shell reads it: each line
// but the last ends in " \", and the later ones are indented further.
std::string continued_command(std::string_view command, std::size_t indent, std::size_t width) {
    const std::string first_indent(indent, ' ');
    const std::string rest_indent(indent + kExampleContinuation, ' ');
    std::vector<std::string> words = wrap_words(command, 1);  // one word a line: regrouped below
    std::string text, line;
    for (const std::string& word : words) {
        const std::size_t line_indent = text.empty() ? first_indent.size() : rest_indent.size();
        // Room for the word and, since more may follow, the " \" that continues the line.
        if (!line.empty() && line_indent + line.size() + 1 + word.size() + 2 > width) {
            text += (text.empty() ? first_indent : "\n" + rest_indent) + line + " \\";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    text += (text.empty() ? first_indent : "\n" + rest_indent) + line;
    return text;
}

}  // namespace

std::size_t help_width() {
    winsize size{};
    if (::isatty(STDOUT_FILENO) && ::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
        return size.ws_col;
    return kDefaultWidth;
}

std::vector<std::string> wrap_words(std::string_view text, std::size_t width) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t start = text.find_first_not_of(' ', at);
        if (start == std::string_view::npos) break;
        const std::size_t end = std::min(text.find(' ', start), text.size());
        const std::string_view word = text.substr(start, end - start);
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            lines.push_back(std::move(line));
            line.clear();
        }
        if (!line.empty()) line += ' ';
        line += word;
        at = end;
    }
    if (!line.empty()) lines.push_back(std::move(line));
    return lines;
}

std::string wrap_help_line(std::string_view line, std::size_t width) {
    if (line.size() <= width) return std::string(line);
    const std::size_t indent = leading_spaces(line);
    if (indent == 0) return joined_lines(wrap_words(line, width), "");
    // An example: "COMMAND  COMMENT", the two parts apart by two spaces or more.
    const std::string_view body = line.substr(indent);
    const std::size_t gap = body.find("  ");
    const std::string_view command = body.substr(0, gap);
    const std::string_view comment =
        gap == std::string_view::npos ? std::string_view() : body.substr(body.find_first_not_of(' ', gap));
    std::string text = indent + command.size() <= width ? std::string(indent, ' ') + std::string(command)
                                                        : continued_command(command, indent, width);
    if (!comment.empty()) {
        const std::size_t comment_indent = indent + kExampleContinuation;
        const std::size_t room = width > comment_indent ? width - comment_indent : 1;
        text += '\n' + joined_lines(wrap_words(comment, room), std::string(comment_indent, ' '));
    }
    return text;
}

std::string wrap_help_text(std::string_view text, std::size_t width) {
    // Unindented lines that follow one another are one paragraph (their
    // breaks were made for some width), reflowed as a whole; a heading
    // ("Examples:"), a blank or an indented line ends it.
    std::string wrapped, paragraph;
    const auto end_paragraph = [&] {
        if (paragraph.empty()) return;
        wrapped += joined_lines(wrap_words(paragraph, width), "") + '\n';
        paragraph.clear();
    };
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        const std::string_view line = text.substr(at, end - at);
        const bool prose = !line.empty() && line.front() != ' ' && line.back() != ':';
        if (prose) {
            if (!paragraph.empty()) paragraph += ' ';
            paragraph += line;
        } else {
            end_paragraph();
            wrapped += wrap_help_line(line, width) + '\n';
        }
        if (end == text.size()) break;
        at = end + 1;
    }
    end_paragraph();
    wrapped.pop_back();  // the lines' last '\n': `text` did not end with one
    return wrapped;
}

}  // namespace orb::cli
