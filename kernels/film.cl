// The film on the device: one buffer per channel of ORB_FILM_CHANNELS
// (film_channels.h), 3 entries per pixel for colours and vectors, 1 for
// scalars. A Sum channel holds 64-bit integer sums in the units of its
// `units` column, so that adding samples is exact: a pixel's sum is the
// same whichever passes, devices, runs or slices its samples came in
// (docs/design/exact-film-sums.md). A CentreRay channel holds floats.

// A pass's sums of one pixel added to the film's, saturating (as add_sat,
// once per pass: the sums of SignedFixed channels never reach it).
inline void film_add3(__global long* sums, uint pixel, long3 value)
{
    vstore3(add_sat(vload3(pixel, sums), value), pixel, sums);
}

inline void film_add1(__global long* sums, uint pixel, long value) { sums[pixel] = add_sat(sums[pixel], value); }

inline void film_set3(__global float* values, uint pixel, float3 value) { vstore3(value, pixel, values); }

inline void film_set1(__global float* values, uint pixel, float value) { values[pixel] = value; }

// A sample's value in a channel's units (film_channels.h): scaled, then
// rounded half away from zero to a whole number
// of units by truncating value + 1/2 (the float addition may round a value
// within a float rounding of a half up: a sample rounds by at most about
// half a unit, the same way on every run). Clamped first, so the conversion
// is always defined: a Fixed value to [0, 2^38] (2^62 units; a sum that
// reaches that is reported on the host), a SignedFixed one to a unit
// vector's [-1, 1]. A Count's value is 0 or 1 already (alpha, a sample).
// rint() would round halves to even, but PoCL expands it into about twenty
// instructions a vector, 8% of the Cornell box's samples/s at 16 lanes
// (docs/design/exact-film-sums.md).
#define ORB_FILM_FIXED_SCALE ((float)(1 << ORB_FILM_FIXED_BITS))
LANE_FN llong film_units_Fixed(lfloat v)
{
    return to_llong(clamp(v, 0.0f, ORB_FILM_FIXED_MAX) * ORB_FILM_FIXED_SCALE + 0.5f);
}
LANE_FN llong film_units_SignedFixed(lfloat v)
{
    const lfloat scaled = clamp(v, -1.0f, 1.0f) * ORB_FILM_FIXED_SCALE;
    return to_llong(scaled + copysign((lfloat)(0.5f), scaled));
}
// A Count's value is 0 or 1 (alpha, a sample): a pass adds at most its
// sample count (an int) to a pixel, so the pass's counts stay in 32 bits.
LANE_FN lint film_units_Count(lfloat v) { return to_lint(v); }

// A pass's sums add plainly; each component of a Fixed channel keeps,
// beside its sum, the OR of the sum's high word after every addition. Units
// are at most 2^62 and a sum starts at 0, so a sum that passes the largest
// long lands below 0 (its sign bit set) before it could wrap any further,
// and the OR keeps that bit for good: at the pass's end a component whose
// OR is below 0 reached 2^63 units and stops at the largest long
// (film_saturated), as the film's own add_sat then keeps it: the sums a
// saturating addition of every sample gives. One OR an addition instead of
// a test and a select (docs/design/exact-film-sums.md). A SignedFixed sum
// cannot overflow (film_channels.h), nor a Count one.
#define film_sum_add_Fixed(sum, units) ((sum) + (units))
#define film_sum_add_SignedFixed(sum, units) ((sum) + (units))
#define film_sum_add_Count(sum, units) ((sum) + (units))
#define film_high_word(sum) to_lint((sum) >> 32)
LANE_FN llong film_saturated(llong sum, lint overflow)
{
#if ORB_LANES == 1
    return overflow < 0 ? LONG_MAX : sum;
#else
    return select(sum, (llong)(LONG_MAX), to_llong(overflow) < (llong)(0));
#endif
}

// A work-item's own copy of one kind of channel, generated from the table:
// FilmSums holds the Sum channels of each lane's pixel (lanes.cl), added up
// over a pass's samples in registers and added to the film once (64-bit
// sums; a Count channel's pass counts in 32 bits, widened then);
// FilmCentre the CentreRay channels of one pixel, stored once by the first
// pass.
typedef struct {
    llong x, y, z;
} FilmSum3;

#define ORB_FILM_FLOAT_1 float
#define ORB_FILM_FLOAT_3 float3
#define ORB_FILM_VALUES_1 lfloat
#define ORB_FILM_VALUES_3 lv3
// A pass's sums by units and components.
#define ORB_FILM_SUMS_Fixed_1 llong
#define ORB_FILM_SUMS_Fixed_3 FilmSum3
#define ORB_FILM_SUMS_SignedFixed_1 llong
#define ORB_FILM_SUMS_SignedFixed_3 FilmSum3
#define ORB_FILM_SUMS_Count_1 lint
#define ORB_FILM_SUMS(units, components) ORB_FILM_SUMS_##units##_##components

