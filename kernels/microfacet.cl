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

LANE_FN lfloat ggx_alpha(lfloat roughness) { return roughness * roughness; }

LANE_FN lmask ggx_is_smooth(lfloat alpha) { return alpha < GGX_SMOOTH_ALPHA; }

// D(m) for a unit microfacet normal m: alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2),
// with cos^2 (alpha^2 - 1) + 1 written as sin^2 + alpha^2 cos^2 and sin^2 taken
// from the cross product, which keeps its precision near the peak of a narrow lobe.
LANE_FN lfloat ggx_d(lfloat alpha, lv3 m, lv3 n)
{
    const lfloat cos_m = lv3_dot(m, n);
    const lv3 c = lv3_cross(m, n);
    const lfloat a2 = alpha * alpha;
    const lfloat t = lv3_dot(c, c) + a2 * cos_m * cos_m;
    return lselect(a2 / (ORB_PI * t * t), (lfloat)(0.0f), cos_m <= 0.0f);
}

// Smith's Lambda for GGX at |cos(theta)| = c > 0:
// (sqrt(1 + alpha^2 tan^2) - 1) / 2 = (sqrt(c^2 + alpha^2 (1 - c^2)) / c - 1) / 2.
LANE_FN lfloat ggx_lambda(lfloat alpha, lfloat c)
{
    const lfloat c2 = c * c;
    return 0.5f * (sqrt(c2 + alpha * alpha * fmax((lfloat)(0.0f), 1.0f - c2)) / c - 1.0f);
}

// The visible-normal density of m seen from wo, divided by D(m) and by wo.m:
// D_wo(m) = G1(wo) max(0, wo.m) D(m) / cos_o (Heitz 2018, eq. 1). Returned
// factor: G1(wo) / cos_o, with G1 = 1 / (1 + Lambda).
LANE_FN lfloat ggx_visible_factor(lfloat lambda_o, lfloat cos_o) { return 1.0f / ((1.0f + lambda_o) * cos_o); }

// A microfacet normal distributed as D_wo (Heitz 2018): wo's direction in the
// configuration stretched to alpha = 1, a point on the projected disk there,
// and the normal unstretched. u, v uniform in [0, 1).
LANE_FN lv3 ggx_sample_visible_normal(lfloat alpha, lv3 wo, lv3 n, lfloat u, lfloat v)
{
    lv3 t, b;
    orthonormal_basis(n, &t, &b);
    const lv3 vh = lv3_normalize(lv3_make(alpha * lv3_dot(wo, t), alpha * lv3_dot(wo, b), lv3_dot(wo, n)));
    const lfloat lensq = vh.x * vh.x + vh.y * vh.y;
    const lfloat inv_len = rsqrt(lensq);
    const lmask tilted = lensq > 0.0f;
    const lv3 t1 = lv3_make(lselect((lfloat)(1.0f), -vh.y * inv_len, tilted), lselect((lfloat)(0.0f), vh.x * inv_len, tilted),
                            (lfloat)(0.0f));
    const lv3 t2 = lv3_cross(vh, t1);
    const lfloat r = sqrt(u);
    lfloat cs_x, cs_y;
    lanes_unit_circle(v, &cs_x, &cs_y);
    const lfloat p1 = r * cs_x;
    const lfloat s = 0.5f * (1.0f + vh.z);
    const lfloat p2 = (1.0f - s) * sqrt(fmax((lfloat)(0.0f), 1.0f - p1 * p1)) + s * (r * cs_y);
    const lv3 nh = lv3_add(lv3_add(lv3_scale(t1, p1), lv3_scale(t2, p2)),
                           lv3_scale(vh, sqrt(fmax((lfloat)(0.0f), 1.0f - p1 * p1 - p2 * p2))));
    const lv3 m_local = lv3_normalize(lv3_make(alpha * nh.x, alpha * nh.y, fmax((lfloat)(1e-7f), nh.z)));
    return lv3_add(lv3_add(lv3_scale(t, m_local.x), lv3_scale(b, m_local.y)), lv3_scale(n, m_local.z));
}
