#!/usr/bin/env python3
"""Two benchmark scenes that differ only in how many spheres emit
(docs/performance.md, "What affects speed"):
10,000 small random spheres over a floor, of which 10 or all 10,000 glow.
Same geometry, so the difference in cost per sample is the lights' alone.

  scripts/gen-many-lights.py OUT_DIR      # writes lights10.json and lights10000.json
"""
import json
import random
import sys
from pathlib import Path


def scene(emitters: int, spheres: int = 10_000, seed: int = 3) -> dict:
    rnd = random.Random(seed)
    materials = [
        {"name": "grey", "type": "diffuse", "color": [0.6, 0.6, 0.6], "emission": [0, 0, 0], "ior": 1.5},
        {"name": "floor", "type": "diffuse", "color": [0.5, 0.5, 0.5], "emission": [0, 0, 0], "ior": 1.5},
        {"name": "glow", "type": "diffuse", "color": [0, 0, 0], "emission": [20, 18, 15], "ior": 1.5},
    ]
    placed = [{"center": [0, -1e4, 0], "radius": 1e4, "material": 1}]
    for i in range(spheres):
        placed.append({"center": [rnd.uniform(-20, 20), rnd.uniform(0.5, 10), rnd.uniform(-20, 20)],
                       "radius": rnd.uniform(0.05, 0.3), "material": 2 if i < emitters else 0})
    return {"format": "orb-scene", "version": 1,
            "camera": {"position": [0, 15, 45], "target": [0, 3, 0], "up": [0, 1, 0], "vfov_deg": 40,
                       "aperture": 0, "focus_distance": 1},
            "render": {"width": 320, "height": 240, "spp": 16, "max_depth": 6},
            "materials": materials, "spheres": placed}


if __name__ == "__main__":
    out = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    out.mkdir(parents=True, exist_ok=True)
    for emitters in (10, 10_000):
        (out / f"lights{emitters}.json").write_text(json.dumps(scene(emitters)) + "\n")
