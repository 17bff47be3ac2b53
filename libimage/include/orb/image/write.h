// Writing display images through OpenImageIO, format chosen by name.
#pragma once

#include <string>

#include "orb/image/image.h"

namespace orb::image {

struct WriteOptions {
    std::string format;  // "png", "jpg", "tif", "exr", ... (OIIO format or extension)
    int bits = 0;        // 0: the format's default (8; EXR: 16-bit half)
    bool dither = true;  // dither when quantising to 8 bits
    // Colour with alpha comes straight (unassociated). true: premultiply it, for
    // formats that store associated alpha (EXR); false: write it straight and
    // say so in the file (PNG; TIFF's ExtraSamples "unassociated alpha").
    bool premultiply_alpha = false;
    // The display record (display_record.h) to keep in the image's metadata,
    // where the format has a carrier for it (record_carrier.h); "" for none.
    std::string record;
};

// Lower-case extension of a path without the dot ("" if none).
std::string extension_of(const std::string& path);

// Normalises a format name or extension ("jpeg" -> "jpg", "tiff" -> "tif");
// throws orb::InputError for formats OIIO cannot write or bit depths they cannot hold.
WriteOptions checked_write_options(WriteOptions options);

// The image encoded in `options.format`, in memory, so that the caller does
// the (checked) writing. Alpha is dropped for formats that cannot store it
// (JPEG, Radiance HDR, PPM, ...). Throws orb::InputError on failure.
std::string encode_image(const Image& image, const WriteOptions& options);

}  // namespace orb::image
