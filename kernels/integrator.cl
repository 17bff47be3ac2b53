// The path tracer, written once over lanes (lanes.cl): a work-item renders
// ORB_LANES adjacent pixels of a row, one camera path per lane, looping over
// this pass's samples (docs/rendering.md gives the estimators and the exact
// meaning of depth, and "Lanes" how one text serves GPUs and CPUs).
// Materials enter only through the BSDF interface (bsdf.cl). Each step is
// masked: `lanes` or `active` says which lanes it applies to, and a step
// that no lane needs is skipped (`if (lanes_any(...))`), which at width 1 is
// the plain branch of a scalar path tracer.
//
// Depth counts scattering events (of any material) along a path from the
// camera: max_depth d admits paths whose light scattered at most d times
// before reaching the camera. The ray leaving scattering event d is still
// traced, for the emission it may hit (the BSDF half of the MIS pair at that
// vertex), but it scatters no further.
//
// A vertex is "non-delta" for a path when the path's light scattered there
// through a lobe with a density (diffuse, glossy, rough glass): next-event
// estimation there counts it, and so does the continuation when the sampled
// lobe was not a delta. Mirror and smooth-glass events are delta vertices.

// Russian roulette applies from scattering event RR_START_EVENT on (a
// kernel feature, kernel_features.h).
// A path whose throughput (refraction's scaling divided out) is at least
// this survives the roulette for sure; below it, it survives with
// probability throughput / RR_THRESHOLD. Chosen by time to equal error, not
// samples/s (docs/design/russian-roulette.md): with 1, caustic paths in the Cornell box
// (floor, then glass, then the light) were cut at every event with q = 0.75
// and came back 1/q brighter, doubling the variance per sample; with 0.25 a
// path survives until its throughput is small, which in these scenes is
// rarely before the depth limit.
// ORB_DRAW_ALL_NUMBERS is 1 on GPUs (kernel_features.h): a scattering
// event's random numbers are all drawn before the branches; 0 draws each
// only where used. The numbers are the same either way (each is a function
// of its block and slot); on a GPU, lanes at delta and non-delta vertices
// then hash together instead of in turn (3% more samples/s on the Cornell
// box, docs/design/sampler.md).

// A lane's row: with a list of active pixels (adaptive sampling) each lane
// has its own; otherwise the work-item's lanes share one.
#if ORB_ACTIVE_PIXELS
typedef lint PixelRow;
#define ROW_AS_FLOAT(y) to_lfloat(y)
#else
typedef int PixelRow;
#define ROW_AS_FLOAT(y) ((float)(y))
#endif

// The state of each lane's camera path between two ray casts.
typedef struct {
    lv3 o, d;      // the ray to cast next
    lint self;     // sphere the ray leaves (and the vertex it was sampled at), -1 for the camera
    lint depth;    // scattering events so far
    lv3 beta;      // path throughput
    lfloat eta2;   // product of the refractions' radiance factors inside beta
    lint nondelta_vertices;
    lmask albedo_set;
    // Where the ray was BSDF-sampled from, for MIS at an emitter it hits.
    lmask from_density;  // sampled from a lobe with a density (light sampling could have produced it)
    lfloat from_pdf;
    lv3 from_point;
} PathState;

