"""Engine pylons and nacelles (docs/nacelle.md) on the rectangular test wing's file. A pylon of the
parabolic CST airfoil (area 0.05·c² at chord c) whose chord grows linearly, 1, 2 and 3 at 0, 1 and
2 m along its span, so that its smooth loft is the straight taper with volume ∫ 0.05·(1 + t)² dt.
Nacelles whose one-section cowls are bodies of revolution: Pappus' theorem relates their volumes
at two radii to the area of their meridian section, and a cylindrical centre cowl has a closed
form."""
import json
import math
import os

from conftest import airshape, conformance_passed, query_answers as ask, shared_path



# tests/data/wing-with-engines.xml: the rectangular wing (at x = 1) with pylons and engines of our
# own. "Pylon": parabolic airfoil sections of chord 1, 2, 3 at 0, 1, 2 m along its span, placed 10 m
# out along y (absLocal); "Bare": a pylon without segments. Engines 20 m out along y, 0, 5, 10, 15,
# 20 m aft: "Low" and "High" (one section of a symmetric profile, chord 2, at radius 0.5 and 0.8),
# "Spun" (as "Low", with a centre cowl: the line at radius 0.1 from x = 0.5 to 1.5), "Hollow" (an
# engine without nacelle) and "Lofted" (three sections as "Low"'s at 0°, 120° and 240°).
ENGINES = os.path.join(os.path.dirname(__file__), "..", "data", "wing-with-engines.xml")


def test_pylon_loft_in_closed_form():
    path = ENGINES
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


def error_of(uid):
    """The error a component's volume answers with."""
    result = airshape("query", ENGINES, stdin=json.dumps({"op": "component_volume", "uid": uid}) + "\n")
    return json.loads(result.stdout)["error"]


def test_a_pylon_without_segments_has_no_shape():
    error = error_of("Bare")
    assert "enginePylon[2]" in error and "no segments" in error


def test_one_section_nacelles_are_bodies_of_revolution():
    path = ENGINES
    low, high, meridian, spun, kind, box = ask(
        path, {"op": "component_volume", "uid": "Low"}, {"op": "component_volume", "uid": "High"},
        {"op": "cross_section_area", "uid": "Low", "point": [0, 20, 0], "normal": [0, 0, 1]},
        {"op": "component_volume", "uid": "Spun"}, {"op": "component_type", "uid": "Low"},
        {"op": "bounding_box", "uid": "High"})
    assert kind == "engine_nacelle"
    # Pappus: moved 0.3 further from the axis, the meridian region A (the section by the plane
    # through the axis holds it twice) sweeps 2π · A · 0.3 more (the section's edges are OCCT's
    # approximations of the surfaces' intersection with the plane, to about 1e-5).
    assert math.isclose(high - low, 2 * math.pi * (meridian / 2) * 0.3, rel_tol=1e-5)
    # The centre cowl: the line at radius 0.1 from x = 0.5 to 1.5 swept into a cylinder.
    assert math.isclose(spun - low, math.pi * 0.1 ** 2 * 1.0, rel_tol=1e-6)
    # Placed 5 m aft and 20 m out along y of the wing (at x = 1): the chord 2 from x = 6 to 8.
    assert math.isclose(box["min"][0], 6, abs_tol=1e-3) and math.isclose(box["max"][0], 8, abs_tol=1e-3)
    assert math.isclose(box["max"][1] - 20, 20 - box["min"][1], abs_tol=1e-6)


def test_a_section_across_the_engine_is_a_ring_round_its_centre_cowl():
    # Across the axis, half way along the chord, "Low" is a ring (its hole taken off) and "Spun",
    # the same 10 m further aft, the same ring with the centre cowl's disc of radius 0.1 in its
    # hole (added again).
    ring, spun, outer = ask(
        ENGINES, {"op": "cross_section_area", "uid": "Low", "point": [2, 20, 0], "normal": [1, 0, 0]},
        {"op": "cross_section_area", "uid": "Spun", "point": [12, 20, 0], "normal": [-1, 0, 0]},
        {"op": "bounding_box", "uid": "Low"})
    assert math.isclose(spun - ring, math.pi * 0.1 ** 2, rel_tol=1e-6)
    radius = (outer["max"][2] - outer["min"][2]) / 2
    assert 0 < ring < 0.5 * math.pi * radius ** 2


