#!/usr/bin/env python3
"""Where a scene's variance comes from: the relative variance of one sample
with the scene as it is, and with its mirror and glass spheres made diffuse
(one at a time and all together), from each render's variance pass
(docs/rendering.md, "Where the variance is").

    relvar = mean over pixels and channels of var(mean) * spp / (mean^2 + 0.01)

the relMSE one sample per pixel would have, weighted by each render's own
mean (so each variant needs no reference of its own). Needs numpy and the
OpenEXR Python bindings.

  scripts/variance-by-specular.py scenes/cornell.scn --spp 1024
"""
import argparse
import json
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import OpenEXR

ROOT = Path(__file__).resolve().parent.parent


def relvar(path: Path, spp: int) -> float:
    channels = OpenEXR.File(str(path)).channels()
    mean = np.asarray(channels["RGBA"].pixels[..., :3] if "RGBA" in channels else channels["RGB"].pixels, np.float64)
    variance = np.asarray(channels["variance"].pixels[..., :3], np.float64)
    return float(np.mean(variance * spp / (mean * mean + 0.01)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("--spp", type=int, default=1024)
    parser.add_argument("--width", type=int, default=320)
    parser.add_argument("--height", type=int, default=240)
    parser.add_argument("--bin", type=Path, default=ROOT / "build" / "bin")
    a = parser.parse_args()
    scene = json.loads(subprocess.run([str(a.bin / "orb-import"), a.scene], check=True, capture_output=True,
                                      text=True).stdout)
    specular = [i for i, s in enumerate(scene["spheres"])
                if scene["materials"][s["material"]]["type"] in ("mirror", "dielectric")]
    variants = [("as it is", [])] + [(f"sphere {i} diffuse", [i]) for i in specular]
    if len(specular) > 1:
        variants.append(("all specular spheres diffuse", specular))
    with tempfile.TemporaryDirectory(prefix="orb-variance-") as work:
        for label, swap in variants:
            variant = json.loads(json.dumps(scene))
            for i in swap:
                material = {k: v for k, v in variant["materials"][variant["spheres"][i]["material"]].items()
                            if k not in ("ior", "roughness", "metallic")}
                material["type"] = "diffuse"
                variant["materials"].append(material)
                variant["spheres"][i]["material"] = len(variant["materials"]) - 1
            scene_path, image = Path(work) / "scene.json", Path(work) / "render.exr"
            scene_path.write_text(json.dumps(variant))
            subprocess.run([str(a.bin / "orb-render"), str(scene_path), "--width", str(a.width), "--height",
                            str(a.height), "--spp", str(a.spp), "--seed", "3", "--passes", "beauty,variance", "-q",
                            "-o", str(image)], check=True)
            print(f"{label:32s} relative variance of one sample {relvar(image, a.spp):.3f}")


if __name__ == "__main__":
    main()
