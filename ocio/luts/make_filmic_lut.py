#!/usr/bin/env python3
"""Writes orb_filmic.spi1d, the tone curve of Orb's "Filmic" view.

The LUT is indexed by a log2 shaper (the config's AllocationTransform:
t = (log2(x + 2^-12) + 12) / 20, i.e. 20 stops from ~2^-12 to 2^8) and returns
display-linear values. The curve is the identity up to 0.5 (mid-tones keep
their exposure and colour) and then a rational shoulder that is C1-continuous
at the splice and approaches white only at 2^8, so highlights roll off softly
instead of clipping at 1.0. Rerun this script after changing the curve.
"""
import os

LOG_MIN, LOG_MAX, OFFSET = -12.0, 8.0, 2.0 ** -12
LENGTH = 4096
SHOULDER_START = 0.5


def curve(x):
    if x <= SHOULDER_START:
        return max(x, 0.0)
    u = (x - SHOULDER_START) / (1.0 - SHOULDER_START)
    return SHOULDER_START + (1.0 - SHOULDER_START) * u / (1.0 + u)


def main():
    top = curve(2.0 ** LOG_MAX - OFFSET)
    lines = ["Version 1", "From 0.0 1.0", "Length %d" % LENGTH, "Components 1", "{"]
    for i in range(LENGTH):
        t = i / (LENGTH - 1)
        x = 2.0 ** (LOG_MIN + t * (LOG_MAX - LOG_MIN)) - OFFSET
        lines.append("    %.8f" % (curve(x) / top))
    lines.append("}")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "orb_filmic.spi1d")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
