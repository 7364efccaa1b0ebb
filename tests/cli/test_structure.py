"""Wing structure (QUERY-components §1, docs/structure.md): spar webs on a wing whose figures
are known in closed form, spar errors, and the conformance floor of cases-structure.json."""
import json
import math
import os

import pytest

from conftest import airshape, conformance_passed
from independent_readers import gmsh_mesh_conformity, vtk_polydata

# The rectangular wing of parabolic arcs (chord 2 from x = 1 to 3, span 5 along y; its skins
# are z = ±0.15·2·ξ(1−ξ) at chord share ξ): the web of a spar at ξ is 0.6·ξ(1−ξ) high.
WITH_DEVICES = os.path.join(os.path.dirname(__file__), "..", "data", "wing-cst-devices.xml")


def position(uid, eta, xsi, reference="RectCS"):
    return (f'<sparPosition uID="{uid}"><sparPositionEtaXsi><eta>{eta}</eta><xsi>{xsi}</xsi>'
            f"<referenceUID>{reference}</referenceUID></sparPositionEtaXsi></sparPosition>")


def segment(uid, *positions):
    uids = "".join(f"<sparPositionUID>{p}</sparPositionUID>" for p in positions)
    return (f'<sparSegment uID="{uid}"><name>{uid}</name><sparPositionUIDs>{uids}</sparPositionUIDs>'
            "<sparCrossSection><rotation>90</rotation></sparCrossSection></sparSegment>")


def with_spars(tmp_path, positions, segments, other=""):
    with open(WITH_DEVICES) as original:
        text = original.read()
    structure = (f"<structure>{other}<spars><sparPositions>{positions}</sparPositions>"
                 f"<sparSegments>{segments}</sparSegments></spars></structure>")
    path = tmp_path / "spars.xml"
    path.write_text(text.replace("<controlSurfaces>", structure + "<controlSurfaces>", 1))
    return path


def ask(path, *queries):
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    return [json.loads(line) for line in result.stdout.splitlines()]


def height(xi):
    return 0.6 * xi * (1 - xi)


def test_spar_webs_in_closed_form(tmp_path):
    positions = (position("A0", 0, 0.3) + position("A1", 1, 0.3) + position("K0", 0, 0.2) +
                 position("K1", 0.5, 0.4) + position("K2", 1, 0.2) + position("S0", 0, 0.3, "RS") +
                 position("S1", 1, 0.3, "RS"))
    path = with_spars(tmp_path, positions,
                      segment("Straight", "A0", "A1") + segment("Kinked", "K0", "K1", "K2") +
                      segment("BySegment", "S0", "S1"))
    answers = ask(path, {"op": "component_surface_area", "uid": "Straight"},
                  {"op": "component_volume", "uid": "Straight"}, {"op": "bounding_box", "uid": "Straight"},
                  {"op": "component_surface_area", "uid": "Kinked"}, {"op": "component_surface_area", "uid": "BySegment"},
                  {"op": "component_type", "uid": "Straight"})
    area, volume, box, kinked, by_segment, kind = (a["ok"] for a in answers)
    # A plane web at ξ = 0.3 over the whole span, from the root cap to the tip cap.
    # Made straight from the skins (no Boolean cut): exact to rounding.
    assert area == pytest.approx(5.0 * height(0.3), rel=1e-10)
    assert volume == 0 and kind == "wing_spar"
    assert box["min"] == pytest.approx([1.6, 0.0, -height(0.3) / 2], abs=1e-6)
    assert box["max"] == pytest.approx([1.6, 5.0, height(0.3) / 2], abs=1e-6)
    # Two plane pieces along which ξ runs linearly 0.2 → 0.4 → 0.2: length × mean height.
    mean = (0.6 * (0.4 ** 2 / 2 - 0.4 ** 3 / 3) - 0.6 * (0.2 ** 2 / 2 - 0.2 ** 3 / 3)) / 0.2
    assert kinked == pytest.approx(2 * math.hypot(2.5, 0.4) * mean, rel=1e-10)
    # Wing segment coordinates: on this one-segment wing the same as the component segment's.
    assert by_segment == pytest.approx(area, rel=1e-9)


def test_spar_errors_name_the_cpacs_path(tmp_path):
    on_rib = ('<sparPosition uID="R"><sparPositionRib><ribDefinitionUID>none</ribDefinitionUID><ribNumber>1'
              "</ribNumber><xsi>0.5</xsi></sparPositionRib></sparPosition>")
    path = with_spars(tmp_path, position("A0", 0, 0.3) + position("A1", 1, 0.3) + on_rib +
                      position("NaN", 1, "nan") + position("Aft", 1, 1.5),
                      segment("Dangling", "A0", "Nowhere") + segment("OnRib", "A0", "R") + segment("Alone", "A0") +
                      segment("Good", "A0", "A1") + segment("NotANumber", "A0", "NaN") + segment("Beyond", "A0", "Aft"))
    dangling, on_rib_answer, alone, good, not_a_number, beyond = ask(
        path, *({"op": "component_surface_area", "uid": uid}
                for uid in ("Dangling", "OnRib", "Alone", "Good", "NotANumber", "Beyond")))
    # A coordinate that is no number, or one beyond the chord, is refused where it is written
    # (a NaN once sent the spar's trace into an endless search).
    assert not_a_number["error"].endswith("sparPosition[4]/sparPositionEtaXsi/xsi: nan is not a number in [0, 1]")
    assert beyond["error"].endswith("sparPosition[5]/sparPositionEtaXsi/xsi: 1.5 is not a number in [0, 1]")
    assert "sparPositionUID 'Nowhere' names no spar position" in dangling["error"]
    assert "sparSegment[1]/sparPositionUIDs" in dangling["error"]
    assert "sparPosition[3]/sparPositionRib" in on_rib_answer["error"] and "'none'" in on_rib_answer["error"]
    assert "at least two spar positions" in alone["error"]
    assert good["ok"] == pytest.approx(5.0 * height(0.3), rel=1e-7), "one broken spar never stops another"


def ribs(uid, start, end, count, rotation="<ribRotationReference>globalY</ribRotationReference><z>90</z>",
         reference="Front", rib_start="Front", rib_end="Rear"):
    return (f'<ribsDefinitions><ribsDefinition uID="{uid}"><name>{uid}</name><ribsPositioning>'
            f"<ribReference>{reference}</ribReference>"
            f"<startCurvePoint><eta>{start}</eta><referenceUID>{reference}</referenceUID></startCurvePoint>"
            f"<endCurvePoint><eta>{end}</eta><referenceUID>{reference}</referenceUID></endCurvePoint>"
            f"<ribStart>{rib_start}</ribStart><ribEnd>{rib_end}</ribEnd><numberOfRibs>{count}</numberOfRibs>"
            f"<ribCrossingBehaviour>end</ribCrossingBehaviour><ribRotation>{rotation}</ribRotation>"
            "</ribsPositioning></ribsDefinition></ribsDefinitions>")


