# Run at build time (cmake -P) by the orb_revision target: writes OUTPUT, a
# C++ file defining orb::cli::build::kRevision from the git checkout at
# SOURCE_DIR. The file is rewritten only when the text changes, so an
# unchanged revision rebuilds nothing.
#   SOURCE_DIR  the source tree
#   OUTPUT      the C++ file to write
#   FALLBACK    the revision to name when SOURCE_DIR is not a git checkout
#               (-DORB_REVISION=..., e.g. a distribution's own); may be empty
set(revision "")
find_program(git_program git)
if(git_program)
  # Only a checkout whose top is the source tree itself: a tarball unpacked
  # inside some other repository must not report that repository's commit.
  execute_process(COMMAND ${git_program} -C ${SOURCE_DIR} rev-parse --show-toplevel
    RESULT_VARIABLE status OUTPUT_VARIABLE top OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(status EQUAL 0)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
    if(top STREQUAL source)
      execute_process(COMMAND ${git_program} -C ${SOURCE_DIR} describe --always --dirty --abbrev=12
        RESULT_VARIABLE status OUTPUT_VARIABLE described OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
      if(status EQUAL 0 AND described)
        set(revision "git ${described}")
      endif()
    endif()
  endif()
endif()
if(NOT revision)
  if(FALLBACK)
    set(revision "${FALLBACK}")
  else()
    set(revision "unknown (the source tree is not a git checkout, or git could not read it)")
  endif()
endif()
string(REPLACE "\\" "\\\\" revision "${revision}")
string(REPLACE "\"" "\\\"" revision "${revision}")
set(text "// Generated at build time by tools/common/cmake/write_revision.cmake; do not edit.
#include \"build_revision.h\"

namespace orb::cli::build {

const char* const kRevision = \"${revision}\";

}  // namespace orb::cli::build
")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
