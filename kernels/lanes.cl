// The lane types: the path tracer (integrator.cl), the BSDFs, lights,
// camera, sampler and film are written once over these, in the masked style
// of Mitsuba 3's path.cpp, and each program is built for one width
// (docs/design/work-decomposition.md, "Lanes"): -DORB_LANES=1 on GPUs, where a work-item is
// one camera path and the hardware already runs work-items in its lanes;
// 4, 8 or 16 on CPUs, where PoCL runs a work-item as scalar code and only
// vector types fill the SIMD units, so a work-item carries ORB_LANES camera
// paths, one per vector lane.
//
//   lfloat, lint, luint  a number per lane (float, int, uint at width 1)
//   lmask                a condition per lane (a bool at width 1)
//   lv3                  a 3-vector per lane (float3 at width 1, so the GPU
//                        code is plain float3 arithmetic; a struct of three
//                        lfloat otherwise). Both have fields .x .y .z.
//   llong                a 64-bit integer per lane (long at width 1): the
//                        film's sums (film.cl)
//
// Masks follow OpenCL C: a scalar comparison gives 1 (true as a bool), a
// vector comparison -1 in each true lane. Shared code touches masks only through the helpers
// below (never ~, any() or arithmetic on a raw mask), which are right for
// both kinds.
//
// What is per lane by nature (tree traversal, the environment map's
// searches, the centre-ray channels) takes scalars, and at width > 1 runs in
// a loop over the lanes (ORB_FOR_EACH_LANE, lane_f / set_lane_f, ...).

// A 3-vector as three vectors of numbers F (one component each): the type
// V3 and its arithmetic under the prefix P (P##_make, P##_sub, ...), for text
// written once over 3-vectors (the lanes' lv3 below; the packets of four
// spheres in intersect.cl). Q qualifies the functions: everything over
// vectors is inlined (LANE_FN, below). The compiler fuses a multiply and an
// add (-cl-mad-enable) only within one expression, so a composition of these
// (P##_sub of P##_scale) rounds otherwise than P##_sub_scaled, a - s b.
// The scale comes first in its product, as the hand-written ray-sphere tests
// had it (oc - b d): the value is the same either way, but in PTX (clang's,
// compiled offline) a - b s had the negated ray direction hoisted out of the
// traversal, three more registers live across it, where a - s b negates the
// scale inside each fused multiply-add (docs/design/one-path-tracer-over-lanes.md).
#define ORB_DEFINE_V3_OF(Q, F, V3, P)                                                          \
    typedef struct {                                                                           \
        F x, y, z;                                                                             \
    } V3;                                                                                      \
    Q V3 P##_make(F x, F y, F z)                                                               \
    {                                                                                          \
        V3 r;                                                                                  \
        r.x = x;                                                                               \
        r.y = y;                                                                               \
        r.z = z;                                                                               \
        return r;                                                                              \
    }                                                                                          \
    Q V3 P##_splat(float3 v) { return P##_make((F)(v.x), (F)(v.y), (F)(v.z)); }                \
    Q V3 P##_add(V3 a, V3 b) { return P##_make(a.x + b.x, a.y + b.y, a.z + b.z); }             \
    Q V3 P##_sub(V3 a, V3 b) { return P##_make(a.x - b.x, a.y - b.y, a.z - b.z); }             \
    Q V3 P##_mul(V3 a, V3 b) { return P##_make(a.x * b.x, a.y * b.y, a.z * b.z); }             \
    Q V3 P##_scale(V3 a, F s) { return P##_make(a.x * s, a.y * s, a.z * s); }                  \
    Q V3 P##_neg(V3 a) { return P##_make(-a.x, -a.y, -a.z); }                                  \
    Q F P##_dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }                      \
    Q V3 P##_sub_scaled(V3 a, V3 b, F s) { return P##_make(a.x - s * b.x, a.y - s * b.y, a.z - s * b.z); }

#if ORB_LANES == 1

typedef float lfloat;
typedef int lint;
typedef uint luint;
typedef long llong;
// A bool, not an int: with an int mask NVIDIA's OpenCL compiler (driver
// 580) combined the masks as 32-bit integers (and.b32) and compared them
// with 0 again before each select and branch, and the program ran 13%
// slower than the scalar kernel on the Cornell box on an H100; as a bool the
// masks are predicates and it runs as fast
// (docs/design/one-path-tracer-over-lanes.md, "Measured on an H100").
typedef bool lmask;
typedef float3 lv3;

// GPUs inline by themselves; the attribute is for PoCL (below).
#define LANE_FN inline

#define lanes_any(m) ((m) != 0)
#define lanes_all(m) ((m) != 0)
#define mask_not(m) (!(m))
#define mask_of(condition) ((condition) ? 1 : 0)
#define lselect(a, b, m) ((m) ? (b) : (a))
#define lv3_select(a, b, m) ((m) ? (b) : (a))

#define to_lfloat(x) ((float)(x))
#define to_lint(x) ((int)(x))
#define to_luint(x) ((uint)(x))
#define to_llong(x) convert_long(x)

