"""Every binding's errors: the tools' messages as orb.Error, ValueError, TypeError or
FileNotFoundError (docs/python.md, "Errors"), never a bare RuntimeError or a crash."""
import subprocess
import sys

import numpy as np
import pytest

import orb


@pytest.fixture
def cornell(scenes_dir):
    return orb.load(scenes_dir / "cornell.scn")


def orb_render_error(bin_dir, scene_path, *arguments, status):
    """orb-render's message for these arguments, without its 'orb-render: error: ' prefix."""
    result = subprocess.run([bin_dir / "orb-render", scene_path, "--width", "8", "--height", "8", "--spp", "1",
                             *arguments, "-o", scene_path.with_suffix(".exr")], capture_output=True, text=True)
    assert result.returncode == status, result.stderr
    message = result.stderr.split("orb-render: error: ", 1)[1]
    return message.split("\nRun with --help")[0].rstrip("\n")


def strictly(error_type, message):
    """pytest.raises for exactly this type (not a subclass) and this whole message."""
    raised = pytest.raises(error_type)

    class Check:
        def __enter__(self):
            self.info = raised.__enter__()
            return self.info

        def __exit__(self, *exc):
            suppressed = raised.__exit__(*exc)
            assert type(self.info.value) is error_type, f"{type(self.info.value)}: {self.info.value}"
            assert str(self.info.value) == message
            return suppressed

    return Check()


def test_no_such_device_is_orb_error_with_orb_renders_message(cornell, bin_dir, tmp_path):
    cornell.save(tmp_path / "cornell.orb")
    for device in ("no-such-device", "7", "0,0"):
        message = orb_render_error(bin_dir, tmp_path / "cornell.orb", "--device", device, status=1)
        with strictly(orb.Error, message):
            cornell.render(8, 8, 1, device=device)
        with strictly(orb.Error, message):
            next(cornell.render_progressive(8, 8, 1, device=device))


def test_render_limits_are_checked_as_orb_render_checks_them(cornell, bin_dir, tmp_path):
    cornell.save(tmp_path / "cornell.orb")
    for keyword, option in (("time_limit", "--time"), ("target_error", "--target-error"),
                            ("noise_threshold", "--noise-threshold")):
        for value in (0, -1, float("nan"), float("inf")):
            word = {0: "0", -1: "-1"}.get(value, str(value))
            message = orb_render_error(bin_dir, tmp_path / "cornell.orb", f"{option}={word}", status=2)
            with strictly(ValueError, message):
                cornell.render(8, 8, 1, **{keyword: value})
            with strictly(ValueError, message):
                cornell.render_progressive(8, 8, 1, **{keyword: value})


def test_material_values_of_the_wrong_kind_name_their_key():
    centers = np.zeros((1, 3))
    with strictly(ValueError, "material['color']: expected (R, G, B) numbers, got 'red'"):
        orb.Scene.from_arrays(centers, 1.0, materials={"color": "red"})
    with strictly(ValueError, "material['ior']: expected a number, got [1.5]"):
        orb.Scene.from_arrays(centers, 1.0, materials={"ior": [1.5]})
    with strictly(ValueError, "material['type']: expected a material type's name, got 3"):
        orb.Scene.from_arrays(centers, 1.0, materials={"type": 3})
    with strictly(ValueError, "material: expected str keys, got 1"):
        orb.Scene.from_arrays(centers, 1.0, materials={1: 2})


def test_writing_where_nothing_can_be_written_is_orb_error(cornell, tmp_path):
    image = cornell.render(4, 4, 1)
    missing = tmp_path / "no-such-folder"
    for write in (lambda: image.save(missing / "x.exr"), lambda: cornell.save(missing / "x.orb")):
        with pytest.raises(orb.Error, match="no-such-folder"):
            write()
        assert not missing.exists()


def test_comparisons_and_wrong_types_are_pythons(cornell):
    assert (cornell == 3) is False and cornell != "cornell"
    with pytest.raises(TypeError):
        cornell.render(8, 8, 1, seed=-1)
    with pytest.raises(TypeError):
        cornell.camera.orbit("far")
    with pytest.raises(TypeError):
        orb.Scene()


def test_a_refused_camera_change_leaves_the_camera_as_it_was(cornell):
    before = repr(cornell.camera)
    with pytest.raises(orb.Error, match="is where the scene's camera stands"):
        cornell.camera.look_at(cornell.camera.position)
    with pytest.raises(orb.Error, match="is the point the scene's camera looks at"):
        cornell.set_camera(camera_position=cornell.camera.target)
    with strictly(ValueError, "--orbit: expected a number of degrees, got 'nan'"):
        cornell.camera.orbit(float("nan"))
    assert repr(cornell.camera) == before
    assert cornell.render(4, 4, 1).final


def test_a_missing_environment_map_is_file_not_found_and_a_bad_radiance_orb_error(cornell):
    with strictly(FileNotFoundError, "--environment missing.exr: no such file"):
        cornell.set_environment("missing.exr")
    with strictly(orb.Error, "--environment -1: radiance must be finite, >= 0 and <= 1e12 (times the intensity)"):
        cornell.set_environment(-1)


def test_an_image_written_over_a_folder_says_why(cornell, tmp_path):
    with strictly(orb.Error, f"{tmp_path}: cannot write: Is a directory"):
        cornell.render(4, 4, 1).save(tmp_path)
    assert list(tmp_path.iterdir()) == []


def test_renders_started_together_on_threads_all_render(scenes_dir):
    # In a fresh interpreter: the first renders find the OpenCL platform together.
    code = """
import sys, threading, orb
scene = orb.load(sys.argv[1])
errors, images = [], []
def render(seed):
    try:
        images.append(scene.render(16, 12, 2, seed=seed).spp)
        images.append(list(scene.render_progressive(16, 12, 2, seed=seed))[-1].spp)
    except Exception as e:
        errors.append(repr(e))
threads = [threading.Thread(target=render, args=(seed,)) for seed in range(4)]
[t.start() for t in threads]
[t.join() for t in threads]
print(errors, images)
"""
    result = subprocess.run([sys.executable, "-c", code, scenes_dir / "cornell.scn"], capture_output=True, text=True)
    assert result.returncode == 0 and result.stdout == "[] [2, 2, 2, 2, 2, 2, 2, 2]\n", result.stderr
