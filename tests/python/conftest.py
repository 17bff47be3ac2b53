"""Where the tests find the repository's scenes and data, and the build's tools."""
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ORB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BIN_DIR = pathlib.Path(os.environ.get("ORB_BIN_DIR", SOURCE_DIR / "build" / "bin"))


@pytest.fixture
def scenes_dir():
    return SOURCE_DIR / "scenes"


@pytest.fixture
def data_dir():
    return SOURCE_DIR / "tests" / "data"


@pytest.fixture
def bin_dir():
    return BIN_DIR