// Starts, for the lanes in `lanes`, the camera path of each lane's sample
// (`coords`) of pixel (x, y) (RNG block 0: pair 0 jitters the pixel, pair 1,
// drawn only for a thin lens, the lens). The other lanes keep their state.
LANE_FN void begin_camera_paths(const CameraParams* cam, lint x, PixelRow y, int width, int height,
                                const SampleCoords* coords, lmask lanes, PathState* path, PathSample* out)
{
    const RandBlock r = rand_block(coords, (luint)(0u), lanes);
    lfloat jitter_x, jitter_y, lens_u = (lfloat)(0.5f), lens_v = (lfloat)(0.5f);
    rand_pair(&r, 0u, lanes, &jitter_x, &jitter_y);
    if (cam->lens_radius > 0.0f) rand_pair(&r, 1u, lanes, &lens_u, &lens_v);
    lv3 o, d;
    camera_ray(cam, to_lfloat(x) + jitter_x, ROW_AS_FLOAT(y) + jitter_y, width, height, lens_u, lens_v, &o, &d);
    path->o = lv3_select(path->o, o, lanes);
    path->d = lv3_select(path->d, d, lanes);
    path->self = lselect(path->self, (lint)(-1), lanes);
    path->depth = lselect(path->depth, (lint)(0), lanes);
    path->beta = lv3_select(path->beta, lv3_fill(1.0f), lanes);
    path->eta2 = lselect(path->eta2, (lfloat)(1.0f), lanes);
    path->nondelta_vertices = lselect(path->nondelta_vertices, (lint)(0), lanes);
    path->albedo_set = lselect(path->albedo_set, mask_of(false), lanes);
    path->from_density = lselect(path->from_density, mask_of(false), lanes);
    path->from_pdf = lselect(path->from_pdf, (lfloat)(0.0f), lanes);
    path->from_point = lv3_select(path->from_point, o, lanes);
    path_sample_clear(out, lanes);
}

// Entry `slot` of the lights table for each lane in `lanes` (what the other
// lanes get is unspecified).
LANE_FN void load_light(const SceneView* scene, lint slot, lmask lanes, lint* sphere, lfloat* probability,
                        lfloat* alias_threshold, lint* alias)
{
#if ORB_LANES == 1
    SCENE_MEM const LightRecord* entry = &scene->lights[slot];
    *sphere = entry->sphere;
    *probability = entry->probability;
    *alias_threshold = entry->alias_threshold;
    *alias = entry->alias;
#else
    *sphere = *alias = (lint)(0);
    *probability = *alias_threshold = (lfloat)(0.0f);
    if (scene->light_count > ORB_LANES_SELECT_GATHER_MAX) {
        ORB_FOR_EACH_LANE(l, lanes)
        {
            SCENE_MEM const LightRecord* entry = &scene->lights[lane_i(slot, l)];
            set_lane_i(*sphere, l, entry->sphere);
            set_lane_f(*probability, l, entry->probability);
            set_lane_f(*alias_threshold, l, entry->alias_threshold);
            set_lane_i(*alias, l, entry->alias);
        }
        return;
    }
    for (int k = 0; k < scene->light_count; ++k) {
        const lmask m = slot == k;
        if (!lanes_any(m)) continue;
        SCENE_MEM const LightRecord* entry = &scene->lights[k];
        *sphere = lselect(*sphere, (lint)(entry->sphere), m);
        *probability = lselect(*probability, (lfloat)(entry->probability), m);
        *alias_threshold = lselect(*alias_threshold, (lfloat)(entry->alias_threshold), m);
        *alias = lselect(*alias, (lint)(entry->alias), m);
    }
#endif
}

