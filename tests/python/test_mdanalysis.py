"""orb.from_mdanalysis and orb.frames: MDAnalysis's atoms as Orb reads the same atoms from a file.

The data are written here: a small PDB (two chains, a box) and a three-frame
XYZ trajectory of its atoms, read by MDAnalysis as any simulation's files."""
import json
import subprocess
import sys
import warnings

import numpy as np
import pytest

import MDAnalysis as mda  # a test dependency (scripts/install-deps.sh --tests); orb itself does not need it
import orb

# Coordinates, B-factors and occupancies that float32 (MDAnalysis's positions) holds exactly.
ATOMS = [  # name, residue, chain, residue number, x, y, z, occupancy, B, element
    ("N", "ALA", "A", 1, 1.5, 1.0, 1.25, 1.0, 10.5, "N"),
    ("CA", "ALA", "A", 1, 2.75, 1.0, 1.0, 1.0, 12.0, "C"),
    ("C", "ALA", "A", 1, 3.25, 2.25, 1.0, 1.0, 14.25, "C"),
    ("O", "ALA", "A", 1, 2.5, 3.25, 1.5, 0.5, 16.0, "O"),
    ("FE", "HEM", "B", 2, 5.0, 5.0, 5.0, 1.0, 20.0, "FE"),
]
BOX = 12.0


def pdb_text():
    lines = [f"CRYST1{BOX:9.3f}{BOX:9.3f}{BOX:9.3f}  90.00  90.00  90.00 P 1           1"]
    for serial, (name, residue, chain, number, x, y, z, occupancy, b, element) in enumerate(ATOMS, 1):
        atom_name = f" {name:<3}" if len(name) < 4 and len(element) == 1 else f"{name:<4}"
        lines.append(f"HETATM{serial:5d} {atom_name} {residue:>3} {chain}{number:4d}    "
                     f"{x:8.3f}{y:8.3f}{z:8.3f}{occupancy:6.2f}{b:6.2f}          {element:>2}")
    return "\n".join(lines + ["END"]) + "\n"


def trajectory(frames):
    """XYZ frames: every atom moved by 0.5 angstrom along x per frame."""
    positions = np.array([atom[4:7] for atom in ATOMS])
    text, moved = "", []
    for frame in range(frames):
        step = positions + [0.5 * frame, 0, 0]
        moved.append(step)
        text += f"{len(ATOMS)}\nframe {frame}\n" + "".join(
            f"{atom[-1].capitalize()} {x} {y} {z}\n" for atom, (x, y, z) in zip(ATOMS, step))
    return text, moved


@pytest.fixture
def files(tmp_path):
    (tmp_path / "small.pdb").write_text(pdb_text())
    text, moved = trajectory(3)
    (tmp_path / "small.xyz").write_text(text)
    return tmp_path, moved


def universe(*paths):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # MDAnalysis's notes on what the PDB lacks
        return mda.Universe(*[str(p) for p in paths])


def test_atoms_become_the_scene_orb_reads_from_the_same_pdb(files):
    folder, _ = files
    u = universe(folder / "small.pdb")
    for options in ({}, {"cell": True}, {"color_by": "chain"}, {"color_by": "b_factor", "radius_scale": 0.5}):
        from_atoms, from_file = orb.from_mdanalysis(u, **options), orb.load(folder / "small.pdb", **options)
        assert from_atoms == from_file, options
    assert orb.from_mdanalysis(u.select_atoms("name FE")).centers.tolist()[0] == [5.0, 5.0, 5.0]


