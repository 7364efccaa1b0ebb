"""Wing geometry on wings whose numbers are known in closed form (tests/data/wing-cst-rectangular.xml)."""
import json
import math
import os
import subprocess
import sys

from conftest import BINARY, DATA, airshape, shared_path

WINGS = os.path.join(DATA, "wing-cst-rectangular.xml")


def ask(*queries):
    result = airshape("query", WINGS, stdin="".join(json.dumps(q) + "\n" for q in queries))
    assert result.returncode == 0, result.stderr
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert all("ok" in a for a in answers), answers
    return [a["ok"] for a in answers]


def parabola_arc(chord, height):
    """Length of z = 4h·x(1−x)/c² ... here z = k·x(c−x)/c over [0, c] with peak `height`."""
    a = 4 * height / chord  # slope at the ends
    return chord / 2 * math.sqrt(1 + a * a) + chord * chord / (8 * height) * math.asinh(a) if height else chord


def test_rectangular_cst_wing_in_closed_form():
    chord, span, b = 2.0, 5.0, 0.15
    volume, area, skin, reference, mac, wing_span = ask(
        {"op": "wing_volume", "wing": "Rect"}, {"op": "wing_surface_area", "wing": "Rect"},
        {"op": "wing_segment_surface_area", "wing": "Rect", "segment": 1},
        {"op": "wing_reference_area", "wing": "Rect", "plane": "x-y"}, {"op": "wing_mac", "wing": "Rect"},
        {"op": "wing_span", "wing": "Rect"})
    profile_area = 2 * b * chord * chord / 6  # two parabolic arcs of height b·c/4
    assert math.isclose(volume, profile_area * span, rel_tol=1e-9)
    side = parabola_arc(chord, b * chord / 4)
    assert math.isclose(skin, 2 * side * span, rel_tol=1e-7)
    assert math.isclose(area, 2 * side * span + 2 * profile_area, rel_tol=1e-7)
    assert math.isclose(reference, chord * span, rel_tol=1e-12)
    assert math.isclose(mac["mac"], chord, rel_tol=1e-12)
    assert math.isclose(wing_span, span + 2 * (1e-4 + 1e-7), rel_tol=1e-9)


def test_points_follow_the_placement():
    upper, lower, chord_point, le_tip = ask(
        {"op": "wing_upper_point", "wing": "Rect", "segment": "RS", "eta": 0.5, "xsi": 0.5},
        {"op": "wing_lower_point", "wing": "Rect", "segment": 1, "eta": 0.0, "xsi": 0.5},
        {"op": "wing_chord_point", "wing": "Rect", "segment": 1, "eta": 1.0, "xsi": 1.0},
        {"op": "wing_chord_point", "wing": "Swept", "segment": 1, "eta": 1.0, "xsi": 0.0})
    # Rect: translated by x = 1; xsi = x/c for N1 = N2 = 1; thickness 2·0.15·0.25·c at mid-chord.
    assert all(math.isclose(u, e, abs_tol=1e-12) for u, e in zip(upper, [1 + 1.0, 2.5, 0.075]))
    assert all(math.isclose(u, e, abs_tol=1e-12) for u, e in zip(lower, [2.0, 0.0, -0.075]))
    assert all(math.isclose(u, e, abs_tol=1e-12) for u, e in zip(chord_point, [3.0, 5.0, 0.0]))
    # Swept: the tip LE sits at the positioning vector L·(sin φ, cos φ cos ψ, cos φ sin ψ).
    phi, psi = math.radians(30), math.radians(5)
    expected = [10 * math.sin(phi), 10 * math.cos(phi) * math.cos(psi), 10 * math.cos(phi) * math.sin(psi)]
    assert all(math.isclose(u, e, abs_tol=1e-12) for u, e in zip(le_tip, expected))


