// Pinhole and thin-lens camera. The host passes an orthonormal frame and the
// image-plane half extents at unit distance: tan(vfov/2) * aspect and tan(vfov/2).

typedef struct {
    float3 origin;
    float3 right;    // unit
    float3 up;       // unit
    float3 forward;  // unit, towards the target
    float half_width;
    float half_height;
    float lens_radius;  // 0 for a pinhole
    float focus_distance;
} CameraView;

// (sx, sy): position on the film in pixels, (0,0) the top-left corner.
inline void camera_ray(const CameraView* cam, float sx, float sy, int width, int height, float lens_u,
                       float lens_v, float3* origin, float3* dir)
{
    const float ndc_x = 2.0f * sx / (float)width - 1.0f;
    const float ndc_y = 1.0f - 2.0f * sy / (float)height;
    const float3 through = cam->forward + (ndc_x * cam->half_width) * cam->right + (ndc_y * cam->half_height) * cam->up;
    if (cam->lens_radius > 0.0f) {
        // `through` has unit length along forward, so it reaches the focal plane at focus_distance.
        const float3 focus_point = cam->origin + cam->focus_distance * through;
        const float2 lens = cam->lens_radius * sample_uniform_disk(lens_u, lens_v);
        *origin = cam->origin + lens.x * cam->right + lens.y * cam->up;
        *dir = normalize(focus_point - *origin);
    } else {
        *origin = cam->origin;
        *dir = normalize(through);
    }
}
