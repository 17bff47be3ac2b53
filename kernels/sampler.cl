// The numbers a path consumes: rng_block(pixel, sample, block, seed) gives
// five uniform numbers in [0, 1) for block `block` of sample `sample` of a
// pixel. Block 0 is the camera: u0, u1 jitter the pixel, u2, u3 the lens.
// Block k >= 1 is scattering event k: u0, u1 sample a light (u0 first picks
// it), u2, u3 the BSDF direction, u4 Russian roulette.
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
//    one point.
// Both are pure functions of (pixel, sample, block, seed): an image depends
// only on which sample indices were rendered, never on how passes, slices
// or resumes split them.

#ifndef ORB_SAMPLER_SOBOL
#define ORB_SAMPLER_SOBOL 1
#endif
// Blocks [0, this) draw Sobol points (the camera and the first scattering
// events, where stratification lowers the error most); later blocks draw
// independent numbers, which cost less and lose little there.
#ifndef ORB_SOBOL_BLOCKS
#define ORB_SOBOL_BLOCKS 3
#endif

// Bit reversal is nine of a block's steps: one instruction where the
// compiler has it (clang's builtin, which NVIDIA's compiler also takes: 18%
// more samples/s on an H100 with Sobol), five shift-and-mask steps elsewhere.
#if defined(__has_builtin)
#if __has_builtin(__builtin_bitreverse32)
#define ORB_HAVE_BITREVERSE 1
#endif
#endif
#ifdef ORB_HAVE_BITREVERSE
inline uint reverse_bits32(uint x) { return __builtin_bitreverse32(x); }
#else
inline uint reverse_bits32(uint x)
{
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x >> 8) & 0x00ff00ffu);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
    x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
    return ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
}
#endif

// A seeded bijection of 32-bit integers in which bit k of the result depends
// only on bits 0..k of x (every step carries information upward only:
// additions, multiplications by odd numbers, and x ^= x * even). This is
// Laine and Karras's hash-based scramble with Vegdahl's constants (2021).
inline uint lk_permutation(uint x, uint seed)
{
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scrambling of x read as a binary fraction (bit 31 is the first
// digit): each digit is flipped by a random function of the digits before
// it. Applied to a point it keeps every stratification the point set has;
// applied to a sample index it shuffles the order of the samples within
// every aligned power-of-two block.
inline uint owen_scramble(uint x, uint seed) { return reverse_bits32(lk_permutation(reverse_bits32(x), seed)); }

// A 32-bit mixing function (Wellons's "lowbias32"), to derive independent
// seeds from one hash.
inline uint mix32(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// The second Sobol dimension of index i, bit-reversed. Its direction
// numbers v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1) hold, reversed, bit m
// exactly when C(k, m) is odd, that is (Lucas) when the bits of m are a
// subset of those of k. So reversed bit m of the point is the XOR of the
// bits k of i over all supersets k of m: a superset transform, five
// shift-and-mask steps instead of a loop over i's 32 bits.
inline uint sobol_dimension1_reversed(uint i)
{
    i ^= (i >> 1) & 0x55555555u;
    i ^= (i >> 2) & 0x33333333u;
    i ^= (i >> 4) & 0x0f0f0f0fu;
    i ^= (i >> 8) & 0x00ff00ffu;
    i ^= (i >> 16) & 0x0000ffffu;
    return i;
}

inline float scrambled_unit(uint bits) { return (float)(bits >> 8) * 0x1p-24f; }

// One scrambled 2D Sobol point: index j of the sequence (j already
// shuffled where the caller wants it). Scrambling works on the reversed
// digits, owen_scramble(x) = reverse(lk(reverse(x))), and dimension 0 of j
// is reverse(j), so both points are formed in reversed form and reversed
// once at the end.
inline float2 sobol_pair(uint j, uint seed)
{
    const uint seed_x = mix32(seed ^ 0x9e3779b9u), seed_y = mix32(seed ^ 0x7f4a7c15u);
    return (float2)(scrambled_unit(reverse_bits32(lk_permutation(j, seed_x))),
                    scrambled_unit(reverse_bits32(lk_permutation(sobol_dimension1_reversed(j), seed_y))));
}

// Owen scrambling of the sample index, given reversed: a random order of the
// samples within every aligned power-of-two block.
inline uint shuffled_index(uint i_reversed, uint seed) { return reverse_bits32(lk_permutation(i_reversed, seed)); }

inline Rand5 sobol_block(uint pixel, ulong sample, uint block, uint2 seed)
{
    // Per pixel and block (and per 2^32 samples, so indices past 2^32 do not
    // repeat points): the seeds of the three groups.
    const uint4 h = philox4x32((uint4)(block, (uint)(sample >> 32), 0x536f626cu, pixel), seed);
    const uint i_reversed = reverse_bits32((uint)sample);
    // Every pair, and the fifth number, takes the samples in its own random
    // order. Scrambled copies of one sequence taken in the same order are
    // correlated (their leading digits are equal or opposite), which would
    // tie the pixel jitter to the light samples of every bounce.
    const float2 a = sobol_pair(shuffled_index(i_reversed, h.x), h.x);
    const float2 b = sobol_pair(shuffled_index(i_reversed, h.y), h.y);
    Rand5 r;
    r.u0 = a.x;
    r.u1 = a.y;
    r.u2 = b.x;
    r.u3 = b.y;
    // 1D: van der Corput of the shuffled index, scrambled.
    r.u4 = scrambled_unit(reverse_bits32(lk_permutation(shuffled_index(i_reversed, h.z), h.w)));
    return r;
}

inline Rand5 rng_block(uint pixel, ulong sample, uint block, uint2 seed)
{
#if ORB_SAMPLER_SOBOL
    if (block < ORB_SOBOL_BLOCKS) return sobol_block(pixel, sample, block, seed);
    return philox_block(pixel, sample, block, seed);
#else
    return philox_block(pixel, sample, block, seed);
#endif
}