def test_swept_tapered_wing():
    reference, span, symmetry, tip_te = ask(
        {"op": "wing_reference_area", "wing": "Swept", "plane": "x-y"}, {"op": "wing_span", "wing": "Swept"},
        {"op": "wing_symmetry", "wing": "Swept"}, {"op": "wing_chord_point", "wing": "Swept", "segment": 1, "eta": 1, "xsi": 1})
    # The tip is twisted by 3° about y, so its chord tilts: TE = LE + 2·(cos 3°, 0, sin 3°).
    phi, psi = math.radians(30), math.radians(5)
    le = [10 * math.sin(phi), 10 * math.cos(phi) * math.cos(psi), 10 * math.cos(phi) * math.sin(psi)]
    twist = math.radians(3)
    assert all(math.isclose(u, e, abs_tol=1e-12) for u, e in zip(tip_te, [le[0] + 2 * math.cos(twist), le[1], le[2] + 2 * math.sin(twist)]))
    # Projected onto x-y: a trapezoid with parallel chords 4 and 2·cos 3° and height y_tip.
    assert math.isclose(reference, (4 + 2 * math.cos(twist)) / 2 * le[1], rel_tol=1e-12)
    assert symmetry == "x-z"
    assert span > 2 * le[1]  # mirrored: tip to tip


def test_bad_arguments_are_errors():
    result = airshape("query", WINGS, stdin='{"op":"wing_upper_point","wing":1,"segment":1,"eta":1.5,"xsi":0}\n'
                                               '{"op":"wing_reference_area","wing":1,"plane":"a-b"}\n'
                                               '{"op":"wing_volume","wing":3}\n')
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert all("error" in a for a in answers), answers


def test_wing_conformance_does_not_regress():
    cases = shared_path("conformance", "cases-wing.json")
    result = subprocess.run([sys.executable, os.path.join(os.path.dirname(cases), "run.py"), "--airshape", BINARY,
                             "--data", shared_path("data", "cpacs"), cases], capture_output=True, text=True, timeout=900)
    passed = int(result.stdout.strip().splitlines()[-1].split()[0])
    # The wing plugin is not finished (guide curves, NACA airfoils, rotor blades and wetted
    # area are open; see docs/wing.md). This floor only guards what works.
    assert passed >= 510, result.stdout[-3000:]


def test_points_map_back_to_eta_and_xsi():
    upper, lower = ask({"op": "wing_upper_point", "wing": "Rect", "segment": 1, "eta": 0.3, "xsi": 0.7},
                       {"op": "wing_lower_point", "wing": "Rect", "segment": 1, "eta": 0.8, "xsi": 0.4})
    on_upper, on_lower = ask({"op": "wing_segment_eta_xsi", "wing": "Rect", "x": upper[0], "y": upper[1], "z": upper[2]},
                             {"op": "wing_segment_eta_xsi", "wing": "Rect", "x": lower[0], "y": lower[1], "z": lower[2]})
    assert on_upper["segment"] == "RS" and on_upper["on_top"] is True
    assert math.isclose(on_upper["eta"], 0.3, abs_tol=1e-7) and math.isclose(on_upper["xsi"], 0.7, abs_tol=1e-7)
    assert on_lower["on_top"] is False
    assert math.isclose(on_lower["eta"], 0.8, abs_tol=1e-7) and math.isclose(on_lower["xsi"], 0.4, abs_tol=1e-7)
    far = airshape("query", WINGS, stdin='{"op":"wing_segment_eta_xsi","wing":"Rect","x":100,"y":0,"z":0}\n')
    assert "lies on no segment" in json.loads(far.stdout)["error"]


def test_bounding_box_and_wetted_area():
    box, wetted, area, everything = ask({"op": "bounding_box", "uid": "Rect"}, {"op": "wing_wetted_area", "wing": "Rect"},
                                         {"op": "wing_surface_area", "wing": "Rect"}, {"op": "bounding_box"})
    # Rect: chord 2 from x = 1, span 5 along y, parabolic sides of height 0.15·0.25·2 = 0.075.
    for got, want in zip(box["min"] + box["max"], [1, 0, -0.075, 3, 5, 0.075]):
        assert math.isclose(got, want, abs_tol=1e-6)
    assert math.isclose(wetted, area, rel_tol=1e-12), "a wing without a parent is wetted all over"
    assert everything["min"][1] < -5, "the whole configuration includes the mirrored swept wing"


def test_wetted_area_leaves_out_the_part_inside_the_parent():
    example = os.path.join(os.path.dirname(DATA), "..", "examples", "example-aircraft.xml")
    result = airshape("query", example, stdin='{"op":"wing_wetted_area","wing":1}\n{"op":"wing_surface_area","wing":1}\n')
    wetted, area = (json.loads(line)["ok"] for line in result.stdout.splitlines())
    assert 0.5 * area < wetted < area
