// The numbers a path consumes: rng_block(pixel, sample, block, seed) gives
// five uniform numbers in [0, 1) for block `block` of sample `sample` of a
// pixel. Block 0 is the camera: u0, u1 jitter the pixel, u2, u3 the lens.
// Block k >= 1 is scattering event k: u0, u1 sample a light (u0 first picks
// it), u2, u3 the BSDF direction, u4 the lobe choice and then, rescaled,
// Russian roulette.
//
// Two samplers, chosen when the program is built (docs/rendering.md):
//  * ORB_SAMPLER_SOBOL=0: independent numbers, Philox (kernels/rng.cl).
//  * ORB_SAMPLER_SOBOL=1 (the default): Owen-scrambled Sobol points for the
//    camera and the first two scattering events (ORB_SOBOL_BLOCKS), Philox
//    numbers after them. Each
//    pair (u0, u1) and (u2, u3) of a block is a 2D Sobol point (the first
//    two Sobol dimensions, a (0, 2)-sequence in base 2), and u4 a 1D van der
//    Corput point; every pair of a block of a pixel gets its own random
//    shuffle of the sample order and its own scrambles (Burley, "Practical
//    Hash-based Owen Scrambling", JCGT 2020), so the pairs are not
//    correlated with each other, across bounces or across pixels. Any 2^k
//    consecutive, 2^k-aligned sample indices of a pixel are stratified in
//    every pair: each of the 2^k elementary intervals of every shape holds
//    one point. The scrambles' seeds are hashes of a per-pixel key
//    (sampler_pixel_key), and each vertex draws only the numbers it uses
//    (rand_pair, rand_single).
// Both are pure functions of (pixel, sample, block, seed): an image depends
// only on which sample indices were rendered, never on how passes, slices
// or resumes split them.

// ORB_SAMPLER_SOBOL chooses between the two (kernel_features.h). Blocks
// [0, ORB_SOBOL_BLOCKS) draw Sobol points (the camera and the first
// scattering events, where stratification lowers the error most); later
// blocks draw independent numbers, which cost less and lose little there.

// Bit reversal is nine of a block's steps: one instruction where the
// compiler has it (clang's builtin, which NVIDIA's compiler also takes: 18%
// more samples/s on an H100 with Sobol), five shift-and-mask steps elsewhere.
#if defined(__has_builtin)
#if __has_builtin(__builtin_bitreverse32)
#define ORB_HAVE_BITREVERSE 1
#endif
#endif

// The integer functions of this file are written once as definitions over
// a type T (uint here; the lanes' luint below, whose lanes must draw exactly these
// numbers), with the function's qualifiers Q.
#define ORB_DEFINE_REVERSE_BITS_SHIFTS(Q, T, name)                    \
    Q T name(T x)                                                     \
    {                                                                 \
        x = (x << 16) | (x >> 16);                                    \
        x = ((x & 0x00ff00ffu) << 8) | ((x >> 8) & 0x00ff00ffu);      \
        x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);      \
        x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);      \
        return ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);   \
    }
#ifdef ORB_HAVE_BITREVERSE
inline uint reverse_bits32(uint x) { return __builtin_bitreverse32(x); }
#else
ORB_DEFINE_REVERSE_BITS_SHIFTS(inline, uint, reverse_bits32)
#endif

// A seeded bijection of 32-bit integers in which bit k of the result depends
// only on bits 0..k of x (every step carries information upward only:
// additions, multiplications by odd numbers, and x ^= x * even). This is
// Laine and Karras's hash-based scramble with Vegdahl's constants (2021).
#define ORB_DEFINE_LK_PERMUTATION(Q, T, name) \
    Q T name(T x, T seed)                     \
    {                                         \
        x ^= x * 0x3d20adeau;                 \
        x += seed;                            \
        x *= (seed >> 16) | 1u;               \
        x ^= x * 0x05526c56u;                 \
        x ^= x * 0x53a22864u;                 \
        return x;                             \
    }
ORB_DEFINE_LK_PERMUTATION(inline, uint, lk_permutation)

// Owen scrambling of x read as a binary fraction (bit 31 is the first
// digit): each digit is flipped by a random function of the digits before
// it. Applied to a point it keeps every stratification the point set has;
// applied to a sample index it shuffles the order of the samples within
// every aligned power-of-two block. With the permutation above it is
// owen_scramble(x) = reverse_bits32(lk_permutation(reverse_bits32(x), seed)),
// which sobol_pair, sobol_single and shuffled_index below compute with the
// reversals merged where they cancel.

// A 32-bit mixing function (Wellons's "lowbias32"), to derive independent
// seeds from one hash.
#define ORB_DEFINE_MIX32(Q, T, name) \
    Q T name(T x)                    \
    {                                \
        x ^= x >> 16;                \
        x *= 0x7feb352du;            \
        x ^= x >> 15;                \
        x *= 0x846ca68bu;            \
        x ^= x >> 16;                \
        return x;                    \
    }
ORB_DEFINE_MIX32(inline, uint, mix32)

