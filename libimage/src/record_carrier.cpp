#include "orb/image/record_carrier.h"

#include <OpenImageIO/imageio.h>

#include <memory>

#include "orb/image/display_record.h"
#include "orb/scene/error.h"

namespace OIIO = OIIO_NAMESPACE;

namespace orb::image {
namespace {

constexpr const char* kOwnAttribute = "orb:tonemap";
constexpr const char* kDescription = "ImageDescription";

}  // namespace

std::string record_attribute_for(const std::string& format) {
    if (format == "png" || format == "exr") return kOwnAttribute;
    if (format == "tif" || format == "jpg") return kDescription;
    return {};
}

std::string read_record_text(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(path + ": not a readable image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    std::string text = spec.get_string_attribute(kOwnAttribute);
    // A description counts only when it is a record: for a file of any format,
    // whatever it was asked to be, since --format may have changed since.
    if (text.empty()) {
        const std::string description = spec.get_string_attribute(kDescription);
        if (description.rfind(kDisplayRecordMagic, 0) == 0) text = description;
    }
    in->close();
    return text;
}

}  // namespace orb::image
