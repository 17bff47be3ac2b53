// The BSDF interface (conventions in bsdf_types.cl): one switch per entry
// point over the material kinds, each case calling the material's own file.
// Adding a material is a MaterialKind, its file, and one line in each switch.

inline bool bsdf_has_density(const Bsdf* b)
{
    switch (b->kind) {
        case MaterialKind_Mirror: return mirror_has_density(b);
        case MaterialKind_Dielectric: return dielectric_has_density(b);
        case MaterialKind_Pbr: return pbr_has_density(b);
        case MaterialKind_Diffuse:
        default: return diffuse_has_density(b);
    }
}

inline BsdfSample bsdf_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v, float* choice)
{
    switch (b->kind) {
        case MaterialKind_Mirror: return mirror_sample(b, wo, n, outside, u, v, choice);
        case MaterialKind_Dielectric: return dielectric_sample(b, wo, n, outside, u, v, choice);
        case MaterialKind_Pbr: return pbr_sample(b, wo, n, outside, u, v, choice);
        case MaterialKind_Diffuse:
        default: return diffuse_sample(b, wo, n, outside, u, v, choice);
    }
}

// f(wo, wi) |cos(wi, n)| over the lobes with a density; *pdf: the density of wi under bsdf_sample.
inline float3 bsdf_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    switch (b->kind) {
        case MaterialKind_Mirror: return mirror_eval(b, wo, wi, n, outside, pdf);
        case MaterialKind_Dielectric: return dielectric_eval(b, wo, wi, n, outside, pdf);
        case MaterialKind_Pbr: return pbr_eval(b, wo, wi, n, outside, pdf);
        case MaterialKind_Diffuse:
        default: return diffuse_eval(b, wo, wi, n, outside, pdf);
    }
}

inline float bsdf_pdf(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside)
{
    float pdf;
    bsdf_eval(b, wo, wi, n, outside, &pdf);
    return pdf;
}

inline float3 bsdf_albedo(const Bsdf* b, float3 wo, float3 n)
{
    switch (b->kind) {
        case MaterialKind_Mirror: return mirror_albedo(b, wo, n);
        case MaterialKind_Dielectric: return dielectric_albedo(b, wo, n);
        case MaterialKind_Pbr: return pbr_albedo(b, wo, n);
        case MaterialKind_Diffuse:
        default: return diffuse_albedo(b, wo, n);
    }
}