// The second Sobol dimension of index i, bit-reversed. Its direction
// numbers v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1) hold, reversed, bit m
// exactly when C(k, m) is odd, that is (Lucas) when the bits of m are a
// subset of those of k. So reversed bit m of the point is the XOR of the
// bits k of i over all supersets k of m: a superset transform, five
// shift-and-mask steps instead of a loop over i's 32 bits.
#define ORB_DEFINE_SOBOL_DIMENSION1_REVERSED(Q, T, name) \
    Q T name(T i)                                        \
    {                                                    \
        i ^= (i >> 1) & 0x55555555u;                     \
        i ^= (i >> 2) & 0x33333333u;                     \
        i ^= (i >> 4) & 0x0f0f0f0fu;                     \
        i ^= (i >> 8) & 0x00ff00ffu;                     \
        i ^= (i >> 16) & 0x0000ffffu;                    \
        return i;                                        \
    }
ORB_DEFINE_SOBOL_DIMENSION1_REVERSED(inline, uint, sobol_dimension1_reversed)

// The same functions over the lanes' luint (at width 1 the names above).
#if ORB_LANES == 1
#define lanes_reverse_bits reverse_bits32
#define lanes_lk_permutation lk_permutation
#define lanes_mix32 mix32
#define lanes_sobol_dimension1_reversed sobol_dimension1_reversed
#define lanes_philox4x32 philox4x32_words
#define lanes_philox_units philox_units
#else
ORB_DEFINE_REVERSE_BITS_SHIFTS(LANE_FN, luint, lanes_reverse_bits)
ORB_DEFINE_LK_PERMUTATION(LANE_FN, luint, lanes_lk_permutation)
ORB_DEFINE_MIX32(LANE_FN, luint, lanes_mix32)
ORB_DEFINE_SOBOL_DIMENSION1_REVERSED(LANE_FN, luint, lanes_sobol_dimension1_reversed)
ORB_DEFINE_PHILOX4X32(LANE_FN, luint, lanes_philox4x32)
#define ORB_LFLOAT_OF_LUINT(x) to_lfloat(x)
ORB_DEFINE_PHILOX_UNITS(LANE_FN, luint, lfloat, ORB_LFLOAT_OF_LUINT, lanes_philox_units)
#endif

LANE_FN lfloat scrambled_units(luint bits) { return to_lfloat(bits >> 8) * 0x1p-24f; }

// A hash of (pixel, seed), computed once per pixel and pass: Philox is a
// good hash but costs about as much as a whole Sobol pair, so it is not run
// per sample or per block.
inline uint sampler_pixel_key(uint pixel, uint2 seed)
{
    return philox4x32((uint4)(0x536f626cu, pixel, 0x9e3779b9u, pixel ^ 0x85ebca6bu), seed).x;
}

// Where each lane's camera path takes its numbers from: set when the path
// starts. The sample index is held as two 32-bit halves.
typedef struct {
    luint pixel;
    luint sample_lo, sample_hi;
    uint2 seed;
#if ORB_SAMPLER_SOBOL
    luint key;         // every Sobol seed of this sample derives from it (below)
    luint i_reversed;  // the sample index, low 32 bits, bit-reversed
#endif
} SampleCoords;

// Sample first + index of each lane's pixel (pixel_key: sampler_pixel_key).
LANE_FN SampleCoords sample_coords(luint pixel_key, luint pixel, uint first_lo, uint first_hi, luint index,
                                   uint2 seed)
{
    SampleCoords c;
    c.pixel = pixel;
    c.sample_lo = (luint)(first_lo) + index;
    c.sample_hi = (luint)(first_hi) + lselect((luint)(0u), (luint)(1u), c.sample_lo < (luint)(first_lo));
    c.seed = seed;
#if ORB_SAMPLER_SOBOL
    // Per 2^32 samples a new key, so indices past 2^32 do not repeat points.
    c.key = lanes_mix32(pixel_key ^ (c.sample_hi * 0x632be5abu));
    c.i_reversed = lanes_reverse_bits(c.sample_lo);
#endif
    return c;
}

// The numbers of one block of a path (block 0 the camera, block k scattering
// event k), drawn when asked for: a Sobol block computes only the pairs its
// vertex uses (a pinhole camera needs no lens pair, a mirror no numbers but
// the roulette's), which on small scenes halved the sampler's share of the
// time; an independent block is one Philox call for all five.
typedef struct {
#if ORB_SAMPLER_SOBOL
    lmask sobol;  // lanes whose block draws Sobol points
    luint key, i_reversed, block;
#endif
    lfloat u0, u1, u2, u3, u4;  // the independent numbers (lanes not sobol)
} RandBlock;

