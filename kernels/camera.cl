// Pinhole and thin-lens camera, perspective or orthographic, from the host's
// CameraParams (device_types.h). kernels/integrator_simd.cl restates it over
// lanes (v_begin_camera_paths): keep the two the same.

// (sx, sy): position on the film in pixels, (0,0) the top-left corner.
inline void camera_ray(const CameraParams* cam, float sx, float sy, int width, int height, float lens_u,
                       float lens_v, float3* origin, float3* dir)
{
    const float ndc_x = 2.0f * sx / (float)width - 1.0f;
    const float ndc_y = 1.0f - 2.0f * sy / (float)height;
    // `base` is where the pinhole ray starts; `through` its direction, of unit
    // length along forward, so that it reaches the focal plane at focus_distance.
    float3 base = cam->origin.xyz;
    float3 through;
    if (cam->projection == CameraProjection_Orthographic) {
        // Parallel rays: the film position moves the origin across the view
        // (half extents in scene units), not the direction.
        base += (ndc_x * cam->half_width) * cam->right.xyz + (ndc_y * cam->half_height) * cam->up.xyz;
        through = cam->forward.xyz;
    } else {
        through =
            cam->forward.xyz + (ndc_x * cam->half_width) * cam->right.xyz + (ndc_y * cam->half_height) * cam->up.xyz;
    }
    if (cam->lens_radius > 0.0f) {
        // The lens sits at `base` (for an orthographic camera, a telecentric
        // lens: every pixel's cone of rays has the same aperture).
        const float3 focus_point = base + cam->focus_distance * through;
        const float2 lens = cam->lens_radius * sample_uniform_disk(lens_u, lens_v);
        *origin = base + lens.x * cam->right.xyz + lens.y * cam->up.xyz;
        *dir = normalize(focus_point - *origin);
    } else {
        *origin = base;
        *dir = normalize(through);
    }
}
