// The path tracer: one work-item per pixel, looping over this pass's samples
// (docs/rendering.md gives the estimators and the exact meaning of depth).
// Materials enter only through the BSDF interface (bsdf.cl).
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

typedef struct {
    float3 emission;  // paths with no non-delta vertex (emitters seen directly or through specular chains)
    float3 direct;    // paths with exactly one non-delta vertex
    float3 indirect;  // paths with two or more non-delta vertices
    float3 albedo;    // specular tints times the reflectance of the first non-delta vertex
    float3 normal;    // normal at the first hit, facing the camera ray
    float3 background;  // the environment's radiance when the camera ray hit nothing
    float alpha;      // 1 when the camera ray hit something
} PathSample;

inline void add_by_vertex_count(PathSample* s, int nondelta_vertices, float3 contribution)
{
    if (nondelta_vertices == 0)
        s->emission += contribution;
    else if (nondelta_vertices == 1)
        s->direct += contribution;
    else
        s->indirect += contribution;
}

// The state of one camera path between two ray casts.
typedef struct {
    float3 o, d;     // the ray to cast next
    int self;        // sphere the ray leaves, -1 for the camera
    int depth;       // scattering events so far
    float3 beta;     // path throughput
    float eta2;      // product of the refractions' radiance factors inside beta
    int nondelta_vertices;
    bool albedo_set;
    // Where the ray was BSDF-sampled from, for MIS at an emitter it hits.
    bool from_density;  // sampled from a lobe with a density (light sampling could have produced it)
    float from_pdf;
    float3 from_point;
    int from_self;
} PathState;

inline void begin_path(PathState* path, PathSample* out, float3 o, float3 d)
{
    path->o = o;
    path->d = d;
    path->self = -1;
    path->depth = 0;
    path->beta = (float3)(1.0f);
    path->eta2 = 1.0f;
    path->nondelta_vertices = 0;
    path->albedo_set = false;
    path->from_density = false;
    path->from_pdf = 0.0f;
    path->from_point = o;
    path->from_self = -1;
    out->emission = out->direct = out->indirect = out->albedo = out->normal = out->background = (float3)(0.0f);
    out->alpha = 0.0f;
}

// Starts the camera path of sample `coords` of pixel (x, y) (RNG block 0:
// pair 0 jitters the pixel, pair 1, drawn only for a thin lens, the lens).
inline void begin_camera_path(const CameraParams* cam, int x, int y, int width, int height,
                              const SampleCoords* coords, PathState* path, PathSample* out)
{
    const RandBlock r = rand_block(coords, 0u);
    const float2 jitter = rand_pair(&r, 0u);
    const float2 lens = cam->lens_radius > 0.0f ? rand_pair(&r, 1u) : (float2)(0.5f);
    float3 o, d;
    camera_ray(cam, (float)x + jitter.x, (float)y + jitter.y, width, height, lens.x, lens.y, &o, &d);
    begin_path(path, out, o, d);
}

