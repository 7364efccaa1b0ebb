"""Fuselage structure (docs/structure.md): pressure bulkheads, walls, cross beams and doors in a unit cylinder the test
writes itself (radius 1, x from 0 to 10, sections at x = 0, 5 and 10), where every area has a
closed form."""
import json
import math

import pytest

from conftest import airshape, query_answers as ask
from independent_readers import gmsh_surfaces
from test_fuselage import HEADER, circle, fuselage

# The interpolated 64-point circle is a circle to about 1e-6.
REL = 1e-5


def position(uid, y, z, x=None, bulkhead=None, section=None, wall=None):
    place = (f"<x>{x}</x>" if x is not None else f"<bulkheadUID>{bulkhead}</bulkheadUID>" if bulkhead
             else f"<fuselageSectionUID>{section}</fuselageSectionUID>" if section
             else f"<wallSegmentUID>{wall}</wallSegmentUID>")
    return f'<wallPosition uID="{uid}">{place}<y>{y}</y><z>{z}</z></wallPosition>'


def wall(uid, phi, *positions, extra=""):
    uids = "".join(f"<wallPositionUID>{p}</wallPositionUID>" for p in positions)
    return f'<wallSegment uID="{uid}"><phi>{phi}</phi>{extra}<wallPositionUIDs>{uids}</wallPositionUIDs></wallSegment>'


def frame(uid, *stations):
    """A frame through (x, referenceY) or (x, referenceY, referenceAngle) positions."""
    positions = "".join(f'<framePosition uID="{uid}P{i}"><structuralElementUID>E</structuralElementUID>'
                        f"<positionX>{x}</positionX><referenceY>{y}</referenceY><referenceZ>0</referenceZ>"
                        f"<referenceAngle>{angle[0] if angle else 0}</referenceAngle></framePosition>"
                        for i, (x, y, *angle) in enumerate(stations))
    return f'<frame uID="{uid}">{positions}</frame>'


def write(path, structure):
    body = fuselage("Tube", "Circle", 10.0).replace("</fuselage>", f"<structure>{structure}</structure></fuselage>")
    profiles = f'<fuselageProfiles><fuselageProfile uID="Circle"><name>c</name>{circle(64)}</fuselageProfile></fuselageProfiles>'
    path.write_text(HEADER + body + f"</fuselages></model></aircraft><profiles>{profiles}</profiles></vehicles></cpacs>")


def stringer(uid, *positions):
    """A stringer through (x, referenceZ, referenceAngle) positions, referenceY 0; an x that is
    a string is a section element's uID."""
    def station(x):
        return f"<sectionElementUID>{x}</sectionElementUID>" if isinstance(x, str) else f"<positionX>{x}</positionX>"
    return f'<stringer uID="{uid}">' + "".join(
        f'<stringerPosition uID="{uid}P{i}"><structuralElementUID>E</structuralElementUID>{station(x)}'
        f"<referenceY>0</referenceY><referenceZ>{z}</referenceZ><referenceAngle>{angle}</referenceAngle>"
        "</stringerPosition>" for i, (x, z, angle) in enumerate(positions)) + "</stringer>"


def door(uid, start_frame, end_frame, start_stringer, end_stringer):
    return (f'<cargoDoor uID="{uid}"><doorElementUID>E</doorElementUID><startFrameUID>{start_frame}</startFrameUID>'
            f"<endFrameUID>{end_frame}</endFrameUID><startStringerUID>{start_stringer}</startStringerUID>"
            f"<endStringerUID>{end_stringer}</endStringerUID></cargoDoor>")


