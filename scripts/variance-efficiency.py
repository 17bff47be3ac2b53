#!/usr/bin/env python3
"""Time to equal error from one render's variance pass, for comparing kernel variants.

For each variant (LABEL=OPENCL_OPTIONS, passed to the kernels through the
development knob ORB_CL_OPTIONS; later -D options override the defaults):
renders SCENE at 320x240 with SPP samples and the variance pass, and turns the
variance of every pixel mean into the relative variance of one sample,
    relvar = mean over pixels and channels of  var(mean) * spp / (ref^2 + 0.01),
the relMSE one sample per pixel would have (orb-diff's relMSE weighting). The
reference REF is a converged render of the scene (its mean only). Then times
the variant with orb-render-benchmark in samples per CPU-second (stable on a
shared machine, unlike wall-clock), ROUNDS interleaved rounds, median, and
prints the CPU-seconds to reach relMSE 0.001 at 320x240:
    relvar * pixels / (samples per CPU-second * 0.001).
On an idle machine wall-clock time is that divided by the core count.

Needs numpy and the OpenEXR Python bindings (pip install numpy OpenEXR).

  scripts/variance-efficiency.py REF.exr scenes/cornell.scn 256 3 \\
      "T1=-DRR_THRESHOLD=1.0f" "T0.25=-DRR_THRESHOLD=0.25f"
"""
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import OpenEXR

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(os.environ.get("ORB_BIN", ROOT / "build" / "bin"))
WIDTH, HEIGHT = 320, 240


def load(path, with_variance):
    channels = OpenEXR.File(str(path)).parts[0].channels
    rgb = channels["RGBA"].pixels[..., :3] if "RGBA" in channels else channels["RGB"].pixels
    variance = channels["variance"].pixels[..., :3] if with_variance else None
    return np.asarray(rgb, np.float64), (None if variance is None else np.asarray(variance, np.float64))


def main():
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    reference, scene, spp, rounds = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    variants = [argument.split("=", 1) for argument in sys.argv[5:]]
    ref = load(reference, False)[0]
    results = {}
    for label, options in variants:
        env = dict(os.environ, ORB_CL_OPTIONS=options)
        out = Path(f"/tmp/variance-efficiency-{os.getpid()}-{label}.exr")
        subprocess.run([str(BIN / "orb-render"), scene, "--width", str(WIDTH), "--height", str(HEIGHT), "--spp",
                        str(spp), "--seed", "3", "--passes", "beauty,variance", "-q", "-o", str(out)], env=env,
                       check=True)
        mean, variance = load(out, True)
        out.unlink()
        results[label] = {"relvar": float((variance * spp / (ref ** 2 + 0.01)).mean()),
                          "relmse": float((((mean - ref) ** 2) / (ref ** 2 + 0.01)).mean()), "rates": []}
    for _ in range(rounds):
        for label, options in variants:
            env = dict(os.environ, ORB_CL_OPTIONS=options)
            text = subprocess.run([str(BIN / "orb-render-benchmark"), scene, "--width", str(WIDTH), "--height",
                                   str(HEIGHT), "--cpu-spp", "16", "--pass-spp", "2"], env=env, check=True,
                                  capture_output=True, text=True).stdout
            results[label]["rates"].append(float(text.strip().split("=")[-1]))
    for label, r in results.items():
        rate = float(np.median(r["rates"]))
        cpu_seconds = r["relvar"] * WIDTH * HEIGHT / (rate * 0.001)
        print(f"{label:12s} relvar/sample {r['relvar']:.4f}  relMSE@{spp}spp {r['relmse']:.2e}  "
              f"samples/CPU-s {rate:,.0f}  CPU-s to relMSE 0.001: {cpu_seconds:.1f}")


if __name__ == "__main__":
    main()
