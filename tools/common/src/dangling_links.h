// Where a symbolic link that points at nothing (yet) would put a new file.
#pragma once

#include <string>

namespace orb::cli::detail {

// Follows a chain of symbolic links from `path` to the first name that is
// not a link (and does not exist); returns `path` itself when it is no link.
// Throws orb::InputError for a chain longer than 40 links.
std::string follow_dangling_links(const std::string& path);

}  // namespace orb::cli::detail
