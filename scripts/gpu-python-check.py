#!/usr/bin/env python3
"""Checks Orb's Python module on a GPU node against orb-render (docs/python.md,
"On a machine without OpenImageIO").

On the node, with the bundle that scripts/gpu-bundle.sh made with ORB_PYTHON_BUNDLE:

    source scripts/gpu-node-env.sh .gpu      # PYTHONPATH, numpy, the NVIDIA ICD
    python3.12 scripts/gpu-python-check.py   # --device nvidia when there is one

It prints orb.devices(); renders scenes/cornell.scn at 320x240, 16 spp, seed 0
from Python and saves the EXR; runs the bundle's orb-render with the same
settings (--compression none) and compares the two images channel by channel,
bit for bit (PASS/FAIL, the largest difference); then times a 1920x1080 16-spp
render from Python against the CLI's. Exit status 0 on PASS, 1 on FAIL.
The EXR files are read here (uncompressed, ZIP or ZIPS scanlines, what Orb
writes) so that the check needs nothing the node lacks.
"""
import argparse
import json
import os
import pathlib
import struct
import subprocess
import sys
import tempfile
import time
import zlib

import numpy as np

import orb

ROOT = pathlib.Path(__file__).resolve().parents[1]
PIXEL_TYPES = {0: np.dtype("<u4"), 1: np.dtype("<f2"), 2: np.dtype("<f4")}
LINES_PER_CHUNK = {0: 1, 2: 1, 3: 16}  # NONE, ZIPS, ZIP: the compressions read here


def exr_channels(path):
    """{channel name: (H, W) array} of a single-part scanline EXR file."""
    data = pathlib.Path(path).read_bytes()
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError(f"{path}: not an OpenEXR file")
    position, attributes = 8, {}
    while data[position] != 0:
        name_end = data.index(b"\0", position)
        type_end = data.index(b"\0", name_end + 1)
        (size,) = struct.unpack_from("<i", data, type_end + 1)
        attributes[data[position:name_end].decode()] = data[type_end + 5:type_end + 5 + size]
        position = type_end + 5 + size
    channels, listed = [], attributes["channels"]
    while listed[0] != 0:
        name_end = listed.index(b"\0")
        (pixel_type,) = struct.unpack_from("<i", listed, name_end + 1)
        channels.append((listed[:name_end].decode(), PIXEL_TYPES[pixel_type]))
        listed = listed[name_end + 17:]
    compression = attributes["compression"][0]
    if compression not in LINES_PER_CHUNK:
        raise ValueError(f"{path}: compression {compression} is not read here (NONE, ZIP, ZIPS are)")
    x0, y0, x1, y1 = struct.unpack("<4i", attributes["dataWindow"])
    width, height = x1 - x0 + 1, y1 - y0 + 1
    lines = LINES_PER_CHUNK[compression]
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{chunks}Q", data, position + 1)
    planes = {name: np.empty((height, width), dtype) for name, dtype in channels}
    for offset in offsets:
        y, packed_size = struct.unpack_from("<ii", data, offset)
        rows = min(lines, y1 + 1 - y)
        expected = rows * width * sum(dtype.itemsize for _, dtype in channels)
        block = data[offset + 8:offset + 8 + packed_size]
        if compression != 0 and packed_size < expected:
            block = _unzip(block)
        at = 0
        for row in range(rows):
            for name, dtype in channels:
                count = width * dtype.itemsize
                planes[name][y - y0 + row] = np.frombuffer(block, dtype, width, at)
                at += count
    return planes


def _unzip(block):
    """OpenEXR's ZIP block: zlib, then its byte predictor (each byte the previous
    plus it, minus 128) and its interleave (even bytes first) undone."""
    t = np.frombuffer(zlib.decompress(block), np.uint8).astype(np.int64)
    t[1:] -= 128
    t = (np.cumsum(t) % 256).astype(np.uint8)
    half = (t.size + 1) // 2
    out = np.empty_like(t)
    out[0::2], out[1::2] = t[:half], t[half:]
    return out.tobytes()


def compare(python_planes, cli_planes):
    """(same, largest absolute difference, differing values) over every channel of both."""
    if python_planes.keys() != cli_planes.keys():
        print(f"  channels differ: Python {sorted(python_planes)}, CLI {sorted(cli_planes)}")
        return False, float("inf"), -1
    largest, differing = 0.0, 0
    for name in sorted(cli_planes):
        a, b = python_planes[name], cli_planes[name]
        if a.shape != b.shape:
            print(f"  {name}: shape {a.shape} against {b.shape}")
            return False, float("inf"), -1
        bits_differ = a.view(f"u{a.dtype.itemsize}") != b.view(f"u{b.dtype.itemsize}")
        differing += int(np.count_nonzero(bits_differ))
        if bits_differ.any():
            largest = max(largest, float(np.nanmax(np.abs(a.astype(np.float64) - b.astype(np.float64)))))
    return differing == 0, largest, differing


