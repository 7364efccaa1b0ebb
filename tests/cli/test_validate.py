"""`airshape validate` lists every problem with its XPath and exits 1 if there is any."""
import os

from conftest import DATA, EXAMPLE, airshape


def test_the_example_is_valid():
    result = airshape("validate", EXAMPLE)
    assert result.returncode == 0, result.stdout
    assert "0 problems" in result.stdout


def test_every_kind_of_flaw_is_listed():
    path = os.path.join(DATA, "flawed.xml")
    result = airshape("validate", path)
    assert result.returncode == 1
    fuselage = "/cpacs/vehicles/aircraft/model[1]/fuselages/fuselage[1]"
    expected = [
        f"{fuselage}: missing required element 'name'",
        f"{fuselage}/@symmetry: 'diagonal' is not one of none, inherit, x-y-plane, x-z-plane, y-z-plane",
        f"{fuselage}/transformation/scaling/x: 'big' is not a number",
        "/cpacs/vehicles/aircraft/model[1]/wings/wing[1]/transformation: element 'transformation' occurs 2 times, at most once allowed",
        "/cpacs/vehicles/aircraft/model/fuselages/fuselage[2]: duplicate uID 'F'",
        "/cpacs/vehicles/aircraft/model[1]/wings/wing[1]/parentUID: uIDref 'NoSuchFuselage' points to no element",
    ]
    for line in expected:
        assert line in result.stdout, f"{line!r} not in:\n{result.stdout}"


def test_loading_warns_about_what_it_ignores():
    result = airshape("info", os.path.join(DATA, "flawed.xml"))
    assert result.returncode == 0
    assert "warning" in result.stderr and "duplicate uID 'F'" in result.stderr
    assert result.stdout.count("fuselage F") == 1, "the repeated fuselage is left out"


def test_build_reports_valid_solids():
    result = airshape("build", EXAMPLE)
    assert result.returncode == 0, result.stdout
    assert result.stdout.count("valid solid") == 2, result.stdout
