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

// Everything below is over lanes (lanes.cl).

// The density of direction wi under uniform sampling of caster c's cone from
// p: 0 outside the cone, and for a p inside the caster (it has no cone).
// Inside the cone when cos(wi, pc) >= cos theta_max = sqrt(d^2 - r^2) / d,
// that is (wi . pc)^2 >= d^2 - r^2 with wi . pc > 0: most directions miss
// every cone, and this test needs no square root or division.
LANE_FN lfloat caster_cone_pdf(SCENE_MEM const CasterRecord* c, lv3 p, lv3 wi)
{
    const lv3 pc = lv3_sub(lv3_splat(c->centre_radius.xyz), p);
    const lfloat distance2 = lv3_dot(pc, pc);
    const float radius = c->centre_radius.w;
    const float radius2 = radius * radius;
    const lfloat along = lv3_dot(wi, pc);
    const lmask inside = mask_and(mask_and(distance2 > radius2, along > 0.0f), along * along >= distance2 - radius2);
    if (!lanes_step(inside)) return (lfloat)(0.0f);
    return lselect((lfloat)(0.0f), 1.0f / (2.0f * ORB_PI * cone_one_minus_cos(distance2, (lfloat)(radius))), inside);
}

// The density of direction wi under the continuation's mixture at p, for a
// BSDF whose own sampling gives wi the density bsdf_pdf.
LANE_FN lfloat continuation_pdf(const SceneView* scene, lv3 p, lfloat bsdf_pdf, lv3 wi)
{
    const int count = scene->caster_count;
    if (ORB_CASTER_SHARE <= 0.0f || count == 0) return bsdf_pdf;
    lfloat cones = (lfloat)(0.0f);
    for (int k = 0; k < count; ++k) cones += caster_cone_pdf(&scene->casters[k], p, wi);
    return (1.0f - ORB_CASTER_SHARE) * bsdf_pdf + (ORB_CASTER_SHARE / (float)count) * cones;
}

// Caster k of each lane in `lanes` (what the other lanes get is unspecified).
LANE_FN void load_caster(const SceneView* scene, lint k, lmask lanes, lv3* centre, lfloat* radius)
{
#if ORB_LANES == 1
    const float4 cr = scene->casters[k].centre_radius;
    *centre = cr.xyz;
    *radius = cr.w;
#else
    *centre = lv3_zero();
    *radius = (lfloat)(0.0f);
    if (scene->caster_count > ORB_LANES_SELECT_GATHER_MAX) {
        ORB_FOR_EACH_LANE(l, lanes)
        {
            const float4 cr = scene->casters[lane_i(k, l)].centre_radius;
            set_lane_v3(*centre, l, cr.xyz);
            set_lane_f(*radius, l, cr.w);
        }
        return;
    }
    for (int c = 0; c < scene->caster_count; ++c) {
        const lmask m = k == c;
        if (!lanes_any(m)) continue;
        const float4 cr = scene->casters[c].centre_radius;
        *centre = lv3_select(*centre, lv3_splat(cr.xyz), m);
        *radius = lselect(*radius, (lfloat)(cr.w), m);
    }
#endif
}

// The continuation at a vertex with a density: a BsdfSample whose weight and
// pdf are the mixture's. *choice picks the strategy (and the caster, or the
// BSDF's lobe) and is handed back rescaled, as bsdf_sample does.
LANE_FN BsdfSample sample_continuation(const SceneView* scene, const Bsdf* b, lv3 p, lv3 wo, lv3 n, lmask outside,
                                       lfloat u, lfloat v, lfloat* choice)
{
    const int count = scene->caster_count;
    if (ORB_CASTER_SHARE <= 0.0f || count == 0) return bsdf_sample(b, wo, n, outside, u, v, choice);
    // The BSDF's own sample first, for every lane that draws one (at width
    // > 1 that is nearly always some lane, so it runs for all of them and
    // the aimed lanes overwrite theirs below, instead of selecting the whole
    // sample into place).
    const lmask aim = choose_lobe((lfloat)(ORB_CASTER_SHARE), choice);
    const lmask own = mask_not(aim);
    BsdfSample s = bsdf_no_sample();
    lv3 f_cos = lv3_zero();            // f |cos| of the direction, whichever strategy drew it
    lfloat bsdf_pdf = (lfloat)(0.0f);  // the BSDF's own density of it
    lmask delta = mask_of(false);
    if (lanes_step(own)) {
        lfloat own_choice = *choice;
        s = bsdf_sample(b, wo, n, outside, u, v, &own_choice);
        *choice = lselect(*choice, own_choice, own);
        // A delta lobe (a smooth coat) is reached only through the BSDF's
        // share: its probability is scaled by it.
        delta = mask_and(own, s.delta);
        s.weight = lv3_select(s.weight, lv3_scale(s.weight, 1.0f / (1.0f - ORB_CASTER_SHARE)), delta);
        bsdf_pdf = s.pdf;
        f_cos = lv3_scale(s.weight, s.pdf);
    }
    lmask lost = mask_of(false);
    if (lanes_step(aim)) {
        const lfloat scaled = *choice * (float)count;
        const lint k = min(to_lint(scaled), (lint)(count - 1));
        *choice = lselect(*choice, fmin(scaled - to_lfloat(k), (lfloat)(0x1.fffffep-1f)), aim);
        lv3 centre;
        lfloat radius;
        load_caster(scene, k, aim, &centre, &radius);
        const lv3 pc = lv3_sub(centre, p);
        const lfloat distance2 = lv3_dot(pc, pc);
        // From inside a caster this strategy has no direction to give: a
        // lost sample, which the mixture's density accounts for (that
        // caster's cone density is 0 here).
        lost = mask_and(aim, distance2 <= radius * radius);
        // The cone as sample_light_direction (lights.cl) samples a sphere
        // light's; one shared helper for both measured 2-3% slower on PoCL,
        // which did not inline it.
        s.wi = lv3_select(s.wi, sample_uniform_cone(lv3_scale(pc, rsqrt(distance2)), cone_one_minus_cos(distance2, radius), u, v),
                          aim);
        lfloat aimed_pdf;
        f_cos = lv3_select(f_cos, bsdf_eval(b, wo, s.wi, n, outside, &aimed_pdf), aim);
        bsdf_pdf = lselect(bsdf_pdf, aimed_pdf, aim);
        s.delta = lselect(s.delta, mask_of(false), aim);
        // eta2 only steers the roulette's survival chance, which any value
        // keeps unbiased; the BSDF's refraction factor is not known here.
        s.eta2 = lselect(s.eta2, (lfloat)(1.0f), aim);
    }
    // One density for both strategies, after the branch: on a GPU the two
    // sides of a warp then share this code instead of running it twice. A
    // lane without a direction (lost, or of density 0) carries nothing: its
    // path ends on the zero weight, whatever the rest of its sample says.
    const lmask mixed = mask_not(delta);
    if (lanes_step(mixed)) {
        const lfloat pdf = continuation_pdf(scene, p, bsdf_pdf, s.wi);
        const lmask valid = mask_and_not(pdf > 0.0f, lost);
        s.pdf = lselect(s.pdf, lselect((lfloat)(0.0f), pdf, valid), mixed);
        s.weight = lv3_select(s.weight, lv3_select(lv3_zero(), lv3_scale(f_cos, 1.0f / pdf), valid), mixed);
    }
    return s;
}
