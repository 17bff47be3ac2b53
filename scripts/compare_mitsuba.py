#!/usr/bin/env python3
"""Orb and Mitsuba 3 side by side: time to equal error on the same CPU.

Run through scripts/compare-mitsuba.sh, which installs Mitsuba 3.5.2 into a
virtual environment (its llvm_ad_rgb variant works with Debian 12's LLVM).

For each scene: the Orb scene (orb-import's JSON) becomes a Mitsuba scene —
analytic spheres, two-sided diffuse (the Cornell walls are huge spheres seen
from inside), a smooth conductor with the mirror's colour as its specular
reflectance, a smooth dielectric tinted by the glass colour in reflection and
transmission, area emitters, a perspective camera with fov_axis y, a box pixel
filter, the path integrator with max_depth = Orb's depth + 1 (Mitsuba counts
path segments, Orb scattering events) — then both renderers climb an spp
ladder, relMSE is measured against the same converged Orb reference with
orb-diff, and the ratio of their times to relMSE 0.01 and 0.001 is printed.

Before any timing, a framing check proves the conversion: every sphere the
camera is outside of glows in its own colour and every BSDF is black, both
renderers render that, and their images must agree within a tolerance
derived from the sample count (otherwise the script stops).

Mitsuba's time is mi.render's, measured after a warm-up render at the same
spp (so JIT compilation is not counted); Orb's is orb-render's rendering time.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import efficiency  # noqa: E402  (the Orb side and the shared report)

import mitsuba as mi  # noqa: E402

mi.set_variant("llvm_ad_rgb")
import drjit as dr  # noqa: E402


def rgb(value):
    return {"type": "rgb", "value": [float(c) for c in value]}


def bsdf_for(material: dict) -> dict:
    kind = material["type"]
    if kind == "diffuse":
        return {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": rgb(material["color"])}}
    if kind == "mirror":
        return {"type": "conductor", "material": "none", "specular_reflectance": rgb(material["color"])}
    if kind == "dielectric":
        return {"type": "dielectric", "int_ior": float(material["ior"]), "ext_ior": 1.0,
                "specular_reflectance": rgb(material["color"]), "specular_transmittance": rgb(material["color"])}
    sys.exit(f"compare_mitsuba: material type {kind!r} has no Mitsuba counterpart here")


def camera_inside(sphere: dict, camera: dict) -> bool:
    return math.dist(sphere["center"], camera["position"]) < sphere["radius"]


def mitsuba_scene(scene: dict, width: int, height: int, depth: int, framing: bool = False) -> dict:
    cam = scene["camera"]
    if cam.get("aperture", 0) > 0:
        sys.exit("compare_mitsuba: thin-lens cameras are not converted")
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": (1 if framing else depth + 1)},
        "sensor": {
            "type": "perspective", "fov": float(cam["vfov_deg"]), "fov_axis": "y",
            "to_world": mi.ScalarTransform4f.look_at(origin=cam["position"], target=cam["target"], up=cam["up"]),
            "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                     "pixel_format": "rgb"},
            "sampler": {"type": "independent", "sample_count": 1},
        },
    }
    for i, sphere in enumerate(scene["spheres"]):
        material = scene["materials"][sphere["material"]]
        shape = {"type": "sphere", "center": [float(c) for c in sphere["center"]], "radius": float(sphere["radius"])}
        if framing:
            shape["bsdf"] = {"type": "diffuse", "reflectance": rgb([0, 0, 0])}
            if not camera_inside(sphere, cam):
                shape["emitter"] = {"type": "area", "radiance": rgb(framing_colour(i))}
        else:
            shape["bsdf"] = bsdf_for(material)
            if any(e > 0 for e in material["emission"]):
                shape["emitter"] = {"type": "area", "radiance": rgb(material["emission"])}
        d[f"sphere{i}"] = shape
    return d


def framing_colour(i: int) -> list[float]:
    return [0.2 + 0.8 * ((i * 37) % 11) / 10, 0.2 + 0.8 * ((i * 53) % 7) / 6, 0.2 + 0.8 * ((i * 71) % 5) / 4]


def orb_framing_scene(scene: dict) -> dict:
    """The same glowing-spheres scene in Orb's JSON form."""
    s = json.loads(json.dumps(scene))
    s.pop("animation", None)
    s["materials"] = []
    for i, sphere in enumerate(s["spheres"]):
        glow = [0, 0, 0] if camera_inside(sphere, scene["camera"]) else framing_colour(i)
        s["materials"].append({"name": f"glow {i}", "type": "diffuse", "color": [0, 0, 0], "emission": glow,
                               "ior": 1.5})
        sphere["material"] = i
    return s


