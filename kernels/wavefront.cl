// A wavefront form of render_pass, for measuring whether one would beat the
// megakernel (issue 9 §5: "if a wavefront design ... beats the megakernel
// at large N, switch"; docs/performance.md, "A wavefront renderer,
// measured": it does not within the memory issue 9 allows). Built only with
// -DORB_WAVEFRONT=1, by librender/src/wavefront_renderer.h; not used for rendering.
//
// The path tracer is render_pass's own, cut at its ray casts. A wave is a
// few samples of every pixel, one path slot each, the paths' state in
// global memory; per scattering event three kernels run over a queue of
// live paths:
//   wavefront_intersect  casts each queued path's ray (closest hit);
//   wavefront_shade      follow_hit (integrator.cl) on that hit: emission,
//                        the next-event estimate, whose shadow ray it queues
//                        instead of casting, and the next direction; live
//                        paths go to the next queue;
//   wavefront_shadow     casts the queued shadow rays (any hit) and adds the
//                        estimates of those that reach their light.
// wavefront_begin starts a wave's camera paths. The numbers a path draws are
// render_pass's (the same pixel, sample index and blocks), so a wave renders
// the very samples render_pass renders for those sample indices; only the
// order in which a sample's terms are summed differs. Each path sums its
// radiance in its own slot; the host adds a pixel's slots. (Handing a
// finished path's slot to the pixel's next sample at once, as render_pass
// does, was slower: benchmarks/2026-11-24-gpu/wavefront-regeneration.patch.)
//
// The paths' state is kept as arrays of float4, one array per group of
// fields (structure of arrays): the 32 work-items of a warp then read and
// write neighbouring 16-byte words, and the intersection kernel reads only
// the ray's two words. Array k of a buffer starts at k * get_global_size(0),
// the same for every kernel of a wave. (An array of 144-byte structs made
// the prototype 1.5 to 3 times slower on an H100.)
//
// Queues are compacted with atomic counters (counts[]: the two path queues'
// lengths and the shadow queue's). Each kernel is launched over every slot
// and items past the queue's length return at once, so the host never waits
// for a count. A slot's radiance is written by at most one work-item per
// launch (one shadow ray per path per event), so no atomics are needed
// there. Global mode only: direct mode's estimate loops over every light,
// which would need a shadow ray per light.

#if ORB_WAVEFRONT
// The float4 words of one path's state (PathState and SampleCoords). The
// fields a stored path always has equal are kept once: from_point is the
// ray's origin and from_self the sphere it leaves (follow_hit sets both to
// the shading point and its sphere, begin_path to the camera and -1), and
// the pixel is the slot's.
#define WAVEFRONT_RAY_ORIGIN 0  // o, self
#define WAVEFRONT_RAY_DIRECTION 1  // d, depth | nondelta_vertices << 8 | albedo_set << 16 | from_density << 17
#define WAVEFRONT_THROUGHPUT 2  // beta, eta2
#define WAVEFRONT_SAMPLE 3  // from_pdf, sample (low, high), the Sobol key (0 for the independent sampler)
#define WAVEFRONT_PATH_WORDS 4
// ... and of a queued shadow ray:
#define WAVEFRONT_SHADOW_ORIGIN 0  // the shading point, the sphere it leaves
#define WAVEFRONT_SHADOW_DIRECTION 1  // direction, the light's sphere slot (-1 the environment)
#define WAVEFRONT_SHADOW_CONTRIBUTION 2  // the estimate, the path it belongs to
#define WAVEFRONT_SHADOW_WORDS 3

// Word k of item i.
#define WAVEFRONT_WORD(buffer, k, i) (buffer)[(size_t)(k) * get_global_size(0) + (size_t)(i)]

// The number of float4 words per path and per shadow ray, for the host's allocations.
__kernel void wavefront_record_words(__global int* words)
{
    words[0] = WAVEFRONT_PATH_WORDS;
    words[1] = WAVEFRONT_SHADOW_WORDS;
}

