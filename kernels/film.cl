// Film sums on the device: 3 floats per pixel for colour sets, 1 for scalars.

inline void film_add3(__global float* sums, uint pixel, float3 value)
{
    vstore3(vload3(pixel, sums) + value, pixel, sums);
}

inline void film_add1(__global float* sums, uint pixel, float value) { sums[pixel] += value; }
