#!/usr/bin/env bash
# Executes docs/examples/first-image.ipynb headless, as Jupyter runs it, in a
# temporary folder laid out like a clone (its relative paths hold there).
#   run_notebook.sh PYTHON SOURCE_DIR
set -euo pipefail
python=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/docs/examples" "$work/home"
ln -s "$source/tests" "$work/tests"
cp "$source/docs/examples/first-image.ipynb" "$work/docs/examples/"
cd "$work/docs/examples"
# Jupyter's runtime files (the kernel's connection file) in the folder too.
HOME=$work/home "$python" -m nbconvert --to notebook --execute --ExecutePreprocessor.timeout=240 \
  --output executed first-image.ipynb
# Every code cell ran and none raised; the images are in the output.
"$python" - executed.ipynb <<'CHECK'
import json, sys
cells = [c for c in json.load(open(sys.argv[1]))["cells"] if c["cell_type"] == "code"]
assert all(c["execution_count"] for c in cells), "a cell did not run"
errors = [o for c in cells for o in c["outputs"] if o["output_type"] == "error"]
assert not errors, errors
pngs = sum("image/png" in o.get("data", {}) for c in cells for o in c["outputs"])
assert pngs >= 3, f"{pngs} images shown, expected 3"
print(f"first-image.ipynb: {len(cells)} cells ran, {pngs} images shown")
CHECK
