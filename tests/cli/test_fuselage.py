"""Fuselage geometry on a cylinder the test writes itself, where every number has a closed form."""
import json
import math

from conftest import airshape, conformance_passed, query_answers as ask, shared_path

HEADER = """<cpacs><header><name>t</name><version>1</version><versionInfos><versionInfo version="1"><creator>t</creator>
<timestamp>2026-01-01T00:00:00</timestamp><description>t</description><cpacsVersion>3.5</cpacsVersion></versionInfo>
</versionInfos></header><vehicles><aircraft><model uID="M"><name>m</name><fuselages>"""


def circle(count, half=False):
    angles = [(math.pi if half else 2 * math.pi) * i / count for i in range(count + 1)]
    ys = ";".join(f"{math.sin(a):.17g}" for a in angles)
    zs = ";".join(f"{math.cos(a):.17g}" for a in angles)
    xs = ";".join("0" for _ in angles)
    return f"<pointList><x>{xs}</x><y>{ys}</y><z>{zs}</z></pointList>"


def fuselage(uid, profile, length, stations=None):
    stations = stations or [0, length / 2, length]
    sections = "".join(
        f'<section uID="{uid}S{i}"><name>s</name><transformation><translation><x>{x}</x></translation></transformation>'
        f'<elements><element uID="{uid}E{i}"><name>e</name><profileUID>{profile}</profileUID><transformation/></element>'
        f"</elements></section>" for i, x in enumerate(stations))
    segments = "".join(f'<segment uID="{uid}G{i}"><name>g</name><fromElementUID>{uid}E{i}</fromElementUID>'
                       f"<toElementUID>{uid}E{i + 1}</toElementUID></segment>" for i in range(len(stations) - 1))
    return (f'<fuselage uID="{uid}"><name>f</name><transformation/><sections>{sections}</sections>'
            f"<segments>{segments}</segments></fuselage>")


def write_cylinders(path):
    profiles = (f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(64)}</fuselageProfile>'
                f'<fuselageProfile uID="Half"><name>h</name>{circle(32, half=True)}</fuselageProfile></fuselageProfiles>')
    path.write_text(HEADER + fuselage("Full", "Circle", 10.0) + fuselage("HalfCylinder", "Half", 10.0) +
                    f"</fuselages></model></aircraft><profiles>{profiles}</profiles></vehicles></cpacs>")


def test_cylinder_in_closed_form(tmp_path):
    path = tmp_path / "cylinders.xml"
    write_cylinders(path)
    volume, area, segment_volume, circumference, start, quarter, half_volume, half_circumference = ask(
        path, {"op": "fuselage_volume", "fuselage": "Full"}, {"op": "fuselage_surface_area", "fuselage": "Full"},
        {"op": "fuselage_segment_volume", "fuselage": 1, "segment": 2},
        {"op": "fuselage_circumference", "fuselage": 1, "segment": 1, "eta": 0.3},
        {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.0, "zeta": 0.0},
        {"op": "fuselage_point", "fuselage": 1, "segment": 2, "eta": 0.5, "zeta": 0.25},
        {"op": "fuselage_volume", "fuselage": "HalfCylinder"},
        {"op": "fuselage_circumference", "fuselage": 2, "segment": 1, "eta": 0.5})
    assert math.isclose(volume, math.pi * 10, rel_tol=1e-5)
    assert math.isclose(segment_volume, math.pi * 5, rel_tol=1e-5)
    assert math.isclose(area, 2 * math.pi * 10, rel_tol=1e-5)
    assert math.isclose(circumference, 2 * math.pi, rel_tol=1e-5)
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(start, [0, 0, 1]))
    # Evenly spaced points: a quarter of the curve parameter is a quarter turn.
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(quarter, [7.5, 1, 0]))
    # A half profile is closed by a flat face: half the volume, half the girth.
    assert math.isclose(half_volume, math.pi * 5, rel_tol=1e-4)
    assert math.isclose(half_circumference, math.pi, rel_tol=1e-5)


def standard_profile_fuselages(path):
    """Prisms 4 long of three standard profiles: the superellipse with all exponents 2 (the
    circle of diameter 1), with all exponents 1 (the diamond of diagonals 1) and a rectangle
    0.6 high with corners of radius 0.1."""
    def superellipse(exponent):
        return (f"<standardProfile><superEllipse><lowerHeightFraction>0.5</lowerHeightFraction>"
                f"<mUpper>{exponent}</mUpper><nUpper>{exponent}</nUpper><mLower>{exponent}</mLower>"
                f"<nLower>{exponent}</nLower></superEllipse></standardProfile>")
    rectangle = ("<standardProfile><rectangle><cornerRadius>0.1</cornerRadius>"
                 "<heightToWidthRatio>0.6</heightToWidthRatio></rectangle></standardProfile>")
    profiles = "".join(f'<fuselageProfile uID="{uid}"><name>p</name>{shape}</fuselageProfile>'
                       for uid, shape in (("Circle", superellipse(2)), ("Diamond", superellipse(1)),
                                          ("Rectangle", rectangle)))
    path.write_text(HEADER + fuselage("C", "Circle", 4.0) + fuselage("D", "Diamond", 4.0) +
                    fuselage("R", "Rectangle", 4.0) +
                    f"</fuselages></model></aircraft><profiles><fuselageProfiles>{profiles}</fuselageProfiles>"
                    "</profiles></vehicles></cpacs>")


