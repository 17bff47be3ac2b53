// Materials: Lambertian diffuse, perfect mirror, smooth dielectric.

typedef struct {
    float3 dir;     // sampled incident direction (unit), pointing away from the surface
    float3 weight;  // f * |cos| / pdf (the throughput factor)
    float pdf;      // solid-angle pdf; 0 for the delta (specular) lobes
    float eta2;     // the (n_i / n_t)^2 radiance factor inside `weight` (refraction), else 1
} BsdfSample;

// Exact Fresnel reflectance of a smooth dielectric for unpolarised light.
// cos_i: cosine of the angle of incidence (> 0); eta = n_incident / n_transmitted.
// Returns 1 on total internal reflection; *cos_t receives the transmitted cosine.
inline float fresnel_dielectric(float cos_i, float eta, float* cos_t)
{
    const float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) {
        *cos_t = 0.0f;
        return 1.0f;
    }
    const float ct = sqrt(1.0f - sin2_t);
    *cos_t = ct;
    const float rs = (eta * cos_i - ct) / (eta * cos_i + ct);
    const float rp = (cos_i - eta * ct) / (cos_i + eta * ct);
    return 0.5f * (rs * rs + rp * rp);
}

// d: incoming ray direction (towards the surface); n: unit normal facing the
// ray (dot(d, n) < 0); entering: the ray arrives from outside the sphere.
inline BsdfSample sample_bsdf(const ShadingSphere* m, float3 d, float3 n, bool entering, float u, float v, float w)
{
    BsdfSample s;
    s.eta2 = 1.0f;
    if (m->kind == MaterialKind_Diffuse) {
        float cos_theta;
        s.dir = sample_cosine_hemisphere(n, u, v, &cos_theta);
        s.weight = m->color;  // (color / pi) * cos / (cos / pi)
        s.pdf = cos_theta * ORB_INV_PI;
        return s;
    }
    const float cos_i = -dot(d, n);
    const float3 reflected = d + (2.0f * cos_i) * n;
    s.pdf = 0.0f;
    s.weight = m->color;
    s.dir = reflected;
    if (m->kind == MaterialKind_Mirror) return s;

    const float eta = entering ? 1.0f / m->ior : m->ior;
    float cos_t;
    const float reflectance = fresnel_dielectric(cos_i, eta, &cos_t);
    // Choose reflection with probability F, so F / F = 1 and (1-F) / (1-F) = 1.
    if (w < reflectance) return s;
    s.dir = normalize(eta * d + (eta * cos_i - cos_t) * n);
    // L / n^2 is invariant across the interface, so radiance arriving from the
    // transmitted side is scaled by (n_i / n_t)^2 = eta^2 on the camera side.
    s.eta2 = eta * eta;
    s.weight = m->color * s.eta2;
    return s;
}