def test_ribs_between_two_spars_in_closed_form(tmp_path):
    # Spars at ξ 0.2 and 0.6 over the whole span; three ribs along the front spar from 10 % to
    # 90 % of its length, turned 90° from the wing's y axis: chordwise planes y = 0.5, 2.5, 4.5.
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Ribs", 0.1, 0.9, 3))
    area, box, kind = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Ribs"},
                                            {"op": "bounding_box", "uid": "Ribs"},
                                            {"op": "component_type", "uid": "Ribs"}))
    # One rib: ∫ 0.6 ξ(1−ξ) dx over x = 1 + 2ξ, ξ from 0.2 to 0.6.
    one = 2 * 0.6 * ((0.6 ** 2 / 2 - 0.6 ** 3 / 3) - (0.2 ** 2 / 2 - 0.2 ** 3 / 3))
    assert area == pytest.approx(3 * one, rel=1e-10) and kind == "wing_rib"
    assert box["min"][:2] == pytest.approx([1.4, 0.5], abs=1e-6) and box["max"][:2] == pytest.approx([2.2, 4.5], abs=1e-6)
    assert box["max"][2] == pytest.approx(height(0.5) / 2, abs=1e-6), "the wing's thickest point lies between"
    # Without a rotation reference the ribs turn from the direction in which eta grows (here y).
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Ribs", 0.1, 0.9, 3, rotation="<z>90</z>"))
    midplane, = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Ribs"}))
    assert midplane == pytest.approx(area, rel=1e-9)
    # Turned 90° from the rear spar where the rib meets it: chordwise too.
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Ribs", 0.1, 0.9, 3, rotation="<ribRotationReference>Rear</ribRotationReference><z>90</z>"))
    by_spar, = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Ribs"}))
    assert by_spar == pytest.approx(area, rel=1e-9)
    # Ribs in the root and the tip section are those sections' faces between the spars.
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Ribs", 0.0, 1.0, 2))
    ends, ends_box = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Ribs"},
                                           {"op": "bounding_box", "uid": "Ribs"}))
    assert ends == pytest.approx(2 * one, rel=1e-10)
    assert ends_box["min"][1] == pytest.approx(0, abs=1e-6) and ends_box["max"][1] == pytest.approx(5, abs=1e-6)


def test_ribs_to_the_wing_edges_in_closed_form(tmp_path):
    # The parabolic-arc skins meet in sharp edges at ξ = 0 and 1: a chordwise rib from the
    # leading to the trailing edge is the whole section, ∫ 0.6 ξ(1−ξ) dx over x = 1 + 2ξ = 0.2; from
    # the leading edge to the rear spar at ξ 0.6, ∫ over ξ from 0 to 0.6.
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))
    spars = segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1")
    whole = with_spars(tmp_path, positions, spars, ribs("Ribs", 0.1, 0.9, 3, rib_start="leadingEdge",
                                                       rib_end="trailingEdge"))
    area, box = (a["ok"] for a in ask(whole, {"op": "component_surface_area", "uid": "Ribs"},
                                      {"op": "bounding_box", "uid": "Ribs"}))
    assert area == pytest.approx(3 * 0.2, rel=1e-9)
    assert box["min"][0] == pytest.approx(1.0, abs=1e-7) and box["max"][0] == pytest.approx(3.0, abs=1e-7)
    edge_to_edge = whole.read_text()
    to_spar = with_spars(tmp_path, positions, spars, ribs("Ribs", 0.1, 0.9, 3, rib_start="leadingEdge"))
    front, = (a["ok"] for a in ask(to_spar, {"op": "component_surface_area", "uid": "Ribs"}))
    assert front == pytest.approx(3 * 2 * 0.6 * (0.6 ** 2 / 2 - 0.6 ** 3 / 3), rel=1e-9)
    # A blunt trailing edge 0.02 of the chord thick (CST: each side ξ·0.01 further out): this flat
    # wing's trailing edge face is plane, crossed by the rib in a straight line; 0.2 + 2·0.02 each.
    blunt = tmp_path / "blunt.xml"
    blunt.write_text(edge_to_edge.replace('<lowerB mapType="vector">0.15</lowerB>',
                                               '<lowerB mapType="vector">0.15</lowerB>'
                                               "<trailingEdgeThickness>0.02</trailingEdgeThickness>", 1))
    blunt_area, = (a["ok"] for a in ask(blunt, {"op": "component_surface_area", "uid": "Ribs"}))
    assert blunt_area == pytest.approx(3 * (0.2 + 2 * 0.02), rel=1e-9)


def test_a_rib_at_a_spars_root_is_the_root_section_whatever_its_rotation(tmp_path):
    # Both spars start in the root section (y = 0). A rib set at eta 0 of the front spar is the
    # root section between the spars, as the reference library builds it, even turned by 0°
    # from the y axis (a plane along the spars, which would never reach the rear spar).
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))
    spars = segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1")
    along = "<ribRotationReference>globalY</ribRotationReference><z>0</z>"
    path = with_spars(tmp_path, positions, spars, ribs("Ribs", 0, 0, 1, rotation=along))
    area, box = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Ribs"},
                                      {"op": "bounding_box", "uid": "Ribs"}))

    def under(xi):
        return xi ** 2 / 2 - xi ** 3 / 3

    assert area == pytest.approx(2 * 0.6 * (under(0.6) - under(0.2)), rel=1e-9)
    assert box["min"][1] == pytest.approx(0.0, abs=1e-6) and box["max"][1] == pytest.approx(0.0, abs=1e-6)
    assert box["min"][0] == pytest.approx(1.4, abs=1e-6) and box["max"][0] == pytest.approx(2.2, abs=1e-6)


def test_an_explicitly_positioned_rib_between_two_spars(tmp_path):
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))

    def point(kind, xsi):
        return (f"<{kind}EtaXsiPoint><eta>0.5</eta><xsi>{xsi}</xsi><referenceUID>RectCS</referenceUID>"
                f"</{kind}EtaXsiPoint>")

    explicit = ('<ribsDefinitions><ribsDefinition uID="Explicit"><name>e</name><ribExplicitPositioning>'
                f"{point('start', 0.2)}{point('end', 0.6)}<ribStart>Front</ribStart><ribEnd>Rear</ribEnd>"
                "</ribExplicitPositioning></ribsDefinition></ribsDefinitions>")
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      explicit)
    area, box = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Explicit"},
                                      {"op": "bounding_box", "uid": "Explicit"}))
    # The chordwise plane y = 2.5 between the spars at ξ 0.2 and 0.6.
    assert area == pytest.approx(2 * 0.6 * ((0.6 ** 2 / 2 - 0.6 ** 3 / 3) - (0.2 ** 2 / 2 - 0.2 ** 3 / 3)), rel=1e-7)
    assert box["min"][1] == pytest.approx(2.5, abs=1e-6) and box["max"][1] == pytest.approx(2.5, abs=1e-6)


def test_an_explicit_rib_in_the_tip_section_is_the_tip(tmp_path):
    def point(kind, xsi):
        return f"<{kind}EtaXsiPoint><eta>1</eta><xsi>{xsi}</xsi><referenceUID>RectCS</referenceUID></{kind}EtaXsiPoint>"

    tip = ('<ribsDefinitions><ribsDefinition uID="Tip"><name>t</name><ribExplicitPositioning>'
           f"{point('start', 0)}{point('end', 1)}<ribStart>leadingEdge</ribStart><ribEnd>trailingEdge</ribEnd>"
           "</ribExplicitPositioning></ribsDefinition></ribsDefinitions>")
    path = with_spars(tmp_path, position("P0", 0, 0.2) + position("P1", 1, 0.2), segment("Front", "P0", "P1"), tip)
    area, box = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Tip"},
                                      {"op": "bounding_box", "uid": "Tip"}))
    # The whole tip section at y = 5, lying on the component segment's tip cap: 2 · ∫ 0.6 ξ(1 − ξ) dξ.
    assert area == pytest.approx(0.2, rel=1e-7)
    assert box["min"][1] == pytest.approx(5, abs=1e-6) and box["max"][0] == pytest.approx(3, abs=1e-6)


def edited(path, old, new):
    """The file with the first `old` in it replaced by `new`."""
    path.write_text(path.read_text().replace(old, new, 1))
    return path


def tilted_tip(path, degrees=30):
    """The file with the wing's tip section turned by `degrees` about x: at 30° its profile
    stands along (0, −sin 30°, cos 30°)."""
    tip = '<section uID="R2"><name>tip</name><transformation><scaling><x>2</x><y>2</y><z>2</z></scaling>'
    return edited(path, tip, tip + f"<rotation><x>{degrees}</x><y>0</y><z>0</z></rotation>")