def test_frames_are_the_trajectorys_frames_with_the_first_frames_camera_and_lights(files):
    folder, moved = files
    u = universe(folder / "small.pdb", folder / "small.xyz")
    scenes = list(orb.frames(u, cell=True))
    assert len(scenes) == 3
    atoms = len(ATOMS)
    for scene, positions in zip(scenes, moved):
        assert np.array_equal(scene.centers[:atoms], positions)
    first = json.loads(scenes[0].to_json())
    for scene in scenes[1:]:
        later = json.loads(scene.to_json())
        assert later["camera"] == first["camera"]
        # after the atoms and the cell: the lights, where frame 1 put them
        assert later["spheres"][-2:] == first["spheres"][-2:]
    u.trajectory[0]
    assert scenes[0] == orb.from_mdanalysis(u, cell=True)
    # a frame on its own is framed anew; in the series it keeps frame 1's view
    u.trajectory[2]
    alone = json.loads(orb.from_mdanalysis(u, cell=True).to_json())
    assert alone["camera"] != first["camera"] and json.loads(scenes[2].to_json())["spheres"][:atoms] == \
        alone["spheres"][:atoms]
    assert [len(s) for s in orb.frames(u.atoms, step=2)] == [len(scenes[0])] * 2


def test_bad_input():
    with pytest.raises(TypeError, match="from_mdanalysis: expected an MDAnalysis Universe or AtomGroup"):
        orb.from_mdanalysis(np.zeros((3, 3)))
    with pytest.raises(TypeError, match="unexpected keyword argument 'frame'"):
        next(orb.frames(mda.Universe.empty(1, trajectory=True), frame=2))
    u = mda.Universe.empty(2, trajectory=True)
    u.add_TopologyAttr("names", ["C1", "Q9"])
    u.atoms.positions = [[0, 0, 0], [1.5, 0, 0]]
    with pytest.warns(UserWarning, match="unknown element"):
        scene = orb.from_mdanalysis(u)
    assert len(scene) >= 2
    with pytest.raises(ValueError, match="--colormap"):
        orb.from_mdanalysis(u, color_by="element", colormap="no-such-map")
    with pytest.raises(orb.Error, match="no_such_property"):
        orb.from_mdanalysis(u, color_by="no_such_property")


def test_the_module_imports_without_mdanalysis():
    # MDAnalysis hidden: orb imports, and the adapters say what they need.
    code = ("import sys; sys.modules['MDAnalysis'] = None; import orb; "
            "assert 'MDAnalysis' not in [m for m in sys.modules if sys.modules[m] is not None]; print('ok')")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode == 0 and result.stdout == "ok\n", result.stderr


def test_a_real_ensemble_read_by_mdanalysis_is_the_one_orb_reads(data_dir):
    # 2hkb.pdb: an NMR ensemble of a DNA dodecamer, 10 models (CC-0, tests/data/chemfiles-tests-data/README.md).
    path = data_dir / "chemfiles-tests-data" / "2hkb.pdb"
    scenes = list(orb.frames(universe(path)))
    assert len(scenes) == 10
    atoms = len(universe(path).atoms)
    for number, scene in enumerate(scenes, 1):
        ours, orbs = json.loads(scene.to_json()), json.loads(orb.load(path, frame=number).to_json())
        assert len(ours["spheres"]) == len(orbs["spheres"]) == atoms + 2  # the atoms and two lights
        # MDAnalysis holds positions as float32: within its rounding of PDB's three decimals
        assert np.allclose(scene.centers[:atoms], orb.load(path, frame=number).centers[:atoms], rtol=0, atol=1e-5)
        assert ours["sphere_colors"] == orbs["sphere_colors"] and ours["materials"] == orbs["materials"]
        assert [s["radius"] for s in ours["spheres"][:atoms]] == [s["radius"] for s in orbs["spheres"][:atoms]]
        # the camera frames the atoms: float32's rounding (2e-6 at 40 angstrom) a few times over
        for key in ("position", "target", "focus_distance"):
            assert np.allclose(ours["camera"][key], orbs["camera"][key], rtol=0, atol=1e-4)
        # the topology's columns; MDAnalysis keeps model 1's B-factors and occupancies for every frame
        static = [p for p in ours["sphere_properties"] if p["name"] not in ("b_factor", "occupancy")]
        assert static == [p for p in orbs["sphere_properties"] if p["name"] not in ("b_factor", "occupancy")]
        if number == 1:
            assert ours["sphere_properties"] == orbs["sphere_properties"]
