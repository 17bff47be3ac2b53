// The samplers of kernels/sampler.cl, run on the default device (PoCL here)
// through a probe kernel: the Sobol sampler's stratification is exact (every
// elementary interval of 2^k aligned samples holds one point), its numbers
// are uniform and independent across pairs, blocks and pixels (Pearson χ²),
// and both samplers are pure functions of (pixel, sample, block, seed).
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "orb/kernels/embedded.h"
#include "orb/tables/kernel_features.h"
#include "orb/render/device.h"
#include "opencl_devices.h"

namespace orb::render::test {
namespace {

constexpr int kNumbersPerBlock = 5;

// Five numbers per (pixel, sample) for `samples` samples from `first`, of
// `pixels` pixels from `first_pixel`, block `block`: out[(p * samples + s) * 5 + k].
class SamplerProbe {
public:
    explicit SamplerProbe(bool sobol)
    {
        const DeviceInfo info = choose_device("");
        device_ = opencl_device(info.index);
        context_ = cl::Context(device_);
        queue_ = cl::CommandQueue(context_, device_);
        std::string source = device::kernel_feature_defaults();
        for (const char* file : {"include/orb/tables/film_channels.h", "include/orb/tables/material_kinds.h",
                                 "include/orb/tables/device_types.h", "lanes.cl", "rng.cl", "sampler.cl"})
            source += std::string(kernels::find_embedded_kernel(file)) + "\n";
        source += R"(
__kernel void probe(__global float* out, uint first_pixel, uint first_lo, uint first_hi, int samples, uint block,
                    uint seed_lo, uint seed_hi)
{
    const uint p = get_global_id(0);
    const ulong first = ((ulong)first_hi << 32) | first_lo;
    for (int s = 0; s < samples; ++s) {
        const Rand5 r = rng_block(first_pixel + p, first + (ulong)s, block, (uint2)(seed_lo, seed_hi));
        __global float* o = out + ((size_t)p * samples + s) * 5;
        o[0] = r.u0; o[1] = r.u1; o[2] = r.u2; o[3] = r.u3; o[4] = r.u4;
    }
}
)";
        program_ = cl::Program(context_, source);
        device::KernelFeatures features;
        features.sampler_sobol = sobol;
        const std::string options = "-cl-std=CL1.2 " + device::kernel_feature_options(features);
        try {
            program_.build({device_}, options.c_str());
        } catch (const cl::Error&) {
            ADD_FAILURE() << program_.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_);
            throw;
        }
    }

    std::vector<float> run(std::uint32_t first_pixel, std::uint32_t pixels, std::uint64_t first_sample, int samples,
                           std::uint32_t block, std::uint64_t seed)
    {
        std::vector<float> out(static_cast<std::size_t>(pixels) * samples * kNumbersPerBlock);
        cl::Buffer buffer(context_, CL_MEM_WRITE_ONLY, out.size() * sizeof(float));
        cl::Kernel kernel(program_, "probe");
        kernel.setArg(0, buffer);
        kernel.setArg(1, first_pixel);
        kernel.setArg(2, static_cast<cl_uint>(first_sample));
        kernel.setArg(3, static_cast<cl_uint>(first_sample >> 32));
        kernel.setArg(4, samples);
        kernel.setArg(5, block);
        kernel.setArg(6, static_cast<cl_uint>(seed));
        kernel.setArg(7, static_cast<cl_uint>(seed >> 32));
        queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(pixels));
        queue_.enqueueReadBuffer(buffer, CL_TRUE, 0, out.size() * sizeof(float), out.data());
        return out;
    }

private:
    cl::Device device_;
    cl::Context context_;
    cl::CommandQueue queue_;
    cl::Program program_;
};

float number(const std::vector<float>& out, int samples, int pixel, int sample, int k)
{
    return out[(static_cast<std::size_t>(pixel) * samples + sample) * kNumbersPerBlock + k];
}

// Every elementary interval [a/2^i, (a+1)/2^i) x [b/2^(k-i), (b+1)/2^(k-i))
// holds exactly one of 2^k points: the (0, k, 2)-net property.
void expect_net(const std::vector<float>& out, int samples, int pixel, int kx, int ky, int log2_samples,
                const std::string& what)
{
    for (int i = 0; i <= log2_samples; ++i) {
        const int nx = 1 << i, ny = 1 << (log2_samples - i);
        std::vector<int> cells(static_cast<std::size_t>(nx) * ny, 0);
        for (int s = 0; s < samples; ++s) {
            const int cx = static_cast<int>(number(out, samples, pixel, s, kx) * nx);
            const int cy = static_cast<int>(number(out, samples, pixel, s, ky) * ny);
            ++cells[static_cast<std::size_t>(cy) * nx + cx];
        }
        for (std::size_t c = 0; c < cells.size(); ++c)
            ASSERT_EQ(cells[c], 1) << what << ": " << nx << "x" << ny << " cell " << c;
    }
}

