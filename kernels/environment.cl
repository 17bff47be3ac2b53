// The environment light (docs/rendering.md, "Environment"): radiance from
// infinitely far away, looked up by direction in a latitude-longitude map of
// EnvironmentParams.width x height texels (a uniform colour is a map of one
// texel), and sampled by texel with the tables of librender's
// environment_distribution.h.
//
// Orientation (docs/scene-format.md, "Environment"): in the map's frame the
// top row is +y, the centre column faces +x, the column a quarter of the
// width to its right faces +z and a quarter to its left -z (Blender's layout,
// with Blender's +z up and -y front taken to +y up and +z front as its glTF
// exporter does). A direction m in that frame has
//   u = 1/2 + atan2(m.z, m.x) / (2 pi)  (column: u * width),
//   v = acos(m.y) / pi                  (row: v * height, from the top).
// The map's frame is the world turned about +y by rotation_deg
// (right-handed: the centre column faces (cos a, 0, -sin a)).
//
// Texels are constant over their area (no filtering), so the sampling
// density, proportional to each texel's radiance times its solid angle and
// uniform in solid angle inside it, follows the radiance exactly.

// ORB_ENVIRONMENT 0 leaves the environment's code out: the host builds such
// a program for a scene without an environment.
inline bool has_environment(const SceneView* scene) { return ORB_ENVIRONMENT && scene->environment.width > 0; }

