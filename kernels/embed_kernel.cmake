# Turns one OpenCL C file into a C++ source defining a std::string_view with
# its text. Run at build time: cmake -DINPUT=x.cl -DOUTPUT=x.cpp -DSYMBOL=name -P embed_kernel.cmake
file(READ "${INPUT}" text)
set(delimiter "orb_cl")
string(FIND "${text}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )${delimiter}\"")
endif()
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by kernels/embed_kernel.cmake. Do not edit.\n"
  "#include <string_view>\n"
  "namespace orb::kernels::embedded_sources {\n"
  "extern const std::string_view ${SYMBOL};\n"
  "const std::string_view ${SYMBOL} = R\"${delimiter}(${text})${delimiter}\";\n"
  "}  // namespace orb::kernels::embedded_sources\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
