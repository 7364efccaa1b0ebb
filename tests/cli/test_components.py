"""Every component is queryable (QUERY-components §1-§2, §4, §6): its type, and the exact
measures of its shape, on files the test writes itself where the numbers have a closed form."""
import json
import math
import os

from conftest import EXAMPLE, airshape, conformance_passed, query_answers as ask
from test_fuselage import write_cylinders


def answers(path, *queries):
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    return [json.loads(line) for line in result.stdout.splitlines()]


def test_types_of_the_model_its_components_and_their_parts():
    types = ask(EXAMPLE, *({"op": "component_type", "uid": uid} for uid in
                           ("ExampleAircraft", "Fuselage", "FSeg2", "MainWing", "WSeg1")))
    assert types == ["plane", "fuselage", "fuselage_segment", "wing", "wing_segment"]


def test_measures_of_a_cylinder_and_its_segments(tmp_path):
    path = tmp_path / "cylinders.xml"
    write_cylinders(path)  # a cylinder of radius 1 and length 10 from x = 0, two segments
    volume, area, segment, section, slanted = ask(
        path, {"op": "component_volume", "uid": "Full"}, {"op": "component_surface_area", "uid": "Full"},
        {"op": "component_volume", "uid": "FullG1"},
        {"op": "cross_section_area", "uid": "Full", "point": [3, 0, 0], "normal": [2, 0, 0]},
        {"op": "cross_section_area", "uid": "Full", "point": [5, 0, 0], "normal": [1, 0, 1]})
    assert math.isclose(volume, math.pi * 10, rel_tol=1e-5), volume
    assert math.isclose(area, 2 * math.pi * 10 + 2 * math.pi, rel_tol=1e-5), area  # caps included
    assert math.isclose(segment, math.pi * 5, rel_tol=1e-5), segment
    assert math.isclose(section, math.pi, rel_tol=1e-5), section
    assert math.isclose(slanted, math.pi * math.sqrt(2), rel_tol=1e-5), slanted  # an ellipse with axes 1, sqrt 2


def test_a_component_segment_and_its_segments_make_up_the_wing():
    wing, first, second, box = ask(EXAMPLE, {"op": "component_volume", "uid": "MainWing"},
                                   {"op": "component_volume", "uid": "WSeg1"},
                                   {"op": "component_volume", "uid": "WSeg2"},
                                   {"op": "bounding_box", "uid": "WSeg1"})
    assert math.isclose(first + second, wing, rel_tol=1e-8), (first, second, wing)
    assert box["min"][1] < box["max"][1]


def test_a_component_segment_is_the_references_loft_without_the_blunt_trailing_edge(tmp_path):
    # The rectangular wing (chord 2, span 5) of parabolic arcs, given a blunt trailing edge and
    # a component segment over its one segment: the component segment's shape (QUERY-components
    # §1, as the reference lofts it) has the skins and caps but not the strip between the
    # trailing edges, 5 m long and as high as the edge; it is held open as a solid, so its
    # volume (about the mean of its vertices) is a little less than the wing's.
    text = open(os.path.join(os.path.dirname(__file__), "..", "data", "wing-cst-rectangular.xml")).read()
    text = text.replace("<lowerB mapType=\"vector\">0.15</lowerB>",
                        "<lowerB mapType=\"vector\">0.15</lowerB><trailingEdgeThickness>0.01</trailingEdgeThickness>", 1)
    text = text.replace('<segments><segment uID="RS">',
                        '<componentSegments><componentSegment uID="RectCS"><name>cs</name>'
                        "<fromElementUID>R1E</fromElementUID><toElementUID>R2E</toElementUID>"
                        "</componentSegment></componentSegments>"
                        '<segments><segment uID="RS">', 1)
    path = tmp_path / "blunt.xml"
    path.write_text(text)
    wing_area, cs_area, wing_volume, cs_volume, upper, lower, wing_box, cs_box = answers(
        path, {"op": "component_surface_area", "uid": "Rect"}, {"op": "component_surface_area", "uid": "RectCS"},
        {"op": "component_volume", "uid": "Rect"}, {"op": "component_volume", "uid": "RectCS"},
        {"op": "wing_upper_point", "wing": "Rect", "segment": 1, "eta": 0.5, "xsi": 1},
        {"op": "wing_lower_point", "wing": "Rect", "segment": 1, "eta": 0.5, "xsi": 1},
        {"op": "bounding_box", "uid": "Rect"}, {"op": "bounding_box", "uid": "RectCS"})
    height = upper["ok"][2] - lower["ok"][2]
    assert height > 0.01, (upper, lower)
    assert math.isclose(wing_area["ok"] - cs_area["ok"], 5 * height, rel_tol=1e-9), (wing_area, cs_area, height)
    # The strip's missing share (1/3)(x − O)·n A, O within the chord (x from 1 to 3), the strip at x = 3.
    missing = wing_volume["ok"] - cs_volume["ok"]
    assert 0 < missing <= 2 / 3 * 5 * height, (wing_volume, cs_volume)
    assert cs_box == wing_box


