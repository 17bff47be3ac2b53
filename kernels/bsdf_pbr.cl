// glTF 2.0's metallic-roughness material (docs/rendering.md, "pbr"): a GGX
// specular lobe with Schlick's Fresnel, F0 = mix(0.04, color, metallic), over
// a Lambertian base of colour color (1 - metallic) that receives what the
// specular layer of the dielectric part does not reflect (albedo scaling with
// the tabulated E of bsdf_pbr_albedo.cl, so a white material never reflects
// more than it receives).

LANE_FN lv3 pbr_f0(const Bsdf* b)
{
    return lv3_add(lv3_fill(0.04f), lv3_scale(lv3_sub(b->color, lv3_fill(0.04f)), b->metallic));
}

LANE_FN lv3 pbr_diffuse_color(const Bsdf* b) { return lv3_scale(b->color, 1.0f - b->metallic); }

LANE_FN lv3 schlick_fresnel(lv3 f0, lfloat cos_theta)
{
    const lfloat x = 1.0f - cos_theta;
    const lfloat x2 = x * x;
    return lv3_add(f0, lv3_scale(lv3_sub(lv3_fill(1.0f), f0), x2 * x2 * x));
}

// The row of the albedo table for `roughness`, as a position in [0, last].
LANE_FN lfloat pbr_albedo_row(lfloat roughness)
{
    const float last = (float)(PBR_ALBEDO_SIZE - 1);
    return clamp((roughness - PBR_ALBEDO_MIN_ROUGHNESS) / (1.0f - PBR_ALBEDO_MIN_ROUGHNESS), (lfloat)(0.0f),
                 (lfloat)(1.0f)) *
           last;
}

// E(cos_o): the directional albedo of the specular lobe of the dielectric
// part (F0 = 0.04), an upper bound interpolated from the table; Schlick's F
// itself for a smooth surface, whose lobe is a delta of exactly that weight.
LANE_FN lfloat pbr_layer_albedo(lfloat roughness, lfloat cos_o)
{
    const lfloat smooth_albedo = schlick_fresnel(lv3_fill(0.04f), cos_o).x;
    const lmask smooth = ggx_is_smooth(ggx_alpha(roughness));
    if (lanes_all(smooth)) return smooth_albedo;
    const float last = (float)(PBR_ALBEDO_SIZE - 1);
    const lfloat x = clamp(cos_o, (lfloat)(0.0f), (lfloat)(1.0f)) * last;
    const lfloat y = pbr_albedo_row(roughness);
    const lint i = min(to_lint(x), (lint)(PBR_ALBEDO_SIZE - 2));
    const lint j = min(to_lint(y), (lint)(PBR_ALBEDO_SIZE - 2));
    const lfloat fx = x - to_lfloat(i), fy = y - to_lfloat(j);
    const lint corner = j * PBR_ALBEDO_SIZE + i;
    const int size = PBR_ALBEDO_SIZE * PBR_ALBEDO_SIZE;
    const lfloat lower = mix(lanes_gather(pbr_albedo_table, corner, size),
                             lanes_gather(pbr_albedo_table, corner + 1, size), fx);
    const lfloat upper = mix(lanes_gather(pbr_albedo_table, corner + PBR_ALBEDO_SIZE, size),
                             lanes_gather(pbr_albedo_table, corner + PBR_ALBEDO_SIZE + 1, size), fx);
    return lselect(mix(lower, upper, fy), smooth_albedo, smooth);
}

// 2 * integral of E(mu) mu dmu, the share of uniform light the layer reflects.
LANE_FN lfloat pbr_layer_albedo_average(lfloat roughness)
{
    // Schlick's F averaged so: F0 + (1 - F0) * 2 B(2, 6) = F0 + (1 - F0) / 21.
    const lmask smooth = ggx_is_smooth(ggx_alpha(roughness));
    const lfloat smooth_average = (lfloat)(0.04f + 0.96f / 21.0f);
    if (lanes_all(smooth)) return smooth_average;
    const lfloat y = pbr_albedo_row(roughness);
    const lint j = min(to_lint(y), (lint)(PBR_ALBEDO_SIZE - 2));
    const lfloat rough_average = mix(lanes_gather(pbr_albedo_average, j, PBR_ALBEDO_SIZE),
                                     lanes_gather(pbr_albedo_average, j + 1, PBR_ALBEDO_SIZE), y - to_lfloat(j));
    return lselect(rough_average, smooth_average, smooth);
}

// What each lobe reflects of light from wo, roughly: Schlick's F at wo for
// the specular lobe (its albedo before shadowing), the scaled base for the
// diffuse one. They choose the lobe to sample and make the albedo pass.
LANE_FN lv3 pbr_specular_share(const Bsdf* b, lfloat cos_o) { return schlick_fresnel(pbr_f0(b), cos_o); }

LANE_FN lv3 pbr_diffuse_share(const Bsdf* b, lfloat cos_o)
{
    return lv3_scale(pbr_diffuse_color(b), 1.0f - pbr_layer_albedo(b->roughness, cos_o));
}

// The chance of sampling the specular lobe: its share of the mean reflectance.
LANE_FN lfloat pbr_specular_probability(const Bsdf* b, lfloat cos_o)
{
    const lv3 s = pbr_specular_share(b, cos_o);
    const lv3 d = pbr_diffuse_share(b, cos_o);
    const lfloat ws = lv3_sum(s), wd = lv3_sum(d);
    return lselect((lfloat)(1.0f), ws / (ws + wd), wd > 0.0f);
}

