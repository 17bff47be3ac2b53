// Ray-sphere intersection: the spheres outside the BVH (huge ones, or all of
// a small scene) in a linear loop over packets of four, then the BVH
// (librender/src/sphere_bvh.h), whose leaves are one packet each.
//
// Robustness without epsilons:
//  * The discriminant is formed as r^2 - |oc - (oc.d) d|^2 (squared distance
//    from the centre to the ray's closest point), which keeps its precision
//    for the radius-1e4 "walls" of the Cornell box (Haines et al., "Precision
//    improvements for ray/sphere intersection", Ray Tracing Gems, 2019).
//  * A ray leaving the surface of sphere `self` never re-hits that surface at
//    its start: for `self` only the far root counts, and only when the ray
//    heads into the sphere (oc.d < 0). Other spheres need no offset.
//  * BVH boxes are built to contain each sphere as stored here (float centre,
//    float radius squared), so the box test never culls a hit the sphere test
//    would find.

#define ORB_NO_HIT 1e30f
// The host builds the program with -DORB_BVH=0 for a scene without a tree:
// the traversal code (and its stacks) then does not exist, and the GPU's
// register allocation for render_pass is what it was before there was a BVH
// (on an H100 that is 5% of the Cornell box's speed).
#ifndef ORB_BVH
#define ORB_BVH 1
#endif
// No root-to-leaf path of the BVH is longer (kBvhMaxDepth, sphere_bvh.h).
#define ORB_BVH_STACK 64

typedef struct {
    float t;  // distance along the (unit) ray direction
    int id;   // sphere slot (index into the spheres table), -1 for a miss
} Hit;

inline float packet_lane(SCENE_MEM const float4* v, int lane) { return ((SCENE_MEM const float*)v)[lane]; }

// Distance along the ray to lane `lane` of a packet (sphere slot `id`), by
// the rules above, or ORB_NO_HIT when the ray misses it (padding lanes too).
inline float lane_distance(SCENE_MEM const SpherePacket* packet, int lane, int id, float3 o, float3 d, int self)
{
    const float3 oc = o - (float3)(packet_lane(&packet->centre_x, lane), packet_lane(&packet->centre_y, lane),
                                   packet_lane(&packet->centre_z, lane));
    const float b = dot(oc, d);
    const float3 f = oc - b * d;
    const float disc = packet_lane(&packet->radius2, lane) - dot(f, f);
    if (disc < 0.0f) return ORB_NO_HIT;
    const float s = sqrt(disc);
    const bool is_self = id == self;
    if (is_self && b >= 0.0f) return ORB_NO_HIT;
    const float t_near = -b - s;
    const float t = (is_self || t_near <= 0.0f) ? -b + s : t_near;
    return t > 0.0f ? t : ORB_NO_HIT;
}

#ifndef ORB_INTERSECT_SCALAR
// Four spheres per step in SIMD lanes: CPUs execute the float4 arithmetic as
// one vector instruction each.
typedef struct {
    float4 t;
    int4 id;
} BestHit;

inline void best_init(BestHit* best)
{
    best->t = (float4)(ORB_NO_HIT);
    best->id = (int4)(-1);
}

// The four lanes' hit distances along the ray (the near root, or the far one
// from inside or for `self`), and in *hits which lanes are hit at all.
inline float4 packet_roots(SCENE_MEM const SpherePacket* packet, int4 id, float3 o, float3 d, int self, int4* hits)
{
    const float4 ocx = (float4)(o.x) - packet->centre_x;
    const float4 ocy = (float4)(o.y) - packet->centre_y;
    const float4 ocz = (float4)(o.z) - packet->centre_z;
    const float4 b = ocx * d.x + ocy * d.y + ocz * d.z;
    const float4 fx = ocx - b * d.x;
    const float4 fy = ocy - b * d.y;
    const float4 fz = ocz - b * d.z;
    const float4 disc = packet->radius2 - (fx * fx + fy * fy + fz * fz);
    const float4 s = sqrt(fmax(disc, (float4)(0.0f)));
    const float4 t_near = -b - s;
    const int4 is_self = id == (int4)(self);
    const float4 t = select(t_near, -b + s, is_self | (t_near <= (float4)(0.0f)));
    *hits = (disc >= (float4)(0.0f)) & (t > (float4)(0.0f)) & ~(is_self & (b >= (float4)(0.0f)));
    return t;
}

