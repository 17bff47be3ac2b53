#!/usr/bin/env python3
"""Writes scenes/bounce.gltf, the tutorial's animated example (Python standard library only).

Usage: scripts/make-bounce-gltf.py [OUTPUT]   (default: scenes/bounce.gltf next to this script)

A red ball bounces twice across a grey floor in two seconds (49 keyframes,
one per 1/24 s, so every frame at 24 fps lands on a key), next to a still
mirror ball, under one spherical lamp. One self-contained .gltf: the buffer is
a data: URI. Running the script again writes the same bytes.
"""
import base64
import json
import math
import os
import struct
import sys

FLOAT, USHORT = 5126, 5123
FPS, SECONDS = 24, 2
BALL_RADIUS, BOUNCE_HEIGHT = 0.5, 1.2


def uv_sphere(segments=32, rings=16):
    """A closed unit UV sphere: two poles plus (rings - 1) rings of `segments` vertices."""
    points = [(0.0, 1.0, 0.0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            points.append((math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)))
    points.append((0.0, -1.0, 0.0))
    south = len(points) - 1
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments
    indices = []
    for s in range(segments):
        indices += [0, ring(1, s + 1), ring(1, s), south, ring(rings - 1, s), ring(rings - 1, s + 1)]
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b, c, d = ring(r, s), ring(r, s + 1), ring(r + 1, s), ring(r + 1, s + 1)
            indices += [a, b, d, a, d, c]
    return points, indices


def ball_position(t):
    """Two parabolic hops from x = -1.5 to x = 1.5: on the floor at t = 0, 1, 2 s."""
    phase = t % 1.0
    height = BOUNCE_HEIGHT * 4 * phase * (1 - phase)
    return (-1.5 + 1.5 * t, BALL_RADIUS + height, 0.0)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "scenes", "bounce.gltf")
    blob = bytearray()
    views, accessors = [], []

    def accessor(values, fmt, component, type_, count, minmax=None):
        while len(blob) % 4:
            blob.append(0)
        offset = len(blob)
        blob.extend(struct.pack("<%d%s" % (len(values), fmt), *values))
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset})
        acc = {"bufferView": len(views) - 1, "componentType": component, "count": count, "type": type_}
        if minmax:
            acc["min"], acc["max"] = minmax
        accessors.append(acc)
        return len(accessors) - 1

    points, indices = uv_sphere()
    position = accessor([c for p in points for c in p], "f", FLOAT, "VEC3", len(points),
                        ([min(p[i] for p in points) for i in range(3)], [max(p[i] for p in points) for i in range(3)]))
    index = accessor(indices, "H", USHORT, "SCALAR", len(indices))
    times = [k / FPS for k in range(FPS * SECONDS + 1)]
    key_times = accessor(times, "f", FLOAT, "SCALAR", len(times), ([times[0]], [times[-1]]))
    key_positions = accessor([c for t in times for c in ball_position(t)], "f", FLOAT, "VEC3", len(times))

    materials = [
        {"name": "Floor", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.7, 0.7, 1], "metallicFactor": 0}},
        {"name": "Red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.08, 1], "metallicFactor": 0}},
        {"name": "Mirror", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1], "metallicFactor": 1,
                                               "roughnessFactor": 0}},
        {"name": "Lamp", "emissiveFactor": [1, 0.9, 0.8],
         "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 12}},
         "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0}},
    ]
    meshes = [{"name": m["name"], "primitives": [{"attributes": {"POSITION": position}, "indices": index, "material": i}]}
              for i, m in enumerate(materials)]
    tilt = math.radians(-10) / 2  # the camera looks 10 degrees down
    nodes = [
        {"name": "Floor", "mesh": 0, "translation": [0, -1000, 0], "scale": [1000, 1000, 1000]},
        {"name": "Ball", "mesh": 1, "translation": list(ball_position(0)), "scale": [BALL_RADIUS] * 3},
        {"name": "MirrorBall", "mesh": 2, "translation": [0.9, 0.7, -1.6], "scale": [0.7] * 3},
        {"name": "Lamp", "mesh": 3, "translation": [-1.5, 5, 2], "scale": [0.8] * 3},
        {"name": "Camera", "camera": 0, "translation": [0, 1.6, 6.5],
         "rotation": [math.sin(tilt), 0, 0, math.cos(tilt)]},
    ]
    gltf = {
        "asset": {"version": "2.0", "generator": "orb scripts/make-bounce-gltf.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "Bounce", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"name": "Camera", "type": "perspective",
                     "perspective": {"yfov": math.radians(40), "aspectRatio": 4 / 3, "znear": 0.1}}],
        "meshes": meshes,
        "materials": materials,
        "animations": [{"name": "Bounce",
                        "samplers": [{"input": key_times, "output": key_positions, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}]}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
