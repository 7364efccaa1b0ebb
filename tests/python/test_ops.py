"""Every query op is a method of `Configuration.ops`, generated from the query registry
(bindings/generate_ops.py): its parameters are the op's arguments, its docstring the op's
summary, and a type checker holds calls to them."""
import inspect
import json
import os
import shutil
import subprocess

import pytest

import airshape
from airshape import _airshape

from conftest import AIRLINER, BUILD


@pytest.fixture(scope="module")
def config():
    return airshape.Configuration.open(AIRLINER)


def test_every_op_of_the_registry_is_a_method_with_its_arguments(config):
    ops = json.loads(_airshape.ops_description())
    assert len(ops) > 60
    for op in ops:
        method = getattr(config.ops, op["name"])
        parameters = list(inspect.signature(method).parameters)
        assert parameters == op["arguments"] + op["optional"], op["name"]
        assert op["summary"] in method.__doc__


def test_a_method_answers_as_the_query_does(config):
    assert config.ops.wing_span(wing="Wing") == config.query("wing_span", wing="Wing")
    assert config.ops.component_type(uid="FrontSpar") == "wing_spar"
    assert config.ops.bounding_box() == config.query("bounding_box")
    assert config.ops.component_faces(uid="Wing", mirrored=True) == config.query("component_faces", uid="Wing",
                                                                                  mirrored=True)
    with pytest.raises(AttributeError, match="no query op 'no_such_op'"):
        config.ops.no_such_op
    with pytest.raises(TypeError):
        config.ops.wing_span(1)  # arguments by name only, as in the query protocol


def test_a_component_has_every_op_that_takes_a_uid_as_a_method(config):
    ops = json.loads(_airshape.ops_description())
    spar = config.component("FrontSpar")
    for op in ops:
        if "uid" not in op["arguments"]:
            continue
        parameters = list(inspect.signature(getattr(spar.ops, op["name"])).parameters)
        assert parameters == [a for a in op["arguments"] if a != "uid"] + op["optional"], op["name"]
    assert spar.ops.component_volume() == config.query("component_volume", uid="FrontSpar")
    wing = config.wings["Wing"]
    assert wing.ops.component_faces(mirrored=True) == config.query("component_faces", uid="Wing", mirrored=True)
    flap = wing.control_surfaces[0]
    assert flap.ops.control_surface_deflection(control_parameter=1) == config.query(
        "control_surface_deflection", uid=flap.uid, control_parameter=1)


def test_a_type_checker_holds_calls_to_them(tmp_path):
    mypy = shutil.which("mypy")
    if mypy is None:
        pytest.fail("mypy is missing (scripts/test.sh installs it from Debian)")
    good = tmp_path / "good.py"
    good.write_text("import airshape\n"
                    "config = airshape.Configuration.open('a.xml')\n"
                    "config.ops.wing_upper_point(wing=1, segment='S', eta=0.5, xsi=0.25)\n"
                    "config.ops.component_faces(uid='Wing')\n"
                    "config.component('FrontSpar').ops.cross_section_area(point=[1, 2, 3], normal=[1, 0, 0])\n")
    bad = tmp_path / "bad.py"
    bad.write_text("import airshape\n"
                   "config = airshape.Configuration.open('a.xml')\n"
                   "config.ops.wing_upper_point(wing=1, segment=1, eta='half', xsi=0.25)\n"
                   "config.ops.component_faces(uid='Wing', flipped=True)\n"
                   "config.component('FrontSpar').ops.component_volume(uid='X')\n")
    environment = {**os.environ, "MYPYPATH": os.path.join(BUILD, "python")}
    arguments = [mypy, "--no-incremental", "--follow-imports=silent", "--ignore-missing-imports"]
    checked = subprocess.run(arguments + [str(good)], capture_output=True, text=True, env=environment, timeout=300)
    assert checked.returncode == 0, checked.stdout + checked.stderr
    refused = subprocess.run(arguments + [str(bad)], capture_output=True, text=True, env=environment, timeout=300)
    assert refused.returncode == 1, refused.stdout
    assert 'Argument "eta" to "wing_upper_point" of "Ops" has incompatible type "str"' in refused.stdout
    assert 'Unexpected keyword argument "flipped" for "component_faces" of "Ops"' in refused.stdout
    assert 'Unexpected keyword argument "uid" for "component_volume" of "ComponentOps"' in refused.stdout
