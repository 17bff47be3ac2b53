// The scene as uploaded by librender (scene_layout.cpp writes the same layout).
//
// Spheres are stored twice, each copy in the form its consumer reads fastest:
//  * packets: groups of four spheres in structure-of-arrays form for the
//    intersection loop, 4 float4 per packet: centre x, centre y, centre z,
//    radius^2. Lanes past the last sphere hold radius^2 = -1 (never hit).
//    Sphere i is lane i % 4 of packet i / 4.
//  * records: 3 float4 per sphere for shading:
//      [0] centre xyz, radius
//      [1] colour rgb, material type (MATERIAL_*)
//      [2] emitted radiance rgb, index of refraction
//  * lights: indices of the spheres whose emission is non-zero.
//
// The address space is chosen by the host: __constant while the scene fits
// the device's constant buffer, __global beyond.

#ifndef ORB_SCENE_SPACE
#define ORB_SCENE_SPACE __constant
#endif
#define SCENE_MEM ORB_SCENE_SPACE

#define MATERIAL_DIFFUSE 0
#define MATERIAL_MIRROR 1
#define MATERIAL_DIELECTRIC 2

typedef struct {
    SCENE_MEM const float4* packets;
    int packet_count;
    int sphere_count;
    SCENE_MEM const float4* records;
    SCENE_MEM const int* lights;
    int light_count;
} SceneView;

typedef struct {
    float3 centre;
    float radius;
    float3 color;
    int type;
    float3 emission;
    float ior;
} SphereRecord;

inline SphereRecord load_sphere(const SceneView* scene, int id)
{
    const float4 a = scene->records[3 * id + 0];
    const float4 b = scene->records[3 * id + 1];
    const float4 c = scene->records[3 * id + 2];
    SphereRecord s;
    s.centre = a.xyz;
    s.radius = a.w;
    s.color = b.xyz;
    s.type = (int)b.w;
    s.emission = c.xyz;
    s.ior = c.w;
    return s;
}
