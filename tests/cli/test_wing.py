"""Wing geometry on wings whose numbers are known in closed form (tests/data/wing-cst-rectangular.xml)."""
import json
import math
import os

from conftest import DATA, airshape, conformance_passed, query_answers as ask_file, shared_path

WINGS = os.path.join(DATA, "wing-cst-rectangular.xml")


def ask(*queries):
    return ask_file(WINGS, *queries)


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
    passed, output = conformance_passed("cases-wing.json")
    assert passed >= 564 and output.strip().endswith(" 0 failed"), output[-3000:]  # every case


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


def test_a_segment_of_zero_length_is_an_error(tmp_path):
    """Two sections in one place: the segment between them encloses nothing, and says so; the
    wing has no span, so no mean aerodynamic chord either."""
    path = tmp_path / "flat.xml"
    sections = "".join(
        f'<section uID="ZS{i}"><name>s</name><transformation/><elements><element uID="ZE{i}"><name>e</name>'
        f"<airfoilUID>Parabolic</airfoilUID><transformation/></element></elements></section>" for i in range(2))
    segments = ('<segment uID="ZW"><name>s</name><fromElementUID>ZE0</fromElementUID>'
                "<toElementUID>ZE1</toElementUID></segment>")
    write_wing(path, "Flat", sections, segments, "")
    result = airshape("query", str(path), stdin='{"op":"wing_segment_volume","wing":"Flat","segment":1}\n')
    answer = json.loads(result.stdout)
    assert answer.get("error", "").startswith("/cpacs/vehicles/aircraft/model[1]/wings/wing[1]/segments/segment[1]: "), answer
    assert "no volume" in answer["error"], answer
    mac = json.loads(airshape("query", str(path), stdin='{"op":"wing_mac","wing":"Flat"}\n').stdout)
    assert mac.get("error") == ("/cpacs/vehicles/aircraft/model[1]/wings/wing[1]: "
                                "the wing has no span, so no mean aerodynamic chord"), mac


def test_a_profile_flattened_to_a_line_is_an_error(tmp_path):
    """A section scaled to no thickness: no cap closes its profile (the solid was invalid)."""
    text = open(os.path.join(os.path.dirname(DATA), "..", "examples", "generic-airliner.xml")).read()
    at = text.index('uID="Wing_S3_E_T"')
    scaling = text.index("<z>", at)
    path = tmp_path / "flat.xml"
    path.write_text(text[:scaling] + "<z>0</z>" + text[text.index("</z>", scaling) + 4:])
    result = airshape("build", str(path))
    wing = next(line for line in result.stdout.splitlines() if line.split()[:2] == ["wing", "Wing"])
    assert "FAILED: /cpacs/vehicles/aircraft/model[1]/wings/wing[1]/segments/segment[2]: " in wing, wing
    assert "encloses no area" in wing, wing


def flattened_section_build(source, path, section, thickness):
    """`airshape build` of `source` with the section's scaling in z set to `thickness`: the
    report line of the wing that section belongs to."""
    text = open(source).read()
    scaling = text.index("<scaling", text.index(f'uID="{section}"'))
    z = text.index("<z>", scaling)
    path.write_text(text[:z] + f"<z>{thickness}</z>" + text[text.index("</z>", z) + 4:])
    wing = text[:scaling].rsplit("<wing ", 1)[1].split('"')[1]
    result = airshape("build", str(path))
    return next(line for line in result.stdout.splitlines() if line.split()[:2] == ["wing", wing])


def test_a_guided_wing_flattened_where_its_solid_stays_valid_is_kept(tmp_path):
    """Sections scaled to almost no thickness pinch the guided test wing; it stays a valid solid."""
    guided = tmp_path / "guided.xml"
    guided_wing(guided, "C0")
    for section in ("GS0", "GS1", "GS2"):
        line = flattened_section_build(guided, tmp_path / "flat.xml", section, "1e-9")
        assert "valid solid" in line and "INVALID" not in line, (section, line)


def test_a_guided_wing_flattened_at_its_root_or_tip_is_an_error_where_its_solid_is_invalid(tmp_path):
    """The guided skin only approximates a section scaled to almost no thickness: sewn to it,
    a root or tip cap crossed itself or faced the wrong way (an INVALID solid)."""
    source = shared_path("data", "cpacs", "simpletest-with-guides.cpacs.xml")
    for section, segment in (("Cpacs2Test_Wing_Sec1", 1), ("Cpacs2Test_Wing_Sec3", 2)):
        line = flattened_section_build(source, tmp_path / "flat.xml", section, "1e-9")
        assert f"FAILED: /cpacs/vehicles/aircraft/model[1]/wings/wing[1]/segments/segment[{segment}]: " in line, line
        assert "encloses no area" in line, line


def test_the_span_of_an_approximated_airfoil_measures_the_fitted_outline(tmp_path):
    """A wing whose tip airfoil stands upright (turned 90 degrees about x): its span reaches
    the tip's lower side, so it follows the airfoil's curve, the fitted one where the points
    are approximated (it measured the interpolated curve instead)."""
    upright = ('<wing uID="Upright"><name>w</name><transformation/><sections>'
               '<section uID="U0"><name>s</name><transformation/><elements><element uID="UE0"><name>e</name>'
               "<airfoilUID>Parabolic</airfoilUID><transformation/></element></elements></section>"
               '<section uID="U1"><name>s</name><transformation><rotation><x>90</x></rotation>'
               "<translation><y>5</y></translation></transformation><elements>"
               '<element uID="UE1"><name>e</name><airfoilUID>Parabolic</airfoilUID><transformation/></element>'
               '</elements></section></sections><segments><segment uID="US"><name>s</name>'
               "<fromElementUID>UE0</fromElementUID><toElementUID>UE1</toElementUID></segment></segments></wing>")
    for name, settings in (("exact", ""), ("fitted", approximation(12))):
        path = tmp_path / f"{name}.xml"
        point_list_wing(path, settings)
        path.write_text(path.read_text().replace("<wings>", "<wings>" + upright))
        lower = [{"op": "wing_lower_point", "wing": "Upright", "segment": 1, "eta": 1, "xsi": i / 2000}
                 for i in range(2001)]
        span, *points = ask_file(path, {"op": "wing_span", "wing": "Upright"}, *lower)
        reach = max(p[1] for p in points)  # the root lies at y = 0
        # The span's box is the tessellated outline's, widened by deflection and tolerance.
        assert math.isclose(span, reach + 2 * (1e-4 + 1e-7), abs_tol=2e-5), (name, span, reach)


