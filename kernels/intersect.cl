// Ray-sphere intersection: the spheres outside the BVH (huge ones, or all of
// a small scene) in a linear loop over packets of four, then the 4-wide BVH
// (librender/src/sphere_bvh.h), whose leaves are one packet each. The test
// of a ray against a sphere is one text (ORB_DEFINE_SPHERE_DISTANCE, below)
// in three forms: one ray and one sphere, one ray and a packet's four
// spheres (CPUs' traversal), each lane's ray and one sphere (intersect_lanes.cl);
// the tree is walked by one loop (traverse_tree) for every device.

#define ORB_NO_HIT 1e30f
// The host builds the program with ORB_BVH 0 for a scene without a tree
// (kernel_features.h): the traversal code (and its stacks) then does not
// exist, and the GPU's register allocation for render_pass is what it was
// before there was a BVH (on an H100 that is 5% of the Cornell box's speed).

// Minimum and maximum of values that are never NaN here (distances from
// finite boxes and spheres). OpenCL's fmin and fmax must return the other
// operand of a NaN, which costs an x86 CPU a compare and a blend besides
// each minps or maxps; a compare-select is the bare instruction. GPUs have
// the NaN-aware instruction, so they keep fmin and fmax.
#if ORB_SCALAR_TRAVERSAL
#define ORB_MIN(a, b) fmin(a, b)
#define ORB_MAX(a, b) fmax(a, b)
#else
#define ORB_MIN(a, b) select(b, a, isless(a, b))
#define ORB_MAX(a, b) select(b, a, isgreater(a, b))
#endif

// The ray-sphere test, the one home of its robustness rules. Distance along
// the ray (o, d) to the sphere (centre, radius2 the radius squared), or
// ORB_NO_HIT where the ray misses it; is_self: the sphere is the one the ray
// leaves (the path's `self`), as a comparison's result. Rules, with no
// epsilon anywhere:
//  * d is of unit length, so b = oc.d is where along the ray it passes the
//    centre closest (oc = o - centre).
//  * The discriminant is r^2 - |oc - b d|^2, the squared radius less the
//    squared distance from the centre to the ray's closest point, not
//    b^2 - (|oc|^2 - r^2): it keeps its precision for the radius-1e4 "walls"
//    of the Cornell box (Haines et al., "Precision improvements for
//    ray/sphere intersection", Ray Tracing Gems, 2019). Not at least 0
//    (below 0, or NaN): the ray passes the sphere by, a miss.
//  * Which root: the near one, -b - sqrt(disc), unless it is not ahead
//    (t <= 0: the origin is inside the sphere or past it); then the far one,
//    -b + sqrt(disc). A hit is ahead: t > 0.
//  * A ray leaving the surface of sphere `self` never re-hits that surface
//    at its start: for `self` only the far root counts, and only when the
//    ray heads into the sphere (b < 0); leaving it outwards misses it. Other
//    spheres need no offset.
//  * BVH boxes are built to contain each sphere as stored (float centre,
//    float radius squared), so the box test never culls a hit this test
//    would find.
// The forms: scalar (F float, I int, V3 float3 under f3_), a packet of four
// spheres (float4, int4, packet_v3 under p4_), the lanes (lfloat, lint, lv3
// under lv3_). All are written with select, & and |, which mean the same for
// a scalar comparison (1) and a vector one (-1 per lane); a scalar ! is 0 or
// 1 and a vector's 0 or -1, so it is right in both.
// How a form leaves on a miss (MISS, below): the scalar form returns as
// soon as the miss is known, as the hand-written copy it replaced did, so
// that a GPU thread pays no square root and no select for a sphere it
// misses (a first try without the returns, among other differences, ran
// up to 17% slower on an H200); its root is then of a discriminant known
// not negative.
// The vector forms do not branch: every lane computes everything, the root
// of the discriminant clamped at 0 (so that no lane's NaN matters), and the
// misses are masked at the end.
// After the scalar form's returns the compiler knows the mask's terms (the
// same values it branched on), so the mask costs it nothing; the vector
// forms' mask is the one the hand-written packet and lane tests had.
// Rounding: -cl-mad-enable lets the compiler fuse a multiply and an add only
// within one expression, so each step the text names is one expression in
// every form (P##_sub_scaled is oc - b d, P##_dot a sum of products), never
// a composition of helpers: the three forms then round alike, as the three
// hand-written copies this text replaced did (images bit for bit the same).
// Inlined copies may still round differently in different programs, so what
// must not depend on the program (the centre ray's depth) takes the scalar
// form of the hit sphere (sphere_distance).
#define ORB_MISS_RETURNS_IF(miss) \
    if (miss) return ORB_NO_HIT;
