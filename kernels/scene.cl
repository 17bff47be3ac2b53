// The scene as the kernels see it: the tables of device_types.h (written by
// librender/src/scene_layout.cpp), in the address space the host chose:
// __constant while the scene fits the device's constant buffer, __global beyond
// (ORB_SCENE_SPACE, kernel_features.h).
#define SCENE_MEM ORB_SCENE_SPACE
// ORB_UNIFORM_LIGHTS is 1 when every light has the same power (one light,
// say): the host then builds the program to pick lights uniformly, which is
// what the alias table would do, without reading it.
//
// At width > 1, above this many records a table is read lane by lane;
// below it, one select per record that any lane names (fewer memory reads
// and no spill of the lanes to memory). The selects test the index alone,
// not the lanes asked for: a lane outside them may get the record its index
// names, which no caller reads, and the test is one operation shorter on
// the sample loop's path (with lanes_step's branches, 3-4% more samples/s
// on caustic.scn on PoCL at 16 lanes).
#define ORB_LANES_SELECT_GATHER_MAX 64

// One pointer per scene table of render_pass's argument list, plus the
// tables' lengths; generated from the list so that a new table needs no edit here.
#define ORB_SCENE_VIEW_FILM(name, components, clear, accumulate, units, merge, layer, stored_as, paired, names)
#define ORB_SCENE_VIEW_TABLE(type, name) SCENE_MEM const type* name;
#define ORB_SCENE_VIEW_PARAMS(type, name)
typedef struct {
    ORB_RENDER_PASS_ARGUMENTS(ORB_SCENE_VIEW_FILM, ORB_SCENE_VIEW_TABLE, ORB_SCENE_VIEW_PARAMS)
    int packet_count;
    int sphere_count;
    int light_count;
    int outside_packet_count;
    int bvh_node_count;
    int caster_count;
    EnvironmentParams environment;  // width 0: none
} SceneView;

// Hit spheres with their materials, unpacked for shading: one per lane.
typedef struct {
    lv3 centre;
    lfloat radius;
    lv3 emission;
    Bsdf bsdf;
    lfloat light_probability;  // the light sampler's chance of picking the sphere
} ShadingSphere;

// One material record in every lane (the BSDF probes of the tests).
inline Bsdf load_bsdf(SCENE_MEM const MaterialRecord* m)
{
    Bsdf b;
    b.color = lv3_splat(m->color.xyz);
    b.kind = (lint)(m->kind);
    b.ior = (lfloat)(m->ior);
    b.roughness = (lfloat)(m->roughness);
    b.metallic = (lfloat)(m->metallic);
    b.lobes = ORB_LOBES_ANY;
    return b;
}

// The colour a hit sphere reflects or tints with: its own where the scene
// gives spheres colours (ORB_SPHERE_COLORS, packed as device_types.h says),
// else its material's. The material's kind, emission and the rest apply either way.
#if ORB_SPHERE_COLORS
inline float3 unpack_sphere_color(uint packed)
{
    const float3 root = (float3)((float)(packed & ORB_SPHERE_COLOR_RED_MAX) * (1.0f / ORB_SPHERE_COLOR_RED_MAX),
                                 (float)((packed >> ORB_SPHERE_COLOR_GREEN_SHIFT) & ORB_SPHERE_COLOR_GREEN_MAX) *
                                     (1.0f / ORB_SPHERE_COLOR_GREEN_MAX),
                                 (float)(packed >> ORB_SPHERE_COLOR_BLUE_SHIFT) * (1.0f / ORB_SPHERE_COLOR_BLUE_MAX));
    return root * root;
}
#define ORB_SPHERE_COLOR(record, material) unpack_sphere_color((record)->color)
#else
#define ORB_SPHERE_COLOR(record, material) ((material)->color.xyz)
#endif

// Lane l of *s becomes sphere slot `id`.
#define ORB_SET_SPHERE_LANE(s, l, scene, id)                                               \
    do {                                                                                   \
        SCENE_MEM const SphereRecord* record_ = &(scene)->spheres[id];                     \
        SCENE_MEM const MaterialRecord* material_ = &(scene)->materials[record_->material]; \
        const float4 centre_radius_ = record_->centre_radius;                              \
        set_lane_v3((s).centre, l, centre_radius_.xyz);                                    \
        set_lane_f((s).radius, l, centre_radius_.w);                                       \
        set_lane_v3((s).emission, l, material_->emission.xyz);                             \
        set_lane_v3((s).bsdf.color, l, ORB_SPHERE_COLOR(record_, material_));              \
        set_lane_i((s).bsdf.kind, l, material_->kind);                                     \
        set_lane_f((s).bsdf.ior, l, material_->ior);                                       \
        set_lane_f((s).bsdf.roughness, l, material_->roughness);                           \
        set_lane_f((s).bsdf.metallic, l, material_->metallic);                             \
        set_lane_f((s).light_probability, l, record_->light_probability);                  \
    } while (0)

