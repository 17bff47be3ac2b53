"""The module's core, orb._orb, without OpenImageIO or OpenColorIO: import orb,
rendering and EXR files load neither; orb._image (the display) is imported on
first use, and where it is missing only the display raises, saying so. The
package copy without orb._image and orb/lib is what scripts/gpu-bundle.sh
packs for a bare GPU node."""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import warnings

import pytest

import orb

PACKAGE = pathlib.Path(orb.__file__).parent
IMAGE_LIBRARIES = ("libOpenImageIO", "libOpenColorIO")


def run_python(code, python_path, cwd):
    """`code`'s stdout, run by this interpreter with `python_path` for the package."""
    environment = dict(os.environ, PYTHONPATH=str(python_path), PYTHONDONTWRITEBYTECODE="1")
    done = subprocess.run([sys.executable, "-c", code], env=environment, cwd=cwd, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


# Prints, after each step, which of IMAGE_LIBRARIES the process has mapped.
MAPPED = f"""
def mapped(step):
    with open("/proc/self/maps") as maps:
        text = maps.read()
    print(step, sorted(name for name in {IMAGE_LIBRARIES!r} if name in text))
"""


@pytest.fixture
def core_only(tmp_path):
    """A folder holding the package with the core module alone: no orb._image, no orb/lib."""
    copy = tmp_path / "core" / "orb"
    copy.mkdir(parents=True)
    for path in PACKAGE.iterdir():
        if path.name.startswith("_orb") or path.suffix == ".py":
            shutil.copy(path, copy)
    assert not list(copy.glob("_image*"))
    return copy.parent


def test_the_core_loads_no_image_library_until_the_display_is_used(scenes_dir, tmp_path):
    out = run_python(MAPPED + f"""
import orb
mapped("import")
image = orb.load({str(scenes_dir / "cornell.scn")!r}).render(16, 12, 2)
image.save("render.exr")
image.encode_exr()
mapped("render")
image.to_srgb8()
mapped("display")
""", PACKAGE.parent, tmp_path)
    imported, rendered, displayed = out.splitlines()
    assert imported == "import []" and rendered == "render []"
    assert "'libOpenColorIO'" in displayed  # the display's view (OpenImageIO too where the linker keeps it)
    assert (tmp_path / "render.exr").read_bytes()[:4] == b"\x76\x2f\x31\x01"


def test_without_orb_image_the_display_raises_import_error_naming_it(core_only, scenes_dir, tmp_path):
    out = run_python(MAPPED + f"""
import numpy as np, orb
assert orb.__file__.startswith({str(core_only)!r}), orb.__file__
image = orb.load({str(scenes_dir / "cornell.scn")!r}).render(16, 12, 2)
image.save("render.exr")
assert image.beauty.shape == (12, 16, 4) and np.all(np.isfinite(image.beauty))
for call in (image.to_srgb, image.to_srgb8, image.png, image._repr_png_):
    try:
        call()
    except ImportError as e:
        print(type(e).__name__, e)
    else:
        print("no error from", call.__name__)
mapped("end")
""", core_only, tmp_path)
    lines = out.splitlines()
    assert lines[-1] == "end []"
    assert [line.split(" needs ")[0] for line in lines[:-1]] == [
        "ImportError orb.Image.to_srgb", "ImportError orb.Image.to_srgb8", "ImportError orb.Image.png",
        "ImportError orb.Image.png"]
    for line in lines[:-1]:
        assert "needs orb._image, Orb's display module (OpenImageIO and OpenColorIO), which cannot be imported " \
               "here: cannot import name '_image'" in line
        assert "Image.save (OpenEXR) work without it" in line
    assert (tmp_path / "render.exr").is_file()


def test_textures_load_through_the_tools_decoder_module(data_dir, bin_dir, tmp_path):
    box = data_dir / "gltf-sample-assets/BoxTextured/BoxTextured.glb"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scene = orb.load(box, non_spheres="bound")
    assert any("textures vary over 1 sphere" in str(w.message) for w in caught), [str(w.message) for w in caught]
    subprocess.run([bin_dir / "orb-import", "-q", box, "--non-spheres", "bound", "-o", tmp_path / "tool.json"],
                   check=True)
    scene.save(tmp_path / "python.json")
    assert (tmp_path / "python.json").read_text() == (tmp_path / "tool.json").read_text()


def test_without_the_decoder_module_a_texture_is_a_warning_naming_it(core_only, data_dir, tmp_path):
    box = data_dir / "gltf-sample-assets/BoxTextured/BoxTextured.glb"
    out = run_python(f"""
import json, warnings, orb
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    scene = orb.load({str(box)!r}, non_spheres="bound")
print(json.dumps([str(w.message) for w in caught]))
print(json.dumps(scene.materials))
""", core_only, tmp_path)
    messages, materials = (json.loads(line) for line in out.splitlines())
    decoder = str(core_only / "orb" / "lib" / "orb_texture_decoder.so")
    assert any("textures cannot be decoded here: the texture decoder (OpenImageIO) did not load (" + decoder in m
               for m in messages), messages
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        decoded = orb.load(box, non_spheres="bound")
    assert materials != decoded.materials  # without the texture's mean, the material keeps its factors