// Indices into counts[]: two path queues (a wave alternates between them)
// and the shadow queue.
#define WAVEFRONT_SHADOW_COUNT 2

inline void store_path(__global float4* state, int p, const PathState* path, const SampleCoords* c)
{
#if ORB_SAMPLER_SOBOL
    const uint key = c->key;
#else
    const uint key = 0u;
#endif
    const int packed = path->depth | (path->nondelta_vertices << 8) | (path->albedo_set ? 1 << 16 : 0) |
                       (path->from_density ? 1 << 17 : 0);
    WAVEFRONT_WORD(state, WAVEFRONT_RAY_ORIGIN, p) = (float4)(path->o, as_float(path->self));
    WAVEFRONT_WORD(state, WAVEFRONT_RAY_DIRECTION, p) = (float4)(path->d, as_float(packed));
    WAVEFRONT_WORD(state, WAVEFRONT_THROUGHPUT, p) = (float4)(path->beta, path->eta2);
    WAVEFRONT_WORD(state, WAVEFRONT_SAMPLE, p) =
        (float4)(path->from_pdf, as_float((uint)c->sample), as_float((uint)(c->sample >> 32)), as_float(key));
}

inline void load_path(__global const float4* state, int p, uint pixel, uint2 seed, PathState* path, SampleCoords* c)
{
    const float4 origin = WAVEFRONT_WORD(state, WAVEFRONT_RAY_ORIGIN, p);
    const float4 direction = WAVEFRONT_WORD(state, WAVEFRONT_RAY_DIRECTION, p);
    const float4 throughput = WAVEFRONT_WORD(state, WAVEFRONT_THROUGHPUT, p);
    const float4 sample = WAVEFRONT_WORD(state, WAVEFRONT_SAMPLE, p);
    const int packed = as_int(direction.w);
    path->o = origin.xyz;
    path->self = as_int(origin.w);
    path->d = direction.xyz;
    path->depth = packed & 0xff;
    path->nondelta_vertices = (packed >> 8) & 0xff;
    path->albedo_set = (packed & (1 << 16)) != 0;
    path->from_density = (packed & (1 << 17)) != 0;
    path->beta = throughput.xyz;
    path->eta2 = throughput.w;
    path->from_point = path->o;
    path->from_self = path->self;
    path->from_pdf = sample.x;
    c->pixel = pixel;
    c->sample = ((ulong)as_uint(sample.z) << 32) | (ulong)as_uint(sample.y);
    c->seed = seed;
#if ORB_SAMPLER_SOBOL
    c->key = as_uint(sample.w);
    c->i_reversed = reverse_bits32(as_uint(sample.y));
#endif
}

// Path p of a wave is pixel p % pixels, sample first_sample + p / pixels.
__kernel void wavefront_begin(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                              __global float4* state, __global int* queue, int paths_per_pixel)
{
    const int width = params.settings.width;
    const int pixels = width * params.settings.height;
    const int p = get_global_id(0);
    if (p >= pixels * paths_per_pixel) return;
    const int pixel = p % pixels;
    const uint2 seed = (uint2)(params.settings.seed_lo, params.settings.seed_hi);
    const ulong first_sample = ((ulong)params.pass.first_sample_hi << 32) | (ulong)params.pass.first_sample_lo;
    const CameraParams cam = params.camera;
    PathState path;
    PathSample unused;
    const SampleCoords coords =
        sample_coords(sampler_pixel_key((uint)pixel, seed), (uint)pixel, first_sample + (ulong)(p / pixels), seed);
    begin_camera_path(&cam, pixel % width, pixel / width, width, params.settings.height, &coords, &path, &unused);
    store_path(state, p, &path, &coords);
    queue[p] = p;
}

