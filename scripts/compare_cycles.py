#!/usr/bin/env python3
"""Orb and Blender Cycles 4.5 side by side: time to relMSE 0.001 on the Cornell box.

Run through scripts/compare-cycles.sh, which installs Blender as a Python
module (PyPI `bpy` 4.5) into a virtual environment.

The scene is the SmallptGPU Cornell box (scenes/cornell.scn, any scene of
nine spheres in that layout works) rebuilt in Blender from orb-import's
JSON: the same camera (position, target, up, vertical field of view), a
box pixel filter of one pixel, black world, and per sphere
- the mirror ball as an analytic sphere: a point cloud of one point made by
  geometry nodes (Cycles intersects points as true spheres, but only from
  outside: a ray inside a point passes out of it unseen);
- the glass ball, which rays must leave, as a smooth-shaded UV sphere of
  256 x 128 segments;
- the six walls, spheres of radius 10 000, as planes tangent to them where
  they face the box (Cycles' point intersection loses them at that radius;
  over the visible box the sphere lies within about 0.5 units of its
  tangent plane);
- the lamp as a point light of the lamp's radius (a sphere light, seen by
  the camera, soft falloff off) whose power gives the lamp's radiance:
  Cycles' sphere light of power P and radius r has radiance P / (4 pi^2 r^2)
  (checked by rendering one);
- diffuse as Diffuse BSDF (roughness 0: Lambert), mirror as Glossy BSDF of
  roughness 0, glass as Glass BSDF of roughness 0 and the same IOR, tinted
  by the material's colour;
- 5 bounces of every kind (Cycles counts bounces after the first hit, Orb
  the scattering events: --max-depth 6), caustics on, no clamping, no
  glossy filter.

Each renderer is measured against its own converged image (16 384 spp for
Orb, 4096 spp for Cycles, no denoising or adaptive sampling, cached), on a
ladder of samples per pixel, a fresh process per rung, stopping below
0.7 x 0.001:
- Orb plain: orb-render, rendering seconds from --stats-json;
- Orb + OIDN: orb-render --denoise (OIDN 2.5.1, albedo and normal); its
  rendering seconds plus the filter's (set-up and filter, as orb-denoise
  prints them for the same file);
- Cycles: CPU device, 2 threads, adaptive sampling (noise threshold 0.01)
  and its OIDN denoiser (albedo and normal, accurate prefilter, high
  quality); the rendering seconds are those of a second
  bpy.ops.render.render in the same process (warm: Blender already
  loaded, as when re-rendering in an open Blender).
Every rung also gives the process's wall time to its first image written
(start-up, kernel loading, first render, output). The time to relMSE 0.001
is interpolated on log-log between the rungs that bracket it, as
scripts/efficiency.py does, and FLIP at that point at the same fraction.
Rounds interleave the three, so load on a shared machine hits them alike,
each round with its own seed (at a few samples relMSE is ruled by rare
bright paths, so one seed's ladder is one draw); the report gives each
round and the median.

  scripts/compare-cycles.sh scenes/cornell.scn --rounds 3 --json cycles.json
"""
from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import efficiency  # noqa: E402  (tools, references, the spp ladder)

TARGET = 1e-3
WALL_RADIUS = 1000.0  # spheres larger than this are walls, drawn as planes


# ---------------------------------------------------------------- the Blender side (run in a child process)