def test_a_spar_web_twists_into_a_tilted_tip(tmp_path):
    # A spar from the root at ξ 0.2 (x 1.4) to the tilted tip at ξ 0.6 (x 2.2) stands along z at
    # the root and in the tip's plane at the tip: its web ends on the tip's line through the
    # position, x = 2.2 from its upper to its lower corner, the lower one 0.3 · 0.6 · 0.4 = 0.072
    # down that line (y 5 + 0.036).
    path = tilted_tip(with_spars(tmp_path, position("P0", 0, 0.2) + position("P1", 1, 0.6),
                                 segment("Twisted", "P0", "P1")))
    box, = (a["ok"] for a in ask(path, {"op": "bounding_box", "uid": "Twisted"}))
    assert box["max"][0] == pytest.approx(2.2, abs=1e-6)
    assert box["max"][1] == pytest.approx(5 + 0.072 * 0.5, abs=1e-6)
    assert box["min"][0] == pytest.approx(1.4, abs=1e-6) and box["min"][1] == pytest.approx(0, abs=1e-6)


def test_an_explicit_rib_from_a_spar_position_on_a_tilted_tip_stands_in_the_tip(tmp_path):
    # A rib from the spar position at the tip (ξ 0.2) to the trailing edge at mid span starts on the
    # tip's line along that direction through the position, as the spar stands there: nothing of
    # it lies ahead of x = 1.4, and its lowest tip corner is 0.3 · 0.2 · 0.8 = 0.048 down that
    # line (the reference library's Rib_SPEX_full of wing_explicitRibPositioning.xml).
    end = ("<endEtaXsiPoint><eta>0.5</eta><xsi>1</xsi><referenceUID>RectCS</referenceUID></endEtaXsiPoint>")
    rib = ('<ribsDefinitions><ribsDefinition uID="FromTip"><name>t</name><ribExplicitPositioning>'
           f"<startSparPositionUID>P1</startSparPositionUID>{end}<ribStart>leadingEdge</ribStart>"
           "<ribEnd>trailingEdge</ribEnd></ribExplicitPositioning></ribsDefinition></ribsDefinitions>")
    path = tilted_tip(with_spars(tmp_path, position("P0", 0, 0.2) + position("P1", 1, 0.2),
                                 segment("Front", "P0", "P1"), rib))
    box, = (a["ok"] for a in ask(path, {"op": "bounding_box", "uid": "FromTip"}))
    assert box["min"][0] == pytest.approx(1.4, abs=1e-6)
    assert box["max"][1] == pytest.approx(5 + 0.048 * 0.5, abs=1e-6)


def test_an_explicit_rib_between_spars_standing_at_different_angles_twists(tmp_path):
    # Spars at ξ 0.2 and 0.6 from the root to the tilted tip. A rib from the front spar's tip
    # position (standing in the tip's plane) to the rear spar at mid span (whose twisted web stands
    # halfway between z and the tip's direction there) is the ruled surface between those two
    # lines: it starts on the tip's line through x = 1.4 (its lowest corner 0.3 · 0.2 · 0.8 = 0.048
    # down that line, y 5 + 0.024) and ends on the rear spar at x = 2.2.
    end = ("<endEtaXsiPoint><eta>0.5</eta><xsi>0.6</xsi><referenceUID>RectCS</referenceUID></endEtaXsiPoint>")
    rib = ('<ribsDefinitions><ribsDefinition uID="Twisted"><name>t</name><ribExplicitPositioning>'
           f"<startSparPositionUID>F1</startSparPositionUID>{end}<ribStart>Front</ribStart>"
           "<ribEnd>Rear</ribEnd></ribExplicitPositioning></ribsDefinition></ribsDefinitions>")
    positions = position("F0", 0, 0.2) + position("F1", 1, 0.2) + position("Q0", 0, 0.6) + position("Q1", 1, 0.6)
    path = tilted_tip(with_spars(tmp_path, positions, segment("Front", "F0", "F1") + segment("Rear", "Q0", "Q1"), rib))
    box, area = (a["ok"] for a in ask(path, {"op": "bounding_box", "uid": "Twisted"},
                                      {"op": "component_surface_area", "uid": "Twisted"}))
    assert box["min"][0] == pytest.approx(1.4, abs=1e-6) and box["max"][0] == pytest.approx(2.2, abs=1e-6)
    assert box["max"][1] == pytest.approx(5 + 0.048 * 0.5, abs=1e-6)
    # Along its 2.62 m the wing is at most 0.6 · ξ(1−ξ) thick (0.136 on average over ξ 0.2 .. 0.6),
    # less where the tip leans: a strip of that height is an upper bound.
    length = (0.8 ** 2 + 2.5 ** 2) ** 0.5
    assert 0.8 * length * 0.136 < area < length * 0.136


def test_the_structural_model_meshes_conformally(tmp_path):
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Ribs", 0.1, 0.9, 3))
    model, loose, faces = tmp_path / "wing_box.step", tmp_path / "loose.step", tmp_path / "wing_box.vtp"
    result = airshape("export", str(path), "--structure", "-o", str(model), "-o", str(faces))
    assert result.returncode == 0, result.stderr
    assert "RectCS structure" in result.stdout
    # Progress: each component built, then the join, which takes seconds on a large wing.
    progress = [line for line in result.stderr.splitlines() if line.startswith("export: ")]
    assert any(line.startswith("export: 1/4 built ") for line in progress), progress
    assert any("4/4 joining the structure of RectCS (3 components)" in line for line in progress), progress
    joined = gmsh_mesh_conformity(model, 0.1)
    # Webs and ribs share their edges with the skins they meet: T-junctions, no doubled nodes.
    assert joined["duplicates"] == 0 and joined["junctions"] >= 10, joined
    names = set(vtk_polydata(faces)["arrays"]["face"])
    assert {"Front/web", "Rear/web", "Ribs/rib 1", "Ribs/rib 3", "RS/upper", "RS/lower"} <= names, names
    # The same faces written as separate components meet nowhere: what the check catches.
    result = airshape("export", str(path), "--components", "Rect,Front,Rear,Ribs", "-o", str(loose))
    assert result.returncode == 0, result.stderr
    separate = gmsh_mesh_conformity(loose, 0.1)
    assert separate["junctions"] == 0, separate
    # A file without structure has no structural model: said, nothing written.
    nothing = tmp_path / "nothing.step"
    result = airshape("export", WITH_DEVICES, "--structure", "-o", str(nothing))
    assert result.returncode == 0 and "holds spars or ribs" in result.stderr and not nothing.exists()


def test_structural_models_of_a_wing_and_its_flap_are_both_written_in_order(tmp_path):
    # Two models, joined side by side (the larger first): the component segment's spars and
    # ribs, and the flap's own spar and rib. Both are written, in the order of their hosts; the
    # flap's is a shell whose spar and rib share their edges with its skins.
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))
    wing = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Ribs", 0.1, 0.9, 3))
    path = with_flap_structure(wing.read_text(), tmp_path / "both.xml")
    model = tmp_path / "models.step"
    result = airshape("export", str(path), "--structure", "-o", str(model))
    assert result.returncode == 0, result.stderr
    rows = [line.split()[0] for line in result.stdout.splitlines() if line.endswith(" structure") or " structure " in line]
    assert rows == ["Flap", "RectCS"], result.stdout
    joining = [line for line in result.stderr.splitlines() if "joining the structure of" in line]
    assert len(joining) == 2 and "RectCS (3 components)" in joining[0], joining  # the larger first
    # Naming the flap writes its model alone (naming the component segment would bring its
    # devices' models too, whose skins lie on the component segment's).
    flap = tmp_path / "flap.step"
    assert airshape("export", str(path), "--structure", "--components", "Flap", "-o", str(flap)).returncode == 0
    joined = gmsh_mesh_conformity(flap, 0.1)
    assert joined["duplicates"] == 0 and joined["junctions"] >= 2, joined