inline void test_packet(BestHit* best, SCENE_MEM const SpherePacket* packet, int first_id, float3 o, float3 d, int self)
{
    const int4 id = (int4)(0, 1, 2, 3) + (int4)(first_id);
    int4 hits;
    const float4 t = packet_roots(packet, id, o, d, self, &hits);
    const int4 valid = hits & (t < best->t);
    best->t = select(best->t, t, valid);
    best->id = select(best->id, id, valid);
}

// Whether a sphere of the packet other than `light` is hit before t_max.
inline bool packet_blocks(SCENE_MEM const SpherePacket* packet, int first_id, float3 o, float3 d, int self, int light,
                          float t_max)
{
    const int4 id = (int4)(0, 1, 2, 3) + (int4)(first_id);
    int4 hits;
    const float4 t = packet_roots(packet, id, o, d, self, &hits);
    return any(hits & (t < (float4)(t_max)) & (id != (int4)(light)));
}

inline float best_distance(const BestHit* best)
{
    const float2 m2 = fmin(best->t.xy, best->t.zw);
    return fmin(m2.x, m2.y);
}

inline Hit best_hit(const BestHit* best)
{
    Hit hit;
    hit.t = best_distance(best);
    hit.id = best->t.x == hit.t ? best->id.x
           : best->t.y == hit.t ? best->id.y
           : best->t.z == hit.t ? best->id.z
                                : best->id.w;
    return hit;
}
#else
// One sphere per step, for GPUs: a GPU thread executes float4 arithmetic one
// lane at a time, so packets would only add the padding lanes' work. Reads
// the same packets lane by lane; same roots and rules as the packet version.
typedef Hit BestHit;

inline void best_init(BestHit* best)
{
    best->t = ORB_NO_HIT;
    best->id = -1;
}

inline void test_packet(BestHit* best, SCENE_MEM const SpherePacket* packet, int first_id, float3 o, float3 d, int self)
{
    for (int lane = 0; lane < 4; ++lane) {
        if (packet_lane(&packet->radius2, lane) < 0.0f) break;  // padding lanes come last
        const float t = lane_distance(packet, lane, first_id + lane, o, d, self);
        if (t < best->t) {
            best->t = t;
            best->id = first_id + lane;
        }
    }
}

inline bool packet_blocks(SCENE_MEM const SpherePacket* packet, int first_id, float3 o, float3 d, int self, int light,
                          float t_max)
{
    for (int lane = 0; lane < 4; ++lane) {
        if (packet_lane(&packet->radius2, lane) < 0.0f) break;  // padding lanes come last
        if (first_id + lane != light && lane_distance(packet, lane, first_id + lane, o, d, self) < t_max) return true;
    }
    return false;
}

inline float best_distance(const BestHit* best) { return best->t; }

inline Hit best_hit(const BestHit* best) { return *best; }
#endif

// Where the ray enters the box, or ORB_NO_HIT if it misses it before t_max.
inline float box_entry(SCENE_MEM const BvhNodeRecord* node, float3 o, float3 inv_d, float t_max)
{
    const float3 t0 = (node->lo_first.xyz - o) * inv_d;
    const float3 t1 = (node->hi_count.xyz - o) * inv_d;
    const float3 near = fmin(t0, t1), far = fmax(t0, t1);
    const float enter = fmax(fmax(near.x, near.y), fmax(near.z, 0.0f));
    const float leave = fmin(fmin(far.x, far.y), fmin(far.z, t_max));
    return enter <= leave ? enter : ORB_NO_HIT;
}

inline float3 safe_inverse(float3 d)
{
    // Direction components of (almost) zero get a huge finite inverse, so no
    // 0 * inf (NaN) enters the slab test.
    return (float3)(1.0f) / select(d, copysign((float3)(1e-20f), d), isless(fabs(d), (float3)(1e-20f)));
}