def build_blender_scene(scene: dict, width: int, height: int, depth: int) -> None:
    import bpy
    from mathutils import Matrix, Vector

    bpy.ops.wm.read_factory_settings(use_empty=True)
    s = bpy.context.scene
    s.render.engine = "CYCLES"
    c = s.cycles
    c.device = "CPU"
    s.render.threads_mode = "FIXED"
    s.render.threads = 2
    s.render.resolution_x, s.render.resolution_y, s.render.resolution_percentage = width, height, 100
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = depth - 1
    c.transparent_max_bounces = depth - 1
    c.volume_bounces = 0
    c.caustics_reflective = c.caustics_refractive = True
    c.blur_glossy = 0.0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.pixel_filter_type = "BOX"
    s.render.filter_size = 1.0
    s.view_settings.view_transform = "Standard"
    s.render.image_settings.file_format = "OPEN_EXR"
    s.render.image_settings.color_depth = "32"

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    s.world = world

    cam = scene["camera"]
    if cam.get("aperture", 0) > 0:
        sys.exit("compare_cycles: thin-lens cameras are not converted")
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(cam["vfov_deg"])
    data.clip_start, data.clip_end = 1e-3, 1e6
    camera = bpy.data.objects.new("camera", data)
    s.collection.objects.link(camera)
    s.camera = camera
    pos = Vector(cam["position"])
    forward = (Vector(cam["target"]) - pos).normalized()
    right = forward.cross(Vector(cam["up"])).normalized()
    up = right.cross(forward)
    # Blender's camera looks down its -Z with +Y up.
    camera.matrix_world = Matrix(((right.x, up.x, -forward.x, pos.x), (right.y, up.y, -forward.y, pos.y),
                                  (right.z, up.z, -forward.z, pos.z), (0, 0, 0, 1)))

    materials = [blender_material(bpy, m, i) for i, m in enumerate(scene["materials"])]
    spheres = scene["spheres"]
    inner = [sp for sp in spheres if sp["radius"] <= WALL_RADIUS]
    box_centre = Vector([sum(sp["center"][k] for sp in inner) / max(1, len(inner)) for k in range(3)])
    for i, sphere in enumerate(spheres):
        material = scene["materials"][sphere["material"]]
        centre, radius = Vector(sphere["center"]), float(sphere["radius"])
        if any(e > 0 for e in material["emission"]):
            peak = max(material["emission"])
            light = bpy.data.lights.new(f"lamp{i}", "POINT")
            light.shadow_soft_size = radius
            light.use_soft_falloff = False
            light.color = [e / peak for e in material["emission"]]
            light.energy = peak * 4 * math.pi ** 2 * radius ** 2
            obj = bpy.data.objects.new(f"lamp{i}", light)
            obj.location = centre
            obj.visible_camera = obj.visible_glossy = obj.visible_transmission = True
            s.collection.objects.link(obj)
        elif radius > WALL_RADIUS:
            normal = (box_centre - centre).normalized()
            if (box_centre - centre).length < radius:
                normal = -normal  # the box is inside this sphere: its wall faces inward
            bpy.ops.mesh.primitive_plane_add(size=4 * WALL_RADIUS, location=centre + radius * (box_centre - centre).normalized())
            obj = bpy.context.active_object
            obj.rotation_mode = "QUATERNION"
            obj.rotation_quaternion = Vector((0, 0, 1)).rotation_difference(normal)
            obj.data.materials.append(materials[sphere["material"]])
        elif material["type"] == "dielectric":
            bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=radius, location=centre)
            obj = bpy.context.active_object
            bpy.ops.object.shade_smooth()
            obj.data.materials.append(materials[sphere["material"]])
        else:
            mesh = bpy.data.meshes.new(f"ball{i}")
            obj = bpy.data.objects.new(f"ball{i}", mesh)
            s.collection.objects.link(obj)
            tree = bpy.data.node_groups.new(f"ball{i}", "GeometryNodeTree")
            tree.interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")
            points = tree.nodes.new("GeometryNodePoints")
            points.inputs["Count"].default_value = 1
            points.inputs["Position"].default_value = centre
            points.inputs["Radius"].default_value = radius
            set_material = tree.nodes.new("GeometryNodeSetMaterial")
            set_material.inputs["Material"].default_value = materials[sphere["material"]]
            tree.links.new(points.outputs["Points"], set_material.inputs["Geometry"])
            tree.links.new(set_material.outputs["Geometry"], tree.nodes.new("NodeGroupOutput").inputs[0])
            obj.modifiers.new("sphere", "NODES").node_group = tree