def test_standard_profiles_in_closed_form(tmp_path):
    path = tmp_path / "standard.xml"
    standard_profile_fuselages(path)
    (circle, diamond, rectangle, top, side, bottom, corner_free, rectangle_top, girth) = ask(
        path, {"op": "fuselage_volume", "fuselage": "C"}, {"op": "fuselage_volume", "fuselage": "D"},
        {"op": "fuselage_volume", "fuselage": "R"},
        {"op": "fuselage_point", "fuselage": "C", "segment": 1, "eta": 0.5, "zeta": 0.0},
        {"op": "fuselage_point", "fuselage": "D", "segment": 1, "eta": 0.5, "zeta": 0.25},
        {"op": "fuselage_point", "fuselage": "D", "segment": 1, "eta": 0.5, "zeta": 0.5},
        {"op": "fuselage_point", "fuselage": "D", "segment": 1, "eta": 0.5, "zeta": 0.125},
        {"op": "fuselage_point", "fuselage": "R", "segment": 2, "eta": 0.0, "zeta": 0.0},
        {"op": "fuselage_circumference", "fuselage": "C", "segment": 1, "eta": 0.3})
    # The quarters are the reference's approximations to 1e-6; volumes follow closely.
    assert math.isclose(circle, math.pi / 4 * 4.0, rel_tol=1e-5), circle
    assert math.isclose(girth, math.pi, rel_tol=1e-5), girth
    assert math.isclose(diamond, 0.5 * 4.0, rel_tol=1e-6), diamond
    # The rounded corners are single cubic spans lying up to 2.7e-4 of the radius outside the
    # circle (as the reference draws them one span each): 1.5e-5 more area than the exact corners.
    assert math.isclose(rectangle, (0.6 - (4 - math.pi) * 0.1 ** 2) * 4.0, rel_tol=2e-5), rectangle
    # Each superellipse starts at the top and its quarters end exactly at the side, the bottom.
    for got, want in ((top, [1, 0, 0.5]), (side, [1, 0.5, 0]), (bottom, [1, 0, -0.5]), (rectangle_top, [2, 0, 0.3])):
        assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(got, want)), (got, want)
    # Half way along the diamond's first edge.
    assert abs(abs(corner_free[1]) + abs(corner_free[2]) - 0.5) < 1e-6, corner_free


def test_a_superellipse_follows_its_sharp_tip(tmp_path):
    """A superellipse whose upper exponent m is 0.5 has a sharp tip at the top, where the
    curve's parameter runs like the square root of the distance: near it the approximation
    stays within 1e-5 of the width of the exact curve |2y|^0.5 + (2z)^2 = 1 (it was 1e-4)."""
    shape = ("<standardProfile><superEllipse><lowerHeightFraction>0.5</lowerHeightFraction><mUpper>0.5</mUpper>"
             "<nUpper>2</nUpper><mLower>2</mLower><nLower>2</nLower></superEllipse></standardProfile>")
    path = tmp_path / "star.xml"
    path.write_text(HEADER + fuselage("S", "Star", 4.0) + "</fuselages></model></aircraft><profiles><fuselageProfiles>"
                    f'<fuselageProfile uID="Star"><name>p</name>{shape}</fuselageProfile>'
                    "</fuselageProfiles></profiles></vehicles></cpacs>")
    zetas = [2e-3 * (i / 100) ** 2 for i in range(101)]
    points = ask(path, *({"op": "fuselage_point", "fuselage": "S", "segment": 1, "eta": 0.5, "zeta": z} for z in zetas))

    def exact(t):  # the curve at angle parameter t near the top
        return 0.5 * math.sin(t), 0.5 * (1 - abs(math.sin(t)) ** 0.5) ** 0.5

    curve = [exact(0.03 * (i / 30000) ** 2) for i in range(30001)]
    for zeta, point in zip(zetas, points):
        distance = min(math.hypot(point[1] - y, point[2] - z) for y, z in curve)
        assert distance < 1e-5, (zeta, point, distance)


