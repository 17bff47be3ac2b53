// Private: the OCIO objects behind ColorConfig.
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include "orb/image/color_config.h"

namespace OCIO = OCIO_NAMESPACE;

namespace orb::image {

struct ColorConfig::Impl {
    OCIO::ConstConfigRcPtr config;
};

}  // namespace orb::image