// Next-event estimation at non-delta vertices (the lanes in `lanes`): in
// direct mode from every light, else from one light picked from the alias
// table (spheres by power, the environment by its share; docs/rendering.md,
// "Picking a light"). Returns the radiance towards wo.
LANE_FN lv3 sample_lights(const SceneView* scene, lv3 p, lint self, const Bsdf* bsdf, lv3 wo, lv3 n, lmask outside,
                          lfloat u_pick, lfloat u_v, int mode, lmask lanes)
{
    const int light_count = scene->light_count;
    lv3 sum = lv3_zero();
    if (mode == IntegratorMode_Direct) {
        for (int i = 0; i < light_count; ++i)
            sum = lv3_add(sum, estimate_light(scene, (lint)(scene->lights[i].sphere), (lfloat)(1.0f), p, self, bsdf,
                                              wo, n, outside, u_pick, u_v, lanes));
        return sum;
    }
    if (light_count == 0) return sum;
    // One uniform number picks the light by power (the alias table) and,
    // rescaled to [0, 1) again, samples it.
    const lfloat scaled = u_pick * (float)light_count;
    const lint slot = min(to_lint(scaled), (lint)(light_count - 1));
    const lfloat rest = scaled - to_lfloat(slot);
    lint sphere, alias;
    lfloat probability, threshold;
    load_light(scene, slot, lanes, &sphere, &probability, &threshold, &alias);
#if ORB_UNIFORM_LIGHTS
    // Lights of equal power: the alias table is the identity, so skip it
    // (the same picks and pdfs, fewer loads; 2% on an H100).
    const lfloat u = fmin(rest, (lfloat)(0x1.fffffep-1f));
    return estimate_light(scene, sphere, (lfloat)(1.0f / (float)light_count), p, self, bsdf, wo, n, outside, u, u_v,
                          lanes);
#else
    // The slot's own light below its threshold, else its alias; what the
    // first read gave of the slot's light itself is left for the compiler
    // to drop.
    const lmask own = rest < threshold;
    const lfloat u = fmin(lselect((rest - threshold) / (1.0f - threshold), rest / threshold, own),
                          (lfloat)(0x1.fffffep-1f));
    load_light(scene, lselect(alias, slot, own), lanes, &sphere, &probability, &threshold, &alias);
    return estimate_light(scene, sphere, probability, p, self, bsdf, wo, n, outside, u, u_v, lanes);
#endif
}

// The BSDFs of the lanes in `lanes`, the others' none (kind -1), so that a
// BSDF call runs only the kinds these lanes have; `lobes` (ORB_LOBES_*)
// says which lanes they are, so the call's code holds only the kinds that
// can be among them. At width 1 the call is reached only for the lane's own
// kind anyway.
LANE_FN Bsdf bsdf_of_lanes(const Bsdf* b, lmask lanes, int lobes)
{
    Bsdf masked = *b;
    masked.lobes = lobes;
#if ORB_LANES > 1
    masked.kind = lselect((lint)(-1), b->kind, lanes);
#endif
    return masked;
}