def test_rounded_corners_follow_their_circles(tmp_path):
    """Points around the rectangle's upper right corner (radius 0.1, centre (0.4, 0.2)) lie
    on its circle within 2.7e-4 of the radius, never inside it, and their angle grows with
    zeta within half a degree of the angle's share."""
    path = tmp_path / "standard.xml"
    standard_profile_fuselages(path)
    top, arc = 0.4, math.pi * 0.1 / 2  # lengths of the half top and of a quarter arc
    length = 2 * (1 - 2 * 0.1) + 2 * (0.6 - 2 * 0.1) + 4 * arc
    shares = [i / 20 for i in range(21)]
    points = ask(path, *({"op": "fuselage_point", "fuselage": "R", "segment": 1, "eta": 0.5,
                          "zeta": (top + share * arc) / length} for share in shares))
    for share, point in zip(shares, points):
        radius = math.hypot(point[1] - 0.4, point[2] - 0.2)
        assert 0.1 - 1e-12 <= radius <= 0.1 * (1 + 2.73e-4), (share, radius)
        angle = math.atan2(point[1] - 0.4, point[2] - 0.2)  # from the vertical, towards +y
        assert abs(angle - share * math.pi / 2) < math.radians(0.5), (share, angle)


def test_corner_radii_the_rectangle_cannot_hold_are_errors(tmp_path):
    """A corner radius beyond half the height would make the corners overlap, one outside
    [0, 0.5) is out of the schema's range: each is one error naming the cornerRadius node."""
    path = tmp_path / "standard.xml"
    standard_profile_fuselages(path)
    text = path.read_text()
    for radius, says in (("0.45", "more than half the rectangle's height"), ("0.6", "outside [0, 0.5)")):
        path.write_text(text.replace("<cornerRadius>0.1</cornerRadius>", f"<cornerRadius>{radius}</cornerRadius>"))
        (answer,) = [json.loads(line) for line in airshape(
            "query", str(path), stdin='{"op":"fuselage_volume","fuselage":"R"}\n').stdout.splitlines()]
        assert says in answer["error"] and answer["error"].endswith("overlap") == (radius == "0.45"), answer
        assert "rectangle/cornerRadius" in answer["error"], answer


def test_bad_arguments_are_errors(tmp_path):
    path = tmp_path / "cylinders.xml"
    write_cylinders(path)
    result = airshape("query", str(path), stdin='{"op":"fuselage_point","fuselage":1,"segment":1,"eta":1.5,"zeta":0}\n'
                                                 '{"op":"fuselage_point","fuselage":1,"segment":3,"eta":0,"zeta":0}\n')
    assert all("error" in json.loads(line) for line in result.stdout.splitlines())


def test_one_smooth_loft_through_unevenly_spaced_sections(tmp_path):
    """Sections at x = 0, 2 and 17: the loft is one quadratic through all three profiles at
    centripetal parameters (0, t1, 1), not two ruled pieces, so x is not linear in eta."""
    path = tmp_path / "uneven.xml"
    profiles = f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(64)}</fuselageProfile></fuselageProfiles>'
    path.write_text(HEADER + fuselage("F", "Circle", 17.0, stations=[0, 2, 17]) +
                    f"</fuselages></model></aircraft><profiles>{profiles}</profiles></vehicles></cpacs>")
    t1 = math.sqrt(2) / (math.sqrt(2) + math.sqrt(15))
    # x(t) = a t + b t^2 through x(t1) = 2 and x(1) = 17.
    b = (2 - 17 * t1) / (t1 * t1 - t1)
    a = 17 - b
    inner, outer, girth = ask(path, {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.5, "zeta": 0.25},
                              {"op": "fuselage_point", "fuselage": 1, "segment": 2, "eta": 0.6, "zeta": 0.25},
                              {"op": "fuselage_circumference", "fuselage": 1, "segment": 2, "eta": 0.6})
    for point, t in ((inner, 0.5 * t1), (outer, t1 + 0.6 * (1 - t1))):
        assert math.isclose(point[0], a * t + b * t * t, abs_tol=1e-9)
        assert math.isclose(point[1], 1.0, abs_tol=1e-9)
    assert math.isclose(girth, 2 * math.pi, rel_tol=1e-5)


