"""Shared paths for the Python module's tests (run by CTest: tests/python/CMakeLists.txt sets the
environment; PYTHONPATH=<build>/python makes `import candela` work)."""
import os
import pathlib

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
REFERENCE = SOURCE / "tests" / "data" / "reference"  # third-party measured files (SOURCES.md)
CANDELA_EXE = os.environ.get("CANDELA_EXE", str(SOURCE / "build" / "cli" / "candela"))


@pytest.fixture
def source():
    return SOURCE


@pytest.fixture
def reference():
    return REFERENCE


@pytest.fixture
def candela_exe():
    return CANDELA_EXE