def test_sections_lofted_around_the_engine():
    path = ENGINES
    revolved, lofted, box, revolved_box, pulled = ask(
        path, {"op": "component_volume", "uid": "Low"}, {"op": "component_volume", "uid": "Lofted"},
        {"op": "bounding_box", "uid": "Lofted"}, {"op": "bounding_box", "uid": "Low"},
        {"op": "bounding_box", "uid": "Chevron"})
    # Three equal sections at 0°, 120° and 240°: the patches run through each section (the one
    # at 0° on top gives the box's top, as the body of revolution of one does) ...
    assert math.isclose(box["max"][2], revolved_box["max"][2], abs_tol=1e-5)
    # ... symmetric about the x-z plane (the sections at 120° and 240° mirror each other) ...
    assert math.isclose(box["max"][1] - 20, 20 - box["min"][1], rel_tol=1e-6)
    # ... and between its guides (circles here) each patch blends the two sections' outlines
    # straight across the sector, the guides adding their bulge as a blend across the cell: half
    # way between two sections the outline's radius counts half (86 % of the body of
    # revolution; a surface smooth around the engine through the sections keeps 97.7 %).
    assert revolved * 0.82 < lofted < revolved * 0.9
    # A guide curve profile with rY = −0.1 at rX = 0.5 pulls the leading edge forward by
    # 0.1 chord (0.2 m) half way between the first two sections (placed at x = 25 + 1).
    assert math.isclose(pulled["min"][0], 26 - 0.2, abs_tol=5e-3)
    assert math.isclose(box["min"][0], 21, abs_tol=5e-3)


def test_an_engine_without_nacelle_has_no_shape():
    error = error_of("Hollow")
    assert "has no nacelle" in error and "vehicles/engines/engine[6]" in error


def edited_engines(path, old, new):
    """The engines file written to `path` with the one piece `old` replaced by `new`."""
    with open(ENGINES) as original:
        text = original.read()
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new))
    return path


def test_an_engine_placed_beyond_any_precision_is_refused_and_the_rest_builds(tmp_path):
    # A placement 1e300 away is finite, but OCCT's shape check crashed on the nacelle moved
    # there; a transformation's numbers beyond 1e9 are refused, naming the number.
    placed = '<engine uID="High"><name>p</name><engineUID>HighEngine</engineUID><parentUID>Rect</parentUID><transformation><translation><x>5</x><y>20</y><z>0</z>'
    path = edited_engines(tmp_path / "far.xml", placed, placed.replace("<z>0</z>", "<z>1e300</z>"))
    result = airshape("build", str(path))
    assert result.returncode == 1, result.stderr
    assert "engines/engine[2]/transformation/translation/z: 1e+300 is beyond 1e+09" in result.stdout + result.stderr
    assert "Low " in result.stdout and "FAILED" not in result.stdout.split("Low ")[1].splitlines()[0]


def test_two_sections_at_one_angle_are_refused_naming_them(tmp_path):
    # The third section of the lofted cowl moved onto the second's angle: no patch fits between.
    third = '<section uID="ThreeSectionEngineS2"><name>s</name><transformation><scaling><x>2</x><y>1</y><z>1</z></scaling><translation><x>240</x>'
    path = edited_engines(tmp_path / "same.xml", third, third.replace("<x>240</x>", "<x>120</x>"))
    result = airshape("query", str(path), stdin='{"op":"component_volume","uid":"Lofted"}\n{"op":"component_volume","uid":"Low"}\n')
    lofted, low = (json.loads(line) for line in result.stdout.splitlines())
    assert "engines/engine[4]/nacelle/fanCowl/sections" in lofted["error"], lofted
    assert "'ThreeSectionEngineS1' and 'ThreeSectionEngineS2' lie at the same angle" in lofted["error"], lofted
    assert low["ok"] > 0


def test_configuration_length_leaves_nacelles_and_empty_pylons_out():
    length, whole, *parts = ask(ENGINES, {"op": "configuration_length"}, {"op": "bounding_box"},
                                *({"op": "bounding_box", "uid": uid} for uid in ("Rect", "Swept", "Pylon")))
    # The wings and the pylon make the configuration's box; the nacelles 5 to 20 m aft of the
    # wing and the pylon without segments are no part of it (QUERY-components §7).
    front = min(box["min"][0] for box in parts)
    back = max(box["max"][0] for box in parts)
    assert math.isclose(length, back - front, abs_tol=1e-9) and back < 10
    assert whole["min"][0] == front and whole["max"][0] == back


def test_nacelle_conformance_does_not_regress():
    passed, output = conformance_passed("cases-nacelle.json")
    # 2 of 44 do not pass: two volumes, each traced in docs/conformance.md.
    assert passed >= 42, output[-3000:]


def test_a_lofted_nacelle_does_not_depend_on_what_was_built_before():
    # A cowl of three sections was once a Gordon surface around the engine, whose parts, made
    # compatible, had a knot inserted twice, so that OCCT read poles it had not written and the
    # nacelle came out different after other work in the same process (here an intersection
    # first). It is kept for the patches that replaced it.
    path = shared_path("data", "cpacs", "simpletest-pylon-nacelle.cpacs.xml")
    area = {"op": "component_surface_area", "uid": "SimpleEnginePositioning"}
    box = {"op": "bounding_box", "uid": "SimpleEnginePositioning"}
    alone = ask(path, area, box)
    after = ask(path, {"op": "intersection_count", "uid1": "Wing", "uid2": "SimpleFuselage"}, area, box)[1:]
    assert alone == after