#define ORB_MISS_RETURNS_ROOT(F, disc) sqrt(disc)
#define ORB_MISS_MASKED_IF(miss)
#define ORB_MISS_MASKED_ROOT(F, disc) sqrt(ORB_MAX(disc, (F)(0.0f)))
#define ORB_DEFINE_SPHERE_DISTANCE(Q, F, I, V3, P, MISS, name)                                \
    Q F name(V3 o, V3 d, V3 centre, F radius2, I is_self)                                      \
    {                                                                                          \
        const V3 oc = P##_sub(o, centre);                                                      \
        const F b = P##_dot(oc, d);                                                            \
        const V3 f = P##_sub_scaled(oc, d, b);                                                 \
        const F disc = radius2 - P##_dot(f, f);                                                \
        const I within_radius = disc >= (F)(0.0f);                                             \
        MISS##_IF(!within_radius)                                                              \
        const F s = MISS##_ROOT(F, disc);                                                      \
        const I leaves_self = is_self & (b >= (F)(0.0f));                                      \
        MISS##_IF(leaves_self)                                                                 \
        const F t_near = -b - s;                                                               \
        const F t = select(t_near, -b + s, is_self | (t_near <= (F)(0.0f)));                   \
        const I hit = within_radius & (t > (F)(0.0f)) & !leaves_self;                          \
        return select((F)(ORB_NO_HIT), t, hit);                                                \
    }

ORB_DEFINE_SPHERE_DISTANCE(inline, float, int, float3, f3, ORB_MISS_RETURNS, ray_sphere_distance)

typedef struct {
    float t;  // distance along the (unit) ray direction
    int id;   // sphere slot (index into the spheres table), -1 for a miss
} Hit;

inline float packet_lane(SCENE_MEM const float4* v, int lane) { return ((SCENE_MEM const float*)v)[lane]; }

// Distance along the ray to lane `lane` of a packet (sphere slot `id`), or
// ORB_NO_HIT when the ray misses it (padding lanes too).
inline float packet_sphere_distance(SCENE_MEM const SpherePacket* packet, int lane, int id, float3 o, float3 d,
                                    int self)
{
    const float3 centre = (float3)(packet_lane(&packet->centre_x, lane), packet_lane(&packet->centre_y, lane),
                                   packet_lane(&packet->centre_z, lane));
    return ray_sphere_distance(o, d, centre, packet_lane(&packet->radius2, lane), id == self);
}

#if !ORB_SCALAR_TRAVERSAL
// Four spheres per step in SIMD lanes: CPUs execute the float4 arithmetic as
// one vector instruction each.
ORB_DEFINE_V3_OF(inline __attribute__((always_inline)), float4, packet_v3, p4)
ORB_DEFINE_SPHERE_DISTANCE(inline __attribute__((always_inline)), float4, int4, packet_v3, p4, ORB_MISS_MASKED,
                           ray_spheres_distance)

typedef struct {
    float4 t;
    int4 id;
} BestHit;

inline void best_init(BestHit* best)
{
    best->t = (float4)(ORB_NO_HIT);
    best->id = (int4)(-1);
}

// The four lanes' distances along the ray (spheres id), ORB_NO_HIT where missed.
inline float4 packet_distances(SCENE_MEM const SpherePacket* packet, int4 id, float3 o, float3 d, int self)
{
    const packet_v3 centre = p4_make(packet->centre_x, packet->centre_y, packet->centre_z);
    return ray_spheres_distance(p4_splat(o), p4_splat(d), centre, packet->radius2, id == (int4)(self));
}