// Next-event estimation at a non-delta vertex: in direct mode from every
// light, else from one light picked from the alias table (spheres by power,
// the environment by its share; docs/rendering.md, "Picking a light").
// Returns the radiance towards wo.
inline float3 sample_lights(const SceneView* scene, float3 p, int self, const Bsdf* bsdf, float3 wo, float3 n,
                            bool outside, float2 u_light, int mode)
{
    const int light_count = scene->light_count;
    float3 sum = (float3)(0.0f);
    if (mode == IntegratorMode_Direct) {
        for (int i = 0; i < light_count; ++i)
            sum += estimate_light(scene, scene->lights[i].sphere, 1.0f, p, self, bsdf, wo, n, outside, u_light.x,
                                  u_light.y);
        return sum;
    }
    if (light_count == 0) return sum;
    // One uniform number picks the light by power (the alias table) and,
    // rescaled to [0, 1) again, samples it.
    const float scaled = u_light.x * (float)light_count;
    const int slot = min((int)scaled, light_count - 1);
#if ORB_UNIFORM_LIGHTS
    // Lights of equal power: the alias table is the identity, so skip it
    // (the same picks and pdfs, fewer loads; 2% on an H100).
    const float u = fmin(scaled - (float)slot, 0x1.fffffep-1f);
    return estimate_light(scene, scene->lights[slot].sphere, 1.0f / (float)light_count, p, self, bsdf, wo, n, outside,
                          u, u_light.y);
#else
    const float rest = scaled - (float)slot;
    SCENE_MEM const LightRecord* entry = &scene->lights[slot];
    const bool own = rest < entry->alias_threshold;
    const int pick = own ? slot : entry->alias;
    const float u = fmin(own ? rest / entry->alias_threshold
                             : (rest - entry->alias_threshold) / (1.0f - entry->alias_threshold),
                         0x1.fffffep-1f);
    SCENE_MEM const LightRecord* light = &scene->lights[pick];
    return estimate_light(scene, light->sphere, light->probability, p, self, bsdf, wo, n, outside, u, u_light.y);
#endif
}

