// What every BSDF shares: its parameters, the result of sampling it, and the
// conventions of the interface that kernels/bsdf.cl dispatches
// (docs/rendering.md, "The BSDF interface").
//
// Directions are unit vectors in world space pointing away from the surface:
// wo towards the viewer (the camera side of the path), wi towards where the
// light comes from. n is the unit normal on wo's side (dot(wo, n) > 0), so
// wi is a reflection when dot(wi, n) > 0 and a transmission when < 0.
// `outside` says whether wo lies outside the sphere, whose medium has index
// of refraction 1; the sphere's inside has the material's `ior`.
//
// Every material implements, in its own file, with this meaning:
//   NAME_sample(b, wo, n, outside, u, v, &choice) -> BsdfSample
//       u, v: uniform numbers for the direction. choice: a uniform number
//       for picking a lobe; on return it is rescaled to be uniform again and
//       independent of the pick (see choose_lobe), so the integrator can use
//       it once more, for Russian roulette.
//   NAME_eval(b, wo, wi, n, outside, &pdf) -> f(wo, wi) |cos(wi, n)|
//       for the lobes with a density (delta lobes contribute nothing), and in
//       pdf the solid-angle density with which NAME_sample returns wi.
//   NAME_has_density(b): per lane, false when every lobe is a delta (mirror, smooth
//       glass): next-event estimation is then pointless and is skipped, and
//       NAME_sample must not use u, v (the integrator does not draw them).
//   NAME_albedo(b, wo, n): the reflectance the albedo pass records.

// Everything here is over lanes (lanes.cl): a BSDF call evaluates the
// lanes' own materials at once; at width 1 it is plain scalar code.
//
// Which lanes a BSDF call serves, a constant wherever a Bsdf is made: the
// integrator calls the BSDF for the lanes whose material has a density
// (next-event estimation, the continuation) apart from those with delta
// lobes only, and says so. A kind that cannot be among the lanes served
// (diffuse among the delta-only ones; smooth glass and mirror among those
// with a density) then drops out of that call's code when the program is
// compiled: at 16 lanes on PoCL that took 14-18% of the spill stores and
// 10-13% of the instructions out of the programs of caustic.scn and
// cornell.scn (docs/design/one-path-tracer-over-lanes.md).
#define ORB_LOBES_ANY 0
#define ORB_LOBES_DENSITY 1
#define ORB_LOBES_DELTA_ONLY 2

// A material's scattering parameters, unpacked from its MaterialRecord.
typedef struct {
    lv3 color;         // reflectance, base colour or transmittance tint
    lint kind;         // a MaterialKind (-1 for a lane with no material)
    lfloat ior;        // index of refraction of the sphere's inside (dielectric)
    lfloat roughness;  // perceptual roughness in [0, 1] (pbr, dielectric); the GGX alpha is its square
    lfloat metallic;   // pbr: 0 dielectric base, 1 metal
    int lobes;         // ORB_LOBES_*: the lanes a call serves
} Bsdf;

typedef struct {
    lv3 wi;        // the sampled direction (unit)
    lv3 weight;    // f |cos| / pdf, the throughput factor; for a delta lobe the lobe's reflectance
    lfloat pdf;    // solid-angle density of wi under NAME_sample, for MIS; 0 for a delta lobe
    lmask delta;   // wi came from a delta (specular) lobe, which light sampling cannot produce
    lfloat eta2;   // the (n_o / n_i)^2 radiance factor inside weight on refraction, else 1
} BsdfSample;

LANE_FN BsdfSample bsdf_no_sample(void)
{
    BsdfSample s;
    s.wi = lv3_make((lfloat)(0.0f), (lfloat)(0.0f), (lfloat)(1.0f));
    s.weight = lv3_zero();
    s.pdf = (lfloat)(0.0f);
    s.delta = mask_of(true);  // no density to weigh against: an emitter it might "hit" is never reached (weight 0)
    s.eta2 = (lfloat)(1.0f);
    return s;
}

// b where m, else a.
LANE_FN BsdfSample bsdf_sample_select(BsdfSample a, BsdfSample b, lmask m)
{
    BsdfSample s;
    s.wi = lv3_select(a.wi, b.wi, m);
    s.weight = lv3_select(a.weight, b.weight, m);
    s.pdf = lselect(a.pdf, b.pdf, m);
    s.delta = lselect(a.delta, b.delta, m);
    s.eta2 = lselect(a.eta2, b.eta2, m);
    return s;
}

// The mirror direction of wo about unit m.
LANE_FN lv3 reflect_about(lv3 wo, lv3 m) { return lv3_sub(lv3_scale(m, 2.0f * lv3_dot(wo, m)), wo); }

// Picks the first of two lobes with probability p using the uniform *u, and
// rescales *u to [0, 1) within the part it fell into, so that it is uniform
// again and independent of the pick.
LANE_FN lmask choose_lobe(lfloat p, lfloat* u)
{
    const lmask first = *u < p;
    const lfloat rescaled = lselect((*u - p) / (1.0f - p), *u / p, first);
    *u = fmin(rescaled, (lfloat)(0x1.fffffep-1f));
    return first;
}
