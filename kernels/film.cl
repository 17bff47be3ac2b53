// The film on the device: one buffer per channel of ORB_FILM_CHANNELS
// (film_channels.h), 3 floats per pixel for colours and vectors, 1 for scalars.

inline void film_add3(__global float* sums, uint pixel, float3 value)
{
    vstore3(vload3(pixel, sums) + value, pixel, sums);
}

inline void film_add1(__global float* sums, uint pixel, float value) { sums[pixel] += value; }

inline void film_set3(__global float* values, uint pixel, float3 value) { vstore3(value, pixel, values); }

inline void film_set1(__global float* values, uint pixel, float value) { values[pixel] = value; }

// A work-item's own copy of one kind of channel, generated from the table:
// FilmSums holds the Sum channels of each lane's pixel (lanes.cl), added up
// over a pass's samples in registers and added to the film once;
// FilmCentre the CentreRay channels of one pixel, stored once by the first
// pass.
#define ORB_FILM_FLOAT_1 float
#define ORB_FILM_FLOAT_3 float3
#define ORB_FILM_LANES_1 lfloat
#define ORB_FILM_LANES_3 lv3

#define ORB_FILM_FIELD_IF_Sum(name, components) ORB_FILM_LANES_##components name;
#define ORB_FILM_FIELD_IF_CentreRay(name, components)
#define ORB_FILM_SUM_FIELD(name, components, clear, accumulate, merge, layer, stored_as, paired, names) ORB_FILM_FIELD_IF_##accumulate(name, components)
typedef struct {
    ORB_FILM_CHANNELS(ORB_FILM_SUM_FIELD)
} FilmSums;

#define ORB_FILM_CENTRE_IF_Sum(name, components)
#define ORB_FILM_CENTRE_IF_CentreRay(name, components) ORB_FILM_FLOAT_##components name;
#define ORB_FILM_CENTRE_FIELD(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    ORB_FILM_CENTRE_IF_##accumulate(name, components)
typedef struct {
    ORB_FILM_CHANNELS(ORB_FILM_CENTRE_FIELD)
} FilmCentre;

#define ORB_FILM_ZERO_1(name) sums->name = (lfloat)(0.0f);
#define ORB_FILM_ZERO_3(name) sums->name = lv3_zero();
#define ORB_FILM_ZERO_IF_Sum(name, components) ORB_FILM_ZERO_##components(name)
#define ORB_FILM_ZERO_IF_CentreRay(name, components)
#define ORB_FILM_ZERO(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    ORB_FILM_ZERO_IF_##accumulate(name, components)
LANE_FN void film_sums_clear(FilmSums* sums) { ORB_FILM_CHANNELS(ORB_FILM_ZERO) }

// Inside render_pass, whose arguments film_<name> are the buffers:
// ORB_FILM_COPY_SUMS copies each channel of the FilmSums `sums` to a
// variable of its own, film_sums_<name>; ORB_FILM_ADD_SUMS then adds lane
// `lane` of those to pixel `pixel`, and ORB_FILM_SET_CENTRE stores the
// FilmCentre `centre` there (local variables of those names), one statement
// per channel the program builds (ORB_FILM_BUILT). A lane is read through
// its variable's memory (lane_f), so the copies, not the sums of the sample
// loop, have their address taken, and each channel has a copy of its own:
// read from one copy of the whole struct, the compiler could not tell which
// fields are read, and every channel, built or not, stayed live through the
// sample loop (on PoCL at 16 lanes, a fifth more spill stores;
// docs/design/one-path-tracer-over-lanes.md).
#define ORB_FILM_COPY_IF_Sum(name, components) const ORB_FILM_LANES_##components film_sums_##name = sums.name;
#define ORB_FILM_COPY_IF_CentreRay(name, components)
#define ORB_FILM_COPY(name, components, clear, accumulate, merge, layer, stored_as, paired, names) \
    ORB_FILM_COPY_IF_##accumulate(name, components)
#define ORB_FILM_COPY_SUMS ORB_FILM_CHANNELS(ORB_FILM_COPY)
#define ORB_FILM_LANE_1(value) lane_f(value, lane)
#define ORB_FILM_LANE_3(value) lane_v3(value, lane)
#define ORB_FILM_ADD_IF_Sum(name, components) \
    if (ORB_FILM_BUILT(name)) film_add##components(film_##name, pixel, ORB_FILM_LANE_##components(film_sums_##name));
