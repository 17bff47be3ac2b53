// The glTF texture decoder, loaded at run time from
// <dir of executable>/../lib/orb/orb_texture_decoder.so (the build tree and
// an installation lay it out alike). It is OpenImageIO behind a module so
// that the tools themselves do not link OpenImageIO: a render node without
// it still renders every untextured scene (docs/design/texture-decoding.md).
#pragma once

#include <string>

#include "orb/import/image_decoder.h"

namespace orb::cli {

// A decoder that loads the module on its first call. If the module cannot be
// loaded, every call throws InputError naming the image, the module's path
// and why, which the importer reports as a texture it could not read.
ImageDecoder texture_decoder();

// The same with the module looked for in `module_folder` instead of beside
// the tools (the Python module carries its own, in orb/lib).
ImageDecoder texture_decoder_in(const std::string& module_folder);

}  // namespace orb::cli
