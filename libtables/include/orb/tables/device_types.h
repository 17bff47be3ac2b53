/* Everything the OpenCL device reads, defined once for both sides: the record
 * layouts of the scene tables, the parameter struct of render_pass, the enums
 * they carry, and render_pass's argument list.
 *
 * The host compiles this file as C++20 (namespace orb::device). The OpenCL C
 * 1.2 program starts with it: kernels/CMakeLists.txt lists it first among the
 * kernel files, which are concatenated into one program (embedded, from
 * --kernel-dir, or from <prefix>/share/orb/kernels, which holds this file as
 * include/orb/tables/device_types.h).
 * It therefore includes nothing on the OpenCL side (film_channels.h and
 * material_kinds.h, which the host includes below, come before it in the
 * program).
 *
 * Rules that keep the host's and the device's layouts identical:
 *  - Fields are int, uint, float (4 bytes, 4-aligned on both sides), float4
 *    or int4 (16 bytes, 16-aligned on both sides), or arrays of them. No
 *    float3 (16 bytes in OpenCL C but 12 in a naive host struct), no bool,
 *    size_t, pointers or 64-bit integers (4-aligned on some 32-bit hosts, 8
 *    on the device).
 *  - Padding is written out as named fields, so there is none implicit, and
 *    a struct holding a float4 is a multiple of 16 bytes (so arrays of it
 *    stay aligned on both sides).
 *  - Every size and offset is listed in ORB_DEVICE_LAYOUT (at the end of this
 *    file): the host static_asserts them, and tests/render/device_layout_test.cpp
 *    has the device compiler report the same figures.
 *
 * docs/design/host-and-device-layout.md says how to add a field or a
 * buffer. */
#ifndef ORB_TABLES_DEVICE_TYPES_H
#define ORB_TABLES_DEVICE_TYPES_H

#ifdef __OPENCL_VERSION__

/* OpenCL C: the built-in types. An enum's members are prefixed with its name,
 * since C has no scoped enums: MaterialKind_Diffuse. */
#define ORB_ENUM(name) enum name
#define ORB_ENUMERATOR(name, member, value) name##_##member = value

#else

#include <cstddef>
#include <cstdint>

#include "orb/tables/film_channels.h"
#include "orb/tables/material_kinds.h"