__kernel void wavefront_intersect(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                                  __global const float4* state, __global const int* queue, __global const int* counts,
                                  int queue_slot, __global int2* hits)
{
    const int i = get_global_id(0);
    if (i >= counts[queue_slot]) return;
    ORB_SCENE_VIEW_OF_ARGUMENTS
    const int p = queue[i];
    const float4 o = WAVEFRONT_WORD(state, WAVEFRONT_RAY_ORIGIN, p);
    const float4 d = WAVEFRONT_WORD(state, WAVEFRONT_RAY_DIRECTION, p);
    const Hit hit = intersect_scene(&scene, o.xyz, d.xyz, as_int(o.w));
    hits[p] = (int2)(hit.id, as_int(hit.t));
}

__kernel void wavefront_shade(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                              __global float4* state, __global const int* queue, __global int* next_queue,
                              __global int* counts, int queue_slot, int next_slot, __global const int2* hits,
                              __global float4* shadow_rays, __global float4* radiance)
{
    const int i = get_global_id(0);
    if (i >= counts[queue_slot]) return;
    ORB_SCENE_VIEW_OF_ARGUMENTS
    const int p = queue[i];
    PathState path;
    SampleCoords coords;
    load_path(state, p, (uint)(p % (params.settings.width * params.settings.height)),
              (uint2)(params.settings.seed_lo, params.settings.seed_hi), &path, &coords);
    const int2 packed = hits[p];
    Hit hit;
    hit.id = packed.x;
    hit.t = as_float(packed.y);
    const float3 shading_point = path.o + hit.t * path.d;

    DeferredShadowRay shadow;
    shadow.pending = 0;
    scene.deferred_shadow = &shadow;
    PathSample s;
    s.emission = s.direct = s.indirect = s.albedo = s.normal = s.background = (float3)(0.0f);
    s.alpha = 0.0f;
    const bool alive = follow_hit(&scene, &path, &s, &coords, hit, params.settings.max_depth, params.settings.mode);

    // render_pass drops a sample whose radiance is not finite; here, the term.
    const float3 term = (s.emission + s.direct) + s.indirect;
    if (all(isfinite(term)) && term.x + term.y + term.z > 0.0f) radiance[p].xyz += term;
    if (shadow.pending && shadow.contribution.x + shadow.contribution.y + shadow.contribution.z > 0.0f) {
        const int k = atomic_inc(&counts[WAVEFRONT_SHADOW_COUNT]);
        WAVEFRONT_WORD(shadow_rays, WAVEFRONT_SHADOW_ORIGIN, k) = (float4)(shading_point, as_float(hit.id));
        WAVEFRONT_WORD(shadow_rays, WAVEFRONT_SHADOW_DIRECTION, k) = (float4)(shadow.direction, as_float(shadow.light));
        WAVEFRONT_WORD(shadow_rays, WAVEFRONT_SHADOW_CONTRIBUTION, k) = (float4)(shadow.contribution, as_float(p));
    }
    if (alive) {
        store_path(state, p, &path, &coords);
        next_queue[atomic_inc(&counts[next_slot])] = p;
    }
}

__kernel void wavefront_shadow(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                               __global const float4* shadow_rays, __global const int* counts,
                               __global float4* radiance)
{
    const int i = get_global_id(0);
    if (i >= counts[WAVEFRONT_SHADOW_COUNT]) return;
    ORB_SCENE_VIEW_OF_ARGUMENTS
    const float4 o = WAVEFRONT_WORD(shadow_rays, WAVEFRONT_SHADOW_ORIGIN, i);
    const float4 d = WAVEFRONT_WORD(shadow_rays, WAVEFRONT_SHADOW_DIRECTION, i);
    if (!light_visible(&scene, o.xyz, d.xyz, as_int(o.w), as_int(d.w))) return;
    const float4 c = WAVEFRONT_WORD(shadow_rays, WAVEFRONT_SHADOW_CONTRIBUTION, i);
    if (all(isfinite(c.xyz))) radiance[as_int(c.w)].xyz += c.xyz;
}
#endif