def volume_answer(path, wing):
    """The answer (a dict with "ok" or "error") to a wing_volume query on the file."""
    return json.loads(airshape("query", str(path), stdin=json.dumps({"op": "wing_volume", "wing": wing}) + "\n").stdout)


def write_wing(path, uid, sections, segments, guide_profiles):
    """The test wings' file with one more wing of the given sections and segments, and the
    given guide curve profiles."""
    wing = (f'<wing uID="{uid}"><name>w</name><transformation/><sections>{sections}</sections>'
            f"<segments>{segments}</segments></wing>")
    text = open(WINGS).read().replace("<wings>", "<wings>" + wing)
    path.write_text(text.replace("</wingAirfoils>", f"</wingAirfoils><guideCurves>{guide_profiles}</guideCurves>"))


def guided_wing(path, second_segment_continuity):
    """A rectangular wing (chord 2, sections at y = 0, 5, 10) of the parabolic CST airfoil
    with guide curves along the leading edge (rc 0) and the sharp trailing edge (rc -1). In
    the first segment the leading-edge guide pushes forward by 0.1 at mid-span; in the second
    it is straight, joined with the given continuity (or none)."""
    def guide(rc, segment, profile):
        if segment == 0:
            start = f"<fromRelativeCircumference>{rc}</fromRelativeCircumference>"
        else:
            start = f"<fromGuideCurveUID>G{rc}S0</fromGuideCurveUID>" + (
                f"<continuity>{second_segment_continuity}</continuity>" if second_segment_continuity and rc == 0 else "")
        return (f'<guideCurve uID="G{rc}S{segment}"><name>g</name><guideCurveProfileUID>{profile}</guideCurveProfileUID>'
                f"{start}<toRelativeCircumference>{rc}</toRelativeCircumference></guideCurve>")

    sections = "".join(
        f'<section uID="GS{i}"><name>s</name><transformation><scaling><x>2</x><y>2</y><z>2</z></scaling>'
        f'<translation><y>{5 * i}</y></translation></transformation><elements><element uID="GE{i}"><name>e</name>'
        f"<airfoilUID>Parabolic</airfoilUID><transformation/></element></elements></section>" for i in range(3))
    segments = "".join(
        f'<segment uID="GW{i}"><name>s</name><fromElementUID>GE{i}</fromElementUID><toElementUID>GE{i + 1}</toElementUID>'
        f"<guideCurves>{guide(0, i, 'Forward' if i == 0 else 'Straight')}{guide(-1, i, 'Straight')}</guideCurves>"
        f"</segment>" for i in range(2))
    guide_profiles = "".join(
        f'<guideCurveProfile uID="{uid}"><name>p</name><pointList><rX>0;{alpha};0</rX><rY>0.25;0.5;0.75</rY>'
        f"<rZ>0;0;0</rZ></pointList></guideCurveProfile>" for uid, alpha in (("Forward", -0.05), ("Straight", 0)))
    write_wing(path, "Guided", sections, segments, guide_profiles)


def leading_edge_slopes_at_the_section(path):
    """dx/dy of the leading edge just inboard and just outboard of y = 5."""
    points = ask_file(path, *({"op": "wing_upper_point", "wing": "Guided", "segment": seg, "eta": eta, "xsi": 0.0}
                              for seg, eta in ((1, 0.999), (1, 1.0), (2, 0.0), (2, 0.001))))
    return ((points[1][0] - points[0][0]) / (points[1][1] - points[0][1]),
            (points[3][0] - points[2][0]) / (points[3][1] - points[2][1]))


def test_guide_curves_shape_the_wing(tmp_path):
    path = tmp_path / "guided.xml"
    guided_wing(path, "C0")
    le_mid, te_mid, root_le = ask_file(
        path, {"op": "wing_upper_point", "wing": "Guided", "segment": 1, "eta": 0.5, "xsi": 0.0},
        {"op": "wing_upper_point", "wing": "Guided", "segment": 1, "eta": 0.5, "xsi": 1.0},
        {"op": "wing_upper_point", "wing": "Guided", "segment": 1, "eta": 0.0, "xsi": 0.0})
    # The leading edge follows its guide: 0.05 of the chord (2) forward at mid-span.
    assert all(math.isclose(a, b, abs_tol=1e-4) for a, b in zip(le_mid, [-0.1, 2.5, 0.0])), le_mid
    assert all(math.isclose(a, b, abs_tol=1e-4) for a, b in zip(te_mid, [2.0, 2.5, 0.0])), te_mid
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(root_le, [0.0, 0.0, 0.0])), root_le
    # C0 leaves a kink in the leading edge at the section; the straight guide beyond stays put.
    before, after = leading_edge_slopes_at_the_section(path)
    assert abs(before - after) > 0.01 and abs(after) < 1e-4, (before, after)
    result = airshape("build", str(path))
    assert result.returncode == 0 and "Guided" in result.stdout, result.stdout + result.stderr


