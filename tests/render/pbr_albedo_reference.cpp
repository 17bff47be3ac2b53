#include "pbr_albedo_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace orb::render::test {
namespace {

constexpr double kSmoothAlpha = 1e-3;

double schlick(double f0, double cos_theta) { return f0 + (1.0 - f0) * std::pow(1.0 - cos_theta, 5.0); }

// Smith's Lambda for GGX at cos(theta) = c > 0.
double smith_lambda(double alpha, double c)
{
    const double s2 = std::max(0.0, 1.0 - c * c);
    return 0.5 * (std::sqrt(c * c + alpha * alpha * s2) / c - 1.0);
}

}  // namespace

// Calls visit(m, lambda_o) for n x n microfacet normals m spread as the visible
// normals of wo = (sin_o, 0, cos_o) (Heitz 2018), each standing for 1 / n^2.
template <typename Visit>
void for_visible_normals(double alpha, double cos_o, int n, Visit visit)
{
    const double sin_o = std::sqrt(std::max(0.0, 1.0 - cos_o * cos_o));
    const double wo[3] = {sin_o, 0.0, cos_o};  // in the frame of the normal (z)
    // The view direction in the stretched (alpha = 1) configuration and an orthonormal frame around it.
    double vh[3] = {alpha * wo[0], alpha * wo[1], wo[2]};
    const double vl = std::sqrt(vh[0] * vh[0] + vh[1] * vh[1] + vh[2] * vh[2]);
    for (double& x : vh) x /= vl;
    const double lensq = vh[0] * vh[0] + vh[1] * vh[1];
    double t1[3] = {1.0, 0.0, 0.0};
    if (lensq > 0) {
        const double inv = 1.0 / std::sqrt(lensq);
        t1[0] = -vh[1] * inv;
        t1[1] = vh[0] * inv;
        t1[2] = 0.0;
    }
    const double t2[3] = {vh[1] * t1[2] - vh[2] * t1[1], vh[2] * t1[0] - vh[0] * t1[2], vh[0] * t1[1] - vh[1] * t1[0]};
    for (int i = 0; i < n; ++i) {
        const double r = std::sqrt((i + 0.5) / n);
        for (int j = 0; j < n; ++j) {
            const double phi = 2.0 * std::numbers::pi * (j + 0.5) / n;
            const double p1 = r * std::cos(phi);
            double p2 = r * std::sin(phi);
            const double s = 0.5 * (1.0 + vh[2]);
            p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
            const double p3 = std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
            double m[3];
            for (int k = 0; k < 3; ++k) m[k] = p1 * t1[k] + p2 * t2[k] + p3 * vh[k];
            m[0] *= alpha;
            m[1] *= alpha;
            m[2] = std::max(0.0, m[2]);
            const double ml = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
            for (double& x : m) x /= ml;
            visit(wo, m);
        }
    }
}

double pbr_specular_albedo(double cos_o, double roughness, int n, double f0)
{
    const double alpha = roughness * roughness;
    cos_o = std::clamp(cos_o, 1e-6, 1.0);
    if (alpha < kSmoothAlpha) return schlick(f0, cos_o);
    const double lambda_o = smith_lambda(alpha, cos_o);
    double sum = 0.0;
    for_visible_normals(alpha, cos_o, n, [&](const double* wo, const double* m) {
        const double om = wo[0] * m[0] + wo[1] * m[1] + wo[2] * m[2];
        const double cos_i = 2.0 * om * m[2] - wo[2];
        if (cos_i <= 0.0) return;  // reflected below the surface: lost
        // Visible-normal sampling of a reflection: f cos / pdf = F G2 / G1(wo).
        const double g2_over_g1 = (1.0 + lambda_o) / (1.0 + lambda_o + smith_lambda(alpha, cos_i));
        sum += schlick(f0, std::max(0.0, om)) * g2_over_g1;
    });
    return sum / (double(n) * double(n));
}

double rough_dielectric_albedo(double cos_o, double roughness, double n_o, double n_i, int n)
{
    const double alpha = roughness * roughness;
    const double eta = n_o / n_i;
    const double lambda_o = smith_lambda(alpha, cos_o);
    double sum = 0.0;
    for_visible_normals(alpha, cos_o, n, [&](const double* wo, const double* m) {
        const double c = wo[0] * m[0] + wo[1] * m[1] + wo[2] * m[2];
        if (c <= 0.0) return;
        // Exact unpolarised Fresnel of the facet.
        const double sin2_t = eta * eta * std::max(0.0, 1.0 - c * c);
        double fresnel = 1.0, ct = 0.0;
        if (sin2_t < 1.0) {
            ct = std::sqrt(1.0 - sin2_t);
            const double rs = (eta * c - ct) / (eta * c + ct), rp = (c - eta * ct) / (c + eta * ct);
            fresnel = 0.5 * (rs * rs + rp * rp);
        }
        const double reflected_z = 2.0 * c * m[2] - wo[2];
        if (reflected_z > 0.0)
            sum += fresnel * (1.0 + lambda_o) / (1.0 + lambda_o + smith_lambda(alpha, reflected_z));
        if (fresnel < 1.0) {
            const double transmitted_z = -eta * wo[2] + (eta * c - ct) * m[2];
            if (transmitted_z < 0.0)
                sum += (1.0 - fresnel) * (1.0 + lambda_o) / (1.0 + lambda_o + smith_lambda(alpha, -transmitted_z));
        }
    });
    return sum / (double(n) * double(n));
}

}  // namespace orb::render::test
