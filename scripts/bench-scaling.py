#!/usr/bin/env python3
"""Cost per sample against sphere count (docs/performance.md, "Many spheres").

Generates the benchmark scenes with scripts/orb-gen.py (fixed seeds, cached
in --work), runs `orb-render --benchmark` on each in interleaved rounds (so a
shared machine's load falls on every size alike), and prints a table of
samples/s and of cost per sample relative to the smallest scene. With --svg
it also draws cost per sample against sphere count on log-log axes.

  scripts/bench-scaling.py                                   # 10 .. 1M at 320x240 on the default device
  scripts/bench-scaling.py --presets 10 1k 100k 1m 10m --width 1920 --height 1080 --orb-args '--device 0'
  scripts/bench-scaling.py --svg docs/images/scaling.svg
"""
from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
COUNTS = {"10": 10, "1k": 1_000, "100k": 100_000, "1m": 1_000_000, "10m": 10_000_000}


def scene_for(preset: str, work: Path) -> Path:
    path = work / f"bench-{preset}.orb"
    if not path.exists():
        subprocess.run([sys.executable, str(ROOT / "scripts" / "orb-gen.py"), "--preset", preset, "-o", str(path)],
                       check=True)
    return path


def benchmark(bin_dir: Path, scene: Path, a: argparse.Namespace) -> tuple[float, int]:
    stats = scene.with_suffix(".stats.json")
    args = [str(bin_dir / "orb-render"), "--benchmark", str(scene), "--width", str(a.width), "--height", str(a.height),
            "--benchmark-seconds", str(a.seconds), "--stats-json", str(stats), "-q"] + a.orb_args.split()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    figures = json.loads(stats.read_text())
    return figures["samples_per_second"], figures["device_memory_bytes"]


def svg_plot(points: list[tuple[int, float]], path: Path, title: str) -> None:
    """Cost per sample (relative to the first point) against sphere count, log-log."""
    w, h, m = 560, 360, 60
    xs = [math.log10(n) for n, _ in points]
    ys = [math.log10(c) for _, c in points]
    x0, x1 = min(xs), max(xs)
    y0, y1 = 0.0, max(1.0, math.ceil(max(ys) * 2) / 2)
    px = lambda x: m + (x - x0) / (x1 - x0 or 1) * (w - 2 * m)
    py = lambda y: h - m - (y - y0) / (y1 - y0) * (h - 2 * m)
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">',
             f'<rect width="{w}" height="{h}" fill="white"/>',
             f'<text x="{w / 2}" y="20" text-anchor="middle" font-size="14">{title}</text>',
             f'<line x1="{m}" y1="{h - m}" x2="{w - m}" y2="{h - m}" stroke="black"/>',
             f'<line x1="{m}" y1="{m}" x2="{m}" y2="{h - m}" stroke="black"/>',
             f'<text x="{w / 2}" y="{h - 15}" text-anchor="middle">spheres</text>',
             f'<text x="15" y="{h / 2}" transform="rotate(-90 15 {h / 2})" text-anchor="middle">'
             f'cost per sample (x the smallest scene)</text>']
    for n, _ in points:
        x = px(math.log10(n))
        parts.append(f'<text x="{x}" y="{h - m + 16}" text-anchor="middle">{n:,}</text>')
    y = y0
    while y <= y1 + 1e-9:
        parts.append(f'<line x1="{m - 4}" y1="{py(y)}" x2="{w - m}" y2="{py(y)}" stroke="#ddd"/>')
        parts.append(f'<text x="{m - 8}" y="{py(y) + 4}" text-anchor="end">{10 ** y:.3g}</text>')
        y += 0.5
    target = py(math.log10(3.0))
    parts.append(f'<line x1="{m}" y1="{target}" x2="{w - m}" y2="{target}" stroke="#c33" stroke-dasharray="5,4"/>')
    parts.append(f'<text x="{w - m}" y="{target - 5}" text-anchor="end" fill="#c33">target 3x</text>')
    line = " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in zip(xs, ys))
    parts.append(f'<polyline points="{line}" fill="none" stroke="#236" stroke-width="2"/>')
    for x, y, (_, c) in zip(xs, ys, points):
        parts.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="4" fill="#236"/>')
        parts.append(f'<text x="{px(x) + 6:.1f}" y="{py(y) - 6:.1f}">{c:.2f}x</text>')
    parts.append("</svg>")
    path.write_text("\n".join(parts) + "\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--presets", nargs="+", default=["10", "1k", "100k", "1m"], choices=list(COUNTS))
    parser.add_argument("--width", type=int, default=320)
    parser.add_argument("--height", type=int, default=240)
    parser.add_argument("--seconds", type=float, default=3.0, help="timed part of each --benchmark run")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--bin", type=Path, default=ROOT / "build" / "bin")
    parser.add_argument("--work", type=Path, default=Path(os.environ.get("TMPDIR", "/tmp")) / "orb-bench-scaling")
    parser.add_argument("--orb-args", default="", help="extra orb-render arguments, e.g. '--device 1'")
    parser.add_argument("--svg", type=Path, help="draw cost per sample against sphere count into this file")
    a = parser.parse_args()
    a.work.mkdir(parents=True, exist_ok=True)
    scenes = {p: scene_for(p, a.work) for p in a.presets}
    rates: dict[str, list[float]] = {p: [] for p in a.presets}
    memory: dict[str, int] = {}
    for _ in range(a.rounds):
        for p in a.presets:
            rate, bytes_on_device = benchmark(a.bin, scenes[p], a)
            rates[p].append(rate)
            memory[p] = bytes_on_device
    best = {p: max(r) for p, r in rates.items()}
    base = best[a.presets[0]]
    print(f"{'spheres':>10} {'samples/s (best of ' + str(a.rounds) + ')':>26} {'all rounds':>36} "
          f"{'cost/sample':>12} {'device MB':>10}")
    for p in a.presets:
        rounds = " ".join(f"{r / 1e6:.3f}M" for r in rates[p])
        print(f"{COUNTS[p]:>10,} {best[p]:>26,.0f} {rounds:>36} {base / best[p]:>11.2f}x {memory[p] / 1e6:>10.1f}")
    if a.svg:
        svg_plot([(COUNTS[p], base / best[p]) for p in a.presets], a.svg,
                 f"Orb: cost per sample against sphere count ({a.width}x{a.height})")


if __name__ == "__main__":
    main()