def structure():
    stringers = (stringer("Side", (0, 0, 90), (10, 0, 90)) + stringer("Top", (0, 0, 0), (10, 0, 0)) +
                 stringer("Left", (5, 0, -45)) + stringer("Right", (5, 0, 45)) +
                 stringer("Tilted", (3, 0, 90), (7, 0.5, 90)) + stringer("AtSections", ("TubeE1", 0, 90), ("TubeE2", 0, 90)))
    doors = (door("D1", "F0", "F1", "Side", "Top") + door("OverTheTop", "F1", "F0", "Right", "Left") +
             door("Rising", "F0", "F1", "Tilted", "Top") + door("Astray", "F0", "F1", "Side", "Nowhere") +
             door("Flat", "F1", "F1", "Side", "Top"))
    frames = (frame("F1", (7, 0)) + frame("Path", (4, -0.5), (4, 0), (4, 0.5)) +
              frame("Riffled", (4, 0, 0), (5, 0, 90), (4, 0, 180), (5, 0, 270), (4, 0, 360)) + frame("F0", (3, 0)) + frame("Pair", (4.5, -0.5), (4.5, 0.5)))
    bulkheads = ('<pressureBulkheads><pressureBulkhead uID="B1"><frameUID>F1</frameUID>'
                 "<pressureBulkheadElementUID>E</pressureBulkheadElementUID></pressureBulkhead>"
                 '<pressureBulkhead uID="OnPath"><frameUID>Path</frameUID>'
                 "<pressureBulkheadElementUID>E</pressureBulkheadElementUID></pressureBulkhead>"
                 '<pressureBulkhead uID="OnRiffles"><frameUID>Riffled</frameUID>'
                 "<pressureBulkheadElementUID>E</pressureBulkheadElementUID></pressureBulkhead>"
                 '<pressureBulkhead uID="OnPair"><frameUID>Pair</frameUID>'
                 "<pressureBulkheadElementUID>E</pressureBulkheadElementUID></pressureBulkhead></pressureBulkheads>")
    positions = (position("P1", 0.3, 0, x=2) + position("P2", 0.3, 0, bulkhead="B1") +
                 position("P3", -0.5, 0, section="TubeS1") + position("P4", -0.5, 0, x=9) +
                 position("P5", 0, 0.5, x=3) + position("P6", 0, 0.5, x=6) +
                 position("Lost", 0, 0, bulkhead="Nowhere") + position("Self", 0.3, 0, wall="Loop"))
    walls = (wall("Upright", 0, "P1", "P2") + wall("Both", 0, "P1", "P2", extra="<doubleSidedExtrusion>true</doubleSidedExtrusion>") +
             wall("Floor", 90, "P3", "P4") +
             wall("Shelf", -90, "P5", "P6", extra="<boundingElementUIDs><boundingElementUID>Upright</boundingElementUID></boundingElementUIDs>") +
             wall("Broken", 0, "P1", "Lost") + wall("Loop", 0, "P1", "Self"))
    beams = ('<cargoCrossBeams><cargoCrossBeam uID="Beam"><structuralElementUID>E</structuralElementUID>'
             "<frameUID>F1</frameUID><positionZ>-0.5</positionZ></cargoCrossBeam>"
             '<cargoCrossBeam uID="Beam0"><structuralElementUID>E</structuralElementUID>'
             "<frameUID>F0</frameUID><positionZ>-0.5</positionZ></cargoCrossBeam></cargoCrossBeams>")
    floor_beams = "<longFloorBeams>" + "".join(
        f'<longFloorBeam uID="{uid}">' + "".join(
            f'<longFloorBeamPosition uID="{uid}P{i}"><structuralElementUID>E</structuralElementUID>'
            f"<crossBeamUID>{beam}</crossBeamUID><positionY>{y}</positionY></longFloorBeamPosition>"
            for i, (beam, y) in enumerate(positions)) + "</longFloorBeam>"
        for uid, positions in (("Keel", (("Beam0", -0.3), ("Beam", 0.2))), ("Outside", (("Beam0", 0), ("Beam", 0.9))))
    ) + "</longFloorBeams>"
    struts = "".join(f'<cargoCrossBeamStrut uID="{uid}"><structuralElementUID>E</structuralElementUID><frameUID>F1</frameUID>'
                     f"<crossBeamUID>Beam</crossBeamUID><positionYAtCrossBeam>{y}</positionYAtCrossBeam>"
                     f"<angleX>{angle}</angleX></cargoCrossBeamStrut>" for uid, y, angle in
                     (("Down", -0.3, 90), ("Leaning", -0.3, 60), ("Beyond", -0.95, 90))) + "</cargoCrossBeamStruts>" + floor_beams
    return (f"<stringers>{stringers}</stringers><frames>{frames}</frames>{bulkheads}{beams}<cargoCrossBeamStruts>{struts}<walls><wallPositions>{positions}</wallPositions>"
            f"<wallSegments>{walls}</wallSegments></walls><cargoDoors>{doors}</cargoDoors>")