def test_a_rib_that_misses_its_component_segment_is_left_out_of_its_set_with_a_warning(tmp_path):
    # Three ribs from the leading edge (at y = 0.1, 2.3, 4.5) between spars at xi 0.2 and 0.6,
    # turned 45 degrees so that they run inboard going aft: the first has passed the root
    # before it reaches the front spar. The other two are built, each sqrt(2) times the
    # chordwise rib between the spars.
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))
    turned = "<ribRotationReference>globalY</ribRotationReference><z>45</z>"
    spars = segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1")
    one = 2 * 0.6 * ((0.6 ** 2 / 2 - 0.6 ** 3 / 3) - (0.2 ** 2 / 2 - 0.2 ** 3 / 3))
    path = with_spars(tmp_path, positions, spars,
                      ribs("Ribs", 0.02, 0.9, 3, rotation=turned, reference="leadingEdge", rib_start="Front"))
    built = airshape("build", str(path))
    assert "ribsDefinition[1]/ribsPositioning: Ribs/rib 1 does not cross its component segment; left out, the set's " \
        "other ribs are built" in built.stderr, built.stderr
    assert "rib 2" not in built.stderr and "rib 3" not in built.stderr
    assert built.returncode == 0 and "Ribs" in built.stdout and "valid faces" in built.stdout.split("Ribs", 1)[1]
    area, = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Ribs"}))
    assert area == pytest.approx(2 * math.sqrt(2) * one, rel=1e-9)
    # Turned so far that none crosses, the set is one error line.
    path = with_spars(tmp_path, positions, spars, ribs("Ribs", 0.01, 0.02, 2, rotation=turned, reference="leadingEdge",
                                                       rib_start="Front"))
    answer, = ask(path, {"op": "component_surface_area", "uid": "Ribs"})
    assert answer["error"].endswith("ribsPositioning: none of its 2 ribs crosses its component segment"), answer


def test_a_rib_before_its_spar_begins_is_left_out_of_its_set_with_a_warning(tmp_path):
    # The rear spar begins at eta 0.4 (y = 2): of the three chordwise ribs at y = 0.5, 2.5 and
    # 4.5 between the spars, the first does not meet it; the other two are built.
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0.4, 0.6) +
                 position("PosR1", 1, 0.6))
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Ribs", 0.1, 0.9, 3))
    built = airshape("build", str(path))
    assert "Ribs/rib 1: a rib does not meet spar 'Rear'; left out, the set's other ribs are built" in built.stderr, \
        built.stderr
    assert built.returncode == 0, built.stdout
    area, = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Ribs"}))
    one = 2 * 0.6 * ((0.6 ** 2 / 2 - 0.6 ** 3 / 3) - (0.2 ** 2 / 2 - 0.2 ** 3 / 3))
    assert area == pytest.approx(2 * one, rel=1e-10)


def test_rib_errors_name_the_cpacs_path(tmp_path):
    positions = position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2)
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1"),
                      ribs("Ribs", 0.1, 0.9, 3, rib_end="Missing"))
    answer, = ask(path, {"op": "component_surface_area", "uid": "Ribs"})
    assert "ribsDefinition[1]/ribsPositioning/ribEnd" in answer["error"]
    assert "no spar segment with uID 'Missing'" in answer["error"]


def test_a_rib_set_asking_for_more_ribs_than_any_wing_has_is_refused(tmp_path):
    positions = position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.7) + \
        position("PosR1", 1, 0.7)
    spacing = ribs("Spaced", 0.1, 0.9, 3).replace("<numberOfRibs>3</numberOfRibs>", "<spacing>1e-300</spacing>")
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      ribs("Many", 0.1, 0.9, 10 ** 9).replace("</ribsDefinitions>", "") +
                      spacing.replace("<ribsDefinitions>", ""))
    many, spaced = ask(path, *({"op": "component_surface_area", "uid": uid} for uid in ("Many", "Spaced")))
    assert many["error"].endswith("ribsDefinition[1]/ribsPositioning/numberOfRibs: asks for 1e+09 ribs in one set, "
                                  "more than 10000; refused")
    assert "ribsDefinition[2]/ribsPositioning/spacing: asks for " in spaced["error"]


def test_a_broken_rib_set_leaves_the_rest_of_a_named_structural_model(tmp_path):
    # The component segment is named; one of its rib sets refers to a spar that is not
    # there. It is left out and said, the rest of the model is written, status 1.
    positions = position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2)
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1"),
                      ribs("Ribs", 0.1, 0.9, 3, rib_end="Missing"))
    model = tmp_path / "model.step"
    result = airshape("export", str(path), "--structure", "--components", "RectCS", "-o", str(model))
    assert result.returncode == 1, result.stderr
    assert "left out Ribs:" in result.stderr and "no file written" not in result.stderr
    assert model.exists()
    named = airshape("export", str(path), "--components", "Ribs", "-o", str(tmp_path / "ribs.step"))
    assert named.returncode == 1 and "no file written" in named.stderr  # the one named failed


def cells(*cells_xml):
    return f"<upperShell><skin/><cells>{''.join(cells_xml)}</cells></upperShell>"


def cell(uid, eta_inner, eta_outer, leading_edge, trailing_edge):
    def eta(value):
        return f"<eta>{value}</eta><referenceUID>RectCS</referenceUID>"

    return (f'<cell uID="{uid}"><positioningLeadingEdge>{leading_edge}</positioningLeadingEdge>'
            f"<positioningTrailingEdge>{trailing_edge}</positioningTrailingEdge>"
            f"<positioningInnerBorder><eta1>{eta(eta_inner)}</eta1><eta2>{eta(eta_inner)}</eta2></positioningInnerBorder>"
            f"<positioningOuterBorder><eta1>{eta(eta_outer)}</eta1><eta2>{eta(eta_outer)}</eta2></positioningOuterBorder>"
            "</cell>")


def skin_length(xi0, xi1, steps=20000):
    """Length of the upper skin z = 0.15·2·ξ(1−ξ), x = 1 + 2ξ between two chord shares."""
    def slope(xi):
        return math.hypot(2.0, 0.3 * (1 - 2 * xi))
    h = (xi1 - xi0) / steps
    return h / 3 * sum((1 if k in (0, steps) else 4 if k % 2 else 2) * slope(xi0 + k * h) for k in range(steps + 1))


def test_cells_are_skin_patches_in_closed_form(tmp_path):
    positions = position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2)
    by_xsi = cell("ByXsi", 0.2, 0.8, "<xsi1>0.2</xsi1><xsi2>0.2</xsi2>", "<xsi1>0.6</xsi1><xsi2>0.6</xsi2>")
    by_spar = cell("BySpar", 0.2, 0.8, "<sparUID>Front</sparUID>", "<xsi1>0.6</xsi1><xsi2>0.6</xsi2>")
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1"), cells(by_xsi, by_spar))
    area, box, spar_area, volume, kind = (a["ok"] for a in ask(
        path, {"op": "component_surface_area", "uid": "ByXsi"}, {"op": "bounding_box", "uid": "ByXsi"},
        {"op": "component_surface_area", "uid": "BySpar"}, {"op": "component_volume", "uid": "ByXsi"},
        {"op": "component_type", "uid": "ByXsi"}))
    # The upper skin between ξ 0.2 and 0.6 over 3 m of span.
    assert area == pytest.approx(3.0 * skin_length(0.2, 0.6), rel=1e-6)
    assert box["min"][:2] == pytest.approx([1.4, 1.0], abs=1e-6) and box["max"][:2] == pytest.approx([2.2, 4.0], abs=1e-6)
    assert box["max"][2] == pytest.approx(height(0.5) / 2, abs=1e-6) and box["min"][2] == pytest.approx(height(0.2) / 2, abs=1e-6)
    assert spar_area == pytest.approx(area, rel=1e-6), "a spar at ξ 0.2 bounds the cell where xsi 0.2 does"
    assert volume == 0 and kind == "wing_cell"
    # Older files write eta1 and eta2 as bare numbers: read as component segment etas, said.
    bare = (by_xsi.replace('uID="ByXsi"', 'uID="Bare"').replace("<eta>0.2</eta><referenceUID>RectCS</referenceUID>", "0.2")
            .replace("<eta>0.8</eta><referenceUID>RectCS</referenceUID>", "0.8"))
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1"), cells(bare))
    result = airshape("query", str(path), stdin=json.dumps({"op": "component_surface_area", "uid": "Bare"}) + "\n")
    assert json.loads(result.stdout)["ok"] == pytest.approx(area, rel=1e-9)
    assert "eta given as a bare number" in result.stderr