def guided_cylinder(path, second_segment_continuity):
    """A cylinder of unit circles at x = 0, 5, 10 with four guides at relative circumference
    0, 1/4, 1/2, 3/4. Along the top (rc 0) the first segment's guide bulges out by 0.1 at its
    middle and the second's is straight; the others are straight."""
    def guide(uid, segment, rc, profile):
        start = (f"<fromRelativeCircumference>{rc}</fromRelativeCircumference>" if segment == 0 else
                 f"<fromGuideCurveUID>G{rc}S0</fromGuideCurveUID>" +
                 (f"<continuity>{second_segment_continuity}</continuity>"
                  if second_segment_continuity and rc == 0 else ""))
        return (f'<guideCurve uID="{uid}"><name>g</name><guideCurveProfileUID>{profile}</guideCurveProfileUID>'
                f"{start}<toRelativeCircumference>{rc}</toRelativeCircumference></guideCurve>")

    def segment(i):
        curves = "".join(guide(f"G{rc}S{i}", i, rc, "Bulge" if (rc == 0 and i == 0) else "Straight")
                         for rc in (0, 0.25, 0.5, 0.75))
        return (f'<segment uID="G{i}"><name>g</name><fromElementUID>FE{i}</fromElementUID>'
                f"<toElementUID>FE{i + 1}</toElementUID><guideCurves>{curves}</guideCurves></segment>")

    sections = "".join(
        f'<section uID="FS{i}"><name>s</name><transformation><translation><x>{x}</x></translation></transformation>'
        f'<elements><element uID="FE{i}"><name>e</name><profileUID>Circle</profileUID><transformation/></element>'
        f"</elements></section>" for i, x in enumerate([0, 5, 10]))
    fuselage = (f'<fuselage uID="F"><name>f</name><transformation/><sections>{sections}</sections>'
                f"<segments>{segment(0)}{segment(1)}</segments></fuselage>")
    # Alpha runs along global z; the circle's "diameter line" is 2 long, so 0.05 lifts by 0.1.
    guide_profiles = "".join(
        f'<guideCurveProfile uID="{uid}"><name>p</name><pointList><rX>0;{alpha};0</rX><rY>0.25;0.5;0.75</rY>'
        f"<rZ>0;0;0</rZ></pointList></guideCurveProfile>" for uid, alpha in (("Bulge", 0.05), ("Straight", 0)))
    profiles = (f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(64)}</fuselageProfile>'
                f"</fuselageProfiles><guideCurves>{guide_profiles}</guideCurves>")
    path.write_text(HEADER + fuselage + f"</fuselages></model></aircraft><profiles>{profiles}</profiles></vehicles></cpacs>")


def test_guide_curves_shape_the_loft(tmp_path):
    path = tmp_path / "guided.xml"
    guided_cylinder(path, "C0")
    bulge, straight_after, side, girth_at_section = ask(
        path, {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.5, "zeta": 0.0},
        {"op": "fuselage_point", "fuselage": 1, "segment": 2, "eta": 0.5, "zeta": 0.0},
        {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.5, "zeta": 0.25},
        {"op": "fuselage_circumference", "fuselage": 1, "segment": 2, "eta": 0.0})
    # The loft passes through the guide's middle point, lifted 0.1 above the cylinder.
    assert all(math.isclose(a, b, abs_tol=1e-4) for a, b in zip(bulge, [2.5, 0, 1.1])), bulge
    # C0: the second segment's guide is straight on its own, so the top stays at z = 1.
    assert math.isclose(straight_after[2], 1.0, abs_tol=1e-4), straight_after
    # A straight guide at the side keeps the side where it was.
    assert all(math.isclose(a, b, abs_tol=1e-4) for a, b in zip(side, [2.5, 1, 0])), side
    # At a section the loft is the profile itself.
    assert math.isclose(girth_at_section, 2 * math.pi, rel_tol=1e-4)
    result = airshape("build", str(path))
    assert result.returncode == 0 and "valid solid" in result.stdout, result.stdout + result.stderr


def top_slopes_at_the_section(path):
    """The slope dz/dx of the top line just before and just after x = 5."""
    before_end, end, start, after_start = ask(
        path, *({"op": "fuselage_point", "fuselage": 1, "segment": seg, "eta": eta, "zeta": 0.0}
                for seg, eta in ((1, 0.99), (1, 1.0), (2, 0.0), (2, 0.01))))
    return ((end[2] - before_end[2]) / (end[0] - before_end[0]),
            (after_start[2] - start[2]) / (after_start[0] - start[0]))


def test_c0_continuity_leaves_a_kink_in_the_guide(tmp_path):
    """With C0 the top guide turns at the section (the bulge's cubic arrives with a slope, the
    straight piece leaves level); without it the guide is one smooth cubic through both."""
    kinked, smooth = tmp_path / "kinked.xml", tmp_path / "smooth.xml"
    guided_cylinder(kinked, "C0")
    guided_cylinder(smooth, None)
    before, after = top_slopes_at_the_section(kinked)
    assert abs(before - after) > 0.05 and abs(after) < 1e-3, (before, after)
    before, after = top_slopes_at_the_section(smooth)
    assert abs(before - after) < 0.01, (before, after)


def test_guide_curve_errors_name_the_curve(tmp_path):
    path = tmp_path / "broken.xml"
    guided_cylinder(path, "C0")
    path.write_text(path.read_text().replace("<guideCurveProfileUID>Straight</guideCurveProfileUID>",
                                             "<guideCurveProfileUID>Nowhere</guideCurveProfileUID>", 1))
    result = airshape("query", str(path), stdin='{"op":"fuselage_volume","fuselage":1}\n')
    answer = json.loads(result.stdout)
    assert "error" in answer and "Nowhere" in answer["error"] and "guideCurve" in answer["error"], answer


