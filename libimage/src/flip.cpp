#include "orb/image/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "orb/scene/error.h"
#include "srgb.h"

namespace orb::image {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Plane = std::vector<float>;
using Planes = std::array<Plane, 3>;

// --- colour spaces (sRGB primaries, D65) -------------------------------------

// Linear sRGB -> XYZ and back.
constexpr float kRgbToXyz[3][3] = {{0.4123908f, 0.3575843f, 0.1804808f},
                                   {0.2126390f, 0.7151687f, 0.0721923f},
                                   {0.0193308f, 0.1191948f, 0.9505322f}};
constexpr float kXyzToRgb[3][3] = {{3.2409699f, -1.5373832f, -0.4986108f},
                                   {-0.9692436f, 1.8759675f, 0.0415551f},
                                   {0.0556301f, -0.2039770f, 1.0569715f}};
// The white the opponent and CIELAB spaces are normalised by: XYZ of RGB (1,1,1).
constexpr float kWhite[3] = {0.9504559f, 1.0f, 1.0890578f};

void mat3(const float m[3][3], const float in[3], float out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
}

// Linear RGB -> YCxCz, the linearised CIELAB the paper filters in.
void rgb_to_ycxcz(const float rgb[3], float out[3]) {
    float xyz[3];
    mat3(kRgbToXyz, rgb, xyz);
    const float x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
    out[0] = 116.0f * y - 16.0f;
    out[1] = 500.0f * (x - y);
    out[2] = 200.0f * (y - z);
}

void ycxcz_to_rgb(const float in[3], float rgb[3]) {
    const float y = (in[0] + 16.0f) / 116.0f;
    const float xyz[3] = {(in[1] / 500.0f + y) * kWhite[0], y * kWhite[1], (y - in[2] / 200.0f) * kWhite[2]};
    mat3(kXyzToRgb, xyz, rgb);
}

float lab_f(float t) {
    constexpr float delta = 6.0f / 29.0f;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

// Linear RGB -> CIELAB with the Hunt effect (chroma scaled by 0.01 L).
void rgb_to_hunt_lab(const float rgb[3], float out[3]) {
    float xyz[3];
    mat3(kRgbToXyz, rgb, xyz);
    const float fx = lab_f(xyz[0] / kWhite[0]), fy = lab_f(xyz[1] / kWhite[1]), fz = lab_f(xyz[2] / kWhite[2]);
    const float L = 116.0f * fy - 16.0f;
    out[0] = L;
    out[1] = 0.01f * L * 500.0f * (fx - fy);
    out[2] = 0.01f * L * 200.0f * (fy - fz);
}

float hyab(const float a[3], const float b[3]) {
    const float da = a[1] - b[1], db = a[2] - b[2];
    return std::fabs(a[0] - b[0]) + std::sqrt(da * da + db * db);
}

// --- separable convolution with clamp-to-edge addressing ----------------------

Plane convolve_separable(const Plane& in, int w, int h, const std::vector<float>& kx, const std::vector<float>& ky) {
    const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
    Plane tmp(in.size()), out(in.size());
    for (int y = 0; y < h; ++y) {
        const float* row = &in[static_cast<size_t>(y) * w];
        for (int x = 0; x < w; ++x) {
            float sum = 0;
            for (int k = -rx; k <= rx; ++k) sum += kx[k + rx] * row[std::clamp(x + k, 0, w - 1)];
            tmp[static_cast<size_t>(y) * w + x] = sum;
        }
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float sum = 0;
            for (int k = -ry; k <= ry; ++k) sum += ky[k + ry] * tmp[static_cast<size_t>(std::clamp(y + k, 0, h - 1)) * w + x];
            out[static_cast<size_t>(y) * w + x] = sum;
        }
    }
    return out;
}

// --- the contrast sensitivity filters of the colour pipeline -----------------

// Each opponent channel's CSF is, in the spatial domain,
//   s(r) = a1 sqrt(pi/b1) exp(-pi^2 r^2 / b1) + a2 sqrt(pi/b2) exp(-pi^2 r^2 / b2)
// with r in degrees, normalised to unit sum over the kernel's support.
struct CsfParameters {
    float a1, b1, a2, b2;
};
constexpr CsfParameters kCsf[3] = {
    {1.0f, 0.0047f, 0.0f, 1e-5f},     // achromatic
    {1.0f, 0.0053f, 0.0f, 1e-5f},     // red-green
    {34.1f, 0.04f, 13.5f, 0.025f},    // blue-yellow
};

int csf_radius(double ppd) {
    const double max_b = 0.04;  // the widest Gaussian over all channels
    return static_cast<int>(std::ceil(3.0 * std::sqrt(max_b / (2.0 * kPi * kPi)) * ppd));
}

std::vector<float> gaussian_1d(int radius, double ppd, double b) {
    std::vector<float> g(2 * radius + 1);
    for (int i = -radius; i <= radius; ++i) {
        const double d = i / ppd;
        g[i + radius] = static_cast<float>(std::exp(-kPi * kPi * d * d / b));
    }
    return g;
}

// A sum of two 2D Gaussians is two separable passes, weighted and normalised.
Plane csf_filter(const Plane& in, int w, int h, double ppd, const CsfParameters& p) {
    const int r = csf_radius(ppd);
    const auto g1 = gaussian_1d(r, ppd, p.b1);
    double s1 = 0;
    for (float v : g1) s1 += v;
    const double w1 = p.a1 * std::sqrt(kPi / p.b1);
    double total = w1 * s1 * s1;
    Plane out = convolve_separable(in, w, h, g1, g1);
    if (p.a2 == 0.0f) {
        const float scale = static_cast<float>(w1 / total);
        for (float& v : out) v *= scale;
        return out;
    }
    const auto g2 = gaussian_1d(r, ppd, p.b2);
    double s2 = 0;
    for (float v : g2) s2 += v;
    const double w2 = p.a2 * std::sqrt(kPi / p.b2);
    total += w2 * s2 * s2;
    const Plane second = convolve_separable(in, w, h, g2, g2);
    const float k1 = static_cast<float>(w1 / total), k2 = static_cast<float>(w2 / total);
    for (size_t i = 0; i < out.size(); ++i) out[i] = k1 * out[i] + k2 * second[i];
    return out;
}

// --- feature detection (edges and points) ------------------------------------

struct FeatureKernels {
    std::vector<float> smooth, first, second;  // Gaussian, its 1st and 2nd derivative
};

// Gaussian derivatives with sigma = w/2 degrees (w = 0.082 degrees, the
// peak-to-trough width of human edge detectors); positive and negative lobes
// normalised to sum to +1 and -1.
FeatureKernels feature_kernels(double ppd) {
    const double sd = 0.5 * 0.082 * ppd;
    const int r = static_cast<int>(std::ceil(3.0 * sd));
    FeatureKernels k;
    k.smooth.resize(2 * r + 1);
    k.first.resize(2 * r + 1);
    k.second.resize(2 * r + 1);
    double sum = 0, pos1 = 0, neg1 = 0, pos2 = 0, neg2 = 0;
    for (int i = -r; i <= r; ++i) {
        const double g = std::exp(-(i * i) / (2.0 * sd * sd));
        const double d1 = -i * g;
        const double d2 = (i * i / (sd * sd) - 1.0) * g;
        k.smooth[i + r] = static_cast<float>(g);
        k.first[i + r] = static_cast<float>(d1);
        k.second[i + r] = static_cast<float>(d2);
        sum += g;
        (d1 > 0 ? pos1 : neg1) += d1;
        (d2 > 0 ? pos2 : neg2) += d2;
    }
    for (int i = 0; i <= 2 * r; ++i) {
        k.smooth[i] = static_cast<float>(k.smooth[i] / sum);
        k.first[i] = static_cast<float>(k.first[i] > 0 ? k.first[i] / pos1 : k.first[i] / -neg1);
        k.second[i] = static_cast<float>(k.second[i] > 0 ? k.second[i] / pos2 : k.second[i] / -neg2);
    }
    return k;
}

struct Features {
    Plane edge, point;  // gradient magnitudes of the 1st and 2nd derivative filters
};

Features detect_features(const Plane& luminance, int w, int h, const FeatureKernels& k) {
    const Plane ex = convolve_separable(luminance, w, h, k.first, k.smooth);
    const Plane ey = convolve_separable(luminance, w, h, k.smooth, k.first);
    const Plane px = convolve_separable(luminance, w, h, k.second, k.smooth);
    const Plane py = convolve_separable(luminance, w, h, k.smooth, k.second);
    Features f;
    f.edge.resize(luminance.size());
    f.point.resize(luminance.size());
    for (size_t i = 0; i < luminance.size(); ++i) {
        f.edge[i] = std::sqrt(ex[i] * ex[i] + ey[i] * ey[i]);
        f.point[i] = std::sqrt(px[i] * px[i] + py[i] * py[i]);
    }
    return f;
}

// --- LDR-FLIP on linear RGB in [0,1] ------------------------------------------

struct OpponentImage {
    Planes ycxcz;
    Plane luminance;  // normalised achromatic channel, (Y + 16) / 116
};

OpponentImage to_opponent(const Planes& rgb) {
    const size_t n = rgb[0].size();
    OpponentImage o;
    for (auto& p : o.ycxcz) p.resize(n);
    o.luminance.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const float in[3] = {rgb[0][i], rgb[1][i], rgb[2][i]};
        float out[3];
        rgb_to_ycxcz(in, out);
        for (int c = 0; c < 3; ++c) o.ycxcz[c][i] = out[c];
        o.luminance[i] = (out[0] + 16.0f) / 116.0f;
    }
    return o;
}

