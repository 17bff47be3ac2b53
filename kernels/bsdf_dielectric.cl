// Glass: a smooth interface between the outside (index 1) and the sphere's
// inside (index `ior`), tinted by `color` on both reflection and refraction.

// Exact Fresnel reflectance of a smooth dielectric for unpolarised light.
// cos_i: cosine of the angle of incidence (> 0); eta = n_incident / n_transmitted.
// Returns 1 on total internal reflection; *cos_t receives the transmitted cosine.
LANE_FN lfloat fresnel_dielectric(lfloat cos_i, lfloat eta, lfloat* cos_t)
{
    const lfloat sin2_t = eta * eta * fmax((lfloat)(0.0f), 1.0f - cos_i * cos_i);
    const lmask total = sin2_t >= 1.0f;
    const lfloat ct = sqrt(fmax((lfloat)(0.0f), 1.0f - sin2_t));
    *cos_t = ct;  // 0 on total reflection
    const lfloat rs = (eta * cos_i - ct) / (eta * cos_i + ct);
    const lfloat rp = (cos_i - eta * ct) / (cos_i + eta * ct);
    return lselect(0.5f * (rs * rs + rp * rp), (lfloat)(1.0f), total);
}

// Rough glass's code is in the program only when a glass of the scene is
// rough (-DORB_ROUGH_DIELECTRIC=0 from the host otherwise; built when absent).
LANE_FN lmask dielectric_is_smooth(lfloat alpha)
{
    return mask_or(mask_of(!ORB_ROUGH_DIELECTRIC), ggx_is_smooth(alpha));
}

LANE_FN lmask dielectric_has_density(const Bsdf* b) { return mask_not(dielectric_is_smooth(ggx_alpha(b->roughness))); }

// n_o / n_i for wo on the `outside` side.
LANE_FN lfloat dielectric_eta(const Bsdf* b, lmask outside) { return lselect(b->ior, 1.0f / b->ior, outside); }

// Smooth glass: reflects with probability F and refracts with 1 - F, so the
// Fresnel factors cancel in the weight.
LANE_FN BsdfSample smooth_dielectric_sample(const Bsdf* b, lv3 wo, lv3 n, lmask outside, lfloat* choice)
{
    BsdfSample s;
    s.pdf = (lfloat)(0.0f);
    s.delta = mask_of(true);
    const lfloat cos_o = lv3_dot(wo, n);
    const lfloat eta = dielectric_eta(b, outside);
    lfloat cos_t;
    const lfloat reflectance = fresnel_dielectric(cos_o, eta, &cos_t);
    const lmask reflect = choose_lobe(reflectance, choice);
    const lv3 refracted = lv3_normalize(lv3_add(lv3_scale(wo, -eta), lv3_scale(n, eta * cos_o - cos_t)));
    s.wi = lv3_select(refracted, reflect_about(wo, n), reflect);
    // L / n^2 is invariant across the interface, so radiance arriving from the
    // transmitted side is scaled by (n_o / n_i)^2 = eta^2 on the viewer's side.
    s.eta2 = lselect(eta * eta, (lfloat)(1.0f), reflect);
    s.weight = lv3_select(lv3_scale(b->color, s.eta2), b->color, reflect);
    return s;
}

