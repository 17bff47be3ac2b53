"""Scene.render_progressive and orb.show: snapshots as the film converges, the last one render's image."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import orb
from test_render import exr_parts


@pytest.fixture
def cornell(scenes_dir):
    return orb.load(scenes_dir / "cornell.scn")


def test_the_last_image_is_renders_bit_for_bit_and_the_snapshots_converge_to_it(cornell):
    images = list(cornell.render_progressive(32, 24, 64, seed=3, passes=("beauty", "albedo"), every_passes=1))
    final = images[-1]
    rendered = cornell.render(32, 24, 64, seed=3, passes=("beauty", "albedo"))
    assert final.final and not final.stopped and final.spp == 64
    assert exr_parts(final.encode_exr()) == exr_parts(rendered.encode_exr())
    assert np.array_equal(final.beauty, rendered.beauty) and np.array_equal(final.albedo, rendered.albedo)
    # Which snapshots the loop sees depends on how soon it takes them (only
    # the newest waits), not what each one is.
    snapshots = images[:-1]
    counts = [image.spp for image in images]
    assert counts == sorted(set(counts)), f"sample counts not increasing: {counts}"
    for snapshot in snapshots:
        assert not snapshot.final and snapshot.layer_names == ["beauty", "albedo"]
        assert snapshot.beauty.shape == (24, 32, 4) and np.all(np.isfinite(snapshot.beauty))


def test_a_snapshot_is_the_mean_of_the_samples_so_far(cornell):
    # The samples a render of k samples per pixel draws are the first k of any
    # longer render with the same seed: a snapshot of k samples is that render.
    first = next(iter(cornell.render_progressive(32, 24, 1 << 20, seed=3, every_passes=1)))
    assert not first.final and 1 <= first.spp < 1 << 20
    assert np.array_equal(first.beauty, cornell.render(32, 24, first.spp, seed=3).beauty)


def test_every_seconds_paces_the_snapshots(cornell):
    started = time.monotonic()
    images = list(cornell.render_progressive(32, 24, 16, every=3600))
    # One hour between snapshots: the first pass's image (unless the final one
    # came before the loop took it), then only the final one.
    assert images[-1].final and images[-1].spp == 16
    assert [(image.final, image.spp) for image in images[:-1]] in ([], [(False, 1)])
    assert time.monotonic() - started < 600


def test_leaving_the_loop_stops_the_render(cornell):
    started = time.monotonic()
    for image in cornell.render_progressive(64, 48, 1 << 24, every_passes=1):  # days, were it not stopped
        assert not image.final
        break
    # The generator is closed as it goes: the render stopped after the pass in flight.
    assert time.monotonic() - started < 120
    images = cornell.render_progressive(64, 48, 1 << 24, every_passes=1)
    next(images)
    images.close()
    with pytest.raises(StopIteration):
        next(images)
    # a render never started is stopped when it is dropped
    unused = cornell.render_progressive(64, 48, 1 << 24)
    del unused
    assert cornell.render(16, 12, 2).final


def test_ctrl_c_stops_a_progressive_render_with_keyboard_interrupt(cornell):
    # Ctrl-C once the first image is in, while the loop waits for the next ones.
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    seen = []
    try:
        with pytest.raises(KeyboardInterrupt):
            for image in cornell.render_progressive(64, 48, 1 << 24, every_passes=1):  # days, were it not stopped
                if not seen:
                    timer.start()
                seen.append(image.spp)
    finally:
        timer.cancel()
    assert seen and all(spp < 1 << 24 for spp in seen)


def test_bad_arguments_raise_at_the_call_and_errors_at_the_first_image(cornell):
    with pytest.raises(ValueError, match="^--width: Value 0 not in range 1 to 65536$"):
        cornell.render_progressive(0, 8, 1)
    with pytest.raises(ValueError, match="^every: expected seconds > 0, got 0$"):
        cornell.render_progressive(8, 8, 1, every=0)
    with pytest.raises(ValueError, match="^every_passes: expected a whole number >= 1, got 1.5$"):
        cornell.render_progressive(8, 8, 1, every_passes=1.5)
    with pytest.raises(ValueError, match="nosuchpass"):
        cornell.render_progressive(8, 8, 1, passes="nosuchpass")
    images = cornell.render_progressive(8, 8, 1, device="no-such-device")
    with pytest.raises(orb.Error, match="^no OpenCL device matches 'no-such-device'"):
        next(images)


class FakeDisplay:
    """What orb.show uses of IPython.display: display(obj, display_id=True) and the handle's update(obj)."""

    def __init__(self):
        self.shown = []

    def display(self, image, display_id=False):
        assert display_id is True
        self.shown.append(("display", image))
        return self

    def update(self, image):
        self.shown.append(("update", image))


def test_show_updates_one_display_as_the_image_converges(cornell, monkeypatch):
    import IPython as ipython  # ipykernel's, a test dependency

    fake = FakeDisplay()
    monkeypatch.setattr(ipython, "get_ipython", lambda: object())
    monkeypatch.setattr(ipython.display, "display", fake.display)
    image = orb.show(cornell, width=32, height=24, spp=64, seed=3, every=1e-9)
    kinds = [kind for kind, _ in fake.shown]
    assert kinds[0] == "display" and set(kinds[1:]) <= {"update"} and len(kinds) >= 2
    assert fake.shown[-1][1] is image and image.final
    assert np.array_equal(image.beauty, cornell.render(32, 24, 64, seed=3).beauty)


def test_show_outside_ipython_renders_once(cornell, monkeypatch):
    import IPython as ipython

    monkeypatch.setattr(ipython, "get_ipython", lambda: None)
    image = orb.show(cornell, width=16, height=12, spp=2)
    assert image.final and np.array_equal(image.beauty, cornell.render(16, 12, 2).beauty)


def test_with_denoise_every_image_has_the_denoised_layer_and_the_last_is_renders(cornell):
    images = list(cornell.render_progressive(32, 24, 16, seed=2, denoise=True, every_passes=1))
    assert all(image.layer_names == ["beauty", "albedo", "normal", "denoised"] for image in images)
    rendered = cornell.render(32, 24, 16, seed=2, denoise=True)
    assert np.array_equal(images[-1].denoised, rendered.denoised) and np.array_equal(images[-1].beauty, rendered.beauty)
