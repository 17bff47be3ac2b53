#!/usr/bin/env python3
"""orb-trace-benchmark --dump writes what embree-trace-benchmark.cpp (beside it)
reads: the sphere slots, the three ray batches and Orb's answers. Checks the
record sizes, that the batches are the ones the benchmark describes (a camera
ray per pixel, a bounce and a shadow ray per hit), and every answer against
a brute-force test in double precision over the dumped spheres.

    trace_dump_test.py --benchmark BIN --gen scripts/orb-gen.py
"""
import argparse
import math
import os
import struct
import subprocess
import sys
import tempfile

WIDTH, HEIGHT = 24, 16


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def read_records(path, fmt):
    size = struct.calcsize(fmt)
    data = open(path, "rb").read()
    if len(data) % size:
        fail(f"{path}: {len(data)} bytes is not a whole number of {size}-byte records")
    return [struct.unpack_from(fmt, data, i) for i in range(0, len(data), size)]


def distance(origin, direction, sphere, leaving):
    """Distance to `sphere` (x, y, z, r) along the ray, as Orb counts it: the
    near side, or the far side from inside; a ray leaving the sphere never
    hits it again. None for a miss."""
    x, y, z, r = sphere
    oc = (origin[0] - x, origin[1] - y, origin[2] - z)
    b = sum(oc[i] * direction[i] for i in range(3))
    if leaving and b >= 0:
        return None
    f = [oc[i] - b * direction[i] for i in range(3)]
    disc = r * r - sum(v * v for v in f)
    if disc < 0:
        return None
    s = math.sqrt(disc)
    t = -b - s
    if leaving or t <= 0:
        t = -b + s
    return t if t > 0 else None


def hits_along(ray, spheres):
    origin, self_slot, direction = ray[0:3], ray[3], ray[4:7]
    found = []
    for slot, sphere in enumerate(spheres):
        if sphere[3] <= 0:
            continue  # padding
        t = distance(origin, direction, sphere[:4], slot == self_slot)
        if t is not None:
            found.append((t, slot))
    return sorted(found)


def near_tie(a, b):
    return abs(a - b) <= 1e-4 * max(1.0, abs(a))


def distance_agrees(t, reference, radius):
    """Orb's single-precision test against this double-precision one. Its
    discriminant r^2 - |f|^2 loses about 2^-24 r^2 to rounding, so the floor
    (radius 1e5) is hit up to a few tenths away from where double puts it."""
    return abs(t - reference) <= 1e-4 * max(1.0, abs(reference)) + 1e-5 * radius


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--benchmark", required=True)
    parser.add_argument("--gen", required=True)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        scene = os.path.join(work, "cloud.orb")
        subprocess.run([sys.executable, args.gen, "--count", "300", "--seed", "3", "-o", scene], check=True,
                       stdout=subprocess.DEVNULL)
        dump = os.path.join(work, "rays")
        os.mkdir(dump)
        subprocess.run([args.benchmark, scene, "--width", str(WIDTH), "--height", str(HEIGHT), "--seconds", "0.001",
                        "--dump", dump], check=True, stdout=subprocess.DEVNULL)

        spheres = read_records(os.path.join(dump, "spheres.f32"), "<5f")
        real = [s for s in spheres if s[3] > 0]
        if len(real) != 300 + 4:  # the cloud, the floor, three lamps
            fail(f"expected 304 spheres in the slots, found {len(real)}")
        if not any(s[4] == 1.0 for s in real) or not all(s[4] in (0.0, 1.0) for s in spheres):
            fail("the outside flag must be 0 or 1, and the floor is outside the tree")

        ray_format = "<3fi3fi"
        camera = read_records(os.path.join(dump, "camera.rays"), ray_format)
        camera_hits = read_records(os.path.join(dump, "camera.hits"), "<if")
        bounce = read_records(os.path.join(dump, "bounce.rays"), ray_format)
        bounce_hits = read_records(os.path.join(dump, "bounce.hits"), "<if")
        shadow = read_records(os.path.join(dump, "shadow.rays"), ray_format)
        shadow_visible = read_records(os.path.join(dump, "shadow.hits"), "<i")
        if len(camera) != WIDTH * HEIGHT or len(camera_hits) != len(camera):
            fail(f"{len(camera)} camera rays and {len(camera_hits)} answers for {WIDTH * HEIGHT} pixels")
        hit_count = sum(1 for h in camera_hits if h[0] >= 0)
        if not (len(bounce) == len(bounce_hits) == len(shadow) == len(shadow_visible) == hit_count):
            fail(f"{hit_count} camera hits, but {len(bounce)} bounce and {len(shadow)} shadow rays")
        if hit_count < len(camera) // 2:
            fail(f"only {hit_count} of {len(camera)} camera rays hit the cloud")

        checked = 0
        for rays, answers in ((camera, camera_hits), (bounce, bounce_hits)):
            for ray, (slot, t) in zip(rays, answers):
                found = hits_along(ray, spheres)
                if not found:
                    if slot != -1:
                        fail(f"ray {ray} hits nothing, Orb says slot {slot}")
                    continue
                best_t, best_slot = found[0]
                tie = len(found) > 1 and near_tie(found[0][0], found[1][0])
                if slot != best_slot and not (tie and slot == found[1][1]):
                    fail(f"ray {ray}: closest slot {best_slot} at {best_t}, Orb says {slot} at {t}")
                if not distance_agrees(t, best_t, spheres[best_slot][3]) and not tie:
                    fail(f"ray {ray}: closest hit at {best_t}, Orb says {t}")
                checked += 1
        for ray, (visible,) in zip(shadow, shadow_visible):
            light = ray[7]
            if not 0 <= light < len(spheres) or spheres[light][3] <= 0:
                fail(f"shadow ray names light slot {light}")
            found = hits_along(ray, spheres)
            first = found[0] if found else None
            expected = first is not None and first[1] == light
            tie = len(found) > 1 and near_tie(found[0][0], found[1][0])
            if bool(visible) != expected and not tie:
                fail(f"shadow ray {ray}: visible {bool(visible)}, brute force says {expected}")
            checked += 1
        print(f"{checked} answers agree with brute force")


if __name__ == "__main__":
    main()