TEST(SobolSampler, EveryPairOfAlignedPowerOfTwoSamplesIsANet)
{
    SamplerProbe probe(true);
    for (const std::uint64_t first : {std::uint64_t{0}, std::uint64_t{1024}, std::uint64_t{5} << 32}) {
        for (const std::uint32_t block : {0u, 1u, 2u}) {
            constexpr int kLog2 = 8, kSamples = 1 << kLog2;
            const std::vector<float> out = probe.run(17, 3, first, kSamples, block, 0x1234567890abcdefull);
            for (int p = 0; p < 3; ++p) {
                const std::string where = "first " + std::to_string(first) + " block " + std::to_string(block) +
                                          " pixel " + std::to_string(p);
                expect_net(out, kSamples, p, 0, 1, kLog2, "(u0, u1) " + where);
                expect_net(out, kSamples, p, 2, 3, kLog2, "(u2, u3) " + where);
                // u4 alone: each interval of width 2^-8 holds one point.
                std::vector<int> cells(kSamples, 0);
                for (int s = 0; s < kSamples; ++s) ++cells[static_cast<int>(number(out, kSamples, p, s, 4) * kSamples)];
                for (int c = 0; c < kSamples; ++c) ASSERT_EQ(cells[c], 1) << "u4 " << where << " cell " << c;
            }
        }
    }
}

// Past the first blocks (ORB_SOBOL_BLOCKS) the Sobol sampler hands out the
// independent sampler's numbers.
TEST(SobolSampler, LaterBlocksAreTheIndependentSamplersNumbers)
{
    SamplerProbe sobol(true), independent(false);
    EXPECT_EQ(sobol.run(5, 16, 77, 8, 3, 11), independent.run(5, 16, 77, 8, 3, 11));
    EXPECT_EQ(sobol.run(5, 16, 77, 8, 9, 11), independent.run(5, 16, 77, 8, 9, 11));
    EXPECT_NE(sobol.run(5, 16, 77, 8, 2, 11), independent.run(5, 16, 77, 8, 2, 11));
}

// Pearson's χ² of `counts` against equal expected counts; the 1e-4 upper
// quantile of χ² with `cells - 1` degrees of freedom by the Wilson-Hilferty
// approximation (accurate to a few per cent at these sizes).
void expect_uniform(const std::vector<double>& counts, double total, const std::string& what)
{
    const double expected = total / static_cast<double>(counts.size());
    double chi2 = 0;
    for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
    const double dof = static_cast<double>(counts.size() - 1);
    const double z = 3.719;  // the standard normal's 1 - 1e-4 quantile
    const double h = 2.0 / (9.0 * dof);
    const double limit = dof * std::pow(1.0 - h + z * std::sqrt(h), 3.0);
    EXPECT_LT(chi2, limit) << what << ": chi2 " << chi2 << " over " << dof << " degrees of freedom";
}

// Within one pixel, two streams that should be independent do not take
// their samples in one shared order. Two Owen scrambles of one Sobol
// dimension taken in the same order have leading digits that are equal in
// every sample or opposite in every sample (the scrambles flip the digit
// of all samples alike), in every pixel; pooled histograms cannot see that,
// since the sign varies from pixel to pixel. Independently shuffled orders
// make that happen in about 1 pixel in 128 (the leading digits then agree
// on a random subset of the 8 pairs of sibling samples; all or none with
// probability 2 / 2^8), independent numbers in 2 / 2^16 of them. Allowing
// 5% tells the two apart with thousands of binomial standard deviations to
// spare, and a shared order fails in every pixel.
template <typename Stream>
void expect_no_shared_order(const std::vector<float>& a, const std::vector<float>& b, int pixels, int samples,
                            Stream x, Stream y, const std::string& what)
{
    int locked = 0;
    for (int p = 0; p < pixels; ++p) {
        int agree = 0;
        for (int s = 0; s < samples; ++s) agree += (x(a, b, p, s) < 0.5f) == (y(a, b, p, s) < 0.5f);
        locked += agree == 0 || agree == samples;
    }
    EXPECT_LT(locked, pixels / 20) << what << ": pixels whose leading digits agree in all samples or in none";
}

