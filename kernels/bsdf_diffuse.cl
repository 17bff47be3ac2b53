// Lambertian diffuse: f = color / pi on the viewer's side (two-sided: n faces
// the viewer), sampled with a cosine-weighted hemisphere, pdf = cos / pi.

LANE_FN lmask diffuse_has_density(const Bsdf* b) { return mask_of(true); }

LANE_FN BsdfSample diffuse_sample(const Bsdf* b, lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lfloat* choice)
{
    BsdfSample s;
    lfloat cos_theta;
    s.wi = sample_cosine_hemisphere(n, u, v, &cos_theta);
    s.weight = b->color;  // (color / pi) cos / (cos / pi)
    s.pdf = cos_theta * ORB_INV_PI;
    s.delta = mask_of(false);
    s.eta2 = (lfloat)(1.0f);
    return s;
}

LANE_FN lv3 diffuse_eval(const Bsdf* b, lv3 wo, lv3 wi, lv3 n, lmask outside, lfloat* pdf)
{
    const lfloat cos_theta = lv3_dot(n, wi);
    *pdf = lselect((lfloat)(0.0f), cos_theta * ORB_INV_PI, cos_theta > 0.0f);
    return lv3_scale(b->color, *pdf);
}

LANE_FN lv3 diffuse_albedo(const Bsdf* b, lv3 wo, lv3 n) { return b->color; }