// Casts each active lane's ray and handles what it hit: emission,
// next-event estimation, scattering. Returns the lanes whose paths go on.
LANE_FN lmask extend_paths(const SceneView* scene, PathState* path, PathSample* out, const SampleCoords* coords,
                           int max_depth, int mode, lmask active)
{
    lfloat t;
    lint id;
    lanes_intersect(scene, path->o, path->d, path->self, active, &t, &id);
    const lmask escaped = mask_and(active, id < 0);
    if (ORB_ENVIRONMENT && lanes_any(escaped)) {
        // Escaped: the environment's radiance (kernels/environment.cl). Alpha
        // stays 0: it is the coverage of spheres, so a render composites over
        // a plate once the background (the camera ray's escape) is taken out.
        const float env_pick_pdf = mode == IntegratorMode_Direct ? 1.0f : scene->environment.light_probability;
        const lv3 seen = lv3_mul(path->beta, escaped_radiance(scene, path->d, path->from_density, path->from_pdf,
                                                              env_pick_pdf, escaped));
        add_by_vertex_count(out, path->nondelta_vertices, seen, escaped);
        if (ORB_FILM_BUILT(background))
            out->background = lv3_select(out->background, seen, mask_and(escaped, path->depth == 0));
    }
    const lmask hit = mask_and(active, id >= 0);
    if (!lanes_any(hit)) return hit;
    const ShadingSphere m = load_sphere(scene, id, hit);
    const lv3 d = path->d;
    const lv3 p = lv3_add(path->o, lv3_scale(d, t));
    const lv3 outward = lv3_scale(lv3_sub(p, m.centre), 1.0f / m.radius);
    const lmask outside = lv3_dot(d, outward) < 0.0f;  // the ray arrives from outside the sphere
    const lv3 n = lv3_select(lv3_neg(outward), outward, outside);
    const lv3 wo = lv3_neg(d);
    const lmask first_hit = mask_and(hit, path->depth == 0);
    out->alpha = lselect(out->alpha, (lfloat)(1.0f), first_hit);
    if (ORB_FILM_BUILT(normal)) out->normal = lv3_select(out->normal, n, first_hit);

    const lmask emissive = mask_and(hit, lv3_sum(m.emission) > 0.0f);
    if (lanes_any(emissive)) {
        lfloat weight = (lfloat)(1.0f);  // after the camera or a delta lobe only this strategy exists
        const lmask weighed = mask_and(emissive, path->from_density);
        if (lanes_any(weighed)) {
            // Global mode picks one light per vertex by power; direct mode samples every light.
#if ORB_UNIFORM_LIGHTS
            const lfloat pick_pdf = (lfloat)(mode == IntegratorMode_Direct ? 1.0f : 1.0f / (float)scene->light_count);
#else
            const lfloat pick_pdf = mode == IntegratorMode_Direct ? (lfloat)(1.0f) : m.light_probability;
#endif
            const lfloat light_pdf =
                pick_pdf * light_direction_pdf(path->from_point, path->self, id, m.centre, m.radius);
            weight = lselect(weight, power_heuristic(path->from_pdf, light_pdf), weighed);
        }
        add_by_vertex_count(out, path->nondelta_vertices, lv3_scale(lv3_mul(path->beta, m.emission), weight),
                            emissive);
    }

    lmask go = mask_and(hit, path->depth < max_depth);
    // Direct mode: the ray after the first non-delta vertex was traced only for its emission.
    if (mode == IntegratorMode_Direct) go = mask_and(go, path->nondelta_vertices != 1);
    if (!lanes_any(go)) return go;

    // The numbers of this scattering event (block depth + 1). A vertex with
    // only delta lobes needs neither the light pair nor the direction pair
    // (its BSDF ignores u, v: bsdf_types.cl).
    const RandBlock r = rand_block(coords, to_luint(path->depth + 1), go);
    const lmask has_density = mask_and(go, bsdf_has_density(&m.bsdf));
    lfloat u_light, v_light, u_direction = (lfloat)(0.5f), v_direction = (lfloat)(0.5f), choice;
#if ORB_DRAW_ALL_NUMBERS
    lfloat u_drawn, v_drawn;
    rand_pair(&r, 0u, go, &u_light, &v_light);
    rand_pair(&r, 1u, go, &u_drawn, &v_drawn);
    choice = rand_single(&r, go);
#endif
    if (lanes_any(has_density)) {
        if (ORB_FILM_BUILT(albedo)) {
            const lmask first = mask_and_not(has_density, path->albedo_set);
            if (lanes_any(first)) {
                out->albedo = lv3_select(out->albedo, lv3_mul(path->beta, bsdf_albedo(&m.bsdf, wo, n)), first);
                path->albedo_set = mask_or(path->albedo_set, first);
            }
        }
#if !ORB_DRAW_ALL_NUMBERS
        rand_pair(&r, 0u, has_density, &u_light, &v_light);
#endif
        const Bsdf shading = bsdf_of_lanes(&m.bsdf, has_density, ORB_LOBES_DENSITY);
        const lv3 light_sample = lv3_mul(
            path->beta, sample_lights(scene, p, id, &shading, wo, n, outside, u_light, v_light, mode, has_density));
        add_by_vertex_count(out, path->nondelta_vertices + 1, light_sample, has_density);
#if ORB_DRAW_ALL_NUMBERS
        u_direction = lselect(u_direction, u_drawn, has_density);
        v_direction = lselect(v_direction, v_drawn, has_density);
#else
        rand_pair(&r, 1u, has_density, &u_direction, &v_direction);
#endif
    }

    // `choice` picks the strategy and the lobe, and comes back rescaled
    // (uniform again and independent of those picks) for the roulette below.
    // Where the BSDF has a density the direction comes from the
    // continuation's mixture, which also aims at glass and mirror balls
    // (caustic_casters.cl).
#if !ORB_DRAW_ALL_NUMBERS
    choice = rand_single(&r, go);
#endif
    BsdfSample bs = bsdf_no_sample();
    lfloat roulette = choice;
    if (lanes_any(has_density)) {
        const Bsdf shading = bsdf_of_lanes(&m.bsdf, has_density, ORB_LOBES_DENSITY);
        lfloat c = choice;
        bs = bsdf_sample_select(
            bs, sample_continuation(scene, &shading, p, wo, n, outside, u_direction, v_direction, &c), has_density);
        roulette = lselect(roulette, c, has_density);
    }
    const lmask delta_only = mask_and_not(go, has_density);
    if (lanes_any(delta_only)) {
        const Bsdf shading = bsdf_of_lanes(&m.bsdf, delta_only, ORB_LOBES_DELTA_ONLY);
        lfloat c = choice;
        bs = bsdf_sample_select(bs, bsdf_sample(&shading, wo, n, outside, u_direction, v_direction, &c), delta_only);
        roulette = lselect(roulette, c, delta_only);
    }
    lv3 beta = lv3_mul(path->beta, bs.weight);
    const lfloat beta_max = lv3_max(beta);
    lmask alive = mask_and(go, beta_max > 0.0f);
    const lfloat eta2 = path->eta2 * bs.eta2;
    // Survive with probability q and divide by q: unbiased. The radiance
    // scaling of refraction is divided out of q (as pbrt-v4's etaScale):
    // inside glass beta carries (1/1.5)^2, which is no loss of energy, and
    // paths there would otherwise die 2.25 times too often.
    const lmask roulette_lanes = mask_and(alive, path->depth + 1 >= RR_START_EVENT);
    if (lanes_step(roulette_lanes)) {
        const lfloat q = fmin((lfloat)(1.0f), beta_max / (eta2 * RR_THRESHOLD));
        alive = mask_and(alive, mask_or(mask_not(roulette_lanes), roulette < q));
        beta = lv3_select(beta, lv3_scale(beta, 1.0f / q), roulette_lanes);
    }
    path->beta = lv3_select(path->beta, beta, alive);
    path->eta2 = lselect(path->eta2, eta2, alive);
    path->nondelta_vertices =
        lselect(path->nondelta_vertices, path->nondelta_vertices + 1, mask_and_not(alive, bs.delta));
    path->from_density = lselect(path->from_density, mask_not(bs.delta), alive);
    path->from_pdf = lselect(path->from_pdf, bs.pdf, alive);
    path->from_point = lv3_select(path->from_point, p, alive);
    path->o = lv3_select(path->o, p, alive);
    path->d = lv3_select(path->d, bs.wi, alive);
    path->self = lselect(path->self, id, alive);
    path->depth = lselect(path->depth, path->depth + 1, alive);
    return alive;
}

