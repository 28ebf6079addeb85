"""Shared fixtures: the texsample program the results are checked against
(LIBSAMPLE_TEXSAMPLE, set by tests/python.cmake) and the source tree."""
import os

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))


@pytest.fixture(scope="session")
def texsample():
    path = os.environ.get("LIBSAMPLE_TEXSAMPLE")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("LIBSAMPLE_TEXSAMPLE does not name the texsample program")
    return path


@pytest.fixture(scope="session")
def testimage():
    return os.path.join(ROOT, "testimages", "rgb8.png")
