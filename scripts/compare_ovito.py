#!/usr/bin/env python3
"""Orb and OVITO 3.17 side by side: a million random atoms at 640x480.

Run through scripts/compare-ovito.sh, which installs OVITO's Python module
(PyPI `ovito` 3.17) and Pillow into a virtual environment.

1. The atoms: N random points (default 1 000 000, numpy's default_rng with a
   fixed seed) uniform in a cubic periodic box of side 200, radius 1, three
   types, written as a LAMMPS text dump (id type x y z radius) that both
   programs read; cached by its settings.
2. One camera for both: position, look-at, up +y and a vertical field of
   view of 42.88 degrees (orb-render's --camera-position/--look-at/--up/--vfov,
   OVITO's Viewport camera_pos/camera_dir/camera_up/fov). The types get
   Orb's colours in OVITO (Okabe-Ito, as orb-import colours LAMMPS types);
   OVITO draws the cell as lines, Orb as grey spheres (--cell). Orb keeps
   its default lights of a particle file and black background, OVITO its
   own lighting and white background.
3. Orb's converged image (--reference-spp, plain) and a ladder of
   orb-render --denoise renders (1, 2, 4, ... spp) against it: relMSE and
   FLIP (orb-diff) of the denoised layer and of the plain beauty; the
   "clean" spp is the smallest whose denoised FLIP is at most --clean-flip
   (0.05) or relMSE at most --clean-relmse (0.001), else the last rung, or
   the one --clean-spp names (judged by looking at the --keep images).
4. Timed rounds, interleaved, each a fresh process:
   - OVITO, Tachyon (its defaults: antialiasing and ambient occlusion, 12
     samples each) and OSPRay (its defaults) when it loads: seconds to read
     the file (import_file and pipeline.compute), seconds of
     Viewport.render_image, and the process's wall time;
   - Orb's first image (orb-render at 1 spp, plain) and Orb --denoise at the
     clean spp: orb-render's setup (reading the file, BVH, kernels from the
     cache), rendering seconds (plus OIDN's filter time for --denoise, as
     orb-denoise prints it for the same file) and the process's wall time.
   The medians are printed as a table.
5. A side-by-side picture: OVITO Tachyon's image left, Orb's denoised image
   right (orb-tonemap's default view), scaled by --picture-scale and saved
   as a 256-colour PNG.

  scripts/compare-ovito.sh --rounds 3 --picture docs/images/ovito-vs-orb-1m-atoms.png
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import efficiency  # noqa: E402  (tools, run)

OKABE_ITO = ["E69F00", "56B4E9", "009E73", "F0E442", "0072B2", "D55E00", "CC79A7"]
BOX = 200.0
TARGET = (100.0, 100.0, 100.0)
CAMERA = (364.0, 338.0, 444.0)
UP = (0.0, 1.0, 0.0)
VFOV_DEG = 42.88


def write_atoms(path: Path, count: int, seed: int) -> None:
    import numpy as np

    rng = np.random.default_rng(seed)
    positions = rng.random((count, 3)) * BOX
    types = rng.integers(1, 4, count)
    partial = path.with_suffix(".partial")
    with partial.open("w") as f:
        f.write(f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n{count}\nITEM: BOX BOUNDS pp pp pp\n"
                f"0 {BOX}\n0 {BOX}\n0 {BOX}\nITEM: ATOMS id type x y z radius\n")
        table = np.column_stack([np.arange(1, count + 1), types, positions, np.ones(count)])
        np.savetxt(f, table, fmt="%d %d %.4f %.4f %.4f %.2f")
    partial.rename(path)


# ---------------------------------------------------------------- OVITO (run in a child process)

def ovito_worker(atoms: str, renderer_name: str, width: int, height: int, out: str) -> None:
    start = time.perf_counter()
    from ovito.io import import_file
    from ovito.vis import OSPRayRenderer, TachyonRenderer, Viewport

    imported = time.perf_counter()
    pipeline = import_file(atoms)
    types = pipeline.source.data.particles_.particle_types_
    for t in list(types.types):
        colour = OKABE_ITO[(t.id - 1) % len(OKABE_ITO)]
        types.type_by_id_(t.id).color = tuple(int(colour[i:i + 2], 16) / 255 for i in (0, 2, 4))
    pipeline.add_to_scene()
    pipeline.compute()
    computed = time.perf_counter()
    renderer = TachyonRenderer() if renderer_name == "tachyon" else OSPRayRenderer()
    viewport = Viewport(type=Viewport.Type.Perspective, camera_pos=CAMERA,
                        camera_dir=tuple(t - c for t, c in zip(TARGET, CAMERA)), camera_up=UP,
                        fov=math.radians(VFOV_DEG))
    viewport.render_image(size=(width, height), filename=out, background=(1.0, 1.0, 1.0), renderer=renderer)
    done = time.perf_counter()
    Path(out + ".json").write_text(json.dumps({"import_seconds": imported - start, "load_seconds": computed - imported,
                                               "render_seconds": done - computed}))


def ovito_run(a, atoms: Path, renderer: str, out: Path) -> dict | None:
    args = [sys.executable, str(Path(__file__).resolve()), "--worker-ovito", renderer, "--atoms", str(atoms),
            "--worker-out", str(out), "--width", str(a.width), "--height", str(a.height)]
    launched = time.perf_counter()
    result = subprocess.run(args, capture_output=True, text=True)
    wall = time.perf_counter() - launched
    if result.returncode != 0 or not out.exists():
        message = (result.stderr or result.stdout).strip().splitlines()
        print(f"compare_ovito: OVITO's {renderer} renderer failed: {message[-1] if message else result.returncode}",
              file=sys.stderr)
        if "Vulkan" in result.stderr:
            print("  OVITO's Python module renders through Vulkan even with Tachyon; on a machine without a GPU "
                  "install Mesa's software driver (Debian: apt-get install mesa-vulkan-drivers)", file=sys.stderr)
        return None
    timing = json.loads(Path(str(out) + ".json").read_text())
    return {"wall": wall, "load": timing["load_seconds"], "render": timing["render_seconds"],
            "seconds": timing["load_seconds"] + timing["render_seconds"]}


# ---------------------------------------------------------------- Orb's Python module (a child process)

def orb_python_worker(atoms: str, width: int, height: int, spp: int, denoise: bool, out: str) -> None:
    """The same picture through `import orb` in the interpreter that runs
    OVITO: orb.load with orb-render's options, one render, its pixels as
    numpy arrays (the denoised layer with --denoise), the image saved."""
    start = time.perf_counter()
    import orb

    imported = time.perf_counter()
    scene = orb.load(atoms, cell=True, camera_position=CAMERA, look_at=TARGET, up=UP, vfov=VFOV_DEG)
    loaded = time.perf_counter()
    image = scene.render(width, height, spp, seed=1, denoise=denoise)
    pixels = image.denoised if denoise else image.beauty
    rendered = time.perf_counter()
    image.save(out)
    Path(out + ".json").write_text(json.dumps({"import_seconds": imported - start, "load_seconds": loaded - imported,
                                               "render_seconds": rendered - loaded, "shape": list(pixels.shape)}))


def orb_python_run(a, atoms: Path, spp: int, denoise: bool, out: Path) -> dict:
    args = [sys.executable, str(Path(__file__).resolve()), "--worker-orb-python", "--atoms", str(atoms),
            "--worker-out", str(out), "--width", str(a.width), "--height", str(a.height), "--worker-spp", str(spp)]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [str(a.orb_python),
                                                                     os.environ.get("PYTHONPATH")])))
    launched = time.perf_counter()
    result = subprocess.run(args + (["--worker-denoise"] if denoise else []), capture_output=True, text=True, env=env)
    wall = time.perf_counter() - launched
    if result.returncode != 0:
        sys.exit(f"compare_ovito: Orb's Python module failed:\n{result.stderr.strip()}")
    timing = json.loads(Path(str(out) + ".json").read_text())
    return {"wall": wall, "load": timing["load_seconds"], "render": timing["render_seconds"],
            "seconds": timing["load_seconds"] + timing["render_seconds"]}


# ---------------------------------------------------------------- Orb

def orb_camera() -> list[str]:
    text = lambda v: ",".join(f"{x:g}" for x in v)  # noqa: E731
    return ["--camera-position", text(CAMERA), "--look-at", text(TARGET), "--up", text(UP), "--vfov", f"{VFOV_DEG:g}"]


def orb_run(a, atoms: Path, spp: int, denoise: bool, out: Path, seed: int = 1) -> dict:
    stats = out.with_suffix(".json")
    args = [efficiency.tool("orb-render", a.bin), str(atoms), "--cell", "--width", str(a.width), "--height",
            str(a.height), "--spp", str(spp), "--seed", str(seed), "-o", str(out), "--stats-json", str(stats),
            "-q"] + orb_camera() + (["--denoise"] if denoise else ["--passes", "beauty"])
    launched = time.perf_counter()
    efficiency.run(args)
    wall = time.perf_counter() - launched
    s = json.loads(stats.read_text())
    seconds = s["seconds"]
    if denoise:
        redone = out.with_name(out.stem + "-filter.exr")
        message = efficiency.run([efficiency.tool("orb-denoise", a.bin), str(out), "-o", str(redone)]).stderr
        match = re.search(r"filter set-up ([0-9.]+) s, filter ([0-9.]+) s", message)
        if not match:
            sys.exit(f"compare_ovito: orb-denoise did not print its filter time:\n{message}")
        seconds += float(match.group(1)) + float(match.group(2))
        redone.unlink()
    return {"wall": wall, "setup": s["setup_seconds"], "render": seconds, "seconds": s["setup_seconds"] + seconds}


def orb_reference(a, atoms: Path) -> Path:
    key = efficiency.hashlib.sha256(f"{atoms.name}|{a.width}|{a.height}|{a.reference_spp}|{orb_camera()}".encode()
                                    ).hexdigest()[:16]
    path = a.cache / f"reference-atoms-{key}.exr"
    if not path.exists():
        print(f"compare_ovito: rendering Orb's reference ({a.reference_spp} spp, cached in {path})", file=sys.stderr)
        partial = path.with_name(path.stem + ".partial.exr")
        orb_run(a, atoms, a.reference_spp, False, partial, seed=1000003)
        partial.rename(path)
    return path


def metrics(a, reference: Path, image: Path, test_pass: str | None) -> tuple[float, float]:
    args = [efficiency.tool("orb-diff", a.bin), str(reference), str(image), "--json", "-", "-q"]
    report = json.loads(efficiency.run(args + (["--test-pass", test_pass] if test_pass else []), ok_codes=(0, 1)).stdout)
    m = report["passes"][0]["metrics"]
    return float(m["relmse"]), float(m["flip"]["mean"])


def side_by_side(a, ovito_png: Path, orb_exr: Path, work: Path, out: Path) -> None:
    from PIL import Image

    orb_png = work / "orb.png"
    efficiency.run([efficiency.tool("orb-tonemap", a.bin), str(orb_exr), "--pass", "denoised", "-o", str(orb_png)])
    left, right = Image.open(ovito_png).convert("RGB"), Image.open(orb_png).convert("RGB")
    size = (round(a.width * a.picture_scale), round(a.height * a.picture_scale))
    picture = Image.new("RGB", (2 * size[0], size[1]))
    picture.paste(left.resize(size, Image.LANCZOS), (0, 0))
    picture.paste(right.resize(size, Image.LANCZOS), (size[0], 0))
    picture = picture.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    out.parent.mkdir(parents=True, exist_ok=True)
    partial = out.with_name(out.stem + ".partial.png")
    picture.save(partial, optimize=True)
    partial.rename(out)
    print(f"wrote {out} ({out.stat().st_size // 1024} kB): OVITO Tachyon left, Orb --denoise right")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--atoms-count", type=int, default=1_000_000)
    parser.add_argument("--atoms-seed", type=int, default=12345)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--reference-spp", type=int, default=512)
    parser.add_argument("--max-spp", type=int, default=64, help="last rung of the --denoise ladder")
    parser.add_argument("--clean-flip", type=float, default=0.05)
    parser.add_argument("--clean-relmse", type=float, default=1e-3)
    parser.add_argument("--clean-spp", type=int, help="time --denoise at this spp (judged clean by looking) "
                        "instead of searching the ladder")
    parser.add_argument("--picture", type=Path, help="write the side-by-side PNG here")
    parser.add_argument("--picture-scale", type=float, default=0.75)
    parser.add_argument("--keep", type=Path, help="copy the rendered images into this folder")
    parser.add_argument("--bin", type=Path, default=efficiency.ROOT / "build" / "bin")
    parser.add_argument("--cache", type=Path,
                        default=Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "orb" / "efficiency")
    parser.add_argument("--json", type=Path)
    parser.add_argument("--worker-ovito", choices=("tachyon", "ospray"), help=argparse.SUPPRESS)
    parser.add_argument("--worker-out", help=argparse.SUPPRESS)
    parser.add_argument("--atoms", help=argparse.SUPPRESS)
    parser.add_argument("--orb-python", type=Path, help="also time Orb's Python module (`import orb`) found in this "
                        "folder (a build's python/ folder, or a site-packages), in OVITO's interpreter")
    parser.add_argument("--worker-orb-python", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--worker-spp", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--worker-denoise", action="store_true", help=argparse.SUPPRESS)
    a = parser.parse_args()
    if a.worker_ovito:
        ovito_worker(a.atoms, a.worker_ovito, a.width, a.height, a.worker_out)
        return
    if a.worker_orb_python:
        orb_python_worker(a.atoms, a.width, a.height, a.worker_spp, a.worker_denoise, a.worker_out)
        return

    a.cache.mkdir(parents=True, exist_ok=True)
    atoms = a.cache / f"random-atoms-{a.atoms_count}-seed{a.atoms_seed}.lammpstrj"
    if not atoms.exists():
        print(f"compare_ovito: writing {a.atoms_count} random atoms to {atoms}", file=sys.stderr)
        write_atoms(atoms, a.atoms_count, a.atoms_seed)
    reference = orb_reference(a, atoms)
    with tempfile.TemporaryDirectory(prefix="orb-vs-ovito-") as work_dir:
        work = Path(work_dir)
        # Orb's ladder: the smallest clean spp with --denoise, and the plain
        # render at the same spp, against the converged image.
        ladder, clean, clean_image = [], None, None
        rungs = [a.clean_spp] if a.clean_spp else efficiency.ladder(1, a.max_spp)
        for spp in rungs:
            image = work / f"orb-d{spp}.exr"
            timing = orb_run(a, atoms, spp, True, image)
            relmse, flip = metrics(a, reference, image, "denoised")
            plain_relmse, plain_flip = metrics(a, reference, image, None)
            ladder.append({"spp": spp, "relmse": relmse, "flip": flip, "plain_relmse": plain_relmse,
                           "plain_flip": plain_flip, **timing})
            print(f"  orb {spp:3d} spp: --denoise relMSE {relmse:.2e}, FLIP {flip:.4f}; plain relMSE "
                  f"{plain_relmse:.2e}, FLIP {plain_flip:.4f}; {timing['render']:.2f} s rendering and filter, "
                  f"{timing['wall']:.1f} s wall", flush=True)
            if a.keep:
                a.keep.mkdir(parents=True, exist_ok=True)
                efficiency.run([efficiency.tool("orb-tonemap", a.bin), str(image), "--pass", "denoised", "-o",
                                str(a.keep / f"orb-denoised-{spp}spp.png")])
                efficiency.run([efficiency.tool("orb-tonemap", a.bin), str(image), "-o",
                                str(a.keep / f"orb-plain-{spp}spp.png")])
            clean, clean_image = spp, image
            if a.clean_spp or flip <= a.clean_flip or relmse <= a.clean_relmse:
                break
            if spp != rungs[-1]:
                image.unlink()
        else:
            print(f"compare_ovito: no --denoise render up to {a.max_spp} spp reaches FLIP {a.clean_flip:g} or "
                  f"relMSE {a.clean_relmse:g}; timing {clean} spp (look at the images, --keep DIR)", file=sys.stderr)
        print(f"timing --denoise at {clean} spp", flush=True)

        renderers = ["tachyon", "ospray"]
        runs = {"ovito-tachyon": [], "ovito-ospray": [], "orb-1spp": [], f"orb-denoise-{clean}spp": []}
        if a.orb_python:
            runs.update({"python-orb-1spp": [], f"python-orb-denoise-{clean}spp": []})
        for r in range(a.rounds):
            for name in renderers[:]:
                out = work / f"ovito-{name}.png"
                timing = ovito_run(a, atoms, name, out)
                if timing is None:
                    renderers.remove(name)
                    continue
                runs[f"ovito-{name}"].append(timing)
            runs["orb-1spp"].append(orb_run(a, atoms, 1, False, work / "orb-1.exr"))
            runs[f"orb-denoise-{clean}spp"].append(orb_run(a, atoms, clean, True, work / "orb-clean.exr"))
            if a.orb_python:
                runs["python-orb-1spp"].append(orb_python_run(a, atoms, 1, False, work / "python-1.exr"))
                runs[f"python-orb-denoise-{clean}spp"].append(
                    orb_python_run(a, atoms, clean, True, work / "python-clean.exr"))
            print(f"  round {r + 1}: " + "; ".join(f"{k} {v[-1]['seconds']:.2f} s ({v[-1]['wall']:.2f} s wall)"
                                                  for k, v in runs.items() if v), flush=True)
        print(f"\n{a.atoms_count} random atoms, {a.width}x{a.height}, median of {a.rounds} rounds "
              "(seconds; 'load or setup' is reading the file, and for Orb the BVH and kernels):")
        print("| renderer | load or setup s | rendering s | to the image s | process wall s |")
        print("| --- | --- | --- | --- | --- |")
        medians = {}
        for name, rows in runs.items():
            if not rows:
                continue
            m = {k: statistics.median(row[k] for row in rows) for k in rows[0]}
            medians[name] = m
            print(f"| {name} | {m.get('load', m.get('setup')):.2f} | {m['render']:.2f} | {m['seconds']:.2f} | "
                  f"{m['wall']:.2f} |")
        if a.keep:
            a.keep.mkdir(parents=True, exist_ok=True)
            for name in renderers:
                (a.keep / f"ovito-{name}.png").write_bytes((work / f"ovito-{name}.png").read_bytes())
            (a.keep / "orb-1spp.exr").write_bytes((work / "orb-1.exr").read_bytes())
            (a.keep / f"orb-denoised-{clean}spp.exr").write_bytes(clean_image.read_bytes())
        if a.picture:
            side_by_side(a, work / "ovito-tachyon.png", clean_image, work, a.picture)
    if a.json:
        a.json.write_text(json.dumps({"ladder": ladder, "clean_spp": clean, "runs": runs, "median": medians},
                                     indent=2) + "\n")


if __name__ == "__main__":
    main()
