#!/usr/bin/env python3
"""orb-gen: benchmark scenes of random spheres, as a PLY point cloud or a binary Orb scene.

    scripts/orb-gen.py --preset 1m -o random-1m.orb      1,000,000 spheres, seed 1
    scripts/orb-gen.py --count 5000 --seed 7 -o r.ply    any count, any seed

Spheres are placed uniformly in a box 100 wide, 50 high and 100 deep resting on
a floor at y = 0, with radii of about a third of the mean spacing, coloured from
a palette of 64 colours. The .orb form also holds the floor (a sphere of radius
1e5), the two lights orb-import gives a point cloud and a camera; the PLY form
holds the points only, and orb-import adds its automatic camera and those
lights (docs/orb-import.md). The same count and seed always give the same file.
Standard library only. Documented in scenes/README.md.
"""
import argparse
import array
import json
import math
import os
import random
import struct
import subprocess
import sys
import textwrap

PRESETS = {"10": 10, "1k": 1_000, "100k": 100_000, "1m": 1_000_000, "10m": 10_000_000}
BOX = ((-50.0, 50.0), (0.0, 50.0), (-50.0, 50.0))
PALETTE_SIZE = 64
MAGIC = b"\x89ORB\r\n\x1a\n"  # docs/scene-format.md, "Binary form"
# Name, radiance and direction from the box's centre of each light: orb-import's
# default lights (libimport/src/default_lights.cpp). A sphere of radiance L seen at
# sin(theta) = 1/4 gives E = pi*L/16: an irradiance of 0.8*pi (key) and 0.3*pi (fill).
LIGHTS = (("key light", 0.8 * 16, (-1.0, 2.0, 1.0)), ("fill light", 0.3 * 16, (1.0, 0.5, 0.5)))


def palette(rng):
    """64 fixed colours as sRGB bytes (for PLY) and linear reflectance (for .orb)."""
    colours = []
    for _ in range(PALETTE_SIZE):
        srgb = [rng.randrange(40, 240) for _ in range(3)]
        colours.append(srgb)
    return colours


def srgb_to_linear(byte):
    c = byte / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def random_spheres(count, seed):
    """Centres (flat x,y,z list), radii and palette indices, reproducible from the seed."""
    rng = random.Random(seed)
    colours = palette(rng)
    volume = 1.0
    for low, high in BOX:
        volume *= high - low
    radius = 0.35 * (volume / max(count, 1)) ** (1.0 / 3.0)
    centers = array.array("d")
    radii = array.array("d")
    indices = array.array("I")
    (x0, x1), (y0, y1), (z0, z1) = BOX
    uniform = rng.random
    for _ in range(count):
        r = radius * (0.5 + uniform())
        centers.extend((x0 + (x1 - x0) * uniform(), y0 + r + (y1 - y0 - r) * uniform(), z0 + (z1 - z0) * uniform()))
        radii.append(r)
        indices.append(rng.randrange(PALETTE_SIZE))
    return colours, centers, radii, indices


def write_ply(out, colours, centers, radii, indices):
    count = len(radii)
    header = (
        "ply\nformat binary_little_endian 1.0\ncomment orb-gen random spheres\n"
        f"element vertex {count}\nproperty float x\nproperty float y\nproperty float z\nproperty float radius\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
    )
    out.write(header.encode("ascii"))
    row = struct.Struct("<ffffBBB")
    chunk = bytearray()
    for i in range(count):
        c = colours[indices[i]]
        chunk += row.pack(centers[3 * i], centers[3 * i + 1], centers[3 * i + 2], radii[i], c[0], c[1], c[2])
        if len(chunk) > 1 << 22:
            out.write(chunk)
            chunk = bytearray()
    out.write(chunk)


def scene_header(colours, count):
    """Everything but the spheres' arrays: the canonical JSON scene without spheres."""
    materials = [
        {"name": "colour %d" % i, "type": "diffuse", "color": [srgb_to_linear(v) for v in c],
         "emission": [0, 0, 0], "ior": 1.5}
        for i, c in enumerate(colours)
    ]
    materials.append({"name": "floor", "type": "diffuse", "color": [0.5, 0.5, 0.5], "emission": [0, 0, 0], "ior": 1.5})
    for name, radiance, _ in LIGHTS:
        materials.append({"name": name, "type": "diffuse", "color": [0, 0, 0], "emission": [radiance] * 3, "ior": 1.5})
    scene = {
        "format": "orb-scene", "version": 1,
        "camera": {"position": [0, 70, 170], "target": [0, 15, 0], "up": [0, 1, 0],
                   "vfov_deg": 42.87978100351012, "aperture": 0, "focus_distance": 1},
        "render": {"width": 640, "height": 480, "spp": 64, "max_depth": 6},
        "materials": materials, "spheres": [],
    }
    return {"format": "orb-scene-binary", "version": 1, "sphere_count": count,
            "sphere_names": False, "scene": scene}


