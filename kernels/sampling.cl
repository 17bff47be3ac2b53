// Direction sampling. All directions are unit vectors in world space.

#define ORB_PI 3.14159265358979f
#define ORB_INV_PI 0.318309886183791f
#define ORB_INV_4PI 0.0795774715459477f

// (cos, sin) of the angle 2 pi v, v in [0, 1), with polynomials instead of
// the trigonometric library: on CPUs (PoCL) sin/cos calls cost a quarter of
// the whole path tracer, and every device gets the same values this way.
// The angle is split into a quarter turn k and a remainder theta in
// [-pi/4, pi/4), where the Taylor polynomials below are accurate to 3e-7.
// The reduction and the polynomials, over a float type T: declares k (the
// quarter turns, as T), s and c of the remainder.
#define ORB_UNIT_CIRCLE_TERMS(T, v)                                                                              \
    const T x_ = 4.0f * (v) + 0.5f;                                                                             \
    const T k = floor(x_);                                                                                      \
    const T theta_ = (x_ - k - 0.5f) * (0.5f * ORB_PI);                                                         \
    const T t2_ = theta_ * theta_;                                                                              \
    const T s = theta_ * (1.0f + t2_ * (-1.0f / 6.0f + t2_ * (1.0f / 120.0f + t2_ * (-1.0f / 5040.0f))));       \
    const T c = 1.0f + t2_ * (-0.5f + t2_ * (1.0f / 24.0f + t2_ * (-1.0f / 720.0f + t2_ * (1.0f / 40320.0f))));
// Then (c, s) rotated by k quarter turns, written with select, which takes
// a scalar condition (nonzero) and a vector one (-1 lanes) alike: one text
// for a float F with int I (the environment's scalar code) and for lanes.
#define ORB_DEFINE_UNIT_CIRCLE(Q, F, I, to_int, name)                    \
    Q void name(F v, F* cos_out, F* sin_out)                             \
    {                                                                    \
        ORB_UNIT_CIRCLE_TERMS(F, v)                                      \
        const I quarter = to_int(k) & 3;                                 \
        const I q0 = quarter == 0, q1 = quarter == 1, odd = (quarter & 1) != 0; \
        *cos_out = select(select(-c, c, q0), select(s, -s, q1), odd);    \
        *sin_out = select(select(-s, s, q0), select(-c, c, q1), odd);    \
    }
#define ORB_INT_OF_FLOAT(x) ((int)(x))
ORB_DEFINE_UNIT_CIRCLE(inline, float, int, ORB_INT_OF_FLOAT, unit_circle_scalar)
#if ORB_LANES == 1
#define lanes_unit_circle unit_circle_scalar
#else
#define ORB_LINT_OF_LFLOAT(x) to_lint(x)
ORB_DEFINE_UNIT_CIRCLE(LANE_FN, lfloat, lint, ORB_LINT_OF_LFLOAT, lanes_unit_circle)
#endif

inline float2 unit_circle(float v)
{
    float c, s;
    unit_circle_scalar(v, &c, &s);
    return (float2)(c, s);
}

// From here on, over lanes.

// An orthonormal basis around unit n (Duff et al., "Building an Orthonormal
// Basis, Revisited", JCGT 2017): branch-free apart from the sign.
LANE_FN void orthonormal_basis(lv3 n, lv3* t, lv3* b)
{
    const lfloat sign = lselect((lfloat)(-1.0f), (lfloat)(1.0f), n.z >= 0.0f);
    const lfloat a = -1.0f / (sign + n.z);
    const lfloat c = n.x * n.y * a;
    *t = lv3_make(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = lv3_make(c, sign + n.y * n.y * a, -n.y);
}

LANE_FN lv3 from_local(lv3 n, lfloat x, lfloat y, lfloat z)
{
    lv3 t, b;
    orthonormal_basis(n, &t, &b);
    return lv3_add(lv3_add(lv3_scale(t, x), lv3_scale(b, y)), lv3_scale(n, z));
}

// Cosine-weighted direction about n; pdf = cos(theta) / pi.
LANE_FN lv3 sample_cosine_hemisphere(lv3 n, lfloat u, lfloat v, lfloat* cos_theta)
{
    const lfloat r = sqrt(u);
    lfloat c, s;
    lanes_unit_circle(v, &c, &s);
    const lfloat z = sqrt(fmax((lfloat)(0.0f), 1.0f - u));
    *cos_theta = z;
    return from_local(n, r * c, r * s, z);
}

// Uniform direction inside the cone about unit w with 1 - cos(theta_max) =
// one_minus_cos_max; pdf = 1 / (2 pi one_minus_cos_max). Works from 1 - cos
// so that small, distant cones keep their precision.
LANE_FN lv3 sample_uniform_cone(lv3 w, lfloat one_minus_cos_max, lfloat u, lfloat v)
{
    const lfloat one_minus_cos = u * one_minus_cos_max;
    const lfloat cos_theta = 1.0f - one_minus_cos;
    const lfloat sin_theta = sqrt(fmax((lfloat)(0.0f), one_minus_cos * (2.0f - one_minus_cos)));
    lfloat c, s;
    lanes_unit_circle(v, &c, &s);
    return from_local(w, sin_theta * c, sin_theta * s, cos_theta);
}

// Uniform direction on the whole sphere; pdf = 1 / (4 pi).
LANE_FN lv3 sample_uniform_sphere(lfloat u, lfloat v)
{
    const lfloat z = 1.0f - 2.0f * u;
    const lfloat r = sqrt(fmax((lfloat)(0.0f), 1.0f - z * z));
    lfloat c, s;
    lanes_unit_circle(v, &c, &s);
    return lv3_make(r * c, r * s, z);
}

// Power heuristic (beta = 2) weight of strategy f against strategy g.
LANE_FN lfloat power_heuristic(lfloat pdf_f, lfloat pdf_g)
{
    const lfloat f2 = pdf_f * pdf_f;
    return f2 / (f2 + pdf_g * pdf_g);
}

// 1 - cos(theta_max) of the cone subtended by a sphere seen from outside,
// computed as sin^2 / (1 + cos) to keep precision for distant spheres.
LANE_FN lfloat cone_one_minus_cos(lfloat distance2, lfloat radius)
{
    const lfloat sin2 = fmin((lfloat)(1.0f), radius * radius / distance2);
    return sin2 / (1.0f + sqrt(1.0f - sin2));
}