def test_c1_from_previous_carries_the_tangent_across_the_section(tmp_path):
    path = tmp_path / "c1.xml"
    guided_wing(path, "C1 from previous")
    before, after = leading_edge_slopes_at_the_section(path)
    assert abs(before) > 0.01 and abs(before - after) < 2e-3, (before, after)


def tapered_wing(path, with_guides, tip_guide_profile="Straight"):
    """One segment from a root chord of 2 to a tip chord of 1 at y = 4, optionally with
    guides along the leading edge (rc 0) and the sharp trailing edge (rc -1)."""
    guides = "".join(
        f'<guideCurve uID="T{rc}"><name>g</name><guideCurveProfileUID>{tip_guide_profile if rc == 0 else "Straight"}'
        f"</guideCurveProfileUID><fromRelativeCircumference>{rc}</fromRelativeCircumference>"
        f"<toRelativeCircumference>{rc}</toRelativeCircumference></guideCurve>" for rc in (0, -1))
    sections = "".join(
        f'<section uID="TS{i}"><name>s</name><transformation><scaling><x>{2 - i}</x><y>1</y><z>{2 - i}</z></scaling>'
        f'<translation><x>{0.5 * i}</x><y>{4 * i}</y></translation></transformation><elements><element uID="TE{i}">'
        f"<name>e</name><airfoilUID>Parabolic</airfoilUID><transformation/></element></elements></section>"
        for i in range(2))
    segment = ('<segment uID="TW"><name>s</name><fromElementUID>TE0</fromElementUID><toElementUID>TE1</toElementUID>'
               + (f"<guideCurves>{guides}</guideCurves>" if with_guides else "") + "</segment>")
    profiles = "".join(
        f'<guideCurveProfile uID="{uid}"><name>p</name><pointList><rX>{alpha}</rX><rY>0.5</rY>'
        f"<rZ>0</rZ></pointList></guideCurveProfile>" for uid, alpha in (("Forward", -0.05), ("Straight", 0)))
    write_wing(path, "Tapered", sections, segment, profiles)


def edited_tapered_wing(path, with_guides, old, new):
    """The tapered wing with one piece of its text replaced (which must be there)."""
    tapered_wing(path, with_guides)
    text = path.read_text()
    assert old in text, old
    path.write_text(text.replace(old, new, 1))
    return path


def cubic_basis(knots, i, t, degree=3):
    """The i-th B-spline basis function of the given degree at t (Cox-de Boor)."""
    if degree == 0:
        return 1.0 if knots[i] <= t < knots[i + 1] else 0.0
    left = right = 0.0
    if knots[i + degree] > knots[i]:
        left = (t - knots[i]) / (knots[i + degree] - knots[i]) * cubic_basis(knots, i, t, degree - 1)
    if knots[i + degree + 1] > knots[i + 1]:
        right = ((knots[i + degree + 1] - t) / (knots[i + degree + 1] - knots[i + 1])
                 * cubic_basis(knots, i + 1, t, degree - 1))
    return left + right