// The centre-ray channels of one pixel: not averages, but what the ray
// through the pixel centre and the lens centre hits. Per pixel at every
// width, so they do not depend on it.
inline FilmCentre film_centre_ray(const SceneView* scene, const CameraParams* cam, int x, int y, int width,
                                  int height)
{
    CameraParams pinhole = *cam;
    pinhole.lens_radius = 0.0f;
    float3 o, d;
    camera_ray_scalar(&pinhole, (float)x + 0.5f, (float)y + 0.5f, width, height, 0.0f, 0.0f, &o, &d);
    const Hit hit = intersect_scene(scene, o, d, -1);
    FilmCentre centre;
    // The distance by one test of the hit sphere, not the traversal's own:
    // fast math lets the compiler round the traversal's inlined copies of
    // the test differently in a program with the tree and one without (the
    // GPU variant on PoCL differed by up to 2e-4 relative on the 1e4 floor,
    // where the root cancels), and the depth must not depend on the tree.
    centre.depth = hit.id < 0 ? INFINITY : sphere_distance(scene, hit.id, o, d, -1);
    // The tables are in BVH order; the id pass names the scene's sphere.
    centre.object_id = hit.id < 0 ? -1.0f : (float)scene->spheres[hit.id].scene_index;
    return centre;
}

