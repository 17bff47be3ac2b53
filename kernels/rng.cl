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

// Philox4x32 over a counter held in four values of an integer type T (uint
// here, the lanes' luint in sampler.cl), with the function's qualifiers Q:
// one text for every width.
#define ORB_DEFINE_PHILOX4X32(Q, T, name)                             \
    Q void name(T* c0, T* c1, T* c2, T* c3, uint2 key)                \
    {                                                                 \
        for (int i = 0; i < PHILOX_ROUNDS; ++i) {                     \
            const T hi0 = mul_hi((T)(PHILOX_M0), *c0);                \
            const T lo0 = PHILOX_M0 * *c0;                            \
            const T hi1 = mul_hi((T)(PHILOX_M1), *c2);                \
            const T lo1 = PHILOX_M1 * *c2;                            \
            *c0 = hi1 ^ *c1 ^ key.x;                                  \
            *c1 = lo1;                                                \
            *c2 = hi0 ^ *c3 ^ key.y;                                  \
            *c3 = lo0;                                                \
            key += (uint2)(PHILOX_W0, PHILOX_W1);                     \
        }                                                             \
    }

#define PHILOX_ROUNDS 7

ORB_DEFINE_PHILOX4X32(inline, uint, philox4x32_words)

inline uint4 philox4x32(uint4 ctr, uint2 key)
{
    uint c0 = ctr.x, c1 = ctr.y, c2 = ctr.z, c3 = ctr.w;
    philox4x32_words(&c0, &c1, &c2, &c3, key);
    return (uint4)(c0, c1, c2, c3);
}

// The five numbers of a block from Philox's four words (of type T, floats
// of type F converted by to_float): the top 24 bits of each word give
// four, the words' low bytes the fifth.
#define ORB_DEFINE_PHILOX_UNITS(Q, T, F, to_float, name)                                            \
    Q void name(T c0, T c1, T c2, T c3, F* u0, F* u1, F* u2, F* u3, F* u4)                          \
    {                                                                                               \
        *u0 = to_float(c0 >> 8) * 0x1p-24f;                                                         \
        *u1 = to_float(c1 >> 8) * 0x1p-24f;                                                         \
        *u2 = to_float(c2 >> 8) * 0x1p-24f;                                                         \
        *u3 = to_float(c3 >> 8) * 0x1p-24f;                                                         \
        const T low = (c0 & 0xFFu) | ((c1 & 0xFFu) << 8) | ((c2 & 0xFFu) << 16) | ((c3 & 0xFFu) << 24); \
        *u4 = to_float(low >> 8) * 0x1p-24f;                                                        \
    }
#define ORB_FLOAT_OF_UINT(x) ((float)(x))
ORB_DEFINE_PHILOX_UNITS(inline, uint, float, ORB_FLOAT_OF_UINT, philox_units)

typedef struct {
    float u0, u1, u2, u3, u4;  // each uniform in [0, 1)
} Rand5;

// The independent sampler (--sampler independent): five fresh numbers per
// (pixel, sample, block). kernels/sampler.cl chooses between it and the
// low-discrepancy sampler.
inline Rand5 philox_block(uint pixel, ulong sample, uint block, uint2 seed)
{
    uint c0 = block, c1 = (uint)sample, c2 = (uint)(sample >> 32), c3 = pixel;
    philox4x32_words(&c0, &c1, &c2, &c3, seed);
    Rand5 r;
    philox_units(c0, c1, c2, c3, &r.u0, &r.u1, &r.u2, &r.u3, &r.u4);
    return r;
}