def default_device():
    """"nvidia" where an NVIDIA device is listed, as orb-render --device nvidia picks it, else the default."""
    for device in orb.devices():
        if "nvidia" in (device["name"] + device["platform"] + device["vendor"]).lower():
            return "nvidia"
    return "default"


def default_orb_render():
    """The bundle's orb-render (the module lies in BUNDLE/python/orb), else $ORB_BIN_DIR's, else the build's."""
    candidates = [pathlib.Path(orb.__file__).resolve().parents[2] / "orb-render"]
    if os.environ.get("ORB_BIN_DIR"):
        candidates.insert(0, pathlib.Path(os.environ["ORB_BIN_DIR"]) / "orb-render")
    candidates.append(ROOT / "build" / "bin" / "orb-render")
    for candidate in candidates:
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate
    sys.exit("gpu-python-check.py: no orb-render found (tried " + ", ".join(map(str, candidates)) +
             "); give --orb-render PATH")


def run_cli(orb_render, scene, width, height, spp, device, output, stats):
    command = [str(orb_render), "-q", str(scene), "--width", str(width), "--height", str(height), "--spp", str(spp),
               "--seed", "0", "--compression", "none", "-o", str(output), "--stats-json", str(stats)]
    if device != "default":  # Python's name for the choice orb-render makes without --device
        command += ["--device", device]
    started = time.perf_counter()
    subprocess.run(command, check=True)
    return time.perf_counter() - started, json.loads(pathlib.Path(stats).read_text())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--device", help="render device (default: nvidia where there is one, else Orb's default)")
    parser.add_argument("--orb-render", type=pathlib.Path, help="the CLI to compare with (default: the bundle's)")
    parser.add_argument("--out", type=pathlib.Path,
                        default=pathlib.Path(os.environ.get("OUT") or "/tmp/orb-python-check"),
                        help="folder for the EXR files (default: $OUT, else /tmp/orb-python-check)")
    parser.add_argument("--timing-size", default="1920x1080", help="WxH of the timed render (default 1920x1080)")
    parser.add_argument("--timing-spp", type=int, default=16, help="its samples per pixel (default 16)")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    scene_path = ROOT / "scenes" / "cornell.scn"

    print(f"python {sys.version.split()[0]} ({sys.executable}), numpy {np.__version__} ({np.__file__})")
    print(f"orb {orb.__file__}")
    print(f"orb._image loaded at import: {'orb._image' in sys.modules}")
    print("orb.devices():")
    for device in orb.devices():
        print(f"  {device}")
    device = args.device or default_device()
    orb_render = args.orb_render or default_orb_render()
    print(f"device: {device}; orb-render: {orb_render}")

    scene = orb.load(scene_path)
    started = time.perf_counter()
    image = scene.render(320, 240, 16, seed=0, device=device)
    print(f"python 320x240 16 spp: {time.perf_counter() - started:.3f} s on {image.device}")
    image.save(args.out / "python.exr")
    cli_seconds, cli_stats = run_cli(orb_render, scene_path, 320, 240, 16, device, args.out / "cli.exr",
                                     args.out / "cli-stats.json")
    print(f"cli    320x240 16 spp: {cli_seconds:.3f} s on {cli_stats['device']['name']}")

    cli_planes = exr_channels(args.out / "cli.exr")
    same_file, file_largest, file_differing = compare(exr_channels(args.out / "python.exr"), cli_planes)
    in_memory = {name: image.beauty[..., i] for i, name in enumerate(image.channels("beauty"))}
    same_memory, memory_largest, memory_differing = compare(in_memory, cli_planes)
    passed = same_file and same_memory
    print(f"python.exr against cli.exr: {file_differing} values differ, max difference {file_largest:g}")
    print(f"image.beauty against cli.exr: {memory_differing} values differ, max difference {memory_largest:g}")
    print("PASS" if passed else "FAIL")

    width, height = (int(v) for v in args.timing_size.lower().split("x"))
    started = time.perf_counter()
    timed = scene.render(width, height, args.timing_spp, seed=0, device=device)
    python_seconds = time.perf_counter() - started
    with tempfile.TemporaryDirectory() as scratch:  # a large file nobody compares
        cli_seconds, cli_stats = run_cli(orb_render, scene_path, width, height, args.timing_spp, device,
                                         pathlib.Path(scratch) / "cli-timed.exr", args.out / "cli-timed-stats.json")
    print(f"timing {width}x{height} {args.timing_spp} spp on {timed.device}:")
    print(f"  python: render() {python_seconds:.3f} s (its render_seconds {timed.render_seconds:.3f})")
    print(f"  cli:    process {cli_seconds:.3f} s (startup_seconds {cli_stats.get('startup_seconds', 0):.3f}, "
          f"setup_seconds {cli_stats.get('setup_seconds', 0):.3f}, seconds {cli_stats['seconds']:.3f})")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