def test_bulkheads_and_walls_in_closed_form(tmp_path):
    path = tmp_path / "tube.xml"
    write(path, structure())
    answers = ask(path, {"op": "component_surface_area", "uid": "B1"}, {"op": "bounding_box", "uid": "B1"},
                  {"op": "component_type", "uid": "B1"}, {"op": "component_surface_area", "uid": "Upright"},
                  {"op": "bounding_box", "uid": "Upright"}, {"op": "component_surface_area", "uid": "Both"},
                  {"op": "component_surface_area", "uid": "Floor"}, {"op": "bounding_box", "uid": "Floor"},
                  {"op": "component_surface_area", "uid": "Shelf"}, {"op": "bounding_box", "uid": "Shelf"},
                  {"op": "component_volume", "uid": "Shelf"}, {"op": "component_type", "uid": "Shelf"})
    bulkhead, box, kind, upright, upright_box, both, floor, floor_box, shelf, shelf_box, volume, wall_kind = answers
    # The bulkhead: the disc the skin encloses at its frame's station x = 7.
    assert math.isclose(bulkhead, math.pi, rel_tol=REL) and kind == "pressure_bulkhead"
    assert math.isclose(box["min"][0], 7, abs_tol=1e-6) and math.isclose(box["max"][0], 7, abs_tol=1e-6)
    # Upright: the plane y = 0.3 from x = 2 to the bulkhead at x = 7, from z = 0 up to the skin.
    height = math.sqrt(1 - 0.3 ** 2)
    assert math.isclose(upright, 5 * height, rel_tol=REL)
    assert math.isclose(upright_box["max"][0], 7, abs_tol=1e-6) and math.isclose(upright_box["min"][2], 0, abs_tol=1e-6)
    assert math.isclose(both, 10 * height, rel_tol=REL), "extruded both ways: down to the skin as well"
    # Floor: phi 90° extrudes along −y; from the section at x = 5 to x = 9, from y = −0.5 to the skin.
    assert math.isclose(floor, 4 * (1 - 0.5), rel_tol=REL)
    assert math.isclose(floor_box["min"][0], 5, abs_tol=1e-6) and math.isclose(floor_box["min"][1], -1, abs_tol=1e-5)
    # Shelf: phi −90° extrudes along +y from y = 0 at z = 0.5; its bound, Upright, cuts it at y = 0.3.
    assert math.isclose(shelf, 3 * 0.3, rel_tol=1e-9) and math.isclose(shelf_box["max"][1], 0.3, abs_tol=1e-6)
    assert volume == 0 and wall_kind == "fuselage_wall"


@pytest.mark.parametrize("uid, x", [("OnPath", 4), ("OnPair", 4.5)])
def test_a_bulkhead_on_a_frame_at_one_station(tmp_path, uid, x):
    path = tmp_path / "tube.xml"
    write(path, structure())
    area, box = ask(path, {"op": "component_surface_area", "uid": uid}, {"op": "bounding_box", "uid": uid})
    # OnPath: rays straight up from y = −0.5, 0, 0.5 meet the unit circle; the chord between the
    # first and last cuts off the circular segment of central angle π/3 above z = √3/2. OnPair:
    # the frame runs between the rays from y = −0.5 and 0.5 over the top (the ray halfway between
    # them tells the side): the same segment.
    angle = math.pi / 3
    assert math.isclose(area, (angle - math.sin(angle)) / 2, rel_tol=1e-5)
    assert math.isclose(box["min"][2], math.sqrt(3) / 2, abs_tol=1e-6) and math.isclose(box["max"][2], 1, abs_tol=1e-5)
    assert math.isclose(box["min"][0], x, abs_tol=1e-6)