#define ORB_FILM_ADD_IF_CentreRay(name, components)
#define ORB_FILM_ADD(name, components, clear, accumulate, merge, layer, stored_as, paired, names) ORB_FILM_ADD_IF_##accumulate(name, components)
#define ORB_FILM_ADD_SUMS ORB_FILM_CHANNELS(ORB_FILM_ADD)

#define ORB_FILM_SET_IF_Sum(name, components)
#define ORB_FILM_SET_IF_CentreRay(name, components) \
    if (ORB_FILM_BUILT(name)) film_set##components(film_##name, pixel, centre.name);
#define ORB_FILM_SET(name, components, clear, accumulate, merge, layer, stored_as, paired, names) ORB_FILM_SET_IF_##accumulate(name, components)
#define ORB_FILM_SET_CENTRE ORB_FILM_CHANNELS(ORB_FILM_SET)

// What one camera path brings, per lane, by the channels it feeds.
typedef struct {
    lv3 emission;    // paths with no non-delta vertex (emitters seen directly or through specular chains)
    lv3 direct;      // paths with exactly one non-delta vertex
    lv3 indirect;    // paths with two or more non-delta vertices
    lv3 albedo;      // specular tints times the reflectance of the first non-delta vertex
    lv3 normal;      // normal at the first hit, facing the camera ray
    lv3 background;  // the environment's radiance when the camera ray hit nothing
    lfloat alpha;    // 1 when the camera ray hit something
} PathSample;

LANE_FN void path_sample_clear(PathSample* s, lmask lanes)
{
    s->emission = lv3_select(s->emission, lv3_zero(), lanes);
    s->direct = lv3_select(s->direct, lv3_zero(), lanes);
    s->indirect = lv3_select(s->indirect, lv3_zero(), lanes);
    s->albedo = lv3_select(s->albedo, lv3_zero(), lanes);
    s->normal = lv3_select(s->normal, lv3_zero(), lanes);
    s->background = lv3_select(s->background, lv3_zero(), lanes);
    s->alpha = lselect(s->alpha, (lfloat)(0.0f), lanes);
}

// Adds `contribution` to the channel of paths with that many non-delta vertices, for the lanes in `lanes`.
LANE_FN void add_by_vertex_count(PathSample* s, lint nondelta_vertices, lv3 contribution, lmask lanes)
{
    s->emission = lv3_add_where(s->emission, contribution, mask_and(lanes, nondelta_vertices == 0));
    s->direct = lv3_add_where(s->direct, contribution, mask_and(lanes, nondelta_vertices == 1));
    s->indirect = lv3_add_where(s->indirect, contribution, mask_and(lanes, nondelta_vertices >= 2));
}

// What one finished camera path adds to each summed channel of the film
// (ORB_FILM_CHANNELS in film_channels.h; a new channel gets its line here),
// for the lanes in `lanes`. A sample whose radiance is not finite (never
// expected) would poison the pixel's sums for good, so it adds no light at all.
LANE_FN void film_add_sample(FilmSums* sums, const PathSample* s, lmask lanes)
{
    const lv3 sum = lv3_add(lv3_add(s->emission, s->direct), s->indirect);
    const lmask finite = mask_and(mask_and(isfinite(sum.x), isfinite(sum.y)), isfinite(sum.z));
    const lv3 emission = lv3_select(lv3_zero(), s->emission, finite);
    const lv3 direct = lv3_select(lv3_zero(), s->direct, finite);
    const lv3 indirect = lv3_select(lv3_zero(), s->indirect, finite);
    const lv3 radiance = lv3_select(lv3_zero(), sum, finite);
    const lv3 background = lv3_select(lv3_zero(), s->background, finite);
    sums->radiance = lv3_add_where(sums->radiance, radiance, lanes);
    sums->alpha = lselect(sums->alpha, sums->alpha + s->alpha, lanes);
    sums->direct = lv3_add_where(sums->direct, direct, lanes);
    sums->indirect = lv3_add_where(sums->indirect, indirect, lanes);
    sums->emission = lv3_add_where(sums->emission, emission, lanes);
    sums->albedo = lv3_add_where(sums->albedo, s->albedo, lanes);
    sums->normal = lv3_add_where(sums->normal, s->normal, lanes);
    sums->radiance_sq = lv3_add_where(sums->radiance_sq, lv3_mul(radiance, radiance), lanes);
    sums->background = lv3_add_where(sums->background, background, lanes);
    sums->sample_count = lselect(sums->sample_count, sums->sample_count + 1.0f, lanes);
}
