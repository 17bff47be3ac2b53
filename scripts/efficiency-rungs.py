#!/usr/bin/env python3
"""Time to equal error from rungs rendered elsewhere (a GPU node without OpenImageIO).

Each rung is a fresh render of SPP samples per pixel, RUNGS/<scene>/rung-SPP.exr with orb-render's
--stats-json beside it as rung-SPP.json (docs/benchmarks/2026-11-23-night/run2.sh makes them). Its
time is that render's own "seconds", as Mitsuba's rungs are timed in compare_mitsuba.py. relMSE is
measured here with orb-diff against the cached converged reference of efficiency.py (rendered here
if missing) or against --reference, and the times to relMSE 0.01 and 0.001 (or --targets) are
interpolated as efficiency.py does. A rung scored on the node already (scripts/exr-relmse.py, whose
output line is in rung-SPP.relmse; docs/benchmarks/2026-11-24-gpu/run46.sh) needs no image here.

  scripts/efficiency-rungs.py RUNGS scenes/cornell.scn scenes/caustic.scn --json gpu.json
  scripts/efficiency-rungs.py RUNGS scenes/cornell.scn --width 640 --height 480 --reference ref.exr --targets 0.001,0.0001
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
    parser.add_argument("--reference", help="converged image to score against (one scene), instead of the cached one")
    parser.add_argument("--targets", default=",".join(f"{t:g}" for t in efficiency.TARGETS),
                        help="relMSE targets, comma-separated (default 0.01,0.001)")
    a = parser.parse_args()
    if a.reference and len(a.scenes) != 1:
        parser.error("--reference scores one scene's rungs")
    curves = []
    for scene in a.scenes:
        folder = a.rungs / Path(scene).stem
        rungs = sorted((int(m.group(1)), p) for p in folder.glob("rung-*.json")
                       if (m := re.fullmatch(r"rung-(\d+)\.json", p.name)))
        if not rungs:
            sys.exit(f"efficiency-rungs: no rung-*.json in {folder}")
        reference = None
        curve = efficiency.Curve(a.label, scene)
        for spp, stats_path in rungs:
            stats = json.loads(stats_path.read_text())
            if (stats["width"], stats["height"]) != (a.width, a.height):
                sys.exit(f"efficiency-rungs: {stats_path} is {stats['width']}x{stats['height']}, "
                         f"not {a.width}x{a.height}")
            scored = stats_path.with_suffix(".relmse")
            if scored.exists():
                relmse = float(scored.read_text().split()[-1])
            else:
                if reference is None:  # rendered (and cached) only when an image needs it
                    reference = a.reference or efficiency.reference_image(
                        a.bin, scene, a.width, a.height, a.max_depth, a.reference_spp, a.cache)
                relmse = efficiency.relmse(a.bin, reference, str(stats_path.with_suffix(".exr")))
            curve.rungs.append(efficiency.Rung(spp, stats["seconds"], relmse))
        curves.append(curve)
    rows = efficiency.report(curves, a.width * a.height, tuple(float(t) for t in a.targets.split(",")))
    if a.json:
        a.json.write_text(json.dumps(rows, indent=2) + "\n")


if __name__ == "__main__":
    main()
