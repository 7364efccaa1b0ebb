"""Engine pylons (docs/nacelle.md) on the rectangular test wing's file: a pylon of the parabolic
CST airfoil (area 0.05·c² at chord c) whose chord grows linearly, 1, 2 and 3 at 0, 1 and 2 m
along its span, so that its smooth loft is the straight taper with volume ∫ 0.05·(1 + t)² dt."""
import json
import math
import os

from conftest import airshape, conformance_passed, query_answers as ask

RECTANGULAR = os.path.join(os.path.dirname(__file__), "..", "data", "wing-cst-rectangular.xml")


def pylon(uid="Pylon", parent="Rect", segments=True):
    sections = "".join(
        f'<section uID="{uid}S{i}"><name>s</name><transformation><scaling><x>{c}</x><y>{c}</y><z>{c}</z></scaling>'
        f'</transformation><elements><element uID="{uid}E{i}"><name>e</name><airfoilUID>Parabolic</airfoilUID>'
        f"<transformation/></element></elements></section>" for i, c in enumerate((1, 2, 3)))
    positionings = "".join(
        f'<positioning uID="{uid}P{i}"><name>p</name><length>{0 if i == 0 else 1}</length><sweepAngle>0</sweepAngle>'
        f"<dihedralAngle>0</dihedralAngle>{'' if i == 0 else f'<fromSectionUID>{uid}S{i - 1}</fromSectionUID>'}"
        f"<toSectionUID>{uid}S{i}</toSectionUID></positioning>" for i in range(3))
    chain = "".join(f'<segment uID="{uid}G{i}"><name>g</name><fromElementUID>{uid}E{i}</fromElementUID>'
                    f"<toElementUID>{uid}E{i + 1}</toElementUID></segment>" for i in range(2))
    return (f'<enginePylon uID="{uid}"><name>p</name><parentUID>{parent}</parentUID><transformation>'
            f'<translation refType="absLocal"><x>0</x><y>10</y><z>0</z></translation></transformation>'
            f"<sections>{sections}</sections><positionings>{positionings}</positionings>"
            f"{f'<segments>{chain}</segments>' if segments else ''}</enginePylon>")


def write(path):
    with open(RECTANGULAR) as original:
        text = original.read()
    pylons = f"<enginePylons>{pylon()}{pylon('Bare', segments=False)}</enginePylons>"
    path.write_text(text.replace("</wings>", "</wings>" + pylons, 1))


def test_pylon_loft_in_closed_form(tmp_path):
    path = tmp_path / "pylon.xml"
    write(path)
    volume, kind, box, first, second, segment_kind = ask(
        path, {"op": "component_volume", "uid": "Pylon"}, {"op": "component_type", "uid": "Pylon"},
        {"op": "bounding_box", "uid": "Pylon"}, {"op": "component_volume", "uid": "PylonG0"},
        {"op": "component_volume", "uid": "PylonG1"}, {"op": "component_type", "uid": "PylonG1"})
    assert kind == "engine_pylon" and segment_kind == "wing_segment"
    assert math.isclose(volume, 0.05 * (27 - 1) / 3, rel_tol=1e-9)
    # Its segments, which the reference library cannot build: the taper from chord 1 to 2, and 2 to 3.
    assert math.isclose(first, 0.05 * (8 - 1) / 3, rel_tol=1e-9)
    assert math.isclose(second, 0.05 * (27 - 8) / 3, rel_tol=1e-9)
    # Placed 10 m out along y from its parent wing, which sits at x = 1 (absLocal: relative to it).
    assert math.isclose(box["min"][1], 10, abs_tol=1e-6) and math.isclose(box["max"][1], 12, abs_tol=1e-6)
    assert math.isclose(box["min"][0], 1, abs_tol=1e-6) and math.isclose(box["max"][0], 1 + 3, abs_tol=1e-6)


def test_a_pylon_without_segments_has_no_shape(tmp_path):
    path = tmp_path / "pylon.xml"
    write(path)
    result = airshape("query", str(path), stdin=json.dumps({"op": "component_volume", "uid": "Bare"}) + "\n")
    answer = json.loads(result.stdout)
    assert "enginePylon[2]" in answer["error"] and "no segments" in answer["error"]


def test_nacelle_conformance_does_not_regress():
    passed, output = conformance_passed("cases-nacelle.json")
    assert passed >= 21, output[-3000:]