def test_straight_guides_fill_the_cells_from_their_poles(tmp_path):
    """Between straight leading- and trailing-edge guides over one segment the cells are
    filled bilinearly from the boundary poles (OCCT's stretch filling), as in the reference.
    Each guide is a cubic through three points with a knot at the middle one: poles at 0, 1/6,
    1/2, 5/6 and 1 of the span, while the filling blends the root and tip airfoils by pole
    index, 0, 1/4, 1/2, 3/4 and 1. At eta the airfoil is therefore scaled by the tip's share
    w(eta), the cubic B-spline with those index weights, not by eta as in the ruled skin; the
    thickness (z: both guides lie in z = 0) shows it exactly. A guide bulging between the
    sections bends the skin next to it."""
    etas = (0.2, 0.7)
    queries = [{"op": "wing_upper_point", "wing": "Tapered", "segment": 1, "eta": eta, "xsi": xsi}
               for eta in etas for xsi in (0.1, 0.4, 0.9)]
    plain, straight, bulging = tmp_path / "plain.xml", tmp_path / "straight.xml", tmp_path / "bulging.xml"
    tapered_wing(plain, with_guides=False)
    tapered_wing(straight, with_guides=True)
    tapered_wing(bulging, with_guides=True, tip_guide_profile="Forward")
    ruled, guided, bent = ask_file(plain, *queries), ask_file(straight, *queries), ask_file(bulging, *queries)
    knots = [0, 0, 0, 0, 0.5, 1, 1, 1, 1]
    for index, (a, b) in enumerate(zip(ruled, guided)):
        eta = etas[index // 3]
        tip_share = sum(weight * cubic_basis(knots, i, eta) for i, weight in enumerate((0, 0.25, 0.5, 0.75, 1)))
        # Chord 2 at the root, 1 at the tip: the ruled skin scales by 2 - eta, the filled one by 2 - w.
        assert math.isclose(b[2], a[2] * (2 - tip_share) / (2 - eta), rel_tol=1e-9), (eta, a, b)
        assert math.isclose(b[1], a[1], abs_tol=1e-9), (a, b)  # spanwise the guides are linear
    assert max(abs(a[0] - b[0]) for a, b in zip(ruled, bent)) > 0.01


def test_guide_offsets_scale_as_the_reference_measures_the_chord(tmp_path):
    """A guide's rZ is scaled by the chord as the reference measures it: its chord line is
    laid along z before the section's transformation, so sections scaled 2 in z (chord 1)
    scale the guide by 2, not by the chord's 1. A rectangular wing with a guide at relative
    circumference 0.5 lifted by rZ = 0.05 at mid-span: the skin there is lifted by 0.1."""
    guides = "".join(
        f'<guideCurve uID="Z{name}"><name>g</name><guideCurveProfileUID>{profile}</guideCurveProfileUID>'
        f"<fromRelativeCircumference>{rc}</fromRelativeCircumference>"
        f"<toRelativeCircumference>{rc}</toRelativeCircumference></guideCurve>"
        for name, rc, profile in (("te", -1, "Flat"), ("le", 0, "Flat"), ("up", 0.5, "Lifted")))
    sections = "".join(
        f'<section uID="ZS{i}"><name>s</name><transformation><scaling><x>1</x><y>1</y><z>2</z></scaling>'
        f'<translation><y>{4 * i}</y></translation></transformation><elements><element uID="ZE{i}">'
        f"<name>e</name><airfoilUID>Parabolic</airfoilUID><transformation/></element></elements></section>"
        for i in range(2))
    segment = (f'<segment uID="ZW"><name>s</name><fromElementUID>ZE0</fromElementUID><toElementUID>ZE1</toElementUID>'
               f"<guideCurves>{guides}</guideCurves></segment>")
    profiles = "".join(
        f'<guideCurveProfile uID="{uid}"><name>p</name><pointList><rX>0</rX><rY>0.5</rY>'
        f"<rZ>{gamma}</rZ></pointList></guideCurveProfile>" for uid, gamma in (("Flat", 0), ("Lifted", 0.05)))
    path = tmp_path / "scaled.xml"
    write_wing(path, "ZScaled", sections, segment, profiles)
    root, middle = ask_file(path, *({"op": "wing_upper_point", "wing": "ZScaled", "segment": 1, "eta": eta, "xsi": 0.5}
                                    for eta in (0.0, 0.5)))
    assert math.isclose(middle[2] - root[2], 2 * 0.05, rel_tol=1e-9), (root, middle)
    assert math.isclose(middle[0], root[0], abs_tol=1e-12) and math.isclose(middle[1], 2.0, rel_tol=1e-12)


def test_guides_are_parametrised_by_the_leading_edges(tmp_path):
    """A guide running through several segments is parametrised by the distances between
    the sections' leading edges (as in the reference), so the leading-edge guide of a wing
    with a kinked leading edge does not change when a middle section's chord does."""
    def kinked_wing(path, middle_chord):
        guides = lambda i: "".join(
            f'<guideCurve uID="K{rc}S{i}"><name>g</name><guideCurveProfileUID>Mid</guideCurveProfileUID>'
            + (f"<fromRelativeCircumference>{rc}</fromRelativeCircumference>" if i == 0
               else f"<fromGuideCurveUID>K{rc}S0</fromGuideCurveUID>")
            + f"<toRelativeCircumference>{rc}</toRelativeCircumference></guideCurve>" for rc in (0, -1))
        chords = (2, middle_chord, 1)
        sections = "".join(
            f'<section uID="KS{i}"><name>s</name><transformation><scaling><x>{c}</x><y>1</y><z>{c}</z></scaling>'
            f'<translation><x>{x}</x><y>{5 * i}</y></translation></transformation><elements><element uID="KE{i}">'
            f"<name>e</name><airfoilUID>Parabolic</airfoilUID><transformation/></element></elements></section>"
            for i, (c, x) in enumerate(zip(chords, (0, 1, 1.5))))
        segments = "".join(
            f'<segment uID="KW{i}"><name>s</name><fromElementUID>KE{i}</fromElementUID>'
            f"<toElementUID>KE{i + 1}</toElementUID><guideCurves>{guides(i)}</guideCurves></segment>" for i in range(2))
        profile = '<guideCurveProfile uID="Mid"><name>p</name><pointList><rX>0</rX><rY>0.5</rY><rZ>0</rZ></pointList></guideCurveProfile>'
        write_wing(path, "Kinked", sections, segments, profile)

    queries = [{"op": "wing_upper_point", "wing": "Kinked", "segment": seg, "eta": eta, "xsi": 0.0}
               for seg in (1, 2) for eta in (0.25, 0.5, 0.75)]
    narrow, wide = tmp_path / "narrow.xml", tmp_path / "wide.xml"
    kinked_wing(narrow, 1.2)
    kinked_wing(wide, 1.9)
    for a, b in zip(ask_file(narrow, *queries), ask_file(wide, *queries)):
        assert all(math.isclose(x, y, abs_tol=1e-12) for x, y in zip(a, b)), (a, b)
    # The guide is curved (one smooth curve through the kink), not the polyline of the edges.
    quarter = ask_file(narrow, queries[0])[0]
    assert abs(quarter[0] - 0.2 * quarter[1]) > 1e-4, quarter


def test_guide_points_that_repeat_or_go_back_are_an_error(tmp_path):
    """Two guide points in one place cannot be interpolated, and points that go back along
    the segment would fold the skin (it was built, folded, and called valid): a clear error
    naming the guide curve profile's rY."""
    for rY in ("0.5;0.5", "0.6;0.4"):
        path = edited_tapered_wing(tmp_path / "back.xml", True, "<rX>0</rX><rY>0.5</rY><rZ>0</rZ>",
                                   f"<rX>0;0</rX><rY>{rY}</rY><rZ>0;0</rZ>")
        answer = volume_answer(path, "Tapered")
        error = answer.get("error", "")
        assert error.startswith("/cpacs/vehicles/profiles/guideCurves/guideCurveProfile["), answer
        assert "]/pointList/rY: rY must increase" in error, answer


def test_a_c2_join_blends_its_cells_like_a_smooth_guide(tmp_path):
    """Cells next to a guide that runs smoothly through a section are blended round, and the
    reference counts a "C2 from previous" join as smooth (a "C1" join is not). Straight,
    evenly spaced guides over two tapered segments are the same curves either way, so a C2
    join gives exactly the skin of guides without any continuity, and a C1 join another one."""
    def two_segments(path, continuity):
        guides = lambda i: "".join(
            f'<guideCurve uID="J{rc}S{i}"><name>g</name><guideCurveProfileUID>Mid</guideCurveProfileUID>'
            + (f"<fromRelativeCircumference>{rc}</fromRelativeCircumference>" if i == 0
               else f"<fromGuideCurveUID>J{rc}S0</fromGuideCurveUID>"
               + (f"<continuity>{continuity}</continuity>" if continuity else ""))
            + f"<toRelativeCircumference>{rc}</toRelativeCircumference></guideCurve>" for rc in (0, -1))
        sections = "".join(
            f'<section uID="JS{i}"><name>s</name><transformation><scaling><x>{c}</x><y>1</y><z>{c}</z></scaling>'
            f'<translation><x>{0.25 * i}</x><y>{4 * i}</y></translation></transformation><elements>'
            f'<element uID="JE{i}"><name>e</name><airfoilUID>Parabolic</airfoilUID><transformation/></element>'
            f"</elements></section>" for i, c in enumerate((2, 1.5, 1)))
        segments = "".join(
            f'<segment uID="JW{i}"><name>s</name><fromElementUID>JE{i}</fromElementUID>'
            f"<toElementUID>JE{i + 1}</toElementUID><guideCurves>{guides(i)}</guideCurves></segment>" for i in range(2))
        profile = ('<guideCurveProfile uID="Mid"><name>p</name><pointList><rX>0</rX><rY>0.5</rY><rZ>0</rZ>'
                   "</pointList></guideCurveProfile>")
        write_wing(path, "Joined", sections, segments, profile)
        return path

    queries = [{"op": "wing_upper_point", "wing": "Joined", "segment": seg, "eta": eta, "xsi": xsi}
               for seg in (1, 2) for eta in (0.3, 0.8) for xsi in (0.2, 0.6)]
    smooth, c2, c1 = (ask_file(two_segments(tmp_path / f"{name}.xml", continuity), *queries)
                      for name, continuity in (("smooth", None), ("c2", "C2 from previous"), ("c1", "C1 from previous")))
    for a, b in zip(smooth, c2):
        assert all(math.isclose(x, y, abs_tol=1e-9) for x, y in zip(a, b)), (a, b)
    assert max(abs(x - y) for a, b in zip(smooth, c1) for x, y in zip(a, b)) > 1e-5


def test_numbers_that_are_not_finite_are_errors_naming_the_node(tmp_path):
    """NaN and INF are numbers to XML Schema, but no wing can be built from them."""
    for old, new, node in (("<scaling><x>2</x>", "<scaling><x>NaN</x>", "scaling/x"),
                           ("<rX>0</rX><rY>0.5</rY>", "<rX>0</rX><rY>INF</rY>", "pointList/rY"),
                           ("<toRelativeCircumference>0</toRelativeCircumference>",
                            "<toRelativeCircumference>NaN</toRelativeCircumference>", "toRelativeCircumference"),
                           ("<toRelativeCircumference>0</toRelativeCircumference>",
                            "<toRelativeCircumference>0</toRelativeCircumference><rXDirection><x>1</x><y>-INF</y>"
                            "<z>0</z></rXDirection>", "rXDirection/y")):
        path = edited_tapered_wing(tmp_path / "not-finite.xml", True, old, new)
        answer = volume_answer(path, "Tapered")
        assert node in answer.get("error", "") and "not a finite number" in answer["error"], answer


def test_a_wing_guide_curve_placed_by_curve_parameter_is_an_error_naming_it(tmp_path):
    """fromParameter (the reference's extension) has no meaning on a wing's airfoil."""
    path = edited_tapered_wing(tmp_path / "parameter.xml", True, "<fromRelativeCircumference>0</fromRelativeCircumference>",
                               "<fromParameter>0</fromParameter>")
    answer = volume_answer(path, "Tapered")
    assert "guideCurves/guideCurve[1]" in answer.get("error", "") and "relative circumferences" in answer["error"], answer


def test_an_absurdly_large_wing_answers_in_finite_time(tmp_path):
    """Sections scaled by 1e300 overflow the geometry: every query still answers, quickly,
    with a finite number or an error, never with null (JSON has no infinity)."""
    path = edited_tapered_wing(tmp_path / "huge.xml", False, "<scaling><x>2</x><y>1</y><z>2</z></scaling>",
                               "<scaling><x>1e300</x><y>1</y><z>1e300</z></scaling>")
    queries = [{"op": op, "wing": "Tapered"} for op in ("wing_span", "wing_volume", "wing_surface_area", "wing_mac")]
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert len(answers) == len(queries)
    for answer in answers:
        assert "error" in answer or "null" not in json.dumps(answer["ok"]), answer
    assert "error" in answers[0], answers[0]  # the span of an overflowing wing


def test_a_number_that_cannot_be_read_is_reported_when_the_file_is_opened(tmp_path):
    """'half' for a translation is left out of the model (read as 0), which changes the wing:
    every command says so on stderr, naming the node, not only `validate`."""
    path = edited_tapered_wing(tmp_path / "unreadable.xml", False, "<translation><x>0.5</x><y>4</y></translation>",
                               "<translation><x>half</x><y>4</y></translation>")
    result = airshape("query", str(path), stdin='{"op":"wing_chord_point","wing":"Tapered","segment":1,"eta":1,"xsi":0}\n')
    assert "translation/x: 'half' is not a number (left out of the model)" in result.stderr, result.stderr
    assert json.loads(result.stdout)["ok"][:2] == [0.0, 4.0]  # the tip's leading edge, x read as 0


def test_a_guided_skin_that_cannot_be_built_names_the_wing(tmp_path):
    """A leading-edge guide that ends at the trailing edge leaves a cell of no width: the
    error names the wing's segments, the elements of the airfoils the cell lies between and
    both guide curves (it counted them by index)."""
    path = edited_tapered_wing(tmp_path / "crossing.xml", True, "<toRelativeCircumference>0</toRelativeCircumference>",
                               "<toRelativeCircumference>-1</toRelativeCircumference>")
    assert volume_answer(path, "Tapered").get("error", "").startswith(
        "/cpacs/vehicles/aircraft/model[1]/wings/wing[1]/segments: the guided skin: the cell between the airfoils of "
        "elements 'TE0' and 'TE1' and between guide curve 'T-1' and guide curve 'T0' is empty")


def test_a_scaling_coordinate_left_out_is_one(tmp_path):
    """The schema's default scaling is 1, 1, 1: a scaling that leaves out z scales z by 1."""
    old = "<scaling><x>2</x><y>1</y><z>2</z></scaling>"
    left_out = edited_tapered_wing(tmp_path / "left-out.xml", False, old, "<scaling><x>2</x><y>1</y></scaling>")
    one = edited_tapered_wing(tmp_path / "one.xml", False, old, "<scaling><x>2</x><y>1</y><z>1</z></scaling>")
    query = {"op": "wing_upper_point", "wing": "Tapered", "segment": 1, "eta": 0.0, "xsi": 0.5}
    (a,), (b,) = ask_file(left_out, query), ask_file(one, query)
    assert a == b and a[2] > 0, (a, b)


def test_faces_are_named():
    (faces,) = ask({"op": "component_faces", "uid": "Rect"})
    areas = {face["name"]: face["area"] for face in faces}
    assert set(areas) == {"Rect/root", "Rect/tip", "RS/upper", "RS/lower"}, areas
    chord, span, b = 2.0, 5.0, 0.15
    side = parabola_arc(chord, b * chord / 4)
    assert math.isclose(areas["RS/upper"], side * span, rel_tol=1e-7)
    assert math.isclose(areas["Rect/root"], 2 * b * chord * chord / 6, rel_tol=1e-7)


def test_the_mirrored_half_is_its_own_named_shape():
    result = airshape("query", WINGS, stdin='{"op":"component_faces","uid":"Swept"}\n'
                                           '{"op":"component_faces","uid":"Swept","mirrored":true}\n'
                                           '{"op":"component_faces","uid":"Rect","mirrored":true}\n')
    original, mirrored, no_symmetry = [json.loads(line) for line in result.stdout.splitlines()]
    assert "no symmetry plane" in no_symmetry["error"]
    for face, image in zip(original["ok"], mirrored["ok"]):
        # x-z-plane symmetry: same name with " (mirrored)", same area, centre with y negated.
        assert image["name"] == face["name"] + " (mirrored)"
        assert math.isclose(image["area"], face["area"], rel_tol=1e-12)
        x, y, z = face["centre"]
        assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(image["centre"], [x, -y, z])), (face, image)


