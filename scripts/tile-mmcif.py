#!/usr/bin/env python3
"""tile-mmcif: a large real-looking structure for timing the molecule path.

Copies the atoms of one mmCIF file (its _atom_site loop, first model) on an
N x N x N grid, each copy shifted by the structure's extent plus a gap and
given its own chain names (chain A of copy 12 becomes A12), and writes them
as one mmCIF file. Tiling tests/data/chemfiles-tests-data/4hhb.cif (4 779
atoms) 6 x 6 x 6 times gives 1 032 264 atoms:

    scripts/tile-mmcif.py tests/data/chemfiles-tests-data/4hhb.cif --grid 6 -o big.cif
    orb-render big.cif --spp 1 --width 1920 --height 1080 -o big.exr

Only the columns Orb reads need to be right; the others are copied as they are.
"""
import argparse
import shlex
import sys


def read_atom_site(path):
    """(column names, rows as token lists) of the file's _atom_site loop."""
    columns, rows, in_loop, reading_rows = [], [], False, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            stripped = line.strip()
            if stripped == "loop_":
                if reading_rows:
                    break
                in_loop, columns = True, []
                continue
            if in_loop and stripped.startswith("_atom_site."):
                columns.append(stripped.split()[0])
                continue
            if in_loop and columns and stripped and not stripped.startswith("_"):
                if stripped.startswith("#"):
                    break
                reading_rows = True
                rows.append(shlex.split(stripped))
                continue
            if in_loop and not columns:
                in_loop = False
    if not rows:
        sys.exit(f"tile-mmcif: {path}: no _atom_site loop")
    return columns, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", help="mmCIF file to tile")
    parser.add_argument("--grid", type=int, default=6, help="copies along each axis (default 6)")
    parser.add_argument("--gap", type=float, default=5.0, help="angstroms between copies (default 5)")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()

    columns, rows = read_atom_site(args.input)
    index = {name: k for k, name in enumerate(columns)}
    x, y, z = (index[f"_atom_site.Cartn_{a}"] for a in "xyz")
    model = index.get("_atom_site.pdbx_PDB_model_num")
    if model is not None:
        first = rows[0][model]
        rows = [r for r in rows if r[model] == first]
    lo = [min(float(r[c]) for r in rows) for c in (x, y, z)]
    hi = [max(float(r[c]) for r in rows) for c in (x, y, z)]
    step = [h - l + args.gap for l, h in zip(lo, hi)]
    chains = [index[c] for c in ("_atom_site.label_asym_id", "_atom_site.auth_asym_id") if c in index]
    serial = index["_atom_site.id"]

    with open(args.output, "w", encoding="utf-8") as out:
        out.write("data_TILED\n#\nloop_\n")
        out.write("".join(name + "\n" for name in columns))
        atom = 0
        copy = 0
        for i in range(args.grid):
            for j in range(args.grid):
                for k in range(args.grid):
                    shift = (i * step[0], j * step[1], k * step[2])
                    for r in rows:
                        atom += 1
                        t = list(r)
                        t[serial] = str(atom)
                        for c, s in zip((x, y, z), shift):
                            t[c] = f"{float(r[c]) + s:.3f}"
                        for c in chains:
                            t[c] = f"{r[c]}{copy}"
                        out.write(" ".join(t) + "\n")
                    copy += 1
        out.write("#\n")
    print(f"tile-mmcif: {atom} atoms in {copy} copies -> {args.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
