#!/usr/bin/env python3
"""Time to equal error: how long a renderer takes to reach a given relMSE.

Renders a scene with orb-render at each rung of an spp ladder (1, 2, 4, ...
spp; each rung a fresh render timed alone, as Mitsuba's rungs are), measures relMSE against a converged reference with orb-diff, and reports the
time to reach relMSE 0.01 and 0.001, interpolated on log-log between the two
rungs that bracket each target and never extrapolated, plus samples/s and
relMSE x seconds (lower is better; constant for an unbiased estimator whose
error falls as 1/time).

The reference is a high-spp Orb render made once and cached (Orb's converged
images agree with Mitsuba 3's, docs/performance.md). Its own error adds to
every measured relMSE, so it should be at least ten times lower than the
smallest target: the default 16384 spp at 320x240 is about 1/20 of 0.001 on
the Cornell box.

Times are the renderers' own rendering seconds (orb-render's --stats-json
"seconds"; for Mitsuba, mi.render after a warm-up, in compare_mitsuba.py),
not process start-up or kernel compilation.

  scripts/efficiency.py scenes/cornell.scn                      # 320x240, depth 6
  scripts/efficiency.py scenes/*.scn --json efficiency.json
The machine must be otherwise idle: the figures are wall-clock.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGETS = (0.01, 0.001)


@dataclass
class Rung:
    spp: int
    seconds: float  # rendering time of this rung's image
    relmse: float


@dataclass
class Curve:
    renderer: str
    scene: str
    rungs: list[Rung] = field(default_factory=list)

    def samples_per_second(self, pixels: int) -> float:
        last = self.rungs[-1]
        return pixels * last.spp / last.seconds

    def time_to(self, target: float) -> float | None:
        """Seconds to reach `target`, interpolated on log-log; None if not reached."""
        for a, b in zip(self.rungs, self.rungs[1:]):
            if a.relmse >= target >= b.relmse and a.relmse > b.relmse:
                f = (math.log(target) - math.log(a.relmse)) / (math.log(b.relmse) - math.log(a.relmse))
                return math.exp(math.log(a.seconds) + f * (math.log(b.seconds) - math.log(a.seconds)))
        return None  # not bracketed (never reached, or already below at the first rung): no extrapolation

    def error_times_seconds(self) -> float:
        last = self.rungs[-1]
        return last.relmse * last.seconds


def tool(name: str, bin_dir: Path) -> str:
    path = bin_dir / name
    if not path.exists():
        sys.exit(f"efficiency: {path} not found; build first (scripts/build.sh) or pass --bin")
    return str(path)


def run(args: list[str], ok_codes: tuple[int, ...] = (0,)) -> subprocess.CompletedProcess:
    result = subprocess.run(args, capture_output=True, text=True)
    if result.returncode not in ok_codes:
        sys.exit(f"efficiency: {' '.join(args)} failed ({result.returncode}):\n{result.stderr}")
    return result


def relmse(bin_dir: Path, reference: str, image: str) -> float:
    # orb-diff exits 1 when the images differ beyond its default gate: expected here.
    result = run([tool("orb-diff", bin_dir), reference, image, "--json", "-", "-q"], ok_codes=(0, 1))
    report = json.loads(result.stdout)
    return float(report["passes"][0]["metrics"]["relmse"])


def scene_json(bin_dir: Path, scene: str) -> str:
    return run([tool("orb-import", bin_dir), scene]).stdout


def reference_image(bin_dir: Path, scene: str, width: int, height: int, depth: int, spp: int,
                    cache: Path) -> str:
    """A converged Orb render, cached by scene content and settings."""
    key = hashlib.sha256(f"{scene_json(bin_dir, scene)}|{width}|{height}|{depth}|{spp}".encode()).hexdigest()[:16]
    cache.mkdir(parents=True, exist_ok=True)
    path = cache / f"reference-{Path(scene).stem}-{key}.exr"
    if not path.exists():
        print(f"efficiency: rendering the reference for {scene} ({spp} spp, cached in {path})", file=sys.stderr)
        run([tool("orb-render", bin_dir), scene, "--width", str(width), "--height", str(height),
             "--max-depth", str(depth), "--spp", str(spp), "--seed", "1000003", "--passes", "beauty",
             "-o", str(path), "-q"])
    return str(path)


def ladder(first: int, last: int) -> list[int]:
    spp, rungs = first, []
    while spp <= last:
        rungs.append(spp)
        spp *= 2
    return rungs


def orb_curve(bin_dir: Path, scene: str, reference: str, width: int, height: int, depth: int,
              max_spp: int, seed: int, workdir: Path, extra: list[str]) -> Curve:
    curve = Curve("orb", scene)
    settings = ["--width", str(width), "--height", str(height), "--max-depth", str(depth), "--seed", str(seed)] + extra
    # A warm-up render with the ladder's settings, untimed, as Mitsuba gets
    # one: the kernels' compilation (OpenCL's build and PoCL's code
    # generation at the first launch) then comes from the caches and is not
    # counted in the first rung.
    run([tool("orb-render", bin_dir), scene, "--spp", "1", "--passes", "beauty", "-o", str(workdir / "warm-up.exr"),
         "-q"] + settings)
    for spp in ladder(1, max_spp):
        # Each rung is a fresh render of its spp, timed alone, as
        # compare_mitsuba.py times Mitsuba's: the time a user waits for an
        # image of that many samples.
        image = workdir / f"orb-{spp}.exr"
        stats = workdir / f"orb-{spp}.json"
        run([tool("orb-render", bin_dir), scene, "--spp", str(spp), "--passes", "beauty", "-o", str(image),
             "--stats-json", str(stats), "-q"] + settings)
        seconds = json.loads(stats.read_text())["seconds"]
        curve.rungs.append(Rung(spp, seconds, relmse(bin_dir, reference, str(image))))
        image.unlink()
        if curve.rungs[-1].relmse < min(TARGETS) * 0.7:
            break
    return curve


def report(curves: list[Curve], pixels: int, targets: tuple[float, ...] = TARGETS) -> list[dict]:
    rows = []
    for c in curves:
        row = {"renderer": c.renderer, "scene": c.scene, "samples_per_second": c.samples_per_second(pixels),
               "relmse_x_seconds": c.error_times_seconds(),
               "rungs": [vars(r) for r in c.rungs]}
        for t in targets:
            row[f"seconds_to_{t:g}"] = c.time_to(t)
        rows.append(row)
        reached = "  ".join(f"t({t:g})={row[f'seconds_to_{t:g}']:.2f}s" if row[f"seconds_to_{t:g}"] is not None
                            else f"t({t:g})=not reached" for t in targets)
        print(f"{c.renderer:8s} {Path(c.scene).name:20s} {row['samples_per_second'] / 1e6:7.3f} M samples/s  "
              f"{reached}  relMSE*s={row['relmse_x_seconds']:.3g}")
    return rows


def common_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scenes", nargs="+", help="scenes (any format orb-import reads)")
    parser.add_argument("--width", type=int, default=320)
    parser.add_argument("--height", type=int, default=240)
    parser.add_argument("--max-depth", type=int, default=6)
    parser.add_argument("--max-spp", type=int, default=4096, help="last rung of the ladder (default 4096)")
    parser.add_argument("--reference-spp", type=int, default=16384)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--bin", type=Path, default=ROOT / "build" / "bin", help="folder of the Orb tools")
    parser.add_argument("--cache", type=Path,
                        default=Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "orb" / "efficiency")
    parser.add_argument("--json", type=Path, help="write the figures as JSON")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    common_arguments(parser)
    parser.add_argument("--orb-args", default="", help="extra orb-render arguments, e.g. '--device 1'")
    a = parser.parse_args()
    curves = []
    with tempfile.TemporaryDirectory(prefix="orb-efficiency-") as work:
        for scene in a.scenes:
            ref = reference_image(a.bin, scene, a.width, a.height, a.max_depth, a.reference_spp, a.cache)
            curves.append(orb_curve(a.bin, scene, ref, a.width, a.height, a.max_depth, a.max_spp, a.seed,
                                    Path(work), a.orb_args.split()))
    rows = report(curves, a.width * a.height)
    if a.json:
        a.json.write_text(json.dumps(rows, indent=2) + "\n")


if __name__ == "__main__":
    main()
