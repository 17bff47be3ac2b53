# What the tools are built with, as --version says it: known when CMake
# configures, from the packages find_package() found (their versions) and,
# for OpenCL, whose CMake files say only the API level of the headers, from
# dpkg where the build machine has it. Writes OUTPUT, a header defining
# orb::cli::build::kBuiltWith: one indented line per component.
function(orb_write_built_with OUTPUT)
  set(lines "")
  macro(add_line name text)
    string(APPEND lines "  ${name} ${text}\n")
  endmacro()

  set(build_type "${CMAKE_BUILD_TYPE}")
  if(NOT build_type)
    set(build_type "no build type")
  endif()
  add_line("compiler    " "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}, ${build_type}")

  # A Debian package's version, or "" where dpkg or the package is missing.
  function(debian_version package out)
    set(version "")
    find_program(dpkg_query dpkg-query)
    if(dpkg_query)
      execute_process(COMMAND ${dpkg_query} -W -f=\${Version} ${package}
        RESULT_VARIABLE status OUTPUT_VARIABLE version ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      if(NOT status EQUAL 0)
        set(version "")
      endif()
    endif()
    set(${out} "${version}" PARENT_SCOPE)
  endfunction()

  set(opencl "headers for OpenCL ${OpenCL_VERSION_STRING} (Orb targets 1.2)")
  debian_version(opencl-c-headers headers_package)
  if(headers_package)
    string(APPEND opencl ", opencl-c-headers ${headers_package}")
  endif()
  debian_version(ocl-icd-libopencl1 loader_package)
  if(loader_package)
    string(APPEND opencl "; ICD loader ocl-icd ${loader_package}")
  else()
    string(APPEND opencl "; ICD loader ${OpenCL_LIBRARY} (version unknown at build time)")
  endif()
  add_line("OpenCL      " "${opencl}")
  add_line("OpenEXR     " "${OpenEXR_VERSION}")
  add_line("OpenImageIO " "${OpenImageIO_VERSION}")
  add_line("OpenColorIO " "${OpenColorIO_VERSION}")

  string(REPLACE "\"" "\\\"" lines "${lines}")
  string(REPLACE "\n" "\\n\"\n    \"" lines "${lines}")
  file(CONFIGURE OUTPUT "${OUTPUT}" CONTENT
"// Generated when CMake configures (tools/common/cmake/built_with.cmake); do not edit.
#pragma once

namespace orb::cli::build {

inline constexpr char kBuiltWith[] =
    \"${lines}\";

}  // namespace orb::cli::build
" @ONLY)
endfunction()