def test_cross_beams_and_struts_are_their_axes(tmp_path):
    path = tmp_path / "tube.xml"
    write(path, structure())
    beam, beam_area, down, leaning, kind = ask(
        path, {"op": "bounding_box", "uid": "Beam"}, {"op": "component_surface_area", "uid": "Beam"},
        {"op": "bounding_box", "uid": "Down"}, {"op": "bounding_box", "uid": "Leaning"},
        {"op": "component_type", "uid": "Leaning"})
    # The beam: the chord of the unit circle at z = −0.5 in the frame's plane x = 7.
    half = math.sqrt(1 - 0.25)
    assert math.isclose(beam["min"][1], -half, abs_tol=1e-5) and math.isclose(beam["max"][1], half, abs_tol=1e-5)
    assert beam_area == 0 and math.isclose(beam["min"][0], 7, abs_tol=1e-6)
    # Straight down from (y, z) = (−0.3, −0.5) to the skin.
    assert math.isclose(down["min"][2], -math.sqrt(1 - 0.09), abs_tol=1e-5)
    # angleX 60: 30° towards −y; the skin along (0, −1/2, −√3/2) from (−0.3, −0.5).
    d = (-0.5, -math.sqrt(3) / 2)
    b = 2 * (-0.3 * d[0] - 0.5 * d[1])
    t = (-b + math.sqrt(b * b - 4 * (0.09 + 0.25 - 1))) / 2
    assert math.isclose(leaning["min"][1], -0.3 + t * d[0], abs_tol=1e-5)
    assert math.isclose(leaning["min"][2], -0.5 + t * d[1], abs_tol=1e-5) and kind == "cross_beam_strut"


def test_long_floor_beams_run_through_their_cross_beams(tmp_path):
    path = tmp_path / "tube.xml"
    write(path, structure())
    box, area, kind = ask(path, {"op": "bounding_box", "uid": "Keel"}, {"op": "component_surface_area", "uid": "Keel"},
                          {"op": "component_type", "uid": "Keel"})
    # From y = −0.3 on the beam at x = 3 to y = 0.2 on the beam at x = 7, both at z = −0.5.
    assert area == 0 and kind == "long_floor_beam"
    assert box["min"] == pytest.approx([3, -0.3, -0.5], abs=1e-6) and box["max"] == pytest.approx([7, 0.2, -0.5], abs=1e-6)
    result = airshape("query", str(path), stdin=json.dumps({"op": "bounding_box", "uid": "Outside"}) + "\n")
    error = json.loads(result.stdout)["error"]
    assert "longFloorBeam[2]/longFloorBeamPosition[2]/positionY" in error and "beyond the ends" in error


def test_fuselage_structure_errors_name_their_path(tmp_path):
    path = tmp_path / "tube.xml"
    write(path, structure())
    queries = [{"op": "component_surface_area", "uid": u} for u in ("Broken", "Loop", "Beyond")]
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    broken, loop, beyond = (json.loads(line) for line in result.stdout.splitlines())
    assert "cargoCrossBeamStrut[3]/positionYAtCrossBeam" in beyond["error"]
    assert "wallPosition[7]/bulkheadUID" in broken["error"] and "'Nowhere'" in broken["error"]
    # A wall placed on itself is refused, not built forever.
    assert "wallPosition[8]/wallSegmentUID" in loop["error"] and "depends on itself" in loop["error"]


def test_a_frame_or_stringer_position_that_is_no_number_is_refused(tmp_path):
    # A NaN reference point once sent the frame's trace round the skin for ever.
    path = tmp_path / "tube.xml"
    write(path, "<frames>" + frame("Good", (5, 0)) + frame("NaN", (6, "nan")) + "</frames><stringers>" +
          stringer("Infinite", (0, 0, "inf"), (10, 0, 90)) + "</stringers>")
    queries = [{"op": "component_type", "uid": "Good"}] + [
        {"op": "bounding_box", "uid": u} for u in ("Good", "NaN", "Infinite")]
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    kind, good, nan, infinite = (json.loads(line) for line in result.stdout.splitlines())
    assert kind["ok"] == "frame" and "ok" in good
    assert nan["error"].endswith("frame[2]/framePosition[1]/referenceY: not a finite number (NaN or INF)")
    assert infinite["error"].endswith("stringer[1]/stringerPosition[1]/referenceAngle: not a finite number (NaN or INF)")