def test_cells_reaching_the_edges_of_their_skin(tmp_path):
    # Cells whose borders lie on the skin's own edges (the root, the tip, the sharp trailing edge
    # at ξ 1) or are carried beyond it follow those edges: the upper skin aft of ξ 0.6 over the
    # whole span, and the lower skin between ξ 0.2 and 0.6 from the root to mid span.
    positions = position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2)
    aft = cell("Aft", 0.0, 1.0, "<xsi1>0.6</xsi1><xsi2>0.6</xsi2>", "<xsi1>1</xsi1><xsi2>1</xsi2>")
    lower = cell("Lower", 0.0, 0.5, "<xsi1>0.2</xsi1><xsi2>0.2</xsi2>", "<xsi1>0.6</xsi1><xsi2>0.6</xsi2>")
    shells = cells(aft) + f"<lowerShell><skin/><cells>{lower}</cells></lowerShell>"
    path = with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1"), shells)
    area, box, lower_area, lower_box = (a["ok"] for a in ask(
        path, {"op": "component_surface_area", "uid": "Aft"}, {"op": "bounding_box", "uid": "Aft"},
        {"op": "component_surface_area", "uid": "Lower"}, {"op": "bounding_box", "uid": "Lower"}))
    assert area == pytest.approx(5.0 * skin_length(0.6, 1.0), rel=1e-6)
    assert box["min"][:2] == pytest.approx([2.2, 0.0], abs=1e-6) and box["max"][:2] == pytest.approx([3.0, 5.0], abs=1e-6)
    assert lower_area == pytest.approx(2.5 * skin_length(0.2, 0.6), rel=1e-6)
    assert lower_box["max"][1] == pytest.approx(2.5, abs=1e-6) and lower_box["max"][2] < 0


def test_a_cell_on_the_tip_reaches_a_tip_that_leans_outwards(tmp_path):
    # The tip section turned −30° about x leans its upper skin outwards: a point of height h on
    # it lies at y = 5 + h/2. The cell's lines at the tip stand along z and meet that skin short
    # of its edge, but a border on the tip is the skin's own edge: the cell of ξ 0.2 to 0.6 ends
    # there, its farthest point at ξ 0.5 (h = 0.075), y = 5.0375.
    positions = position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2)
    tip = cell("TipCell", 0.5, 1.0, "<xsi1>0.2</xsi1><xsi2>0.2</xsi2>", "<xsi1>0.6</xsi1><xsi2>0.6</xsi2>")
    path = tilted_tip(with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1"), cells(tip)), -30)
    box, = (a["ok"] for a in ask(path, {"op": "bounding_box", "uid": "TipCell"}))
    assert box["max"][1] == pytest.approx(5 + 0.075 * 0.5, abs=1e-6)
    assert box["min"][0] == pytest.approx(1.4, abs=1e-3) and box["max"][0] == pytest.approx(2.2, abs=1e-3)


def simpson(f, a, b, steps=200):
    h = (b - a) / steps
    return h / 3 * sum((1 if k in (0, steps) else 4 if k % 2 else 2) * f(a + k * h) for k in range(steps + 1))


def test_a_cell_follows_the_kinks_of_its_spar(tmp_path):
    # The spar runs ξ 0.2 → 0.4 → 0.2 along the span; the cell lies behind it up to ξ 0.6
    # between η 0.2 and 0.8 (y 1 to 4), so its outline bends at the spar's kink at y = 2.5.
    positions = position("K0", 0, 0.2) + position("K1", 0.5, 0.4) + position("K2", 1, 0.2)
    behind = cell("Behind", 0.2, 0.8, "<sparUID>Kinked</sparUID>", "<xsi1>0.6</xsi1><xsi2>0.6</xsi2>")
    path = with_spars(tmp_path, positions, segment("Kinked", "K0", "K1", "K2"), cells(behind))
    area, = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Behind"}))

    def spar_xsi(y):
        return 0.2 + 0.2 * (y / 2.5 if y <= 2.5 else (5 - y) / 2.5)

    expected = sum(simpson(lambda y: skin_length(spar_xsi(y), 0.6, steps=400), a, b) for a, b in ((1, 2.5), (2.5, 4)))
    assert area == pytest.approx(expected, rel=1e-6)


def test_a_cell_ends_on_the_web_of_its_spar(tmp_path):
    # The wing rises at a dihedral of 30°; its spar runs from ξ 0.2 at the root to ξ 0.5 at the
    # tip, its web upright (the wing's z axis). A cell behind the spar, up to ξ 0.8 over the
    # whole span, ends where that web meets the skin, not on lines along the cell direction
    # (square to the dihedral), which would meet the skin elsewhere along the slanting spar.
    # Skin: the profile z = 0.3·ξ(1−ξ), x = 1 + 2ξ moved along (0, 5 cos 30°, 5 sin 30°).
    positions = position("S0", 0, 0.2) + position("S1", 1, 0.5)
    behind = cell("Behind", 0.0, 1.0, "<sparUID>Slanting</sparUID>", "<xsi1>0.8</xsi1><xsi2>0.8</xsi2>")
    path = edited(with_spars(tmp_path, positions, segment("Slanting", "S0", "S1"), cells(behind)),
                  "<length>5</length><sweepAngle>0</sweepAngle><dihedralAngle>0</dihedralAngle>",
                  "<length>5</length><sweepAngle>0</sweepAngle><dihedralAngle>30</dihedralAngle>")
    area, box = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Behind"},
                                      {"op": "bounding_box", "uid": "Behind"}))
    lean = math.cos(math.radians(30))

    def across(s):  # the skin's area per unit of s, from the spar to ξ 0.8
        return simpson(lambda xi: 5 * math.sqrt(4 + (0.3 * (1 - 2 * xi) * lean) ** 2), 0.2 + 0.3 * s, 0.8, steps=400)

    assert area == pytest.approx(simpson(across, 0.0, 1.0), rel=1e-6)
    assert box["min"][0] == pytest.approx(1.4, abs=1e-6), "the web meets the root's skin at ξ 0.2"


def test_older_spar_points_and_rib_etas_are_read_with_a_warning(tmp_path):
    # CPACS 3.0 files of some tools give a spar position as `sparPoint` and a rib set's first
    # and last rib by `etaStart`/`etaEnd` (where the reference line reaches that eta): the
    # same spars and ribs as the schema's forms, each with a warning naming the element.
    source = os.path.join(os.path.dirname(__file__), "..", "data", "wing-cst-structure.xml")
    with open(source) as original:
        text = original.read()
    older = text.replace("sparPositionEtaXsi>", "sparPoint>")
    for end in ("start", "end"):
        older = older.replace(f"<{end}CurvePoint>", f"<eta{end.title()}>").replace(
            f"</{end}CurvePoint>", f"</eta{end.title()}>")
    older = older.replace("<referenceUID>Front</referenceUID>\n                      </eta", "<referenceUID>RectCS"
                          "</referenceUID>\n                      </eta")
    assert older.count("<sparPoint>") == 4 and "<etaStart>" in older and "<etaEnd>" in older
    path = tmp_path / "older.xml"
    path.write_text(older)
    queries = [{"op": "component_surface_area", "uid": uid} for uid in ("Front", "Rear", "Ribs")]
    expected = [a["ok"] for a in ask(source, *queries)]
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    got = [json.loads(line)["ok"] for line in result.stdout.splitlines()]
    assert got == pytest.approx(expected, rel=1e-9)
    assert "sparPosition[1]/sparPoint: a spar point in an older form" in result.stderr
    assert "ribsPositioning/etaStart: a rib start or end in an older form" in result.stderr


def test_structure_conformance_does_not_regress():
    passed, output = conformance_passed("cases-structure.json")
    # Spar webs, ribs, cells, pressure bulkheads, fuselage and vessel walls, cross beams and struts are built
    # (docs/structure.md): every case passes.
    assert passed >= 500, output[-3000:]


