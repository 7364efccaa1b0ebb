"""Every command meets bad input with one clear line on stderr, exit status 2, and no crash."""
import json
import os

import pytest

from conftest import DATA, EXAMPLE, airshape

COMMANDS = [["info"], ["query"], ["validate"], ["save", "-o", "/tmp/airshape-never-written.xml"]]


def bad_inputs(tmp_path):
    files = {
        "missing": str(tmp_path / "missing.xml"),
        "empty": tmp_path / "empty.xml",
        "truncated": tmp_path / "truncated.xml",
        "binary": tmp_path / "binary.xml",
        "not-cpacs": tmp_path / "not-cpacs.xml",
        "cpacs2": os.path.join(DATA, "cpacs2.xml"),
        "no-version": os.path.join(DATA, "no-version.xml"),
        "cycle": os.path.join(DATA, "parent-cycle.xml"),
    }
    files["empty"].write_text("")
    files["truncated"].write_text('<?xml version="1.0"?>\n<cpacs><header><cpacsVersion>3.5</cpacsVersion></head')
    files["binary"].write_bytes(bytes(range(256)) * 8)
    files["not-cpacs"].write_text("<html><body>hello</body></html>")
    return {name: str(path) for name, path in files.items()}


EXPECTED = {
    "missing": "no such file",
    "empty": "is empty",
    "truncated": "not well-formed XML",
    "binary": "not well-formed XML",
    "not-cpacs": "not a CPACS document",
    "cpacs2": "is a CPACS 2 file",
    "no-version": "declares no CPACS version",
    "cycle": "parentUID cycle between components",
}


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: c[0])
@pytest.mark.parametrize("kind", sorted(EXPECTED))
def test_bad_input_gives_one_clear_line(tmp_path, command, kind):
    path = bad_inputs(tmp_path)[kind]
    result = airshape(command[0], path, *command[1:], stdin="")
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert path in lines[0] and EXPECTED[kind] in lines[0], lines[0]
    assert "terminate" not in result.stderr and "Traceback" not in result.stderr
    assert not os.path.exists("/tmp/airshape-never-written.xml")


def test_unknown_command_and_usage():
    assert airshape("frobnicate").returncode == 2
    assert airshape().returncode == 2
    assert airshape("info").returncode == 2
    result = airshape("help", "save")
    assert result.returncode == 0 and "--in-place" in result.stdout


def test_component_segment_ops_on_a_wing_without_component_segments():
    # The fuzzing round found the wing's component-segment list used before it was checked.
    answers = airshape("query", EXAMPLE, stdin='{"op":"component_segment_to_segment","wing":1,"component_segment":1,'
                       '"eta":0.5,"xsi":0.5}\n{"op":"segment_to_component_segment","wing":1,"segment":1,'
                       '"component_segment":"CS","eta":0.5,"xsi":0.5}\n')
    assert answers.returncode == 0, answers.stderr
    index, uid = (json.loads(line) for line in answers.stdout.splitlines())
    assert index == {"error": "component segment index 1 is out of range (there are 0 component segments)"}
    assert uid == {"error": "no component segment with uID 'CS'"}
