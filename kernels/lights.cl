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

inline bool light_surrounds(float3 p, int self, int light_id, float3 centre, float radius)
{
    const float3 pc = centre - p;
    return self == light_id || dot(pc, pc) <= radius * radius;
}

inline float light_direction_pdf(float3 p, int self, int light_id, float3 centre, float radius)
{
    if (light_surrounds(p, self, light_id, centre, radius)) return ORB_INV_4PI;
    const float3 pc = centre - p;
    return 1.0f / (2.0f * ORB_PI * cone_one_minus_cos(dot(pc, pc), radius));
}

inline float3 sample_light_direction(float3 p, int self, int light_id, float3 centre, float radius, float u,
                                     float v, float* pdf)
{
    if (light_surrounds(p, self, light_id, centre, radius)) {
        *pdf = ORB_INV_4PI;
        return sample_uniform_sphere(u, v);
    }
    const float3 pc = centre - p;
    const float distance2 = dot(pc, pc);
    const float one_minus_cos_max = cone_one_minus_cos(distance2, radius);
    *pdf = 1.0f / (2.0f * ORB_PI * one_minus_cos_max);
    return sample_uniform_cone(pc * rsqrt(distance2), one_minus_cos_max, u, v);
}

// Next-event estimate at a point p with a density-carrying BSDF (wo towards
// the viewer, n the normal on wo's side) from one light chosen with
// probability `pick_pdf`, weighted against BSDF sampling by the power
// heuristic. Visibility: the first thing the shadow ray hits must be the light
// itself (nothing else before the light's own distance along the ray, found by
// the same sphere test), so no epsilon is needed.
inline float3 estimate_direct_light(const SceneView* scene, int light_id, float pick_pdf, float3 p, int self,
                                    const Bsdf* bsdf, float3 wo, float3 n, bool outside, float u, float v)
{
    const ShadingSphere light = load_sphere(scene, light_id);
    float direction_pdf;
    const float3 wi = sample_light_direction(p, self, light_id, light.centre, light.radius, u, v, &direction_pdf);
    float bsdf_pdf;
    const float3 f_cos = bsdf_eval(bsdf, wo, wi, n, outside, &bsdf_pdf);
    // Nothing to carry (below the surface, outside every lobe, or black): no shadow ray.
    if (!(f_cos.x + f_cos.y + f_cos.z > 0.0f)) return (float3)(0.0f);
    if (!light_visible(scene, p, wi, self, light_id)) return (float3)(0.0f);
    const float light_pdf = pick_pdf * direction_pdf;
    // BSDF sampling's side of the pair is the continuation's mixture (caustic_casters.cl).
    const float weight = power_heuristic(light_pdf, continuation_pdf(scene, p, bsdf_pdf, wi));
    return light.emission * f_cos * (weight / light_pdf);
}