def two_segment_wing(tmp_path, shells):
    """The rectangular wing with a third section at y = 1, so that its segments are 1 m and 4 m
    long, and the given shells (upper and lower, with cells) in its component segment."""
    with open(WITH_DEVICES) as original:
        text = original.read()
    middle = ('<section uID="RM"><name>middle</name><transformation><scaling><x>2</x><y>2</y><z>2</z></scaling>'
              '</transformation><elements><element uID="RME"><name>e</name><airfoilUID>Parabolic</airfoilUID>'
              "<transformation/></element></elements></section>")
    text = text.replace('<section uID="R2">', middle + '<section uID="R2">', 1)
    text = text.replace('<length>5</length><sweepAngle>0</sweepAngle><dihedralAngle>0</dihedralAngle>'
                        "<fromSectionUID>R1</fromSectionUID><toSectionUID>R2</toSectionUID>",
                        "<length>1</length><sweepAngle>0</sweepAngle><dihedralAngle>0</dihedralAngle>"
                        "<fromSectionUID>R1</fromSectionUID><toSectionUID>RM</toSectionUID></positioning>"
                        '<positioning uID="RP3"><name>p</name><length>4</length><sweepAngle>0</sweepAngle>'
                        "<dihedralAngle>0</dihedralAngle><fromSectionUID>RM</fromSectionUID>"
                        "<toSectionUID>R2</toSectionUID>", 1)
    text = text.replace('<segment uID="RS"><name>s</name><fromElementUID>R1E</fromElementUID>'
                        "<toElementUID>R2E</toElementUID></segment>",
                        '<segment uID="RS"><name>s</name><fromElementUID>R1E</fromElementUID>'
                        '<toElementUID>RME</toElementUID></segment><segment uID="RS2"><name>s</name>'
                        "<fromElementUID>RME</fromElementUID><toElementUID>R2E</toElementUID></segment>", 1)
    path = tmp_path / "two-segments.xml"
    path.write_text(text.replace("<controlSurfaces>", f"<structure>{shells}</structure><controlSurfaces>", 1))
    return path


def test_a_spar_crosses_a_section_on_the_line_to_its_upper_trailing_edge(tmp_path):
    # A blunt trailing edge 0.1 of the chord thick: the upper skin ends at z = 0.1 ξ (chord 2).
    # The spar from (y 0, ξ 0.2) to (y 5, ξ 0.6) crosses the section at y = 1 at ξ 0.28, on the
    # line from the leading edge to the upper trailing edge (the reference library's), z = 0.028,
    # not on the chord (z = 0). A rib square to y at half the spar's length lies where that
    # kinked line reaches half its length; through the chord it would be y = 2.5 exactly.
    spar = segment("Diagonal", "D0", "D1")
    rib = ribs("Rib", 0.5, 0.5, 1, reference="Diagonal", rib_start="leadingEdge", rib_end="trailingEdge")
    path = two_segment_wing(tmp_path, rib + f"<spars><sparPositions>{position('D0', 0, 0.2)}{position('D1', 1, 0.6)}"
                            f"</sparPositions><sparSegments>{spar}</sparSegments></spars>")
    path.write_text(path.read_text().replace('<lowerB mapType="vector">0.15</lowerB>',
                                             '<lowerB mapType="vector">0.15</lowerB>'
                                             "<trailingEdgeThickness>0.1</trailingEdgeThickness>", 1))
    box, = (a["ok"] for a in ask(path, {"op": "bounding_box", "uid": "Rib"}))
    rise = 0.1 * 0.28
    inner, outer = math.sqrt(0.16 ** 2 + 1 + rise ** 2), math.sqrt(0.64 ** 2 + 16 + rise ** 2)
    expected = 1 + (0.5 * (inner + outer) - inner) / outer * 4
    assert (box["min"][1] + box["max"][1]) / 2 == pytest.approx(expected, abs=1e-9)
    assert expected < 2.5 - 1e-4


def test_cell_sides_lean_with_the_leading_edge_from_root_to_tip(tmp_path):
    # The 4 m segment rises at a dihedral of 40°: seen from the front the leading edge runs from
    # the root (y 0, z 0) to the tip (y 1 + 4 cos 40°, z 4 sin 40°). Every side of a cell stands
    # square to the root chord and to that line (as the reference's cells are cut), so a border
    # at the kink (y = 1, eta 0.2 by the chord's midpoints) is the plane y = 1 − z·tan(lean)
    # through the kink's chord, not the plane of either segment's normal. The cell of ξ 0.2 to
    # 0.6 on the flat first segment's upper skin (z = 0.3·ξ(1−ξ), x = 1 + 2ξ) loses what lies
    # beyond it.
    path = two_segment_wing(tmp_path, cells(cell("Kinked", 0.0, 0.2, "<xsi1>0.2</xsi1><xsi2>0.2</xsi2>",
                                                 "<xsi1>0.6</xsi1><xsi2>0.6</xsi2>")))
    kink = '<positioning uID="RP3"><name>p</name><length>4</length><sweepAngle>0</sweepAngle><dihedralAngle>'
    edited(path, kink + "0</dihedralAngle>", kink + "40</dihedralAngle>")
    area, = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "Kinked"}))
    dihedral = math.radians(40)
    lean = 4 * math.sin(dihedral) / (1 + 4 * math.cos(dihedral))
    expected = simpson(lambda xi: (1 - 0.3 * xi * (1 - xi) * lean) * math.hypot(2, 0.3 * (1 - 2 * xi)), 0.2, 0.6)
    assert area == pytest.approx(expected, rel=1e-7)


def contour_cell(uid, inner, outer, leading_edge, trailing_edge):
    def border(name, value):
        return f"<{name}><contourCoordinate>{value}</contourCoordinate></{name}>"

    return (f'<cell uID="{uid}">{border("positioningInnerBorder", inner)}'
            f'{border("positioningLeadingEdge", leading_edge)}{border("positioningOuterBorder", outer)}'
            f'{border("positioningTrailingEdge", trailing_edge)}</cell>')


def test_cells_bounded_by_contour_coordinates(tmp_path):
    # Both segments carry the same airfoil, so every pole moves straight along y: the skin's
    # centripetal parameters at the sections are √1 : √4, i.e. 0, 1/3 and 1 (docs/structure.md).
    # Spanwise 0.5 therefore lies a quarter into the 4 m segment, at y = 2; chordwise is ξ.
    upper = contour_cell("Aft", 0.5, 1.0, 0.2, 0.6) + contour_cell("Across", 1 / 6, 0.5, 0.2, 0.6)
    upper += contour_cell("Sliver", 1 / 3 + 0.0025 * 2 / 3, 1.0, 0.2, 0.6)
    mixed = contour_cell("Mixed", 0.2, 0.8, 0.2, 0.6).replace(
        "<positioningLeadingEdge><contourCoordinate>0.2</contourCoordinate>",
        "<positioningLeadingEdge><xsi1>0.2</xsi1><xsi2>0.2</xsi2>")
    lower = contour_cell("Below", 0.5, 1.0, 0.2, 0.6)
    shells = (f"<upperShell><skin/><cells>{upper}{mixed}</cells></upperShell>"
              f"<lowerShell><skin/><cells>{lower}</cells></lowerShell>")
    path = two_segment_wing(tmp_path, shells)
    answers = ask(path, {"op": "component_surface_area", "uid": "Aft"}, {"op": "bounding_box", "uid": "Aft"},
                  {"op": "component_surface_area", "uid": "Across"}, {"op": "bounding_box", "uid": "Across"},
                  {"op": "bounding_box", "uid": "Sliver"}, {"op": "bounding_box", "uid": "Below"},
                  {"op": "component_surface_area", "uid": "Below"}, {"op": "component_volume", "uid": "Aft"},
                  {"op": "component_surface_area", "uid": "Mixed"})
    area, box, across, across_box, sliver_box, below_box, below, volume = (a["ok"] for a in answers[:-1])
    assert area == pytest.approx(3.0 * skin_length(0.2, 0.6), rel=1e-6)
    assert box["min"][:2] == pytest.approx([1.4, 2.0], abs=1e-6) and box["max"][:2] == pytest.approx([2.2, 5.0], abs=1e-6)
    # From y = 0.5 in the first segment over the section at y = 1 to y = 2 in the second.
    assert across == pytest.approx(1.5 * skin_length(0.2, 0.6), rel=1e-6)
    assert across_box["min"][1] == pytest.approx(0.5, abs=1e-6) and across_box["max"][1] == pytest.approx(2.0, abs=1e-6)
    # A border within 1 % of a segment's span of its end is taken at that end: no sliver faces.
    assert sliver_box["min"][1] == pytest.approx(1.0, abs=1e-6)
    # The lower shell's cell mirrors the upper one's (the airfoil is symmetric).
    assert below == pytest.approx(area, rel=1e-6) and below_box["max"][2] == pytest.approx(-box["min"][2], abs=1e-6)
    assert volume == 0
    assert "cell[4]" in answers[-1]["error"] and "needs them on all four borders" in answers[-1]["error"]