LANE_FN lmask pbr_has_density(const Bsdf* b)
{
    return mask_or(mask_not(ggx_is_smooth(ggx_alpha(b->roughness))), b->metallic < 1.0f);
}

// f cos for both lobes (the specular one only when rough) and the pdf of
// pbr_sample, which picks the specular lobe with pbr_specular_probability.
LANE_FN lv3 pbr_eval(const Bsdf* b, lv3 wo, lv3 wi, lv3 n, lmask outside, lfloat* pdf)
{
    const lfloat cos_o = lv3_dot(wo, n);
    const lfloat cos_i = lv3_dot(wi, n);
    *pdf = (lfloat)(0.0f);
    const lmask valid = mask_and(cos_i > 0.0f, cos_o > 0.0f);
    if (!lanes_any(valid)) return lv3_zero();
    const lfloat alpha = ggx_alpha(b->roughness);
    const lfloat p_specular = pbr_specular_probability(b, cos_o);

    // Diffuse base: color (1 - metallic) / pi, scaled by what the layer lets
    // through on both sides, (1 - E(cos_o)) (1 - E(cos_i)) / (1 - E_avg):
    // reciprocal, and its albedo is exactly color (1 - metallic) (1 - E(cos_o)).
    const lfloat e_o = pbr_layer_albedo(b->roughness, cos_o);
    const lfloat e_i = pbr_layer_albedo(b->roughness, cos_i);
    const lfloat scale = (1.0f - e_o) * (1.0f - e_i) / (1.0f - pbr_layer_albedo_average(b->roughness));
    lv3 f_cos = lv3_scale(pbr_diffuse_color(b), scale * cos_i * ORB_INV_PI);
    lfloat density = (1.0f - p_specular) * cos_i * ORB_INV_PI;

    const lmask glossy = mask_and(valid, mask_not(ggx_is_smooth(alpha)));
    if (lanes_any(glossy)) {
        // Specular lobe: F(wo.h) D(h) G2 / (4 cos_o cos_i), times cos_i; its
        // pdf, visible normals reflected about h: D_wo(h) / (4 wo.h) = G1(wo) D(h) / (4 cos_o).
        const lv3 h = lv3_normalize(lv3_add(wo, wi));
        const lfloat d = ggx_d(alpha, h, n);
        const lfloat lambda_o = ggx_lambda(alpha, cos_o);
        const lfloat g2 = 1.0f / (1.0f + lambda_o + ggx_lambda(alpha, cos_i));
        const lv3 fresnel = schlick_fresnel(pbr_f0(b), fmax((lfloat)(0.0f), lv3_dot(wo, h)));
        f_cos = lv3_select(f_cos, lv3_add(f_cos, lv3_scale(fresnel, d * g2 / (4.0f * cos_o))), glossy);
        density = lselect(density, density + p_specular * d * ggx_visible_factor(lambda_o, cos_o) * 0.25f, glossy);
    }
    *pdf = lselect((lfloat)(0.0f), density, valid);
    return lv3_select(lv3_zero(), f_cos, valid);
}

LANE_FN BsdfSample pbr_sample(const Bsdf* b, lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lfloat* choice)
{
    const lfloat cos_o = lv3_dot(wo, n);
    const lfloat alpha = ggx_alpha(b->roughness);
    const lfloat p_specular = pbr_specular_probability(b, cos_o);
    const lmask specular = choose_lobe(p_specular, choice);
    const lmask smooth = ggx_is_smooth(alpha);
    BsdfSample s = bsdf_no_sample();
    // A smooth specular layer: a delta lobe of reflectance F(cos_o).
    const lmask delta = mask_and(specular, smooth);
    if (lanes_any(delta)) {
        BsdfSample d;
        d.wi = reflect_about(wo, n);
        d.weight = lv3_scale(pbr_specular_share(b, cos_o), 1.0f / p_specular);
        d.pdf = (lfloat)(0.0f);
        d.delta = mask_of(true);
        d.eta2 = (lfloat)(1.0f);
        s = bsdf_sample_select(s, d, delta);
    }
    const lmask density = mask_not(delta);
    if (lanes_any(density)) {
        lv3 wi = lv3_zero();
        const lmask glossy = mask_and(specular, density);
        if (lanes_any(glossy)) wi = lv3_select(wi, reflect_about(wo, ggx_sample_visible_normal(alpha, wo, n, u, v)), glossy);
        const lmask base = mask_not(specular);
        if (lanes_any(base)) {
            lfloat cos_i;
            wi = lv3_select(wi, sample_cosine_hemisphere(n, u, v, &cos_i), base);
        }
        // Both lobes could have produced wi: weigh it by the whole BSDF over the
        // mixture's pdf, from the same function that MIS and pbr_pdf use.
        BsdfSample r;
        r.wi = wi;
        r.delta = mask_of(false);
        r.eta2 = (lfloat)(1.0f);
        const lv3 f_cos = pbr_eval(b, wo, wi, n, outside, &r.pdf);
        r.weight = lv3_scale(f_cos, 1.0f / r.pdf);
        s = bsdf_sample_select(s, r, mask_and(density, r.pdf > 0.0f));  // else reflected below the surface
    }
    return s;
}

LANE_FN lv3 pbr_albedo(const Bsdf* b, lv3 wo, lv3 n)
{
    const lfloat cos_o = lv3_dot(wo, n);
    return lv3_add(pbr_specular_share(b, cos_o), pbr_diffuse_share(b, cos_o));
}