// Handles what the path's ray hit: emission, next-event estimation,
// scattering. Returns false when the path has ended.
inline bool follow_hit(const SceneView* scene, PathState* path, PathSample* out, const SampleCoords* coords,
                       Hit hit, int max_depth, int mode)
{
    if (hit.id < 0) {
        // Escaped: the environment's radiance (kernels/environment.cl). Alpha
        // stays 0: it is the coverage of spheres, so a render composites over
        // a plate once the background (the camera ray's escape) is taken out.
        const float env_pick_pdf = mode == IntegratorMode_Direct ? 1.0f : scene->environment.light_probability;
        const float3 seen =
            path->beta * escaped_radiance(scene, path->d, path->from_density, path->from_pdf, env_pick_pdf);
        add_by_vertex_count(out, path->nondelta_vertices, seen);
        if (ORB_FILM_BUILT(background) && path->depth == 0) out->background = seen;
        return false;
    }
    const ShadingSphere m = load_sphere(scene, hit.id);
    const float3 d = path->d;
    const float3 p = path->o + hit.t * d;
    const float3 outward = (p - m.centre) * (1.0f / m.radius);
    const bool outside = dot(d, outward) < 0.0f;  // the ray arrives from outside the sphere
    const float3 n = outside ? outward : -outward;
    const float3 wo = -d;
    const int depth = path->depth;
    if (depth == 0) {
        out->alpha = 1.0f;
        if (ORB_FILM_BUILT(normal)) out->normal = n;
    }

    if (m.emission.x + m.emission.y + m.emission.z > 0.0f) {
        float weight = 1.0f;  // after the camera or a delta lobe only this strategy exists
        if (path->from_density) {
            // Global mode picks one light per vertex by power; direct mode samples every light.
#if ORB_UNIFORM_LIGHTS
            const float pick_pdf = mode == IntegratorMode_Direct ? 1.0f : 1.0f / (float)scene->light_count;
#else
            const float pick_pdf = mode == IntegratorMode_Direct ? 1.0f : scene->spheres[hit.id].light_probability;
#endif
            const float light_pdf =
                pick_pdf * light_direction_pdf(path->from_point, path->from_self, hit.id, m.centre, m.radius);
            weight = power_heuristic(path->from_pdf, light_pdf);
        }
        add_by_vertex_count(out, path->nondelta_vertices, path->beta * m.emission * weight);
    }

    if (depth == max_depth) return false;
    // Direct mode: the ray after the first non-delta vertex was traced only for its emission.
    if (mode == IntegratorMode_Direct && path->nondelta_vertices == 1) return false;

    // The numbers of this scattering event (block depth + 1). A vertex with
    // only delta lobes needs neither the light pair nor the direction pair
    // (its BSDF ignores u, v: bsdf_types.cl); CPUs draw them only where
    // used. GPUs draw all of them in every lane before the branches: the
    // numbers are the same (each is a function of its block and slot), and
    // lanes at delta and non-delta vertices hash together instead of in
    // turn (3% more samples/s on the Cornell box, docs/design/sampler.md).
    const RandBlock r = rand_block(coords, (uint)(depth + 1));
    const bool has_density = bsdf_has_density(&m.bsdf);
#if ORB_DRAW_ALL_NUMBERS
    const float2 u_light = rand_pair(&r, 0u);
    const float2 u_drawn = rand_pair(&r, 1u);
    float choice = rand_single(&r);
#define ORB_LIGHT_PAIR u_light
#define ORB_DIRECTION_PAIR u_drawn
#else
#define ORB_LIGHT_PAIR rand_pair(&r, 0u)
#define ORB_DIRECTION_PAIR rand_pair(&r, 1u)
#endif
    float2 u_direction = (float2)(0.5f);
    if (has_density) {
        if (ORB_FILM_BUILT(albedo) && !path->albedo_set) {
            out->albedo = path->beta * bsdf_albedo(&m.bsdf, wo, n);
            path->albedo_set = true;
        }
        const float3 light_sample =
            path->beta * sample_lights(scene, p, hit.id, &m.bsdf, wo, n, outside, ORB_LIGHT_PAIR, mode);
        add_by_vertex_count(out, path->nondelta_vertices + 1, light_sample);
        u_direction = ORB_DIRECTION_PAIR;
    }
#undef ORB_LIGHT_PAIR
#undef ORB_DIRECTION_PAIR

    // u4 picks the strategy and the lobe, and comes back rescaled (uniform
    // again and independent of those picks) for the roulette below. Where
    // the BSDF has a density the direction comes from the continuation's
    // mixture, which also aims at glass and mirror balls (caustic_casters.cl).
#if !ORB_DRAW_ALL_NUMBERS
    float choice = rand_single(&r);
#endif
    const BsdfSample bs =
        has_density ? sample_continuation(scene, &m.bsdf, p, wo, n, outside, u_direction.x, u_direction.y, &choice)
                    : bsdf_sample(&m.bsdf, wo, n, outside, u_direction.x, u_direction.y, &choice);
    const float roulette = choice;
    float3 beta = path->beta * bs.weight;
    const float beta_max = fmax(beta.x, fmax(beta.y, beta.z));
    if (beta_max <= 0.0f) return false;
    const float eta2 = path->eta2 * bs.eta2;
    if (depth + 1 >= RR_START_EVENT) {
        // Survive with probability q and divide by q: unbiased. The radiance
        // scaling of refraction is divided out of q (as pbrt-v4's etaScale):
        // inside glass beta carries (1/1.5)^2, which is no loss of energy, and
        // paths there would otherwise die 2.25 times too often.
        const float q = fmin(1.0f, beta_max / (eta2 * RR_THRESHOLD));
        if (roulette >= q) return false;
        beta *= 1.0f / q;
    }
    path->beta = beta;
    path->eta2 = eta2;
    path->nondelta_vertices += bs.delta ? 0 : 1;
    path->from_density = !bs.delta;
    path->from_pdf = bs.pdf;
    path->from_point = p;
    path->from_self = hit.id;
    path->o = p;
    path->d = bs.wi;
    path->self = hit.id;
    path->depth = depth + 1;
    return true;
}

// Casts the path's next ray and follows it. Returns false when the path has ended.
inline bool extend_path(const SceneView* scene, PathState* path, PathSample* out, const SampleCoords* coords,
                        int max_depth, int mode)
{
    return follow_hit(scene, path, out, coords, intersect_scene(scene, path->o, path->d, path->self), max_depth,
                      mode);
}

