// Calls the kernels' BSDF interface (kernels/bsdf.cl) directly on the
// default OpenCL device (PoCL here), for the BSDF tests: the whole Orb
// program plus two small probe kernels, one that samples and one that
// evaluates. The shading frame is fixed: the origin, n = +z, wo in the xz
// plane. Both go through the continuation's mixture (caustic_casters.cl):
// with casters, directions also aim at their cones and densities are the
// mixture's; with none, they are the BSDF's own.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "orb/tables/device_types.h"

namespace orb::render::test {

using Dir = std::array<double, 3>;

struct ProbeSample {
    Dir wi;
    std::array<double, 3> weight;
    double pdf = 0;          // as the sampling returned it
    bool valid = false;      // a direction was returned: with a density (pdf > 0), or a delta lobe's with a non-zero weight
    bool delta = false;
    std::array<double, 3> eval_f_cos;  // bsdf_eval at (wo, wi)
    double eval_pdf = 0;               // the density of wi (the mixture's, with casters)
};

struct ProbeEval {
    std::array<double, 3> f_cos;  // f(wo, wi) |cos(wi, n)|
    double pdf = 0;
};

class BsdfProbe {
public:
    BsdfProbe();
    ~BsdfProbe();
    BsdfProbe(const BsdfProbe&) = delete;
    BsdfProbe& operator=(const BsdfProbe&) = delete;

    // `count` samples of bsdf_sample from wo (n = +z; `outside`: wo lies
    // outside the sphere), with the random numbers of RNG blocks 0..count-1
    // under `seed`.
    std::vector<ProbeSample> sample(const device::MaterialRecord& material, const Dir& wo, bool outside,
                                    std::size_t count, unsigned seed,
                                    const std::vector<device::CasterRecord>& casters = {});
    // bsdf_eval for each pair (wo[k], wi[k]); every wo[k].z > 0 (n = +z).
    std::vector<ProbeEval> eval(const device::MaterialRecord& material, bool outside, const std::vector<Dir>& wo,
                                const std::vector<Dir>& wi, const std::vector<device::CasterRecord>& casters = {});
    // The same with one wo for all.
    std::vector<ProbeEval> eval(const device::MaterialRecord& material, bool outside, const Dir& wo,
                                const std::vector<Dir>& wi, const std::vector<device::CasterRecord>& casters = {});

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// A MaterialRecord as librender would upload it.
device::MaterialRecord material_record(device::MaterialKind kind, std::array<float, 3> color, float roughness = 0,
                                       float metallic = 0, float ior = 1.5f);

// wo at cos(theta) = cos_theta from n = +z, in the xz plane.
Dir direction_at(double cos_theta);

}  // namespace orb::render::test
