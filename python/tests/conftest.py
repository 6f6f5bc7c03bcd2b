"""Shared fixtures: the CLI of the same build and the source tree (set by ctest)."""
import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("WEARSCALE_CLI")
    if not path or not os.path.exists(path):
        pytest.skip("WEARSCALE_CLI (the wearscale program of this build) is not set; ctest sets it")
    return path


@pytest.fixture(scope="session")
def source_dir():
    return pathlib.Path(os.environ.get("WEARSCALE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
