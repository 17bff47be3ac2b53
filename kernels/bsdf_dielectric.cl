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

inline bool dielectric_has_density(const Bsdf* b) { return false; }

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

inline float3 dielectric_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    *pdf = 0.0f;
    return (float3)(0.0f);
}

inline BsdfSample dielectric_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v,
                                    float* choice)
{
    return smooth_dielectric_sample(b, wo, n, outside, choice);
}

inline float3 dielectric_albedo(const Bsdf* b, float3 wo, float3 n) { return b->color; }
