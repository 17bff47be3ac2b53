// Finding and loading Intel Open Image Denoise (libOpenImageDenoise.so.2) at
// run time. Orb does not link OIDN: the tools build and run without it, and
// only denoising needs it (docs/design/denoising-with-oidn.md). Where it is
// looked for, in order:
//   1. $ORB_OIDN_LIBRARY, a path to the library; when set, nothing else is tried;
//   2. the place scripts/install-deps.sh installs it:
//      ORB_OIDN_PREFIX/pyoidn/oidn/lib/libOpenImageDenoise.so.2
//      (ORB_OIDN_PREFIX is a CMake setting, /usr/local/lib/orb/oidn by default);
//   3. the dynamic loader's own search (LD_LIBRARY_PATH, ld.so.cache, ...).
#pragma once

#include <string>
#include <vector>

#include "orb/scene/error.h"

namespace orb::denoise {

namespace oidn {
struct Api;
}

// The environment variable that names the library.
inline constexpr const char* kLibraryVariable = "ORB_OIDN_LIBRARY";
// The library's file name (OIDN 2's soname).
inline constexpr const char* kLibraryName = "libOpenImageDenoise.so.2";

// OIDN could not be loaded: the message says where it was looked for, why
// each failed and how to install it. An InputError, so tools exit with 1.
struct DenoiserUnavailable : InputError {
    using InputError::InputError;
};

// The places tried, in order, for messages and documentation: each a path,
// or the bare file name for the loader's own search.
std::vector<std::string> library_candidates();

// Where scripts/install-deps.sh puts OIDN (the known location above).
std::string installed_library_path();

// Loads the library on the first call (once per process, never unloaded) and
// returns its entry points; throws DenoiserUnavailable, every later call too.
const oidn::Api& load_oidn();

// The path of the library that load_oidn() loaded (as found by dlopen).
const std::string& loaded_library_path();

}  // namespace orb::denoise