// Closest hit along the ray, ordered front to back: the nearer child first,
// the farther one on the stack with its entry distance, dropped when a hit
// closer than that entry has been found by then.
inline void traverse_bvh(BestHit* best, const SceneView* scene, float3 o, float3 d, int self)
{
    const float3 inv_d = safe_inverse(d);
    uint stack_node[ORB_BVH_STACK];
    float stack_entry[ORB_BVH_STACK];
    int top = 0;
    uint node = 0;
    for (;;) {
        SCENE_MEM const BvhNodeRecord* n = &scene->bvh_nodes[node];
        const uint first = as_uint(n->lo_first.w);
        if (as_uint(n->hi_count.w) > 0) {
            test_packet(best, &scene->packets[first], (int)(4 * first), o, d, self);
        } else {
            const float t_max = best_distance(best);
            const float t_left = box_entry(&scene->bvh_nodes[first], o, inv_d, t_max);
            const float t_right = box_entry(&scene->bvh_nodes[first + 1], o, inv_d, t_max);
            if (t_left < ORB_NO_HIT && t_right < ORB_NO_HIT) {
                const bool left_first = t_left <= t_right;
                stack_node[top] = left_first ? first + 1 : first;
                stack_entry[top] = left_first ? t_right : t_left;
                ++top;
                node = left_first ? first : first + 1;
                continue;
            }
            if (t_left < ORB_NO_HIT || t_right < ORB_NO_HIT) {
                node = t_left < ORB_NO_HIT ? first : first + 1;
                continue;
            }
        }
        // Next: the nearest deferred node that can still hold a closer hit.
        while (top > 0 && stack_entry[top - 1] >= best_distance(best)) --top;
        if (top == 0) break;
        node = stack_node[--top];
    }
}

inline Hit intersect_scene(const SceneView* scene, float3 o, float3 d, int self)
{
    BestHit best;
    best_init(&best);
    for (int p = 0; p < scene->outside_packet_count; ++p) test_packet(&best, &scene->packets[p], 4 * p, o, d, self);
#if ORB_BVH
    if (scene->bvh_node_count > 0) traverse_bvh(&best, scene, o, d, self);
#endif
    return best_hit(&best);
}

// Distance along the ray to sphere slot `id` by the same test as above, or
// ORB_NO_HIT when the ray misses it.
inline float sphere_distance(const SceneView* scene, int id, float3 o, float3 d, int self)
{
    return lane_distance(&scene->packets[id >> 2], id & 3, id, o, d, self);
}

// Shadow rays: whether sphere `light` is the first thing along the ray. Any
// other sphere hit before it ends the search at once (any-hit traversal, in
// no particular order), which in a dense cloud is usually within a few nodes.
// light -1 stands for the environment: the ray must hit nothing at all.
inline bool light_visible(const SceneView* scene, float3 o, float3 d, int self, int light)
{
    // Without a tree (a handful of spheres) the closest hit over the few
    // packets is as quick as an early exit, and costs no distance to the light.
#if !ORB_BVH
    return intersect_scene(scene, o, d, self).id == light;
#else
    if (scene->bvh_node_count == 0) return intersect_scene(scene, o, d, self).id == light;
    float t_light = ORB_NO_HIT;  // the environment: every hit blocks
    if (light >= 0) {
        t_light = sphere_distance(scene, light, o, d, self);
        if (t_light >= ORB_NO_HIT) return false;
    }
    for (int p = 0; p < scene->outside_packet_count; ++p)
        if (packet_blocks(&scene->packets[p], 4 * p, o, d, self, light, t_light)) return false;
    const float3 inv_d = safe_inverse(d);
    uint stack[ORB_BVH_STACK];
    int top = 0;
    uint node = 0;
    for (;;) {
        SCENE_MEM const BvhNodeRecord* n = &scene->bvh_nodes[node];
        const uint first = as_uint(n->lo_first.w);
        if (as_uint(n->hi_count.w) > 0) {
            if (packet_blocks(&scene->packets[first], (int)(4 * first), o, d, self, light, t_light)) return false;
        } else {
            const bool left = box_entry(&scene->bvh_nodes[first], o, inv_d, t_light) < ORB_NO_HIT;
            const bool right = box_entry(&scene->bvh_nodes[first + 1], o, inv_d, t_light) < ORB_NO_HIT;
            if (left && right) stack[top++] = first + 1;
            if (left || right) {
                node = left ? first : first + 1;
                continue;
            }
        }
        if (top == 0) return true;
        node = stack[--top];
    }
#endif
}
