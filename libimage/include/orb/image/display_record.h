// The record orb-tonemap keeps inside each display image it writes: what the
// image was made from and with which settings, so that a later
// --skip-existing run can tell a current image from a stale one.
//
// Its text form is one "key=value" line per fact under a first line naming
// the record and its version, e.g.
//     orb-tonemap display image 1
//     source-size=1048576
//     source-mtime-ns=1718000000123456789
//     source.orb:spp=256
//     pass=beauty
//     ...
// so that `oiiotool --info -v` shows it readably. Backslashes and line breaks
// in values are escaped (\\ and \n).
#pragma once

#include <optional>
#include <string>

#include "orb/image/display_settings.h"
#include "orb/image/source_identity.h"

namespace orb::image {

// Bumped whenever orb-tonemap changes how it turns a source and settings into
// pixels, so that images made the old way count as stale. 2: images are
// opaque by default (the environment shown), with auto-exposure and alpha recorded.
inline constexpr int kDisplayRecordVersion = 2;

// The first line of every record, without the version number.
inline constexpr const char* kDisplayRecordMagic = "orb-tonemap display image";

struct DisplayRecord {
    int version = kDisplayRecordVersion;
    bool source_is_file = false;  // false: made from standard input or another stream
    SourceIdentity source;        // when source_is_file
    DisplaySettings settings;
};

std::string format_display_record(const DisplayRecord& record);

// The record in `text`; nullopt when it is not a record or lacks a field.
// A record of another version parses as far as its first line (version set,
// the rest left default) so that the caller can name the version.
std::optional<DisplayRecord> parse_display_record(const std::string& text);

}  // namespace orb::image