def test_guides_that_meet_name_their_cell(tmp_path):
    """The guide at a quarter of the circumference led to the half at the second profile,
    where the next guide ends: their cell is empty, and the error names both guide curves
    and the elements of the profiles around it (it counted them by index)."""
    path = tmp_path / "meeting.xml"
    guided_cylinder(path, "C0")
    start = '<guideCurve uID="G0.25S0">'
    text = path.read_text()
    at = text.index("<toRelativeCircumference>0.25</toRelativeCircumference>", text.index(start))
    path.write_text(text[:at] + "<toRelativeCircumference>0.5</toRelativeCircumference>" +
                    text[at + len("<toRelativeCircumference>0.25</toRelativeCircumference>"):])
    answer = json.loads(airshape("query", str(path), stdin='{"op":"fuselage_volume","fuselage":1}\n').stdout)
    assert answer.get("error", "").startswith(
        "/cpacs/vehicles/aircraft/model[1]/fuselages/fuselage[1]/segments: the guided skin: the cell between the "
        "profiles of elements 'FE0' and 'FE1' and between guide curves 'G0.25S0' and 'G0.5S0' is empty"), answer


def diamond_with_map(path, params):
    """Sections of a diamond with corners at its four points; point 1 (y = 1) is pinned to the
    profile parameter params[0] and point 3 (y = -1) to params[1]."""
    points = ("<pointList><x>0;0;0;0;0</x><y>0;1;0;-1;0</y><z>1;0;-1;0;1</z>"
              "<kinkIndices>0;1;2;3</kinkIndices><parameterMap><pointIndices>1;3</pointIndices>"
              f"<paramOnCurve>{params[0]};{params[1]}</paramOnCurve></parameterMap></pointList>")
    profiles = f'<fuselageProfiles><fuselageProfile uID="Diamond"><name>d</name>{points}</fuselageProfile></fuselageProfiles>'
    path.write_text(HEADER + fuselage("F", "Diamond", 4.0) +
                    f"</fuselages></model></aircraft><profiles>{profiles}</profiles></vehicles></cpacs>")


def test_a_parameter_map_pins_points_to_zeta(tmp_path):
    path = tmp_path / "diamond.xml"
    diamond_with_map(path, (0.1, 0.6))
    pinned, between = ask(path, {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.0, "zeta": 0.1},
                          {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.0, "zeta": 0.35})
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(pinned, [0, 1, 0])), pinned
    # Point 2 (the bottom) lies halfway between the pinned points in parameter.
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(between, [0, 0, -1])), between
    diamond_with_map(path, (0.6, 0.1))
    result = airshape("query", str(path), stdin='{"op":"fuselage_volume","fuselage":1}\n')
    answer = json.loads(result.stdout)
    assert "error" in answer and "parameterMap" in answer["error"], answer


def test_a_mirrored_half_profile_keeps_its_kinks(tmp_path):
    """The reference's <symmetry>half</symmetry>: the half diamond bottom, side, top with a
    corner at the side is mirrored into the whole (corners at both sides), interpolated and
    cut back to the half. Its lower run is the parabola z = y^2 - 1 through the bottom, its
    upper run z = 1 - y^2, so the half section has area 4/3 and the side lies at zeta 1/2."""
    path = tmp_path / "half.xml"
    points = ("<pointList><x>0;0;0</x><y>0;1;0</y><z>-1;0;1</z><kinkIndices>1</kinkIndices></pointList>"
              "<symmetry>half</symmetry>")
    profiles = f'<fuselageProfiles><fuselageProfile uID="Half"><name>h</name>{points}</fuselageProfile></fuselageProfiles>'
    path.write_text(HEADER + fuselage("F", "Half", 4.0) +
                    f"</fuselages></model></aircraft><profiles>{profiles}</profiles></vehicles></cpacs>")
    side, lower, volume = ask(path, {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.5, "zeta": 0.5},
                              {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.5, "zeta": 0.25},
                              {"op": "fuselage_volume", "fuselage": 1})
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(side, [1, 1, 0])), side
    assert all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(lower, [1, 0.5, -0.75])), lower
    assert math.isclose(volume, 4 * 4 / 3, rel_tol=1e-9), volume


def test_fuselage_conformance_does_not_regress():
    passed, output = conformance_passed("cases-fuselage.json")
    assert passed >= 207 and output.strip().endswith(" 0 failed"), output[-3000:]  # every case


def reference_cases(file_name, case_files=("cases-fuselage.json", "cases-components.json")):
    """The number-valued cases of the shared case files on one CPACS file (skips without them)."""
    cases = []
    for case_file in case_files:
        with open(shared_path("conformance", case_file)) as text:
            cases += [case for case in json.load(text)["cases"]
                      if case["file"] == file_name and isinstance(case.get("expect"), (int, float, list))
                      and not isinstance(case.get("expect"), bool) and case["query"]["op"].startswith(("fuselage", "cross"))]
    return cases


def test_rectangles_are_drawn_as_the_reference_draws_them():
    """An unguided loft through a circle and two rectangles: with each straight piece and
    each corner of the rectangles one cubic span, points, sections and volumes agree with the
    reference's figures 100 times closer than the cases ask (points were 2 mm off when the
    rectangle was a spline through dense samples of the same shape)."""
    name = "simpletest_standard_profile_rectangle_circle_kink.cpacs.xml"
    cases = [case for case in reference_cases(name) if case["query"]["op"] != "fuselage_count"]
    assert len(cases) >= 6, cases
    answers = ask(shared_path("data", "cpacs", name), *(case["query"] for case in cases))
    for case, got in zip(cases, answers):
        expected = case["expect"]
        if isinstance(expected, list):
            assert max(abs(a - b) for a, b in zip(got, expected)) < 5e-5, (case["query"], got, expected)
        else:
            assert math.isclose(got, expected, rel_tol=1e-5), (case["query"], got, expected)


