# CPack post-build script (CPACK_POST_BUILD_SCRIPTS): takes out of each .deb
# the postinst and postrm CPack writes to run ldconfig. CPack adds them
# whenever a shared object lies under /usr/lib, even in a private folder the
# dynamic linker never searches: Orb's run-time modules in /usr/lib/orb are
# opened by path (dlopen of bin/../lib/orb/NAME.so), so the ldconfig cache
# has nothing to learn from them, and lintian warns about the calls
# (maintscript-calls-ldconfig). A script that does anything else is kept,
# and the package rebuilt only when one was taken out.
foreach(package IN LISTS CPACK_PACKAGE_FILES)
  if(NOT package MATCHES "\\.deb$")
    continue()
  endif()
  set(tree ${package}.tree)
  file(REMOVE_RECURSE ${tree})
  execute_process(COMMAND dpkg-deb -R ${package} ${tree} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "dpkg-deb -R ${package} failed")
  endif()
  set(dropped FALSE)
  foreach(script postinst postrm)
    set(path ${tree}/DEBIAN/${script})
    if(NOT EXISTS ${path})
      continue()
    endif()
    file(STRINGS ${path} lines)
    # What CPack writes: a shebang, set -e, and ldconfig under an if on the action.
    set(other "")
    foreach(line IN LISTS lines)
      string(STRIP "${line}" line)
      if(NOT line STREQUAL "" AND NOT line MATCHES "^(#!/bin/sh|set -e|if \\[ \"\\$1\" = \"(configure|remove)\" \\]; then|ldconfig|fi)$")
        string(APPEND other "\n  ${line}")
      endif()
    endforeach()
    if(other STREQUAL "")
      file(REMOVE ${path})
      set(dropped TRUE)
    else()
      message(STATUS "Keeping ${script}: it does more than run ldconfig:${other}")
    endif()
  endforeach()
  if(dropped)
    execute_process(COMMAND dpkg-deb --root-owner-group -Zxz --build ${tree} ${package}
                    RESULT_VARIABLE status OUTPUT_QUIET)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "dpkg-deb --build ${package} failed")
    endif()
    message(STATUS "Took out the ldconfig maintainer scripts of ${package}")
  endif()
  file(REMOVE_RECURSE ${tree})
endforeach()