inline void test_packet(BestHit* best, SCENE_MEM const SpherePacket* packet, int first_id, float3 o, float3 d, int self)
{
    const int4 id = (int4)(0, 1, 2, 3) + (int4)(first_id);
    const float4 t = packet_distances(packet, id, o, d, self);
    const int4 closer = t < best->t;
    best->t = select(best->t, t, closer);
    best->id = select(best->id, id, closer);
}

// Whether a sphere of the packet other than `light` is hit before t_max.
inline bool packet_blocks(SCENE_MEM const SpherePacket* packet, int first_id, float3 o, float3 d, int self, int light,
                          float t_max)
{
    const int4 id = (int4)(0, 1, 2, 3) + (int4)(first_id);
    const float4 t = packet_distances(packet, id, o, d, self);
    return any((t < (float4)(t_max)) & (id != (int4)(light)));
}

inline float best_distance(const BestHit* best)
{
    const float2 m2 = ORB_MIN(best->t.xy, best->t.zw);
    return ORB_MIN(m2.x, m2.y);
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
// the same packets lane by lane, with the scalar form of the same test.
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
        const float t = packet_sphere_distance(packet, lane, first_id + lane, o, d, self);
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
        if (first_id + lane != light && packet_sphere_distance(packet, lane, first_id + lane, o, d, self) < t_max)
            return true;
    }
    return false;
}

inline float best_distance(const BestHit* best) { return best->t; }

inline Hit best_hit(const BestHit* best) { return *best; }
#endif

inline float3 safe_inverse(float3 d)
{
    // Direction components of (almost) zero get a huge finite inverse, so no
    // 0 * inf (NaN) enters the slab test.
    return (float3)(1.0f) / select(d, copysign((float3)(1e-20f), d), isless(fabs(d), (float3)(1e-20f)));
}

// A ray as the box tests read it: per axis, which of a node's planes
// (BvhNodeRecord::bounds) it enters by, lo for a positive direction, hi for
// a negative one, and leaves by. For a box with lo <= hi this gives what
// min/max of the two slab distances would; an inverted box (an empty lane)
// is entered after it is left, so no ray ever hits it.
typedef struct {
    float3 o;
    float3 inv_d;
    int enter_x, enter_y, enter_z;
} BoxRay;

inline BoxRay box_ray(float3 o, float3 d)
{
    BoxRay ray;
    ray.o = o;
    ray.inv_d = safe_inverse(d);
    ray.enter_x = ray.inv_d.x < 0.0f ? 3 : 0;
    ray.enter_y = ray.inv_d.y < 0.0f ? 4 : 1;
    ray.enter_z = ray.inv_d.z < 0.0f ? 5 : 2;
    return ray;
}

// The four children's boxes against the ray up to t_max: where the ray
// enters each (*entry), and which it hits (-1 lanes).
inline int4 child_boxes(SCENE_MEM const BvhNodeRecord* node, const BoxRay* ray, float t_max, float4* entry)
{
    SCENE_MEM const float4* b = node->bounds;
    const float4 enter_x = (b[ray->enter_x] - (float4)(ray->o.x)) * ray->inv_d.x;
    const float4 enter_y = (b[ray->enter_y] - (float4)(ray->o.y)) * ray->inv_d.y;
    const float4 enter_z = (b[ray->enter_z] - (float4)(ray->o.z)) * ray->inv_d.z;
    const float4 leave_x = (b[3 - ray->enter_x] - (float4)(ray->o.x)) * ray->inv_d.x;
    const float4 leave_y = (b[5 - ray->enter_y] - (float4)(ray->o.y)) * ray->inv_d.y;
    const float4 leave_z = (b[7 - ray->enter_z] - (float4)(ray->o.z)) * ray->inv_d.z;
    const float4 enter = ORB_MAX(ORB_MAX(enter_x, enter_y), ORB_MAX(enter_z, (float4)(0.0f)));
    const float4 leave = ORB_MIN(ORB_MIN(leave_x, leave_y), ORB_MIN(leave_z, (float4)(t_max)));
    *entry = enter;
    return enter <= leave;
}

