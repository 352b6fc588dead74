"""Shared set-up of the Python package's tests: the program and the source tree, from the
environment ctest gives (tests/CMakeLists.txt)."""
import os
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def abut_exe():
    return os.environ["ABUT_EXE"]


@pytest.fixture(scope="session")
def source_dir():
    return Path(os.environ["ABUT_SOURCE_DIR"])
