// Aiming BSDF sampling at glass and mirror balls (docs/rendering.md,
// "Caustics").
//
// Light that reaches a diffuse or glossy surface through a glass or mirror
// ball (a caustic) arrives along a path next-event estimation cannot build:
// its shadow ray stops at the ball. Only a BSDF-sampled direction that
// happens to hit the ball finds it, so caustics are where a path tracer's
// error concentrates (on the Cornell box the worst 5% of pixels held 92% of
// it). The host lists the spheres whose material has no density (mirror,
// smooth glass, smooth metal) as casters; at every vertex with a density the
// continuation direction comes from a mixture:
//   with probability 1 - ORB_CASTER_SHARE: the BSDF's own sampling;
//   with probability ORB_CASTER_SHARE: uniformly inside the cone of a caster,
//     picked uniformly among the K casters.
// Its density, p(wi) = (1 - s) p_bsdf(wi) + (s / K) sum_k cone_k(wi), is what
// the throughput divides by and what multiple importance sampling weighs
// against light sampling, at an emitter the continuation hits and in
// next-event estimation alike. The estimator stays unbiased whatever the
// casters are: the mixture covers every direction the BSDF covers.

// The share of continuations aimed at casters, chosen by time to equal error
// (docs/design/caustic-casters.md; -DORB_CASTER_SHARE=0 turns the aiming off).

// The density of direction wi under uniform sampling of caster c's cone from
// p: 0 outside the cone, and for a p inside the caster (it has no cone).
// Inside the cone when cos(wi, pc) >= cos theta_max = sqrt(d^2 - r^2) / d,
// that is (wi . pc)^2 >= d^2 - r^2 with wi . pc > 0: most directions miss
// every cone, and this test needs no square root or division.
inline float caster_cone_pdf(SCENE_MEM const CasterRecord* c, float3 p, float3 wi)
{
    const float3 pc = c->centre_radius.xyz - p;
    const float distance2 = dot(pc, pc);
    const float radius = c->centre_radius.w;
    const float radius2 = radius * radius;
    const float along = dot(wi, pc);
    if (distance2 <= radius2 || along <= 0.0f || along * along < distance2 - radius2) return 0.0f;
    return 1.0f / (2.0f * ORB_PI * cone_one_minus_cos(distance2, radius));
}

// The density of direction wi under the continuation's mixture at p, for a
// BSDF whose own sampling gives wi the density bsdf_pdf.
inline float continuation_pdf(const SceneView* scene, float3 p, float bsdf_pdf, float3 wi)
{
    const int count = scene->caster_count;
    if (ORB_CASTER_SHARE <= 0.0f || count == 0) return bsdf_pdf;
    float cones = 0.0f;
    for (int k = 0; k < count; ++k) cones += caster_cone_pdf(&scene->casters[k], p, wi);
    return (1.0f - ORB_CASTER_SHARE) * bsdf_pdf + (ORB_CASTER_SHARE / (float)count) * cones;
}

// The continuation at a vertex with a density: a BsdfSample whose weight and
// pdf are the mixture's. *choice picks the strategy (and the caster, or the
// BSDF's lobe) and is handed back rescaled, as bsdf_sample does.
inline BsdfSample sample_continuation(const SceneView* scene, const Bsdf* b, float3 p, float3 wo, float3 n,
                                      bool outside, float u, float v, float* choice)
{
    const int count = scene->caster_count;
    if (ORB_CASTER_SHARE <= 0.0f || count == 0) return bsdf_sample(b, wo, n, outside, u, v, choice);
    BsdfSample s;
    float3 f_cos;     // f |cos| of the direction, whichever strategy drew it
    float bsdf_pdf;   // the BSDF's own density of it
    if (choose_lobe(ORB_CASTER_SHARE, choice)) {
        const float scaled = *choice * (float)count;
        const int k = min((int)scaled, count - 1);
        *choice = fmin(scaled - (float)k, 0x1.fffffep-1f);
        SCENE_MEM const CasterRecord* c = &scene->casters[k];
        const float3 pc = c->centre_radius.xyz - p;
        const float distance2 = dot(pc, pc);
        const float radius = c->centre_radius.w;
        // From inside a caster this strategy has no direction to give: a
        // lost sample, which the mixture's density accounts for (that
        // caster's cone density is 0 here).
        if (distance2 <= radius * radius) return bsdf_no_sample();
        // The cone as sample_light_direction (lights.cl) samples a sphere
        // light's; one shared helper for both measured 2-3% slower on PoCL,
        // which did not inline it.
        s.wi = sample_uniform_cone(pc * rsqrt(distance2), cone_one_minus_cos(distance2, radius), u, v);
        f_cos = bsdf_eval(b, wo, s.wi, n, outside, &bsdf_pdf);
        s.delta = false;
        // eta2 only steers the roulette's survival chance, which any value
        // keeps unbiased; the BSDF's refraction factor is not known here.
        s.eta2 = 1.0f;
    } else {
        s = bsdf_sample(b, wo, n, outside, u, v, choice);
        if (s.delta) {
            // A delta lobe (a smooth coat) is reached only through the
            // BSDF's share: its probability is scaled by it.
            s.weight *= 1.0f / (1.0f - ORB_CASTER_SHARE);
            return s;
        }
        bsdf_pdf = s.pdf;
        f_cos = s.weight * s.pdf;
    }
    // One density for both strategies, after the branch: on a GPU the two
    // sides of a warp then share this code instead of running it twice.
    s.pdf = continuation_pdf(scene, p, bsdf_pdf, s.wi);
    if (!(s.pdf > 0.0f)) return bsdf_no_sample();
    s.weight = f_cos * (1.0f / s.pdf);
    return s;
}
