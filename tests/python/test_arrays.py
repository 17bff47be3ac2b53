"""Scene.from_arrays: numpy arrays of any float dtype and layout, checked as a scene file is."""
import math

import numpy as np
import pytest

import orb


def grid(n=4):
    axis = np.arange(n, dtype=np.float64)
    return np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)


def test_spheres_keep_their_centres_and_radii():
    centers = grid()
    radii = np.linspace(0.1, 0.4, len(centers))
    scene = orb.Scene.from_arrays(centers, radii)
    # the particles first, then the two default lights of a point cloud
    assert len(scene) == len(centers) + 2
    np.testing.assert_array_equal(scene.centers[: len(centers)], centers)
    np.testing.assert_array_equal(scene.radii[: len(centers)], radii)
    assert [m["emission"] != [0, 0, 0] for m in scene.materials].count(True) == 2


@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.int32, np.int64])
def test_every_numeric_dtype_gives_the_same_scene(dtype):
    centers = grid()
    reference = orb.Scene.from_arrays(centers, 0.25)
    assert orb.Scene.from_arrays(centers.astype(dtype), np.full(len(centers), 0.25, dtype=np.float32)) == reference


def test_non_contiguous_arrays_are_read_through_their_strides():
    centers = grid()
    wide = np.zeros((len(centers), 6))
    wide[:, ::2] = centers  # every other column: strided rows
    fortran = np.asfortranarray(centers)
    radii = np.repeat(np.full(len(centers), 0.2), 2)[::2]
    reference = orb.Scene.from_arrays(centers, 0.2)
    assert not wide[:, ::2].flags.c_contiguous and not fortran.flags.c_contiguous
    assert orb.Scene.from_arrays(wide[:, ::2], radii) == reference
    assert orb.Scene.from_arrays(fortran, 0.2) == reference
    assert orb.Scene.from_arrays(centers.tolist(), 0.2) == reference


@pytest.mark.parametrize("radius", [np.float32(0.25), np.float64(0.25), np.array(0.25), np.int64(1)])
def test_one_radius_as_a_numpy_number(radius):
    centers = grid()
    expected = orb.Scene.from_arrays(centers, np.full(len(centers), float(radius)))
    assert orb.Scene.from_arrays(centers, radius) == expected


def test_colors_are_display_values_decoded_to_linear():
    centers = grid(2)
    colors = np.tile([[0.5, 0.0, 1.0]], (len(centers), 1))
    scene = orb.Scene.from_arrays(centers, 0.3, colors=colors)
    text = scene.to_json()
    # sRGB 0.5 is linear ((0.5 + 0.055) / 1.055) ** 2.4, stored as a float (written shortest)
    linear = np.float32(((0.5 + 0.055) / 1.055) ** 2.4)
    assert text.count("[" + str(linear) + ", 0, 1]") == len(centers)


def test_properties_numeric_and_categorical():
    centers = grid(2)
    scene = orb.Scene.from_arrays(
        centers, 0.3, properties={"temperature": np.arange(len(centers)), "element": ["C", "O"] * 4}
    )
    text = scene.to_json()
    assert '"temperature"' in text and '"element"' in text and '"C"' in text and '"O"' in text


def test_material_preset_and_dict():
    centers = grid(2)
    assert orb.Scene.from_arrays(centers, 0.3, materials="metal").materials[0]["type"] == "pbr"
    glass = orb.Scene.from_arrays(centers, 0.3, materials={"type": "dielectric", "ior": 1.33})
    assert glass.materials[0]["type"] == "dielectric" and glass.materials[0]["ior"] == 1.33


@pytest.mark.parametrize(
    "centers, radii, message",
    [
        (np.zeros((4, 2)), 0.1, "centers: expected shape (N, 3), got (4, 2)"),
        (np.zeros(3), 0.1, "centers: expected shape (N, 3), got (3,)"),
        (np.zeros((0, 3)), 0.1, "centers: expected at least one sphere"),
        (np.zeros((4, 3)), np.ones(3), "radii: expected shape (4,), got (3,)"),
        (np.zeros((4, 3)), np.ones((4, 1)), "radii: expected shape (4,), got (4, 1)"),
        (np.array([["a", "b", "c"]]), 0.1, "centers: expected numbers (a float or integer array), got dtype <U1"),
    ],
)
def test_wrong_shapes_and_dtypes_raise_value_error(centers, radii, message):
    with pytest.raises(ValueError) as raised:
        orb.Scene.from_arrays(centers, radii)
    assert message in str(raised.value)


def test_nan_centre_names_the_sphere():
    centers = grid(2)
    centers[3, 1] = math.nan
    with pytest.raises(ValueError, match=r"^Scene\.from_arrays: spheres\[3\]\.center"):
        orb.Scene.from_arrays(centers, 0.3)


def test_negative_and_zero_radii_name_the_sphere():
    radii = np.full(8, 0.3)
    radii[5] = -2
    with pytest.raises(ValueError, match=r"^Scene\.from_arrays: spheres\[5\]\.radius"):
        orb.Scene.from_arrays(grid(2), radii)
    with pytest.raises(ValueError, match=r"spheres\[0\]\.radius"):
        orb.Scene.from_arrays(grid(2), 0.0)


def test_colors_out_of_range_and_bad_shapes():
    colors = np.full((8, 3), 0.5)
    colors[2, 0] = 1.5
    with pytest.raises(ValueError, match=r"Scene\.from_arrays: "):
        orb.Scene.from_arrays(grid(2), 0.3, colors=colors)
    with pytest.raises(ValueError, match=r"colors: expected shape \(8, 3\), got \(8, 4\)"):
        orb.Scene.from_arrays(grid(2), 0.3, colors=np.ones((8, 4)))


def test_bad_materials():
    with pytest.raises(ValueError, match="material: unknown preset 'gold'"):
        orb.Scene.from_arrays(grid(2), 0.3, materials="gold")
    with pytest.raises(ValueError, match="material\\['type'\\]: unknown material type 'wood'"):
        orb.Scene.from_arrays(grid(2), 0.3, materials={"type": "wood"})
    with pytest.raises(ValueError, match=r"^Scene\.from_arrays: materials\[0\]\.ior"):
        orb.Scene.from_arrays(grid(2), 0.3, materials={"type": "dielectric", "ior": -1})
    with pytest.raises(ValueError, match="material: unknown key 'shine'"):
        orb.Scene.from_arrays(grid(2), 0.3, materials={"shine": 1})