// Orders two (entry, child) pairs so that the nearer comes first.
inline void order_pair(float* e0, int* c0, float* e1, int* c1)
{
    const bool swap = *e1 < *e0;
    const float e = *e0;
    const int c = *c0;
    *e0 = swap ? *e1 : *e0;
    *c0 = swap ? *c1 : *c0;
    *e1 = swap ? e : *e1;
    *c1 = swap ? c : *c1;
}

// The children of `node` whose boxes the ray enters before t_max, nearest
// first: returns how many, and in the first that many lanes of *child and
// *entry the children (as BvhNodeRecord::child) and their entry distances.
inline int hit_children(SCENE_MEM const BvhNodeRecord* node, const BoxRay* ray, float t_max, int4* child, float4* entry)
{
    float4 enter;
    const int4 hit = child_boxes(node, ray, t_max, &enter);
    // Missed children sort last: FLT_MAX is beyond every hit's entry (<= t_max <= 1e30).
    enter = select((float4)(FLT_MAX), enter, hit);
    const int4 c = node->child;
    float e0 = enter.x, e1 = enter.y, e2 = enter.z, e3 = enter.w;
    int c0 = c.x, c1 = c.y, c2 = c.z, c3 = c.w;
    // A sorting network of four.
    order_pair(&e0, &c0, &e1, &c1);
    order_pair(&e2, &c2, &e3, &c3);
    order_pair(&e0, &c0, &e2, &c2);
    order_pair(&e1, &c1, &e3, &c3);
    order_pair(&e1, &c1, &e2, &c2);
    *child = (int4)(c0, c1, c2, c3);
    *entry = (float4)(e0, e1, e2, e3);
    return -(hit.x + hit.y + hit.z + hit.w);
}

// Pushes sorted hit children 1..count-1 (and their entry distances, when
// `entries` is not null), farthest first, so the nearest is on top. CPUs
// store three entries whatever the count, without a branch per child (two
// spare stack entries take the unused ones); GPUs store only the children
// pushed, as predicated stores, since every store there is local-memory
// traffic. Returns the new top.
inline int push_deferred(int* children, float* entries, int top, int4 c, float4 e, int count)
{
#if ORB_SCALAR_TRAVERSAL
    if (count > 3) {
        children[top] = c.w;
        if (entries) entries[top] = e.w;
        ++top;
    }
    if (count > 2) {
        children[top] = c.z;
        if (entries) entries[top] = e.z;
        ++top;
    }
    if (count > 1) {
        children[top] = c.y;
        if (entries) entries[top] = e.y;
        ++top;
    }
    return top;
#else
    children[top] = count > 3 ? c.w : count > 2 ? c.z : c.y;
    children[top + 1] = count > 3 ? c.z : c.y;
    children[top + 2] = c.y;
    if (entries) {
        entries[top] = count > 3 ? e.w : count > 2 ? e.z : e.y;
        entries[top + 1] = count > 3 ? e.z : e.y;
        entries[top + 2] = e.y;
    }
    return top + count - 1;
#endif
}

// Development knob: ORB_BVH_CHECK 1 (-DORB_BVH_CHECK=1 through
// ORB_CL_OPTIONS) checks every index the traversals read (nodes, packets,
// stack entries) before reading, and reports the first violation of a ray
// with printf and gives up the ray instead of reading out of bounds.
// ORB_BVH_CHECK_STACK, when positive, lowers the stack limit it checks
// against (tests/render/bvh_render_test.cpp shows with a small one that
// violations are reported). Off by default: no cost.
// Leaf runs (CPUs): a node whose children are all leaves tests their
// packets straight away (BvhNodeRecord::leaf_run), four spheres per vector
// instruction, instead of testing the four boxes, ordering the hit ones and
// visiting them one by one. A visit there is a chain of dependent steps and
// branches; the spheres are a few branch-free vector tests, more arithmetic
// than the boxes would have let through but less time
// (docs/design/simd-lanes.md). GPUs test one sphere at a time,
// so for them the boxes stay: the host turns ORB_BVH_LEAF_RUNS off where it
// turns ORB_SCALAR_TRAVERSAL on.
#define ORB_BVH_STACK_LIMIT (ORB_BVH_CHECK_STACK > 0 ? ORB_BVH_CHECK_STACK : ORB_BVH_STACK_SIZE)
#if ORB_BVH_CHECK
#define ORB_BVH_EXPECT(ok, what, value, limit, give_up)                                        \
    if (!(ok)) {                                                                               \
        printf("orb BVH check: %s %d out of range (limit %d)\n", what, (int)(value), (int)(limit)); \
        give_up;                                                                               \
    }
