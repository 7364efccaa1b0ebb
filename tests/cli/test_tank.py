"""Fuel tanks and their vessels (docs/tank.md) on a file the test writes: vessels of design
parameters whose volumes, areas and lengths are known in closed form, a vessel lofted from
sections, tanks placed on their parent, the CPACS 3.5 tank inside a fuselage, and the errors."""
import json
import math

from conftest import airshape, query_answers as ask
from test_fuselage import HEADER, circle, fuselage


def vessel(uid, radius, length, dome, transformation=""):
    return (f'<vessel uID="{uid}"><name>v</name><transformation>{transformation}</transformation>'
            f"<cylinderRadius>{radius}</cylinderRadius><cylinderLength>{length}</cylinderLength>"
            f"<domeType>{dome}</domeType></vessel>")


def ellipsoid(fraction):
    return f"<ellipsoid><halfAxisFraction>{fraction}</halfAxisFraction></ellipsoid>"


def lofted_vessel(uid):
    """A cylinder of radius 0.5 and length 2 lofted from three circular sections."""
    sections = "".join(
        f'<section uID="{uid}S{i}"><name>s</name><transformation><translation><x>{x}</x></translation>'
        f'<scaling><x>1</x><y>0.5</y><z>0.5</z></scaling></transformation><elements><element uID="{uid}E{i}">'
        f"<name>e</name><profileUID>Circle</profileUID><transformation/></element></elements></section>"
        for i, x in enumerate([0, 1, 2]))
    segments = "".join(f'<segment uID="{uid}G{i}"><name>g</name><fromElementUID>{uid}E{i}</fromElementUID>'
                       f"<toElementUID>{uid}E{i + 1}</toElementUID></segment>" for i in range(2))
    return (f'<vessel uID="{uid}"><name>v</name><transformation/><sections>{sections}</sections>'
            f"<segments>{segments}</segments></vessel>")


def tank(uid, vessels, transformation="", parent="Body"):
    return (f'<fuelTank uID="{uid}"><name>t</name><parentUID>{parent}</parentUID>'
            f"<transformation>{transformation}</transformation><vessels>{vessels}</vessels></fuelTank>")


# Walls inside a vessel (the structure plugin, through the tank plugin's services): positioned
# in the vessel's frame, kept inside its solid.
WALLED = ('<vessel uID="Walled"><name>v</name><transformation/><cylinderRadius>1</cylinderRadius>'
          "<cylinderLength>2</cylinderLength><domeType>" + ellipsoid(0) + "</domeType><structure><walls>"
          '<wallPositions><wallPosition uID="WP1"><x>1</x><y>-1</y><z>-0.2</z></wallPosition>'
          '<wallPosition uID="WP2"><x>1</x><y>1</y><z>-0.2</z></wallPosition></wallPositions>'
          '<wallSegments><wallSegment uID="Baffle"><phi>180</phi><wallPositionUIDs><wallPositionUID>WP1'
          "</wallPositionUID><wallPositionUID>WP2</wallPositionUID></wallPositionUIDs></wallSegment></wallSegments>"
          "</walls></structure></vessel>")

TANKS = (
    tank("Spheres", vessel("Sphere", 1, 2, ellipsoid(1)) + vessel("Half", 1, 2, ellipsoid(0.5)) +
         vessel("Flat", 1, 2, ellipsoid(0)) + vessel("Long", 0.5, 1, ellipsoid(2))) +
    tank("Turned", vessel("Tori", 1, 2, "<torispherical><dishRadius>2</dishRadius><knuckleRadius>0.2</knuckleRadius>"
                                       "</torispherical>"),
         "<translation><x>1</x><y>-3</y></translation><rotation><z>90</z></rotation>") +
    tank("Wound", vessel("Iso", 1, 2, "<isotensoid><polarOpeningRadius>0.1</polarOpeningRadius></isotensoid>")) +
    tank("Lofted", lofted_vessel("Loft")) +
    tank("Broken", vessel("NoRadius", -1, 1, ellipsoid(1)) +
         vessel("TooWide", 1, 1, "<isotensoid><polarOpeningRadius>1.5</polarOpeningRadius></isotensoid>") +
         '<vessel uID="Nothing"><name>v</name></vessel>') +
    tank("Baffled", WALLED))

# A fuselage 10 m long placed 5 m aft holds a CPACS 3.5 tank of design parameters.
INNER_TANK = ("<fuelTanks><genericFuelTanks><genericFuelTank uID=\"Inner\"><name>t</name><designParameters>"
              "<transformation><translation><x>2</x></translation></transformation><cylinderRadius>0.5"
              "</cylinderRadius><cylinderLength>3</cylinderLength><domeType><spherical/></domeType>"
              "</designParameters></genericFuelTank></genericFuelTanks></fuelTanks></fuselage>")


def write_tanks(path):
    body = fuselage("Body", "Circle", 10.0).replace("<transformation/>",
                                                     "<transformation><translation><x>5</x></translation>"
                                                     "</transformation>", 1)
    body = body[:-len("</fuselage>")] + INNER_TANK
    profiles = f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(64)}</fuselageProfile></fuselageProfiles>'
    path.write_text(HEADER + body + f"</fuselages><fuelTanks>{TANKS}</fuelTanks></model></aircraft>"
                    f"<profiles>{profiles}</profiles></vehicles></cpacs>")


def measures(path, uid):
    return ask(path, {"op": "component_volume", "uid": uid}, {"op": "component_surface_area", "uid": uid},
               {"op": "bounding_box", "uid": uid})


