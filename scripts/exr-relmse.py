#!/usr/bin/env python3
"""relMSE of EXR images against a reference, where orb-diff is not installed.

The lent GPU nodes have Python with numpy but not OpenImageIO, so orb-diff
(libimage) does not run there. This computes orb-diff's relMSE of the
beauty layer's R, G and B (libimage/src/metrics.cpp: the mean over every pixel and
channel of d^2 / (r^2 + 0.01), a non-finite reference value counted as 0)
with the OpenEXR Python module, so that a run on a node can score its own
images and send back figures instead of images. Checked against orb-diff on
the development machine (docs/performance.md, "Time to equal error on the
GPU, measured").

  exr-relmse.py REFERENCE.exr IMAGE.exr [IMAGE.exr ...]   # prints "IMAGE relmse" lines
"""
import sys

import numpy as np
import OpenEXR

EPSILON = 0.01  # kRelMseEpsilon in libimage


def beauty(path: str) -> np.ndarray:
    with OpenEXR.File(path, separate_channels=True) as f:
        channels = f.channels()
        # The unprefixed layer is the beauty; orb-diff compares its colour, not its alpha.
        names = [n for n in ("R", "G", "B") if n in channels]
        if not names:
            sys.exit(f"exr-relmse: {path}: no beauty channels")
        return np.stack([np.asarray(channels[n].pixels, dtype=np.float64) for n in names])


def relmse(reference: np.ndarray, image: np.ndarray) -> float:
    if reference.shape != image.shape:
        sys.exit("exr-relmse: images of different shapes")
    d = np.abs(image - reference)
    d[reference == image] = 0.0  # equal values, equal infinities included, are no error
    d[np.isnan(reference) | np.isnan(image)] = np.inf
    r = np.where(np.isfinite(reference), reference, 0.0)
    return float(np.mean(d * d / (r * r + EPSILON)))


def main() -> None:
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    reference = beauty(sys.argv[1])
    for path in sys.argv[2:]:
        print(path, repr(relmse(reference, beauty(path))))


if __name__ == "__main__":
    main()
