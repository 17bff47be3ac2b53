"""orb.load: every importer through libimport's registry, with orb-import's options and messages."""
import subprocess
import warnings

import numpy as np
import pytest

import orb


@pytest.mark.parametrize(
    "relative",
    [
        "scenes/cornell.scn",
        "scenes/cornell.json",
        "scenes/bounce.gltf",
        "tests/data/ply-files/blender-2.91-points.ply",
        "tests/data/chemfiles-tests-data/4hhb.pdb",
        "tests/data/chemfiles-tests-data/4hhb.cif",
    ],
)
def test_real_files_load_as_orb_import_reads_them(relative, bin_dir, tmp_path, scenes_dir):
    path = scenes_dir.parent / relative
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = orb.load(path)
    assert len(scene) > 0
    # orb-import of the same file writes the same scene
    subprocess.run([bin_dir / "orb-import", "-q", path, "-o", tmp_path / "tool.json"], check=True)
    scene.save(tmp_path / "python.json")
    assert (tmp_path / "python.json").read_text() == (tmp_path / "tool.json").read_text()


def test_options_are_orb_imports(scenes_dir, bin_dir, tmp_path):
    pdb = scenes_dir.parent / "tests/data/chemfiles-tests-data/4hhb.pdb"
    scene = orb.load(pdb, color_by="b_factor", colormap="inferno", radius_scale=0.5, look_at=(1, 2, 3), vfov=30)
    assert scene.camera.target == [1, 2, 3] and scene.camera.vfov == 30
    subprocess.run(
        [bin_dir / "orb-import", "-q", pdb, "--color-by", "b_factor", "--colormap", "inferno", "--radius-scale",
         "0.5", "--look-at", "1,2,3", "--vfov", "30", "-o", tmp_path / "tool.orb"],
        check=True,
    )
    assert orb.load(tmp_path / "tool.orb") == scene


def test_missing_file_is_file_not_found():
    with pytest.raises(FileNotFoundError, match=r"^no/such\.ply: cannot open: No such file or directory$"):
        orb.load("no/such.ply")


def test_bad_file_is_orb_error_with_the_tools_message(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"version": 1, "spheres": [{"center": [0, 0, 0], "radius": -2}]}')
    with pytest.raises(orb.Error, match=r"bad\.json") as raised:
        orb.load(bad)
    assert isinstance(raised.value, RuntimeError)
    obj = tmp_path / "tri.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(orb.Error, match="tri.obj"):
        orb.load(obj)


def test_bad_options_are_value_errors_and_unknown_ones_type_errors(scenes_dir):
    cornell = scenes_dir / "cornell.scn"
    with pytest.raises(ValueError, match="--vfov"):
        orb.load(cornell, vfov=200)
    with pytest.raises(ValueError, match="--colormap"):
        orb.load(cornell, colormap="rainbowish", color_by="x")
    with pytest.raises(ValueError, match="--from"):
        orb.load(cornell, **{"from": "obj"})
    with pytest.raises(TypeError, match="load\\(\\) got an unexpected keyword argument 'colour_by'"):
        orb.load(cornell, colour_by="x")
    with pytest.raises(TypeError, match="'legend'"):
        orb.load(cornell, legend="x.png")


def test_a_missing_property_names_the_ones_there(scenes_dir):
    with pytest.raises(orb.Error, match="temperature"):
        orb.load(scenes_dir.parent / "tests/data/chemfiles-tests-data/4hhb.pdb", color_by="temperature")


def test_importer_warnings_are_python_warnings(scenes_dir):
    with pytest.warns(UserWarning):
        orb.load(scenes_dir / "bounce.gltf", radius=0.5)  # a PLY option given for glTF: ignored, as orb-import says


def test_numbered_frame(scenes_dir):
    xyz = scenes_dir.parent / "tests/data/chemfiles-tests-data/extended.xyz"
    with pytest.warns(UserWarning, match="holds 3 frames; this is frame 2"):
        second = orb.load(xyz, frame=2)
    with pytest.warns(UserWarning, match="holds 3 frames; this is frame 1"):
        first = orb.load(xyz)
    assert len(first) > 0 and not np.array_equal(first.centers, second.centers)