#else
#define ORB_BVH_EXPECT(ok, what, value, limit, give_up)
#endif

// Development knob: ORB_BVH_COUNT 1 (-DORB_BVH_COUNT=1 through
// ORB_CL_OPTIONS) prints, for every ray that enters the tree, how many nodes
// and leaves its traversal visited: "orb BVH visits: closest N" or "orb BVH
// visits: shadow N". scripts/bvh-visits.sh sums them per sample. Off by
// default: no cost.
// ORB_TRAVERSAL_RETURN ends a traversal (traverse_tree below), printing
// its count first.
#if ORB_BVH_COUNT
#define ORB_BVH_VISITS_BEGIN int bvh_visits = 0;
#define ORB_BVH_VISIT ++bvh_visits;
#define ORB_TRAVERSAL_RETURN(blocked)                                      \
    {                                                                    \
        if (any_hit) printf("orb BVH visits: shadow %d\n", bvh_visits); \
        else printf("orb BVH visits: closest %d\n", bvh_visits);        \
        return blocked;                                                  \
    }
#else
#define ORB_BVH_VISITS_BEGIN
#define ORB_BVH_VISIT
#define ORB_TRAVERSAL_RETURN(blocked) return blocked;
#endif

// One traversal serves both kinds of ray. any_hit false: the closest hit
// (`best` is kept; children are visited nearest first, deferred ones are
// stacked with their entry distances, and a popped child that starts beyond
// the closest hit found by then is dropped). any_hit true: a shadow ray,
// whether a sphere other than `light` lies along the ray before t_light;
// children are still visited nearest first, since in a dense cloud the
// blocker is usually near the ray's origin, and the first blocker ends the
// search. Every caller passes any_hit as a constant, so each inlined copy
// keeps only its own branches (and the closest hit's entry stack is gone
// from the shadow rays' copy). `current` is a node (>= 0) or a leaf (< 0,
// its packet -1 - current), as in BvhNodeRecord::child. Returns true when a
// shadow ray is blocked, or when a bounds check gives up on the ray.

// Tests leaf packet `packet` for what the traversal looks for; true when a
// shadow ray is blocked by it.
inline bool leaf_ends_search(BestHit* best, const SceneView* scene, int packet, float3 o, float3 d, int self,
                             const bool any_hit, int light, float t_light)
{
    if (any_hit) return packet_blocks(&scene->packets[packet], 4 * packet, o, d, self, light, t_light);
    test_packet(best, &scene->packets[packet], 4 * packet, o, d, self);
    return false;
}

// How far along the ray a child may start and still matter.
inline float search_limit(const BestHit* best, const bool any_hit, float t_light)
{
    return any_hit ? t_light : best_distance(best);
}

#define ORB_TRAVERSAL_DONE 0x7fffffff  // what pop_deferred returns once the stack is empty

// The nearest deferred child that can still matter, taken off the stack: a
// closest-hit traversal first drops the children that start beyond the
// closest hit found so far (a shadow ray keeps no entry distances).
inline int pop_deferred(const BestHit* best, const int* children, const float* entries, int* top, const bool any_hit)
{
    if (!any_hit) {
        const float t_best = best_distance(best);
        while (*top > 0 && entries[*top - 1] >= t_best) --*top;
    }
    return *top > 0 ? children[--*top] : ORB_TRAVERSAL_DONE;
}

