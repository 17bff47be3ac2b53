# Fails when a library reaches, through its links, a library or package its
# layer must not use. LINKS: a file setting links_<library> for each of
# LIBRARIES (tests/layers/CMakeLists.txt writes it from the targets).
cmake_minimum_required(VERSION 3.25)
include(${LINKS})

# What each layer must not reach (README.md, "Layout").
set(opencl orb_kernels orb_render OpenCL::OpenCL)
set(image_formats orb_exr orb_image OpenEXR::OpenEXR OpenEXR::OpenEXRCore OpenImageIO::OpenImageIO
    OpenColorIO::OpenColorIO)
# The shared tables are the floor: header-only, reaching nothing.
set(forbidden_orb_tables orb_scene orb_import orb_film ${opencl} ${image_formats})
# The scene model reads no foreign format: its one parser is nlohmann_json.
set(forbidden_orb_scene orb_import orb_film TinyGLTF::TinyGLTF CLI11::CLI11 ${opencl} ${image_formats})
set(forbidden_orb_import orb_film ${opencl} ${image_formats})
set(forbidden_orb_film orb_scene orb_import ${opencl} ${image_formats})
set(forbidden_orb_kernels orb_scene orb_import orb_film orb_render ${image_formats})
# The renderer takes scenes made already: it reads no file format.
set(forbidden_orb_render orb_import ${image_formats})
set(forbidden_orb_exr ${opencl} orb_import orb_image OpenImageIO::OpenImageIO OpenColorIO::OpenColorIO)
set(forbidden_orb_image ${opencl} orb_exr)
# The denoiser reads and writes EXR through OpenEXR and loads OIDN at run time:
# no OpenCL, no OpenImageIO or OpenColorIO, and it links no OIDN.
set(forbidden_orb_denoise ${opencl} orb_import orb_image OpenImageIO::OpenImageIO OpenColorIO::OpenColorIO)
# The render job sits under every front end and reads no command line: none
# of the tools' own libraries (CLI11 reaches it only as libimport's private
# option groups); and no image formats but EXR (no libimage, OpenImageIO or
# OpenColorIO).
set(forbidden_orb_job orb_cli orb_request_cli orb_cli_development_knobs orb_image
    OpenImageIO::OpenImageIO OpenColorIO::OpenColorIO)

# Everything `library` reaches: its links and, for Orb's own libraries, theirs.
function(reach library out)
  set(seen "")
  set(todo ${library})
  while(todo)
    list(POP_FRONT todo current)
    foreach(link IN LISTS links_${current})
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
      if(NOT link IN_LIST seen)
        list(APPEND seen ${link})
        if(DEFINED links_${link})
          list(APPEND todo ${link})
        endif()
      endif()
    endforeach()
  endwhile()
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

set(failures "")
foreach(library IN LISTS LIBRARIES)
  reach(${library} reached)
  message(STATUS "${library} reaches: ${reached}")
  foreach(link IN LISTS reached)
    if(link IN_LIST forbidden_${library})
      string(APPEND failures "\n  ${library} reaches ${link}")
    endif()
  endforeach()
endforeach()
# Below librender no source includes the kernels' folder: what those layers
# share with the kernels is libtables/'s (orb/tables/). SOURCE_DIR and
# BELOW_RENDER (folders of the source tree) come from tests/layers/CMakeLists.txt.
foreach(folder IN LISTS BELOW_RENDER)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${folder}/*.h" "${SOURCE_DIR}/${folder}/*.cpp")
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" kernel_includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]orb/kernels/")
    if(kernel_includes)
      string(APPEND failures "\n  ${source} includes the kernels' folder: ${kernel_includes}")
    endif()
  endforeach()
endforeach()

if(failures)
  message(FATAL_ERROR "libraries reach what their layer must not:${failures}")
endif()
