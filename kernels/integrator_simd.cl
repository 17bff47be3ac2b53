// The path tracer of integrator.cl with ORB_LANES camera paths in the
// SIMD lanes of one work-item, for CPUs (docs/rendering.md, "SIMD lanes on
// CPUs"). PoCL runs each work-item's path as scalar code: the megakernel's
// loops and branches keep LLVM from vectorising across work-items, so a
// 16-lane AVX-512 core did one path at a time. Here lane l of work-item
// (gx, y) is pixel (gx * ORB_LANES + l, y), each lane loops over the
// pass's samples with its own path regeneration, and every step is vector
// arithmetic over all lanes with masks where the lanes' paths differ.
//
// The estimator is the scalar kernel's, step for step: the same sample
// numbers (the same Sobol and Philox draws for each pixel, sample and
// block), next-event estimation with the power heuristic, the continuation's
// mixture aimed at casters (caustic_casters.cl), Russian roulette with the
// refraction factor divided out, the same split of light into the emission,
// direct and indirect channels, in both modes. The BSDF formulas of
// bsdf_diffuse.cl, bsdf_mirror.cl and bsdf_dielectric.cl (smooth case) are
// written over lanes; what is per lane by nature -- tree traversal, the
// environment's map lookups and searches, and the shading of pbr and rough
// glass vertices -- calls render_pass's functions lane by lane. The host
// uses it for every scene on CPUs (librender/src/device_renderer.cpp).
// tests/render/simd_kernel_test.cpp renders scenes with both kernels and
// requires the same paths.

#if ORB_LANES > 1

#define ORB_VEC_NAME_(type, width) type##width
#define ORB_VEC_NAME(type, width) ORB_VEC_NAME_(type, width)
typedef ORB_VEC_NAME(float, ORB_LANES) vfloat;
typedef ORB_VEC_NAME(int, ORB_LANES) vint;
typedef ORB_VEC_NAME(uint, ORB_LANES) vuint;
#define vload_lanes ORB_VEC_NAME(vload, ORB_LANES)
#define vstore_lanes ORB_VEC_NAME(vstore, ORB_LANES)
#define to_vfloat ORB_VEC_NAME(convert_float, ORB_LANES)
#define vint_from_float ORB_VEC_NAME(convert_int, ORB_LANES)
#define vuint_from_int ORB_VEC_NAME(convert_uint, ORB_LANES)
#if ORB_LANES == 16
#define ORB_LANE_INDEX ((vint)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))
#elif ORB_LANES == 8
#define ORB_LANE_INDEX ((vint)(0, 1, 2, 3, 4, 5, 6, 7))
#elif ORB_LANES == 4
#define ORB_LANE_INDEX ((vint)(0, 1, 2, 3))
#else
#error "ORB_LANES must be 4, 8 or 16"
#endif

// Everything here is inlined: PoCL passes the vectors of a call that is not
// through memory, which costs more than the arithmetic.
#define SIMD_FN inline __attribute__((always_inline))

// Masks are vint lanes of -1 (true) or 0, as OpenCL's vector comparisons give.

// ---- Three-vectors over lanes ----
typedef struct {
    vfloat x, y, z;
} v3;

SIMD_FN v3 v3_make(vfloat x, vfloat y, vfloat z)
{
    v3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}