def test_where_the_wing_meets_the_fuselage():
    count, length, reversed_length, curves = ask(
        EXAMPLE, {"op": "intersection_count", "uid1": "MainWing", "uid2": "Fuselage"},
        {"op": "intersection_length", "uid1": "MainWing", "uid2": "Fuselage"},
        {"op": "intersection_length", "uid1": "Fuselage", "uid2": "MainWing"},
        {"op": "intersection_curves", "uid": "MainWing", "other": "Fuselage", "deflection": 1e-5})
    assert count == len(curves) >= 1
    polyline = sum(math.dist(a, b) for line in curves for a, b in zip(line, line[1:]))
    assert math.isclose(length, polyline, rel_tol=1e-3), (length, polyline)  # exact arc length, not chords
    assert math.isclose(length, reversed_length, rel_tol=1e-7)  # the order does not matter


def test_a_fuselage_that_cannot_be_built_is_left_out(tmp_path):
    path = tmp_path / "cylinders.xml"
    write_cylinders(path)
    # Reversed, the second segment ends where the first does: no chain of segments.
    text = path.read_text().replace("<fromElementUID>FullE1</fromElementUID><toElementUID>FullE2</toElementUID>",
                                    "<fromElementUID>FullE2</fromElementUID><toElementUID>FullE1</toElementUID>")
    path.write_text(text)
    listed, length, volume = answers(path, {"op": "component_list"}, {"op": "configuration_length"},
                                     {"op": "component_volume", "uid": "Full"})
    uids = [entry["uid"] for entry in listed["ok"]]
    assert "HalfCylinder" in uids and "Full" not in uids and "FullG1" not in uids
    assert math.isclose(length["ok"], 10, abs_tol=1e-6)  # the half cylinder alone
    assert "continuous chain" in volume["error"] and "fuselage[1]/segments" in volume["error"]


def test_errors_name_what_is_wrong():
    wrong = answers(EXAMPLE, {"op": "component_type", "uid": "Nobody"},
                    {"op": "component_volume", "uid": "ExampleAircraft"},
                    {"op": "cross_section_area", "uid": "Fuselage", "point": [1, 0, 0], "normal": [0, 0, 0]},
                    {"op": "intersection_count", "uid1": "MainWing", "uid2": "MainWing"},
                    {"op": "cross_section_area", "uid": "Fuselage", "point": [1, 0], "normal": [1, 0, 0]},
                    {"op": "bounding_box", "uid": "ExampleAircraft"}, {"op": "component_faces", "uid": "ExampleAircraft"})
    assert wrong[0] == {"error": "no component with uID 'Nobody'"}
    # The model has no shape, whichever op asks for it (the box said "no builder yet for model").
    for answer in (wrong[1], wrong[5], wrong[6]):
        assert answer == {"error": "'ExampleAircraft' is the model (type plane): it has no shape"}, answer
    assert wrong[2] == {"error": "the normal must not be zero"}
    assert "same component" in wrong[3]["error"]
    assert wrong[4] == {"error": "argument 'point' must be [x, y, z]"}


def test_component_conformance_does_not_regress():
    passed, output = conformance_passed("cases-components.json")
    assert passed >= 1471 and output.strip().endswith(" 0 failed"), output[-3000:]  # every case
