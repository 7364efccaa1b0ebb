"""Engine pylons and nacelles (docs/nacelle.md) on the rectangular test wing's file. A pylon of the
parabolic CST airfoil (area 0.05·c² at chord c) whose chord grows linearly, 1, 2 and 3 at 0, 1 and
2 m along its span, so that its smooth loft is the straight taper with volume ∫ 0.05·(1 + t)² dt.
Nacelles whose one-section cowls are bodies of revolution: Pappus' theorem relates their volumes
at two radii to the area of their meridian section, and a cylindrical centre cowl has a closed
form."""
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


# A symmetric nacelle profile (x from 1 over 0 back to 1, thickness 0.1) and two curve profiles:
# a straight inner line and a straight centre cowl line at radius 0.1.
THICKNESS = [0.0, 0.02, 0.035, 0.045, 0.05, 0.045, 0.03, 0.0]
STATIONS = [1.0, 0.8, 0.6, 0.4, 0.25, 0.12, 0.04, 0.0]


def nacelle_profiles():
    xs = STATIONS + STATIONS[-2::-1]
    ys = [-t for t in THICKNESS] + THICKNESS[-2::-1]
    profile = (f'<nacelleProfile uID="Cowl"><name>c</name><pointList><x>{";".join(map(str, xs))}</x>'
               f'<y>{";".join(map(str, ys))}</y></pointList></nacelleProfile>')
    curves = ('<curveProfile uID="Inner"><name>i</name><pointList><x>0;1</x><y>-0.06;-0.06</y></pointList></curveProfile>'
              '<curveProfile uID="Spinner"><name>s</name><pointList><x>0;1</x><y>0.1;0.1</y></pointList></curveProfile>')
    return f"<nacelleProfiles>{profile}</nacelleProfiles><curveProfiles>{curves}</curveProfiles>"


def engine(uid, radius, spinner=False, angles=(0,)):
    section = "".join(
        f'<section uID="{uid}S{"" if i == 0 else i}"><name>s</name><transformation><scaling><x>2</x><y>1</y><z>1</z>'
        f"</scaling><translation><x>{angle}</x><y>0</y><z>{radius}</z></translation></transformation>"
        "<profileUID>Cowl</profileUID></section>" for i, angle in enumerate(angles))
    rotation = (f'<rotationCurve uID="{uid}R"><referenceSectionUID>{uid}S</referenceSectionUID>'
                "<curveProfileUID>Inner</curveProfileUID><startZeta>-0.6</startZeta><endZeta>-0.3</endZeta>"
                "<startZetaBlending>-0.7</startZetaBlending><endZetaBlending>-0.2</endZetaBlending></rotationCurve>")
    centre = ('<centerCowl uID="{0}C"><xOffset>0.5</xOffset><curveUID>Spinner</curveUID></centerCowl>'.format(uid)
              if spinner else "")
    return (f'<engine uID="{uid}"><name>e</name><nacelle uID="{uid}N"><fanCowl uID="{uid}F"><sections>{section}'
            f"</sections>{rotation}</fanCowl>{centre}</nacelle></engine>")


def placement(uid, engine_uid, x=0.0):
    return (f'<engine uID="{uid}"><name>p</name><engineUID>{engine_uid}</engineUID><parentUID>Rect</parentUID>'
            f"<transformation><translation><x>{x}</x><y>20</y><z>0</z></translation></transformation></engine>")


def write(path):
    with open(RECTANGULAR) as original:
        text = original.read()
    pylons = f"<enginePylons>{pylon()}{pylon('Bare', segments=False)}</enginePylons>"
    placements = ("<engines>" + placement("Low", "LowEngine") + placement("High", "HighEngine", x=5) +
                  placement("Spun", "SpinnerEngine", x=10) + placement("Hollow", "NoNacelle", x=15) +
                  placement("Lofted", "ThreeSectionEngine", x=20) + "</engines>")
    engines = ("<engines>" + engine("LowEngine", 0.5) + engine("HighEngine", 0.8) + engine("SpinnerEngine", 0.5, True) +
               engine("ThreeSectionEngine", 0.5, angles=(0, 120, 240)) +
               '<engine uID="NoNacelle"><name>n</name></engine></engines>')
    text = text.replace("</wings>", "</wings>" + placements + pylons, 1)
    text = text.replace("</aircraft>", "</aircraft>" + engines, 1)
    path.write_text(text.replace("<wingAirfoils>", nacelle_profiles() + "<wingAirfoils>", 1))


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


def test_one_section_nacelles_are_bodies_of_revolution(tmp_path):
    path = tmp_path / "nacelles.xml"
    write(path)
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


def test_sections_lofted_around_the_engine(tmp_path):
    path = tmp_path / "nacelles.xml"
    write(path)
    revolved, lofted, box = ask(path, {"op": "component_volume", "uid": "Low"},
                                {"op": "component_volume", "uid": "Lofted"}, {"op": "bounding_box", "uid": "Lofted"})
    # Three equal sections at 0°, 120° and 240°: the loft around the engine is the body of
    # revolution of one, up to the interpolation between the sampled angles.
    assert math.isclose(lofted, revolved, rel_tol=1e-4)
    assert math.isclose(box["max"][1] - 20, 20 - box["min"][1], rel_tol=1e-4)


def test_an_engine_without_nacelle_has_no_shape(tmp_path):
    path = tmp_path / "nacelles.xml"
    write(path)
    result = airshape("query", str(path), stdin=json.dumps({"op": "component_volume", "uid": "Hollow"}) + "\n")
    answer = json.loads(result.stdout)
    assert "has no nacelle" in answer["error"] and "vehicles/engines/engine[5]" in answer["error"]


def test_nacelle_conformance_does_not_regress():
    passed, output = conformance_passed("cases-nacelle.json")
    assert passed >= 35, output[-3000:]
