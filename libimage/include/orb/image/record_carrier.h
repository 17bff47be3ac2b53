// Where a display image keeps its orb-tonemap record (display_record.h), by
// format. Each carrier is one OpenImageIO metadata attribute that was checked
// to come back byte for byte after a write and a read
// (tests/image/record_carrier_test.cpp):
//   png  "orb:tonemap"        a PNG text chunk
//   exr  "orb:tonemap"        an EXR header string attribute
//   tif  "ImageDescription"   the TIFF ImageDescription tag
//   jpg  "ImageDescription"   a JPEG comment (COM) marker
// TIFF and JPEG writers keep no attribute of their own choosing, so the
// record goes where each keeps a free text description. Other formats (BMP,
// Radiance HDR, PPM, TGA, ...) keep no record: their images are always made
// again under --skip-existing.
#pragma once

#include <string>

namespace orb::image {

// The attribute that carries the record in `format` ("png", "jpg", "tif",
// "exr", normalised as by checked_write_options); empty when the format keeps none.
std::string record_attribute_for(const std::string& format);

// The record text kept in the image file at `path`, read from its header
// only; empty when it has none (written by another program or by an
// orb-tonemap from before records). Throws orb::InputError when the file
// does not open as an image.
std::string read_record_text(const std::string& path);

}  // namespace orb::image
