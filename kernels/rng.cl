// Counter-based random numbers: Philox4x32 with 7 rounds (Salmon et al.,
// "Parallel random numbers: as easy as 1, 2, 3", SC'11, report 7 rounds
// already pass TestU01's BigCrush; 10 is their default safety margin, which
// here cost 15% of the CPU path tracer's speed). A draw is a pure function of
// (pixel, sample index, block, seed), so an image depends only on the seed and
// on which sample indices were rendered, never on how passes were split.
//
// One block yields five uniform floats: the top 24 bits of each 32-bit
// output give four, and the four low bytes (unused by those) give a fifth.

#define PHILOX_M0 0xD2511F53u
#define PHILOX_M1 0xCD9E8D57u
#define PHILOX_W0 0x9E3779B9u
#define PHILOX_W1 0xBB67AE85u

inline uint4 philox_round(uint4 ctr, uint2 key)
{
    const uint hi0 = mul_hi(PHILOX_M0, ctr.x);
    const uint lo0 = PHILOX_M0 * ctr.x;
    const uint hi1 = mul_hi(PHILOX_M1, ctr.z);
    const uint lo1 = PHILOX_M1 * ctr.z;
    return (uint4)(hi1 ^ ctr.y ^ key.x, lo1, hi0 ^ ctr.w ^ key.y, lo0);
}

#define PHILOX_ROUNDS 7

inline uint4 philox4x32(uint4 ctr, uint2 key)
{
    for (int i = 0; i < PHILOX_ROUNDS - 1; ++i) {
        ctr = philox_round(ctr, key);
        key += (uint2)(PHILOX_W0, PHILOX_W1);
    }
    return philox_round(ctr, key);
}

typedef struct {
    float u0, u1, u2, u3, u4;  // each uniform in [0, 1)
} Rand5;

inline float bits24_to_unit(uint bits24) { return (float)bits24 * 0x1p-24f; }

// The independent sampler (--sampler independent): five fresh numbers per
// (pixel, sample, block). kernels/sampler.cl chooses between it and the
// low-discrepancy sampler.
inline Rand5 philox_block(uint pixel, ulong sample, uint block, uint2 seed)
{
    const uint4 ctr = (uint4)(block, (uint)sample, (uint)(sample >> 32), pixel);
    const uint4 x = philox4x32(ctr, seed);
    Rand5 r;
    r.u0 = bits24_to_unit(x.x >> 8);
    r.u1 = bits24_to_unit(x.y >> 8);
    r.u2 = bits24_to_unit(x.z >> 8);
    r.u3 = bits24_to_unit(x.w >> 8);
    const uint low = (x.x & 0xFFu) | ((x.y & 0xFFu) << 8) | ((x.z & 0xFFu) << 16) | ((x.w & 0xFFu) << 24);
    r.u4 = bits24_to_unit(low >> 8);
    return r;
}
