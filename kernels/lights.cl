// Sphere lights: every sphere with non-zero emission. Emission is radiance,
// emitted from both sides of the surface.
//
// A light is sampled by direction from the shading point p:
//  * p outside the sphere: uniformly inside the cone the sphere subtends,
//    pdf = 1 / (2 pi (1 - cos theta_max)), sin theta_max = r / |c - p|;
//  * p inside the sphere or on its surface (self == light), e.g. under a sky
//    dome or inside an emitting enclosure: uniformly over all directions,
//    pdf = 1 / (4 pi).
// light_direction_pdf() gives the same density for a direction reached by BSDF
// sampling, for multiple importance sampling; both use the same test.

LANE_FN lmask light_surrounds(lv3 p, lint self, lint light_id, lv3 centre, lfloat radius)
{
    const lv3 pc = lv3_sub(centre, p);
    return mask_or(self == light_id, lv3_dot(pc, pc) <= radius * radius);
}

LANE_FN lfloat light_direction_pdf(lv3 p, lint self, lint light_id, lv3 centre, lfloat radius)
{
    const lv3 pc = lv3_sub(centre, p);
    return lselect(1.0f / (2.0f * ORB_PI * cone_one_minus_cos(lv3_dot(pc, pc), radius)), (lfloat)(ORB_INV_4PI),
                   light_surrounds(p, self, light_id, centre, radius));
}

LANE_FN lv3 sample_light_direction(lv3 p, lint self, lint light_id, lv3 centre, lfloat radius, lfloat u, lfloat v,
                                   lfloat* pdf)
{
    const lmask surrounds = light_surrounds(p, self, light_id, centre, radius);
    const lv3 pc = lv3_sub(centre, p);
    const lfloat distance2 = lv3_dot(pc, pc);
    const lfloat one_minus_cos_max = cone_one_minus_cos(distance2, radius);
    *pdf = lselect(1.0f / (2.0f * ORB_PI * one_minus_cos_max), (lfloat)(ORB_INV_4PI), surrounds);
    lv3 wi = lv3_zero();
    if (lanes_step(surrounds)) wi = sample_uniform_sphere(u, v);
    const lmask cone = mask_not(surrounds);
    if (lanes_step(cone))
        wi = lv3_select(wi, sample_uniform_cone(lv3_scale(pc, rsqrt(distance2)), one_minus_cos_max, u, v), cone);
    return wi;
}

// Next-event estimate at a point p with a density-carrying BSDF (wo towards
// the viewer, n the normal on wo's side) from one light chosen with
// probability `pick_pdf`, weighted against BSDF sampling by the power
// heuristic, for the lanes in `lanes`. Visibility: the first thing the
// shadow ray hits must be the light itself (nothing else before the light's
// own distance along the ray, found by the same sphere test), so no epsilon
// is needed.
LANE_FN lv3 estimate_direct_light(const SceneView* scene, lint light_id, lfloat pick_pdf, lv3 p, lint self,
                                  const Bsdf* bsdf, lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lmask lanes)
{
    const EmitterSphere light = load_emitter(scene, light_id, lanes);
    lfloat direction_pdf;
    const lv3 wi = sample_light_direction(p, self, light_id, light.centre, light.radius, u, v, &direction_pdf);
    lfloat bsdf_pdf;
    const lv3 f_cos = bsdf_eval(bsdf, wo, wi, n, outside, &bsdf_pdf);
    // Nothing to carry (below the surface, outside every lobe, or black): no shadow ray.
    lmask carries = mask_and(lanes, lv3_sum(f_cos) > 0.0f);
    if (!lanes_any(carries)) return lv3_zero();
    carries = mask_and(carries, lanes_light_visible(scene, p, wi, self, light_id, carries));
    if (!lanes_any(carries)) return lv3_zero();
    const lfloat light_pdf = pick_pdf * direction_pdf;
    // BSDF sampling's side of the pair is the continuation's mixture (caustic_casters.cl).
    const lfloat weight = power_heuristic(light_pdf, continuation_pdf(scene, p, bsdf_pdf, wi));
    return lv3_select(lv3_zero(), lv3_scale(lv3_mul(light.emission, f_cos), weight / light_pdf), carries);
}