def test_cells_of_contour_coordinates_between_etas(tmp_path):
    # Chordwise contour coordinates 0.2 to 0.6 (ξ), spanwise from a quarter into the 4 m segment
    # (y = 2) to its outer end (y = 5), given by the segment's eta: the cell "Aft" above.
    def eta_border(name, eta):
        return (f"<{name}><eta1><eta>{eta}</eta><referenceUID>RS2</referenceUID></eta1>"
                f"<eta2><eta>{eta}</eta><referenceUID>RS2</referenceUID></eta2></{name}>")

    cell = ('<cell uID="ByEta">' + eta_border("positioningInnerBorder", 0.25) +
            "<positioningLeadingEdge><contourCoordinate>0.2</contourCoordinate></positioningLeadingEdge>" +
            eta_border("positioningOuterBorder", 1) +
            "<positioningTrailingEdge><contourCoordinate>0.6</contourCoordinate></positioningTrailingEdge></cell>")
    slanted = cell.replace('uID="ByEta"', 'uID="Slanted"').replace("<eta2><eta>0.25</eta>", "<eta2><eta>0.5</eta>")
    path = two_segment_wing(tmp_path, f"<upperShell><skin/><cells>{cell}{slanted}</cells></upperShell>")
    area, box, slanted_error = ask(path, {"op": "component_surface_area", "uid": "ByEta"},
                                   {"op": "bounding_box", "uid": "ByEta"},
                                   {"op": "component_surface_area", "uid": "Slanted"})
    assert area["ok"] == pytest.approx(3.0 * skin_length(0.2, 0.6), rel=1e-6)
    assert box["ok"]["min"][1] == pytest.approx(2.0, abs=1e-6) and box["ok"]["max"][1] == pytest.approx(5.0, abs=1e-6)
    # A border whose two etas differ runs across the contour coordinates: refused with its path.
    assert "cell[2]" in slanted_error["error"] and "at one eta each" in slanted_error["error"]


def cells_between_ribs(tmp_path, rib_set, with_beyond=False):
    """The chordwise ribs `rib_set` ("Ribs", as `ribs` draws them) between spars at ξ 0.2 and 0.6,
    and the cell "BetweenRibs" from rib 1 to rib 2, from the front spar to xsi 0.6 (with
    `with_beyond`, also "Beyond", up to rib 7, which the set does not have)."""
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6))
    border = ("<positioningInnerBorder><ribDefinitionUID>Ribs</ribDefinitionUID><ribNumber>1</ribNumber>"
              "</positioningInnerBorder><positioningOuterBorder><ribDefinitionUID>Ribs</ribDefinitionUID>"
              "<ribNumber>2</ribNumber></positioningOuterBorder>")
    between = (f'<cell uID="BetweenRibs"><positioningLeadingEdge><sparUID>Front</sparUID></positioningLeadingEdge>'
               "<positioningTrailingEdge><xsi1>0.6</xsi1><xsi2>0.6</xsi2></positioningTrailingEdge>"
               f"{border}</cell>")
    beyond = between.replace('uID="BetweenRibs"', 'uID="Beyond"').replace("<ribNumber>2</ribNumber>",
                                                                          "<ribNumber>7</ribNumber>")
    return with_spars(tmp_path, positions, segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1"),
                      rib_set + cells(between, *([beyond] if with_beyond else [])))


def test_cells_bounded_by_ribs(tmp_path):
    # The chordwise ribs y = 0.5, 2.5, 4.5 between spars at ξ 0.2 and 0.6 (as above); a cell from
    # rib 1 to rib 2, from the front spar to xsi 0.6: the upper skin between ξ 0.2 and 0.6 over 2 m.
    path = cells_between_ribs(tmp_path, ribs("Ribs", 0.1, 0.9, 3), with_beyond=True)
    area, box = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "BetweenRibs"},
                                      {"op": "bounding_box", "uid": "BetweenRibs"}))
    assert area == pytest.approx(2.0 * skin_length(0.2, 0.6), rel=1e-6)
    assert box["min"][1] == pytest.approx(0.5, abs=1e-6) and box["max"][1] == pytest.approx(2.5, abs=1e-6)
    missing, = ask(path, {"op": "component_surface_area", "uid": "Beyond"})
    assert "positioningOuterBorder" in missing["error"] and "has no rib 7" in missing["error"]


def test_a_cell_ends_on_the_plane_of_its_rib(tmp_path):
    # The same ribs leaning 30° about their own direction (ribCrossSection rotation x = 60°):
    # the cell between rib 1 and rib 2 ends on their planes, y = y_rib ± z·tan 30° over the skin
    # z = 0.3·ξ(1−ξ), not on upright lines through their feet. Its area stays the skin between
    # ξ 0.2 and 0.6 over 2 m (parallel planes across a skin straight along y).
    leaning = ribs("Ribs", 0.1, 0.9, 3).replace(
        "</ribsPositioning>", "</ribsPositioning><ribCrossSection><ribRotation><x>60</x></ribRotation>"
        "</ribCrossSection>")
    path = cells_between_ribs(tmp_path, leaning)
    area, box = (a["ok"] for a in ask(path, {"op": "component_surface_area", "uid": "BetweenRibs"},
                                      {"op": "bounding_box", "uid": "BetweenRibs"}))
    assert area == pytest.approx(2.0 * skin_length(0.2, 0.6), rel=1e-6)
    lean = math.tan(math.radians(30))
    low, top = 0.3 * 0.2 * 0.8, 0.3 * 0.5 * 0.5  # the skin's lowest and highest z in the cell
    shifts = (box["min"][1] - 0.5, box["max"][1] - 2.5)
    assert (shifts == pytest.approx((lean * low, lean * top), abs=1e-6) or
            shifts == pytest.approx((-lean * top, -lean * low), abs=1e-6)), shifts


def test_spar_positions_on_ribs(tmp_path):
    # The chordwise ribs y = 0.5, 2.5, 4.5 between the spars at ξ 0.2 and 0.6; a third spar from the
    # middle of rib 1 to the middle of rib 3 (xsi 0.5 along each rib: ξ 0.4) is the plane web at
    # ξ 0.4 from y = 0.5 to 4.5.
    on_rib = "".join(f'<sparPosition uID="{uid}"><sparPositionRib><ribDefinitionUID>Ribs</ribDefinitionUID>'
                     f"<ribNumber>{number}</ribNumber><xsi>0.5</xsi></sparPositionRib></sparPosition>"
                     for uid, number in (("OnRib1", 1), ("OnRib3", 3), ("OnRib9", 9)))
    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6) + on_rib)
    segments = (segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1") +
                segment("Middle", "OnRib1", "OnRib3") + segment("Broken", "OnRib1", "OnRib9"))
    path = with_spars(tmp_path, positions, segments, ribs("Ribs", 0.1, 0.9, 3))
    area, box, broken = ask(path, {"op": "component_surface_area", "uid": "Middle"},
                            {"op": "bounding_box", "uid": "Middle"}, {"op": "component_surface_area", "uid": "Broken"})
    assert area["ok"] == pytest.approx(4.0 * height(0.4), rel=1e-7)
    assert box["ok"]["min"][0] == pytest.approx(1.8, abs=1e-6) and box["ok"]["min"][1] == pytest.approx(0.5, abs=1e-6)
    assert "sparPosition[7]/sparPositionRib" in broken["error"] and "has no rib 9" in broken["error"]


