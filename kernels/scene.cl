// The scene as the kernels see it: the tables of device_types.h (written by
// librender/src/scene_layout.cpp), in the address space the host chose:
// __constant while the scene fits the device's constant buffer, __global beyond
// (ORB_SCENE_SPACE, kernel_features.h).
#define SCENE_MEM ORB_SCENE_SPACE
// ORB_UNIFORM_LIGHTS is 1 when every light has the same power (one light,
// say): the host then builds the program to pick lights uniformly, which is
// what the alias table would do, without reading it.

// One pointer per scene table of render_pass's argument list, plus the
// tables' lengths; generated from the list so that a new table needs no edit here.
#define ORB_SCENE_VIEW_FILM(name, components, clear, accumulate, merge, layer, stored_as, paired, names)
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

// A hit sphere with its material, unpacked for shading.
typedef struct {
    float3 centre;
    float radius;
    float3 emission;
    Bsdf bsdf;
} ShadingSphere;

inline Bsdf load_bsdf(SCENE_MEM const MaterialRecord* m)
{
    Bsdf b;
    b.color = m->color.xyz;
    b.kind = m->kind;
    b.ior = m->ior;
    b.roughness = m->roughness;
    b.metallic = m->metallic;
    return b;
}

inline ShadingSphere load_sphere(const SceneView* scene, int id)
{
    const float4 centre_radius = scene->spheres[id].centre_radius;
    SCENE_MEM const MaterialRecord* m = &scene->materials[scene->spheres[id].material];
    ShadingSphere s;
    s.centre = centre_radius.xyz;
    s.radius = centre_radius.w;
    s.emission = m->emission.xyz;
    s.bsdf = load_bsdf(m);
    return s;
}