def test_rotor_blades_are_wings_placed_by_their_own_transformation(tmp_path):
    """In a rotorcraft model the rotor blades count as wings; a blade's transformation (here
    scaling by 0.5 and moving by y = 1) places it like a wing's does."""
    text = open(WINGS).read()
    start, end = text.index('<wing uID="Rect">'), text.index("</wing>", text.index('<wing uID="Rect">')) + len("</wing>")
    blade = (text[start:end].replace('<wing uID="Rect">', '<rotorBlade uID="Blade">').replace("</wing>", "</rotorBlade>")
             .replace("<translation><x>1</x><y>0</y><z>0</z></translation>",
                      "<scaling><x>0.5</x><y>0.5</y><z>0.5</z></scaling><translation><x>0</x><y>1</y><z>0</z></translation>"))
    models_start, models_end = text.index("<aircraft>"), text.index("</aircraft>") + len("</aircraft>")
    rotorcraft = (f'<rotorcraft><model uID="Heli"><name>h</name><rotorBlades>{blade}</rotorBlades></model></rotorcraft>')
    path = tmp_path / "rotorcraft.xml"
    path.write_text(text[:models_start] + rotorcraft + text[models_end:])
    count, tip_te = ask_file(path, {"op": "wing_count"},
                             {"op": "wing_chord_point", "wing": 1, "segment": 1, "eta": 1.0, "xsi": 1.0})
    assert count == 1
    # Unscaled, the tip trailing edge is at (2, 5, 0); scaled by 0.5 and moved by y = 1.
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(tip_te, [1.0, 3.5, 0.0])), tip_te


