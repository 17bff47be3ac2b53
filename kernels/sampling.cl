// Direction sampling. All directions are unit vectors in world space.

#define ORB_PI 3.14159265358979f
#define ORB_INV_PI 0.318309886183791f
#define ORB_INV_4PI 0.0795774715459477f

// (cos, sin) of the angle 2 pi v, v in [0, 1), with polynomials instead of
// the trigonometric library: on CPUs (PoCL) sin/cos calls cost a quarter of
// the whole path tracer, and every device gets the same values this way.
// The angle is split into a quarter turn k and a remainder theta in
// [-pi/4, pi/4), where the Taylor polynomials below are accurate to 3e-7.
// The reduction and the polynomials, over a float type T (the lanes of
// integrator_simd.cl use them too): declares k (the quarter turns, as T), s
// and c of the remainder.
#define ORB_UNIT_CIRCLE_TERMS(T, v)                                                                              \
    const T x_ = 4.0f * (v) + 0.5f;                                                                             \
    const T k = floor(x_);                                                                                      \
    const T theta_ = (x_ - k - 0.5f) * (0.5f * ORB_PI);                                                         \
    const T t2_ = theta_ * theta_;                                                                              \
    const T s = theta_ * (1.0f + t2_ * (-1.0f / 6.0f + t2_ * (1.0f / 120.0f + t2_ * (-1.0f / 5040.0f))));       \
    const T c = 1.0f + t2_ * (-0.5f + t2_ * (1.0f / 24.0f + t2_ * (-1.0f / 720.0f + t2_ * (1.0f / 40320.0f))));
inline float2 unit_circle(float v)
{
    ORB_UNIT_CIRCLE_TERMS(float, v)
    // Rotate (c, s) by k quarter turns.
    const int quarter = ((int)k) & 3;
    const float2 even = quarter == 0 ? (float2)(c, s) : (float2)(-c, -s);
    const float2 odd = quarter == 1 ? (float2)(-s, c) : (float2)(s, -c);
    return (quarter & 1) ? odd : even;
}

// An orthonormal basis around unit n (Duff et al., "Building an Orthonormal
// Basis, Revisited", JCGT 2017): branch-free apart from the sign.
inline void orthonormal_basis(float3 n, float3* t, float3* b)
{
    const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    *t = (float3)(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = (float3)(c, sign + n.y * n.y * a, -n.y);
}

inline float3 from_local(float3 n, float x, float y, float z)
{
    float3 t, b;
    orthonormal_basis(n, &t, &b);
    return x * t + y * b + z * n;
}

// Cosine-weighted direction about n; pdf = cos(theta) / pi.
inline float3 sample_cosine_hemisphere(float3 n, float u, float v, float* cos_theta)
{
    const float r = sqrt(u);
    const float2 cs = unit_circle(v);
    const float z = sqrt(max(0.0f, 1.0f - u));
    *cos_theta = z;
    return from_local(n, r * cs.x, r * cs.y, z);
}

// Uniform direction inside the cone about unit w with 1 - cos(theta_max) =
// one_minus_cos_max; pdf = 1 / (2 pi one_minus_cos_max). Works from 1 - cos
// so that small, distant cones keep their precision.
inline float3 sample_uniform_cone(float3 w, float one_minus_cos_max, float u, float v)
{
    const float one_minus_cos = u * one_minus_cos_max;
    const float cos_theta = 1.0f - one_minus_cos;
    const float sin_theta = sqrt(max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
    const float2 cs = unit_circle(v);
    return from_local(w, sin_theta * cs.x, sin_theta * cs.y, cos_theta);
}

// Uniform direction on the whole sphere; pdf = 1 / (4 pi).
inline float3 sample_uniform_sphere(float u, float v)
{
    const float z = 1.0f - 2.0f * u;
    const float r = sqrt(max(0.0f, 1.0f - z * z));
    const float2 cs = unit_circle(v);
    return (float3)(r * cs.x, r * cs.y, z);
}

// Point on the unit disk, uniform by area (polar mapping).
inline float2 sample_uniform_disk(float u, float v)
{
    const float r = sqrt(u);
    const float2 cs = unit_circle(v);
    return (float2)(r * cs.x, r * cs.y);
}

// Power heuristic (beta = 2) weight of strategy f against strategy g.
inline float power_heuristic(float pdf_f, float pdf_g)
{
    const float f2 = pdf_f * pdf_f;
    return f2 / (f2 + pdf_g * pdf_g);
}

// 1 - cos(theta_max) of the cone subtended by a sphere seen from outside,
// computed as sin^2 / (1 + cos) to keep precision for distant spheres.
inline float cone_one_minus_cos(float distance2, float radius)
{
    const float sin2 = fmin(1.0f, radius * radius / distance2);
    return sin2 / (1.0f + sqrt(1.0f - sin2));
}
