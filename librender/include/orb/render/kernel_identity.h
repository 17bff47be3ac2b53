// Which kernels a render runs: a hash of the program text (the kernel
// sources, embedded or from ORB_KERNEL_DIR, with the feature defaults the
// host writes at their head, and adaptive sampling's decision program) and
// of the build options a user adds (ORB_CL_OPTIONS). Films carry it
// (orb:kernel), so that --resume, --skip-existing and orb-merge never
// combine the samples of different kernels.
//
// The options the renderer derives itself (the lane width of a device, the
// traversal, the code a scene needs: orb/tables/kernel_features.h) are left
// out: they give the same estimator by design (tests compare them), so the
// slices of one frame rendered on a GPU and on a CPU still merge.
#pragma once

#include <string>

#include "orb/render/development_knobs.h"

namespace orb::render {

// 16 hex digits (64-bit FNV-1a, orb/scene/content_hash.h). Throws
// std::runtime_error if a file of the kernel folder cannot be read.
std::string kernel_identity(const DevelopmentKnobs& knobs);

}  // namespace orb::render