// What one finished camera path adds to each summed channel of the film
// (ORB_FILM_CHANNELS in film_channels.h; a new channel gets its line here).
// A sample whose radiance is not finite (never expected) would poison the
// pixel's sums for good, so it adds no light at all.
inline void film_add_sample(FilmSums* sums, const PathSample* s)
{
    float3 emission = s->emission, direct = s->direct, indirect = s->indirect, background = s->background;
    float3 radiance = (emission + direct) + indirect;
    if (!all(isfinite(radiance))) emission = direct = indirect = radiance = background = (float3)(0.0f);
    sums->radiance += radiance;
    sums->alpha += s->alpha;
    sums->direct += direct;
    sums->indirect += indirect;
    sums->emission += emission;
    sums->albedo += s->albedo;
    sums->normal += s->normal;
    sums->radiance_sq += radiance * radiance;
    sums->background += background;
}

// The centre-ray channels: not averages, but what the ray through the pixel
// centre and the lens centre hits.
inline FilmCentre film_centre_ray(const SceneView* scene, const CameraParams* cam, int x, int y, int width,
                                  int height)
{
    CameraParams pinhole = *cam;
    pinhole.lens_radius = 0.0f;
    float3 o, d;
    camera_ray(&pinhole, (float)x + 0.5f, (float)y + 0.5f, width, height, 0.0f, 0.0f, &o, &d);
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
#define ORB_KERNEL_FILM_ARG(name, components, clear, accumulate, merge, layer, stored_as, paired, names) __global float* film_##name,
#define ORB_KERNEL_TABLE_ARG(type, name) SCENE_MEM const type* name,
#define ORB_KERNEL_PARAMS_ARG(type, name) type name
// Inside a kernel with those arguments (render_pass, render_pass_simd):
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
__kernel void render_pass(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG))
{
    const int width = params.settings.width;
    const int height = params.settings.height;
    const int x = get_global_id(0);
    const int y = get_global_id(1);
    if (x >= width || y >= height) return;
    const uint pixel = (uint)y * (uint)width + (uint)x;

    ORB_SCENE_VIEW_OF_ARGUMENTS

    const CameraParams cam = params.camera;
    const uint2 seed = (uint2)(params.settings.seed_lo, params.settings.seed_hi);
    const int max_depth = params.settings.max_depth;
    const int mode = params.settings.mode;
    const ulong first_sample = ((ulong)params.pass.first_sample_hi << 32) | (ulong)params.pass.first_sample_lo;
    const int sample_count = params.pass.sample_count;

    // The centre-ray channels first, on the pass that writes them. Cast after
    // the sample loop, as it once was, NVIDIA's driver 580 faulted (OpenCL
    // error -36) in most renders of a scene with a tree that built the depth
    // or id channel and let paths reach a third scattering event, at every
    // register cap but one; cast before the loop, never
    // (docs/design/nvidia-fault-36.md).
    if ((ORB_FILM_BUILT(depth) || ORB_FILM_BUILT(object_id)) && params.pass.write_centre_ray) {
        const FilmCentre centre = film_centre_ray(&scene, &cam, x, y, width, height);
        ORB_FILM_SET_CENTRE
    }

    FilmSums sums;
    film_sums_clear(&sums);

    // Path regeneration: one flat loop of ray casts, where a finished path
    // hands over to the pass's next sample at once. On GPUs the threads of a
    // warp then stay busy casting rays instead of waiting for the longest
    // path of the group to end before all start their next sample.
    PathState path;
    PathSample s;
    int i = 0;
    const uint pixel_key = sampler_pixel_key(pixel, seed);
    SampleCoords coords = sample_coords(pixel_key, pixel, first_sample, seed);
    if (sample_count > 0) begin_camera_path(&cam, x, y, width, height, &coords, &path, &s);
    while (i < sample_count) {
        if (extend_path(&scene, &path, &s, &coords, max_depth, mode)) continue;
        film_add_sample(&sums, &s);
        if (++i < sample_count) {
            coords = sample_coords(pixel_key, pixel, first_sample + (ulong)i, seed);
            begin_camera_path(&cam, x, y, width, height, &coords, &path, &s);
        }
    }
    ORB_FILM_ADD_SUMS
}
