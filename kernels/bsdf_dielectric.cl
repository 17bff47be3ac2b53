// Glass: a smooth interface between the outside (index 1) and the sphere's
// inside (index `ior`), tinted by `color` on both reflection and refraction.

// Exact Fresnel reflectance of a smooth dielectric for unpolarised light.
// cos_i: cosine of the angle of incidence (> 0); eta = n_incident / n_transmitted.
// Returns 1 on total internal reflection; *cos_t receives the transmitted cosine.
inline float fresnel_dielectric(float cos_i, float eta, float* cos_t)
{
    const float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) {
        *cos_t = 0.0f;
        return 1.0f;
    }
    const float ct = sqrt(1.0f - sin2_t);
    *cos_t = ct;
    const float rs = (eta * cos_i - ct) / (eta * cos_i + ct);
    const float rp = (cos_i - eta * ct) / (cos_i + eta * ct);
    return 0.5f * (rs * rs + rp * rp);
}

// Rough glass's code is in the program only when a glass of the scene is
// rough (-DORB_ROUGH_DIELECTRIC=0 from the host otherwise; built when absent).
inline bool dielectric_is_smooth(float alpha) { return !ORB_ROUGH_DIELECTRIC || ggx_is_smooth(alpha); }

inline bool dielectric_has_density(const Bsdf* b) { return !dielectric_is_smooth(ggx_alpha(b->roughness)); }

// Smooth glass: reflects with probability F and refracts with 1 - F, so the
// Fresnel factors cancel in the weight.
inline BsdfSample smooth_dielectric_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float* choice)
{
    BsdfSample s;
    s.pdf = 0.0f;
    s.delta = true;
    s.eta2 = 1.0f;
    s.weight = b->color;
    const float cos_o = dot(wo, n);
    const float eta = outside ? 1.0f / b->ior : b->ior;  // n_o / n_i
    float cos_t;
    const float reflectance = fresnel_dielectric(cos_o, eta, &cos_t);
    if (choose_lobe(reflectance, choice)) {
        s.wi = reflect_about(wo, n);
        return s;
    }
    s.wi = normalize(-eta * wo + (eta * cos_o - cos_t) * n);
    // L / n^2 is invariant across the interface, so radiance arriving from the
    // transmitted side is scaled by (n_o / n_i)^2 = eta^2 on the viewer's side.
    s.eta2 = eta * eta;
    s.weight = b->color * s.eta2;
    return s;
}

// Rough glass (Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces"): GGX microfacets, each a smooth interface. f cos and the pdf
// of dielectric_sample, which reflects about a visible normal m with
// probability F(wo.m) and refracts through it otherwise.
//   reflection:   f cos = F D G2 / (4 cos_o),
//                 pdf = F G1(wo) D / (4 cos_o)      (m = the half vector of wo, wi)
//   refraction:   f cos = eta^2 (1 - F) D G2 |wi.m| (wo.m) / (cos_o (wi.m + eta wo.m)^2),
//                 pdf = (1 - F) G1(wo) D (wo.m) |wi.m| / (cos_o (wi.m + eta wo.m)^2)
//                 (m along eta wo + wi, the generalised half vector)
// with eta = n_o / n_i; both times color.
inline float3 dielectric_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    *pdf = 0.0f;
    const float alpha = ggx_alpha(b->roughness);
    const float cos_o = dot(wo, n);
    const float cos_i = dot(wi, n);
    if (dielectric_is_smooth(alpha) || cos_o <= 0.0f || cos_i == 0.0f) return (float3)(0.0f);
    const float eta = outside ? 1.0f / b->ior : b->ior;
    const bool reflection = cos_i > 0.0f;
    float3 m = reflection ? wo + wi : eta * wo + wi;
    const float length2 = dot(m, m);
    if (!(length2 > 0.0f)) return (float3)(0.0f);  // index-matched straight transmission: no microfacet
    m *= rsqrt(length2);
    if (dot(m, n) < 0.0f) m = -m;
    const float cos_om = dot(wo, m);
    const float cos_im = dot(wi, m);
    // Light arrives and leaves on the facet's sides that match the macro surface.
    if (cos_om <= 0.0f || cos_im * cos_i <= 0.0f) return (float3)(0.0f);
    float cos_t;
    const float fresnel = fresnel_dielectric(cos_om, eta, &cos_t);
    const float d = ggx_d(alpha, m, n);
    const float lambda_o = ggx_lambda(alpha, cos_o);
    const float g2 = 1.0f / (1.0f + lambda_o + ggx_lambda(alpha, fabs(cos_i)));
    const float visible = d * ggx_visible_factor(lambda_o, cos_o);  // D_wo(m) / (wo.m)
    if (reflection) {
        *pdf = fresnel * visible * 0.25f;
        return b->color * (fresnel * d * g2 / (4.0f * cos_o));
    }
    const float sum = cos_im + eta * cos_om;
    const float jacobian = -cos_im / (sum * sum);  // d omega_m / d omega_i (Walter et al., eq. 17)
    *pdf = (1.0f - fresnel) * visible * cos_om * jacobian;
    return b->color * (eta * eta * (1.0f - fresnel) * d * g2 * cos_om * jacobian / cos_o);
}

inline BsdfSample dielectric_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v,
                                    float* choice)
{
    const float alpha = ggx_alpha(b->roughness);
    if (dielectric_is_smooth(alpha)) return smooth_dielectric_sample(b, wo, n, outside, choice);
    const float eta = outside ? 1.0f / b->ior : b->ior;
    const float3 m = ggx_sample_visible_normal(alpha, wo, n, u, v);
    const float cos_om = dot(wo, m);
    float cos_t;
    const float fresnel = fresnel_dielectric(fmax(0.0f, cos_om), eta, &cos_t);
    BsdfSample s;
    s.delta = false;
    s.eta2 = 1.0f;
    if (choose_lobe(fresnel, choice)) {
        s.wi = reflect_about(wo, m);
        if (dot(s.wi, n) <= 0.0f) return bsdf_no_sample();
    } else {
        s.wi = normalize(-eta * wo + (eta * cos_om - cos_t) * m);
        if (dot(s.wi, n) >= 0.0f) return bsdf_no_sample();
        s.eta2 = eta * eta;
    }
    // The weight from the same functions MIS and dielectric_pdf use, so the
    // three agree: G2 / G1(wo), times eta^2 for refraction, times color.
    const float3 f_cos = dielectric_eval(b, wo, s.wi, n, outside, &s.pdf);
    if (!(s.pdf > 0.0f)) return bsdf_no_sample();
    s.weight = f_cos * (1.0f / s.pdf);
    return s;
}

inline float3 dielectric_albedo(const Bsdf* b, float3 wo, float3 n) { return b->color; }