// World -> map frame: the inverse turn about +y.
inline float3 environment_to_map(const SceneView* scene, float3 d)
{
    const float c = scene->environment.rotation.x, s = scene->environment.rotation.y;
    return (float3)(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

// Map frame -> world: the turn about +y by rotation_deg.
inline float3 environment_from_map(const SceneView* scene, float3 m)
{
    const float c = scene->environment.rotation.x, s = scene->environment.rotation.y;
    return (float3)(c * m.x + s * m.z, m.y, -s * m.x + c * m.z);
}

// The texel that direction d (any length) falls in, as row * width + column.
inline int environment_texel_of(const SceneView* scene, float3 d)
{
    const int width = scene->environment.width, height = scene->environment.height;
    const float3 m = environment_to_map(scene, d);
    const float u = 0.5f + atan2(m.z, m.x) * (0.5f * ORB_INV_PI);
    const float v = acos(clamp(m.y * rsqrt(dot(m, m)), -1.0f, 1.0f)) * ORB_INV_PI;
    const int column = clamp((int)(u * (float)width), 0, width - 1);
    const int row = clamp((int)(v * (float)height), 0, height - 1);
    return row * width + column;
}

// xyz: the radiance arriving from direction d; w: the solid-angle density
// with which sample_environment produces d.
inline float4 environment_lookup(const SceneView* scene, float3 d)
{
    return scene->environment_texels[environment_texel_of(scene, d)].radiance_pdf;
}

// The first of n cumulative probabilities that exceeds u (the host's twin is
// sample_environment_texel in librender/src/environment_distribution.cpp).
inline int environment_search(SCENE_MEM const EnvironmentCdf* cdf, int n, float u)
{
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        const int mid = (lo + hi) >> 1;
        if (cdf[mid].upper > u)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

// Where u lies inside entry k's interval, rescaled to [0, 1): the position
// inside the chosen row or column.
inline float environment_remainder(SCENE_MEM const EnvironmentCdf* cdf, int k, float u)
{
    const float lo = k > 0 ? cdf[k - 1].upper : 0.0f;
    return fmin((u - lo) / (cdf[k].upper - lo), 0x1.fffffep-1f);
}

// A direction towards the environment, drawn by the 2D distribution: u picks
// the row, v the column, and what is left of each places the direction
// inside the texel, uniformly in solid angle (cos theta uniform between the
// row's bounds, phi uniform across the column). *texel receives the texel's
// radiance and density (EnvironmentTexel.radiance_pdf).
inline float3 sample_environment(const SceneView* scene, float u, float v, float4* texel)
{
    const int width = scene->environment.width, height = scene->environment.height;
    SCENE_MEM const EnvironmentCdf* rows = scene->environment_cdf;
    const int row = environment_search(rows, height, u);
    const float in_row = environment_remainder(rows, row, u);
    SCENE_MEM const EnvironmentCdf* columns = rows + height + row * width;
    const int column = environment_search(columns, width, v);
    const float in_column = environment_remainder(columns, column, v);

    // cos(pi * k / height) is the x of unit_circle(k / (2 height)).
    const float inv_2h = 0.5f / (float)height;
    const float cos_top = unit_circle((float)row * inv_2h).x;
    const float cos_bottom = unit_circle((float)(row + 1) * inv_2h).x;
    const float cos_theta = cos_top + in_row * (cos_bottom - cos_top);
    const float sin_theta = sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta));
    // phi = 2 pi u - pi from +x towards +z: (cos phi, sin phi) = -unit_circle(u).
    const float2 cs = unit_circle(((float)column + in_column) / (float)width);
    *texel = scene->environment_texels[row * width + column].radiance_pdf;
    return environment_from_map(scene, (float3)(-sin_theta * cs.x, cos_theta, -sin_theta * cs.y));
}

// Next-event estimate at a point p with a density-carrying BSDF (wo towards
// the viewer, n the normal on wo's side; the interface of kernels/bsdf.cl)
// from the environment, chosen with probability `pick_pdf`, weighted against
// BSDF sampling by the power heuristic, for the lanes in `lanes` (over lanes:
// the map's searches lane by lane, the rest for all at once). The shadow ray
// must escape: it may hit nothing at all (light -1).
LANE_FN lv3 estimate_environment_light(const SceneView* scene, lfloat pick_pdf, lv3 p, lint self, const Bsdf* bsdf,
                                       lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lmask lanes)
{
    lv3 wi = lv3_zero(), radiance = lv3_zero();
    lfloat texel_pdf = (lfloat)(0.0f);
    ORB_FOR_EACH_LANE(l, lanes)
    {
        float4 texel;
        set_lane_v3(wi, l, sample_environment(scene, lane_f(u, l), lane_f(v, l), &texel));
        set_lane_v3(radiance, l, texel.xyz);
        set_lane_f(texel_pdf, l, texel.w);
    }
    lmask carries = mask_and(lanes, texel_pdf > 0.0f);
    if (!lanes_any(carries)) return lv3_zero();
    lfloat bsdf_pdf;
    const lv3 f_cos = bsdf_eval(bsdf, wo, wi, n, outside, &bsdf_pdf);
    // Nothing to carry (below the surface, outside every lobe, or black): no shadow ray.
    carries = mask_and(carries, lv3_sum(f_cos) > 0.0f);
    if (!lanes_any(carries)) return lv3_zero();
    carries = mask_and(carries, lanes_light_visible(scene, p, wi, self, (lint)(-1), carries));
    if (!lanes_any(carries)) return lv3_zero();
    const lfloat light_pdf = pick_pdf * texel_pdf;
    const lfloat weight = power_heuristic(light_pdf, continuation_pdf(scene, p, bsdf_pdf, wi));
    return lv3_select(lv3_zero(), lv3_scale(lv3_mul(radiance, f_cos), weight / light_pdf), carries);
}

// Next-event estimate from one light of the lights table for each lane in
// `lanes`: an emissive sphere, or the environment (LightRecord.sphere -1).
LANE_FN lv3 estimate_light(const SceneView* scene, lint light_sphere, lfloat pick_pdf, lv3 p, lint self,
                           const Bsdf* bsdf, lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lmask lanes)
{
    lv3 sum = lv3_zero();
    lmask spheres = lanes;
    if (ORB_ENVIRONMENT) {
        const lmask environment = mask_and(lanes, light_sphere < 0);
        spheres = mask_and_not(lanes, environment);
        if (lanes_any(environment))
            sum = estimate_environment_light(scene, pick_pdf, p, self, bsdf, wo, n, outside, u, v, environment);
    }
    if (lanes_any(spheres))
        sum = lv3_add(sum, estimate_direct_light(scene, light_sphere, pick_pdf, p, self, bsdf, wo, n, outside, u, v,
                                                 spheres));
    return sum;
}

// Radiance a ray that left the scene in direction d brings back, for the
// lanes in `lanes`, weighted by multiple importance sampling when it was
// sampled from a lobe with a density (the other strategy being
// estimate_environment_light there, with the same pdfs); weight 1 from the
// camera or after a delta lobe. `pick_pdf` is the chance the light sampler
// picks the environment.
LANE_FN lv3 escaped_radiance(const SceneView* scene, lv3 d, lmask from_density, lfloat from_pdf, float pick_pdf,
                             lmask lanes)
{
    if (!has_environment(scene)) return lv3_zero();
    lv3 radiance = lv3_zero();
    lfloat pdf = (lfloat)(0.0f);
    ORB_FOR_EACH_LANE(l, lanes)
    {
        const float4 e = environment_lookup(scene, lane_v3(d, l));
        set_lane_v3(radiance, l, e.xyz);
        set_lane_f(pdf, l, e.w);
    }
    const lfloat weight = lselect((lfloat)(1.0f), power_heuristic(from_pdf, pick_pdf * pdf), from_density);
    return lv3_scale(radiance, weight);
}
