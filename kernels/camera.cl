// Pinhole and thin-lens camera, perspective or orthographic, from the host's
// CameraParams (device_types.h). One text over a float type F and its
// 3-vector V3 with operations P##_add and so on (lanes.cl): camera_ray over
// lanes for the paths, camera_ray_scalar for the centre-ray channels, which
// cast one ray per pixel at every width and so must not depend on the width.
// UC is the (cos, sin) of a turn (sampling.cl) for that type.

// (sx, sy): position on the film in pixels, (0,0) the top-left corner.
#define ORB_DEFINE_CAMERA_RAY(Q, F, V3, P, UC, name)                                                                \
    Q void name(const CameraParams* cam, F sx, F sy, int width, int height, F lens_u, F lens_v, V3* origin, V3* dir) \
    {                                                                                                               \
        const F ndc_x = 2.0f * sx / (float)width - 1.0f;                                                            \
        const F ndc_y = 1.0f - 2.0f * sy / (float)height;                                                           \
        const V3 right = P##_splat(cam->right.xyz), up = P##_splat(cam->up.xyz);                                    \
        const V3 forward = P##_splat(cam->forward.xyz);                                                             \
        /* `base` is where the pinhole ray starts; `through` its direction, of unit */                              \
        /* length along forward, so that it reaches the focal plane at focus_distance. */                           \
        V3 base = P##_splat(cam->origin.xyz);                                                                       \
        V3 through;                                                                                                 \
        if (cam->projection == CameraProjection_Orthographic) {                                                     \
            /* Parallel rays: the film position moves the origin across the view */                                \
            /* (half extents in scene units), not the direction. */                                                 \
            base = P##_add(base, P##_add(P##_scale(right, ndc_x * cam->half_width),                                  \
                                         P##_scale(up, ndc_y * cam->half_height)));                                 \
            through = forward;                                                                                      \
        } else {                                                                                                    \
            through = P##_add(P##_add(forward, P##_scale(right, ndc_x * cam->half_width)),                          \
                              P##_scale(up, ndc_y * cam->half_height));                                             \
        }                                                                                                           \
        if (cam->lens_radius > 0.0f) {                                                                              \
            /* The lens sits at `base` (for an orthographic camera, a telecentric */                                \
            /* lens: every pixel's cone of rays has the same aperture); a point on */                               \
            /* it uniform by area (polar mapping). */                                                               \
            const V3 focus_point = P##_add(base, P##_scale(through, (F)(cam->focus_distance)));                      \
            const F r = sqrt(lens_u);                                                                               \
            F c, s;                                                                                                 \
            UC(lens_v, &c, &s);                                                                                     \
            const F lens_x = cam->lens_radius * (r * c), lens_y = cam->lens_radius * (r * s);                       \
            *origin = P##_add(P##_add(base, P##_scale(right, lens_x)), P##_scale(up, lens_y));                      \
            *dir = P##_normalize(P##_sub(focus_point, *origin));                                                    \
        } else {                                                                                                    \
            *origin = base;                                                                                         \
            *dir = P##_normalize(through);                                                                          \
        }                                                                                                           \
    }

ORB_DEFINE_CAMERA_RAY(inline, float, float3, f3, unit_circle_scalar, camera_ray_scalar)
#if ORB_LANES == 1
#define camera_ray camera_ray_scalar
#else
ORB_DEFINE_CAMERA_RAY(LANE_FN, lfloat, lv3, lv3, lanes_unit_circle, camera_ray)
#endif