def test_naca_four_digit_airfoils(tmp_path):
    """The reference's nacaProfile (outside CPACS 3.5): NACA 0012 with a closed trailing edge
    has the area 10·t·∫(0.2969√x − 0.1260x − 0.3516x² + 0.2843x³ − 0.1036x⁴) dx per unit chord."""
    text = open(WINGS).read().replace(
        "<cst2D>", "<nacaProfile><naca4DigitCode>0012</naca4DigitCode></nacaProfile><cst2D>", 1)
    start, end = text.index("<cst2D>"), text.index("</cst2D>") + len("</cst2D>")
    path = tmp_path / "naca.xml"
    path.write_text(text[:start] + text[end:])
    volume, le, te = ask_file(path, {"op": "wing_volume", "wing": "Rect"},
                              {"op": "wing_chord_point", "wing": "Rect", "segment": 1, "eta": 0.0, "xsi": 0.0},
                              {"op": "wing_chord_point", "wing": "Rect", "segment": 1, "eta": 0.0, "xsi": 1.0})
    area = 10 * 0.12 * (0.2969 * 2 / 3 - 0.1260 / 2 - 0.3516 / 3 + 0.2843 / 4 - 0.1036 / 5)
    chord, span = 2.0, 5.0
    # The sides are the reference's approximations (about 1e-5 of the chord, here 2.5e-4 of
    # the thickness), so the volume is that close and no closer.
    assert math.isclose(volume, area * chord * chord * span, rel_tol=1e-3), volume
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(le, [1.0, 0.0, 0.0])), le
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(te, [3.0, 0.0, 0.0])), te


