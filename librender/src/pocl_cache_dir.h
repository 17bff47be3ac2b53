// Where PoCL may keep its compiled kernels.
#pragma once

namespace orb::render {

// PoCL caches compiled kernels under $HOME/.cache/pocl, and when it cannot
// create that directory (an unwritable $HOME, as under `docker --user`) it
// offers no platform at all, so orb-render would report "no OpenCL platform
// found". Call before the first OpenCL call: unless POCL_CACHE_DIR is set,
// it points it at Orb's own cache directory plus "/pocl" when that can be
// created and written, else at a private temporary directory (mkdtemp under
// $TMPDIR or /tmp, mode 0700) that is removed when the process exits.
// Does its work once per process; other OpenCL drivers ignore the variable.
void prepare_pocl_cache_dir();

}  // namespace orb::render
