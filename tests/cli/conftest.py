"""Shared fixtures of the command-line tests: where the binary, the sources and ../shared are."""
import json
import os
import subprocess
import sys

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


def conformance_passed(case_file):
    """Runs ../shared/conformance/run.py on one case file against this build (skips when the
    shared data is absent); returns the number of passed cases and the runner's output, whose
    last line is 'N passed, M failed'."""
    cases = shared_path("conformance", case_file)
    runner = os.path.join(os.path.dirname(cases), "run.py")
    result = subprocess.run([sys.executable, runner, "--airshape", BINARY, "--data", shared_path("data", "cpacs"), cases],
                            capture_output=True, text=True, timeout=900)
    return int(result.stdout.strip().splitlines()[-1].split()[0]), result.stdout


def query_answers(path, *queries):
    """Runs `airshape query` on a file with the queries and returns their results; every
    query must succeed."""
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    assert result.returncode == 0, result.stderr
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert all("ok" in a for a in answers), answers
    return [a["ok"] for a in answers]