def blender_material(bpy, material: dict, index: int):
    mat = bpy.data.materials.new(f"{material['name']} {index}")
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    colour = [float(v) for v in material["color"]] + [1.0]
    kind = material["type"]
    if kind == "diffuse":
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Roughness"].default_value = 0.0
    elif kind == "mirror":
        bsdf = nodes.new("ShaderNodeBsdfGlossy")
        bsdf.distribution = "GGX"
        bsdf.inputs["Roughness"].default_value = 0.0
    elif kind == "dielectric":
        bsdf = nodes.new("ShaderNodeBsdfGlass")
        bsdf.distribution = "GGX"
        bsdf.inputs["Roughness"].default_value = 0.0
        bsdf.inputs["IOR"].default_value = float(material["ior"])
    else:
        sys.exit(f"compare_cycles: material type {kind!r} has no Cycles counterpart here")
    bsdf.inputs["Color"].default_value = colour
    mat.node_tree.links.new(bsdf.outputs[0], nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
    return mat


def worker(a: argparse.Namespace) -> None:
    """One Cycles rung: the first render is the cold one a user waits for
    (its end is the process's time to first image); the second, timed, is
    Cycles' rendering time."""
    import bpy

    build_blender_scene(json.loads(Path(a.worker_scene).read_text()), a.width, a.height, a.max_depth)
    s = bpy.context.scene
    c = s.cycles
    c.samples = a.worker_spp
    c.seed = a.seed
    c.use_adaptive_sampling = a.worker_mode == "denoised"
    c.use_denoising = a.worker_mode == "denoised"
    if c.use_denoising:
        c.adaptive_threshold = 0.01
        c.adaptive_min_samples = 0
        c.denoiser = "OPENIMAGEDENOISE"
        c.denoising_input_passes = "RGB_ALBEDO_NORMAL"
        c.denoising_prefilter = "ACCURATE"
        c.denoising_quality = "HIGH"
        c.denoising_use_gpu = False
    s.render.filepath = a.worker_out
    timings = {}
    for run in range(a.worker_renders):
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        timings["render_seconds"] = time.perf_counter() - start
        if run == 0:
            timings["first_image_epoch"] = time.time()
    Path(a.worker_out + ".json").write_text(json.dumps(timings))


# ---------------------------------------------------------------- the driver

def cycles_rung(a: argparse.Namespace, scene_json: Path, spp: int, mode: str, out: Path, renders: int) -> dict:
    args = [sys.executable, str(Path(__file__).resolve()), "--worker-scene", str(scene_json), "--worker-spp", str(spp),
            "--worker-mode", mode, "--worker-out", str(out), "--worker-renders", str(renders), "--width",
            str(a.width), "--height", str(a.height), "--max-depth", str(a.max_depth), "--seed", str(a.seed), "x"]
    launched = time.time()
    result = subprocess.run(args, capture_output=True, text=True)
    if result.returncode != 0 or not out.exists():
        sys.exit(f"compare_cycles: the Cycles render failed ({result.returncode}):\n{result.stdout[-2000:]}\n"
                 f"{result.stderr[-2000:]}")
    timings = json.loads(Path(str(out) + ".json").read_text())
    return {"seconds": timings["render_seconds"], "wall": timings["first_image_epoch"] - launched}


def cycles_reference(a: argparse.Namespace, scene_path: str, scene_json: Path) -> str:
    key = efficiency.hashlib.sha256(f"{scene_json.read_text()}|{a.width}|{a.height}|{a.max_depth}|"
                                    f"{a.cycles_reference_spp}|bpy-4.5|glass-mesh".encode()).hexdigest()[:16]
    a.cache.mkdir(parents=True, exist_ok=True)
    path = a.cache / f"cycles-reference-{Path(scene_path).stem}-{key}.exr"
    if not path.exists():
        print(f"compare_cycles: rendering Cycles' reference ({a.cycles_reference_spp} spp, cached in {path})",
              file=sys.stderr)
        partial = path.with_suffix(".partial.exr")
        cycles_rung(a, scene_json, a.cycles_reference_spp, "plain", partial, 1)
        partial.rename(path)
    return str(path)


def metrics(bin_dir: Path, reference: str, image: str, test_pass: str | None = None) -> tuple[float, float]:
    args = [efficiency.tool("orb-diff", bin_dir), reference, image, "--json", "-", "-q"]
    if test_pass:
        args += ["--test-pass", test_pass]
    report = json.loads(efficiency.run(args, ok_codes=(0, 1)).stdout)
    m = report["passes"][0]["metrics"]
    return float(m["relmse"]), float(m["flip"]["mean"])


def orb_rung(a: argparse.Namespace, scene: str, reference: str, spp: int, denoise: bool, work: Path) -> dict:
    image, stats = work / f"orb-{spp}.exr", work / f"orb-{spp}.json"
    args = [efficiency.tool("orb-render", a.bin), scene, "--width", str(a.width), "--height", str(a.height),
            "--max-depth", str(a.max_depth), "--seed", str(a.seed), "--spp", str(spp), "-o", str(image),
            "--stats-json", str(stats), "-q"] + (["--denoise"] if denoise else ["--passes", "beauty"])
    launched = time.perf_counter()
    efficiency.run(args)
    wall = time.perf_counter() - launched
    seconds = json.loads(stats.read_text())["seconds"]
    if denoise:
        # orb-render does not report the filter's time; orb-denoise, run on
        # the same file (the same beauty and guides), does.
        redone = work / f"orb-{spp}-filter.exr"
        text = efficiency.run([efficiency.tool("orb-denoise", a.bin), str(image), "-o", str(redone)]).stderr
        seconds += filter_seconds(text)
        redone.unlink()
    relmse, flip = metrics(a.bin, reference, str(image), "denoised" if denoise else None)
    image.unlink()
    return {"spp": spp, "seconds": seconds, "wall": wall, "relmse": relmse, "flip": flip}


def filter_seconds(orb_denoise_message: str) -> float:
    # "denoised X in 0.31 s (filter set-up 0.01 s, filter 0.05 s; ...)"
    import re
    match = re.search(r"filter set-up ([0-9.]+) s, filter ([0-9.]+) s", orb_denoise_message)
    if not match:
        sys.exit(f"compare_cycles: orb-denoise did not print its filter time:\n{orb_denoise_message}")
    return float(match.group(1)) + float(match.group(2))


def climb(render, first: int, last: int) -> list[dict]:
    rungs = []
    for spp in efficiency.ladder(first, last):
        rungs.append(render(spp))
        if rungs[-1]["relmse"] < 0.7 * TARGET:
            break
    return rungs


def at_target(rungs: list[dict]) -> dict | None:
    """Seconds, wall seconds and FLIP where relMSE crosses TARGET (log-log between the bracketing rungs)."""
    for lo, hi in zip(rungs, rungs[1:]):
        if lo["relmse"] >= TARGET >= hi["relmse"] and lo["relmse"] > hi["relmse"]:
            f = (math.log(TARGET) - math.log(lo["relmse"])) / (math.log(hi["relmse"]) - math.log(lo["relmse"]))
            mix = lambda key: math.exp(math.log(lo[key]) + f * (math.log(hi[key]) - math.log(lo[key])))  # noqa: E731
            return {"seconds": mix("seconds"), "wall": mix("wall"), "flip": mix("flip"),
                    "spp": mix("spp"), "between": [lo["spp"], hi["spp"]]}
    return None


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    efficiency.common_arguments(parser)
    parser.set_defaults(width=160, height=120)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--cycles-reference-spp", type=int, default=4096)
    parser.add_argument("--worker-scene", help=argparse.SUPPRESS)
    parser.add_argument("--worker-spp", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--worker-mode", choices=("plain", "denoised"), help=argparse.SUPPRESS)
    parser.add_argument("--worker-out", help=argparse.SUPPRESS)
    parser.add_argument("--worker-renders", type=int, default=2, help=argparse.SUPPRESS)
    a = parser.parse_args()
    if a.worker_scene:
        worker(a)
        return
    results = {}
    with tempfile.TemporaryDirectory(prefix="orb-vs-cycles-") as work_dir:
        work = Path(work_dir)
        for scene_path in a.scenes:
            scene_json = work / "scene.json"
            scene_json.write_text(efficiency.scene_json(a.bin, scene_path))
            orb_ref = efficiency.reference_image(a.bin, scene_path, a.width, a.height, a.max_depth, a.reference_spp,
                                                 a.cache)
            cyc_ref = cycles_reference(a, scene_path, scene_json)
            # How alike the two scenes are: the converged images against each other.
            like_relmse, like_flip = metrics(a.bin, orb_ref, cyc_ref)
            print(f"{Path(scene_path).name}: Cycles' converged image against Orb's: relMSE {like_relmse:.4f}, "
                  f"FLIP {like_flip:.4f}")
            # Warm-ups: kernel caches, OIDN's and Blender's files in the page cache.
            orb_rung(a, scene_path, orb_ref, 1, True, work)
            cycles_rung(a, scene_json, 1, "denoised", work / "warm-up.exr", 1)
            runs = {"orb": [], "orb+oidn": [], "cycles+oidn": []}
            base_seed = a.seed
            for r in range(a.rounds):
                # A new seed each round: at a few samples relMSE is ruled by
                # rare bright paths, so one seed's ladder is one draw.
                a.seed = base_seed + r
                runs["orb"].append(climb(lambda spp: orb_rung(a, scene_path, orb_ref, spp, False, work), 16, a.max_spp))
                runs["orb+oidn"].append(climb(lambda spp: orb_rung(a, scene_path, orb_ref, spp, True, work), 1,
                                              a.max_spp))
                runs["cycles+oidn"].append(climb(lambda spp: cycles_rung_measured(a, scene_json, cyc_ref, spp, work),
                                                 1, a.max_spp))
                for name, rounds in runs.items():
                    hit = at_target(rounds[-1])
                    print(f"  round {r + 1} {name:12s} " + (
                        f"relMSE {TARGET:g} at {hit['spp']:.1f} spp: {hit['seconds']:.3f} s rendering, "
                        f"{hit['wall']:.3f} s wall, FLIP {hit['flip']:.3f}" if hit else "target not bracketed") +
                          "  rungs: " + ", ".join(f"{x['spp']}:{x['relmse']:.2e}/{x['seconds']:.2f}s"
                                                  for x in rounds[-1]), flush=True)
            summary = {}
            for name, rounds in runs.items():
                hits = [h for h in map(at_target, rounds) if h]
                summary[name] = {key: statistics.median(h[key] for h in hits) for key in ("seconds", "wall", "flip", "spp")
                                 } if hits else None
            print(f"\n{Path(scene_path).name} {a.width}x{a.height}, median of {a.rounds} rounds, to relMSE {TARGET:g}:")
            print("| renderer | spp | rendering s | wall s | FLIP |")
            print("| --- | --- | --- | --- | --- |")
            for name, m in summary.items():
                print(f"| {name} | {m['spp']:.1f} | {m['seconds']:.3f} | {m['wall']:.3f} | {m['flip']:.3f} |" if m
                      else f"| {name} | not reached | | | |")
            cyc = summary["cycles+oidn"]
            for name in ("orb", "orb+oidn"):
                if summary[name] and cyc:
                    print(f"  {name} reaches it {cyc['seconds'] / summary[name]['seconds']:.1f}x sooner than Cycles "
                          f"(rendering), {cyc['wall'] / summary[name]['wall']:.1f}x (wall)")
            results[scene_path] = {"like": {"relmse": like_relmse, "flip": like_flip}, "runs": runs,
                                   "median": summary}
    if a.json:
        a.json.write_text(json.dumps(results, indent=2) + "\n")


def cycles_rung_measured(a, scene_json: Path, reference: str, spp: int, work: Path) -> dict:
    out = work / f"cycles-{spp}.exr"
    timing = cycles_rung(a, scene_json, spp, "denoised", out, 2)
    relmse, flip = metrics(a.bin, reference, str(out))
    out.unlink()
    return {"spp": spp, **timing, "relmse": relmse, "flip": flip}


if __name__ == "__main__":
    main()