def light_spheres():
    """The two lights orb-import gives a point cloud (docs/orb-import.md): a key
    light from the upper left and a fill light from the right, 4R from the box's
    centre, R (their radius) half its diagonal, out of the camera's view. They
    light the faces the camera sees, as the .ply form of the same cloud is lit."""
    center = [(low + high) / 2 for low, high in BOX]
    radius = math.sqrt(sum((high - low) ** 2 for low, high in BOX)) / 2
    spheres = []
    for k, (_, _, direction) in enumerate(LIGHTS):
        length = math.sqrt(sum(d * d for d in direction))
        spheres.append((tuple(c + d / length * 4 * radius for c, d in zip(center, direction)), radius,
                        PALETTE_SIZE + 1 + k))
    return spheres


def write_orb(out, colours, centers, radii, indices):
    floor_material = PALETTE_SIZE
    # The floor and the two lights follow the random spheres.
    extra = [((0.0, -1e5, 0.0), 1e5, floor_material)] + light_spheres()
    centers = array.array("d", centers)
    radii = array.array("d", radii)
    indices = array.array("I", indices)
    for center, radius, material in extra:
        centers.extend(center)
        radii.append(radius)
        indices.append(material)
    header = json.dumps(scene_header(colours, len(radii)), separators=(",", ":")).encode("utf-8")
    preamble = MAGIC + struct.pack("<II", 1, len(header))
    out.write(preamble + header + b"\0" * ((8 - (len(preamble) + len(header)) % 8) % 8))
    if sys.byteorder != "little":
        for column in (centers, radii, indices):
            column.byteswap()
    assert indices.itemsize == 4
    for column in (centers, radii, indices):
        out.write(column.tobytes())


class OrbHelp(argparse.HelpFormatter):
    """--help in the shape of every Orb tool's ("Usage:", as the man page and
    bash completion made from it expect: packaging/cli_reference.py), wrapped
    to the terminal's width (80 when not a terminal): prose line by line, an
    example (an indented line) kept whole."""

    def add_usage(self, usage, actions, groups, prefix=None):
        super().add_usage(usage, actions, groups, prefix="Usage: ")

    def _fill_text(self, text, width, indent):
        lines = []
        for line in text.splitlines():
            lines.extend([line] if line.startswith("  ") or len(line) <= width else textwrap.wrap(line, width))
        return "\n".join(indent + line for line in lines)


class VersionAction(argparse.Action):
    """--version: orb-gen's version, and the revision and libraries of the build
    it came with, as the orb-render beside it (installed, or in a build's bin/)
    says them; asked only when --version is given."""

    def __init__(self, option_strings, dest, **kwargs):
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS, **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        print(version_text())
        parser.exit()


def version_text():
    here = os.path.dirname(os.path.realpath(sys.argv[0]))
    render = os.path.join(here, "orb-render")
    if os.access(render, os.X_OK):
        lines = subprocess.run([render, "--version"], capture_output=True, text=True, check=False).stdout.splitlines()
        if lines and lines[0].startswith("orb-render (Orb) "):
            return "\n".join(["orb-gen (Orb) " + lines[0].split()[-1]] + lines[1:])
    return "orb-gen (Orb) unknown\nrevision: unknown (no orb-render beside orb-gen in %s)" % here


EXAMPLES = """Examples:
  orb-gen --preset 1m -o random-1m.orb
      1,000,000 spheres, seed 1
  orb-gen --count 5000 --seed 7 -o r.ply
      any count, any seed, as PLY
  orb-gen --preset 100k -o c.orb
  orb-render c.orb --spp 16 -o c.exr

From a clone it is scripts/orb-gen.py; the package installs it as orb-gen. Details: scenes/README.md.

Exit status: 0 success, 1 failure, 2 usage error."""


def main():
    description = __doc__.split("\n")[0].removeprefix("orb-gen: ")
    parser = argparse.ArgumentParser(prog="orb-gen", description=description[:1].upper() + description[1:],
                                     epilog=EXAMPLES, formatter_class=OrbHelp)
    size = parser.add_mutually_exclusive_group(required=True)
    size.add_argument("--preset", choices=PRESETS, metavar="|".join(PRESETS),
                      help="10, 1k, 100k, 1m or 10m spheres")
    size.add_argument("--count", type=int, metavar="N", help="number of random spheres")
    parser.add_argument("--seed", type=int, default=1, metavar="N", help="random seed (default 1)")
    parser.add_argument("--format", choices=("ply", "orb"), metavar="ply|orb", help="default: from the -o extension")
    parser.add_argument("-o", "--output", required=True, metavar="FILE", help="file to write (.ply or .orb)")
    parser.add_argument("--version", action=VersionAction,
                        help="the version, and the revision and libraries of the build it came with")
    args = parser.parse_args()
    count = PRESETS[args.preset] if args.preset else args.count
    if count < 0:
        parser.error("--count must be >= 0")
    fmt = args.format or ("ply" if args.output.endswith(".ply") else "orb" if args.output.endswith(".orb") else None)
    if fmt is None:
        parser.error("name the output .ply or .orb, or pass --format")
    colours, centers, radii, indices = random_spheres(count, args.seed)
    # Written to a temporary name and renamed, so an interrupted run leaves no half file.
    temporary = args.output + ".orb-gen-partial"
    with open(temporary, "wb") as out:
        (write_ply if fmt == "ply" else write_orb)(out, colours, centers, radii, indices)
    os.replace(temporary, args.output)


if __name__ == "__main__":
    main()
