// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic, with Smith's
// height-correlated masking-shadowing (Heitz 2014, "Understanding the
// Masking-Shadowing Function") and sampling of the visible normals (Heitz 2018,
// "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)). Shared by the
// pbr material and rough glass; docs/rendering.md gives the equations.
//
// alpha is the GGX width, the square of the perceptual roughness (glTF's
// convention). Cosines are taken against the macro normal n.

// Below this alpha a surface is smooth: its lobe is a delta, handled by the
// materials' exact specular code (pbrt-v4's threshold). A GGX lobe this narrow
// would only add float trouble (D reaches 1 / (pi alpha^2) = 3e5).
#define GGX_SMOOTH_ALPHA 1e-3f

inline float ggx_alpha(float roughness) { return roughness * roughness; }

inline bool ggx_is_smooth(float alpha) { return alpha < GGX_SMOOTH_ALPHA; }

// D(m) for a unit microfacet normal m: alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2),
// with cos^2 (alpha^2 - 1) + 1 written as sin^2 + alpha^2 cos^2 and sin^2 taken
// from the cross product, which keeps its precision near the peak of a narrow lobe.
inline float ggx_d(float alpha, float3 m, float3 n)
{
    const float cos_m = dot(m, n);
    if (cos_m <= 0.0f) return 0.0f;
    const float3 c = cross(m, n);
    const float a2 = alpha * alpha;
    const float t = dot(c, c) + a2 * cos_m * cos_m;
    return a2 / (ORB_PI * t * t);
}

// Smith's Lambda for GGX at |cos(theta)| = c > 0:
// (sqrt(1 + alpha^2 tan^2) - 1) / 2 = (sqrt(c^2 + alpha^2 (1 - c^2)) / c - 1) / 2.
inline float ggx_lambda(float alpha, float c)
{
    const float c2 = c * c;
    return 0.5f * (sqrt(c2 + alpha * alpha * fmax(0.0f, 1.0f - c2)) / c - 1.0f);
}

// The visible-normal density of m seen from wo, divided by D(m) and by wo.m:
// D_wo(m) = G1(wo) max(0, wo.m) D(m) / cos_o (Heitz 2018, eq. 1). Returned
// factor: G1(wo) / cos_o, with G1 = 1 / (1 + Lambda).
inline float ggx_visible_factor(float lambda_o, float cos_o) { return 1.0f / ((1.0f + lambda_o) * cos_o); }

// A microfacet normal distributed as D_wo (Heitz 2018): wo's direction in the
// configuration stretched to alpha = 1, a point on the projected disk there,
// and the normal unstretched. u, v uniform in [0, 1).
inline float3 ggx_sample_visible_normal(float alpha, float3 wo, float3 n, float u, float v)
{
    float3 t, b;
    orthonormal_basis(n, &t, &b);
    const float3 vh = normalize((float3)(alpha * dot(wo, t), alpha * dot(wo, b), dot(wo, n)));
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const float3 t1 = lensq > 0.0f ? (float3)(-vh.y, vh.x, 0.0f) * rsqrt(lensq) : (float3)(1.0f, 0.0f, 0.0f);
    const float3 t2 = cross(vh, t1);
    const float r = sqrt(u);
    const float2 cs = unit_circle(v);
    const float p1 = r * cs.x;
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * sqrt(fmax(0.0f, 1.0f - p1 * p1)) + s * (r * cs.y);
    const float3 nh = p1 * t1 + p2 * t2 + sqrt(fmax(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    const float3 m_local = normalize((float3)(alpha * nh.x, alpha * nh.y, fmax(1e-7f, nh.z)));
    return m_local.x * t + m_local.y * b + m_local.z * n;
}