def naca0012_points():
    """NACA 0012 points TE → lower → LE → upper → TE: 41 points at cosine stations."""
    stations = [0.5 * (1 - math.cos(math.pi * i / 20)) for i in range(21)]
    half = [0.6 * (0.2969 * math.sqrt(x) - 0.126 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3 - 0.1036 * x ** 4)
            for x in stations]
    return stations[::-1] + stations[1:], [-h for h in half[::-1]] + half[1:]


def point_list_wing(path, settings="", reverse=False):
    """The Rect wing with the NACA 0012 point list as its airfoil (in the other order when
    `reverse`), optionally with approximationSettings."""
    xs, zs = naca0012_points()
    if reverse:
        xs, zs = xs[::-1], zs[::-1]
    points = (f'<pointList><x mapType="vector">{";".join(map(str, xs))}</x>'
              f'<y mapType="vector">{";".join("0" for _ in xs)}</y>'
              f'<z mapType="vector">{";".join(map(str, zs))}</z>{settings}</pointList>')
    text = open(WINGS).read()
    start, end = text.index("<cst2D>"), text.index("</cst2D>") + len("</cst2D>")
    path.write_text(text[:start] + points + text[end:])


def test_cst_parameters_that_leave_the_airfoil_open_are_errors_naming_them(tmp_path):
    """A negative class-function exponent makes a side infinite at an end, an exponent of 0
    leaves it off the chord there; a gap at the trailing edge is fine where a thickness is
    given (a blunt trailing edge)."""
    cst = "/cpacs/vehicles/profiles/wingAirfoils/wingAirfoil[1]/cst2D"
    thick = "</lowerB><trailingEdgeThickness>0.01</trailingEdgeThickness>"
    for edits, expected in (
            ({"<upperN1>1</upperN1>": "<upperN1>-1</upperN1>"}, f"{cst}/upperN1: must not be negative"),
            ({"<lowerN2>1</lowerN2>": "<lowerN2>-0.5</lowerN2>"}, f"{cst}/lowerN2: must not be negative"),
            ({"</lowerB>": "</lowerB><trailingEdgeThickness>-0.01</trailingEdgeThickness>"},
             f"{cst}/trailingEdgeThickness: must not be negative"),
            ({"<lowerN1>1</lowerN1>": "<lowerN1>0</lowerN1>"}, f"{cst}: the upper and lower sides do not meet at the leading"),
            ({"<upperN2>1</upperN2>": "<upperN2>0</upperN2>"}, f"{cst}: the upper and lower sides do not meet at the sharp"),
            ({"<upperN2>1</upperN2>": "<upperN2>0</upperN2>", "</lowerB>": thick}, None)):
        text = open(WINGS).read()
        for old, new in edits.items():
            assert old in text, old
            text = text.replace(old, new, 1)
        path = tmp_path / "cst.xml"
        path.write_text(text)
        answer = volume_answer(path, "Rect")
        if expected:
            assert answer.get("error", "").startswith(expected), (edits, answer)
        else:
            assert answer.get("ok", 0) > 0, (edits, answer)
            build = airshape("build", str(path)).stdout
            assert "INVALID" not in build and "FAILED" not in build, build


def test_build_says_what_makes_a_solid_invalid(tmp_path):
    """CST exponents so large that the two sides lie on the chord along most of it: the
    solid is invalid, and build says what BRepCheck found."""
    text = open(WINGS).read().replace("<upperN2>1</upperN2>", "<upperN2>100</upperN2>", 1)
    path = tmp_path / "thin.xml"
    path.write_text(text.replace("<lowerN1>1</lowerN1>", "<lowerN1>1e6</lowerN1>", 1))
    result = airshape("build", str(path))
    line = next(line for line in result.stdout.splitlines() if line.split()[:2] == ["wing", "Rect"])
    assert result.returncode == 1 and "INVALID solid" in line, result.stdout
    assert "(BRepCheck: " in line and "self intersecting wire" in line, line


def test_a_standard_profile_wing_airfoil_is_an_error_naming_it(tmp_path):
    """The schema lets a wing airfoil be a fuselage's rectangle or superellipse; it has no
    leading or trailing edge, so it is refused, naming the node."""
    text = open(WINGS).read()
    start, end = text.index("<cst2D>"), text.index("</cst2D>") + len("</cst2D>")
    path = tmp_path / "standard.xml"
    path.write_text(text[:start] + "<standardProfile><rectangle><heightToWidthRatio>0.2</heightToWidthRatio>"
                    "</rectangle></standardProfile>" + text[end:])
    answer = volume_answer(path, "Rect")
    assert answer.get("error", "").endswith("/standardProfile: a standardProfile (rectangle or superellipse) is a "
                                            "fuselage profile; a wing airfoil needs a pointList, cst2D or nacaProfile"), answer


