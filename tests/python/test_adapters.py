"""orb.from_ase: atoms as Orb reads the same atoms from an extended XYZ file."""
import numpy as np
import pytest

import orb


class Atoms:
    """What from_ase reads of an ase.Atoms (ASE is not installed in the test environment)."""

    def __init__(self, symbols, positions, cell=None, pbc=(True, True, True)):
        self.symbols, self.positions, self.cell, self.pbc = symbols, np.asarray(positions), cell, pbc

    def get_chemical_symbols(self):
        return list(self.symbols)

    def get_positions(self):
        return self.positions

    def get_cell(self):
        return np.zeros((3, 3)) if self.cell is None else np.asarray(self.cell)

    def get_pbc(self):
        return np.asarray(self.pbc)


def test_atoms_become_the_scene_of_the_same_extended_xyz(tmp_path):
    water = Atoms(["O", "H", "H"], [[0, 0, 0], [0.7586, 0.5865, 0], [-0.7586, 0.5865, 0]], cell=np.eye(3) * 4)
    (tmp_path / "water.xyz").write_text(
        '3\nLattice="4 0 0 0 4 0 0 0 4" Properties=species:S:1:pos:R:3 pbc="T T T"\n'
        "O 0 0 0\nH 0.7586 0.5865 0\nH -0.7586 0.5865 0\n")
    assert orb.from_ase(water, cell=True) == orb.load(tmp_path / "water.xyz", cell=True)
    assert orb.from_ase(water, color_by="element") == orb.load(tmp_path / "water.xyz", color_by="element")


def test_without_a_cell_and_with_bad_input():
    assert len(orb.from_ase(Atoms(["C"], [[1, 2, 3]]))) >= 1
    with pytest.raises(TypeError, match="expected an ase.Atoms"):
        orb.from_ase(np.zeros((3, 3)))
    with pytest.raises(orb.Error):
        orb.from_ase(Atoms(["C"], [[np.nan, 0, 0]]))
