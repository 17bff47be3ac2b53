// Perfect mirror: one delta lobe, reflectance `color`.

LANE_FN lmask mirror_has_density(const Bsdf* b) { return mask_of(false); }

LANE_FN BsdfSample mirror_sample(const Bsdf* b, lv3 wo, lv3 n, lmask outside, lfloat u, lfloat v, lfloat* choice)
{
    BsdfSample s;
    s.wi = reflect_about(wo, n);
    s.weight = b->color;
    s.pdf = (lfloat)(0.0f);
    s.delta = mask_of(true);
    s.eta2 = (lfloat)(1.0f);
    return s;
}

LANE_FN lv3 mirror_eval(const Bsdf* b, lv3 wo, lv3 wi, lv3 n, lmask outside, lfloat* pdf)
{
    *pdf = (lfloat)(0.0f);
    return lv3_zero();
}

LANE_FN lv3 mirror_albedo(const Bsdf* b, lv3 wo, lv3 n) { return b->color; }