def test_an_airfoil_whose_points_lie_on_a_line_is_an_error_naming_it(tmp_path):
    """A flat plate (every z = 0) encloses nothing: the point list says so (the segment said
    its faces enclosed no volume)."""
    path = tmp_path / "flat.xml"
    point_list_wing(path)
    text = path.read_text()
    start = text.index('<z mapType="vector">')
    end = text.index("</z>", start)
    count = text[start:end].count(";") + 1
    path.write_text(text[:start] + '<z mapType="vector">' + ";".join("0" for _ in range(count)) + text[end:])
    answer = volume_answer(path, "Rect")
    assert answer.get("error") == ("/cpacs/vehicles/profiles/wingAirfoils/wingAirfoil[1]/pointList: "
                                   "the points enclose no area (they lie on a line)"), answer


def test_an_airfoil_whose_points_are_out_of_order_is_an_error_naming_it(tmp_path):
    """Points given out of order make an outline that crosses itself (an INVALID solid before)."""
    path = tmp_path / "scrambled.xml"
    point_list_wing(path)
    text = path.read_text()
    start, end = text.index("<pointList>"), text.index("</pointList>") + len("</pointList>")
    xs, zs = naca0012_points()
    order = list(range(0, len(xs), 2)) + list(range(1, len(xs), 2))  # every other point, then the rest
    scrambled = (f'<pointList><x mapType="vector">{";".join(str(xs[i]) for i in order)}</x>'
                 f'<y mapType="vector">{";".join("0" for _ in order)}</y>'
                 f'<z mapType="vector">{";".join(str(zs[i]) for i in order)}</z></pointList>')
    path.write_text(text[:start] + scrambled + text[end:])
    answer = volume_answer(path, "Rect")
    assert answer.get("error", "").startswith(
        "/cpacs/vehicles/profiles/wingAirfoils/wingAirfoil[1]/pointList: the points' outline crosses itself"), answer


def approximation(count, indices="", method=""):
    attribute = f' errorComputationMethod="{method}"' if method else ""
    pinned = f"<interpolatedPointsIndices>{indices}</interpolatedPointsIndices>" if indices else ""
    return f"<approximationSettings{attribute}><controlPointNumber>{count}</controlPointNumber>{pinned}</approximationSettings>"


def test_approximated_point_list_airfoils(tmp_path):
    """The reference's approximationSettings (outside CPACS 3.5): a least-squares cubic with
    the given number of control points instead of the interpolating one, through both ends,
    the leading edge (at parameter 0.5) and the interpolatedPointsIndices; bad settings are
    errors naming the node."""
    files = {name: tmp_path / f"{name}.xml"
             for name in ("exact", "fitted", "reversed", "largest", "bad", "method", "many", "fraction")}
    point_list_wing(files["exact"])
    point_list_wing(files["fitted"], approximation(12, "10"))
    point_list_wing(files["reversed"], approximation(12, "32"), reverse=True)  # point 10 counted from the end
    point_list_wing(files["largest"], approximation(12, "10", "MaxError"))
    point_list_wing(files["bad"], approximation(12, "99"))
    point_list_wing(files["method"], approximation(12, "10", "Largest"))
    point_list_wing(files["many"], approximation(42))
    point_list_wing(files["fraction"], approximation(12, "10.5"))
    # Point 10 lies on the lower side at the same xsi in both: its centripetal parameter's
    # share of the leading edge's (the fit stretches the lower side's parameters to [0, 0.5]).
    xs, zs = naca0012_points()
    steps = [math.hypot(xs[i + 1] - xs[i], zs[i + 1] - zs[i]) ** 0.5 for i in range(len(xs) - 1)]
    xsi = 1 - sum(steps[:9]) / sum(steps[:20])
    queries = [{"op": "wing_volume", "wing": "Rect"},
               {"op": "wing_upper_point", "wing": "Rect", "segment": 1, "eta": 0.0, "xsi": 0.0},
               {"op": "wing_lower_point", "wing": "Rect", "segment": 1, "eta": 0.5, "xsi": xsi},
               {"op": "wing_lower_point", "wing": "Rect", "segment": 1, "eta": 0.5, "xsi": 0.5}]
    exact, fitted = ask_file(files["exact"], *queries), ask_file(files["fitted"], *queries)
    # Twelve control points fit the NACA 0012 to about 2 % in volume.
    assert math.isclose(exact[0], fitted[0], rel_tol=3e-2) and not math.isclose(exact[0], fitted[0], rel_tol=1e-6)
    for passed_through in (1, 2):  # the leading edge and point 10
        assert math.dist(exact[passed_through], fitted[passed_through]) < 1e-9, (exact, fitted)
    assert 1e-6 < math.dist(exact[3], fitted[3]) < 1e-2, (exact[3], fitted[3])  # elsewhere only near
    # The indices count in the file's order, also when the points run the other way round.
    assert math.isclose(ask_file(files["reversed"], queries[0])[0], fitted[0], rel_tol=1e-9)
    # MaxError measures the corrections by the largest distance instead (here they stop at the
    # same fit).
    assert math.isclose(ask_file(files["largest"], queries[0])[0], fitted[0], rel_tol=1e-2)
    for name, words in (("bad", ["interpolatedPointsIndices", "approximationSettings"]),
                        ("method", ["errorComputationMethod", "Largest", "approximationSettings"]),
                        ("many", ["controlPointNumber", "got 42 for 41 points"]),
                        ("fraction", ["interpolatedPointsIndices", "not a whole number: 10.5"])):
        error = volume_answer(files[name], "Rect").get("error", "")
        assert all(word in error for word in words), error
