// Defined in the file tools/common/cmake/write_revision.cmake generates at
// every build (generated/build_revision.cpp), so a new commit shows in
// --version without configuring again.
#pragma once

namespace orb::cli::build {

extern const char* const kRevision;

}  // namespace orb::cli::build
