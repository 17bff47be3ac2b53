/* A headless host for SmallptGPU 1.6's OpenCL kernel (RadianceGPU, by David
 * Bucciarelli), to measure it beside Orb on the GPU node: samples/s, and the
 * relMSE of its progressive image after 16, 32, ... samples per pixel against
 * a converged render of its own (docs/performance.md, "How to reproduce").
 * Written for the project; the kernel's files (rendering_kernel.cl, camera.h,
 * geom.h, geomfunc.h, vec.h and simplernd.h of the repository
 * tigrazone/smallptgpu1.6, commit 0636140) are not in Orb's tree and are
 * passed by their folder.
 *
 * It does what SmallptGPU's own host does, as far as the kernel sees: reads a
 * .scn (camera line, size line, sphere lines), sets the camera as its
 * UpdateCamera does (45° vertical field of view, x scaled by the aspect), one
 * random seed pair per pixel (>= 2), the kernel's default work-group size, one
 * launch per sample per pixel with currentSample counting up (the kernel keeps
 * the running mean in `colors`). Launches are queued back to back; the clock
 * stops at clFinish before each read-back.
 *
 *   smallptgpu-bench KERNEL_DIR SCENE.scn WIDTH HEIGHT LAST_SPP OUT_PREFIX [REFERENCE.raw]
 *
 * Writes OUT_PREFIX-SPP.raw (float32 RGB, the kernel's layout) at every power
 * of two from 16 to LAST_SPP; with a reference, prints per rung
 * "spp SPP seconds S samples_per_second R relmse E" (relMSE as orb-diff:
 * mean of d^2 / (r^2 + 0.01) over pixels and channels).
 */
#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct { float x, y, z; } Vec;                    /* the kernel's Vec */
typedef struct { float rad; Vec p, e, c; int refl; } Sphere; /* its Sphere: radius, position, emission, colour, DIFF/SPEC/REFR */
typedef struct { Vec orig, target, dir, x, y; } Camera;      /* its Camera */

static void check(cl_int status, const char *what) {
    if (status != CL_SUCCESS) {
        fprintf(stderr, "smallptgpu-bench: %s failed: %d\n", what, status);
        exit(1);
    }
}

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static Vec sub(Vec a, Vec b) { Vec r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static Vec cross(Vec a, Vec b) { Vec r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; return r; }
static Vec scaled(Vec a, float k) { Vec r = {a.x * k, a.y * k, a.z * k}; return r; }
static Vec unit(Vec a) { return scaled(a, 1.f / sqrtf(a.x * a.x + a.y * a.y + a.z * a.z)); }

static char *read_text(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) { fprintf(stderr, "smallptgpu-bench: cannot read %s\n", path); exit(1); }
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc(n + 1);
    if (fread(text, 1, n, f) != (size_t)n) { fprintf(stderr, "smallptgpu-bench: short read %s\n", path); exit(1); }
    text[n] = 0;
    fclose(f);
    return text;
}

