// Private: the option group of each importer (orb/import/importers.h
// ImportOptionGroup), each defined in the importer's *_options.cpp and named
// by its entries in importers.cpp.
#pragma once

#include "orb/import/importers.h"

namespace orb::detail {

extern const ImportOptionGroup kGltfOptions;       // gltf_options.cpp
extern const ImportOptionGroup kPlyOptions;        // ply_options.cpp
extern const ImportOptionGroup kMolecularOptions;  // molecular_options.cpp

}  // namespace orb::detail
