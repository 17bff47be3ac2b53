/* The material kinds, defined once for every layer that names one: the
 * MaterialKind enum (device_types.h), the kernels' BSDF dispatch
 * (kernels/bsdf.cl), the scene format's "type" names (libscene's JSON reader
 * and writer, docs/orb-scene.schema.json, checked by a test), the .scn
 * writer's words, and the rule that makes a sphere a caustic caster
 * (librender's scene layout, kernels/caustic_casters.cl).
 *
 * One row per kind:
 *   X(Member, value, "scene name", "scn word", bsdf_prefix, CASTER_RULE)
 * Member: MaterialKind_Member in OpenCL C, MaterialKind::Member in C++.
 * bsdf_prefix: the kernels' functions of the kind are bsdf_prefix##_sample,
 *   _eval, _has_density and _albedo, in kernels/bsdf_<prefix>.cl (the
 *   interface is in kernels/bsdf_types.cl).
 * CASTER_RULE(roughness, metallic): whether a sphere of this kind is worth
 *   aiming the continuation at, because light reaches what lies behind it only
 *   along BSDF-sampled paths (no density). Any rule keeps the estimator
 *   unbiased; it only chooses where caustics get help.
 *
 * Adding a material: a row here, its kernels/bsdf_<prefix>.cl file listed in
 * kernels/CMakeLists.txt, and its parameters in the scene format. Nothing
 * else switches over the kinds.
 *
 * Plain C preprocessor text: the host includes it as C++20, and the OpenCL
 * program has it before device_types.h. */
#ifndef ORB_TABLES_MATERIAL_KINDS_H
#define ORB_TABLES_MATERIAL_KINDS_H

#define ORB_CASTER_NEVER(roughness, metallic) 0
#define ORB_CASTER_ALWAYS(roughness, metallic) 1
#define ORB_CASTER_WHEN_SMOOTH(roughness, metallic) ((roughness) == 0.0f)
#define ORB_CASTER_WHEN_SMOOTH_METAL(roughness, metallic) ((roughness) == 0.0f && (metallic) >= 1.0f)

#define ORB_MATERIAL_TABLE(X)                                                           \
    X(Diffuse, 0, "diffuse", "diffuse", diffuse, ORB_CASTER_NEVER)                      \
    X(Mirror, 1, "mirror", "mirror", mirror, ORB_CASTER_ALWAYS)                         \
    X(Dielectric, 2, "dielectric", "glass", dielectric, ORB_CASTER_WHEN_SMOOTH)         \
    X(Pbr, 3, "pbr", "pbr", pbr, ORB_CASTER_WHEN_SMOOTH_METAL)

#endif