int main(int argc, char **argv) {
    if (argc < 7) {
        fprintf(stderr, "usage: smallptgpu-bench KERNEL_DIR SCENE.scn WIDTH HEIGHT LAST_SPP OUT_PREFIX [REFERENCE.raw]\n");
        return 2;
    }
    const char *kernel_dir = argv[1];
    const int width = atoi(argv[3]), height = atoi(argv[4]), last = atoi(argv[5]);
    const char *prefix = argv[6];
    const size_t pixels = (size_t)width * height;

    /* The scene. */
    FILE *f = fopen(argv[2], "r");
    if (!f) { fprintf(stderr, "smallptgpu-bench: cannot read %s\n", argv[2]); return 1; }
    Camera camera;
    memset(&camera, 0, sizeof camera);
    unsigned count = 0;
    if (fscanf(f, " camera %f %f %f %f %f %f", &camera.orig.x, &camera.orig.y, &camera.orig.z, &camera.target.x,
               &camera.target.y, &camera.target.z) != 6 || fscanf(f, " size %u", &count) != 1 || count == 0) {
        fprintf(stderr, "smallptgpu-bench: %s: bad camera or size line\n", argv[2]);
        return 1;
    }
    Sphere *spheres = calloc(count, sizeof(Sphere));
    for (unsigned i = 0; i < count; ++i) {
        Sphere *s = &spheres[i];
        if (fscanf(f, " sphere %f %f %f %f %f %f %f %f %f %f %d", &s->rad, &s->p.x, &s->p.y, &s->p.z, &s->e.x, &s->e.y,
                   &s->e.z, &s->c.x, &s->c.y, &s->c.z, &s->refl) != 11) {
            fprintf(stderr, "smallptgpu-bench: %s: bad sphere %u\n", argv[2], i);
            return 1;
        }
    }
    fclose(f);
    const float fov = (float)(3.14159265358979323846 / 180.0) * 45.f;
    const Vec up = {0.f, 1.f, 0.f};
    camera.dir = unit(sub(camera.target, camera.orig));
    camera.x = scaled(unit(cross(camera.dir, up)), width * fov / height);
    camera.y = scaled(unit(cross(camera.x, camera.dir)), fov);

    /* The device: the first GPU (SPT_CPU=1: the first CPU, to try it on PoCL). */
    const cl_device_type wanted = getenv("SPT_CPU") ? CL_DEVICE_TYPE_CPU : CL_DEVICE_TYPE_GPU;
    cl_platform_id platforms[8];
    cl_uint platform_count = 0;
    check(clGetPlatformIDs(8, platforms, &platform_count), "clGetPlatformIDs");
    cl_device_id device = 0;
    for (cl_uint p = 0; p < platform_count && !device; ++p)
        if (clGetDeviceIDs(platforms[p], wanted, 1, &device, NULL) != CL_SUCCESS) device = 0;
    if (!device) { fprintf(stderr, "smallptgpu-bench: no such device\n"); return 1; }
    char name[256];
    clGetDeviceInfo(device, CL_DEVICE_NAME, sizeof name, name, NULL);
    cl_int status;
    cl_context context = clCreateContext(NULL, 1, &device, NULL, NULL, &status);
    check(status, "clCreateContext");
    cl_command_queue queue = clCreateCommandQueue(context, device, 0, &status);
    check(status, "clCreateCommandQueue");

    char path[4096];
    snprintf(path, sizeof path, "%s/rendering_kernel.cl", kernel_dir);
    const char *source = read_text(path);
    cl_program program = clCreateProgramWithSource(context, 1, &source, NULL, &status);
    check(status, "clCreateProgramWithSource");
    char options[4200];
    snprintf(options, sizeof options, "-I%s", kernel_dir);
    if (clBuildProgram(program, 1, &device, options, NULL, NULL) != CL_SUCCESS) {
        static char log[1 << 16];
        clGetProgramBuildInfo(program, device, CL_PROGRAM_BUILD_LOG, sizeof log, log, NULL);
        fprintf(stderr, "smallptgpu-bench: build failed:\n%s\n", log);
        return 1;
    }
    cl_kernel kernel = clCreateKernel(program, "RadianceGPU", &status);
    check(status, "clCreateKernel");
    size_t group = 0;
    check(clGetKernelWorkGroupInfo(kernel, device, CL_KERNEL_WORK_GROUP_SIZE, sizeof group, &group, NULL),
          "work-group size");
    if (getenv("SPT_GROUP")) group = (size_t)atoi(getenv("SPT_GROUP"));

    unsigned *seeds = malloc(2 * pixels * sizeof(unsigned));
    srand(getenv("SPT_SEED") ? atoi(getenv("SPT_SEED")) : 1);
    for (size_t i = 0; i < 2 * pixels; ++i) {
        seeds[i] = (unsigned)rand();
        if (seeds[i] < 2) seeds[i] = 2;
    }
    cl_mem colors = clCreateBuffer(context, CL_MEM_READ_WRITE, 3 * sizeof(float) * pixels, NULL, &status);
    check(status, "colors");
    cl_mem seed_buffer =
        clCreateBuffer(context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, 2 * sizeof(unsigned) * pixels, seeds, &status);
    check(status, "seeds");
    cl_mem sphere_buffer =
        clCreateBuffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(Sphere) * count, spheres, &status);
    check(status, "spheres");
    cl_mem camera_buffer =
        clCreateBuffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(Camera), &camera, &status);
    check(status, "camera");
    cl_mem pixel_buffer = clCreateBuffer(context, CL_MEM_WRITE_ONLY, sizeof(int) * pixels, NULL, &status);
    check(status, "pixels");
    unsigned flags = 0;
    clSetKernelArg(kernel, 0, sizeof(cl_mem), &colors);
    clSetKernelArg(kernel, 1, sizeof(cl_mem), &seed_buffer);
    clSetKernelArg(kernel, 2, sizeof(cl_mem), &sphere_buffer);
    clSetKernelArg(kernel, 3, sizeof(cl_mem), &camera_buffer);
    clSetKernelArg(kernel, 4, sizeof(unsigned), &count);
    clSetKernelArg(kernel, 5, sizeof(int), &width);
    clSetKernelArg(kernel, 6, sizeof(int), &height);
    clSetKernelArg(kernel, 8, sizeof(cl_mem), &pixel_buffer);
    clSetKernelArg(kernel, 9, sizeof(unsigned), &flags);
    const size_t global = (pixels + group - 1) / group * group;

    float *reference = NULL;
    if (argc > 7) {
        reference = malloc(3 * sizeof(float) * pixels);
        FILE *r = fopen(argv[7], "rb");
        if (!r || fread(reference, sizeof(float), 3 * pixels, r) != 3 * pixels) {
            fprintf(stderr, "smallptgpu-bench: cannot read reference %s\n", argv[7]);
            return 1;
        }
        fclose(r);
    }
    printf("device %s, %u spheres, %dx%d, work-group %zu\n", name, count, width, height, group);

    /* Warm-up: one launch (compilation and first-launch costs), then the
       seeds and the sample count start again. */
    int sample = 0;
    clSetKernelArg(kernel, 7, sizeof(int), &sample);
    check(clEnqueueNDRangeKernel(queue, kernel, 1, NULL, &global, &group, 0, NULL, NULL), "warm-up");
    check(clFinish(queue), "clFinish");
    check(clEnqueueWriteBuffer(queue, seed_buffer, CL_TRUE, 0, 2 * sizeof(unsigned) * pixels, seeds, 0, NULL, NULL),
          "seeds again");

    float *image = malloc(3 * sizeof(float) * pixels);
    double seconds = 0;
    for (int rung = 16; rung <= last; rung *= 2) {
        const double start = now();
        for (; sample < rung; ++sample) {
            clSetKernelArg(kernel, 7, sizeof(int), &sample);
            check(clEnqueueNDRangeKernel(queue, kernel, 1, NULL, &global, &group, 0, NULL, NULL), "launch");
        }
        check(clFinish(queue), "clFinish");
        seconds += now() - start;
        check(clEnqueueReadBuffer(queue, colors, CL_TRUE, 0, 3 * sizeof(float) * pixels, image, 0, NULL, NULL),
              "read-back");
        snprintf(path, sizeof path, "%s-%d.raw", prefix, rung);
        FILE *out = fopen(path, "wb");
        if (!out || fwrite(image, sizeof(float), 3 * pixels, out) != 3 * pixels) {
            fprintf(stderr, "smallptgpu-bench: cannot write %s\n", path);
            return 1;
        }
        fclose(out);
        printf("spp %d seconds %.6f samples_per_second %.6g", rung, seconds, (double)rung * pixels / seconds);
        if (reference) {
            double sum = 0;
            for (size_t i = 0; i < 3 * pixels; ++i) {
                const double r = isfinite(reference[i]) ? reference[i] : 0.0;
                const double d = image[i] == reference[i] ? 0.0 : fabs((double)image[i] - reference[i]);
                sum += d * d / (r * r + 0.01);
            }
            printf(" relmse %.6g", sum / (3.0 * pixels));
        }
        printf("\n");
        fflush(stdout);
    }
    return 0;
}
