// orb:kernel's value (orb/render/kernel_identity.h): the same kernels and
// options give the same identity; an edited kernel file or ORB_CL_OPTIONS
// give another. Needs no device.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "orb/render/kernel_identity.h"

namespace fs = std::filesystem;
using orb::render::DevelopmentKnobs;
using orb::render::kernel_identity;

namespace {

// A copy of the build's share/orb/kernels (laid out as an installed tree's) in a fresh folder.
fs::path copied_kernels(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("orb-kernel-identity-" + std::to_string(::getpid())) / name;
    fs::remove_all(dir);
    fs::create_directories(dir.parent_path());
    fs::copy(ORB_KERNELS_DIR, dir, fs::copy_options::recursive);
    return dir;
}

}  // namespace

TEST(KernelIdentity, IsTheSameForTheSameKernelsAndOptions) {
    const std::string embedded = kernel_identity({});
    EXPECT_EQ(embedded.size(), 16u);
    EXPECT_EQ(embedded.find_first_not_of("0123456789abcdef"), std::string::npos) << embedded;
    EXPECT_EQ(kernel_identity({}), embedded);
    // The installed copy of the kernels is the embedded text: the same identity.
    DevelopmentKnobs installed;
    installed.kernel_dir = copied_kernels("same").string();
    EXPECT_EQ(kernel_identity(installed), embedded);
    // Knobs that change no kernel text or option leave it.
    DevelopmentKnobs tuning;
    tuning.pass_spp = 3;
    tuning.local_size = orb::render::LocalSize{4, 4};
    EXPECT_EQ(kernel_identity(tuning), embedded);
    fs::remove_all(fs::path(installed.kernel_dir).parent_path());
}

TEST(KernelIdentity, AnEditedKernelOrOtherOptionsAreOtherKernels) {
    const std::string embedded = kernel_identity({});
    DevelopmentKnobs options;
    options.cl_options = "-DORB_SCALAR_TRAVERSAL=1";
    EXPECT_NE(kernel_identity(options), embedded);

    DevelopmentKnobs edited;
    edited.kernel_dir = copied_kernels("edited").string();
    std::ofstream(fs::path(edited.kernel_dir) / "integrator.cl", std::ios::app) << "\n// an edit\n";
    EXPECT_NE(kernel_identity(edited), embedded);
    // The decision program counts too.
    DevelopmentKnobs decision;
    decision.kernel_dir = copied_kernels("decision").string();
    std::ofstream(fs::path(decision.kernel_dir) / "adaptive.cl", std::ios::app) << "\n// an edit\n";
    EXPECT_NE(kernel_identity(decision), embedded);
    EXPECT_NE(kernel_identity(decision), kernel_identity(edited));
    fs::remove_all(fs::path(edited.kernel_dir).parent_path());
}

TEST(KernelIdentity, AMissingKernelFileIsAnError) {
    DevelopmentKnobs missing;
    missing.kernel_dir = copied_kernels("missing").string();
    fs::remove(fs::path(missing.kernel_dir) / "integrator.cl");
    EXPECT_THROW(kernel_identity(missing), std::runtime_error);
    fs::remove_all(fs::path(missing.kernel_dir).parent_path());
}