def mitsuba_render(scene, spp: int, seed: int, path: Path) -> float:
    """Renders and writes `path`; returns the seconds of mi.render (synchronised)."""
    dr.sync_thread()
    start = time.perf_counter()
    image = mi.render(scene, spp=spp, seed=seed)
    dr.eval(image)
    dr.sync_thread()
    seconds = time.perf_counter() - start
    mi.util.write_bitmap(str(path), image)
    return seconds


def framing_check(bin_dir: Path, scene: dict, width: int, height: int, work: Path) -> None:
    spp = 256
    orb_scene = work / "framing.json"
    orb_scene.write_text(json.dumps(orb_framing_scene(scene)))
    orb_image, mts_image = work / "framing-orb.exr", work / "framing-mitsuba.exr"
    efficiency.run([efficiency.tool("orb-render", bin_dir), str(orb_scene), "--width", str(width), "--height",
                    str(height), "--spp", str(spp), "--max-depth", "0", "--passes", "beauty", "-o", str(orb_image),
                    "-q"])
    mts = mi.load_dict(mitsuba_scene(scene, width, height, 0, framing=True))
    mitsuba_render(mts, spp, 7, mts_image)
    # Only edge pixels are noisy (coverage of a box-filtered pixel, a Bernoulli
    # mean over spp samples): the mean squared error is at most the edge
    # fraction times 2 * 0.25 / spp times the brightest colour squared. With
    # edges under 20% of pixels, 2e-3 is a bound that a mirrored, shifted or
    # wrongly scaled image exceeds by orders of magnitude.
    result = efficiency.run([efficiency.tool("orb-diff", bin_dir), str(orb_image), str(mts_image), "--json", "-",
                             "-q"], ok_codes=(0, 1))
    rmse = json.loads(result.stdout)["passes"][0]["metrics"]["rmse"]
    bound = math.sqrt(0.2 * 2 * 0.25 / spp)
    print(f"framing check: RMSE {rmse:.3g} (bound {bound:.3g})", file=sys.stderr)
    if rmse > bound:
        sys.exit(f"compare_mitsuba: the framing check failed (RMSE {rmse:.3g} > {bound:.3g}); "
                 f"compare {orb_image} and {mts_image}")


def mitsuba_curve(scene_path: str, mts_dict: dict, bin_dir: Path, reference: str, max_spp: int, seed: int,
                  work: Path) -> efficiency.Curve:
    curve = efficiency.Curve("mitsuba", scene_path)
    scene = mi.load_dict(mts_dict)
    for spp in efficiency.ladder(1, max_spp):
        image = work / f"mitsuba-{spp}.exr"
        mitsuba_render(scene, spp, seed + 1_000_000, image)  # warm-up: compiles this spp's kernel
        seconds = mitsuba_render(scene, spp, seed, image)
        curve.rungs.append(efficiency.Rung(spp, seconds, efficiency.relmse(bin_dir, reference, str(image))))
        if curve.rungs[-1].relmse < min(efficiency.TARGETS) * 0.7:
            break
    return curve


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    efficiency.common_arguments(parser)
    a = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory(prefix="orb-vs-mitsuba-") as work_dir:
        work = Path(work_dir)
        for scene_path in a.scenes:
            scene = json.loads(efficiency.scene_json(a.bin, scene_path))
            framing_check(a.bin, scene, a.width, a.height, work)
            ref = efficiency.reference_image(a.bin, scene_path, a.width, a.height, a.max_depth, a.reference_spp,
                                             a.cache)
            # Interleaved on the same CPU, one after the other, per scene.
            orb = efficiency.orb_curve(a.bin, scene_path, ref, a.width, a.height, a.max_depth, a.max_spp, a.seed,
                                       work, [])
            mts = mitsuba_curve(scene_path, mitsuba_scene(scene, a.width, a.height, a.max_depth), a.bin, ref,
                                a.max_spp, a.seed, work)
            scene_rows = efficiency.report([orb, mts], a.width * a.height)
            for target in efficiency.TARGETS:
                t_orb, t_mts = (r[f"seconds_to_{target:g}"] for r in scene_rows)
                ratio = f"{t_mts / t_orb:.2f}x" if t_orb and t_mts else "n/a (a target was not reached)"
                print(f"  {Path(scene_path).name}: Orb reaches relMSE {target:g} {ratio} as fast as Mitsuba 3")
            rows += scene_rows
    if a.json:
        a.json.write_text(json.dumps(rows, indent=2) + "\n")


if __name__ == "__main__":
    main()