// Block `block` for the lanes in `lanes` (the others' numbers are not used).
LANE_FN RandBlock rand_block(const SampleCoords* c, luint block, lmask lanes)
{
    RandBlock r;
    r.u0 = r.u1 = r.u2 = r.u3 = r.u4 = (lfloat)(0.5f);
    lmask independent = lanes;
#if ORB_SAMPLER_SOBOL
    r.sobol = block < (luint)(ORB_SOBOL_BLOCKS);
    r.key = c->key;
    r.i_reversed = c->i_reversed;
    r.block = block;
    independent = mask_and_not(lanes, r.sobol);
#endif
    if (lanes_any(independent)) {
        luint c0 = block, c1 = c->sample_lo, c2 = c->sample_hi, c3 = c->pixel;
        lanes_philox4x32(&c0, &c1, &c2, &c3, c->seed);
        lanes_philox_units(c0, c1, c2, c3, &r.u0, &r.u1, &r.u2, &r.u3, &r.u4);
    }
    return r;
}

#if ORB_SAMPLER_SOBOL
// Seed number `slot` (0..7) of a block: a different 32-bit hash for every
// (pixel, seed, sample >> 32, block, slot). Slots 0-2 belong to pair 0,
// 3-5 to pair 1, 6-7 to the fifth number.
LANE_FN luint block_seed(luint key, luint block, uint slot)
{
    return lanes_mix32(key ^ ((block * 8u + slot) * 0x9e3779b9u));
}

// Owen scrambling of the sample index, given reversed: a random order of the
// samples within every aligned power-of-two block.
LANE_FN luint shuffled_index(luint i_reversed, luint seed)
{
    return lanes_reverse_bits(lanes_lk_permutation(i_reversed, seed));
}

// One scrambled 2D Sobol point: the sample index in this pair's own random
// order (an Owen scramble of the index: a random order within every aligned
// power-of-two block, so the pairs are not correlated with each other), then
// its first two Sobol dimensions, each Owen-scrambled. Scrambling works on
// reversed digits, owen_scramble(x) = reverse(lk(reverse(x))), and dimension
// 0 of j is reverse(j), so both are formed reversed and reversed once.
// (Scalar arguments, not the RandBlock: where PoCL does not inline this, a
// struct passed by address went through memory and stalled the caller.)
LANE_FN void sobol_pair(luint key, luint i_reversed, luint block, uint pair, lfloat* u, lfloat* v)
{
    const uint slot = 3u * pair;
    const luint j = shuffled_index(i_reversed, block_seed(key, block, slot));
    *u = scrambled_units(lanes_reverse_bits(lanes_lk_permutation(j, block_seed(key, block, slot + 1u))));
    *v = scrambled_units(lanes_reverse_bits(
        lanes_lk_permutation(lanes_sobol_dimension1_reversed(j), block_seed(key, block, slot + 2u))));
}

// A van der Corput point of the index in its own random order, scrambled.
LANE_FN lfloat sobol_single(luint key, luint i_reversed, luint block)
{
    const luint j = shuffled_index(i_reversed, block_seed(key, block, 6u));
    return scrambled_units(lanes_reverse_bits(lanes_lk_permutation(j, block_seed(key, block, 7u))));
}
#endif

// Pair 0 is (u0, u1): the light sample at a scattering event (u0 first picks
// the light), the pixel jitter for the camera. Pair 1 is (u2, u3): the BSDF
// direction, the lens position for the camera. For the lanes in `lanes`.
LANE_FN void rand_pair(const RandBlock* r, uint pair, lmask lanes, lfloat* u, lfloat* v)
{
    *u = pair == 0u ? r->u0 : r->u2;
    *v = pair == 0u ? r->u1 : r->u3;
#if ORB_SAMPLER_SOBOL
    if (lanes_any(mask_and(lanes, r->sobol))) {
        lfloat su, sv;
        sobol_pair(r->key, r->i_reversed, r->block, pair, &su, &sv);
        *u = lselect(*u, su, r->sobol);
        *v = lselect(*v, sv, r->sobol);
    }
#endif
}

// u4: picks a BSDF lobe, and then (rescaled) decides the Russian roulette.
LANE_FN lfloat rand_single(const RandBlock* r, lmask lanes)
{
    lfloat u = r->u4;
#if ORB_SAMPLER_SOBOL
    if (lanes_any(mask_and(lanes, r->sobol))) u = lselect(u, sobol_single(r->key, r->i_reversed, r->block), r->sobol);
#endif
    return u;
}

// All five numbers of a block at once, for one pixel (the sampler tests
// and BSDF probes; the integrator asks for what it uses).
inline Rand5 rng_block(uint pixel, ulong sample, uint block, uint2 seed)
{
    const SampleCoords c = sample_coords((luint)(sampler_pixel_key(pixel, seed)), (luint)(pixel), (uint)sample,
                                         (uint)(sample >> 32), (luint)(0u), seed);
    const lmask all_lanes = mask_of(true);
    const RandBlock r = rand_block(&c, (luint)(block), all_lanes);
    lfloat u0, u1, u2, u3, u4;
    rand_pair(&r, 0u, all_lanes, &u0, &u1);
    rand_pair(&r, 1u, all_lanes, &u2, &u3);
    u4 = rand_single(&r, all_lanes);
    Rand5 out;
    out.u0 = lane_f(u0, 0);
    out.u1 = lane_f(u1, 0);
    out.u2 = lane_f(u2, 0);
    out.u3 = lane_f(u3, 0);
    out.u4 = lane_f(u4, 0);
    return out;
}
