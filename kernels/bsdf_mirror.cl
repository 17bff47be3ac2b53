// Perfect mirror: one delta lobe, reflectance `color`.

inline bool mirror_has_density(const Bsdf* b) { return false; }

inline BsdfSample mirror_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v, float* choice)
{
    BsdfSample s;
    s.wi = reflect_about(wo, n);
    s.weight = b->color;
    s.pdf = 0.0f;
    s.delta = true;
    s.eta2 = 1.0f;
    return s;
}

inline float3 mirror_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    *pdf = 0.0f;
    return (float3)(0.0f);
}

inline float3 mirror_albedo(const Bsdf* b, float3 wo, float3 n) { return b->color; }