def test_ellipsoid_domes_in_closed_form(tmp_path):
    path = tmp_path / "tanks.xml"
    write_tanks(path)
    volume, area, box = measures(path, "Sphere")
    # A cylinder of radius 1 and length 2 between two half spheres, from the tank's parent's
    # origin (x = 5) on.
    assert math.isclose(volume, 2 * math.pi + 4 / 3 * math.pi, rel_tol=1e-6)
    assert math.isclose(area, 4 * math.pi + 4 * math.pi, rel_tol=1e-6)
    assert all(math.isclose(a, b, abs_tol=1e-6) for a, b in zip(box["min"] + box["max"], [5, -1, -1, 9, 1, 1]))
    half, flat, long_ = (ask(path, {"op": "component_volume", "uid": uid})[0] for uid in ("Half", "Flat", "Long"))
    assert math.isclose(half, 2 * math.pi + 4 / 3 * math.pi * 0.5, rel_tol=1e-6)
    assert math.isclose(flat, 2 * math.pi, rel_tol=1e-6)  # flat ends
    assert math.isclose(long_, math.pi * 0.25 + 4 / 3 * math.pi * 0.25 * 1.0, rel_tol=1e-6)  # domes 1 deep


def test_a_wall_inside_a_vessel(tmp_path):
    path = tmp_path / "tanks.xml"
    write_tanks(path)
    volume, area, box = measures(path, "Baffle")
    # The plane x = 1 of the vessel (the cylinder runs from x = 0 to 2 between flat ends, from
    # the parent's origin x = 5 on), from z = -0.2 downwards (phi 180°): a segment of the unit disc.
    assert volume == 0 and math.isclose(area, math.acos(0.2) - 0.2 * math.sqrt(0.96), rel_tol=1e-6)
    assert math.isclose(box["min"][0], 6, abs_tol=1e-6) and math.isclose(box["max"][0], 6, abs_tol=1e-6)
    assert math.isclose(box["max"][2], -0.2, abs_tol=1e-6) and math.isclose(box["min"][2], -1, abs_tol=1e-6)


def test_torispherical_dome_on_a_turned_tank(tmp_path):
    path = tmp_path / "tanks.xml"
    write_tanks(path)
    volume, area, box = measures(path, "Tori")
    depth = 2 - math.sqrt(1.8 ** 2 - 0.8 ** 2)  # crown radius 2, knuckle 0.2 on a cylinder of radius 1
    # Turned by 90° about z and moved to (1, -3) from the parent's origin: the axis runs along y.
    assert math.isclose(box["max"][1] - box["min"][1], 2 + 2 * depth, rel_tol=1e-6)
    assert math.isclose(box["min"][1], -3, abs_tol=1e-6) and math.isclose(box["min"][0], 5, abs_tol=1e-6)
    # Between the cylinder alone and the cylinder with flat caps out to the domes' apexes.
    assert 2 * math.pi < volume < math.pi * (2 + 2 * depth) and area > 4 * math.pi + 2 * math.pi


def test_isotensoid_dome(tmp_path):
    path = tmp_path / "tanks.xml"
    write_tanks(path)
    volume, area, box = measures(path, "Iso")
    length = box["max"][0] - box["min"][0]
    depth = (length - 2) / 2
    # A dome of netting theory on radius 1 with a polar opening of 0.1 is about 0.6 deep, less
    # than a half sphere's volume and more than a cone's.
    assert 0.55 < depth < 0.65, depth
    dome = (volume - 2 * math.pi) / 2
    assert math.pi * depth / 3 < dome < 2 / 3 * math.pi, dome


def test_tank_of_vessels_and_a_lofted_vessel(tmp_path):
    path = tmp_path / "tanks.xml"
    write_tanks(path)
    tank_volume, sphere, half, flat, long_, loft, segment, kind = ask(
        path, {"op": "component_volume", "uid": "Spheres"},
        *({"op": "component_volume", "uid": uid} for uid in ("Sphere", "Half", "Flat", "Long", "Loft", "LoftG0")),
        {"op": "component_type", "uid": "Loft"})
    assert math.isclose(tank_volume, sphere + half + flat + long_, rel_tol=1e-9)  # the compound of its vessels
    assert kind == "tank_hull"
    # The circle of 64 points lofted: a cylinder of radius 0.5 and length 2 (to the polygon's
    # interpolation), its first segment half of it.
    assert math.isclose(loft, math.pi * 0.25 * 2, rel_tol=1e-4), loft
    assert math.isclose(segment, loft / 2, rel_tol=1e-6)


def test_a_cpacs_35_tank_inside_a_fuselage(tmp_path):
    path = tmp_path / "tanks.xml"
    write_tanks(path)
    volume, area, box = measures(path, "Inner")
    assert math.isclose(volume, math.pi * 0.25 * 3 + 4 / 3 * math.pi * 0.125, rel_tol=1e-6)
    assert math.isclose(box["min"][0], 7, abs_tol=1e-6)  # the fuselage's origin 5, then 2 along x


def test_broken_vessels_name_their_paths(tmp_path):
    path = tmp_path / "tanks.xml"
    write_tanks(path)
    queries = "".join(json.dumps({"op": "component_volume", "uid": uid}) + "\n"
                      for uid in ("NoRadius", "TooWide", "Nothing", "Broken"))
    radius, opening, nothing, tank = (json.loads(line)["error"]
                                      for line in airshape("query", str(path), stdin=queries).stdout.splitlines())
    assert radius.endswith("fuelTank[5]/vessels/vessel[1]/cylinderRadius: the cylinder radius must be positive")
    assert "vessel[2]/domeType: the polar opening radius 1.5 must lie between 0 and the cylinder radius 1" in opening
    assert "vessel[3]: the vessel needs sections and segments" in nothing
    assert "vessel[1]/cylinderRadius" in tank  # a tank is as broken as its first broken vessel
