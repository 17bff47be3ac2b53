"""Camera, environment, lights, render settings, save and load of orb.Scene."""
import numpy as np
import pytest

import orb


@pytest.fixture
def cloud():
    rng = np.random.default_rng(7)
    return orb.Scene.from_arrays(rng.uniform(-1, 1, (50, 3)), rng.uniform(0.02, 0.08, 50),
                                 colors=rng.uniform(0, 1, (50, 3)), properties={"t": rng.uniform(size=50)})


@pytest.mark.parametrize("name", ["scene.json", "scene.orb", "SCENE.ORB"])
def test_save_and_load_round_trip_exactly(cloud, tmp_path, name):
    cloud.save(tmp_path / name)
    assert orb.load(tmp_path / name) == cloud


def test_save_refuses_other_names_and_unwritable_folders(cloud, tmp_path):
    with pytest.raises(ValueError, match=r"scene\.png: expected a \.json .* or \.orb"):
        cloud.save(tmp_path / "scene.png")
    with pytest.raises(orb.Error, match="no-such-folder"):
        cloud.save(tmp_path / "no-such-folder" / "scene.orb")
    assert list(tmp_path.iterdir()) == []


def test_camera_look_at_orbit_and_orthographic(cloud):
    camera = cloud.camera
    camera.look_at((0, 0, 0), position=(0, 0, 5), up=(0, 1, 0))
    assert cloud.camera.position == [0, 0, 5] and cloud.camera.target == [0, 0, 0]
    camera.orbit(90)  # whole quarter turns are exact: (0, 0, 5) about +y is (5, 0, 0)
    assert cloud.camera.position == [5, 0, 0]
    camera.orthographic(3)
    assert cloud.camera.orthographic_height == 3
    camera.perspective(vfov=40)
    assert cloud.camera.orthographic_height == 0 and cloud.camera.vfov == 40
    camera.vfov = 35
    assert cloud.camera.vfov == 35


def test_camera_values_are_checked_as_the_command_line_checks_them(cloud):
    with pytest.raises(ValueError, match="--vfov"):
        cloud.camera.vfov = 180
    with pytest.raises(ValueError, match="--orthographic"):
        cloud.camera.orthographic(-1)
    with pytest.raises(ValueError, match="--look-at"):
        cloud.camera.target = (float("nan"), 0, 0)
    with pytest.raises(orb.Error, match="camera"):
        cloud.camera.look_at(cloud.camera.position)  # no view direction
    before = cloud.camera.position
    with pytest.raises(ValueError):
        cloud.camera.position = (1e300, 0, 0)
    assert cloud.camera.position == before


def test_set_camera_auto_camera_frames_the_spheres(cloud):
    cloud.set_camera(look_at=(9, 9, 9))
    assert cloud.camera.target == [9, 9, 9]
    cloud.set_camera(auto_camera=True)
    assert np.allclose(cloud.camera.target, 0, atol=1)


def test_environment_colour_map_and_none(cloud, scenes_dir, tmp_path):
    cloud.set_environment((0.1, 0.2, 0.3))
    assert cloud.environment == [0.1, 0.2, 0.3]
    cloud.set_environment(0.5, intensity=2)
    assert cloud.environment == [1.0, 1.0, 1.0]
    cloud.set_environment(scenes_dir / "studio.exr", rotation=90)
    assert cloud.environment["map"].endswith("scenes/studio.exr") and cloud.environment["rotation"] == 90
    # saved elsewhere, the map is named from the scene's folder
    cloud.save(tmp_path / "lit.json")
    assert orb.load(tmp_path / "lit.json").environment["map"] == cloud.environment["map"]
    cloud.set_environment(None)
    assert cloud.environment is None
    with pytest.raises(FileNotFoundError, match="--environment missing.exr: no such file"):
        cloud.set_environment("missing.exr")
    with pytest.raises(orb.Error, match="radiance must be finite"):
        cloud.set_environment((-1, 0, 0))


def test_add_light(cloud):
    count = len(cloud)
    cloud.add_light((0, 3, 0), 0.5, (10, 10, 10))
    assert len(cloud) == count + 1 and cloud.materials[-1]["emission"] == [10, 10, 10]
    with pytest.raises(ValueError, match=r"^add_light: spheres\[%d\]\.radius: must be > 0, got -1$" % (count + 1)):
        cloud.add_light((0, 3, 0), -1, (1, 1, 1))
    assert len(cloud) == count + 1


def test_render_settings_are_checked(cloud):
    cloud.width, cloud.height, cloud.spp, cloud.max_depth = 64, 48, 16, 4
    assert (cloud.width, cloud.height, cloud.spp, cloud.max_depth) == (64, 48, 16, 4)
    with pytest.raises(ValueError, match="render.width"):
        cloud.width = 0


def test_devices_lists_opencl_devices():
    devices = orb.devices()
    assert devices and {"index", "type", "name", "platform", "vendor", "version", "compute_units",
                        "memory_bytes"} <= set(devices[0])
    assert all(device["type"] in ("gpu", "cpu", "other") for device in devices)