// Rough glass (Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces"): GGX microfacets, each a smooth interface. f cos and the pdf
// of dielectric_sample, which reflects about a visible normal m with
// probability F(wo.m) and refracts through it otherwise.
//   reflection:   f cos = F D G2 / (4 cos_o),
//                 pdf = F G1(wo) D / (4 cos_o)      (m = the half vector of wo, wi)
//   refraction:   f cos = eta^2 (1 - F) D G2 |wi.m| (wo.m) / (cos_o (wi.m + eta wo.m)^2),
//                 pdf = (1 - F) G1(wo) D (wo.m) |wi.m| / (cos_o (wi.m + eta wo.m)^2)
//                 (m along eta wo + wi, the generalised half vector)
// with eta = n_o / n_i; both times color.
LANE_FN lv3 dielectric_eval(const Bsdf* b, lv3 wo, lv3 wi, lv3 n, lmask outside, lfloat* pdf)
{
    *pdf = (lfloat)(0.0f);
    const lfloat alpha = ggx_alpha(b->roughness);
    const lfloat cos_o = lv3_dot(wo, n);
    const lfloat cos_i = lv3_dot(wi, n);
    lmask valid = mask_and(mask_not(dielectric_is_smooth(alpha)), mask_and(cos_o > 0.0f, cos_i != 0.0f));
    if (!lanes_any(valid)) return lv3_zero();
    const lfloat eta = dielectric_eta(b, outside);
    const lmask reflection = cos_i > 0.0f;
    lv3 m = lv3_select(lv3_add(lv3_scale(wo, eta), wi), lv3_add(wo, wi), reflection);
    const lfloat length2 = lv3_dot(m, m);
    valid = mask_and(valid, length2 > 0.0f);  // not: index-matched straight transmission, no microfacet
    m = lv3_scale(m, rsqrt(length2));
    m = lv3_select(m, lv3_neg(m), lv3_dot(m, n) < 0.0f);
    const lfloat cos_om = lv3_dot(wo, m);
    const lfloat cos_im = lv3_dot(wi, m);
    // Light arrives and leaves on the facet's sides that match the macro surface.
    valid = mask_and(valid, mask_and(cos_om > 0.0f, cos_im * cos_i > 0.0f));
    lfloat cos_t;
    const lfloat fresnel = fresnel_dielectric(cos_om, eta, &cos_t);
    const lfloat d = ggx_d(alpha, m, n);
    const lfloat lambda_o = ggx_lambda(alpha, cos_o);
    const lfloat g2 = 1.0f / (1.0f + lambda_o + ggx_lambda(alpha, fabs(cos_i)));
    const lfloat visible = d * ggx_visible_factor(lambda_o, cos_o);  // D_wo(m) / (wo.m)
    const lfloat sum = cos_im + eta * cos_om;
    const lfloat jacobian = -cos_im / (sum * sum);  // d omega_m / d omega_i (Walter et al., eq. 17)
    const lfloat reflected_pdf = fresnel * visible * 0.25f;
    const lfloat refracted_pdf = (1.0f - fresnel) * visible * cos_om * jacobian;
    const lfloat reflected = fresnel * d * g2 / (4.0f * cos_o);
    const lfloat refracted = eta * eta * (1.0f - fresnel) * d * g2 * cos_om * jacobian / cos_o;
    *pdf = lselect((lfloat)(0.0f), lselect(refracted_pdf, reflected_pdf, reflection), valid);
    return lv3_scale(b->color, lselect((lfloat)(0.0f), lselect(refracted, reflected, reflection), valid));
}

LANE_FN BsdfSample dielectric_sample(const Bsdf* b, lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lfloat* choice)
{
    const lfloat alpha = ggx_alpha(b->roughness);
    const lmask smooth = dielectric_is_smooth(alpha);
    BsdfSample s = bsdf_no_sample();
    lfloat smooth_choice = *choice, rough_choice = *choice;
    if (lanes_any(smooth)) s = bsdf_sample_select(s, smooth_dielectric_sample(b, wo, n, outside, &smooth_choice), smooth);
    const lmask rough = mask_not(smooth);
    if (ORB_ROUGH_DIELECTRIC && lanes_any(rough)) {
        const lfloat eta = dielectric_eta(b, outside);
        const lv3 m = ggx_sample_visible_normal(alpha, wo, n, u, v);
        const lfloat cos_om = lv3_dot(wo, m);
        lfloat cos_t;
        const lfloat fresnel = fresnel_dielectric(fmax((lfloat)(0.0f), cos_om), eta, &cos_t);
        const lmask reflect = choose_lobe(fresnel, &rough_choice);
        BsdfSample r;
        r.delta = mask_of(false);
        r.wi = lv3_select(lv3_normalize(lv3_add(lv3_scale(wo, -eta), lv3_scale(m, eta * cos_om - cos_t))),
                          reflect_about(wo, m), reflect);
        const lfloat cos_i = lv3_dot(r.wi, n);
        r.eta2 = lselect(eta * eta, (lfloat)(1.0f), reflect);
        // The weight from the same functions MIS and dielectric_pdf use, so the
        // three agree: G2 / G1(wo), times eta^2 for refraction, times color.
        const lv3 f_cos = dielectric_eval(b, wo, r.wi, n, outside, &r.pdf);
        r.weight = lv3_scale(f_cos, 1.0f / r.pdf);
        const lmask kept = mask_and(lselect(cos_i < 0.0f, cos_i > 0.0f, reflect), r.pdf > 0.0f);
        s = bsdf_sample_select(s, r, mask_and(rough, kept));
    }
    *choice = lselect(rough_choice, smooth_choice, smooth);
    return s;
}

LANE_FN lv3 dielectric_albedo(const Bsdf* b, lv3 wo, lv3 n) { return b->color; }
