"""Scene.render: the render-job library's still, bit for bit orb-render's, its layers as numpy arrays."""
import os
import signal
import struct
import subprocess
import threading

import numpy as np
import pytest

import orb

# Attributes that say when, where and from what file a render ran: the only
# ones in which Python's EXR and orb-render's of the same render may differ.
RUN_ATTRIBUTES = {b"orb:renderSeconds", b"orb:device", b"orb:sceneFile"}


def exr_parts(data):
    """(attributes other than RUN_ATTRIBUTES, chunk offsets relative to the first, the chunks' bytes)."""
    position, attributes = 8, {}
    while data[position] != 0:
        name_end = data.index(b"\0", position)
        type_end = data.index(b"\0", name_end + 1)
        (size,) = struct.unpack_from("<i", data, type_end + 1)
        name = data[position:name_end]
        if name not in RUN_ATTRIBUTES:
            attributes[name] = data[name_end:type_end + 5 + size]
        position = type_end + 5 + size
    header_end = position + 1
    (first,) = struct.unpack_from("<Q", data, header_end)
    count = (first - header_end) // 8
    offsets = [o - first for o in struct.unpack_from("<%dQ" % count, data, header_end)]
    return attributes, offsets, data[first:]


@pytest.fixture
def cornell(scenes_dir):
    return orb.load(scenes_dir / "cornell.scn")


def test_render_is_orb_renders_image_bit_for_bit(cornell, bin_dir, tmp_path):
    image = cornell.render(32, 24, 8, seed=5, passes=("beauty", "albedo", "normal"))
    image.save(tmp_path / "python.exr")
    cornell.save(tmp_path / "cornell.orb")
    subprocess.run([bin_dir / "orb-render", "-q", tmp_path / "cornell.orb", "--width", "32", "--height", "24",
                    "--spp", "8", "--seed", "5", "--passes", "beauty,albedo,normal", "-o", tmp_path / "tool.exr"],
                   check=True)
    python, tool = (tmp_path / "python.exr").read_bytes(), (tmp_path / "tool.exr").read_bytes()
    (python_attributes, *python_pixels), (tool_attributes, *tool_pixels) = exr_parts(python), exr_parts(tool)
    differing = {name: (python_attributes.get(name), tool_attributes.get(name))
                 for name in python_attributes.keys() | tool_attributes.keys()
                 if python_attributes.get(name) != tool_attributes.get(name)}
    assert not differing, differing
    assert python_pixels == tool_pixels
    assert image.encode_exr()[:8] == python[:8]


def test_layers_are_float32_arrays_sharing_the_images_memory(cornell):
    image = cornell.render(16, 12, 2, passes=["beauty", "albedo", "depth"])
    assert image.layer_names == ["beauty", "albedo", "depth"]
    beauty = image.beauty
    assert beauty.shape == (12, 16, 4) and beauty.dtype == np.float32 and not beauty.flags.owndata
    assert image["albedo"].shape == (12, 16, 3) and image.depth.shape == (12, 16, 1)
    assert image.channels("albedo") == ["albedo.R", "albedo.G", "albedo.B"]
    # the same memory each time, kept alive by the array after the image is gone
    assert np.shares_memory(image.beauty, beauty)
    del image
    assert np.all(np.isfinite(beauty)) and beauty[..., :3].max() > 0
    with pytest.raises(KeyError, match="no layer 'variance'"):
        cornell.render(4, 4, 1)["variance"]


def test_same_seed_same_pixels_other_seed_other_pixels(cornell):
    a, b, c = (cornell.render(16, 12, 2, seed=s).beauty for s in (1, 1, 2))
    assert np.array_equal(a, b) and not np.array_equal(a, c)


def test_to_srgb8_is_orb_tonemaps_image(cornell, bin_dir, tmp_path):
    image = cornell.render(16, 12, 2)
    image.save(tmp_path / "render.exr")
    subprocess.run([bin_dir / "orb-tonemap", "-q", tmp_path / "render.exr", "-o", tmp_path / "shown.ppm"], check=True)
    ppm = (tmp_path / "shown.ppm").read_bytes()
    assert ppm.startswith(b"P6\n16 12\n255\n")
    tool = np.frombuffer(ppm[len(b"P6\n16 12\n255\n"):], dtype=np.uint8).reshape(12, 16, 3)
    assert np.array_equal(image.to_srgb8(), tool)
    shown = image.to_srgb()
    assert shown.shape == (12, 16, 3) and np.all((np.abs(shown * 255 - tool) <= 1) | (shown > 1) | (shown < 0))
    png = image._repr_png_()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and png[12:16] == b"IHDR"


def test_bad_settings_raise(cornell):
    with pytest.raises(ValueError, match="nosuchpass"):
        cornell.render(8, 8, 1, passes=("nosuchpass",))
    with pytest.raises(ValueError, match="^--width: Value 0 not in range 1 to 65536$"):
        cornell.render(0, 8, 1)
    with pytest.raises(ValueError, match="^--spp: Value -1 not in range 1 to 2147483647$"):
        cornell.render(8, 8, -1)
    with pytest.raises(orb.Error, match="no OpenCL device with index 7; the devices are:"):
        cornell.render(8, 8, 1, device="7")


def test_progress_callback_sees_each_pass_and_stops_the_render(cornell):
    seen = []

    def progress(state):
        seen.append(state)
        return False  # stop after the first pass

    image = cornell.render(16, 12, 4096, progress=progress)
    assert len(seen) == 1 and seen[0]["pass"] >= 1 and image.stopped and image.spp < 4096


def test_an_error_in_the_callback_is_raised(cornell):
    def progress(state):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        cornell.render(16, 12, 4096, progress=progress)


def test_ctrl_c_stops_the_render_with_keyboard_interrupt(cornell):
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            cornell.render(64, 48, 1 << 20)  # hours, were it not stopped
    finally:
        timer.cancel()