// Sphere slot id of each lane in `lanes`; a lane that names no sphere (id -1)
// gets no material (kind -1), so no BSDF runs for it, and what the other
// lanes get is unspecified.
LANE_FN ShadingSphere load_sphere(const SceneView* scene, lint id, lmask lanes)
{
    ShadingSphere s;
    s.bsdf.lobes = ORB_LOBES_ANY;
#if ORB_LANES == 1
    ORB_SET_SPHERE_LANE(s, 0, scene, id);
#else
    s.centre = s.emission = s.bsdf.color = lv3_zero();
    s.radius = s.bsdf.ior = (lfloat)(1.0f);
    s.bsdf.roughness = s.bsdf.metallic = s.light_probability = (lfloat)(0.0f);
    s.bsdf.kind = (lint)(-1);
    if (scene->sphere_count > ORB_LANES_SELECT_GATHER_MAX) {
        ORB_FOR_EACH_LANE(l, lanes) ORB_SET_SPHERE_LANE(s, l, scene, lane_i(id, l));
        return s;
    }
    // Few spheres: one select per sphere the lanes name.
    for (int i = 0; i < scene->sphere_count; ++i) {
        const lmask m = id == i;
        if (!lanes_any(m)) continue;
        SCENE_MEM const SphereRecord* r = &scene->spheres[i];
        SCENE_MEM const MaterialRecord* material = &scene->materials[r->material];
        const float4 cr = r->centre_radius;
        s.centre = lv3_select(s.centre, lv3_splat(cr.xyz), m);
        s.radius = lselect(s.radius, (lfloat)(cr.w), m);
        s.emission = lv3_select(s.emission, lv3_splat(material->emission.xyz), m);
        s.bsdf.color = lv3_select(s.bsdf.color, lv3_splat(ORB_SPHERE_COLOR(r, material)), m);
        s.bsdf.kind = lselect(s.bsdf.kind, (lint)(material->kind), m);
        s.bsdf.ior = lselect(s.bsdf.ior, (lfloat)(material->ior), m);
        s.bsdf.roughness = lselect(s.bsdf.roughness, (lfloat)(material->roughness), m);
        s.bsdf.metallic = lselect(s.bsdf.metallic, (lfloat)(material->metallic), m);
        s.light_probability = lselect(s.light_probability, (lfloat)(r->light_probability), m);
    }
#endif
    return s;
}

// A light's sphere for next-event estimation: only its place and emission,
// the three of ShadingSphere's fields that sampling a light reads (at width
// > 1 each field is a select per sphere the lanes name).
typedef struct {
    lv3 centre;
    lfloat radius;
    lv3 emission;
} EmitterSphere;

LANE_FN EmitterSphere load_emitter(const SceneView* scene, lint id, lmask lanes)
{
    EmitterSphere s;
#if ORB_LANES == 1
    SCENE_MEM const SphereRecord* r = &scene->spheres[id];
    s.centre = r->centre_radius.xyz;
    s.radius = r->centre_radius.w;
    s.emission = scene->materials[r->material].emission.xyz;
#else
    s.centre = s.emission = lv3_zero();
    s.radius = (lfloat)(1.0f);
    if (scene->sphere_count > ORB_LANES_SELECT_GATHER_MAX) {
        ORB_FOR_EACH_LANE(l, lanes)
        {
            SCENE_MEM const SphereRecord* r = &scene->spheres[lane_i(id, l)];
            set_lane_v3(s.centre, l, r->centre_radius.xyz);
            set_lane_f(s.radius, l, r->centre_radius.w);
            set_lane_v3(s.emission, l, scene->materials[r->material].emission.xyz);
        }
        return s;
    }
    for (int i = 0; i < scene->sphere_count; ++i) {
        const lmask m = id == i;
        if (!lanes_any(m)) continue;
        SCENE_MEM const SphereRecord* r = &scene->spheres[i];
        s.centre = lv3_select(s.centre, lv3_splat(r->centre_radius.xyz), m);
        s.radius = lselect(s.radius, (lfloat)(r->centre_radius.w), m);
        s.emission = lv3_select(s.emission, lv3_splat(scene->materials[r->material].emission.xyz), m);
    }
#endif
    return s;
}
