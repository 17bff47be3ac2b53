// A wavefront form of render_pass, for measuring whether one would beat the
// megakernel (issue 9 §5: "if a wavefront design ... beats the megakernel
// at large N, switch"). Built only with -DORB_WAVEFRONT=1, by
// librender/src/wavefront_renderer.h; not used for rendering.
//
// The path tracer is render_pass's own, cut at its ray casts: one path per
// pixel of a wave (one sample of every pixel), its state in global memory,
// and per scattering event three kernels over a queue of live paths:
//   wavefront_intersect  casts each queued path's ray (closest hit);
//   wavefront_shade      follow_hit (integrator.cl) on that hit: emission,
//                        the next-event estimate, whose shadow ray it queues
//                        instead of casting, and the next direction; live
//                        paths go to the next queue;
//   wavefront_shadow     casts the queued shadow rays (any hit) and adds the
//                        estimates of those that reach their light.
// wavefront_begin starts a wave's camera paths. The numbers a path draws are
// render_pass's (the same pixel, sample index and blocks), so a wave renders
// the very samples render_pass renders for that sample index; only the order
// in which a sample's terms are summed differs. Each path sums its radiance
// in its own slot; the host adds a pixel's slots.
//
// Queues are compacted with atomic counters (counts[]: the two path queues'
// lengths and the shadow queue's). Each kernel is launched over every pixel
// and items past the queue's length return at once, so the host never waits
// for a count. A path's radiance slot is written by at most one work-item
// per launch (one shadow ray per path per event), so no atomics are needed there.
// Global mode only: direct mode's estimate loops over every light, which
// would need a shadow ray per light.

#if ORB_WAVEFRONT
typedef struct {
    PathState path;
    SampleCoords coords;
} WavefrontPath;

typedef struct {
    float4 origin_self;        // the shading point; w: the sphere it leaves (int bits)
    float4 direction_light;    // w: the light's sphere slot (int bits), -1 the environment
    float4 contribution_path;  // w: the path it belongs to (int bits)
} WavefrontShadowRay;

// Indices into counts[]: two path queues (a wave alternates between them)
// and the shadow queue.
#define WAVEFRONT_SHADOW_COUNT 2

// The size of the records above as this device lays them out, for the host's allocations.
__kernel void wavefront_record_sizes(__global int* sizes)
{
    sizes[0] = (int)sizeof(WavefrontPath);
    sizes[1] = (int)sizeof(WavefrontShadowRay);
}

// PathState holds bools, which may not appear in a kernel argument's
// pointee type, so the paths travel as bytes.
#define WAVEFRONT_PATHS ((__global WavefrontPath*)path_bytes)

// Path p of a wave is pixel p % pixels, sample first_sample + p / pixels.
__kernel void wavefront_begin(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                              __global uchar* path_bytes, __global int* queue, int paths_per_pixel)
{
    const int width = params.settings.width;
    const int pixels = width * params.settings.height;
    const int p = get_global_id(0);
    if (p >= pixels * paths_per_pixel) return;
    const int pixel = p % pixels;
    const uint2 seed = (uint2)(params.settings.seed_lo, params.settings.seed_hi);
    const ulong first_sample = ((ulong)params.pass.first_sample_hi << 32) | (ulong)params.pass.first_sample_lo;
    const CameraParams cam = params.camera;
    WavefrontPath w;
    PathSample unused;
    w.coords = sample_coords(sampler_pixel_key((uint)pixel, seed), (uint)pixel, first_sample + (ulong)(p / pixels), seed);
    begin_camera_path(&cam, pixel % width, pixel / width, width, params.settings.height, &w.coords, &w.path, &unused);
    WAVEFRONT_PATHS[p] = w;
    queue[p] = p;
}

__kernel void wavefront_intersect(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                                  __global uchar* path_bytes, __global const int* queue, __global const int* counts,
                                  int queue_slot, __global int2* hits)
{
    const int i = get_global_id(0);
    if (i >= counts[queue_slot]) return;
    ORB_SCENE_VIEW_OF_ARGUMENTS
    const int p = queue[i];
    __global const PathState* path = &WAVEFRONT_PATHS[p].path;
    const Hit hit = intersect_scene(&scene, path->o, path->d, path->self);
    hits[p] = (int2)(hit.id, as_int(hit.t));
}

__kernel void wavefront_shade(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                              __global uchar* path_bytes, __global const int* queue, __global int* next_queue,
                              __global int* counts, int queue_slot, int next_slot, __global const int2* hits,
                              __global WavefrontShadowRay* shadow_rays, __global float4* radiance)
{
    const int i = get_global_id(0);
    if (i >= counts[queue_slot]) return;
    ORB_SCENE_VIEW_OF_ARGUMENTS
    const int p = queue[i];
    PathState path = WAVEFRONT_PATHS[p].path;
    const SampleCoords coords = WAVEFRONT_PATHS[p].coords;
    const int2 packed = hits[p];
    Hit hit;
    hit.id = packed.x;
    hit.t = as_float(packed.y);
    const float3 shading_point = path.o + hit.t * path.d;

    DeferredShadowRay shadow;
    shadow.pending = 0;
    scene.deferred_shadow = &shadow;
    PathSample s;
    s.emission = s.direct = s.indirect = s.albedo = s.normal = (float3)(0.0f);
    s.alpha = 0.0f;
    const bool alive = follow_hit(&scene, &path, &s, &coords, hit, params.settings.max_depth, params.settings.mode);

    // render_pass drops a sample whose radiance is not finite; here, the term.
    const float3 term = (s.emission + s.direct) + s.indirect;
    if (all(isfinite(term)) && term.x + term.y + term.z > 0.0f) radiance[p].xyz += term;
    if (shadow.pending && shadow.contribution.x + shadow.contribution.y + shadow.contribution.z > 0.0f) {
        WavefrontShadowRay ray;
        ray.origin_self = (float4)(shading_point, as_float(hit.id));
        ray.direction_light = (float4)(shadow.direction, as_float(shadow.light));
        ray.contribution_path = (float4)(shadow.contribution, as_float(p));
        shadow_rays[atomic_inc(&counts[WAVEFRONT_SHADOW_COUNT])] = ray;
    }
    if (alive) {
        WAVEFRONT_PATHS[p].path = path;
        next_queue[atomic_inc(&counts[next_slot])] = p;
    }
}

__kernel void wavefront_shadow(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                               __global const WavefrontShadowRay* shadow_rays, __global const int* counts,
                               __global float4* radiance)
{
    const int i = get_global_id(0);
    if (i >= counts[WAVEFRONT_SHADOW_COUNT]) return;
    ORB_SCENE_VIEW_OF_ARGUMENTS
    const WavefrontShadowRay ray = shadow_rays[i];
    if (!light_visible(&scene, ray.origin_self.xyz, ray.direction_light.xyz, as_int(ray.origin_self.w),
                       as_int(ray.direction_light.w)))
        return;
    const float3 term = ray.contribution_path.xyz;
    if (all(isfinite(term))) radiance[as_int(ray.contribution_path.w)].xyz += term;
}
#endif
