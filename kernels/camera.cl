// Pinhole and thin-lens camera, from the host's CameraParams (device_types.h).

// (sx, sy): position on the film in pixels, (0,0) the top-left corner.
inline void camera_ray(const CameraParams* cam, float sx, float sy, int width, int height, float lens_u,
                       float lens_v, float3* origin, float3* dir)
{
    const float ndc_x = 2.0f * sx / (float)width - 1.0f;
    const float ndc_y = 1.0f - 2.0f * sy / (float)height;
    const float3 through =
        cam->forward.xyz + (ndc_x * cam->half_width) * cam->right.xyz + (ndc_y * cam->half_height) * cam->up.xyz;
    if (cam->lens_radius > 0.0f) {
        // `through` has unit length along forward, so it reaches the focal plane at focus_distance.
        const float3 focus_point = cam->origin.xyz + cam->focus_distance * through;
        const float2 lens = cam->lens_radius * sample_uniform_disk(lens_u, lens_v);
        *origin = cam->origin.xyz + lens.x * cam->right.xyz + lens.y * cam->up.xyz;
        *dir = normalize(focus_point - *origin);
    } else {
        *origin = cam->origin.xyz;
        *dir = normalize(through);
    }
}
