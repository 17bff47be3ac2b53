// The BSDF interface (conventions in bsdf_types.cl): one switch per entry
// point over the material kinds, each case calling the material's own file.
// Adding a material is a MaterialKind, its file, and one line in each switch.
//
// A program carries only the kinds its scene uses: the host passes
// -DORB_MATERIAL_KINDS, bit k for MaterialKind k (all kinds when absent, as
// in the BSDF tests). A kind left out is never asked for; its case falls
// back to diffuse, and its code is gone from the program.
#ifndef ORB_MATERIAL_KINDS
#define ORB_MATERIAL_KINDS 0xffffffffu
#endif
#define ORB_KIND_BUILT(kind) ((((uint)(ORB_MATERIAL_KINDS)) >> (kind)) & 1u)
#define ORB_BSDF_CASE(kind, call) \
    case kind:                    \
        if (ORB_KIND_BUILT(kind)) return call; \
        break;

inline bool bsdf_has_density(const Bsdf* b)
{
    switch (b->kind) {
        ORB_BSDF_CASE(MaterialKind_Mirror, mirror_has_density(b))
        ORB_BSDF_CASE(MaterialKind_Dielectric, dielectric_has_density(b))
        ORB_BSDF_CASE(MaterialKind_Pbr, pbr_has_density(b))
        default: break;
    }
    return diffuse_has_density(b);
}

inline BsdfSample bsdf_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v, float* choice)
{
    switch (b->kind) {
        ORB_BSDF_CASE(MaterialKind_Mirror, mirror_sample(b, wo, n, outside, u, v, choice))
        ORB_BSDF_CASE(MaterialKind_Dielectric, dielectric_sample(b, wo, n, outside, u, v, choice))
        ORB_BSDF_CASE(MaterialKind_Pbr, pbr_sample(b, wo, n, outside, u, v, choice))
        default: break;
    }
    return diffuse_sample(b, wo, n, outside, u, v, choice);
}

// f(wo, wi) |cos(wi, n)| over the lobes with a density; *pdf: the density of wi under bsdf_sample.
inline float3 bsdf_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    switch (b->kind) {
        ORB_BSDF_CASE(MaterialKind_Mirror, mirror_eval(b, wo, wi, n, outside, pdf))
        ORB_BSDF_CASE(MaterialKind_Dielectric, dielectric_eval(b, wo, wi, n, outside, pdf))
        ORB_BSDF_CASE(MaterialKind_Pbr, pbr_eval(b, wo, wi, n, outside, pdf))
        default: break;
    }
    return diffuse_eval(b, wo, wi, n, outside, pdf);
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
        ORB_BSDF_CASE(MaterialKind_Mirror, mirror_albedo(b, wo, n))
        ORB_BSDF_CASE(MaterialKind_Dielectric, dielectric_albedo(b, wo, n))
        ORB_BSDF_CASE(MaterialKind_Pbr, pbr_albedo(b, wo, n))
        default: break;
    }
    return diffuse_albedo(b, wo, n);
}