// A Fixed channel's sums have their overflow words beside them (name_overflow).
typedef struct {
    lint x, y, z;
} FilmOverflow3;
#define ORB_FILM_OVERFLOW_1 lint
#define ORB_FILM_OVERFLOW_3 FilmOverflow3
#define ORB_FILM_OVERFLOW_FIELD_Fixed(name, components) ORB_FILM_OVERFLOW_##components name##_overflow;
#define ORB_FILM_OVERFLOW_FIELD_SignedFixed(name, components)
#define ORB_FILM_OVERFLOW_FIELD_Count(name, components)
#define ORB_FILM_FIELD_IF_Sum(name, components, units) \
    ORB_FILM_SUMS(units, components) name;               \
    ORB_FILM_OVERFLOW_FIELD_##units(name, components)
#define ORB_FILM_FIELD_IF_CentreRay(name, components, units)
#define ORB_FILM_SUM_FIELD(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ORB_FILM_FIELD_IF_##accumulate(name, components, units)
typedef struct {
    ORB_FILM_CHANNELS(ORB_FILM_SUM_FIELD)
} FilmSums;

#define ORB_FILM_CENTRE_IF_Sum(name, components)
#define ORB_FILM_CENTRE_IF_CentreRay(name, components) ORB_FILM_FLOAT_##components name;
#define ORB_FILM_CENTRE_FIELD(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ORB_FILM_CENTRE_IF_##accumulate(name, components)
typedef struct {
    ORB_FILM_CHANNELS(ORB_FILM_CENTRE_FIELD)
} FilmCentre;

#define ORB_FILM_ZERO_1(name) sums->name = 0;
#define ORB_FILM_ZERO_3(name) sums->name.x = sums->name.y = sums->name.z = 0;
#define ORB_FILM_ZERO_OVERFLOW_Fixed(name, components) ORB_FILM_ZERO_##components(name##_overflow)
#define ORB_FILM_ZERO_OVERFLOW_SignedFixed(name, components)
#define ORB_FILM_ZERO_OVERFLOW_Count(name, components)
#define ORB_FILM_ZERO_IF_Sum(name, components, units) \
    ORB_FILM_ZERO_##components(name) ORB_FILM_ZERO_OVERFLOW_##units(name, components)
#define ORB_FILM_ZERO_IF_CentreRay(name, components, units)
#define ORB_FILM_ZERO(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ORB_FILM_ZERO_IF_##accumulate(name, components, units)
LANE_FN void film_sums_clear(FilmSums* sums) { ORB_FILM_CHANNELS(ORB_FILM_ZERO) }

// film_sample_<name>(sums, value): adds one sample's value of channel <name>
// (an lfloat or an lv3) to its sums, in the channel's units, in every lane:
// a lane whose sample is not done holds 0 there (film_add_sample selects
// the values once, with the selection a value needs anyway).
#define ORB_FILM_NOTE_Fixed(overflow, sum) (overflow) |= film_high_word(sum);
#define ORB_FILM_NOTE_SignedFixed(overflow, sum)
#define ORB_FILM_NOTE_Count(overflow, sum)
#define ORB_FILM_ACCUMULATE_ONE(sum, overflow, units, value)               \
    (sum) = film_sum_add_##units((sum), film_units_##units(value)); \
    ORB_FILM_NOTE_##units(overflow, sum)
