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
//   NAME_has_density(b): false when every lobe is a delta (mirror, smooth
//       glass): next-event estimation is then pointless and is skipped, and
//       NAME_sample must not use u, v (the integrator does not draw them).
//   NAME_albedo(b, wo, n): the reflectance the albedo pass records.

// A material's scattering parameters, unpacked from its MaterialRecord.
typedef struct {
    float3 color;     // reflectance, base colour or transmittance tint
    int kind;         // a MaterialKind
    float ior;        // index of refraction of the sphere's inside (dielectric)
    float roughness;  // perceptual roughness in [0, 1] (pbr, dielectric); the GGX alpha is its square
    float metallic;   // pbr: 0 dielectric base, 1 metal
} Bsdf;

typedef struct {
    float3 wi;      // the sampled direction (unit)
    float3 weight;  // f |cos| / pdf, the throughput factor; for a delta lobe the lobe's reflectance
    float pdf;      // solid-angle density of wi under NAME_sample, for MIS; 0 for a delta lobe
    bool delta;     // wi came from a delta (specular) lobe, which light sampling cannot produce
    float eta2;     // the (n_o / n_i)^2 radiance factor inside weight on refraction, else 1
} BsdfSample;

inline BsdfSample bsdf_no_sample(void)
{
    BsdfSample s;
    s.wi = (float3)(0.0f, 0.0f, 1.0f);
    s.weight = (float3)(0.0f);
    s.pdf = 0.0f;
    s.delta = true;  // no density to weigh against: an emitter it might "hit" is never reached (weight 0)
    s.eta2 = 1.0f;
    return s;
}

// The mirror direction of wo about unit m.
inline float3 reflect_about(float3 wo, float3 m) { return (2.0f * dot(wo, m)) * m - wo; }

// Picks the first of two lobes with probability p using the uniform *u, and
// rescales *u to [0, 1) within the part it fell into, so that it is uniform
// again and independent of the pick.
inline bool choose_lobe(float p, float* u)
{
    const bool first = *u < p;
    const float rescaled = first ? *u / p : (*u - p) / (1.0f - p);
    *u = fmin(rescaled, 0x1.fffffep-1f);
    return first;
}
