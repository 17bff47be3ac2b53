// glTF 2.0's metallic-roughness material (docs/rendering.md, "pbr"): a GGX
// specular lobe with Schlick's Fresnel, F0 = mix(0.04, color, metallic), over
// a Lambertian base of colour color (1 - metallic) that receives what the
// specular layer of the dielectric part does not reflect (albedo scaling with
// the tabulated E of bsdf_pbr_albedo.cl, so a white material never reflects
// more than it receives).

inline float3 pbr_f0(const Bsdf* b) { return mix((float3)(0.04f), b->color, b->metallic); }

inline float3 pbr_diffuse_color(const Bsdf* b) { return b->color * (1.0f - b->metallic); }

inline float3 schlick_fresnel(float3 f0, float cos_theta)
{
    const float x = 1.0f - cos_theta;
    const float x2 = x * x;
    return f0 + (1.0f - f0) * (x2 * x2 * x);
}

// E(cos_o): the directional albedo of the specular lobe of the dielectric
// part (F0 = 0.04), an upper bound interpolated from the table; Schlick's F
// itself for a smooth surface, whose lobe is a delta of exactly that weight.
inline float pbr_layer_albedo(float roughness, float cos_o)
{
    if (ggx_is_smooth(ggx_alpha(roughness))) return schlick_fresnel((float3)(0.04f), cos_o).x;
    const float last = (float)(PBR_ALBEDO_SIZE - 1);
    const float x = clamp(cos_o, 0.0f, 1.0f) * last;
    const float y = clamp((roughness - PBR_ALBEDO_MIN_ROUGHNESS) / (1.0f - PBR_ALBEDO_MIN_ROUGHNESS), 0.0f, 1.0f) * last;
    const int i = min((int)x, PBR_ALBEDO_SIZE - 2);
    const int j = min((int)y, PBR_ALBEDO_SIZE - 2);
    const float fx = x - (float)i, fy = y - (float)j;
    __constant const float* row = pbr_albedo_table + j * PBR_ALBEDO_SIZE + i;
    const float lower = mix(row[0], row[1], fx);
    const float upper = mix(row[PBR_ALBEDO_SIZE], row[PBR_ALBEDO_SIZE + 1], fx);
    return mix(lower, upper, fy);
}

// 2 * integral of E(mu) mu dmu, the share of uniform light the layer reflects.
inline float pbr_layer_albedo_average(float roughness)
{
    // Schlick's F averaged so: F0 + (1 - F0) * 2 B(2, 6) = F0 + (1 - F0) / 21.
    if (ggx_is_smooth(ggx_alpha(roughness))) return 0.04f + 0.96f / 21.0f;
    const float last = (float)(PBR_ALBEDO_SIZE - 1);
    const float y = clamp((roughness - PBR_ALBEDO_MIN_ROUGHNESS) / (1.0f - PBR_ALBEDO_MIN_ROUGHNESS), 0.0f, 1.0f) * last;
    const int j = min((int)y, PBR_ALBEDO_SIZE - 2);
    return mix(pbr_albedo_average[j], pbr_albedo_average[j + 1], y - (float)j);
}

// What each lobe reflects of light from wo, roughly: Schlick's F at wo for
// the specular lobe (its albedo before shadowing), the scaled base for the
// diffuse one. They choose the lobe to sample and make the albedo pass.
inline float3 pbr_specular_share(const Bsdf* b, float cos_o) { return schlick_fresnel(pbr_f0(b), cos_o); }

inline float3 pbr_diffuse_share(const Bsdf* b, float cos_o)
{
    return pbr_diffuse_color(b) * (1.0f - pbr_layer_albedo(b->roughness, cos_o));
}

// The chance of sampling the specular lobe: its share of the mean reflectance.
inline float pbr_specular_probability(const Bsdf* b, float cos_o)
{
    const float3 s = pbr_specular_share(b, cos_o);
    const float3 d = pbr_diffuse_share(b, cos_o);
    const float ws = s.x + s.y + s.z, wd = d.x + d.y + d.z;
    return wd > 0.0f ? ws / (ws + wd) : 1.0f;
}

