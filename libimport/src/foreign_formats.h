// Formats Orb does not read, recognised so that such an input is refused as
// what it is ("tri.obj: unsupported format (Wavefront OBJ); ...") rather
// than with a parse error from the .scn reader, the fallback for text.
#pragma once

#include <string>
#include <string_view>

namespace orb::detail {

// The name of a format Orb cannot read that the bytes' magic number or first
// lines show ("Wavefront OBJ", "STL (binary)"); empty when none matches.
// Never matches Orb's own magic numbers nor JSON; the caller tells an .scn
// (text starting with "camera") apart first.
std::string foreign_format_by_content(std::string_view bytes);

// The name of a format Orb cannot read that `path`'s extension names (any
// case); empty for other extensions, none, and those of the importers
// (orb/import/importers.h), so an importer added for a format listed here
// takes its files. (By content, import_scene asks the importers first.)
std::string foreign_format_by_extension(const std::string& path);

}  // namespace orb::detail
