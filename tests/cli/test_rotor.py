"""Rotors (QUERY-components §5, docs/rotor.md) on a rotorcraft of our own: rectangular
blades of the parabolic CST airfoil (z = ±0.15·x(1−x) on a unit chord), chord 0.3, from 0.5 m to
4.5 m off the hub, so that areas, volumes and radii have closed forms."""
import json
import math
import os

from conftest import airshape, conformance_passed, query_answers as ask

CHORD, ROOT, TIP = 0.3, 0.5, 4.5

# tests/data/rotorcraft-two-blades.xml: rotors "Main" (two blades, 300 rpm), "Clockwise" (three
# blades at listed azimuths on a 10° pitch hinge, −300 rpm) and "Orphan" (a blade that is missing).
HELI = os.path.join(os.path.dirname(__file__), "..", "data", "rotorcraft-two-blades.xml")


def test_two_bladed_rotor_in_closed_form():
    path = HELI
    (count, uid, blades, radius, reference, planform, solidity, tip, volume, box, clockwise_blades,
     clockwise_volume, clockwise_planform) = ask(
        path, {"op": "rotor_count"}, {"op": "rotor_uid", "rotor": 1}, {"op": "rotor_blade_count", "rotor": "Main"},
        {"op": "rotor_radius", "rotor": 1}, {"op": "rotor_reference_area", "rotor": 1},
        {"op": "rotor_total_blade_planform_area", "rotor": 1}, {"op": "rotor_solidity", "rotor": 1},
        {"op": "rotor_tip_speed", "rotor": 1}, {"op": "rotor_volume", "rotor": 1}, {"op": "bounding_box", "uid": "Main"},
        {"op": "rotor_blade_count", "rotor": 2}, {"op": "rotor_volume", "rotor": "Clockwise"},
        {"op": "rotor_total_blade_planform_area", "rotor": 2})
    assert count == 3 and uid == "Main" and blades == 2 and clockwise_blades == 3
    # The quarter-chord point of the tip, 0.075 behind the blade's axis, is farthest out.
    r = math.hypot(CHORD / 4, TIP)
    assert math.isclose(radius, r, rel_tol=1e-9) and math.isclose(reference, math.pi * r * r, rel_tol=1e-9)
    blade_planform = CHORD * (TIP - ROOT)
    assert math.isclose(planform, 2 * blade_planform, rel_tol=1e-9)
    assert math.isclose(solidity, 2 * blade_planform / (math.pi * r * r), rel_tol=1e-9)
    assert math.isclose(tip, 300 / 30 * math.pi * r, rel_tol=1e-9)
    # Each blade: the airfoil's area 0.05·c² over its span; hinges and mirroring keep it.
    blade_volume = 0.05 * CHORD ** 2 * (TIP - ROOT)
    assert math.isclose(volume, 2 * blade_volume, rel_tol=1e-6)
    assert math.isclose(clockwise_volume, 3 * blade_volume, rel_tol=1e-6)
    assert math.isclose(clockwise_planform, 3 * blade_planform, rel_tol=1e-9)
    # Blades at azimuth 0 and 180° reach ±4.5 along y, on the hub at z = 2.
    assert math.isclose(box["max"][1], TIP, abs_tol=1e-6) and math.isclose(box["min"][1], -TIP, abs_tol=1e-6)
    assert math.isclose(box["min"][2] + box["max"][2], 4, abs_tol=1e-6)


def test_rotor_errors_name_their_path():
    path = HELI
    queries = [{"op": "rotor_radius", "rotor": "Orphan"}, {"op": "rotor_uid", "rotor": 4}]
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    orphan, beyond = (json.loads(line) for line in result.stdout.splitlines())
    assert "rotor[3]/rotorHub/rotorBladeAttachments/rotorBladeAttachment[1]/rotorBladeUID" in orphan["error"]
    assert "rotor" in beyond["error"]


def errors_of(path, query):
    result = airshape("query", str(path), stdin=json.dumps(query) + "\n")
    return json.loads(result.stdout)["error"]


def test_blade_counts_and_azimuths_that_cannot_be_built_are_refused(tmp_path):
    text = open(HELI).read()
    many = tmp_path / "many-blades.xml"
    many.write_text(text.replace("<numberOfBlades>2</numberOfBlades>", "<numberOfBlades>1000000000</numberOfBlades>", 1))
    nan = tmp_path / "nan-azimuth.xml"
    nan.write_text(text.replace("<azimuthAngles mapType=\"vector\">", "<azimuthAngles mapType=\"vector\">nan;", 1))
    answer = errors_of(many, {"op": "rotor_blade_count", "rotor": "Main"})
    assert answer.endswith("rotorBladeAttachment[1]/numberOfBlades: 1000000000 blades, more than 1000; refused")
    answer = errors_of(nan, {"op": "rotor_volume", "rotor": "Clockwise"})
    assert answer.endswith("rotorBladeAttachment[1]/azimuthAngles: not a finite number (NaN or INF)")


def test_rotor_conformance_does_not_regress():
    passed, output = conformance_passed("cases-rotor.json")
    assert passed >= 79, output[-3000:]