def test_doors_are_the_skin_between_their_frames_and_stringers(tmp_path):
    path = tmp_path / "tube.xml"
    write(path, structure())
    d1, box, kind, volume, over, over_box, rising = ask(
        path, {"op": "component_surface_area", "uid": "D1"}, {"op": "bounding_box", "uid": "D1"},
        {"op": "component_type", "uid": "D1"}, {"op": "component_volume", "uid": "D1"},
        {"op": "component_surface_area", "uid": "OverTheTop"}, {"op": "bounding_box", "uid": "OverTheTop"},
        {"op": "component_surface_area", "uid": "Rising"})
    # A quarter of the unit tube's skin from x = 3 to 7: from the side (−y) up to the top.
    assert math.isclose(d1, 4 * math.pi / 2, rel_tol=REL) and kind == "cargo_door" and volume == 0
    assert math.isclose(box["min"][0], 3, abs_tol=1e-6) and math.isclose(box["max"][0], 7, abs_tol=1e-6)
    assert math.isclose(box["min"][1], -1, abs_tol=1e-5) and math.isclose(box["max"][1], 0, abs_tol=1e-5)
    # From 45° on the +y side over the top to 45° on the −y side, the frames given back to front.
    assert math.isclose(over, 4 * math.pi / 2, rel_tol=REL)
    assert math.isclose(over_box["max"][1], math.sqrt(0.5), abs_tol=1e-5)
    assert math.isclose(over_box["min"][1], -math.sqrt(0.5), abs_tol=1e-5)
    # The tilted stringer's reference rises from z = 0 to 0.5 between the frames: the skin above
    # z(x) up to the top, ∫ acos z dx = 8 [z acos z − √(1 − z²)] from 0 to 0.5.
    expected = 8 * (0.5 * math.acos(0.5) - math.sqrt(0.75) + 1)
    assert math.isclose(rising, expected, rel_tol=REL)
    queries = [{"op": "component_surface_area", "uid": u} for u in ("Astray", "Flat")]
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    lost, flat = (json.loads(line)["error"] for line in result.stdout.splitlines())
    assert "cargoDoor[4]/endStringerUID" in lost and "'Nowhere'" in lost
    assert "cargoDoor[5]/endFrameUID" in flat and "one station" in flat


def test_frames_and_stringers_are_lines_on_the_skin(tmp_path):
    path = tmp_path / "tube.xml"
    write(path, structure())
    ring, ring_area, tilted, riffled, riffled_box, at_sections = ask(
        path, {"op": "bounding_box", "uid": "F1"}, {"op": "component_surface_area", "uid": "F1"},
        {"op": "bounding_box", "uid": "Tilted"}, {"op": "component_surface_area", "uid": "OnRiffles"},
        {"op": "bounding_box", "uid": "OnRiffles"}, {"op": "bounding_box", "uid": "AtSections"})
    # A frame of one position: the unit circle at x = 7.
    assert ring_area == 0 and math.isclose(ring["min"][0], 7, abs_tol=1e-6) and math.isclose(ring["max"][0], 7, abs_tol=1e-6)
    assert all(math.isclose(ring["max"][k], 1, abs_tol=1e-5) and math.isclose(ring["min"][k], -1, abs_tol=1e-5)
               for k in (1, 2))
    # The tilted stringer: on the −y side from z = 0 at x = 3 up to z = 0.5 at x = 7.
    assert math.isclose(tilted["min"][0], 3, abs_tol=1e-6) and math.isclose(tilted["max"][0], 7, abs_tol=1e-6)
    assert math.isclose(tilted["min"][2], 0, abs_tol=1e-6) and math.isclose(tilted["max"][2], 0.5, abs_tol=1e-6)
    assert math.isclose(tilted["min"][1], -1, abs_tol=1e-5)
    assert math.isclose(tilted["max"][1], -math.sqrt(0.75), abs_tol=1e-5)
    # Positions at the section elements of x = 5 and 10.
    assert math.isclose(at_sections["min"][0], 5, abs_tol=1e-6) and math.isclose(at_sections["max"][0], 10, abs_tol=1e-6)
    assert math.isclose(at_sections["min"][1], -1, abs_tol=1e-5) and math.isclose(at_sections["max"][2], 0, abs_tol=1e-6)
    # A riffled frame (positions at x = 4 and 5 in turn, a quarter turn apart): its bulkhead is the
    # plane face at the positions' mean station inside the frame's line, which lies on the tube,
    # so seen along x the line is the unit circle: the face's area is π; its box holds the line,
    # from x = 4 to 5.
    assert math.isclose(riffled, math.pi, rel_tol=REL)
    assert math.isclose(riffled_box["min"][0], 4, abs_tol=1e-6) and math.isclose(riffled_box["max"][0], 5, abs_tol=1e-6)
    assert all(math.isclose(riffled_box["max"][k], 1, abs_tol=1e-5) and math.isclose(riffled_box["min"][k], -1, abs_tol=1e-5)
               for k in (1, 2))