SIMD_FN v3 v3_splat(float3 s) { return v3_make((vfloat)(s.x), (vfloat)(s.y), (vfloat)(s.z)); }
SIMD_FN v3 v3_zero(void) { return v3_make((vfloat)(0.0f), (vfloat)(0.0f), (vfloat)(0.0f)); }
SIMD_FN v3 v3_add(v3 a, v3 b) { return v3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
SIMD_FN v3 v3_sub(v3 a, v3 b) { return v3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
SIMD_FN v3 v3_mul(v3 a, v3 b) { return v3_make(a.x * b.x, a.y * b.y, a.z * b.z); }
SIMD_FN v3 v3_scale(v3 a, vfloat s) { return v3_make(a.x * s, a.y * s, a.z * s); }
SIMD_FN v3 v3_neg(v3 a) { return v3_make(-a.x, -a.y, -a.z); }
SIMD_FN vfloat v3_dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
SIMD_FN v3 v3_normalize(v3 a) { return v3_scale(a, rsqrt(v3_dot(a, a))); }
SIMD_FN vfloat v3_sum(v3 a) { return a.x + a.y + a.z; }
SIMD_FN vfloat v3_max(v3 a) { return fmax(a.x, fmax(a.y, a.z)); }
// b where m, else a.
SIMD_FN v3 v3_select(v3 a, v3 b, vint m) { return v3_make(select(a.x, b.x, m), select(a.y, b.y, m), select(a.z, b.z, m)); }
// a + b where m.
SIMD_FN v3 v3_add_where(v3 a, v3 b, vint m) { return v3_select(a, v3_add(a, b), m); }
// A v3's lanes to three arrays and back, for work done lane by lane.
SIMD_FN void v3_store_lanes(v3 v, float* x, float* y, float* z)
{
    vstore_lanes(v.x, 0, x);
    vstore_lanes(v.y, 0, y);
    vstore_lanes(v.z, 0, z);
}
SIMD_FN v3 v3_load_lanes(const float* x, const float* y, const float* z)
{
    return v3_make(vload_lanes(0, x), vload_lanes(0, y), vload_lanes(0, z));
}

// ---- The sampler over lanes (sampler.cl's functions, the same numbers) ----
ORB_DEFINE_REVERSE_BITS_SHIFTS(SIMD_FN, vuint, v_reverse_bits)
ORB_DEFINE_LK_PERMUTATION(SIMD_FN, vuint, v_lk_permutation)
ORB_DEFINE_MIX32(SIMD_FN, vuint, v_mix32)
ORB_DEFINE_SOBOL_DIMENSION1_REVERSED(SIMD_FN, vuint, v_sobol_dimension1_reversed)

SIMD_FN vfloat v_unit_from_bits(vuint bits24) { return to_vfloat(bits24) * 0x1p-24f; }

// Where each lane's current sample takes its numbers from (SampleCoords).
typedef struct {
    vuint pixel;
    vuint sample_lo, sample_hi;
    vuint key;         // Sobol seeds derive from it
    vuint i_reversed;  // sample_lo, bit-reversed
} VCoords;

SIMD_FN VCoords v_sample_coords(vuint pixel, vuint pixel_key, uint first_lo, uint first_hi, vint index)
{
    VCoords c;
    c.pixel = pixel;
    c.sample_lo = (vuint)(first_lo) + vuint_from_int(index);
    c.sample_hi = (vuint)(first_hi) + select((vuint)(0u), (vuint)(1u), c.sample_lo < (vuint)(first_lo));
    c.key = v_mix32(pixel_key ^ (c.sample_hi * 0x632be5abu));
    c.i_reversed = v_reverse_bits(c.sample_lo);
    return c;
}

// One block's numbers (RandBlock): Sobol lanes compute theirs when asked,
// the independent lanes' five come from one Philox call for the block.
typedef struct {
    vint sobol;  // lanes whose block draws Sobol points
    vuint block;
    vfloat u0, u1, u2, u3, u4;  // independent numbers (lanes not sobol)
} VRandBlock;

SIMD_FN void v_philox_round(vuint* c0, vuint* c1, vuint* c2, vuint* c3, uint2 key)
{
    const vuint hi0 = mul_hi((vuint)(PHILOX_M0), *c0);
    const vuint lo0 = PHILOX_M0 * *c0;
    const vuint hi1 = mul_hi((vuint)(PHILOX_M1), *c2);
    const vuint lo1 = PHILOX_M1 * *c2;
    *c0 = hi1 ^ *c1 ^ key.x;
    *c1 = lo1;
    *c2 = hi0 ^ *c3 ^ key.y;
    *c3 = lo0;
}

SIMD_FN VRandBlock v_rand_block(const VCoords* c, vuint block, vint lanes, uint2 seed)
{
    VRandBlock r;
    r.block = block;
#if ORB_SAMPLER_SOBOL
    r.sobol = block < (vuint)(ORB_SOBOL_BLOCKS);
#else
    r.sobol = (vint)(0);
#endif
    r.u0 = r.u1 = r.u2 = r.u3 = r.u4 = (vfloat)(0.5f);
    if (any(lanes & ~r.sobol)) {
        vuint c0 = block, c1 = c->sample_lo, c2 = c->sample_hi, c3 = c->pixel;
        uint2 key = seed;
        for (int i = 0; i < PHILOX_ROUNDS - 1; ++i) {
            v_philox_round(&c0, &c1, &c2, &c3, key);
            key += (uint2)(PHILOX_W0, PHILOX_W1);
        }
        v_philox_round(&c0, &c1, &c2, &c3, key);
        r.u0 = v_unit_from_bits(c0 >> 8);
        r.u1 = v_unit_from_bits(c1 >> 8);
        r.u2 = v_unit_from_bits(c2 >> 8);
        r.u3 = v_unit_from_bits(c3 >> 8);
        const vuint low = (c0 & 0xFFu) | ((c1 & 0xFFu) << 8) | ((c2 & 0xFFu) << 16) | ((c3 & 0xFFu) << 24);
        r.u4 = v_unit_from_bits(low >> 8);
    }
    return r;
}

SIMD_FN vuint v_block_seed(vuint key, vuint block, uint slot)
{
    return v_mix32(key ^ ((block * 8u + slot) * 0x9e3779b9u));
}

// Pair 0 (u0, u1) or pair 1 (u2, u3) of the block, for the lanes in `lanes`.
SIMD_FN void v_rand_pair(const VRandBlock* r, const VCoords* c, uint pair, vint lanes, vfloat* u, vfloat* v)
{
    *u = pair == 0u ? r->u0 : r->u2;
    *v = pair == 0u ? r->u1 : r->u3;
#if ORB_SAMPLER_SOBOL
    if (any(lanes & r->sobol)) {
        const uint slot = 3u * pair;
        const vuint j = v_reverse_bits(v_lk_permutation(c->i_reversed, v_block_seed(c->key, r->block, slot)));
        const vfloat su =
            v_unit_from_bits(v_reverse_bits(v_lk_permutation(j, v_block_seed(c->key, r->block, slot + 1u))) >> 8);
        const vfloat sv = v_unit_from_bits(
            v_reverse_bits(v_lk_permutation(v_sobol_dimension1_reversed(j), v_block_seed(c->key, r->block, slot + 2u))) >>
            8);
        *u = select(*u, su, r->sobol);
        *v = select(*v, sv, r->sobol);
    }
#endif
}

SIMD_FN vfloat v_rand_single(const VRandBlock* r, const VCoords* c, vint lanes)
{
    vfloat u = r->u4;
#if ORB_SAMPLER_SOBOL
    if (any(lanes & r->sobol)) {
        const vuint j = v_reverse_bits(v_lk_permutation(c->i_reversed, v_block_seed(c->key, r->block, 6u)));
        const vfloat s = v_unit_from_bits(v_reverse_bits(v_lk_permutation(j, v_block_seed(c->key, r->block, 7u))) >> 8);
        u = select(u, s, r->sobol);
    }
#endif
    return u;
}

// ---- Sampling (sampling.cl over lanes) ----
SIMD_FN void v_unit_circle(vfloat v, vfloat* cos_out, vfloat* sin_out)
{
    ORB_UNIT_CIRCLE_TERMS(vfloat, v)
    const vint quarter = vint_from_float(k) & 3;
    const vint q0 = quarter == 0, q1 = quarter == 1, odd = (quarter & 1) != 0;
    const vfloat even_c = select(-c, c, q0), even_s = select(-s, s, q0);
    const vfloat odd_c = select(s, -s, q1), odd_s = select(-c, c, q1);
    *cos_out = select(even_c, odd_c, odd);
    *sin_out = select(even_s, odd_s, odd);
}

SIMD_FN v3 v_from_local(v3 n, vfloat x, vfloat y, vfloat z)
{
    const vfloat sign = select((vfloat)(-1.0f), (vfloat)(1.0f), n.z >= 0.0f);
    const vfloat a = -1.0f / (sign + n.z);
    const vfloat c = n.x * n.y * a;
    const v3 t = v3_make(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    const v3 b = v3_make(c, sign + n.y * n.y * a, -n.y);
    return v3_add(v3_add(v3_scale(t, x), v3_scale(b, y)), v3_scale(n, z));
}

SIMD_FN v3 v_sample_cosine_hemisphere(v3 n, vfloat u, vfloat v, vfloat* cos_theta)
{
    const vfloat r = sqrt(u);
    vfloat c, s;
    v_unit_circle(v, &c, &s);
    const vfloat z = sqrt(fmax((vfloat)(0.0f), 1.0f - u));
    *cos_theta = z;
    return v_from_local(n, r * c, r * s, z);
}

SIMD_FN v3 v_sample_uniform_cone(v3 w, vfloat one_minus_cos_max, vfloat u, vfloat v)
{
    const vfloat one_minus_cos = u * one_minus_cos_max;
    const vfloat cos_theta = 1.0f - one_minus_cos;
    const vfloat sin_theta = sqrt(fmax((vfloat)(0.0f), one_minus_cos * (2.0f - one_minus_cos)));
    vfloat c, s;
    v_unit_circle(v, &c, &s);
    return v_from_local(w, sin_theta * c, sin_theta * s, cos_theta);
}

SIMD_FN v3 v_sample_uniform_sphere(vfloat u, vfloat v)
{
    const vfloat z = 1.0f - 2.0f * u;
    const vfloat r = sqrt(fmax((vfloat)(0.0f), 1.0f - z * z));
    vfloat c, s;
    v_unit_circle(v, &c, &s);
    return v3_make(r * c, r * s, z);
}

SIMD_FN vfloat v_power_heuristic(vfloat f, vfloat g)
{
    const vfloat f2 = f * f;
    return f2 / (f2 + g * g);
}

SIMD_FN vfloat v_cone_one_minus_cos(vfloat distance2, vfloat radius)
{
    const vfloat sin2 = fmin((vfloat)(1.0f), radius * radius / distance2);
    return sin2 / (1.0f + sqrt(1.0f - sin2));
}

// Picks the first lobe where u < p and rescales u as choose_lobe does.
SIMD_FN vint v_choose_lobe(vfloat p, vfloat* u)
{
    const vint first = *u < p;
    const vfloat rescaled = select((*u - p) / (1.0f - p), *u / p, first);
    *u = fmin(rescaled, 0x1.fffffep-1f);
    return first;
}

// ---- The scene over lanes ----

// The closest sphere along each lane's ray in `lanes` (intersect.cl's packet
// test, one sphere at a time for all lanes): *id -1 where nothing is hit.
SIMD_FN void v_intersect(const SceneView* scene, v3 o, v3 d, vint self, vint lanes, vfloat* t_out, vint* id_out)
{
    vfloat best = (vfloat)(ORB_NO_HIT);
    vint id = (vint)(-1);
    for (int p = 0; p < scene->outside_packet_count; ++p) {
        SCENE_MEM const SpherePacket* packet = &scene->packets[p];
        for (int lane = 0; lane < 4; ++lane) {
            const float radius2 = packet_lane(&packet->radius2, lane);
            if (radius2 < 0.0f) break;  // padding lanes come last
            const int sphere = 4 * p + lane;
            const vfloat ocx = o.x - packet_lane(&packet->centre_x, lane);
            const vfloat ocy = o.y - packet_lane(&packet->centre_y, lane);
            const vfloat ocz = o.z - packet_lane(&packet->centre_z, lane);
            const vfloat b = ocx * d.x + ocy * d.y + ocz * d.z;
            const vfloat fx = ocx - b * d.x, fy = ocy - b * d.y, fz = ocz - b * d.z;
            const vfloat disc = radius2 - (fx * fx + fy * fy + fz * fz);
            const vfloat s = sqrt(fmax(disc, (vfloat)(0.0f)));
            const vfloat t_near = -b - s;
            const vint is_self = self == sphere;
            const vfloat t = select(t_near, -b + s, is_self | (t_near <= 0.0f));
            const vint hit = (disc >= 0.0f) & (t > 0.0f) & ~(is_self & (b >= 0.0f)) & (t < best);
            best = select(best, t, hit);
            id = select(id, (vint)(sphere), hit);
        }
    }
#if ORB_BVH
    // The tree, lane by lane with render_pass's traversal: lanes' rays go
    // through different nodes, and a node's four boxes are one vector test
    // already. Each lane starts from its closest hit outside the tree, as
    // intersect_scene does, so the traversal prunes by it.
    if (scene->bvh_node_count > 0 && any(lanes)) {
        float ox[ORB_LANES], oy[ORB_LANES], oz[ORB_LANES];
        float dx[ORB_LANES], dy[ORB_LANES], dz[ORB_LANES], t_lane[ORB_LANES];
        int self_lane[ORB_LANES], id_lane[ORB_LANES], traced[ORB_LANES];
        v3_store_lanes(o, ox, oy, oz);
        v3_store_lanes(d, dx, dy, dz);
        vstore_lanes(best, 0, t_lane), vstore_lanes(id, 0, id_lane), vstore_lanes(self, 0, self_lane);
        vstore_lanes(lanes, 0, traced);
        for (int l = 0; l < ORB_LANES; ++l) {
            const float3 lane_o = (float3)(ox[l], oy[l], oz[l]), lane_d = (float3)(dx[l], dy[l], dz[l]);
            if (!traced[l] || !(all(isfinite(lane_o)) && all(isfinite(lane_d)))) continue;
            BestHit lane_best;
            best_init(&lane_best);
#if ORB_SCALAR_TRAVERSAL
            lane_best.t = t_lane[l];
            lane_best.id = id_lane[l];
#else
            lane_best.t.x = t_lane[l];
            lane_best.id.x = id_lane[l];
#endif
            traverse_bvh(&lane_best, scene, lane_o, lane_d, self_lane[l]);
            const Hit hit = best_hit(&lane_best);
            t_lane[l] = hit.t;
            id_lane[l] = hit.id;
        }
        best = vload_lanes(0, t_lane);
        id = vload_lanes(0, id_lane);
    }
#endif
    *t_out = best;
    *id_out = id;
}

// Shadow rays: whether sphere `light` is the first thing along each lane's
// ray (light_visible). Without a tree the closest hit over the few spheres
// is as quick; with one, each lane's any-hit traversal stops at the first
// blocker.
SIMD_FN vint v_light_visible(const SceneView* scene, v3 o, v3 d, vint self, vint light, vint lanes)
{
#if ORB_BVH
    if (scene->bvh_node_count > 0) {
        float ox[ORB_LANES], oy[ORB_LANES], oz[ORB_LANES];
        float dx[ORB_LANES], dy[ORB_LANES], dz[ORB_LANES];
        int self_lane[ORB_LANES], light_lane[ORB_LANES], visible[ORB_LANES];
        v3_store_lanes(o, ox, oy, oz);
        v3_store_lanes(d, dx, dy, dz);
        vstore_lanes(self, 0, self_lane), vstore_lanes(light, 0, light_lane), vstore_lanes(lanes, 0, visible);
        for (int l = 0; l < ORB_LANES; ++l)
            if (visible[l])
                visible[l] = light_visible(scene, (float3)(ox[l], oy[l], oz[l]), (float3)(dx[l], dy[l], dz[l]),
                                           self_lane[l], light_lane[l])
                                 ? -1
                                 : 0;
        return vload_lanes(0, visible);
    }
#endif
    vfloat t;
    vint first;
    v_intersect(scene, o, d, self, lanes, &t, &first);
    return lanes & (first == light);
}

// A sphere's geometry and material for each lane (load_sphere), gathered by
// one select per sphere the lanes name: these scenes have few spheres.
typedef struct {
    v3 centre;
    vfloat radius;
    v3 color;
    v3 emission;
    vfloat ior;
    vint kind;
    vfloat light_probability;
} VSphere;

// Above this many sphere slots a select per sphere costs more than
// gathering each lane's record on its own.
#define ORB_SIMD_SELECT_GATHER_MAX 64

SIMD_FN VSphere v_load_spheres(const SceneView* scene, vint id)
{
    if (scene->sphere_count > ORB_SIMD_SELECT_GATHER_MAX) {
        int ids[ORB_LANES], kind[ORB_LANES];
        float f[12][ORB_LANES];
        vstore_lanes(id, 0, ids);
        for (int l = 0; l < ORB_LANES; ++l) {
            SCENE_MEM const SphereRecord* r = &scene->spheres[max(ids[l], 0)];
            SCENE_MEM const MaterialRecord* material = &scene->materials[r->material];
            const float4 cr = r->centre_radius;
            f[0][l] = cr.x, f[1][l] = cr.y, f[2][l] = cr.z, f[3][l] = cr.w;
            f[4][l] = material->color.x, f[5][l] = material->color.y, f[6][l] = material->color.z;
            f[7][l] = material->emission.x, f[8][l] = material->emission.y, f[9][l] = material->emission.z;
            f[10][l] = material->ior;
            f[11][l] = r->light_probability;
            kind[l] = material->kind;
        }
        VSphere s;
        s.centre = v3_load_lanes(f[0], f[1], f[2]);
        s.radius = vload_lanes(0, f[3]);
        s.color = v3_load_lanes(f[4], f[5], f[6]);
        s.emission = v3_load_lanes(f[7], f[8], f[9]);
        s.ior = vload_lanes(0, f[10]);
        s.light_probability = vload_lanes(0, f[11]);
        s.kind = vload_lanes(0, kind);
        return s;
    }
    VSphere s;
    s.centre = v3_zero();
    s.radius = (vfloat)(1.0f);
    s.color = v3_zero();
    s.emission = v3_zero();
    s.ior = (vfloat)(1.0f);
    s.kind = (vint)(MaterialKind_Diffuse);
    s.light_probability = (vfloat)(0.0f);
    for (int i = 0; i < scene->sphere_count; ++i) {
        const vint m = id == i;
        if (!any(m)) continue;
        SCENE_MEM const SphereRecord* r = &scene->spheres[i];
        SCENE_MEM const MaterialRecord* material = &scene->materials[r->material];
        const float4 cr = r->centre_radius;
        s.centre = v3_select(s.centre, v3_splat(cr.xyz), m);
        s.radius = select(s.radius, (vfloat)(cr.w), m);
        s.color = v3_select(s.color, v3_splat(material->color.xyz), m);
        s.emission = v3_select(s.emission, v3_splat(material->emission.xyz), m);
        s.ior = select(s.ior, (vfloat)(material->ior), m);
        s.kind = select(s.kind, (vint)(material->kind), m);
        s.light_probability = select(s.light_probability, (vfloat)(r->light_probability), m);
    }
    return s;
}

// light_direction_pdf over lanes.
SIMD_FN vfloat v_light_direction_pdf(v3 p, vint self, vint light, v3 centre, vfloat radius)
{
    const v3 pc = v3_sub(centre, p);
    const vfloat distance2 = v3_dot(pc, pc);
    const vint surrounds = (self == light) | (distance2 <= radius * radius);
    return select(1.0f / (2.0f * ORB_PI * v_cone_one_minus_cos(distance2, radius)), (vfloat)(ORB_INV_4PI), surrounds);
}

// continuation_pdf over lanes: the density of wi under the continuation's
// mixture at p, for a BSDF whose own sampling gives wi the density bsdf_pdf.
SIMD_FN vfloat v_continuation_pdf(const SceneView* scene, v3 p, vfloat bsdf_pdf, v3 wi)
{
    const int count = scene->caster_count;
    if (ORB_CASTER_SHARE <= 0.0f || count == 0) return bsdf_pdf;
    vfloat cones = (vfloat)(0.0f);
    for (int k = 0; k < count; ++k) {
        const float4 cr = scene->casters[k].centre_radius;
        const v3 pc = v3_sub(v3_splat(cr.xyz), p);
        const vfloat distance2 = v3_dot(pc, pc);
        const float radius2 = cr.w * cr.w;
        const vfloat along = v3_dot(wi, pc);
        const vint inside_cone = (distance2 > radius2) & (along > 0.0f) & (along * along >= distance2 - radius2);
        cones += select((vfloat)(0.0f), 1.0f / (2.0f * ORB_PI * v_cone_one_minus_cos(distance2, (vfloat)(cr.w))),
                        inside_cone);
    }
    return (1.0f - ORB_CASTER_SHARE) * bsdf_pdf + (ORB_CASTER_SHARE / (float)count) * cones;
}

// ---- One camera path per lane ----
typedef struct {
    v3 o, d;          // the ray to cast next
    vint self;        // sphere the ray leaves (and the vertex it was sampled at), -1 for the camera
    vint depth;       // scattering events so far
    v3 beta;          // path throughput
    vfloat eta2;      // refraction's radiance factors inside beta
    vint nondelta_vertices;
    vint albedo_set;
    vint from_density;  // the ray was sampled from a lobe with a density
    vfloat from_pdf;
    v3 from_point;
} VPath;

typedef struct {
    v3 emission, direct, indirect, albedo, normal;
    v3 background;  // the environment's radiance where the camera ray hit nothing
    vfloat alpha;
} VPathSample;

SIMD_FN void v_add_by_vertex_count(VPathSample* s, vint nondelta_vertices, v3 contribution, vint lanes)
{
    s->emission = v3_add_where(s->emission, contribution, lanes & (nondelta_vertices == 0));
    s->direct = v3_add_where(s->direct, contribution, lanes & (nondelta_vertices == 1));
    s->indirect = v3_add_where(s->indirect, contribution, lanes & (nondelta_vertices >= 2));
}

// begin_camera_path for the lanes in `lanes`; the others keep their state.
SIMD_FN void v_begin_camera_paths(const CameraParams* cam, vint x, int y, int width, int height, const VCoords* c,
                                  uint2 seed, vint lanes, VPath* path, VPathSample* out)
{
    const VRandBlock r = v_rand_block(c, (vuint)(0u), lanes, seed);
    vfloat jx, jy;
    v_rand_pair(&r, c, 0u, lanes, &jx, &jy);
    const vfloat sx = to_vfloat(x) + jx;
    const vfloat sy = (float)y + jy;
    const vfloat ndc_x = 2.0f * sx / (float)width - 1.0f;
    const vfloat ndc_y = 1.0f - 2.0f * sy / (float)height;
    // camera_ray's `base` is `o` here, its `through` the same, summed in the same order (kernels/camera.cl).
    v3 o = v3_splat(cam->origin.xyz), d, through;
    if (cam->projection == CameraProjection_Orthographic) {
        o = v3_add(o, v3_add(v3_scale(v3_splat(cam->right.xyz), ndc_x * cam->half_width),
                             v3_scale(v3_splat(cam->up.xyz), ndc_y * cam->half_height)));
        through = v3_splat(cam->forward.xyz);
    } else {
        through = v3_add(v3_add(v3_splat(cam->forward.xyz), v3_scale(v3_splat(cam->right.xyz), ndc_x * cam->half_width)),
                         v3_scale(v3_splat(cam->up.xyz), ndc_y * cam->half_height));
    }
    if (cam->lens_radius > 0.0f) {
        vfloat lu, lv;
        v_rand_pair(&r, c, 1u, lanes, &lu, &lv);
        vfloat cs, sn;
        v_unit_circle(lv, &cs, &sn);
        const vfloat radius = cam->lens_radius * sqrt(lu);
        const v3 focus_point = v3_add(o, v3_scale(through, (vfloat)(cam->focus_distance)));
        o = v3_add(o, v3_add(v3_scale(v3_splat(cam->right.xyz), radius * cs), v3_scale(v3_splat(cam->up.xyz), radius * sn)));
        d = v3_normalize(v3_sub(focus_point, o));
    } else {
        d = v3_normalize(through);
    }
    path->o = v3_select(path->o, o, lanes);
    path->d = v3_select(path->d, d, lanes);
    path->self = select(path->self, (vint)(-1), lanes);
    path->depth = select(path->depth, (vint)(0), lanes);
    path->beta = v3_select(path->beta, v3_splat((float3)(1.0f)), lanes);
    path->eta2 = select(path->eta2, (vfloat)(1.0f), lanes);
    path->nondelta_vertices = select(path->nondelta_vertices, (vint)(0), lanes);
    path->albedo_set = select(path->albedo_set, (vint)(0), lanes);
    path->from_density = select(path->from_density, (vint)(0), lanes);
    path->from_pdf = select(path->from_pdf, (vfloat)(0.0f), lanes);
    path->from_point = v3_select(path->from_point, o, lanes);
    out->emission = v3_select(out->emission, v3_zero(), lanes);
    out->direct = v3_select(out->direct, v3_zero(), lanes);
    out->indirect = v3_select(out->indirect, v3_zero(), lanes);
    out->albedo = v3_select(out->albedo, v3_zero(), lanes);
    out->normal = v3_select(out->normal, v3_zero(), lanes);
    out->alpha = select(out->alpha, (vfloat)(0.0f), lanes);
}

// estimate_light over lanes: the next-event estimate from each lane's light
// `light_sphere` (-1: the environment), picked with probability pick_pdf,
// for a diffuse BSDF of reflectance `color`; u, u_v sample the light.
SIMD_FN v3 v_estimate_light(const SceneView* scene, v3 p, vint self, v3 color, v3 n, vint light_sphere,
                            vfloat pick_pdf, vfloat u, vfloat u_v, vint lanes)
{
    // Lanes that picked the environment (light -1): estimate_environment_light
    // lane by lane (its map lookups and searches are per lane anyway).
    v3 environment = v3_zero();
    const vint environment_lanes = lanes & (light_sphere < 0);
    if (ORB_ENVIRONMENT && any(environment_lanes) && scene->environment.width == 1 && scene->environment.height == 1) {
        // A uniform environment (one texel): sample_environment's steps for
        // a map of one row and one column, over lanes.
        const float4 texel = scene->environment_texels[0].radiance_pdf;
        SCENE_MEM const EnvironmentCdf* cdf = scene->environment_cdf;
        const vfloat in_row = fmin(u / cdf[0].upper, 0x1.fffffep-1f);
        const vfloat in_column = fmin(u_v / cdf[1].upper, 0x1.fffffep-1f);
        const float cos_top = unit_circle(0.0f).x, cos_bottom = unit_circle(0.5f).x;
        const vfloat cos_theta = cos_top + in_row * (cos_bottom - cos_top);
        const vfloat sin_theta = sqrt(fmax((vfloat)(0.0f), 1.0f - cos_theta * cos_theta));
        vfloat cs, sn;
        v_unit_circle(in_column, &cs, &sn);
        const vfloat mx = -sin_theta * cs, mz = -sin_theta * sn;
        const float c = scene->environment.rotation.x, r = scene->environment.rotation.y;
        const v3 wi = v3_make(c * mx + r * mz, cos_theta, -r * mx + c * mz);
        const vfloat cos_n = v3_dot(n, wi);
        const vfloat bsdf_pdf = select((vfloat)(0.0f), cos_n * ORB_INV_PI, cos_n > 0.0f);
        const v3 f_cos = v3_scale(color, bsdf_pdf);
        vint carries = environment_lanes & (v3_sum(f_cos) > 0.0f) & (vint)(texel.w > 0.0f ? -1 : 0);
        if (any(carries)) carries = v_light_visible(scene, p, wi, self, (vint)(-1), carries);
        if (any(carries)) {
            const vfloat light_pdf = pick_pdf * texel.w;
            const vfloat weight = v_power_heuristic(light_pdf, v_continuation_pdf(scene, p, bsdf_pdf, wi));
            environment = v3_select(environment, v3_scale(v3_mul(v3_splat(texel.xyz), f_cos), weight / light_pdf), carries);
        }
        lanes &= ~environment_lanes;
        if (!any(lanes)) return environment;
    } else if (ORB_ENVIRONMENT && any(environment_lanes)) {
        float px[ORB_LANES], py[ORB_LANES], pz[ORB_LANES], nx[ORB_LANES], ny[ORB_LANES],
            nz[ORB_LANES], cr[ORB_LANES], cg[ORB_LANES], cb[ORB_LANES], pick_lane[ORB_LANES],
            u_lane[ORB_LANES], v_lane[ORB_LANES];
        int self_lane[ORB_LANES], sampled[ORB_LANES];
        v3_store_lanes(p, px, py, pz);
        v3_store_lanes(n, nx, ny, nz);
        v3_store_lanes(color, cr, cg, cb);
        vstore_lanes(pick_pdf, 0, pick_lane), vstore_lanes(u, 0, u_lane), vstore_lanes(u_v, 0, v_lane);
        vstore_lanes(self, 0, self_lane), vstore_lanes(environment_lanes, 0, sampled);
        for (int l = 0; l < ORB_LANES; ++l) {
            float3 radiance = (float3)(0.0f);
            if (sampled[l]) {
                Bsdf bsdf;
                bsdf.color = (float3)(cr[l], cg[l], cb[l]);
                bsdf.kind = MaterialKind_Diffuse;
                bsdf.ior = 1.0f;
                bsdf.roughness = 0.0f;
                bsdf.metallic = 0.0f;
                const float3 lane_n = (float3)(nx[l], ny[l], nz[l]);
                // A diffuse BSDF reads neither wo nor the side.
                radiance = estimate_environment_light(scene, pick_lane[l], (float3)(px[l], py[l], pz[l]), self_lane[l],
                                                      &bsdf, lane_n, lane_n, true, u_lane[l], v_lane[l]);
            }
            cr[l] = radiance.x, cg[l] = radiance.y, cb[l] = radiance.z;
        }
        environment = v3_load_lanes(cr, cg, cb);
        lanes &= ~environment_lanes;
        if (!any(lanes)) return environment;
    }
    const VSphere light = v_load_spheres(scene, light_sphere);
    // sample_light_direction
    const v3 pc = v3_sub(light.centre, p);
    const vfloat distance2 = v3_dot(pc, pc);
    const vint surrounds = (self == light_sphere) | (distance2 <= light.radius * light.radius);
    const vfloat one_minus_cos_max = v_cone_one_minus_cos(distance2, light.radius);
    const v3 cone = v_sample_uniform_cone(v3_scale(pc, rsqrt(distance2)), one_minus_cos_max, u, u_v);
    const v3 wi = v3_select(cone, v_sample_uniform_sphere(u, u_v), surrounds);
    const vfloat direction_pdf = select(1.0f / (2.0f * ORB_PI * one_minus_cos_max), (vfloat)(ORB_INV_4PI), surrounds);
    // diffuse_eval
    const vfloat cos_theta = v3_dot(n, wi);
    const vfloat bsdf_pdf = select((vfloat)(0.0f), cos_theta * ORB_INV_PI, cos_theta > 0.0f);
    const v3 f_cos = v3_scale(color, bsdf_pdf);
    vint carries = lanes & (v3_sum(f_cos) > 0.0f);
    if (!any(carries)) return environment;
    carries = v_light_visible(scene, p, wi, self, light_sphere, carries);
    if (!any(carries)) return environment;
    const vfloat light_pdf = pick_pdf * direction_pdf;
    const vfloat weight = v_power_heuristic(light_pdf, v_continuation_pdf(scene, p, bsdf_pdf, wi));
    const v3 radiance = v3_scale(v3_mul(light.emission, f_cos), weight / light_pdf);
    return v3_add(environment, v3_select(v3_zero(), radiance, carries));
}

// sample_lights over lanes (global mode): one light per lane, picked by
// power through the alias table (or uniformly), then estimate_direct_light
// for a diffuse BSDF of reflectance `color`. Returns the radiance towards wo.
SIMD_FN v3 v_sample_lights(const SceneView* scene, v3 p, vint self, v3 color, v3 n, vfloat u_pick, vfloat u_v,
                           vint lanes)
{
    const int light_count = scene->light_count;
    if (light_count == 0) return v3_zero();
    const vfloat scaled = u_pick * (float)light_count;
    const vint slot = min(vint_from_float(scaled), (vint)(light_count - 1));
    const vfloat rest = scaled - to_vfloat(slot);
    vint light_sphere;
    vfloat pick_pdf, u;
#if ORB_UNIFORM_LIGHTS
    u = fmin(rest, 0x1.fffffep-1f);
    pick_pdf = (vfloat)(1.0f / (float)light_count);
#endif
    if (light_count > ORB_SIMD_SELECT_GATHER_MAX) {
        // Many lights: each lane reads its alias-table slot on its own.
        int slot_lane[ORB_LANES], sphere_lane[ORB_LANES];
        float rest_lane[ORB_LANES], pdf_lane[ORB_LANES], u_lane[ORB_LANES];
        vstore_lanes(slot, 0, slot_lane);
        vstore_lanes(rest, 0, rest_lane);
        for (int l = 0; l < ORB_LANES; ++l) {
            SCENE_MEM const LightRecord* entry = &scene->lights[slot_lane[l]];
#if ORB_UNIFORM_LIGHTS
            sphere_lane[l] = entry->sphere;
            pdf_lane[l] = 0.0f;
            u_lane[l] = 0.0f;
#else
            const bool own = rest_lane[l] < entry->alias_threshold;
            SCENE_MEM const LightRecord* light = &scene->lights[own ? slot_lane[l] : entry->alias];
            sphere_lane[l] = light->sphere;
            pdf_lane[l] = light->probability;
            u_lane[l] = fmin(own ? rest_lane[l] / entry->alias_threshold
                                 : (rest_lane[l] - entry->alias_threshold) / (1.0f - entry->alias_threshold),
                             0x1.fffffep-1f);
#endif
        }
        light_sphere = vload_lanes(0, sphere_lane);
#if !ORB_UNIFORM_LIGHTS
        pick_pdf = vload_lanes(0, pdf_lane);
        u = vload_lanes(0, u_lane);
#endif
    } else {
#if ORB_UNIFORM_LIGHTS
        light_sphere = (vint)(scene->lights[0].sphere);
        for (int k = 1; k < light_count; ++k)
            light_sphere = select(light_sphere, (vint)(scene->lights[k].sphere), slot == k);
#else
        vfloat threshold = (vfloat)(scene->lights[0].alias_threshold);
        vint alias = (vint)(scene->lights[0].alias);
        for (int k = 1; k < light_count; ++k) {
            const vint m = slot == k;
            threshold = select(threshold, (vfloat)(scene->lights[k].alias_threshold), m);
            alias = select(alias, (vint)(scene->lights[k].alias), m);
        }
        const vint own = rest < threshold;
        const vint pick = select(alias, slot, own);
        u = fmin(select((rest - threshold) / (1.0f - threshold), rest / threshold, own), 0x1.fffffep-1f);
        pick_pdf = (vfloat)(scene->lights[0].probability);
        light_sphere = (vint)(scene->lights[0].sphere);
        for (int k = 1; k < light_count; ++k) {
            const vint m = pick == k;
            pick_pdf = select(pick_pdf, (vfloat)(scene->lights[k].probability), m);
            light_sphere = select(light_sphere, (vint)(scene->lights[k].sphere), m);
        }
#endif
    }
    return v_estimate_light(scene, p, self, color, n, light_sphere, pick_pdf, u, u_v, lanes);
}

// sample_lights in direct mode: every light, each with the same numbers.
SIMD_FN v3 v_sample_every_light(const SceneView* scene, v3 p, vint self, v3 color, v3 n, vfloat u, vfloat u_v,
                                vint lanes)
{
    v3 sum = v3_zero();
    for (int k = 0; k < scene->light_count; ++k)
        sum = v3_add(sum, v_estimate_light(scene, p, self, color, n, (vint)(scene->lights[k].sphere), (vfloat)(1.0f),
                                           u, u_v, lanes));
    return sum;
}

// The continuation at diffuse lanes (sample_continuation with diffuse_sample):
// the mixture of cosine sampling and cones aimed at the casters.
SIMD_FN void v_diffuse_continuation(const SceneView* scene, v3 p, v3 n, v3 color, vfloat u, vfloat v, vfloat* choice,
                                    v3* wi, v3* weight, vfloat* pdf)
{
    vfloat cos_theta;
    const v3 cosine = v_sample_cosine_hemisphere(n, u, v, &cos_theta);
    const int count = scene->caster_count;
    if (ORB_CASTER_SHARE <= 0.0f || count == 0) {
        *wi = cosine;
        *weight = color;
        *pdf = cos_theta * ORB_INV_PI;
        return;
    }
    const vint aim = v_choose_lobe((vfloat)(ORB_CASTER_SHARE), choice);
    const vfloat scaled = *choice * (float)count;
    const vint k = min(vint_from_float(scaled), (vint)(count - 1));
    *choice = select(*choice, fmin(scaled - to_vfloat(k), 0x1.fffffep-1f), aim);
    float4 cr0 = scene->casters[0].centre_radius;
    v3 centre = v3_splat(cr0.xyz);
    vfloat radius = (vfloat)(cr0.w);
    for (int c = 1; c < count; ++c) {
        const vint m = k == c;
        const float4 cr = scene->casters[c].centre_radius;
        centre = v3_select(centre, v3_splat(cr.xyz), m);
        radius = select(radius, (vfloat)(cr.w), m);
    }
    const v3 pc = v3_sub(centre, p);
    const vfloat distance2 = v3_dot(pc, pc);
    const vint lost = aim & (distance2 <= radius * radius);  // inside the caster: no cone to sample
    const v3 aimed = v_sample_uniform_cone(v3_scale(pc, rsqrt(distance2)), v_cone_one_minus_cos(distance2, radius), u, v);
    *wi = v3_select(cosine, aimed, aim);
    const vfloat cos_wi = v3_dot(n, *wi);
    const vfloat bsdf_pdf = select((vfloat)(0.0f), cos_wi * ORB_INV_PI, cos_wi > 0.0f);
    const v3 f_cos = v3_scale(color, bsdf_pdf);
    const vfloat mixture = v_continuation_pdf(scene, p, bsdf_pdf, *wi);
    const vint valid = (mixture > 0.0f) & ~lost;
    *pdf = select((vfloat)(0.0f), mixture, valid);
    *weight = v3_select(v3_zero(), v3_scale(f_cos, 1.0f / mixture), valid);
}

// extend_path over lanes: casts every active lane's ray and handles what it
// hits. Returns the lanes whose paths go on.
SIMD_FN vint v_extend_paths(const SceneView* scene, VPath* path, VPathSample* out, const VCoords* coords, uint2 seed,
                            int max_depth, int mode, vint active)
{
    vfloat t;
    vint id;
    v_intersect(scene, path->o, path->d, path->self, active, &t, &id);
    // A ray that escapes brings the environment's radiance (escaped_radiance,
    // lane by lane: a map lookup per lane), weighted by MIS after a lobe
    // with a density.
    const vint escaped = active & (id < 0);
    // Direct mode samples every light, so the environment's pick is certain.
    const float environment_pick = mode == IntegratorMode_Direct ? 1.0f : scene->environment.light_probability;
    if (ORB_ENVIRONMENT && scene->environment.width == 1 && scene->environment.height == 1 && any(escaped)) {
        // A uniform environment: the same radiance and density everywhere.
        const float4 texel = scene->environment_texels[0].radiance_pdf;
        const vfloat weight = select((vfloat)(1.0f),
                                     v_power_heuristic(path->from_pdf, (vfloat)(environment_pick * texel.w)),
                                     path->from_density);
        const v3 seen = v3_scale(v3_mul(path->beta, v3_splat(texel.xyz)), weight);
        v_add_by_vertex_count(out, path->nondelta_vertices, seen, escaped);
        if (ORB_FILM_BUILT(background)) out->background = v3_select(out->background, seen, escaped & (path->depth == 0));
    } else if (ORB_ENVIRONMENT && scene->environment.width > 0 && any(escaped)) {
        float dx[ORB_LANES], dy[ORB_LANES], dz[ORB_LANES], pdf_lane[ORB_LANES];
        float er[ORB_LANES], eg[ORB_LANES], eb[ORB_LANES];
        int density_lane[ORB_LANES], escaped_lane[ORB_LANES];
        v3_store_lanes(path->d, dx, dy, dz);
        vstore_lanes(path->from_pdf, 0, pdf_lane), vstore_lanes(path->from_density, 0, density_lane);
        vstore_lanes(escaped, 0, escaped_lane);
        for (int l = 0; l < ORB_LANES; ++l) {
            const float3 e = escaped_lane[l] ? escaped_radiance(scene, (float3)(dx[l], dy[l], dz[l]), density_lane[l] != 0,
                                                                pdf_lane[l], environment_pick)
                                             : (float3)(0.0f);
            er[l] = e.x, eg[l] = e.y, eb[l] = e.z;
        }
        const v3 seen = v3_mul(path->beta, v3_load_lanes(er, eg, eb));
        v_add_by_vertex_count(out, path->nondelta_vertices, seen, escaped);
        if (ORB_FILM_BUILT(background)) out->background = v3_select(out->background, seen, escaped & (path->depth == 0));
    }
    const vint hit = active & (id >= 0);
    if (!any(hit)) return hit;
    const VSphere m = v_load_spheres(scene, id);
    const v3 p = v3_add(path->o, v3_scale(path->d, t));
    const v3 outward = v3_scale(v3_sub(p, m.centre), 1.0f / m.radius);
    const vint outside = v3_dot(path->d, outward) < 0.0f;
    const v3 n = v3_select(v3_neg(outward), outward, outside);
    const v3 wo = v3_neg(path->d);
    const vint first_hit = hit & (path->depth == 0);
    out->alpha = select(out->alpha, (vfloat)(1.0f), first_hit);
    if (ORB_FILM_BUILT(normal)) out->normal = v3_select(out->normal, n, first_hit);

    const vint emissive = hit & (v3_sum(m.emission) > 0.0f);
    if (any(emissive)) {
        vfloat weight = (vfloat)(1.0f);
        const vint weighed = emissive & path->from_density;
        if (any(weighed)) {
#if ORB_UNIFORM_LIGHTS
            vfloat pick_pdf = (vfloat)(1.0f / (float)scene->light_count);
#else
            vfloat pick_pdf = m.light_probability;
#endif
            if (mode == IntegratorMode_Direct) pick_pdf = (vfloat)(1.0f);
            const vfloat light_pdf =
                pick_pdf * v_light_direction_pdf(path->from_point, path->self, id, m.centre, m.radius);
            weight = select(weight, v_power_heuristic(path->from_pdf, light_pdf), weighed);
        }
        v_add_by_vertex_count(out, path->nondelta_vertices, v3_scale(v3_mul(path->beta, m.emission), weight), emissive);
    }

    vint go = hit & (path->depth < max_depth);
    // Direct mode: the ray after the first non-delta vertex was traced only for its emission.
    if (mode == IntegratorMode_Direct) go &= path->nondelta_vertices != 1;
    if (!any(go)) return go;

    const vuint block = vuint_from_int(path->depth + 1);
    const VRandBlock r = v_rand_block(coords, block, go, seed);
    // Lanes whose BSDF the vector code does not have (pbr, rough glass) go
    // through render_pass's BSDF interface, lane by lane (below).
    vint general = (vint)(0);
    if (ORB_KIND_BUILT(MaterialKind_Pbr) || ORB_ROUGH_DIELECTRIC) {
        int id_lane[ORB_LANES], general_lane[ORB_LANES];
        vstore_lanes(id, 0, id_lane);
        vstore_lanes(go, 0, general_lane);
        for (int l = 0; l < ORB_LANES; ++l) {
            if (!general_lane[l]) continue;
            const Bsdf b = load_bsdf(&scene->materials[scene->spheres[id_lane[l]].material]);
            const bool pbr = b.kind == MaterialKind_Pbr && ORB_KIND_BUILT(MaterialKind_Pbr);
            const bool rough_glass = b.kind == MaterialKind_Dielectric && ORB_KIND_BUILT(MaterialKind_Dielectric) &&
                                     dielectric_has_density(&b);
            general_lane[l] = pbr || rough_glass ? -1 : 0;
        }
        general = vload_lanes(0, general_lane);
    }
    // A kind the program leaves out (ORB_MATERIAL_KINDS) is diffuse, as in bsdf.cl.
    const vint mirror = go & ~general & (m.kind == MaterialKind_Mirror) &
                        (vint)(ORB_KIND_BUILT(MaterialKind_Mirror) ? -1 : 0);
    const vint glass = go & ~general & (m.kind == MaterialKind_Dielectric) &
                       (vint)(ORB_KIND_BUILT(MaterialKind_Dielectric) ? -1 : 0);
    const vint diffuse = go & ~general & ~mirror & ~glass;
    vfloat u_dir = (vfloat)(0.5f), v_dir = (vfloat)(0.5f);
    if (any(diffuse)) {
        if (ORB_FILM_BUILT(albedo)) {
            const vint first = diffuse & ~path->albedo_set;
            out->albedo = v3_select(out->albedo, v3_mul(path->beta, m.color), first);
            path->albedo_set |= first;
        }
        vfloat u_pick, v_light;
        v_rand_pair(&r, coords, 0u, diffuse, &u_pick, &v_light);
        const v3 direct = mode == IntegratorMode_Direct
                              ? v_sample_every_light(scene, p, id, m.color, n, u_pick, v_light, diffuse)
                              : v_sample_lights(scene, p, id, m.color, n, u_pick, v_light, diffuse);
        v_add_by_vertex_count(out, path->nondelta_vertices + 1, v3_mul(path->beta, direct), diffuse);
        v_rand_pair(&r, coords, 1u, diffuse, &u_dir, &v_dir);
    }
    vfloat choice = v_rand_single(&r, coords, go);
    vint nondelta_step = diffuse;  // lanes whose continuation has a density

    // The continuation, per material kind; lanes of other kinds discard it.
    v3 wi = wo, weight = v3_zero();
    vfloat pdf = (vfloat)(0.0f), eta2 = (vfloat)(1.0f);
    if (any(diffuse)) {
        vfloat c = choice, diffuse_pdf;
        v3 diffuse_wi, diffuse_weight;
        v_diffuse_continuation(scene, p, n, m.color, u_dir, v_dir, &c, &diffuse_wi, &diffuse_weight, &diffuse_pdf);
        wi = v3_select(wi, diffuse_wi, diffuse);
        weight = v3_select(weight, diffuse_weight, diffuse);
        pdf = select(pdf, diffuse_pdf, diffuse);
        choice = select(choice, c, diffuse);
    }
    const v3 mirrored = v3_sub(v3_scale(n, 2.0f * v3_dot(wo, n)), wo);
    if (any(mirror)) {
        wi = v3_select(wi, mirrored, mirror);
        weight = v3_select(weight, m.color, mirror);
    }
    if (any(glass)) {
        // smooth_dielectric_sample: reflect with probability F, else refract.
        const vfloat cos_o = v3_dot(wo, n);
        const vfloat eta = select(m.ior, 1.0f / m.ior, outside);
        const vfloat sin2_t = eta * eta * fmax((vfloat)(0.0f), 1.0f - cos_o * cos_o);
        const vint total = sin2_t >= 1.0f;
        const vfloat cos_t = sqrt(fmax((vfloat)(0.0f), 1.0f - sin2_t));
        const vfloat rs = (eta * cos_o - cos_t) / (eta * cos_o + cos_t);
        const vfloat rp = (cos_o - eta * cos_t) / (cos_o + eta * cos_t);
        const vfloat reflectance = select(0.5f * (rs * rs + rp * rp), (vfloat)(1.0f), total);
        vfloat c = choice;
        const vint reflect = v_choose_lobe(reflectance, &c);
        const v3 refracted = v3_normalize(v3_add(v3_scale(wo, -eta), v3_scale(n, eta * cos_o - cos_t)));
        const vfloat glass_eta2 = select(eta * eta, (vfloat)(1.0f), reflect);
        wi = v3_select(wi, v3_select(refracted, mirrored, reflect), glass);
        weight = v3_select(weight, v3_scale(m.color, glass_eta2), glass);
        eta2 = select(eta2, glass_eta2, glass);
        choice = select(choice, c, glass);
    }
    if (any(general)) {
        // extend_path's shading, lane by lane: next-event estimation and the
        // continuation through the BSDF interface (bsdf.cl, caustic_casters.cl).
        vfloat u_light, v_light, u_d, v_d;
        v_rand_pair(&r, coords, 0u, general, &u_light, &v_light);
        v_rand_pair(&r, coords, 1u, general, &u_d, &v_d);
        float f[25][ORB_LANES];
        int id_lane[ORB_LANES], lane_on[ORB_LANES], outside_lane[ORB_LANES],
            albedo_set_lane[ORB_LANES], delta_lane[ORB_LANES];
        v3_store_lanes(p, f[0], f[1], f[2]);
        v3_store_lanes(n, f[3], f[4], f[5]);
        v3_store_lanes(wo, f[6], f[7], f[8]);
        v3_store_lanes(path->beta, f[9], f[10], f[11]);
        vstore_lanes(u_light, 0, f[12]), vstore_lanes(v_light, 0, f[13]), vstore_lanes(u_d, 0, f[14]);
        vstore_lanes(v_d, 0, f[15]), vstore_lanes(choice, 0, f[16]);
        vstore_lanes(id, 0, id_lane), vstore_lanes(general, 0, lane_on), vstore_lanes(outside, 0, outside_lane);
        vstore_lanes(path->albedo_set, 0, albedo_set_lane);
        float a[3][ORB_LANES], direct[3][ORB_LANES];
        for (int l = 0; l < ORB_LANES; ++l) {
            a[0][l] = a[1][l] = a[2][l] = direct[0][l] = direct[1][l] = direct[2][l] = 0.0f;
            delta_lane[l] = 0;
            if (!lane_on[l]) continue;
            const Bsdf b = load_bsdf(&scene->materials[scene->spheres[id_lane[l]].material]);
            const float3 lp = (float3)(f[0][l], f[1][l], f[2][l]), ln = (float3)(f[3][l], f[4][l], f[5][l]),
                         lwo = (float3)(f[6][l], f[7][l], f[8][l]), lbeta = (float3)(f[9][l], f[10][l], f[11][l]);
            const bool lane_outside = outside_lane[l] != 0;
            const bool has_density = bsdf_has_density(&b);
            float lane_choice = f[16][l];
            BsdfSample bs;
            if (has_density) {
                if (ORB_FILM_BUILT(albedo) && !albedo_set_lane[l]) {
                    const float3 albedo = lbeta * bsdf_albedo(&b, lwo, ln);
                    a[0][l] = albedo.x, a[1][l] = albedo.y, a[2][l] = albedo.z;
                    albedo_set_lane[l] = -2;  // set here (told apart from -1, set before)
                }
                const float3 d = lbeta * sample_lights(scene, lp, id_lane[l], &b, lwo, ln, lane_outside,
                                                       (float2)(f[12][l], f[13][l]), mode);
                direct[0][l] = d.x, direct[1][l] = d.y, direct[2][l] = d.z;
                bs = sample_continuation(scene, &b, lp, lwo, ln, lane_outside, f[14][l], f[15][l], &lane_choice);
            } else {
                bs = bsdf_sample(&b, lwo, ln, lane_outside, 0.5f, 0.5f, &lane_choice);
            }
            f[17][l] = bs.wi.x, f[18][l] = bs.wi.y, f[19][l] = bs.wi.z;
            f[20][l] = bs.weight.x, f[21][l] = bs.weight.y, f[22][l] = bs.weight.z;
            f[23][l] = bs.pdf, f[24][l] = bs.eta2;
            f[16][l] = lane_choice;
            delta_lane[l] = bs.delta ? -1 : 0;
        }
        const vint albedo_now = vload_lanes(0, albedo_set_lane) == -2;
        if (ORB_FILM_BUILT(albedo)) {
            out->albedo = v3_select(out->albedo, v3_load_lanes(a[0], a[1], a[2]),
                                    albedo_now);
            path->albedo_set |= albedo_now;
        }
        v_add_by_vertex_count(out, path->nondelta_vertices + 1,
                              v3_load_lanes(direct[0], direct[1], direct[2]),
                              general);
        wi = v3_select(wi, v3_load_lanes(f[17], f[18], f[19]), general);
        weight = v3_select(weight, v3_load_lanes(f[20], f[21], f[22]), general);
        pdf = select(pdf, vload_lanes(0, f[23]), general);
        eta2 = select(eta2, vload_lanes(0, f[24]), general);
        choice = select(choice, vload_lanes(0, f[16]), general);
        nondelta_step |= general & ~vload_lanes(0, delta_lane);
    }

    v3 beta = v3_mul(path->beta, weight);
    const vfloat beta_max = v3_max(beta);
    vint alive = go & (beta_max > 0.0f);
    const vfloat path_eta2 = path->eta2 * eta2;
    // Russian roulette, as extend_path: refraction's factor divided out of q.
    const vint roulette = alive & (path->depth + 1 >= RR_START_EVENT);
    const vfloat q = fmin((vfloat)(1.0f), beta_max / (path_eta2 * RR_THRESHOLD));
    alive &= ~roulette | (choice < q);
    beta = v3_select(beta, v3_scale(beta, 1.0f / q), roulette);

    path->beta = v3_select(path->beta, beta, alive);
    path->eta2 = select(path->eta2, path_eta2, alive);
    path->nondelta_vertices = select(path->nondelta_vertices, path->nondelta_vertices + 1, alive & nondelta_step);
    path->from_density = select(path->from_density, nondelta_step, alive);
    path->from_pdf = select(path->from_pdf, pdf, alive);
    path->from_point = v3_select(path->from_point, p, alive);
    path->o = v3_select(path->o, p, alive);
    path->d = v3_select(path->d, wi, alive);
    path->self = select(path->self, id, alive);
    path->depth = select(path->depth, path->depth + 1, alive);
    return alive;
}

// ---- The film over lanes: FilmSums with a vector per component ----
#define ORB_SIMD_SUM_FIELD_1(name) vfloat name;
#define ORB_SIMD_SUM_FIELD_3(name) v3 name;
#define ORB_SIMD_SUM_FIELD_IF_Sum(name, components) ORB_SIMD_SUM_FIELD_##components(name)
#define ORB_SIMD_SUM_FIELD_IF_CentreRay(name, components)
#define ORB_SIMD_SUM_FIELD(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    ORB_SIMD_SUM_FIELD_IF_##accumulate(name, components)
typedef struct {
    ORB_FILM_CHANNELS(ORB_SIMD_SUM_FIELD)
} VFilmSums;

#define ORB_SIMD_ZERO_1(name) sums->name = (vfloat)(0.0f);
#define ORB_SIMD_ZERO_3(name) sums->name = v3_zero();
#define ORB_SIMD_ZERO_IF_Sum(name, components) ORB_SIMD_ZERO_##components(name)
#define ORB_SIMD_ZERO_IF_CentreRay(name, components)
#define ORB_SIMD_ZERO(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    ORB_SIMD_ZERO_IF_##accumulate(name, components)
SIMD_FN void v_film_sums_clear(VFilmSums* sums) { ORB_FILM_CHANNELS(ORB_SIMD_ZERO) }

// film_add_sample for the lanes in `lanes`.
SIMD_FN void v_film_add_sample(VFilmSums* sums, const VPathSample* s, vint lanes)
{
    v3 emission = s->emission, direct = s->direct, indirect = s->indirect;
    v3 radiance = v3_add(v3_add(emission, direct), indirect);
    const vint finite = isfinite(radiance.x) & isfinite(radiance.y) & isfinite(radiance.z);
    emission = v3_select(v3_zero(), emission, finite);
    direct = v3_select(v3_zero(), direct, finite);
    indirect = v3_select(v3_zero(), indirect, finite);
    radiance = v3_select(v3_zero(), radiance, finite);
    const v3 background = v3_select(v3_zero(), s->background, finite);
    sums->radiance = v3_add_where(sums->radiance, radiance, lanes);
    sums->alpha = select(sums->alpha, sums->alpha + s->alpha, lanes);
    sums->direct = v3_add_where(sums->direct, direct, lanes);
    sums->indirect = v3_add_where(sums->indirect, indirect, lanes);
    sums->emission = v3_add_where(sums->emission, emission, lanes);
    sums->albedo = v3_add_where(sums->albedo, s->albedo, lanes);
    sums->normal = v3_add_where(sums->normal, s->normal, lanes);
    sums->radiance_sq = v3_add_where(sums->radiance_sq, v3_mul(radiance, radiance), lanes);
    sums->background = v3_add_where(sums->background, background, lanes);
}

// Lane l of a VFilmSums into the FilmSums `sums` that ORB_FILM_ADD_SUMS reads:
// each built channel's vectors are stored to an array once, then read per lane.
#define ORB_SIMD_SPILL_1(name) float name##_lanes[ORB_LANES]; vstore_lanes(vsums.name, 0, name##_lanes);
#define ORB_SIMD_SPILL_3(name)                     \
    float name##_lanes[3 * ORB_LANES];       \
    vstore_lanes(vsums.name.x, 0, name##_lanes);  \
    vstore_lanes(vsums.name.y, 1, name##_lanes);  \
    vstore_lanes(vsums.name.z, 2, name##_lanes);
#define ORB_SIMD_SPILL_IF_Sum(name, components) ORB_SIMD_SPILL_##components(name)
#define ORB_SIMD_SPILL_IF_CentreRay(name, components)
#define ORB_SIMD_SPILL(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    ORB_SIMD_SPILL_IF_##accumulate(name, components)
#define ORB_SIMD_PICK_1(name) sums.name = name##_lanes[lane];
#define ORB_SIMD_PICK_3(name) \
    sums.name = (float3)(name##_lanes[lane], name##_lanes[ORB_LANES + lane], name##_lanes[2 * ORB_LANES + lane]);
#define ORB_SIMD_PICK_IF_Sum(name, components) ORB_SIMD_PICK_##components(name)
#define ORB_SIMD_PICK_IF_CentreRay(name, components)
#define ORB_SIMD_PICK(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    ORB_SIMD_PICK_IF_##accumulate(name, components)

__kernel void render_pass_simd(ORB_RENDER_PASS_ARGUMENTS(ORB_KERNEL_FILM_ARG, ORB_KERNEL_TABLE_ARG, ORB_KERNEL_PARAMS_ARG))
{
    const int width = params.settings.width;
    const int height = params.settings.height;
    const int x0 = (int)get_global_id(0) * ORB_LANES;
    const int y = get_global_id(1);
    if (x0 >= width || y >= height) return;

    ORB_SCENE_VIEW_OF_ARGUMENTS

    const CameraParams cam = params.camera;
    const uint2 seed = (uint2)(params.settings.seed_lo, params.settings.seed_hi);
    const int max_depth = params.settings.max_depth;
    const int mode = params.settings.mode;
    const int sample_count = params.pass.sample_count;

    const vint x = (vint)(x0) + ORB_LANE_INDEX;
    const vint in_image = x < width;
    const vuint pixel = (vuint)((uint)y * (uint)width) + vuint_from_int(x);
    uint keys[ORB_LANES];
    for (int lane = 0; lane < ORB_LANES; ++lane)
        keys[lane] = sampler_pixel_key((uint)(y * width + x0 + lane), seed);
    const vuint pixel_key = vload_lanes(0, keys);

    // This work-item's pixels: lanes past the image's right edge have none.
    const int lanes_in_image = min(ORB_LANES, width - x0);

    // The centre-ray channels first, lane by lane, as render_pass does.
    if ((ORB_FILM_BUILT(depth) || ORB_FILM_BUILT(object_id)) && params.pass.write_centre_ray) {
        for (int lane = 0; lane < lanes_in_image; ++lane) {
            const uint pixel = (uint)y * (uint)width + (uint)(x0 + lane);
            const FilmCentre centre = film_centre_ray(&scene, &cam, x0 + lane, y, width, height);
            ORB_FILM_SET_CENTRE
        }
    }

    VFilmSums vsums;
    v_film_sums_clear(&vsums);

    // Path regeneration per lane, as render_pass does per work-item: a lane
    // whose path ends starts its pixel's next sample at once.
    VPath path;
    VPathSample s;
    path.o = path.d = path.beta = path.from_point = v3_zero();
    path.self = path.depth = path.nondelta_vertices = path.albedo_set = path.from_density = (vint)(0);
    path.eta2 = path.from_pdf = (vfloat)(0.0f);
    s.emission = s.direct = s.indirect = s.albedo = s.normal = s.background = v3_zero();
    s.alpha = (vfloat)(0.0f);
    vint index = (vint)(0);
    vint active = in_image & (vint)(sample_count > 0 ? -1 : 0);
    VCoords coords = v_sample_coords(pixel, pixel_key, params.pass.first_sample_lo, params.pass.first_sample_hi, index);
    if (any(active)) v_begin_camera_paths(&cam, x, y, width, height, &coords, seed, active, &path, &s);
    while (any(active)) {
        const vint alive = v_extend_paths(&scene, &path, &s, &coords, seed, max_depth, mode, active);
        const vint done = active & ~alive;
        active = alive;
        if (any(done)) {
            v_film_add_sample(&vsums, &s, done);
            // The camera path's start (v_begin_camera_paths) clears the other
            // fields; the background is set only by an escape, so it is cleared here.
            s.background = v3_select(s.background, v3_zero(), done);
            index -= done;  // done lanes are -1
            const vint next = done & (index < sample_count);
            if (any(next)) {
                const VCoords fresh = v_sample_coords(pixel, pixel_key, params.pass.first_sample_lo,
                                                      params.pass.first_sample_hi, index);
                coords.sample_lo = select(coords.sample_lo, fresh.sample_lo, next);
                coords.sample_hi = select(coords.sample_hi, fresh.sample_hi, next);
                coords.key = select(coords.key, fresh.key, next);
                coords.i_reversed = select(coords.i_reversed, fresh.i_reversed, next);
                v_begin_camera_paths(&cam, x, y, width, height, &coords, seed, next, &path, &s);
                active |= next;
            }
        }
    }

    ORB_FILM_CHANNELS(ORB_SIMD_SPILL)
    for (int lane = 0; lane < lanes_in_image; ++lane) {
        const uint pixel = (uint)y * (uint)width + (uint)(x0 + lane);
        FilmSums sums;
        ORB_FILM_CHANNELS(ORB_SIMD_PICK)
        ORB_FILM_ADD_SUMS
    }
}

#endif  // ORB_LANES > 1