// Perceived (CSF-filtered) colours as Hunt-adjusted CIELAB.
Planes filtered_lab(const OpponentImage& o, int w, int h, double ppd) {
    Planes filtered;
    for (int c = 0; c < 3; ++c) filtered[c] = csf_filter(o.ycxcz[c], w, h, ppd, kCsf[c]);
    Planes lab;
    for (auto& p : lab) p.resize(filtered[0].size());
    for (size_t i = 0; i < filtered[0].size(); ++i) {
        const float in[3] = {filtered[0][i], filtered[1][i], filtered[2][i]};
        float rgb[3];
        ycxcz_to_rgb(in, rgb);
        for (float& v : rgb) v = std::clamp(v, 0.0f, 1.0f);
        float out[3];
        rgb_to_hunt_lab(rgb, out);
        for (int c = 0; c < 3; ++c) lab[c][i] = out[c];
    }
    return lab;
}

// The largest colour difference FLIP expects: pure green vs pure blue.
float max_color_difference() {
    const float green[3] = {0, 1, 0}, blue[3] = {0, 0, 1};
    float lg[3], lb[3];
    rgb_to_hunt_lab(green, lg);
    rgb_to_hunt_lab(blue, lb);
    return std::pow(hyab(lg, lb), 0.7f);
}

