// The glTF texture decoder, loaded at run time from
// <dir of executable>/../lib/orb/orb_texture_decoder.so (the build tree and
// an installation lay it out alike). It is OpenImageIO behind a module so
// that the tools themselves do not link OpenImageIO: a render node without
// it still renders every untextured scene (docs/design/texture-decoding.md).
#pragma once

#include "orb/import/image_decoder.h"

namespace orb::cli {

// A decoder that loads the module on its first call. If the module cannot be
// loaded, every call throws InputError naming the image, the module's path
// and why, which the importer reports as a texture it could not read.
ImageDecoder texture_decoder();

}  // namespace orb::cli