def cst_side(x, n1, n2, coefficients):
    n = len(coefficients) - 1
    shape = sum(b * math.comb(n, i) * x ** i * (1 - x) ** (n - i) for i, b in enumerate(coefficients))
    return x ** n1 * (1 - x) ** n2 * shape


def with_cowl_profile(tmp_path, name, profile_xml):
    with open(ENGINES) as original:
        text = original.read()
    start = text.index('<nacelleProfile uID="Cowl">')
    end = text.index("</nacelleProfile>", start) + len("</nacelleProfile>")
    path = tmp_path / name
    path.write_text(text[:start] + f'<nacelleProfile uID="Cowl"><name>c</name>{profile_xml}</nacelleProfile>' +
                    text[end:])
    return path


def test_a_cst_cowl_profile_is_the_curve_its_formula_gives(tmp_path):
    # A round-nosed symmetric CST profile (N1 = 0.5, N2 = 1, B = 0.1, 0.12, 0.1) against the same
    # formula written out as a dense point list: the two cowls agree as closely as the points' curve
    # follows the formula.
    upper_b = [0.1, 0.12, 0.1]
    cst = ("<cst2D><psi>0;1</psi><upperN1>0.5</upperN1><upperN2>1</upperN2><upperB>0.1;0.12;0.1</upperB>"
           "<lowerN1>0.5</lowerN1><lowerN2>1</lowerN2><lowerB>0.1;0.12;0.1</lowerB></cst2D>")
    xs = [(1 - math.cos(math.pi * k / 1600)) / 2 for k in range(1601)]
    lower = [(x, -cst_side(x, 0.5, 1, upper_b)) for x in reversed(xs)]
    upper = [(x, cst_side(x, 0.5, 1, upper_b)) for x in xs[1:]]
    points = lower + upper
    listed = (f"<pointList><x>{';'.join(repr(x) for x, _ in points)}</x>"
              f"<y>{';'.join(repr(y) for _, y in points)}</y></pointList>")
    by_formula, box, meridian, high = ask(
        with_cowl_profile(tmp_path, "cst.xml", cst), {"op": "component_volume", "uid": "Low"},
        {"op": "bounding_box", "uid": "Low"},
        {"op": "cross_section_area", "uid": "Low", "point": [0, 20, 0], "normal": [0, 0, 1]},
        {"op": "component_volume", "uid": "High"})
    by_points, = ask(with_cowl_profile(tmp_path, "listed.xml", listed), {"op": "component_volume", "uid": "Low"})
    assert math.isclose(by_formula, by_points, rel_tol=1e-7)
    # Chord 2 from x = 1 to 3 (placed at the wing, x = 1), and Pappus between the two radii.
    assert math.isclose(box["min"][0], 1, abs_tol=1e-6) and math.isclose(box["max"][0], 3, abs_tol=1e-6)
    assert math.isclose(high - by_formula, 2 * math.pi * (meridian / 2) * 0.3, rel_tol=1e-5)


def test_a_broken_cst_cowl_profile_names_its_path(tmp_path):
    cst = ("<cst2D><psi>0;1</psi><upperN1>-0.5</upperN1><upperN2>1</upperN2><upperB>0.1</upperB>"
           "<lowerN1>0.5</lowerN1><lowerN2>1</lowerN2><lowerB>0.1</lowerB></cst2D>")
    result = airshape("query", str(with_cowl_profile(tmp_path, "broken.xml", cst)),
                      stdin=json.dumps({"op": "component_volume", "uid": "Low"}) + "\n")
    error = json.loads(result.stdout)["error"]
    assert "nacelleProfile[1]/cst2D/upperN1" in error and "must not be negative" in error


def test_the_rotation_curve_is_read_from_its_trailing_end_and_joined_by_name(tmp_path):
    # The same inner line written the other way round: the cowl does not change.
    reversed_line = edited_engines(tmp_path / "reversed.xml", "<x>0;1</x><y>-0.06;-0.06</y>",
                                   "<x>1;0</x><y>-0.06;-0.06</y>")
    query = {"op": "component_volume", "uid": "Low"}
    assert ask(reversed_line, query) == ask(ENGINES, query)
    # startZeta ahead of endZeta while startZetaBlending lies behind endZetaBlending: joined by
    # name, the blending lines cross. Built as given, with one warning naming the rotation curve.
    low = "<startZeta>-0.6</startZeta><endZeta>-0.3</endZeta>"
    text = open(ENGINES).read()
    crossing = tmp_path / "crossing.xml"
    crossing.write_text(text.replace(low, "<startZeta>-0.3</startZeta><endZeta>-0.6</endZeta>", 1))
    built = airshape("build", str(crossing))
    warnings = [line for line in built.stderr.splitlines() if "cross itself" in line]
    assert len(warnings) == 1, built.stderr
    assert "engines/engine[1]/nacelle/fanCowl/rotationCurve: the cowl's blending lines, joined by name" in warnings[0]
    line = next(line for line in built.stdout.splitlines() if " Low " in line)
    assert "solid" in line and "FAILED" not in line, line
    assert ask(crossing, query)[0] != ask(ENGINES, query)[0]