Plane ldr_flip_linear(const Planes& reference, const Planes& test, int w, int h, double ppd) {
    constexpr float qc = 0.7f, pc = 0.4f, pt = 0.95f, qf = 0.5f;
    const OpponentImage ro = to_opponent(reference), to = to_opponent(test);
    const Planes rl = filtered_lab(ro, w, h, ppd), tl = filtered_lab(to, w, h, ppd);
    const FeatureKernels k = feature_kernels(ppd);
    const Features rf = detect_features(ro.luminance, w, h, k), tf = detect_features(to.luminance, w, h, k);
    const float cmax = max_color_difference();
    const float knee = pc * cmax;
    Plane error(reference[0].size());
    for (size_t i = 0; i < error.size(); ++i) {
        const float a[3] = {rl[0][i], rl[1][i], rl[2][i]}, b[3] = {tl[0][i], tl[1][i], tl[2][i]};
        const float d = std::pow(hyab(a, b), qc);
        // Compress large colour differences into the top of the [0,1] range.
        const float color = d < knee ? (pt / knee) * d : pt + (d - knee) / (cmax - knee) * (1.0f - pt);
        const float edge = std::fabs(rf.edge[i] - tf.edge[i]);
        const float point = std::fabs(rf.point[i] - tf.point[i]);
        const float feature = std::pow(std::max(edge, point) / std::sqrt(2.0f), qf);
        error[i] = std::pow(color, 1.0f - feature);
    }
    return error;
}

Planes to_planes(const Image& image, bool decode_srgb, float max_value) {
    if (image.channels() < 3) throw InputError("internal: FLIP needs three colour channels");
    Planes p;
    const size_t n = image.pixel_count();
    for (auto& plane : p) plane.resize(n);
    const int stride = image.channels();
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            float v = image.pixels[i * stride + c];
            if (std::isnan(v)) v = 0.0f;
            v = std::clamp(v, 0.0f, max_value);
            p[c][i] = decode_srgb ? srgb_to_linear(v) : v;
        }
    }
    return p;
}

void summarize(FlipResult& r) {
    double sum = 0, mx = 0;
    for (float v : r.error) {
        sum += v;
        mx = std::max(mx, static_cast<double>(v));
    }
    r.mean = r.error.empty() ? 0.0 : sum / static_cast<double>(r.error.size());
    r.max = mx;
}

