"""The Python blocks of docs/python.md and README.md's "From Python" work as written."""
import re
import textwrap

import pytest

from conftest import SOURCE_DIR


def python_blocks(document):
    # a block inside a list item is indented with it
    blocks = re.findall(r"^( *)```python\n(.*?)^\1```", (SOURCE_DIR / document).read_text(), flags=re.S | re.M)
    return [scaled_down(textwrap.dedent(block)) for _, block in blocks]


def scaled_down(block):
    """Renders run at 64 x 48 with 2 samples, as the shell blocks of the docs run scaled down."""
    return re.sub(r"\.render(_progressive)?\(\d+, \d+, spp=\d+", r".render\1(64, 48, spp=2", block)


@pytest.mark.parametrize("document", ["docs/python.md", "README.md"])
def test_python_blocks_run_in_order_from_a_clones_root(document, tmp_path, monkeypatch):
    blocks = python_blocks(document)
    assert blocks, f"{document} has no python block"
    for name in ("scenes", "tests"):
        (tmp_path / name).symlink_to(SOURCE_DIR / name)
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in blocks:
        exec(compile(block, document, "exec"), namespace)
    if document == "docs/python.md":
        assert (tmp_path / "cloud.exr").stat().st_size > 0 and namespace["image"].beauty.shape == (48, 64, 4)