#define lv3_make(x, y, z) ((float3)((x), (y), (z)))
#define lv3_splat(v) (v)
#define lv3_zero() ((float3)(0.0f))
#define lv3_fill(x) ((float3)(x))
#define lv3_add(a, b) ((a) + (b))
#define lv3_sub(a, b) ((a) - (b))
#define lv3_mul(a, b) ((a) * (b))
#define lv3_scale(a, s) ((a) * (s))
#define lv3_neg(a) (-(a))
#define lv3_dot(a, b) dot(a, b)
#define lv3_normalize(a) normalize(a)
#define lv3_cross(a, b) cross(a, b)

// Lane l of a value, and setting it (l is 0).
#define lane_f(v, l) (v)
#define lane_i(v, l) (v)
#define lane_l(v, l) (v)
#define lane_v3(v, l) (v)
#define lane_on(m, l) ((m) != 0)
#define set_lane_f(v, l, value) ((v) = (value))
#define set_lane_i(v, l, value) ((v) = (value))
#define set_lane_v3(v, l, value) ((v) = (value))
// The lane index of each lane.
#define lane_index() 0
// table[index] (index in [0, count) wherever it is read).
#define lanes_gather(table, index, count) ((table)[index])

#else  // ORB_LANES > 1

#if ORB_LANES != 4 && ORB_LANES != 8 && ORB_LANES != 16
#error "ORB_LANES must be 1, 4, 8 or 16"
#endif
#define ORB_LANE_TYPE_(type, width) type##width
#define ORB_LANE_TYPE(type, width) ORB_LANE_TYPE_(type, width)
typedef ORB_LANE_TYPE(float, ORB_LANES) lfloat;
typedef ORB_LANE_TYPE(int, ORB_LANES) lint;
typedef ORB_LANE_TYPE(uint, ORB_LANES) luint;
typedef ORB_LANE_TYPE(long, ORB_LANES) llong;
typedef lint lmask;  // -1 or 0 per lane

// Everything over lanes is inlined: PoCL passes the vectors of a call that
// is not through memory, which costs more than the arithmetic.
#define LANE_FN inline __attribute__((always_inline))

// Whether any (all) lanes of a mask are on. A vector mask is 0 or -1 in
// every lane (a comparison's, or the helpers' below), so the lanes' OR (AND)
// is nonzero exactly then. Clang's reduction builtins let LLVM test the
// compare's mask register at once (kortest on AVX-512): on PoCL at 16
// lanes, 8% fewer instructions in the programs of cornell.scn and
// caustic.scn, and 2-3% more samples/s on caustic.scn, than OR-ing the
// halves as the fallback below does. PoCL's own any()
// and all() test the lanes one by one with a branch each, which in a path
// tracer that asks this at every step cost as much as the arithmetic it
// guards (docs/design/one-path-tracer-over-lanes.md).
#define ORB_LANES_REDUCE_BUILTINS 0
#ifdef __has_builtin
#if __has_builtin(__builtin_reduce_or) && __has_builtin(__builtin_reduce_and)
#undef ORB_LANES_REDUCE_BUILTINS
#define ORB_LANES_REDUCE_BUILTINS 1
#endif
#endif
#if ORB_LANES_REDUCE_BUILTINS
LANE_FN bool lanes_any(lint m) { return __builtin_reduce_or(m) != 0; }
LANE_FN bool lanes_all(lint m) { return __builtin_reduce_and(m) != 0; }
#else
#define ORB_DEFINE_LANES_REDUCE(op, name)                       \
    LANE_FN bool name(lint m)                                   \
    {                                                           \
        ORB_LANES_REDUCE_STEPS(op)                              \
        return (r.x op r.y) < 0;                                \
    }
#if ORB_LANES == 16
#define ORB_LANES_REDUCE_STEPS(op)             \
    const int8 h8 = m.lo op m.hi;              \
    const int4 h4 = h8.lo op h8.hi;            \
    const int2 r = h4.lo op h4.hi;
#elif ORB_LANES == 8
#define ORB_LANES_REDUCE_STEPS(op)             \
    const int4 h4 = m.lo op m.hi;              \
    const int2 r = h4.lo op h4.hi;
#else
#define ORB_LANES_REDUCE_STEPS(op) const int2 r = m.lo op m.hi;
#endif
ORB_DEFINE_LANES_REDUCE(|, lanes_any)
ORB_DEFINE_LANES_REDUCE(&, lanes_all)
#endif
#define mask_not(m) (~(m))
#define mask_of(condition) ((lint)((condition) ? -1 : 0))
#define lselect(a, b, m) select(a, b, m)

#define to_lfloat(x) ORB_LANE_TYPE(convert_float, ORB_LANES)(x)
#define to_lint(x) ORB_LANE_TYPE(convert_int, ORB_LANES)(x)
#define to_luint(x) ORB_LANE_TYPE(convert_uint, ORB_LANES)(x)
#define to_llong(x) ORB_LANE_TYPE(convert_long, ORB_LANES)(x)

