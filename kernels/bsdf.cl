// The BSDF interface (conventions in bsdf_types.cl): each entry point
// dispatches over the rows of ORB_MATERIAL_TABLE (material_kinds.h) to the
// kind's own file. Adding a material is a row there and its file; no switch
// here names a kind.
//
// A program carries only the kinds its scene uses: the host passes
// -DORB_MATERIAL_KINDS, bit k for MaterialKind k (all kinds when absent, as
// in the BSDF tests). A kind left out is never asked for; its case is gone
// from the program, and asking for it anyway is a host error (the kinds
// mask is made from the scene).
#define ORB_KIND_BUILT(kind) ((((uint)(ORB_MATERIAL_KINDS)) >> (kind)) & 1u)

#define ORB_BSDF_CASE_HAS_DENSITY(member, value, name, scn_word, prefix, caster_rule) \
    case MaterialKind_##member:                                                       \
        if (ORB_KIND_BUILT(MaterialKind_##member)) return prefix##_has_density(b);   \
        break;
inline bool bsdf_has_density(const Bsdf* b)
{
    switch (b->kind) {
        ORB_MATERIAL_TABLE(ORB_BSDF_CASE_HAS_DENSITY)
        default: break;
    }
    return false;
}

#define ORB_BSDF_CASE_SAMPLE(member, value, name, scn_word, prefix, caster_rule)                     \
    case MaterialKind_##member:                                                                     \
        if (ORB_KIND_BUILT(MaterialKind_##member)) return prefix##_sample(b, wo, n, outside, u, v, choice); \
        break;
inline BsdfSample bsdf_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v, float* choice)
{
    switch (b->kind) {
        ORB_MATERIAL_TABLE(ORB_BSDF_CASE_SAMPLE)
        default: break;
    }
    return bsdf_no_sample();
}

// f(wo, wi) |cos(wi, n)| over the lobes with a density; *pdf: the density of wi under bsdf_sample.
#define ORB_BSDF_CASE_EVAL(member, value, name, scn_word, prefix, caster_rule)                     \
    case MaterialKind_##member:                                                                   \
        if (ORB_KIND_BUILT(MaterialKind_##member)) return prefix##_eval(b, wo, wi, n, outside, pdf); \
        break;
inline float3 bsdf_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    switch (b->kind) {
        ORB_MATERIAL_TABLE(ORB_BSDF_CASE_EVAL)
        default: break;
    }
    *pdf = 0.0f;
    return (float3)(0.0f);
}

inline float bsdf_pdf(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside)
{
    float pdf;
    bsdf_eval(b, wo, wi, n, outside, &pdf);
    return pdf;
}

#define ORB_BSDF_CASE_ALBEDO(member, value, name, scn_word, prefix, caster_rule)    \
    case MaterialKind_##member:                                                     \
        if (ORB_KIND_BUILT(MaterialKind_##member)) return prefix##_albedo(b, wo, n); \
        break;
inline float3 bsdf_albedo(const Bsdf* b, float3 wo, float3 n)
{
    switch (b->kind) {
        ORB_MATERIAL_TABLE(ORB_BSDF_CASE_ALBEDO)
        default: break;
    }
    return (float3)(0.0f);
}
