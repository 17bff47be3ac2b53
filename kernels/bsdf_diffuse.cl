// Lambertian diffuse: f = color / pi on the viewer's side (two-sided: n faces
// the viewer), sampled with a cosine-weighted hemisphere, pdf = cos / pi.

inline bool diffuse_has_density(const Bsdf* b) { return true; }

inline BsdfSample diffuse_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v, float* choice)
{
    BsdfSample s;
    float cos_theta;
    s.wi = sample_cosine_hemisphere(n, u, v, &cos_theta);
    s.weight = b->color;  // (color / pi) cos / (cos / pi)
    s.pdf = cos_theta * ORB_INV_PI;
    s.delta = false;
    s.eta2 = 1.0f;
    return s;
}

inline float3 diffuse_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    const float cos_theta = dot(n, wi);
    if (cos_theta <= 0.0f) {
        *pdf = 0.0f;
        return (float3)(0.0f);
    }
    *pdf = cos_theta * ORB_INV_PI;
    return b->color * *pdf;
}

inline float3 diffuse_albedo(const Bsdf* b, float3 wo, float3 n) { return b->color; }