def test_spar_positions_on_curves(tmp_path):
    # Spars at ξ 0.2 and 0.6 over the whole span (y 0 to 5); a diagonal spar from a quarter of the
    # front spar's length (y 1.25, ξ 0.2) to three quarters of the rear spar's (y 3.75, ξ 0.6): one
    # plane piece along which ξ runs linearly from 0.2 to 0.4.
    def on_curve(uid, eta, line):
        return (f'<sparPosition uID="{uid}"><sparPositionCurve><eta>{eta}</eta>'
                f"<referenceUID>{line}</referenceUID></sparPositionCurve></sparPosition>")

    positions = (position("PosF0", 0, 0.2) + position("PosF1", 1, 0.2) + position("PosR0", 0, 0.6) +
                 position("PosR1", 1, 0.6) + on_curve("OnFront", 0.25, "Front") + on_curve("OnRear", 0.75, "Rear") +
                 on_curve("OnLoop", 0.5, "Loop") + on_curve("OnNothing", 0.5, "Nothing"))
    segments = (segment("Front", "PosF0", "PosF1") + segment("Rear", "PosR0", "PosR1") +
                segment("Diagonal", "OnFront", "OnRear") + segment("Loop", "PosF0", "OnLoop") +
                segment("Dangling", "PosF0", "OnNothing"))
    path = with_spars(tmp_path, positions, segments)
    area, box, loop, dangling = ask(path, {"op": "component_surface_area", "uid": "Diagonal"},
                                    {"op": "bounding_box", "uid": "Diagonal"},
                                    {"op": "component_surface_area", "uid": "Loop"},
                                    {"op": "component_surface_area", "uid": "Dangling"})
    mean = (0.6 * (0.6 ** 2 / 2 - 0.6 ** 3 / 3) - 0.6 * (0.2 ** 2 / 2 - 0.2 ** 3 / 3)) / 0.4
    assert area["ok"] == pytest.approx(math.hypot(2.5, 0.8) * mean, rel=1e-7)
    assert box["ok"]["min"][:2] == pytest.approx([1.4, 1.25], abs=1e-6)
    assert box["ok"]["max"][:2] == pytest.approx([2.2, 3.75], abs=1e-6)
    assert "sparPosition[7]/sparPositionCurve/referenceUID" in loop["error"]
    assert "positioned on itself" in loop["error"]
    assert "sparPosition[8]/sparPositionCurve/referenceUID" in dangling["error"] and "'Nothing'" in dangling["error"]


def flap_structure():
    """A spar at device xsi 0.5 of the test wing's flap, a rib at its eta 0.5 and a cell of its
    upper skin aft of the spar."""
    def eta_xsi(kind, eta, xsi):
        return f"<{kind}><eta>{eta}</eta><xsi>{xsi}</xsi><referenceUID>RectCS</referenceUID></{kind}>"

    return (
        "<structure><upperShell><skin/><cells><cell uID=\"FlapCell\">"
        "<positioningLeadingEdge><sparUID>FlapSpar</sparUID></positioningLeadingEdge>"
        "<positioningTrailingEdge><xsi1>1</xsi1><xsi2>1</xsi2></positioningTrailingEdge>"
        "<positioningInnerBorder><eta1><eta>0</eta><referenceUID>Flap</referenceUID></eta1>"
        "<eta2><eta>0</eta><referenceUID>Flap</referenceUID></eta2></positioningInnerBorder>"
        "<positioningOuterBorder><eta1><eta>1</eta><referenceUID>Flap</referenceUID></eta1>"
        "<eta2><eta>1</eta><referenceUID>Flap</referenceUID></eta2></positioningOuterBorder>"
        "</cell></cells></upperShell>"
        '<ribsDefinitions><ribsDefinition uID="FlapRib"><name>r</name><ribExplicitPositioning>'
        f"{eta_xsi('startEtaXsiPoint', 0.5, 0)}{eta_xsi('endEtaXsiPoint', 0.5, 1)}"
        "<ribStart>le</ribStart><ribEnd>trailingEdge</ribEnd></ribExplicitPositioning></ribsDefinition>"
        "</ribsDefinitions><spars><sparPositions>"
        + position("FlapSpar0", 0, 0.5) + position("FlapSpar1", 1, 0.5)
        + "</sparPositions><sparSegments>" + segment("FlapSpar", "FlapSpar0", "FlapSpar1")
        + "</sparSegments></spars></structure>")


def with_flap_structure(text, path):
    """The file's text with flap_structure() in its flap, written to path."""
    at = text.index("<path>", text.index('<trailingEdgeDevice uID="Flap">'))
    path.write_text(text[:at] + flap_structure() + text[at:])
    return path


def test_the_structure_of_a_flap_in_its_own_coordinates(tmp_path):
    # The flap of the test wing spans component segment eta 0.2 to 0.8 (y 1 to 4) aft of xsi 0.7
    # (x 2.4 to 3). Its own spar at device xsi 0.5 (ξ 0.85, x 2.7) from its inner to its outer
    # border, positioned with the component segment as reference (as the D150 and D250 files
    # do), its own rib at device eta 0.5 (y 2.5) from its leading to its trailing edge, and a
    # cell of its upper skin aft of its spar.
    with open(WITH_DEVICES) as original:
        path = with_flap_structure(original.read(), tmp_path / "flap-structure.xml")
    answers = ask(path, {"op": "component_surface_area", "uid": "FlapSpar"}, {"op": "bounding_box", "uid": "FlapSpar"},
                  {"op": "component_surface_area", "uid": "FlapRib"}, {"op": "bounding_box", "uid": "FlapRib"},
                  {"op": "component_surface_area", "uid": "FlapCell"}, {"op": "component_type", "uid": "FlapSpar"})
    spar_area, spar_box, rib_area, rib_box, cell_area, kind = (a.get("ok", a) for a in answers)
    assert kind == "wing_spar"
    # The flap is cut from the wing by a Boolean operation, but its spar, rib and cell are made
    # from the wing's untrimmed skins in common with the simple solid that cuts the flap out
    # (docs/structure.md), without the Boolean's tolerance: the areas hold to 1e-9 (the boxes
    # carry the edges' tolerance, 1e-7).
    assert spar_area == pytest.approx(3 * height(0.85), rel=1e-9)
    assert spar_box["min"][0] == pytest.approx(2.7, abs=1e-6) and spar_box["max"][0] == pytest.approx(2.7, abs=1e-6)
    assert spar_box["min"][1] == pytest.approx(1, abs=1e-6) and spar_box["max"][1] == pytest.approx(4, abs=1e-6)
    # The flap's section at y = 2.5: 2 · ∫ from ξ 0.7 to 1 of 0.6 ξ(1 − ξ) dξ.
    assert rib_area == pytest.approx(1.2 * ((1 / 2 - 1 / 3) - (0.7 ** 2 / 2 - 0.7 ** 3 / 3)), rel=1e-9)
    assert rib_box["min"][1] == pytest.approx(2.5, abs=1e-6) and rib_box["min"][0] == pytest.approx(2.4, abs=1e-6)
    assert cell_area == pytest.approx(3 * skin_length(0.85, 1), rel=1e-9)
    warned = airshape("query", str(path), stdin=json.dumps({"op": "component_surface_area", "uid": "FlapRib"}) + "\n")
    assert "'le' read as leadingEdge" in warned.stderr and "ribExplicitPositioning/ribStart" in warned.stderr