def test_faces_are_named(tmp_path):
    path = tmp_path / "cylinders.xml"
    write_cylinders(path)
    full, half = ask(path, {"op": "component_faces", "uid": "Full"}, {"op": "component_faces", "uid": "HalfCylinder"})
    areas = {face["name"]: face["area"] for face in full}
    assert set(areas) == {"Full/front", "Full/rear", "FullG0/skin", "FullG1/skin"}, areas
    assert math.isclose(areas["FullG0/skin"], 2 * math.pi * 5, rel_tol=1e-5)
    assert math.isclose(areas["Full/front"], math.pi, rel_tol=1e-5)
    names = {face["name"] for face in half}
    assert {"HalfCylinderG0/symmetry", "HalfCylinderG1/symmetry"} <= names, names


def test_guides_may_start_at_a_profile_parameter(tmp_path):
    """The reference's fromParameter/toParameter (outside the schema) place a guide at a
    parameter of the profile curve: on an evenly spaced circle, zeta 0.25 is rc 0.25."""
    by_circumference, by_parameter = tmp_path / "rc.xml", tmp_path / "parameter.xml"
    guided_cylinder(by_circumference, "C0")
    text = by_circumference.read_text()
    by_parameter.write_text(
        text.replace("<fromRelativeCircumference>0.25</fromRelativeCircumference>", "<fromParameter>0.25</fromParameter>")
            .replace("<toRelativeCircumference>0.25</toRelativeCircumference>",
                     "<toParameter>0.25</toParameter><toRelativeCircumference>0</toRelativeCircumference>"))
    query = {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0.3, "zeta": 0.25}
    (a,) = ask(by_circumference, query)
    (b,) = ask(by_parameter, query)
    assert all(math.isclose(x, y, abs_tol=1e-6) for x, y in zip(a, b)), (a, b)


def test_a_loft_that_cannot_be_built_names_the_fuselage(tmp_path):
    """Two sections in one place leave the loft's interpolation singular: the error names the
    fuselage's segments, and the other fuselage still builds. (Sections 1e200 apart, which
    overflowed the loft, are now refused at their translation: beyond 1e9.)"""
    profile = f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(16)}</fuselageProfile></fuselageProfiles>'
    path = tmp_path / "far.xml"
    path.write_text(HEADER + fuselage("Far", "Circle", 1.0, [0, 1, 1]) + fuselage("Near", "Circle", 10.0) +
                    f"</fuselages></model></aircraft><profiles>{profile}</profiles></vehicles></cpacs>")
    result = airshape("query", str(path), stdin='{"op":"fuselage_volume","fuselage":"Far"}\n'
                                                 '{"op":"fuselage_volume","fuselage":"Near"}\n')
    far, near = (json.loads(line) for line in result.stdout.splitlines())
    assert "/fuselages/fuselage[1]/segments" in far.get("error", ""), far
    assert near["ok"] > 0


def test_a_fuselage_whose_end_profile_is_flattened_names_the_fuselage(tmp_path):
    """A nose profile scaled to a line (y = 0) closes with no cap: `build` names the fuselage's
    CPACS path (it said "the fuselage"), and the other fuselage still builds."""
    profile = f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(16)}</fuselageProfile></fuselageProfiles>'
    flat = fuselage("Flat", "Circle", 10.0).replace(
        '<element uID="FlatE0"><name>e</name><profileUID>Circle</profileUID><transformation/>',
        '<element uID="FlatE0"><name>e</name><profileUID>Circle</profileUID>'
        "<transformation><scaling><x>1</x><y>0</y><z>1</z></scaling></transformation>", 1)
    assert "<y>0</y>" in flat
    path = tmp_path / "flat.xml"
    path.write_text(HEADER + flat + fuselage("Round", "Circle", 10.0) +
                    f"</fuselages></model></aircraft><profiles>{profile}</profiles></vehicles></cpacs>")
    lines = {line.split()[1]: line for line in airshape("build", str(path)).stdout.splitlines()
             if line.startswith("  fuselage")}
    assert "FAILED: /cpacs/vehicles/aircraft/model[1]/fuselages/fuselage[1]: " in lines["Flat"], lines
    assert "encloses no area" in lines["Flat"] and "valid solid" in lines["Round"], lines


