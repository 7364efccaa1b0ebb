"""Shared fixtures of the command-line tests: where the binary, the sources and ../shared are."""
import os
import subprocess

import pytest

SOURCE = os.environ.get("AIRSHAPE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("AIRSHAPE_BUILD_DIR", os.path.join(SOURCE, "build"))
BINARY = os.environ.get("AIRSHAPE_BIN", os.path.join(BUILD, "bin", "airshape"))
SHARED = os.environ.get("AIRSHAPE_SHARED", os.path.join(SOURCE, "..", "shared"))
EXAMPLE = os.path.join(SOURCE, "examples", "example-aircraft.xml")
DATA = os.path.join(SOURCE, "tests", "data")


def shared_path(*parts):
    """A path under ../shared; skips the test when it is absent."""
    path = os.path.join(SHARED, *parts)
    if not os.path.exists(path):
        pytest.skip(f"{path} is absent")
    return path


def airshape(*arguments, stdin=None, env=None):
    """Runs the airshape command and returns the completed process (text mode)."""
    return subprocess.run([BINARY, *arguments], input=stdin, capture_output=True, text=True, timeout=300,
                          env={**os.environ, **(env or {})})