# An L profile: a web from the skin 0.1 into the body, then a flange 0.03 along the profile's x.
L_PROFILE = ('<structuralProfiles><structuralProfile2D uID="L"><name>L</name><pointList>'
             '<point uID="L1"><x>0</x><y>0</y></point><point uID="L2"><x>0</x><y>0.1</y></point>'
             '<point uID="L3"><x>0.03</x><y>0.1</y></point></pointList><sheetList>'
             '<sheet uID="web"><fromPointUID>L1</fromPointUID><toPointUID>L2</toPointUID></sheet>'
             '<sheet uID="flange"><fromPointUID>L2</fromPointUID><toPointUID>L3</toPointUID></sheet>'
             "</sheetList></structuralProfile2D></structuralProfiles>")
ELEMENTS = ('<structuralElements><profileBasedStructuralElements>'
            '<profileBasedStructuralElement uID="LElement"><sheetProperties><sheetUID>web</sheetUID>'
            "<materialUID>M</materialUID><thickness>0.002</thickness></sheetProperties>"
            "<structuralProfileUID>L</structuralProfileUID></profileBasedStructuralElement>"
            '<profileBasedStructuralElement uID="TElement"><sheetProperties><standardProfileSheetID>S1</standardProfileSheetID>'
            "<length>0.1</length><materialUID>M</materialUID><thickness>0.002</thickness></sheetProperties>"
            "<standardProfileType>T</standardProfileType></profileBasedStructuralElement>"
            "</profileBasedStructuralElements></structuralElements>")


def test_frames_and_stringers_export_with_their_profiles_swept(tmp_path):
    path = tmp_path / "tube.xml"
    write(path, structure())
    text = path.read_text().replace("</profiles>", L_PROFILE + "</profiles>" + ELEMENTS, 1)
    for uid, element in (("F1", "LElement"), ("Top", "LElement"), ("Side", "LElement"), ("F0", "TElement")):
        text = text.replace(f'uID="{uid}P0"><structuralElementUID>E<', f'uID="{uid}P0"><structuralElementUID>{element}<')
    # Side's profile moved 0.05 into the body.
    text = text.replace('<referenceAngle>90</referenceAngle></stringerPosition><stringerPosition uID="SideP1">',
                        '<referenceAngle>90</referenceAngle><alignment uID="SideA"><translationLocZ>0.05</translationLocZ>'
                        '</alignment></stringerPosition><stringerPosition uID="SideP1">', 1)
    path.write_text(text)
    out = tmp_path / "profiles.step"
    result = airshape("export", str(path), "--profiles", "--components", "F1,Top,Side,F0", "-o", str(out))
    assert result.returncode == 0, result.stderr
    # A standard profile is drawn only in the schema's picture: the line is written, with a note.
    assert "note: F0: written as built, without its profile" in result.stderr and "standard profile" in result.stderr
    # gmsh names surfaces by their component; its areas are good to about 1e-4.
    surfaces = [(name.split("/")[-1], area, box) for name, area, box in gmsh_surfaces(out)]
    assert {name for name, _, _ in surfaces} == {"F1", "Top", "Side"}

    def total(component, kind):
        return sum(area for name, area, box in surfaces if name == component and kind(box))

    def extent(box, axis):
        return box[axis + 3] - box[axis]

    # Frame F1 at x = 7 round the unit circle: the web sweeps the annulus 0.9 <= r <= 1, the flange
    # the band of radius 0.9 from x = 7 to 7.03 (the profile's x runs along the body's x axis).
    assert math.isclose(total("F1", lambda box: extent(box, 0) < 1e-3), math.pi * (1 - 0.81), rel_tol=2e-4)
    flanges = [box for name, _, box in surfaces if name == "F1" and extent(box, 0) > 1e-3]
    assert math.isclose(total("F1", lambda box: extent(box, 0) > 1e-3), 2 * math.pi * 0.9 * 0.03, rel_tol=2e-4)
    assert all(math.isclose(box[0], 7, abs_tol=1e-6) and math.isclose(box[3], 7.03, abs_tol=1e-6) for box in flanges)
    # Stringer Top along the crown from x = 0 to 10: the web from z = 1 down to 0.9, the flange at
    # z = 0.9 from y = 0 to -0.03 (local y = z × x with z down and x along the body).
    top_webs = [box for name, _, box in surfaces if name == "Top" and extent(box, 2) > 1e-3]
    assert math.isclose(total("Top", lambda box: extent(box, 2) > 1e-3), 1.0, rel_tol=2e-4)
    assert math.isclose(total("Top", lambda box: extent(box, 2) < 1e-3), 0.3, rel_tol=2e-4)
    assert all(math.isclose(box[2], 0.9, abs_tol=1e-6) and math.isclose(box[5], 1, abs_tol=1e-6) for box in top_webs)
    assert all(math.isclose(box[1], -0.03, abs_tol=1e-6) for name, _, box in surfaces
               if name == "Top" and extent(box, 2) < 1e-3)
    # Stringer Side on the -y side, moved 0.05 into the body: its web from y = -0.95 to -0.85.
    side_webs = [box for name, _, box in surfaces if name == "Side" and extent(box, 1) > 1e-3]
    assert math.isclose(total("Side", lambda box: extent(box, 1) > 1e-3), 1.0, rel_tol=2e-4)
    assert all(math.isclose(box[1], -0.95, abs_tol=1e-6) and math.isclose(box[4], -0.85, abs_tol=1e-6)
               for box in side_webs)
    # Queries keep answering for the lines.
    assert ask(path, {"op": "component_surface_area", "uid": "F1"}) == [0]