inline bool pbr_has_density(const Bsdf* b)
{
    return !ggx_is_smooth(ggx_alpha(b->roughness)) || b->metallic < 1.0f;
}

// f cos for both lobes (the specular one only when rough) and the pdf of
// pbr_sample, which picks the specular lobe with pbr_specular_probability.
inline float3 pbr_eval(const Bsdf* b, float3 wo, float3 wi, float3 n, bool outside, float* pdf)
{
    const float cos_o = dot(wo, n);
    const float cos_i = dot(wi, n);
    *pdf = 0.0f;
    if (cos_i <= 0.0f || cos_o <= 0.0f) return (float3)(0.0f);
    const float alpha = ggx_alpha(b->roughness);
    const float p_specular = pbr_specular_probability(b, cos_o);

    // Diffuse base: color (1 - metallic) / pi, scaled by what the layer lets
    // through on both sides, (1 - E(cos_o)) (1 - E(cos_i)) / (1 - E_avg):
    // reciprocal, and its albedo is exactly color (1 - metallic) (1 - E(cos_o)).
    const float e_o = pbr_layer_albedo(b->roughness, cos_o);
    const float e_i = pbr_layer_albedo(b->roughness, cos_i);
    const float scale = (1.0f - e_o) * (1.0f - e_i) / (1.0f - pbr_layer_albedo_average(b->roughness));
    float3 f_cos = pbr_diffuse_color(b) * (scale * cos_i * ORB_INV_PI);
    float density = (1.0f - p_specular) * cos_i * ORB_INV_PI;

    if (!ggx_is_smooth(alpha)) {
        // Specular lobe: F(wo.h) D(h) G2 / (4 cos_o cos_i), times cos_i; its
        // pdf, visible normals reflected about h: D_wo(h) / (4 wo.h) = G1(wo) D(h) / (4 cos_o).
        const float3 h = normalize(wo + wi);
        const float d = ggx_d(alpha, h, n);
        const float lambda_o = ggx_lambda(alpha, cos_o);
        const float g2 = 1.0f / (1.0f + lambda_o + ggx_lambda(alpha, cos_i));
        const float3 fresnel = schlick_fresnel(pbr_f0(b), fmax(0.0f, dot(wo, h)));
        f_cos += fresnel * (d * g2 / (4.0f * cos_o));
        density += p_specular * d * ggx_visible_factor(lambda_o, cos_o) * 0.25f;
    }
    *pdf = density;
    return f_cos;
}

inline BsdfSample pbr_sample(const Bsdf* b, float3 wo, float3 n, bool outside, float u, float v, float* choice)
{
    const float cos_o = dot(wo, n);
    const float alpha = ggx_alpha(b->roughness);
    const float p_specular = pbr_specular_probability(b, cos_o);
    BsdfSample s;
    s.eta2 = 1.0f;
    s.delta = false;
    if (choose_lobe(p_specular, choice)) {
        if (ggx_is_smooth(alpha)) {
            // A smooth specular layer: a delta lobe of reflectance F(cos_o).
            s.wi = reflect_about(wo, n);
            s.weight = pbr_specular_share(b, cos_o) * (1.0f / p_specular);
            s.pdf = 0.0f;
            s.delta = true;
            return s;
        }
        s.wi = reflect_about(wo, ggx_sample_visible_normal(alpha, wo, n, u, v));
    } else {
        float cos_i;
        s.wi = sample_cosine_hemisphere(n, u, v, &cos_i);
    }
    // Both lobes could have produced wi: weigh it by the whole BSDF over the
    // mixture's pdf, from the same function that MIS and pbr_pdf use.
    const float3 f_cos = pbr_eval(b, wo, s.wi, n, outside, &s.pdf);
    if (!(s.pdf > 0.0f)) return bsdf_no_sample();  // reflected below the surface
    s.weight = f_cos * (1.0f / s.pdf);
    return s;
}

inline float3 pbr_albedo(const Bsdf* b, float3 wo, float3 n)
{
    const float cos_o = dot(wo, n);
    return pbr_specular_share(b, cos_o) + pbr_diffuse_share(b, cos_o);
}