// The signature is generated from ORB_RENDER_PASS_ARGUMENTS (device_types.h),
// the list the host binds from: film buffers (one per row of the channel
// table), scene tables, then the parameters.
#define ORB_KERNEL_FILM_ARG(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    __global ORB_FILM_ELEMENT_##accumulate* film_##name,
#define ORB_KERNEL_TABLE_ARG(type, name) SCENE_MEM const type* name,
#define ORB_KERNEL_PARAMS_ARG(type, name) type name
// Inside a kernel with those arguments (render_pass, trace_rays):
// declares `scene`, the SceneView of its tables and counts.
#define ORB_SCENE_VIEW_SET_TABLE(type, name) scene.name = name;
#define ORB_SCENE_VIEW_OF_ARGUMENTS                                                                  \
    SceneView scene;                                                                                 \
    ORB_RENDER_PASS_ARGUMENTS(ORB_SCENE_VIEW_FILM, ORB_SCENE_VIEW_SET_TABLE, ORB_SCENE_VIEW_PARAMS) \
    scene.packet_count = params.scene.packet_count;                                                  \
    scene.sphere_count = params.scene.sphere_count;                                                  \
    scene.light_count = params.scene.light_count;                                                    \
    scene.outside_packet_count = params.scene.outside_packet_count;                                  \
    scene.bvh_node_count = params.scene.bvh_node_count;                                              \
    scene.caster_count = params.scene.caster_count;                                                  \
    scene.environment = params.environment;
