// Ray casting alone: each work-item casts one ray of a batch through the
// scene's tables with intersect.cl's traversal, and nothing else. Not part
// of the product's program: dev/ray_casting/ray_caster.cpp appends it to the
// product's kernels and builds it with -DORB_TRACE_KERNEL=1, for
// orb-trace-benchmark (docs/design/bvh-traversal.md), which measures what a wavefront design's ray-casting kernel would
// achieve on its own, and for dev/ray_casting/trace_kernel_test.cpp, which
// checks the device's traversal against brute force.
//
// The arguments are render_pass's (so that the host binds the scene the same
// way; the film buffers go unused) followed by the batch: two float4 per ray,
// the origin with the bits of the sphere slot the ray leaves (-1: none) in w,
// then the unit direction with, for shadow rays, the bits of the light's
// sphere slot (-1: the environment) in w (dev/ray_casting/ray_caster.h,
// CastRay); and one result per ray: for closest hits the sphere slot hit
// (-1: none) and the distance's bits, for shadow rays 1 when the light is
// visible, else 0.

#ifndef ORB_TRACE_KERNEL
#define ORB_TRACE_KERNEL 0
#endif
#if ORB_TRACE_KERNEL
__kernel void trace_rays(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG),
                         __global const float4* rays, __global int2* results, int ray_count, int shadow_rays)
{
    const int i = get_global_id(0);
    if (i >= ray_count) return;
    ORB_SCENE_VIEW_OF_ARGUMENTS
    const float4 o = rays[2 * i];
    const float4 d = rays[2 * i + 1];
    const int self = as_int(o.w);
    if (shadow_rays) {
        results[i] = (int2)(light_visible(&scene, o.xyz, d.xyz, self, as_int(d.w)) ? 1 : 0, 0);
    } else {
        const Hit hit = intersect_scene(&scene, o.xyz, d.xyz, self);
        results[i] = (int2)(hit.id, as_int(hit.t));
    }
}
#endif
