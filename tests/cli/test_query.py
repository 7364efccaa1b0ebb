"""`airshape query` on the project's own example, and the conformance cases that need no geometry."""
import json
import os
import subprocess
import sys

from conftest import BINARY, EXAMPLE, airshape, shared_path


def ask(path, *queries):
    result = airshape("query", path, stdin="".join(json.dumps(q) + "\n" for q in queries))
    assert result.returncode == 0, result.stderr
    return [json.loads(line) for line in result.stdout.splitlines()]


def test_example_answers():
    answers = ask(EXAMPLE, {"op": "wing_count"}, {"op": "wing_uid", "wing": 1}, {"op": "wing_symmetry", "wing": "MainWing"},
                  {"op": "wing_segment_count", "wing": 1}, {"op": "wing_section_count", "wing": 1},
                  {"op": "fuselage_segment_count", "fuselage": "Fuselage"}, {"op": "wing_uid", "wing": 2},
                  {"op": "wing_wetted_area", "wing": 1}, {"op": "wing_volume", "wing": 1})
    assert answers[:6] == [{"ok": 1}, {"ok": "MainWing"}, {"ok": "x-z"}, {"ok": 2}, {"ok": 3}, {"ok": 3}]
    assert "out of range" in answers[6]["error"]
    assert 0 < answers[7]["ok"] < answers[8]["ok"] * 10
    assert answers[8]["ok"] > 0


def test_core_conformance_cases():
    cases = shared_path("conformance", "cases-core.json")
    result = subprocess.run([sys.executable, os.path.join(os.path.dirname(cases), "run.py"), "--airshape", BINARY,
                             "--data", shared_path("data", "cpacs"), cases], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout
    assert result.stdout.strip().splitlines()[-1].endswith(" 0 failed"), result.stdout