#define ORB_FILM_ACCUMULATE_1(name, units, value) ORB_FILM_ACCUMULATE_ONE(sums->name, sums->name##_overflow, units, value)
#define ORB_FILM_ACCUMULATE_3(name, units, value)                                             \
    ORB_FILM_ACCUMULATE_ONE(sums->name.x, sums->name##_overflow.x, units, (value).x) \
    ORB_FILM_ACCUMULATE_ONE(sums->name.y, sums->name##_overflow.y, units, (value).y) \
    ORB_FILM_ACCUMULATE_ONE(sums->name.z, sums->name##_overflow.z, units, (value).z)
#define ORB_FILM_SAMPLE_ADDER_IF_Sum(name, components, units)                             \
    LANE_FN void film_sample_##name(FilmSums* sums, ORB_FILM_VALUES_##components value) \
    {                                                                                     \
        ORB_FILM_ACCUMULATE_##components(name, units, value)                              \
    }
#define ORB_FILM_SAMPLE_ADDER_IF_CentreRay(name, components, units)
#define ORB_FILM_SAMPLE_ADDER(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ORB_FILM_SAMPLE_ADDER_IF_##accumulate(name, components, units)
ORB_FILM_CHANNELS(ORB_FILM_SAMPLE_ADDER)

// Inside render_pass, whose arguments film_<name> are the buffers:
// ORB_FILM_COPY_SUMS copies each channel of the FilmSums `sums` to a
// variable of its own, film_sums_<name>; ORB_FILM_ADD_SUMS then adds lane
// `lane` of those to pixel `pixel`, and ORB_FILM_SET_CENTRE stores the
// FilmCentre `centre` there (local variables of those names), one statement
// per channel the program builds (ORB_FILM_BUILT). A lane is read through
// its variable's memory (lane_l, lane_i), so the copies, not the sums of the sample
// loop, have their address taken, and each channel has a copy of its own:
// read from one copy of the whole struct, the compiler could not tell which
// fields are read, and every channel, built or not, stayed live through the
// sample loop (on PoCL at 16 lanes, a fifth more spill stores;
// docs/design/one-path-tracer-over-lanes.md).
#define ORB_FILM_SATURATED_Fixed_1(name) film_saturated(sums.name, sums.name##_overflow)
#define ORB_FILM_SATURATED_Fixed_3(name)                                           \
    {film_saturated(sums.name.x, sums.name##_overflow.x), film_saturated(sums.name.y, sums.name##_overflow.y), \
     film_saturated(sums.name.z, sums.name##_overflow.z)}
#define ORB_FILM_SATURATED_SignedFixed_1(name) sums.name
#define ORB_FILM_SATURATED_SignedFixed_3(name) sums.name
#define ORB_FILM_SATURATED_Count_1(name) sums.name
#define ORB_FILM_COPY_IF_Sum(name, components, units) \
    const ORB_FILM_SUMS(units, components) film_sums_##name = ORB_FILM_SATURATED_##units##_##components(name);
#define ORB_FILM_COPY_IF_CentreRay(name, components, units)
#define ORB_FILM_COPY(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ORB_FILM_COPY_IF_##accumulate(name, components, units)
#define ORB_FILM_COPY_SUMS ORB_FILM_CHANNELS(ORB_FILM_COPY)
#define ORB_FILM_LANE_Fixed_1(value) lane_l(value, lane)
#define ORB_FILM_LANE_Fixed_3(value) ((long3)(lane_l((value).x, lane), lane_l((value).y, lane), lane_l((value).z, lane)))
#define ORB_FILM_LANE_SignedFixed_1 ORB_FILM_LANE_Fixed_1
#define ORB_FILM_LANE_SignedFixed_3 ORB_FILM_LANE_Fixed_3
#define ORB_FILM_LANE_Count_1(value) ((long)lane_i(value, lane))
#define ORB_FILM_ADD_IF_Sum(name, components, units)                \
    if (ORB_FILM_BUILT(name))                                       \
        film_add##components(film_##name, pixel, ORB_FILM_LANE_##units##_##components(film_sums_##name));
#define ORB_FILM_ADD_IF_CentreRay(name, components, units)
#define ORB_FILM_ADD(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ORB_FILM_ADD_IF_##accumulate(name, components, units)
#define ORB_FILM_ADD_SUMS ORB_FILM_CHANNELS(ORB_FILM_ADD)

#define ORB_FILM_SET_IF_Sum(name, components)
#define ORB_FILM_SET_IF_CentreRay(name, components) \
    if (ORB_FILM_BUILT(name)) film_set##components(film_##name, pixel, centre.name);
#define ORB_FILM_SET(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names) \
    ORB_FILM_SET_IF_##accumulate(name, components)
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
// for the lanes in `lanes` (the others add 0). A sample whose radiance is not
// finite (never expected) would poison the pixel's sums for good, so it adds
// no light at all.
LANE_FN void film_add_sample(FilmSums* sums, const PathSample* s, lmask lanes)
{
    const lv3 sum = lv3_add(lv3_add(s->emission, s->direct), s->indirect);
    const lmask finite = mask_and(mask_and(isfinite(sum.x), isfinite(sum.y)), isfinite(sum.z));
    const lmask light = mask_and(lanes, finite);
    const lv3 radiance = lv3_select(lv3_zero(), sum, light);
    film_sample_radiance(sums, radiance);
    film_sample_alpha(sums, lselect((lfloat)(0.0f), s->alpha, lanes));
    film_sample_direct(sums, lv3_select(lv3_zero(), s->direct, light));
    film_sample_indirect(sums, lv3_select(lv3_zero(), s->indirect, light));
    film_sample_emission(sums, lv3_select(lv3_zero(), s->emission, light));
    film_sample_albedo(sums, lv3_select(lv3_zero(), s->albedo, lanes));
    film_sample_normal(sums, lv3_select(lv3_zero(), s->normal, lanes));
    film_sample_radiance_sq(sums, lv3_mul(radiance, radiance));
    film_sample_background(sums, lv3_select(lv3_zero(), s->background, light));
    film_sample_sample_count(sums, lselect((lfloat)(0.0f), (lfloat)(1.0f), lanes));
}
