#!/usr/bin/env python3
"""Time to equal error from rungs rendered elsewhere (a GPU node without OpenImageIO).

Each rung is a fresh render of SPP samples per pixel, RUNGS/<scene>/rung-SPP.exr with orb-render's
--stats-json beside it as rung-SPP.json (docs/benchmarks/2026-11-23-night/run2.sh makes them). Its
time is that render's own "seconds", as Mitsuba's rungs are timed in compare_mitsuba.py. relMSE is
measured here with orb-diff against the cached converged reference of efficiency.py (rendered here
if missing), and the times to relMSE 0.01 and 0.001 are interpolated as efficiency.py does.

  scripts/efficiency-rungs.py RUNGS scenes/cornell.scn scenes/caustic.scn --json gpu.json
"""
import argparse
import json
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import efficiency  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("rungs", type=Path, help="folder holding one folder of rungs per scene (named by its stem)")
    efficiency.common_arguments(parser)
    parser.add_argument("--label", default="orb", help="the renderer's name in the report")
    a = parser.parse_args()
    curves = []
    for scene in a.scenes:
        ref = efficiency.reference_image(a.bin, scene, a.width, a.height, a.max_depth, a.reference_spp, a.cache)
        folder = a.rungs / Path(scene).stem
        rungs = sorted((int(re.fullmatch(r"rung-(\d+)\.exr", p.name).group(1)), p)
                       for p in folder.glob("rung-*.exr"))
        if not rungs:
            sys.exit(f"efficiency-rungs: no rung-*.exr in {folder}")
        curve = efficiency.Curve(a.label, scene)
        for spp, image in rungs:
            stats = json.loads(image.with_suffix(".json").read_text())
            if (stats["width"], stats["height"]) != (a.width, a.height):
                sys.exit(f"efficiency-rungs: {image} is {stats['width']}x{stats['height']}, not {a.width}x{a.height}")
            curve.rungs.append(efficiency.Rung(spp, stats["seconds"], efficiency.relmse(a.bin, ref, str(image))))
        curves.append(curve)
    rows = efficiency.report(curves, a.width * a.height)
    if a.json:
        a.json.write_text(json.dumps(rows, indent=2) + "\n")


if __name__ == "__main__":
    main()
