"""Fuselage geometry on a cylinder the test writes itself, where every number has a closed form."""
import json
import math

from conftest import airshape

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


def ask(path, *queries):
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    assert result.returncode == 0, result.stderr
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert all("ok" in a for a in answers), answers
    return [a["ok"] for a in answers]


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
