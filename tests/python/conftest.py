"""Shared fixtures of the Python package's tests (tests/python/python_tests.cmake runs each
test_*.py under Debian's pytest, with these variables set)."""

import json
import os
import pathlib
import subprocess

import pytest


def _environment(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(name + " is not set: run the Python tests through CTest (tests/python/python_tests.cmake)")
    return value


@pytest.fixture(scope="session")
def scatterlab_exe():
    return _environment("SCATTERLAB_EXE")


@pytest.fixture(scope="session")
def data_dir():
    return pathlib.Path(_environment("SCATTERLAB_DATA_DIR"))


@pytest.fixture()
def scratch(request):
    """A fresh directory per test under the build tree's test output."""
    path = pathlib.Path(_environment("SCATTERLAB_TEST_OUTPUT_DIR")) / request.node.name
    if path.exists():
        for child in sorted(path.rglob("*"), reverse=True):
            child.unlink() if child.is_file() or child.is_symlink() else child.rmdir()
    path.mkdir(parents=True, exist_ok=True)
    return path


@pytest.fixture(scope="session")
def run_json(scatterlab_exe):
    """Runs the executable with --json and returns the parsed output (exit 0 required)."""
    def run(*args):
        result = subprocess.run([scatterlab_exe, *args, "--json"], capture_output=True, text=True)
        assert result.returncode == 0, result.stderr
        return json.loads(result.stdout)
    return run