void check_sizes(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw InputError("internal: FLIP needs images of the same size");
}

// The ACES filmic fit used by HDR-FLIP, as a rational function
// t(x) = (k0 x^2 + k1 x + k2) / (k3 x^2 + k4 x + k5) (Narkowicz's fit with
// its 0.6 pre-exposure folded into the coefficients).
constexpr double kTone[6] = {0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14};

float tone_map(float x) {
    const double v = x;
    const double t = (kTone[0] * v * v + kTone[1] * v + kTone[2]) / (kTone[3] * v * v + kTone[4] * v + kTone[5]);
    return static_cast<float>(std::clamp(t, 0.0, 1.0));
}

// The input value the tone mapper maps to `target`: the positive root of
// (k0 - target k3) x^2 + (k1 - target k4) x + (k2 - target k5) = 0.
double tone_map_inverse(double target) {
    const double a = kTone[0] - target * kTone[3];
    const double c0 = (kTone[1] - target * kTone[4]) / a;
    const double c1 = (kTone[2] - target * kTone[5]) / a;
    return -0.5 * c0 + std::sqrt(0.25 * c0 * c0 - c1);
}

}  // namespace

double default_flip_ppd() { return 0.7 * (3840.0 / 0.7) * (kPi / 180.0); }

FlipResult flip_ldr(const Image& reference, const Image& test, double ppd) {
    check_sizes(reference, test);
    FlipResult r;
    r.error = ldr_flip_linear(to_planes(reference, true, 1.0f), to_planes(test, true, 1.0f), reference.width,
                              reference.height, ppd);
    summarize(r);
    return r;
}

FlipResult flip_hdr(const Image& reference, const Image& test, double ppd) {
    check_sizes(reference, test);
    constexpr float kHalfMax = 65504.0f;  // keeps infinities finite
    const Planes ref = to_planes(reference, false, kHalfMax), tst = to_planes(test, false, kHalfMax);
    const int w = reference.width, h = reference.height;
    const size_t n = ref[0].size();

    // Exposure range: from the exposure that maps the reference's brightest
    // luminance to 0.85 after tone mapping, to the one that does so for its median.
    std::vector<float> luminance(n);
    for (size_t i = 0; i < n; ++i) luminance[i] = 0.2126f * ref[0][i] + 0.7152f * ref[1][i] + 0.0722f * ref[2][i];
    const float l_max = *std::max_element(luminance.begin(), luminance.end());
    std::nth_element(luminance.begin(), luminance.begin() + n / 2, luminance.end());
    float l_median = luminance[n / 2];
    if (l_median <= 0.0f) {
        // Mostly black reference: use its dimmest lit pixel instead.
        float dimmest = std::numeric_limits<float>::infinity();
        for (float l : luminance)
            if (l > 0.0f) dimmest = std::min(dimmest, l);
        l_median = std::isfinite(dimmest) ? dimmest : 1.0f;
    }
    const double x_target = tone_map_inverse(0.85);
    FlipResult r;
    r.hdr = true;
    r.start_exposure = l_max > 0.0f ? std::log2(x_target / l_max) : 0.0;
    r.stop_exposure = std::max(r.start_exposure, std::log2(x_target / l_median));
    r.exposures = std::max(2, static_cast<int>(std::ceil(r.stop_exposure - r.start_exposure)));
    const double step = (r.stop_exposure - r.start_exposure) / (r.exposures - 1);

    r.error.assign(n, 0.0f);
    Planes ref_ldr, tst_ldr;
    for (int c = 0; c < 3; ++c) {
        ref_ldr[c].resize(n);
        tst_ldr[c].resize(n);
    }
    for (int e = 0; e < r.exposures; ++e) {
        const float gain = static_cast<float>(std::exp2(r.start_exposure + e * step));
        for (int c = 0; c < 3; ++c)
            for (size_t i = 0; i < n; ++i) {
                ref_ldr[c][i] = tone_map(ref[c][i] * gain);
                tst_ldr[c][i] = tone_map(tst[c][i] * gain);
            }
        const Plane err = ldr_flip_linear(ref_ldr, tst_ldr, w, h, ppd);
        for (size_t i = 0; i < n; ++i) r.error[i] = std::max(r.error[i], err[i]);
    }
    summarize(r);
    return r;
}

}  // namespace orb::image
