// Ray-sphere intersection over the whole scene: a linear loop over packets of
// four spheres (a BVH can replace this file without touching shading).
//
// Robustness without epsilons:
//  * The discriminant is formed as r^2 - |oc - (oc.d) d|^2 (squared distance
//    from the centre to the ray's closest point), which keeps its precision
//    for the radius-1e4 "walls" of the Cornell box (Haines et al., "Precision
//    improvements for ray/sphere intersection", Ray Tracing Gems, 2019).
//  * A ray leaving the surface of sphere `self` never re-hits that surface at
//    its start: for `self` only the far root counts, and only when the ray
//    heads into the sphere (oc.d < 0). Other spheres need no offset.

#define ORB_NO_HIT 1e30f

typedef struct {
    float t;  // distance along the (unit) ray direction
    int id;   // sphere index, -1 for a miss
} Hit;

#ifndef ORB_INTERSECT_SCALAR
// Four spheres per step in SIMD lanes: CPUs execute the float4 arithmetic as
// one vector instruction each.
inline Hit intersect_scene(const SceneView* scene, float3 o, float3 d, int self)
{
    float4 best_t = (float4)(ORB_NO_HIT);
    int4 best_id = (int4)(-1);
    const int4 lane = (int4)(0, 1, 2, 3);
    const int4 self4 = (int4)(self);
    for (int p = 0; p < scene->packet_count; ++p) {
        SCENE_MEM const SpherePacket* packet = &scene->packets[p];
        const float4 ocx = (float4)(o.x) - packet->centre_x;
        const float4 ocy = (float4)(o.y) - packet->centre_y;
        const float4 ocz = (float4)(o.z) - packet->centre_z;
        const float4 radius2 = packet->radius2;
        const float4 b = ocx * d.x + ocy * d.y + ocz * d.z;
        const float4 fx = ocx - b * d.x;
        const float4 fy = ocy - b * d.y;
        const float4 fz = ocz - b * d.z;
        const float4 disc = radius2 - (fx * fx + fy * fy + fz * fz);
        const float4 s = sqrt(fmax(disc, (float4)(0.0f)));
        const float4 t_near = -b - s;
        const float4 t_far = -b + s;
        const int4 id = lane + (int4)(4 * p);
        const int4 is_self = id == self4;
        const float4 t = select(t_near, t_far, is_self | (t_near <= (float4)(0.0f)));
        const int4 valid = (disc >= (float4)(0.0f)) & (t > (float4)(0.0f)) & (t < best_t) &
                           ~(is_self & (b >= (float4)(0.0f)));
        best_t = select(best_t, t, valid);
        best_id = select(best_id, id, valid);
    }
    const float2 m2 = fmin(best_t.xy, best_t.zw);
    Hit hit;
    hit.t = fmin(m2.x, m2.y);
    hit.id = best_t.x == hit.t ? best_id.x
           : best_t.y == hit.t ? best_id.y
           : best_t.z == hit.t ? best_id.z
                               : best_id.w;
    return hit;
}
#else
// One sphere per step, for GPUs: a GPU thread executes float4 arithmetic one
// lane at a time, so packets would only add the padding lanes' work. Reads
// the same packets (lane i & 3 of packet i >> 2); same roots and rules as
// the packet version.
inline float packet_lane(SCENE_MEM const float4* v, int lane) { return ((SCENE_MEM const float*)v)[lane]; }

inline Hit intersect_scene(const SceneView* scene, float3 o, float3 d, int self)
{
    Hit hit;
    hit.t = ORB_NO_HIT;
    hit.id = -1;
    for (int i = 0; i < scene->sphere_count; ++i) {
        SCENE_MEM const SpherePacket* packet = &scene->packets[i >> 2];
        const int lane = i & 3;
        const float3 oc = o - (float3)(packet_lane(&packet->centre_x, lane), packet_lane(&packet->centre_y, lane),
                                       packet_lane(&packet->centre_z, lane));
        const float b = dot(oc, d);
        const float3 f = oc - b * d;
        const float disc = packet_lane(&packet->radius2, lane) - dot(f, f);
        if (disc < 0.0f) continue;
        const float s = sqrt(disc);
        const float t_near = -b - s;
        const bool is_self = i == self;
        if (is_self && b >= 0.0f) continue;
        const float t = (is_self || t_near <= 0.0f) ? -b + s : t_near;
        if (t > 0.0f && t < hit.t) {
            hit.t = t;
            hit.id = i;
        }
    }
    return hit;
}
#endif