// Numbers that are not meant to be stratified together are independent:
// pairs of numbers from different pairs, blocks or pixels, binned 16 x 16
// over many pixels and samples, fill the unit square uniformly.
void expect_independent_pairs(bool sobol)
{
    SamplerProbe probe(sobol);
    constexpr int kPixels = 4096, kSamples = 16, kBins = 16;
    const std::vector<float> a = probe.run(0, kPixels, 3, kSamples, 1, 42);
    const std::vector<float> b = probe.run(0, kPixels, 3, kSamples, 2, 42);
    struct Pairing {
        std::string what;
        float (*x)(const std::vector<float>&, const std::vector<float>&, int, int);
        float (*y)(const std::vector<float>&, const std::vector<float>&, int, int);
    };
    const std::vector<Pairing> pairings = {
        {"u1 and u2 of one block", [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 1); },
         [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 2); }},
        {"u0 and u4 of one block", [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 0); },
         [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 4); }},
        {"u0 of blocks 1 and 2", [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 0); },
         [](auto&, auto& b, int p, int s) { return number(b, kSamples, p, s, 0); }},
        {"u1 of blocks 1 and 2", [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 1); },
         [](auto&, auto& b, int p, int s) { return number(b, kSamples, p, s, 1); }},
        {"u4 of blocks 1 and 2", [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 4); },
         [](auto&, auto& b, int p, int s) { return number(b, kSamples, p, s, 4); }},
        {"u2 of blocks 1 and 2", [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 2); },
         [](auto&, auto& b, int p, int s) { return number(b, kSamples, p, s, 2); }},
        {"u0 of neighbouring pixels",
         [](auto& a, auto&, int p, int s) { return number(a, kSamples, p, s, 0); },
         [](auto& a, auto&, int p, int s) { return number(a, kSamples, (p + 1) % kPixels, s, 0); }},
    };
    for (const Pairing& pairing : pairings) {
        std::vector<double> counts(kBins * kBins, 0.0);
        for (int p = 0; p < kPixels; ++p)
            for (int s = 0; s < kSamples; ++s) {
                const int bx = static_cast<int>(pairing.x(a, b, p, s) * kBins);
                const int by = static_cast<int>(pairing.y(a, b, p, s) * kBins);
                ASSERT_TRUE(bx >= 0 && bx < kBins && by >= 0 && by < kBins) << pairing.what;
                counts[static_cast<std::size_t>(by) * kBins + bx] += 1.0;
            }
        expect_uniform(counts, static_cast<double>(kPixels) * kSamples,
                       std::string(sobol ? "sobol " : "independent ") + pairing.what);
        expect_no_shared_order(a, b, kPixels, kSamples, pairing.x, pairing.y,
                               std::string(sobol ? "sobol " : "independent ") + pairing.what);
    }
}

TEST(SobolSampler, NumbersOfDifferentPairsBlocksAndPixelsAreIndependent) { expect_independent_pairs(true); }
TEST(IndependentSampler, NumbersOfDifferentPairsBlocksAndPixelsAreIndependent) { expect_independent_pairs(false); }

// A sample's numbers do not depend on which other samples a launch computes
// (the basis of exact pass splits, resume, slices and merging).
TEST(Samplers, ASampleIsAPureFunctionOfPixelIndexBlockAndSeed)
{
    for (const bool sobol : {true, false}) {
        SamplerProbe probe(sobol);
        const std::vector<float> whole = probe.run(100, 8, 1000, 32, 3, 7);
        for (int split = 1; split < 32; split += 13) {
            const std::vector<float> head = probe.run(100, 8, 1000, split, 3, 7);
            const std::vector<float> tail = probe.run(100, 8, 1000 + split, 32 - split, 3, 7);
            for (int p = 0; p < 8; ++p)
                for (int s = 0; s < 32; ++s)
                    for (int k = 0; k < kNumbersPerBlock; ++k) {
                        const float expected = number(whole, 32, p, s, k);
                        const float got = s < split ? number(head, split, p, s, k)
                                                    : number(tail, 32 - split, p, s - split, k);
                        ASSERT_EQ(got, expected) << (sobol ? "sobol" : "independent") << " pixel " << p
                                                 << " sample " << s << " number " << k;
                    }
        }
        // Different seeds give different numbers.
        const std::vector<float> other = probe.run(100, 8, 1000, 32, 3, 8);
        int equal = 0;
        for (std::size_t i = 0; i < other.size(); ++i) equal += other[i] == whole[i];
        EXPECT_LT(equal, 8) << (sobol ? "sobol" : "independent");
    }
}

// Every number lies in [0, 1).
TEST(Samplers, NumbersLieInTheUnitInterval)
{
    for (const bool sobol : {true, false}) {
        SamplerProbe probe(sobol);
        const std::vector<float> out = probe.run(0, 256, (std::uint64_t{1} << 32) - 64, 128, 0, 99);
        for (float u : out) ASSERT_TRUE(u >= 0.0f && u < 1.0f) << u;
    }
}

}  // namespace
}  // namespace orb::render::test
