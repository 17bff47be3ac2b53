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
// FilmSums holds the Sum channels, added up over a pass's samples in
// registers and added to the film once; FilmCentre the CentreRay channels,
// stored once by the first pass.
#define ORB_FILM_FLOAT_1 float
#define ORB_FILM_FLOAT_3 float3

#define ORB_FILM_FIELD_IF_Sum(name, components) ORB_FILM_FLOAT_##components name;
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

#define ORB_FILM_ZERO_IF_Sum(name) sums->name = 0.0f;
#define ORB_FILM_ZERO_IF_CentreRay(name)
#define ORB_FILM_ZERO(name, components, clear, accumulate, merge, layer, stored_as, paired, names) ORB_FILM_ZERO_IF_##accumulate(name)
inline void film_sums_clear(FilmSums* sums) { ORB_FILM_CHANNELS(ORB_FILM_ZERO) }

// Inside render_pass, whose arguments film_<name> are the buffers: adds the
// FilmSums `sums` to pixel `pixel`, or stores the FilmCentre `centre` there
// (local variables of those names), one statement per channel the program
// builds (ORB_FILM_BUILT); what a channel left out would add is dead code.
#define ORB_FILM_ADD_IF_Sum(name, components) \
    if (ORB_FILM_BUILT(name)) film_add##components(film_##name, pixel, sums.name);
#define ORB_FILM_ADD_IF_CentreRay(name, components)
#define ORB_FILM_ADD(name, components, clear, accumulate, merge, layer, stored_as, paired, names) ORB_FILM_ADD_IF_##accumulate(name, components)
#define ORB_FILM_ADD_SUMS ORB_FILM_CHANNELS(ORB_FILM_ADD)

#define ORB_FILM_SET_IF_Sum(name, components)
#define ORB_FILM_SET_IF_CentreRay(name, components) \
    if (ORB_FILM_BUILT(name)) film_set##components(film_##name, pixel, centre.name);
#define ORB_FILM_SET(name, components, clear, accumulate, merge, layer, stored_as, paired, names) ORB_FILM_SET_IF_##accumulate(name, components)
#define ORB_FILM_SET_CENTRE ORB_FILM_CHANNELS(ORB_FILM_SET)