def test_a_profile_whose_points_are_out_of_order_is_an_error_naming_it(tmp_path):
    """A circle's points given every other one first: the outline crosses itself (the
    fuselage was an INVALID solid with a volume)."""
    count = 32
    order = list(range(0, count + 1, 2)) + list(range(1, count + 1, 2))
    angles = [2 * math.pi * i / count for i in order]
    points = (f'<pointList><x>{";".join("0" for _ in angles)}</x>'
              f'<y>{";".join(f"{math.sin(a):.17g}" for a in angles)}</y>'
              f'<z>{";".join(f"{math.cos(a):.17g}" for a in angles)}</z></pointList>')
    profile = f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{points}</fuselageProfile></fuselageProfiles>'
    path = tmp_path / "scrambled.xml"
    path.write_text(HEADER + fuselage("Scrambled", "Circle", 10.0) +
                    f"</fuselages></model></aircraft><profiles>{profile}</profiles></vehicles></cpacs>")
    answer = json.loads(airshape("query", str(path), stdin='{"op":"fuselage_volume","fuselage":1}\n').stdout)
    assert answer.get("error", "").startswith(
        "/cpacs/vehicles/profiles/fuselageProfiles/fuselageProfile[1]/pointList: the points' outline crosses itself"), answer


def approximated_cylinders(path, settings, kinks=""):
    """Prisms 10 long of a circle of radius 1 given by 64 points with a ripple of 1 mm on every
    other point, approximated by the settings given (the reference's approximationSettings),
    with the kinkIndices given."""
    angles = [2 * math.pi * i / 64 for i in range(65)]
    radius = [1.0 + (0.001 if i % 2 else 0.0) for i in range(65)]
    ys = ";".join(f"{r * math.sin(a):.17g}" for r, a in zip(radius, angles))
    zs = ";".join(f"{r * math.cos(a):.17g}" for r, a in zip(radius, angles))
    kink_list = f"<kinkIndices>{kinks}</kinkIndices>" if kinks else ""
    profile = (f'<fuselageProfile uID="Rippled"><name>p</name><pointList><x>{";".join("0" * 65)}</x><y>{ys}</y>'
               f"<z>{zs}</z>{kink_list}<approximationSettings{settings}</approximationSettings></pointList>"
               "</fuselageProfile>")
    path.write_text(HEADER + fuselage("Smooth", "Rippled", 10.0) +
                    f"</fuselages></model></aircraft><profiles><fuselageProfiles>{profile}</fuselageProfiles>"
                    "</profiles></vehicles></cpacs>")


def test_approximation_settings_smooth_a_fuselage_profile(tmp_path):
    path = tmp_path / "approximated.xml"
    approximated_cylinders(path, ' errorComputationMethod="MaxError"><controlPointNumber>16</controlPointNumber>'
                                 "<interpolatedPointsIndices>17</interpolatedPointsIndices>")
    volume, circumference, seam, pinned, between = ask(
        path, {"op": "fuselage_volume", "fuselage": 1}, {"op": "fuselage_circumference", "fuselage": 1, "segment": 1,
                                                         "eta": 0.5},
        {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0, "zeta": 0},
        {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0, "zeta": 0.25},
        {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0, "zeta": 1 / 64})
    # The fit runs between the rippled points: its radius is that of their mean, not a zig-zag.
    assert math.isclose(volume, math.pi * 1.0005 ** 2 * 10, rel_tol=2e-4), volume
    assert math.isclose(circumference, 2 * math.pi * 1.0005, rel_tol=2e-4), circumference
    assert abs(math.hypot(seam[1], seam[2]) - 1.0005) < 5e-4 and seam[2] > 0.99, seam
    # Point 17 (1-based; a quarter turn, radius 1) is interpolated exactly.
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(pinned, [0, 1, 0])), pinned
    assert abs(math.hypot(between[1], between[2]) - 1.0005) < 5e-4, between


def test_an_approximated_profile_counts_its_kinks_from_one(tmp_path):
    # kinkIndices 17 beside approximationSettings is the 17th point (the schema's [1, npoints],
    # as the reference reads them there beside the 1-based interpolatedPointsIndices): the
    # quarter turn at radius 1, which the fit then passes through exactly. Counted from 0 it
    # would be the next point, on the ripple (radius 1.001 at 2π · 17/64).
    path = tmp_path / "kinked.xml"
    approximated_cylinders(path, "><controlPointNumber>16</controlPointNumber>", kinks="17")
    at_kink, = ask(path, {"op": "fuselage_point", "fuselage": 1, "segment": 1, "eta": 0, "zeta": 0.25})
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(at_kink, [0, 1, 0])), at_kink
    approximated_cylinders(path, "><controlPointNumber>16</controlPointNumber>", kinks="0")
    answer = json.loads(airshape("query", str(path), stdin='{"op":"fuselage_volume","fuselage":1}\n').stdout)
    assert answer["error"].endswith("pointList/kinkIndices: index 0 names no point of the list"), answer


