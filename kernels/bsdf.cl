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

// Over lanes (lanes.cl): each entry point runs the function of every kind
// present among the lanes, for all lanes, and keeps each lane's own kind's
// result. At width 1 that is one kind, chosen by the same tests. A lane
// whose kind is none of the built ones (no material: kind -1) gets no
// sample, no density and black.
#define ORB_BSDF_LANES_OF_KIND(member) \
    mask_and(mask_of(ORB_KIND_BUILT(MaterialKind_##member)), b->kind == MaterialKind_##member)
// Those of them the call serves (Bsdf.lobes, a constant): for a kind whose
// _has_density is a constant the test folds away, and so does the kind's
// case where it cannot be served.
#define ORB_BSDF_SERVED_LANES_OF_KIND(member, prefix)                                \
    mask_and(ORB_BSDF_LANES_OF_KIND(member),                                         \
             b->lobes == ORB_LOBES_DENSITY        ? prefix##_has_density(b)          \
             : (b->lobes == ORB_LOBES_DELTA_ONLY) ? mask_not(prefix##_has_density(b)) \
                                                  : mask_of(true))

#define ORB_BSDF_CASE_HAS_DENSITY(member, value, name, scn_word, prefix, caster_rule)      \
    if (ORB_KIND_BUILT(MaterialKind_##member)) {                                         \
        const lmask kind_lanes = ORB_BSDF_LANES_OF_KIND(member);                          \
        if (lanes_any(kind_lanes)) density = lselect(density, prefix##_has_density(b), kind_lanes); \
    }
LANE_FN lmask bsdf_has_density(const Bsdf* b)
{
    lmask density = mask_of(false);
    ORB_MATERIAL_TABLE(ORB_BSDF_CASE_HAS_DENSITY)
    return density;
}

#define ORB_BSDF_CASE_SAMPLE(member, value, name, scn_word, prefix, caster_rule)           \
    if (ORB_KIND_BUILT(MaterialKind_##member)) {                                         \
        const lmask kind_lanes = ORB_BSDF_SERVED_LANES_OF_KIND(member, prefix);          \
        if (lanes_any(kind_lanes)) {                                                      \
            lfloat kind_choice = *choice;                                                 \
            s = bsdf_sample_select(s, prefix##_sample(b, wo, n, outside, u, v, &kind_choice), kind_lanes); \
            rescaled = lselect(rescaled, kind_choice, kind_lanes);                        \
        }                                                                                 \
    }
LANE_FN BsdfSample bsdf_sample(const Bsdf* b, lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lfloat* choice)
{
    BsdfSample s = bsdf_no_sample();
    lfloat rescaled = *choice;
    ORB_MATERIAL_TABLE(ORB_BSDF_CASE_SAMPLE)
    *choice = rescaled;
    return s;
}

// f(wo, wi) |cos(wi, n)| over the lobes with a density; *pdf: the density of wi under bsdf_sample.
#define ORB_BSDF_CASE_EVAL(member, value, name, scn_word, prefix, caster_rule)             \
    if (ORB_KIND_BUILT(MaterialKind_##member)) {                                         \
        const lmask kind_lanes = ORB_BSDF_SERVED_LANES_OF_KIND(member, prefix);          \
        if (lanes_any(kind_lanes)) {                                                      \
            lfloat kind_pdf;                                                              \
            f_cos = lv3_select(f_cos, prefix##_eval(b, wo, wi, n, outside, &kind_pdf), kind_lanes); \
            *pdf = lselect(*pdf, kind_pdf, kind_lanes);                                   \
        }                                                                                 \
    }
LANE_FN lv3 bsdf_eval(const Bsdf* b, lv3 wo, lv3 wi, lv3 n, lmask outside, lfloat* pdf)
{
    lv3 f_cos = lv3_zero();
    *pdf = (lfloat)(0.0f);
    ORB_MATERIAL_TABLE(ORB_BSDF_CASE_EVAL)
    return f_cos;
}

#define ORB_BSDF_CASE_ALBEDO(member, value, name, scn_word, prefix, caster_rule)           \
    if (ORB_KIND_BUILT(MaterialKind_##member)) {                                         \
        const lmask kind_lanes = ORB_BSDF_SERVED_LANES_OF_KIND(member, prefix);          \
        if (lanes_any(kind_lanes)) albedo = lv3_select(albedo, prefix##_albedo(b, wo, n), kind_lanes); \
    }
LANE_FN lv3 bsdf_albedo(const Bsdf* b, lv3 wo, lv3 n)
{
    lv3 albedo = lv3_zero();
    ORB_MATERIAL_TABLE(ORB_BSDF_CASE_ALBEDO)
    return albedo;
}