namespace orb::device {

/* The host spells the OpenCL C types the same way inside orb::device, so the
 * struct definitions below are one text for both compilers. */
using uint = std::uint32_t;
struct alignas(16) float4 {
    float x, y, z, w;
};
struct alignas(16) int4 {
    int x, y, z, w;
};
static_assert(sizeof(int) == 4 && sizeof(float) == 4, "OpenCL C's int and float are 4 bytes");
static_assert(sizeof(float4) == 16 && alignof(float4) == 16, "OpenCL C's float4 is 16 bytes, 16-aligned");
static_assert(sizeof(int4) == 16 && alignof(int4) == 16, "OpenCL C's int4 is 16 bytes, 16-aligned");

/* C++: a scoped enum, MaterialKind::Diffuse, stored as the device's int. */
#define ORB_ENUM(name) enum class name : int
#define ORB_ENUMERATOR(name, member, value) member = value

#endif

/* ---- Enums (struct fields hold them as int) ---- */

/* How a material scatters light: one enumerator per row of
 * ORB_MATERIAL_TABLE (material_kinds.h), which also names the kinds in the
 * scene format and generates the kernels' dispatch. Also the scene model's
 * material type: libscene's orb::MaterialType is this enum. */
#define ORB_MATERIAL_KIND_ENUMERATOR(member, value, name, scn_word, prefix, caster_rule) \
    ORB_ENUMERATOR(MaterialKind, member, value),
ORB_ENUM(MaterialKind){ORB_MATERIAL_TABLE(ORB_MATERIAL_KIND_ENUMERATOR)};
#undef ORB_MATERIAL_KIND_ENUMERATOR

/* What the integrator estimates (docs/rendering.md); librender's public
 * orb::render::IntegratorMode is this enum. */
ORB_ENUM(IntegratorMode){
    ORB_ENUMERATOR(IntegratorMode, Global, 0),  /* path tracing */
    ORB_ENUMERATOR(IntegratorMode, Direct, 1),  /* the paper's local illumination */
};

/* Where a path's random numbers come from (kernels/sampler.cl); the host
 * builds the program with -DORB_SAMPLER_SOBOL=(this == Sobol), and
 * orb-render's --sampler and the EXR's orb:sampler name it. */
ORB_ENUM(SamplerKind){
    ORB_ENUMERATOR(SamplerKind, Independent, 0), /* Philox: fresh numbers for every sample */
    ORB_ENUMERATOR(SamplerKind, Sobol, 1),       /* Owen-scrambled Sobol for the first bounces */
};

/* How camera rays leave the film (kernels/camera.cl): from one point
 * through the image plane, or parallel along the view direction. */
ORB_ENUM(CameraProjection){
    ORB_ENUMERATOR(CameraProjection, Perspective, 0),  /* pinhole or thin lens */
    ORB_ENUMERATOR(CameraProjection, Orthographic, 1), /* parallel rays, telecentric thin lens */
};

/* ---- Scene tables: read-only buffers, __constant or __global ---- */

/* Four spheres in structure-of-arrays form, for the intersection loop: CPUs
 * test all four lanes with one vector instruction per float4. Sphere i is
 * lane i % 4 of packet i / 4. Lanes past the last sphere hold radius2 = -1,
 * which makes the discriminant negative, so they never hit. GPUs read the
 * same packets one lane at a time (ORB_SCALAR_TRAVERSAL). */
typedef struct SpherePacket {
    float4 centre_x;
    float4 centre_y;
    float4 centre_z;
    float4 radius2; /* radius squared */
} SpherePacket;

/* One sphere as shading reads it, once per hit. */
typedef struct SphereRecord {
    float4 centre_radius; /* xyz: centre, w: radius (one 16-byte load for both) */
    int material;         /* index into the materials table */
    int scene_index;      /* the sphere's index in the scene (the id pass); the tables are in BVH order */
    float light_probability; /* the chance that next-event estimation picks this sphere; 0 unless emissive */
    uint color;              /* ORB_SPHERE_COLORS: the sphere's own colour, packed as below; else 0 */
} SphereRecord;

/* A per-sphere colour (Scene::sphere_attributes, ORB_SPHERE_COLORS) in the
 * SphereRecord's last 4 bytes, so that a million colours cost no table and no
 * kernel argument: the square root of each linear component as an unsigned
 * fraction, red in bits 0-10 (of 2047), green in bits 11-21 (of 2047), blue in
 * bits 22-31 (of 1023); the kernels square it back (scene.cl). The root keeps
 * dark colours' relative precision: a component c comes back within
 * 2/(2*1023*sqrt(c)) of itself relatively (within 0.1% at c = 1, 1% at
 * c = 0.01, 10% at c = 1e-4, a tenth of the first 8-bit sRGB step). */
#define ORB_SPHERE_COLOR_RED_MAX 2047u
#define ORB_SPHERE_COLOR_GREEN_MAX 2047u
#define ORB_SPHERE_COLOR_BLUE_MAX 1023u
#define ORB_SPHERE_COLOR_GREEN_SHIFT 11
#define ORB_SPHERE_COLOR_BLUE_SHIFT 22

/* A node of the 4-wide sphere BVH (librender/src/sphere_bvh.h): the boxes of
 * its up to four children in structure-of-arrays form, lane k of each
 * float4 being child k (CPUs test all four boxes with one vector instruction
 * per float4), and what each child is:
 *   child[k] >= 0: an interior node, index into the nodes table
 *   child[k] <  0: a leaf, one packet of up to four spheres: packet -1 - child[k]
 * bounds[] are the boxes' planes: lo_x, lo_y, lo_z, hi_x, hi_y, hi_z, so that
 * a ray picks the plane it enters by per axis as bounds[axis] or
 * bounds[axis + 3] (intersect.cl). A lane without a child holds the inverted
 * box lo = FLT_MAX, hi = -FLT_MAX, which every ray leaves before it enters.
 * leaf_run.x: when every child is a leaf, the first of their packets, which
 * are consecutive (leaf_run.y of them); else -1. CPUs test those packets
 * straight away instead of the boxes (kernels/intersect.cl).
 * 128 bytes: two 64-byte cache lines, eight 16-byte loads. */
typedef struct BvhNodeRecord {
    float4 bounds[6];
    int4 child;
    int4 leaf_run; /* x: first packet, y: packet count; x -1 unless every child is a leaf; z, w: 0 */
} BvhNodeRecord;

/* The traversal stack's entries (kernels/intersect.cl). The build keeps
 * every tree within it: sphere_bvh.h says how, and the host checks each tree
 * against it before upload. */
#define ORB_BVH_STACK_SIZE 48

typedef struct MaterialRecord {
    float4 color;    /* xyz: reflectance, base colour or tint in [0, 1]; w: 0 */
    float4 emission; /* xyz: emitted radiance; w: 0. Non-zero makes every sphere using it a light */
    float ior;       /* index of refraction, for dielectrics */
    int kind;        /* a MaterialKind */
    float roughness; /* perceptual roughness in [0, 1] (dielectric, pbr); GGX alpha = roughness^2 */
    float metallic;  /* in [0, 1] (pbr) */
} MaterialRecord;

/* A light for next-event estimation: an emissive sphere or the environment,
 * and one slot of the alias table that picks lights (librender/src/alias_table.h):
 * a number u in [0, 1) chooses slot k = floor(u n); its remainder picks this
 * slot's light when below alias_threshold, else light `alias`. */
typedef struct LightRecord {
    int sphere;            /* index into the spheres table; -1: the environment */
    float probability;     /* chance of picking this light (docs/rendering.md, "Picking a light") */
    float alias_threshold; /* see above */
    int alias;             /* index into the lights table */
} LightRecord;

/* A sphere that BSDF sampling at diffuse and glossy vertices also aims at
 * (kernels/caustics.cl): one whose material has no density, so that light
 * reaches a surface through it only along BSDF-sampled paths (the caustics
 * of glass and mirror balls, which next-event estimation cannot find).
 * Filled by librender/src/scene_layout.cpp. */
typedef struct CasterRecord {
    float4 centre_radius; /* xyz: centre; w: radius */
} CasterRecord;

/* One texel of the environment (kernels/environment.cl), row-major from the
 * top row (+y). A uniform environment is a single texel. Filled by
 * librender/src/environment_layout.cpp. */
typedef struct EnvironmentTexel {
    float4 radiance_pdf; /* xyz: radiance (intensity times the map's texel); w: the solid-angle density
                          * of a direction in this texel when the environment is sampled: its probability
                          * over its solid angle (0 for a texel the sampler never picks) */
} EnvironmentTexel;

/* The environment's sampling tables: the piecewise-constant 2D distribution
 * over its texels. Entries [0, height) are the rows' cumulative probabilities
 * (marginal); row r's columns follow at [height + r * width, height + (r + 1) * width),
 * cumulative probabilities within the row (conditional). Each entry is the
 * probability of its index and all before it; the last of each run is 1. */
typedef struct EnvironmentCdf {
    float upper;
} EnvironmentCdf;

/* ---- The parameter struct of render_pass, passed by value ---- */

/* Pinhole or thin lens: an orthonormal frame and the half extents of the
 * image: perspective, of the image plane at unit distance, tan(vfov / 2) *
 * aspect and tan(vfov / 2); orthographic, of the view itself in scene units,
 * orthographic_height / 2 * aspect and orthographic_height / 2. */
typedef struct CameraParams {
    float4 origin;  /* xyz; w: 0 */
    float4 right;   /* unit; w: 0 */
    float4 up;      /* unit; w: 0 */
    float4 forward; /* unit, towards the target; w: 0 */
    float half_width;
    float half_height;
    float lens_radius; /* 0 for a pinhole */
    float focus_distance;
    int projection; /* a CameraProjection */
    int pad0, pad1, pad2;
} CameraParams;

/* Lengths of the scene tables (a table with no records still holds one
 * placeholder, since OpenCL has no empty buffers). */
typedef struct SceneCounts {
    int packet_count;
    int sphere_count;   /* sphere slots: packet_count * 4, padding lanes included */
    int light_count;
    int outside_packet_count; /* packets [0, this) hold the spheres outside the BVH: every ray tests them */
    int bvh_node_count;       /* 0: no tree, every sphere is outside it */
    int caster_count;         /* records of the casters table; 0: BSDF sampling aims at no sphere */
    int pad1, pad2;
} SceneCounts;

/* Fixed for a whole render. */
typedef struct RenderSettings {
    int width;
    int height;
    int max_depth; /* scattering events per path (docs/rendering.md) */
    int mode;      /* an IntegratorMode */
    uint seed_lo;  /* the 64-bit seed, split: no 64-bit fields (see above) */
    uint seed_hi;
    int pad0, pad1;
} RenderSettings;

/* Changes with every pass: the samples [first_sample, first_sample + sample_count). */
typedef struct PassRange {
    uint first_sample_lo;
    uint first_sample_hi;
    int sample_count;
    int write_centre_ray; /* 1 on the first pass: depth and object id of the pixel-centre ray */
} PassRange;

/* The environment light, fixed for a render (docs/rendering.md, "Environment"). */
typedef struct EnvironmentParams {
    float4 rotation;         /* x, y: cos and sin of rotation_deg, the map's turn about +y; zw: 0 */
    int width;               /* texels per row; 0: no environment (escaping rays carry nothing) */
    int height;              /* rows */
    float light_probability; /* the chance that next-event estimation (global mode) picks it */
    int pad0;
} EnvironmentParams;

typedef struct RenderPassParams {
    CameraParams camera;
    SceneCounts scene;
    RenderSettings settings;
    PassRange pass;
    EnvironmentParams environment;
} RenderPassParams;

/* ---- render_pass's arguments, in order ----
 * The kernel's signature (kernels/integrator.cl), the host's argument indices,
 * its set of scene buffers and its count of __constant arguments
 * (librender/src/pass_arguments.h) are all generated from this one list:
 *   FILM(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names)
 *                       __global long* film_<name> (a Sum channel's sums) or
 *                       __global float* (a CentreRay channel's values): one
 *                       per row of the film's channel table
 *                       (ORB_FILM_CHANNELS, film_channels.h), which passes
 *                       the row's other columns along
 *   TABLE(type, name)   a read-only scene table of `type` records, in the
 *                       address space ORB_SCENE_SPACE (__constant or __global)
 *   PARAMS(type, name)  the parameter struct, by value; last, since it ends
 *                       the signature without a comma */
#define ORB_RENDER_PASS_ARGUMENTS(FILM, TABLE, PARAMS) \
    ORB_FILM_CHANNELS(FILM)                            \
    TABLE(SpherePacket, packets)                       \
    TABLE(BvhNodeRecord, bvh_nodes)                    \
    TABLE(SphereRecord, spheres)                       \
    TABLE(MaterialRecord, materials)                   \
    TABLE(LightRecord, lights)                         \
    TABLE(CasterRecord, casters)                       \
    TABLE(EnvironmentTexel, environment_texels)        \
    TABLE(EnvironmentCdf, environment_cdf)             \
    PARAMS(RenderPassParams, params)

/* After that list render_pass takes one more argument, `__global const uint*
 * active_pixels`: with ORB_ACTIVE_PIXELS (adaptive sampling) the pixels still
 * sampling (row-major indices, ascending), ORB_LANES of them per work-item,
 * padded with ORB_NO_PIXEL to the launch's size; without it a placeholder
 * the kernel never reads. */
#define ORB_NO_PIXEL 0xffffffffu

#ifndef __OPENCL_VERSION__

/* ---- Host checks: the layouts above, byte for byte ----
 * Every struct's size and every field's offset, listed once: the host
 * static_asserts them here, and tests/render/device_layout_test.cpp has the
 * device compiler report the same figures for the same list. */
#define ORB_DEVICE_LAYOUT(SIZE, FIELD)                                                                      \
    SIZE(SpherePacket, 64)                                                                                 \
    FIELD(SpherePacket, centre_x, 0) FIELD(SpherePacket, centre_y, 16) FIELD(SpherePacket, centre_z, 32)   \
    FIELD(SpherePacket, radius2, 48)                                                                       \
    SIZE(SphereRecord, 32)                                                                                 \
    FIELD(SphereRecord, centre_radius, 0) FIELD(SphereRecord, material, 16)                                \
    FIELD(SphereRecord, scene_index, 20) FIELD(SphereRecord, light_probability, 24)                        \
    FIELD(SphereRecord, color, 28)                                                                         \
    SIZE(BvhNodeRecord, 128)                                                                               \
    FIELD(BvhNodeRecord, bounds, 0) FIELD(BvhNodeRecord, child, 96) FIELD(BvhNodeRecord, leaf_run, 112)    \
    SIZE(MaterialRecord, 48)                                                                               \
    FIELD(MaterialRecord, color, 0) FIELD(MaterialRecord, emission, 16) FIELD(MaterialRecord, ior, 32)     \
    FIELD(MaterialRecord, kind, 36) FIELD(MaterialRecord, roughness, 40) FIELD(MaterialRecord, metallic, 44) \
    SIZE(LightRecord, 16)                                                                                  \
    FIELD(LightRecord, sphere, 0) FIELD(LightRecord, probability, 4)                                       \
    FIELD(LightRecord, alias_threshold, 8) FIELD(LightRecord, alias, 12)                                   \
    SIZE(CameraParams, 96)                                                                                 \
    FIELD(CameraParams, origin, 0) FIELD(CameraParams, right, 16) FIELD(CameraParams, up, 32)              \
    FIELD(CameraParams, forward, 48) FIELD(CameraParams, half_width, 64)                                   \
    FIELD(CameraParams, half_height, 68) FIELD(CameraParams, lens_radius, 72)                              \
    FIELD(CameraParams, focus_distance, 76) FIELD(CameraParams, projection, 80)                            \
    SIZE(SceneCounts, 32)                                                                                  \
    FIELD(SceneCounts, packet_count, 0) FIELD(SceneCounts, sphere_count, 4)                                \
    FIELD(SceneCounts, light_count, 8) FIELD(SceneCounts, outside_packet_count, 12)                        \
    FIELD(SceneCounts, bvh_node_count, 16) FIELD(SceneCounts, caster_count, 20)                            \
    SIZE(RenderSettings, 32)                                                                               \
    FIELD(RenderSettings, width, 0) FIELD(RenderSettings, height, 4) FIELD(RenderSettings, max_depth, 8)   \
    FIELD(RenderSettings, mode, 12) FIELD(RenderSettings, seed_lo, 16) FIELD(RenderSettings, seed_hi, 20)  \
    SIZE(PassRange, 16)                                                                                    \
    FIELD(PassRange, first_sample_lo, 0) FIELD(PassRange, first_sample_hi, 4)                              \
    FIELD(PassRange, sample_count, 8) FIELD(PassRange, write_centre_ray, 12)                               \
    SIZE(CasterRecord, 16)                                                                                 \
    FIELD(CasterRecord, centre_radius, 0)                                                                  \
    SIZE(EnvironmentTexel, 16)                                                                             \
    FIELD(EnvironmentTexel, radiance_pdf, 0)                                                               \
    SIZE(EnvironmentCdf, 4)                                                                                \
    FIELD(EnvironmentCdf, upper, 0)                                                                        \
    SIZE(EnvironmentParams, 32)                                                                            \
    FIELD(EnvironmentParams, rotation, 0) FIELD(EnvironmentParams, width, 16)                              \
    FIELD(EnvironmentParams, height, 20) FIELD(EnvironmentParams, light_probability, 24)                   \
    SIZE(RenderPassParams, 208)                                                                            \
    FIELD(RenderPassParams, camera, 0) FIELD(RenderPassParams, scene, 96)                                  \
    FIELD(RenderPassParams, settings, 128) FIELD(RenderPassParams, pass, 160)                              \
    FIELD(RenderPassParams, environment, 176)

#define ORB_CHECK_SIZE(type, size) static_assert(sizeof(type) == (size), "sizeof " #type);
#define ORB_CHECK_FIELD(type, field, offset) static_assert(offsetof(type, field) == (offset), #type "." #field);
ORB_DEVICE_LAYOUT(ORB_CHECK_SIZE, ORB_CHECK_FIELD)
#undef ORB_CHECK_SIZE
#undef ORB_CHECK_FIELD

}  // namespace orb::device

#endif

#undef ORB_ENUM
#undef ORB_ENUMERATOR

#endif /* ORB_TABLES_DEVICE_TYPES_H */