// The traversal: nearest hit child first, the others deferred on a stack.
// Where a warp vote exists (ORB_WARP_VOTE, warp_vote.cl: NVIDIA), it
// speculates (Aila and Laine, "Understanding the Efficiency of Ray Traversal
// on GPUs", 2009): a lane that reaches a leaf postpones it and goes on
// through the tree's inner nodes until every converged lane of its warp
// holds a leaf; then the warp tests leaves together, each lane its postponed
// one and, if its traversal stands on leaves too, those. Nsight Compute
// showed the ordered traversal testing leaves with 2 to 3 of a warp's 32
// lanes at a million spheres; speculation gave 4% more samples/s on an H100
// at 1 k to 1 M spheres (docs/design/speculative-traversal.md). Without a
// vote the traversal is ordered: each leaf is tested as soon as it is
// reached, and the next deferred child popped after its test, so that what
// the test found culls it. Speculating, the next deferred child is popped as
// a leaf is taken up, before its test. Visits made while a leaf waits only
// cull less, so the hits are the same.
//
// The inner node's step is one text (ORB_TRAVERSAL_NODE_STEP) in the two
// walks' loops, which keep the shapes of their hand-written originals: a
// single loop with one test of the kind of `current` per step (ordered),
// inner nodes then leaves (speculating). One loop for both, or popping after
// the test while speculating, gave NVIDIA's compiler more registers and
// branches (docs/design/one-path-tracer-over-lanes.md).
//
// ORB_TRAVERSAL_NODE_STEP(after_push, after_none): visits inner node
// `current`: a leaf run's packets (CPUs) or the boxes of its children, the
// hit ones pushed nearest on top and the nearest taken as `current`; then
// `after_push`, or `after_none` where no child was pushed.
#define ORB_TRAVERSAL_NODE_STEP(after_push, after_none)                                                          \
    ORB_BVH_EXPECT(current < scene->bvh_node_count, "node", current, scene->bvh_node_count, return true)         \
    const int4 run = ORB_BVH_LEAF_RUNS ? scene->bvh_nodes[current].leaf_run : (int4)(-1);                       \
    if (run.x >= 0) {                                                                                          \
        ORB_BVH_EXPECT(run.x + run.y <= scene->packet_count, "leaf run", run.x + run.y - 1, scene->packet_count, \
                       return true)                                                                            \
        for (int k = run.x; k < run.x + run.y; ++k)                                                            \
            if (leaf_ends_search(best, scene, k, o, d, self, any_hit, light, t_light)) ORB_TRAVERSAL_RETURN(true) \
        after_none                                                                                             \
    } else {                                                                                                   \
        int4 child;                                                                                            \
        float4 entry;                                                                                          \
        const int count =                                                                                      \
            hit_children(&scene->bvh_nodes[current], ray, search_limit(best, any_hit, t_light), &child, &entry);  \
        if (count > 0) {                                                                                       \
            ORB_BVH_EXPECT(top + count - 1 <= ORB_BVH_STACK_LIMIT, "stack top", top + count - 1,               \
                           ORB_BVH_STACK_LIMIT, return true)                                                   \
            top = push_deferred(stack_child, any_hit ? 0 : stack_entry, top, child, entry, count);             \
            current = child.x;                                                                                 \
            after_push                                                                                         \
        } else {                                                                                               \
            after_none                                                                                         \
        }                                                                                                      \
    }
#define ORB_TRAVERSAL_POP current = pop_deferred(best, stack_child, stack_entry, &top, any_hit);
// Tests leaf `leaf` (< 0: packet -1 - leaf).
#define ORB_TRAVERSAL_LEAF_STEP(leaf)                                                                          \
    const int packet = -1 - (leaf);                                                                            \
    ORB_BVH_EXPECT(packet < scene->packet_count, "leaf packet", packet, scene->packet_count, return true)       \
    if (leaf_ends_search(best, scene, packet, o, d, self, any_hit, light, t_light)) ORB_TRAVERSAL_RETURN(true)