def test_an_approximated_profile_whose_fit_parts_its_seam_is_closed(tmp_path):
    # A D of the unit half disc (top, down the right quarter, along the flat bottom with its
    # corners as kinks, up the left quarter in fewer, uneven points), 12 poles: the corrections
    # part the fit's ends at the top by some 5 cm, as the reference's fit of such a profile
    # does, and a straight piece closes it, so that the fuselage is a closed solid of nearly
    # the half disc's area.
    right = [(math.sin(a), math.cos(a)) for a in (0.5 * math.pi * i / 20 for i in range(21))]
    bottom = [(1 - 2 * i / 20, 0.0) for i in range(1, 21)]
    left = [(-math.cos(a), math.sin(a)) for a in (0.5 * math.pi * (i / 7) ** 1.5 for i in range(1, 8))]
    points = right + bottom + left
    ys = ";".join(f"{y:.17g}" for y, _ in points)
    zs = ";".join(f"{z:.17g}" for _, z in points)
    profile = (f'<fuselageProfile uID="DProfile"><name>p</name><pointList><x>{";".join("0" * len(points))}</x><y>{ys}</y>'
               f"<z>{zs}</z><kinkIndices>21;41</kinkIndices><approximationSettings><controlPointNumber>12"
               "</controlPointNumber></approximationSettings></pointList></fuselageProfile>")
    path = tmp_path / "d.xml"
    path.write_text(HEADER + fuselage("D", "DProfile", 10.0) + "</fuselages></model></aircraft><profiles><fuselageProfiles>"
                    f"{profile}</fuselageProfiles></profiles></vehicles></cpacs>")
    built = airshape("build", str(path))
    assert "valid solid" in built.stdout, built.stdout + built.stderr
    volume, = ask(path, {"op": "fuselage_volume", "fuselage": 1})
    assert math.isclose(volume, 0.5 * math.pi * 10, rel_tol=0.01), volume


def test_approximation_settings_that_cannot_be_met_name_the_node(tmp_path):
    path = tmp_path / "approximated.xml"
    approximated_cylinders(path, "><controlPointNumber>2</controlPointNumber>")
    answer = json.loads(airshape("query", str(path), stdin='{"op":"fuselage_volume","fuselage":1}\n').stdout)
    assert "pointList/approximationSettings/controlPointNumber: controlPointNumber must lie in [4" in answer["error"]


def test_ducts_are_lofted_as_fuselages_are(tmp_path):
    # A duct of the unit circle at x = 0, 5 and 10: the cylinder again, and its segments halves.
    profiles = f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(64)}</fuselageProfile></fuselageProfiles>'
    def duct(uid, shift=0.0):
        return (fuselage(uid, "Circle", 10.0).replace("<fuselage ", "<duct ").replace("</fuselage>", "</duct>")
                .replace("<transformation/>", f"<transformation><translation><x>{shift}</x></translation>"
                                              "</transformation>", 1))
    # "Both": the pipe and the same pipe 4 further along x, overlapping over 6 m; "Empty": none.
    assembly = ('<ductAssembly uID="Both"><name>a</name><ductUIDs><uID>Pipe</uID><uID>Further</uID></ductUIDs>'
                '</ductAssembly><ductAssembly uID="Empty"><name>a</name><ductUIDs/></ductAssembly>'
                '<ductAssembly uID="Wrong"><name>a</name><ductUIDs><uID>Hull</uID></ductUIDs></ductAssembly>')
    path = tmp_path / "duct.xml"
    path.write_text(HEADER + fuselage("Hull", "Circle", 10.0) + f"</fuselages><ducts>{duct('Pipe')}{duct('Further', 4.0)}{assembly}</ducts>"
                    f"</model></aircraft><profiles>{profiles}</profiles></vehicles></cpacs>")
    volume, segment, kind, segment_kind = ask(
        path, {"op": "component_volume", "uid": "Pipe"}, {"op": "component_volume", "uid": "PipeG1"},
        {"op": "component_type", "uid": "Pipe"}, {"op": "component_type", "uid": "PipeG1"})
    assert math.isclose(volume, math.pi * 10, rel_tol=1e-5) and math.isclose(segment, math.pi * 5, rel_tol=1e-5)
    assert kind == "duct" and segment_kind == "fuselage_segment"
    union, both_kind = ask(path, {"op": "component_volume", "uid": "Both"}, {"op": "component_type", "uid": "Both"})
    assert math.isclose(union, math.pi * 14, rel_tol=1e-5) and both_kind == "duct"  # one pipe 14 long
    queries = "".join(json.dumps({"op": "component_volume", "uid": uid}) + "\n" for uid in ("Empty", "Wrong"))
    empty, wrong = (json.loads(line)["error"] for line in airshape("query", str(path), stdin=queries).stdout.splitlines())
    assert "ductAssembly[2]: the duct assembly names no ducts" in empty
    assert "ductAssembly[3]/ductUIDs: 'Hull' names no duct" in wrong
    # An export writes each duct once, through the ducts, not again through their assemblies.
    exported = airshape("export", str(path), "-o", str(tmp_path / "ducts.brep"))
    assert exported.returncode == 0, exported.stderr
    assert "Pipe " in exported.stdout and "Further " in exported.stdout and "Both " not in exported.stdout
