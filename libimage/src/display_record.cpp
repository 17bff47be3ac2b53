#include "orb/image/display_record.h"

#include <charconv>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "number_text.h"

namespace orb::image {
namespace {

constexpr const char* kSourcePrefix = "source.";  // followed by an orb-render header attribute's name

std::string escaped(const std::string& value) {
    std::string out;
    for (char c : value) {
        if (c == '\\')
            out += "\\\\";
        else if (c == '\n')
            out += "\\n";
        else
            out += c;
    }
    return out;
}

std::optional<std::string> unescaped(const std::string& value) {
    std::string out;
    for (size_t i = 0; i < value.size(); ++i) {
        if (value[i] != '\\') {
            out += value[i];
            continue;
        }
        if (++i == value.size()) return std::nullopt;
        if (value[i] == '\\')
            out += '\\';
        else if (value[i] == 'n')
            out += '\n';
        else
            return std::nullopt;
    }
    return out;
}

std::optional<long long> parse_integer(const std::string& text) {
    if (text.empty()) return std::nullopt;
    long long value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
    return value;
}

// Fields taken one by one; any missing or malformed one fails the whole record.
class Fields {
public:
    explicit Fields(std::map<std::string, std::string> values) : values_(std::move(values)) {}
    bool ok() const { return ok_; }
    std::string text(const std::string& key) {
        const auto it = values_.find(key);
        if (it == values_.end()) {
            ok_ = false;
            return {};
        }
        return it->second;
    }
    long long integer(const std::string& key) {
        const auto value = parse_integer(text(key));
        if (!value) ok_ = false;
        return value.value_or(0);
    }
    bool flag(const std::string& key) {
        const std::string value = text(key);
        if (value != "0" && value != "1") ok_ = false;
        return value == "1";
    }
    double number(const std::string& key) {
        const auto value = parse_double(text(key));
        if (!value) ok_ = false;
        return value.value_or(0.0);
    }
    bool has(const std::string& key) const { return values_.count(key) != 0; }

private:
    std::map<std::string, std::string> values_;
    bool ok_ = true;
};

}  // namespace

std::string format_display_record(const DisplayRecord& r) {
    std::ostringstream out;
    auto line = [&out](const std::string& key, const std::string& value) {
        out << key << '=' << escaped(value) << '\n';
    };
    out << kDisplayRecordMagic << ' ' << r.version << '\n';
    if (r.source_is_file) {
        line("source-size", std::to_string(r.source.size));
        line("source-mtime-ns", std::to_string(r.source.mtime_ns));
        for (const auto& [name, value] : r.source.render) line(kSourcePrefix + name, value);
    } else {
        line("source", "not a file");
    }
    const DisplaySettings& s = r.settings;
    line("contact-sheet", s.contact_sheet ? "1" : "0");
    line("pass", s.pass);
    line("input-space", s.input_space);
    line("display", s.display);
    line("view", s.view);
    line("look", s.look);
    line("exposure", shortest_text(s.exposure));
    line("auto-exposure", s.auto_exposure ? "1" : "0");
    line("alpha", s.alpha);
    line("config", s.config);
    line("format", s.format);
    line("bits", std::to_string(s.bits));
    line("dither", s.dither ? "1" : "0");
    return out.str();
}

std::optional<DisplayRecord> parse_display_record(const std::string& text) {
    std::istringstream in(text);
    std::string first;
    const std::string magic = std::string(kDisplayRecordMagic) + ' ';
    if (!std::getline(in, first) || first.rfind(magic, 0) != 0) return std::nullopt;
    const auto version = parse_integer(first.substr(magic.size()));
    if (!version) return std::nullopt;
    DisplayRecord r;
    r.version = static_cast<int>(*version);
    if (r.version != kDisplayRecordVersion) return r;

    std::map<std::string, std::string> values;
    std::vector<std::pair<std::string, std::string>> render;
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) continue;
        const auto equals = line.find('=');
        if (equals == std::string::npos) return std::nullopt;
        const std::string key = line.substr(0, equals);
        const auto value = unescaped(line.substr(equals + 1));
        if (!value) return std::nullopt;
        if (key.rfind(kSourcePrefix, 0) == 0)
            render.emplace_back(key.substr(std::string(kSourcePrefix).size()), *value);
        else
            values[key] = *value;
    }
    Fields f(std::move(values));
    r.source_is_file = !f.has("source");
    if (r.source_is_file) {
        const long long size = f.integer("source-size");
        if (size < 0) return std::nullopt;
        r.source.size = static_cast<std::uint64_t>(size);
        r.source.mtime_ns = f.integer("source-mtime-ns");
        r.source.render = std::move(render);
    }
    DisplaySettings& s = r.settings;
    s.contact_sheet = f.flag("contact-sheet");
    s.pass = f.text("pass");
    s.input_space = f.text("input-space");
    s.display = f.text("display");
    s.view = f.text("view");
    s.look = f.text("look");
    s.exposure = f.number("exposure");
    s.auto_exposure = f.flag("auto-exposure");
    s.alpha = f.text("alpha");
    s.config = f.text("config");
    s.format = f.text("format");
    s.bits = static_cast<int>(f.integer("bits"));
    s.dither = f.flag("dither");
    if (!f.ok()) return std::nullopt;
    return r;
}

}  // namespace orb::image