__kernel void render_pass(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                          __global const uint* active_pixels)
{
    const int width = params.settings.width;
    const int height = params.settings.height;
#if ORB_ACTIVE_PIXELS
    // Adaptive sampling: work-item i renders entries i * ORB_LANES ... of the
    // list of pixels still sampling (device_types.h), one a lane, so that the
    // lanes and warps stay full however few pixels are left. The list is
    // ascending: its padding comes last, and neighbouring entries are mostly
    // neighbouring pixels.
    const uint entry = (uint)get_global_id(0) * ORB_LANES;
    if (active_pixels[entry] == ORB_NO_PIXEL) return;
    luint pixels = (luint)(0u);
    lint x = (lint)(0);
    PixelRow y = (lint)(0);
    lmask listed = mask_of(false);
    for (int lane = 0; lane < ORB_LANES; ++lane) {
        const uint p = active_pixels[entry + lane];
        if (p == ORB_NO_PIXEL) continue;
        set_lane_i(pixels, lane, p);
        set_lane_i(x, lane, (int)(p % (uint)width));
        set_lane_i(y, lane, (int)(p / (uint)width));
        set_lane_i(listed, lane, -1);  // a mask's true: -1 in a vector lane, true at width 1
    }
#else
    const int x0 = (int)get_global_id(0) * ORB_LANES;
    const int y = get_global_id(1);
    if (x0 >= width || y >= height) return;
#endif

    ORB_SCENE_VIEW_OF_ARGUMENTS

    const CameraParams cam = params.camera;
    const uint2 seed = (uint2)(params.settings.seed_lo, params.settings.seed_hi);
    const int max_depth = params.settings.max_depth;
    const int mode = params.settings.mode;
    const int sample_count = params.pass.sample_count;
#if !ORB_ACTIVE_PIXELS
    // This work-item's pixels: lanes past the image's right edge have none.
    const int lanes_in_image = min(ORB_LANES, width - x0);
#endif

    // The centre-ray channels first, on the pass that writes them. Cast after
    // the sample loop, as it once was, NVIDIA's driver 580 faulted (OpenCL
    // error -36) in most renders of a scene with a tree that built the depth
    // or id channel and let paths reach a third scattering event, at every
    // register cap but one; cast before the loop, never
    // (docs/design/nvidia-fault-36.md).
    if ((ORB_FILM_BUILT(depth) || ORB_FILM_BUILT(object_id)) && params.pass.write_centre_ray) {
#if ORB_ACTIVE_PIXELS
        ORB_FOR_EACH_LANE(lane, listed)
        {
            const uint pixel = (uint)lane_i(pixels, lane);
            const FilmCentre centre =
                film_centre_ray(&scene, &cam, lane_i(x, lane), lane_i(y, lane), width, height);
            ORB_FILM_SET_CENTRE
        }
#else
        for (int lane = 0; lane < lanes_in_image; ++lane) {
            const uint pixel = (uint)y * (uint)width + (uint)(x0 + lane);
            const FilmCentre centre = film_centre_ray(&scene, &cam, x0 + lane, y, width, height);
            ORB_FILM_SET_CENTRE
        }
#endif
    }

#if ORB_ACTIVE_PIXELS
    luint pixel_key = pixels;
    for (int lane = 0; lane < ORB_LANES; ++lane)
        set_lane_i(pixel_key, lane, sampler_pixel_key((uint)lane_i(pixels, lane), seed));
#else
    const lint x = (lint)(x0) + lane_index();
    const luint pixels = (luint)((uint)y * (uint)width) + to_luint(x);
    luint pixel_key = pixels;
    for (int lane = 0; lane < ORB_LANES; ++lane)
        set_lane_i(pixel_key, lane, sampler_pixel_key((uint)(y * width + x0 + lane), seed));
#endif

    FilmSums sums;
    film_sums_clear(&sums);

    // Path regeneration: one flat loop of ray casts, where a lane whose path
    // ends starts its pixel's next sample at once. On GPUs the threads of a
    // warp then stay busy casting rays instead of waiting for the longest
    // path of the group to end before all start their next sample; on CPUs
    // the vector lanes do.
    PathState path;
    PathSample s;
    path.o = path.d = path.beta = path.from_point = lv3_zero();
    path.self = path.depth = path.nondelta_vertices = (lint)(0);
    path.albedo_set = path.from_density = mask_of(false);
    path.eta2 = path.from_pdf = (lfloat)(0.0f);
    path_sample_clear(&s, mask_of(true));
    luint index = (luint)(0u);
#if ORB_ACTIVE_PIXELS
    lmask active = mask_and(listed, mask_of(sample_count > 0));
#else
    lmask active = mask_and(x < width, mask_of(sample_count > 0));
#endif
    const uint first_lo = params.pass.first_sample_lo, first_hi = params.pass.first_sample_hi;
    SampleCoords coords = sample_coords(pixel_key, pixels, first_lo, first_hi, index, seed);
    if (lanes_any(active)) begin_camera_paths(&cam, x, y, width, height, &coords, active, &path, &s);
    while (lanes_any(active)) {
        const lmask alive = extend_paths(&scene, &path, &s, &coords, max_depth, mode, active);
        const lmask done = mask_and_not(active, alive);
        active = alive;
        if (!lanes_any(done)) continue;
        film_add_sample(&sums, &s, done);
        index = lselect(index, index + 1u, done);
        const lmask next = mask_and(done, index < (luint)(sample_count));
        if (lanes_any(next)) {
            const SampleCoords fresh = sample_coords(pixel_key, pixels, first_lo, first_hi, index, seed);
            coords.sample_lo = lselect(coords.sample_lo, fresh.sample_lo, next);
            coords.sample_hi = lselect(coords.sample_hi, fresh.sample_hi, next);
#if ORB_SAMPLER_SOBOL
            coords.key = lselect(coords.key, fresh.key, next);
            coords.i_reversed = lselect(coords.i_reversed, fresh.i_reversed, next);
#endif
            begin_camera_paths(&cam, x, y, width, height, &coords, next, &path, &s);
            active = mask_or(active, next);
        }
    }
    // Each channel's sums to a variable of its own, read lane by lane (film.cl).
    ORB_FILM_COPY_SUMS
#if ORB_ACTIVE_PIXELS
    ORB_FOR_EACH_LANE(lane, listed)
    {
        const uint pixel = (uint)lane_i(pixels, lane);
        ORB_FILM_ADD_SUMS
    }
#else
    for (int lane = 0; lane < lanes_in_image; ++lane) {
        const uint pixel = (uint)y * (uint)width + (uint)(x0 + lane);
        ORB_FILM_ADD_SUMS
    }
#endif
}