def test_a_wall_bounded_by_a_system_component(tmp_path):
    # The upright wall y = 0.3 from x = 2 to the bulkhead at x = 7, bounded by a box (x 4 to 6,
    # y 0 to 1, z −0.5 to 2.5) of a generic system: the box's faces cut it, and the pieces that
    # hold the wall's base points stay: x 2 to 4 and 6 to 7.
    box = ('<genericComponent uID="BoxElement"><name>e</name><geometry><cuboids><cuboid><lengthX>2</lengthX>'
           "<depthY>1</depthY><heightZ>3</heightZ></cuboid></cuboids></geometry></genericComponent>")
    system = ('<systems><genericSystems><genericSystem uID="Plant"><name>s</name><components>'
              '<component uID="Box"><name>c</name><systemElementUID>BoxElement</systemElementUID>'
              "<transformation><translation><x>4</x><z>-0.5</z></translation></transformation></component>"
              "</components></genericSystem></genericSystems></systems>")
    fenced = structure().replace(
        "</wallSegments>", wall("Fenced", 0, "P1", "P2", extra="<boundingElementUIDs><boundingElementUID>Box"
                                                               "</boundingElementUID></boundingElementUIDs>") +
        wall("Unbounded", 0, "P1", "P2", extra="<boundingElementUIDs><boundingElementUID>Nothing"
                                                "</boundingElementUID></boundingElementUIDs>") + "</wallSegments>")
    path = tmp_path / "tube.xml"
    write(path, fenced)
    text = path.read_text().replace("</fuselages></model>", "</fuselages>" + system + "</model>", 1)
    path.write_text(text.replace("</profiles>", f"</profiles><systems><genericComponents>{box}</genericComponents>"
                                                "</systems>", 1))
    area, bounds = ask(path, {"op": "component_surface_area", "uid": "Fenced"}, {"op": "bounding_box", "uid": "Fenced"})
    assert math.isclose(area, 3 * math.sqrt(1 - 0.3 ** 2), rel_tol=REL)
    assert math.isclose(bounds["min"][0], 2, abs_tol=1e-6) and math.isclose(bounds["max"][0], 7, abs_tol=1e-6)
    unbounded = airshape("query", str(path), stdin=json.dumps({"op": "component_surface_area", "uid": "Unbounded"}) + "\n")
    assert "bounding element 'Nothing' names no component" in unbounded.stdout
    assert "wallSegment[8]/boundingElementUIDs" in unbounded.stdout

