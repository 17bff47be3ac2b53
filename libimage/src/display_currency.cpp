#include "orb/image/display_currency.h"

#include <sys/stat.h>

#include <exception>
#include <string>
#include <vector>

#include "orb/image/display_record.h"
#include "orb/image/load.h"
#include "orb/image/record_carrier.h"
#include "orb/image/source_identity.h"

namespace orb::image {
namespace {

using Kind = DisplayImageVerdict::Kind;

bool is_regular_file(const std::string& path) {
    struct stat st {};
    return path != "-" && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string joined(const std::vector<std::string>& phrases) {
    std::string out;
    for (const std::string& phrase : phrases) out += (out.empty() ? "" : "; ") + phrase;
    return out;
}

// What the header says changed, e.g. "orb:spp 64, now 256; orb:sampleRanges 0:64, now 0:256"; empty when it
// says the same.
std::string render_changes(const SourceIdentity& made, const SourceIdentity& now) {
    std::vector<std::string> changes;
    for (const std::string& name : render_identity_attributes()) {
        auto value_in = [&name](const SourceIdentity& identity) -> std::string {
            for (const auto& [key, value] : identity.render)
                if (key == name) return value;
            return "(none)";
        };
        const std::string was = value_in(made), is = value_in(now);
        if (was != is) changes.push_back(name + " " + was + ", now " + is);
    }
    return joined(changes);
}

DisplayImageVerdict stale(std::string reason) { return {Kind::Stale, std::move(reason)}; }

}  // namespace

DisplayImageVerdict judge_display_image(const std::string& output, const std::string& source,
                                        const DisplaySettings& asked) {
    if (!is_regular_file(output)) return {Kind::Absent, {}};
    const SourceLookup now = identify_source(source);
    if (now.state == SourceLookup::State::NotAFile)
        return {Kind::CannotJudge, display_name(source) + " is not a file, so there is nothing to tell whether " +
                                       output + " was made from it"};
    if (record_attribute_for(asked.format).empty())
        return stale(asked.format + " images keep no record of what they were made from");

    std::string text;
    try {
        load_image(output);  // every pixel: a file damaged after it was written must not pass
        text = read_record_text(output);
    } catch (const std::exception& e) {
        return {Kind::Damaged, e.what()};
    }
    if (text.empty())
        return stale("it has no record of what it was made from (an older orb-tonemap or another program wrote it)");
    const auto record = parse_display_record(text);
    if (!record) return stale("its record of what it was made from does not read");
    if (record->version != kDisplayRecordVersion)
        return stale("an orb-tonemap that makes pixels differently made it (record version " +
                     std::to_string(record->version) + ", this one writes " + std::to_string(kDisplayRecordVersion) +
                     ")");
    if (const auto differences = settings_differences(record->settings, asked); !differences.empty())
        return stale(joined(differences));

    if (now.state == SourceLookup::State::Missing) return {Kind::Current, {}};
    if (!record->source_is_file)
        return stale("it was made from standard input or another stream, not from " + source);
    if (record->source != now.identity) {
        const std::string changes = render_changes(record->source, now.identity);
        if (!changes.empty()) return stale("its source " + source + " was rendered again (" + changes + ")");
        return stale("its source " + source + " changed since it was made");
    }
    return {Kind::Current, {}};
}

}  // namespace orb::image