inline bool traverse_tree(BestHit* best, const SceneView* scene, const BoxRay* ray, float3 o, float3 d, int self,
                          const bool any_hit, int light, float t_light)
{
    // Two spare entries: a push may write three children whatever their count.
    int stack_child[ORB_BVH_STACK_SIZE + 2];
    float stack_entry[ORB_BVH_STACK_SIZE + 2];  // closest hits only
    int top = 0;
    int current = 0;
    ORB_BVH_VISITS_BEGIN
#if ORB_WARP_VOTE
    int leaf = 0;  // the leaf to test next (< 0): postponed, or taken up for the leaf phase; 0 for none
    for (;;) {
        // Inner nodes, until every converged lane of the warp holds a leaf
        // or the ray's stack is empty.
        while (current >= 0 && current != ORB_TRAVERSAL_DONE) {
            ORB_BVH_VISIT
            ORB_TRAVERSAL_NODE_STEP(, ORB_TRAVERSAL_POP)
            if (current < 0 && leaf == 0) {
                leaf = current;
                ORB_TRAVERSAL_POP
            }
            if (!warp_any(leaf == 0)) break;
        }
        // Leaves: the postponed one, then each the traversal stands on.
        if (leaf == 0 && current < 0) {
            leaf = current;
            ORB_TRAVERSAL_POP
        }
        while (leaf < 0) {
            ORB_BVH_VISIT
            ORB_TRAVERSAL_LEAF_STEP(leaf)
            leaf = 0;
            if (current < 0) {
                leaf = current;
                ORB_TRAVERSAL_POP
            }
        }
        if (current == ORB_TRAVERSAL_DONE) ORB_TRAVERSAL_RETURN(false)
    }
#else
    for (;;) {
        ORB_BVH_VISIT
        if (current < 0) {
            ORB_TRAVERSAL_LEAF_STEP(current)
        } else {
            ORB_TRAVERSAL_NODE_STEP(continue;, )
        }
        ORB_TRAVERSAL_POP
        if (current == ORB_TRAVERSAL_DONE) ORB_TRAVERSAL_RETURN(false)
    }
#endif
}

// Closest hit in the tree, kept in `best`.
inline void traverse_bvh(BestHit* best, const SceneView* scene, float3 o, float3 d, int self)
{
    const BoxRay ray = box_ray(o, d);
    traverse_tree(best, scene, &ray, o, d, self, false, -1, ORB_NO_HIT);
}

inline Hit intersect_scene(const SceneView* scene, float3 o, float3 d, int self)
{
    BestHit best;
    best_init(&best);
    for (int p = 0; p < scene->outside_packet_count; ++p) test_packet(&best, &scene->packets[p], 4 * p, o, d, self);
#if ORB_BVH
    // A ray with a NaN or infinite component hits no sphere (every distance
    // is NaN, so no test passes), but every box test passes: skip the tree
    // rather than visit all of it to find nothing.
    const bool finite_ray = all(isfinite(o)) && all(isfinite(d));
#if ORB_BVH_CHECK
    if (!finite_ray) printf("orb BVH check: a ray with a non-finite origin or direction\n");
#endif
    if (scene->bvh_node_count > 0 && finite_ray) traverse_bvh(&best, scene, o, d, self);
#endif
    return best_hit(&best);
}

// Distance along the ray to sphere slot `id` by the scalar form of the
// test, or ORB_NO_HIT when the ray misses it.
inline float sphere_distance(const SceneView* scene, int id, float3 o, float3 d, int self)
{
    ORB_BVH_EXPECT(id >= 0 && id < scene->sphere_count, "light sphere", id, scene->sphere_count, return ORB_NO_HIT)
    return packet_sphere_distance(&scene->packets[id >> 2], id & 3, id, o, d, self);
}

// Shadow rays: whether sphere `light` is the first thing along the ray. Any
// other sphere hit before it ends the search at once (traverse_tree's any-hit
// mode), which in a dense cloud is usually within a few nodes.
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
    const BoxRay ray = box_ray(o, d);
    return !traverse_tree(0, scene, &ray, o, d, self, true, light, t_light);
#endif
}