ORB_DEFINE_V3_OF(LANE_FN, lfloat, lv3, lv3)
LANE_FN lv3 lv3_zero(void) { return lv3_make((lfloat)(0.0f), (lfloat)(0.0f), (lfloat)(0.0f)); }
// Every component of every lane x (a float or an lfloat).
#define lv3_fill(x) lv3_make((lfloat)(x), (lfloat)(x), (lfloat)(x))
LANE_FN lv3 lv3_normalize(lv3 a) { return lv3_scale(a, rsqrt(lv3_dot(a, a))); }
LANE_FN lv3 lv3_cross(lv3 a, lv3 b)
{
    return lv3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
// b where m, else a.
LANE_FN lv3 lv3_select(lv3 a, lv3 b, lmask m)
{
    return lv3_make(select(a.x, b.x, m), select(a.y, b.y, m), select(a.z, b.z, m));
}

// Lane l of a value, and setting it: through the vector's memory, which
// LLVM keeps in registers where l is a loop counter it unrolls.
#define lane_f(v, l) (((const float*)&(v))[l])
#define lane_i(v, l) (((const int*)&(v))[l])
#define lane_l(v, l) (((const long*)&(v))[l])
#define lane_v3(v, l) ((float3)(lane_f((v).x, l), lane_f((v).y, l), lane_f((v).z, l)))
#define lane_on(m, l) (lane_i(m, l) != 0)
#define set_lane_f(v, l, value) (((float*)&(v))[l] = (value))
#define set_lane_i(v, l, value) (((int*)&(v))[l] = (value))
#define set_lane_v3(v, l, value)                  \
    do {                                          \
        const float3 lane_value_ = (value);       \
        set_lane_f((v).x, l, lane_value_.x);      \
        set_lane_f((v).y, l, lane_value_.y);      \
        set_lane_f((v).z, l, lane_value_.z);      \
    } while (0)

#if ORB_LANES == 16
#define lane_index() ((lint)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))
#elif ORB_LANES == 8
#define lane_index() ((lint)(0, 1, 2, 3, 4, 5, 6, 7))
#else
#define lane_index() ((lint)(0, 1, 2, 3))
#endif

// table[index] for each lane. Lanes that do not use the result may hold
// any index (their inputs are what a lane without a path left there), so
// each is clamped into the table.
#define lanes_gather(table, index, count) lanes_gather_((table), (index), (count))
#define ORB_DEFINE_LANES_GATHER(space, name)                                   \
    LANE_FN lfloat name(space const float* table, lint index, int count)       \
    {                                                                          \
        const lint clamped = clamp(index, (lint)(0), (lint)(count - 1));       \
        lfloat r;                                                              \
        for (int l = 0; l < ORB_LANES; ++l) set_lane_f(r, l, table[lane_i(clamped, l)]); \
        return r;                                                              \
    }
ORB_DEFINE_LANES_GATHER(__constant, lanes_gather_)

#endif  // ORB_LANES

// Both widths.

// Whether to run a cheap step for the lanes in m: at width 1 the path's
// own branch; at width > 1 always, the step masked. At 16 lanes some lane
// almost always needs such a step, and the branch (the lanes' OR, a jump
// the lanes' data decide) cost more than the step: on PoCL, running the
// continuation's strategies, the light's two direction samplers, the caster
// cone test and the roulette so, with the unmasked table selects of
// scene.cl, gave caustic.scn 3-4% more samples/s
// (docs/design/one-path-tracer-over-lanes.md).
#define lanes_step(m) (ORB_LANES > 1 || lanes_any(m))

// The float3 operations under the names of lv3's (f3_ for lv3_), for text
// written once over either, such as camera_ray (camera.cl; the centre-ray
// channels cast one scalar ray per pixel at every width) and the ray-sphere
// test (intersect.cl).
#define f3_make(x, y, z) ((float3)((x), (y), (z)))
#define f3_splat(v) (v)
#define f3_add(a, b) ((a) + (b))
#define f3_sub(a, b) ((a) - (b))
#define f3_scale(a, s) ((a) * (s))
#define f3_dot(a, b) dot(a, b)
#define f3_sub_scaled(a, b, s) ((a) - (s) * (b))
#define f3_normalize(a) normalize(a)
#define mask_and(a, b) ((a) & (b))
#define mask_or(a, b) ((a) | (b))
#define mask_and_not(a, b) ((a) & mask_not(b))
#define lv3_sum(a) ((a).x + (a).y + (a).z)
#define lv3_max(a) fmax((a).x, fmax((a).y, (a).z))
// a + b where m.
#define lv3_add_where(a, b, m) lv3_select(a, lv3_add(a, b), m)

// The body that follows runs once per lane l of `mask` that is on, with
// scalars: at width 1 once when the mask is (l is 0).
#define ORB_FOR_EACH_LANE(l, mask) \
    for (int l = 0; l < ORB_LANES; ++l) \
        if (lane_on(mask, l))
