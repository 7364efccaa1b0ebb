"""Control devices (QUERY-components §3): which devices a wing counts and in which order, their
kinds and control parameter ranges; devices at rest and deflected on a wing whose figures are
known in closed form (docs/controlsurfaces.md)."""
import json
import math
import os
import re

import pytest

from conftest import EXAMPLE, SOURCE, airshape, conformance_passed, shared_path
from independent_readers import gmsh_solids, gmsh_volumes, vtk_polydata

with open(EXAMPLE) as example:
    AIRCRAFT = example.read()


def steps(*parameters):
    return ("<path><steps>" + "".join(f"<step><controlParameter>{p}</controlParameter></step>" for p in parameters) +
            "</steps></path>")


def device(kind, uid, path=""):
    return f'<{kind} uID="{uid}"><name>d</name><parentUID>CS</parentUID>{path}</{kind}>'


SEGMENTS = f"""<componentSegments>
  <componentSegment uID="CS"><name>inner</name><fromElementUID>WS1_E1</fromElementUID><toElementUID>WS2_E1</toElementUID>
    <controlSurfaces>
      <leadingEdgeDevices>{device("leadingEdgeDevice", "Slat", steps(0, 1))}</leadingEdgeDevices>
      <trailingEdgeDevices>{device("trailingEdgeDevice", "Flap", steps(-1, 0, 2))}</trailingEdgeDevices>
      <spoilers>{device("spoiler", "Spoiler", steps(0, 1))}</spoilers>
    </controlSurfaces>
  </componentSegment>
  <componentSegment uID="CS2"><name>outer</name><fromElementUID>WS2_E1</fromElementUID><toElementUID>WS3_E1</toElementUID>
    <controlSurfaces><trailingEdgeDevices>{device("trailingEdgeDevice", "Aileron", steps(25, -25))}
    {device("trailingEdgeDevice", "Stepless")}</trailingEdgeDevices></controlSurfaces>
  </componentSegment>
</componentSegments></wing>"""


def ask(tmp_path, *queries):
    path = tmp_path / "devices.xml"
    path.write_text(AIRCRAFT.replace("</wing>", SEGMENTS, 1))
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    return [json.loads(line) for line in result.stdout.splitlines()]


def test_devices_in_the_protocols_order_without_spoilers(tmp_path):
    answers = ask(tmp_path, {"op": "control_surface_count", "wing": "MainWing"},
                  *({"op": "control_surface_uid", "wing": 1, "index": i} for i in range(1, 6)))
    # Trailing-edge devices before leading-edge devices within a component segment.
    assert [a.get("ok") for a in answers[:5]] == [4, "Flap", "Slat", "Aileron", "Stepless"], answers
    assert "out of range" in answers[5]["error"]


def test_kinds_and_control_parameter_ranges(tmp_path):
    answers = ask(tmp_path, *({"op": "control_surface_type", "uid": uid} for uid in ("Flap", "Slat", "Spoiler")),
                  *({"op": "control_surface_parameter_range", "uid": uid} for uid in ("Flap", "Aileron")),
                  {"op": "control_surface_type", "uid": "MainWing"},
                  {"op": "control_surface_parameter_range", "uid": "Stepless"})
    assert [a["ok"] for a in answers[:3]] == ["trailing_edge_device", "leading_edge_device", "spoiler"]
    assert answers[3]["ok"] == {"min": -1, "max": 2}
    assert answers[4]["ok"] == {"min": 25, "max": -25}, "first and last step, in document order"
    assert answers[5] == {"error": "no control surface with uID 'MainWing'"}
    assert "trailingEdgeDevice[2]/path: the control surface has no path steps" in answers[6]["error"]


def test_spoilers_are_counted_on_their_own(tmp_path):
    answers = ask(tmp_path, {"op": "spoiler_count", "wing": 1}, {"op": "spoiler_uid", "wing": 1, "index": 1},
                  {"op": "spoiler_uid", "wing": 1, "index": 2}, {"op": "control_surface_uid", "wing": 1, "index": "Flap"})
    assert answers[0] == {"ok": 1} and answers[1] == {"ok": "Spoiler"}
    assert "out of range" in answers[2]["error"]
    assert answers[3] == {"error": "argument 'index' must be a 1-based integer"}


def test_spoilers_are_components_the_component_list_leaves_out(tmp_path):
    listed, kind, volume, every = ask(tmp_path, {"op": "component_list"}, {"op": "component_type", "uid": "Spoiler"},
                                      {"op": "component_volume", "uid": "Slat"}, {"op": "component_list", "all": True})
    uids = [entry["uid"] for entry in listed["ok"]]
    # The list is the reference's components (QUERY-components §1), which has no spoilers.
    assert "Flap" in uids and "Slat" in uids and "Spoiler" not in uids
    assert kind == {"ok": "control_surface"}
    assert uids == sorted(uids)
    assert {"uid": "Spoiler", "type": "control_surface"} in every["ok"]  # all: every component


# A rectangular wing (chord 2, span 5, x from 1 to 3) of parabolic arcs z = ±0.15·c·ξ(1−ξ),
# ξ = x/c: the section area aft of ξ0 is 0.3·c²·(1/6 − ξ0²/2 + ξ0³/3), so a plain flap's volume
# is known in closed form, and its hinge line (on the chord, the airfoil is symmetric) too. Its
# devices: a plain flap (aft of xsi 0.7, eta 0.2 .. 0.8, hinge on the chord at xsi 0.7, 20° at
# p = 1), a slat (ahead of xsi 0.15 with a hollow back, -20° at p = 1), a spoiler (xsi 0.5 ..
# 0.65, eta 0.3 .. 0.6, down to half the height).
WITH_DEVICES = os.path.join(os.path.dirname(__file__), "..", "data", "wing-cst-devices.xml")


def section_area_aft(xi, chord=2.0):
    return 0.3 * chord ** 2 * (1 / 6 - xi ** 2 / 2 + xi ** 3 / 3)


def ask_rectangular(*queries):
    result = airshape("query", WITH_DEVICES, stdin="".join(json.dumps(q) + "\n" for q in queries))
    answers = [json.loads(line) for line in result.stdout.splitlines()]
    assert all("ok" in a for a in answers), answers
    return [a["ok"] for a in answers]


def test_a_plain_flap_at_rest_and_deflected_in_closed_form():
    volume, area, box, motion, moved_volume, moved_box = ask_rectangular(
        {"op": "component_volume", "uid": "Flap"}, {"op": "component_surface_area", "uid": "Flap"},
        {"op": "bounding_box", "uid": "Flap"}, {"op": "control_surface_deflection", "uid": "Flap", "control_parameter": 1},
        {"op": "control_surface_volume", "uid": "Flap", "control_parameter": 0.5},
        {"op": "control_surface_bounding_box", "uid": "Flap", "control_parameter": 1})
    # The CST sides are B-splines within 1e-5 of the chord of the parabolas.
    assert volume == pytest.approx(3.0 * section_area_aft(0.7), rel=1e-6)
    assert box["min"][:2] == pytest.approx([2.4, 1.0], abs=1e-6) and box["max"][:2] == pytest.approx([3.0, 4.0], abs=1e-6)
    assert box["max"][2] == pytest.approx(0.15 * 2 * 0.7 * 0.3, abs=1e-6), "the skin's height at the flap's front"
    assert area > 2 * 3.0 * 0.6, "skins above and below, front face and sides"
    # The hinge line lies on the chord at x = 2.4: 20 degrees about +y through it, trailing edge down.
    angle = math.radians(20)
    assert motion["rotation"] == pytest.approx(20, abs=1e-9)
    expected_rotation = [[math.cos(angle), 0, math.sin(angle)], [0, 1, 0], [-math.sin(angle), 0, math.cos(angle)]]
    for row, expected in zip(motion["matrix"], expected_rotation):
        assert row[:3] == pytest.approx(expected, abs=1e-12)
    hinge = [2.4, 0.0, 0.0]
    translation = [hinge[i] - sum(expected_rotation[i][k] * hinge[k] for k in range(3)) for i in range(3)]
    assert [row[3] for row in motion["matrix"]] == pytest.approx(translation, abs=1e-12)
    assert moved_volume == pytest.approx(volume, rel=1e-7), "a rigid motion keeps the volume"
    # The trailing edge (x = 3, z = 0) turns down to 2.4 + 0.6 cos 20°, −0.6 sin 20°.
    assert moved_box["min"][2] == pytest.approx(-0.6 * math.sin(angle), abs=1e-6)
    assert moved_box["max"][0] == pytest.approx(2.4 + 0.6 * math.cos(angle), abs=1e-3)


def test_a_slat_and_a_spoiler_lie_where_their_borders_say():
    slat, slat_box, slat_motion, spoiler, spoiler_box = ask_rectangular(
        {"op": "component_volume", "uid": "Slat"}, {"op": "bounding_box", "uid": "Slat"},
        {"op": "control_surface_deflection", "uid": "Slat", "control_parameter": 1},
        {"op": "component_volume", "uid": "Spoiler"}, {"op": "bounding_box", "uid": "Spoiler"})
    # The slat's chord ends at xsi 0.15; its hollow back meets the skins at 0.15 of that chord
    # from its end (xsi 0.1275) and is deepest halfway (xsi 0.075): it holds the nose up to
    # 0.075 and lies within the nose up to 0.1275.
    def nose(xi):
        return 3.0 * (section_area_aft(0.0) - section_area_aft(xi))

    assert nose(0.075) < slat < nose(0.1275)
    assert slat_box["min"][:2] == pytest.approx([1.0, 1.0], abs=1e-6) and slat_box["max"][0] <= 1.3 + 1e-6
    assert slat_motion["rotation"] == pytest.approx(20, abs=1e-9) and slat_motion["matrix"][0][2] < 0, "nose down"
    # The spoiler is the upper half of the wing between xsi 0.5 and 0.65 over eta 0.3 .. 0.6.
    upper_half = 1.5 * (section_area_aft(0.5) - section_area_aft(0.65)) / 2
    assert spoiler == pytest.approx(upper_half, rel=1e-5)
    assert spoiler_box["min"] == pytest.approx([2.0, 1.5, 0.0], abs=1e-6)
    assert spoiler_box["max"][:2] == pytest.approx([2.3, 3.0], abs=1e-6)


def export_summary(result):
    """{solid name: volume} from the summary `airshape export` prints."""
    assert result.returncode == 0, result.stderr
    rows = result.stdout.split("area [m2]\n", 1)[1].split("total time")[0].strip().splitlines()
    return {row.rsplit(None, 2)[0].strip(): float(row.rsplit(None, 2)[1]) for row in rows}


def test_the_wing_with_deflected_devices_exports_as_named_solids(tmp_path):
    source = WITH_DEVICES
    step, vtp = tmp_path / "deflected.step", tmp_path / "deflected.vtp"
    result = airshape("export", str(source), "--deflect", "Flap=1,Slat=max,Spoiler=0.5", "--components", "Rect", "-o",
                      str(step), "-o", str(vtp))
    volumes = export_summary(result)
    # The cut, the longest step, is said on the progress lines like the builds before it.
    assert re.search(r"^export: 4/4 cut its moving parts out of Rect, [0-9.]+ s$", result.stderr, re.M)
    flap = 3.0 * section_area_aft(0.7)
    assert volumes["Flap"] == pytest.approx(flap, abs=1e-4)
    # The wing loses exactly what its devices take out of it (they do not overlap).
    assert volumes["Rect"] == pytest.approx(1.0 - volumes["Flap"] - volumes["Slat"] - volumes["Spoiler"], abs=2e-4)
    # A CAD reader sees the four solids, each of its own volume, the flap turned 20° about
    # its hinge line (its trailing edge below the wing).
    read = {name.rsplit("/", 1)[-1]: volume for name, volume in gmsh_volumes(str(step))}
    assert sorted(read) == ["Flap", "Rect", "Slat", "Spoiler"]
    assert read["Rect"] == pytest.approx(volumes["Rect"], rel=1e-2)
    faces = set(vtk_polydata(str(vtp))["arrays"]["face"])
    assert {"Flap/upper", "Flap/lower", "Flap/leading edge", "Flap/inner side", "Flap/outer side", "Slat/trailing edge",
            "Spoiler/upper", "Flap/cut-out", "RS/upper"} <= faces
    box = ask_rectangular({"op": "control_surface_bounding_box", "uid": "Flap", "control_parameter": 1})[0]
    assert box["min"][2] == pytest.approx(-0.6 * math.sin(math.radians(20)), abs=1e-6)


def test_the_wing_loses_the_union_of_devices_that_overlap(tmp_path):
    # The spoiler made to reach xsi 0.8 overlaps the flap (aft of 0.7) over its span (eta 0.3 ..
    # 0.6, 1.5 m): the wing loses the flap, the spoiler's upper half from 0.5 to 0.8, less their
    # common upper half from 0.7 to 0.8, once. (Cut by both cut-outs as two tools at once, OCCT
    # kept most of the flap.)
    text = open(WITH_DEVICES).read()
    spoiler = text.index('<spoiler uID="Spoiler">')
    reaching = text[:spoiler] + text[spoiler:].replace("<xsi>0.65</xsi>", "<xsi>0.8</xsi>", 2)
    path = tmp_path / "overlapping.xml"
    path.write_text(reaching)
    volumes = export_summary(airshape("export", str(path), "--deflect", "Flap=1,Spoiler=0.5", "--components", "Rect",
                                      "-o", str(tmp_path / "deflected.brep")))
    def upper_half(xi_from, xi_to):
        return 1.5 * (section_area_aft(xi_from) - section_area_aft(xi_to)) / 2
    flap, spoiler = 3.0 * section_area_aft(0.7), upper_half(0.5, 0.8)
    assert volumes["Spoiler"] == pytest.approx(spoiler, abs=1e-4)
    assert volumes["Rect"] == pytest.approx(1.0 - (flap + spoiler - upper_half(0.7, 0.8)), abs=2e-4)


def test_spoilers_over_flaps_take_out_no_less_than_either_alone(tmp_path):
    # CPACS_30_aircraft_flaps.xml's five spoilers overlap its two flaps. Cut by every device,
    # the wing loses at least what the flaps, slats and aileron alone take and at least what the
    # spoilers alone take, and at most both together. (Cut by them as eleven tools at once, OCCT
    # kept 21.574 -> 22.986 m³: less than the flaps alone took out.)
    source = shared_path("data", "cpacs", "CPACS_30_aircraft_flaps.xml")
    prefix = "D150_VAMP_W1_CompSeg1_"
    groups = {"all": "all=max",
              "flaps": ",".join(f"{prefix}{d}=max" for d in ("innerFlap", "outerFlap", "aileron", "innerLED",
                                                              "outerLED1", "outerLED2")),
              "spoilers": ",".join(f"{prefix}Spoiler{k}=max" for k in range(4, 9))}
    wing = {}
    for name, poses in groups.items():
        volumes = export_summary(airshape("export", source, "--deflect", poses, "--components", "D150_VAMP_W1", "-o",
                                          str(tmp_path / f"{name}.brep")))
        wing[name] = volumes["D150_VAMP_W1"]
    clean, = [json.loads(line)["ok"] for line in airshape(
        "query", source, stdin='{"op":"component_volume","uid":"D150_VAMP_W1"}\n').stdout.splitlines()]
    assert wing["all"] < min(wing["flaps"], wing["spoilers"]) - 0.1
    assert wing["all"] >= wing["flaps"] + wing["spoilers"] - clean - 1e-4


def test_all_deflects_the_devices_of_the_components_exported(tmp_path):
    # The example airliner's devices are all on its main wing: exporting the tails with
    # `all=max` writes the tails alone; a device named on its own is written wherever it lies.
    airliner = os.path.join(SOURCE, "examples", "generic-airliner.xml")
    def written(*arguments):
        return set(export_summary(airshape("export", airliner, *arguments, "-o", str(tmp_path / "out.brep"),
                                           "--force")))
    assert written("--deflect", "all=max", "--components", "HTP,VTP") == {"HTP", "VTP"}
    assert written("--deflect", "all=max", "--components", "Wing") == {
        "Wing", "InnerFlap", "OuterFlap", "Aileron", "Slat", "Spoiler"}
    assert written("--deflect", "all=max,InnerFlap=1", "--components", "HTP") == {"HTP", "InnerFlap"}


def test_without_deflect_the_export_is_unchanged_and_bad_poses_are_one_line(tmp_path):
    source = WITH_DEVICES
    plain = export_summary(airshape("export", str(source), "-o", str(tmp_path / "plain.brep")))
    assert set(plain) == {"Rect", "Swept"} and plain["Rect"] == pytest.approx(1.0, abs=1e-6)
    for deflect, message in (("Flap=3", "lies outside the range [0.000000, 1.000000] of 'Flap'"),
                             ("Rect=1", "'Rect' names no moving component"), ("Flap", "expected UID=P"),
                             ("all=0.5", "all takes min or max"), ("Flap=up", "'up' is not a control parameter")):
        result = airshape("export", str(source), "--deflect", deflect, "-o", str(tmp_path / "bad.brep"))
        assert result.returncode == 2 and message in result.stderr, (deflect, result.stderr)
        assert len(result.stderr.strip().splitlines()) == 1
        assert not (tmp_path / "bad.brep").exists()


def transform(matrix, point):
    return [sum(row[k] * point[k] for k in range(3)) + row[3] for row in matrix]


def compose(outer, inner):
    """The 3x4 matrix of applying `inner`, then `outer`."""
    return [[sum(outer[i][k] * inner[k][j] for k in range(3)) + (outer[i][3] if j == 3 else 0) for j in range(4)]
            for i in range(3)]


def test_a_tab_is_cut_out_of_its_flap_and_moves_with_it(tmp_path):
    at_rest, posed = tmp_path / "rest.step", tmp_path / "posed.step"
    export_summary(airshape("export", WITH_DEVICES, "--components", "Tab,Flap", "-o", str(at_rest)))
    volumes = export_summary(airshape("export", WITH_DEVICES, "--deflect", "Flap=1,Tab=1", "--components", "Rect",
                                      "-o", str(posed)))
    tab = 1.0 * section_area_aft(0.9)  # aft of xsi 0.9 over 1 m of span
    assert volumes["Tab"] == pytest.approx(tab, abs=1e-4)
    assert volumes["Flap"] == pytest.approx(3.0 * section_area_aft(0.7) - tab, abs=1e-4), "the flap less its tab"
    assert volumes["Rect"] == pytest.approx(1.0 - 3.0 * section_area_aft(0.7), abs=1e-4), "the wing less the flap"
    flap, own = (ask_rectangular({"op": "control_surface_deflection", "uid": uid, "control_parameter": 1})[0]["matrix"]
                 for uid in ("Flap", "Tab"))
    rest = {name.rsplit("/", 1)[-1]: centre for name, _, centre in gmsh_solids(str(at_rest))}
    moved = {name.rsplit("/", 1)[-1]: centre for name, _, centre in gmsh_solids(str(posed))}
    # The tab turns about its own hinge line, then with its flap about the flap's.
    assert moved["Tab"] == pytest.approx(transform(compose(flap, own), rest["Tab"]), abs=1e-6)


def airfoil_border(eta):
    return (f"<etaLE><eta>{eta}</eta><referenceUID>RectCS</referenceUID></etaLE><xsiLE><xsi>0.7</xsi>"
            "<referenceUID>RectCS</referenceUID></xsiLE><airfoil><airfoilUID>Parabolic</airfoilUID><rotX>90</rotX>"
            "<scalY>1</scalY><scalZ>1</scalZ></airfoil>")


def test_intermediate_airfoils_shape_a_device_of_airfoils(tmp_path):
    # Borders of the wing's own airfoil (z scaled by 1 on a chord of 0.6: area 0.6 * 0.05) and,
    # halfway, the same airfoil twice as thick: two ruled pieces of 1.5 m, in closed form.
    intermediate = ("<intermediateAirfoils><intermediateAirfoil><eta><eta>0.5</eta><referenceUID>RectCS</referenceUID>"
                    "</eta><airfoilUID>Parabolic</airfoilUID><rotX>90</rotX><rotZ>90</rotZ><scalY>1</scalY>"
                    "<scalZ>2</scalZ></intermediateAirfoil></intermediateAirfoils>")
    device = ('<trailingEdgeDevice uID="Shaped"><name>s</name><parentUID>RectCS</parentUID><outerShape>'
              f"<innerBorder>{airfoil_border(0.2)}</innerBorder><outerBorder>{airfoil_border(0.8)}</outerBorder>"
              f"{intermediate}</outerShape></trailingEdgeDevice>")
    with open(WITH_DEVICES) as original:
        text = original.read()
    path = tmp_path / "intermediate.xml"
    path.write_text(text.replace("<trailingEdgeDevices>", "<trailingEdgeDevices>" + device, 1))
    plain = tmp_path / "plain.xml"
    plain.write_text(path.read_text().replace(intermediate, ""))
    queries = json.dumps({"op": "component_volume", "uid": "Shaped"}) + "\n"
    shaped = json.loads(airshape("query", str(path), stdin=queries).stdout)["ok"]
    straight = json.loads(airshape("query", str(plain), stdin=queries).stdout)["ok"]
    section = 0.6 * 0.05
    assert straight == pytest.approx(3.0 * section, rel=1e-4)
    assert shaped == pytest.approx(2 * 1.5 * (section + 2 * section) / 2, rel=1e-4)


def test_a_wing_cut_out_removes_the_skins_from_its_xsi(tmp_path):
    # The flap's wingCutOut opens the upper skin from xsi 0.6 and the lower from 0.65: the wing
    # loses the section aft of the straight line between those skin points, over 3 m of span.
    cut_out = ("<wingCutOut><upperSkin><xsiInnerBorder>0.6</xsiInnerBorder><xsiOuterBorder>0.6</xsiOuterBorder>"
               "</upperSkin><lowerSkin><xsiInnerBorder>0.65</xsiInnerBorder><xsiOuterBorder>0.65</xsiOuterBorder>"
               "</lowerSkin></wingCutOut>")
    with open(WITH_DEVICES) as original:
        text = original.read()
    end_of_shape = text.index("</outerShape>", text.index('uID="Flap"')) + len("</outerShape>")
    path = tmp_path / "cut-out.xml"
    path.write_text(text[:end_of_shape] + cut_out + text[end_of_shape:])
    volumes = export_summary(airshape("export", str(path), "--deflect", "Flap=1", "--components", "Rect", "-o",
                                      str(tmp_path / "cut.brep")))

    def skin(xi, sign):  # chord 2 from x = 0: z = ±0.15·2·ξ(1−ξ)
        return (2 * xi, sign * 0.3 * xi * (1 - xi))

    n = 4000
    outline = ([skin(0.6 + 0.4 * k / n, 1) for k in range(n + 1)] +
               [skin(1 - 0.35 * k / n, -1) for k in range(n + 1)])
    area = 0.5 * abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(outline, outline[1:] + outline[:1])))
    assert volumes["Rect"] == pytest.approx(1.0 - 3.0 * area, abs=1e-4)  # the summary has 4 decimals
    assert volumes["Flap"] == pytest.approx(3.0 * section_area_aft(0.7), abs=1e-4), "the flap is as before"


def nose_ahead_of(xi_upper, xi_lower, n=4000):
    """The section area (chord 2) ahead of the straight line from the upper skin at xi_upper to
    the lower skin at xi_lower, by the shoelace formula on the parabolas."""
    def skin(xi, sign):
        return (2 * xi, sign * 0.3 * xi * (1 - xi))

    outline = ([skin(xi_upper * (1 - k / n), 1) for k in range(n + 1)] +
               [skin(xi_lower * k / n, -1) for k in range(n + 1)])
    return 0.5 * abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(outline, outline[1:] + outline[:1])))


@pytest.mark.parametrize("upper,lower", [(0.15, 0.15), (0.15, 0.1)])
def test_a_slat_without_a_shape_is_the_nose_ahead_of_a_straight_cut(tmp_path, upper, lower):
    # Without innerShape a slat is the wing ahead of the straight line from the upper skin at
    # xsiTEUpper to the lower skin at xsiTELower, over eta 0.2 .. 0.8 (3 m of span).
    with open(WITH_DEVICES) as original:
        text = original.read()
    start = text.index('<leadingEdgeDevice uID="Slat">')
    shape = text[text.index("<outerShape>", start):text.index("</outerShape>", start)]
    plain = shape.replace("<innerShape>", "<!--").replace("</innerShape>", "-->")
    plain = plain.replace("<xsiTE>\n", "<xsiTE>", 2)
    for old in [plain[plain.index("<xsiTE>"):plain.index("</xsiTE>") + len("</xsiTE>")]] * 2:
        plain = plain.replace(old, f"<xsiTEUpper>{upper}</xsiTEUpper><xsiTELower>{lower}</xsiTELower>", 1)
    path = tmp_path / "plain-slat.xml"
    path.write_text(text.replace(shape, plain, 1))
    volume, box = (json.loads(line)["ok"] for line in airshape(
        "query", str(path), stdin=json.dumps({"op": "component_volume", "uid": "Slat"}) + "\n" +
        json.dumps({"op": "bounding_box", "uid": "Slat"}) + "\n").stdout.splitlines())
    assert volume == pytest.approx(3.0 * nose_ahead_of(upper, lower), rel=1e-5)
    assert box["min"][:2] == pytest.approx([1.0, 1.0], abs=1e-6) and box["max"][:2] == pytest.approx([1.3, 4.0], abs=1e-6)


def built_volume(path, uid):
    """`airshape build` of a file: the device's volume, asserting it is a valid solid, and the
    command's warnings."""
    built = airshape("build", str(path))
    found = re.search(rf"control_surface +{uid} +valid solid, volume ([0-9.e-]+)", built.stdout)
    assert found, built.stdout
    return float(found.group(1)), built.stderr


def flap_with_outer_border(tmp_path, border, name):
    """The test wing with its flap's outer border opened as `border` (up to its xsiLE)."""
    with open(WITH_DEVICES) as original:
        text = original.read()
    outer = text.index("<outerBorder>", text.index('<trailingEdgeDevice uID="Flap">'))
    end = text.index("</outerBorder>", outer)
    path = tmp_path / f"{name}.xml"
    path.write_text(text[:outer] + border + text[end:])
    return path


def airliner_with(tmp_path, control_surfaces, name):
    """The example airliner (without its tanks) with its wing's devices replaced."""
    with open(os.path.join(SOURCE, "examples", "generic-airliner.xml")) as original:
        text = re.sub(r"<wingFuelTanks>.*?</wingFuelTanks>", "", original.read(), flags=re.S)
    path = tmp_path / f"{name}.xml"
    path.write_text(re.sub(r"<controlSurfaces>.*?</controlSurfaces>", f"<controlSurfaces>{control_surfaces}"
                           "</controlSurfaces>", text, count=1, flags=re.S))
    return path


ROUNDED_NOSE = ("<leadingEdgeShape><relHeightLE>0.5</relHeightLE><xsiUpperSkin>0.9</xsiUpperSkin>"
                "<xsiLowerSkin>0.9</xsiLowerSkin></leadingEdgeShape>")


@pytest.mark.parametrize("rounded", ["innerBorder", "outerBorder"])
def test_a_flap_with_one_rounded_border_lies_between_the_straight_and_the_rounded_flap(tmp_path, rounded):
    # A file may give one border a leadingEdgeShape and leave the other a straight cut; the ruled
    # solid between a rounded and a straight outline then takes out less than the straight flap
    # and more than the flap rounded at both borders, and is a valid solid.
    with open(WITH_DEVICES) as original:
        text = original.read()
    start = text.index('<trailingEdgeDevice uID="Flap">')
    end = text.index("</outerShape>", start)

    def flap_volume(borders, name):
        shape = text[start:end]
        for border in borders:
            at = shape.index(f"</{border}>")
            shape = shape[:at] + ROUNDED_NOSE + shape[at:]
        path = tmp_path / f"{name}.xml"
        path.write_text(text[:start] + shape + text[end:])
        return built_volume(path, "Flap")[0]

    straight = flap_volume([], "straight")
    both = flap_volume(["innerBorder", "outerBorder"], "both")
    one = flap_volume([rounded], "one")
    assert both < one < straight, (both, one, straight)
    assert min(one - both, straight - one) > 0.2 * (straight - both)


def test_a_flap_whose_oblique_border_runs_inboard_is_the_wing_between_its_planes(tmp_path):
    # The outer border from (eta 0.5, xsi 0.7) to (eta 0.3, xsi 1): its chord runs inboard. The
    # flap is the wing aft of x = 2.4 between y = 1 and the vertical plane through (2.4, 2.5) and
    # (3, 1.5): its span at x is 1.5 - (x - 2.4) / 0.6, its thickness 0.6 xi (1 - xi).
    oblique = ("<outerBorder><etaLE><eta>0.5</eta><referenceUID>RectCS</referenceUID></etaLE><etaTE><eta>0.3</eta>"
               "<referenceUID>RectCS</referenceUID></etaTE><xsiLE><xsi>0.7</xsi><referenceUID>RectCS</referenceUID>"
               "</xsiLE>")
    volume, _ = built_volume(flap_with_outer_border(tmp_path, oblique, "oblique"), "Flap")

    def integrand(x):
        xi = (x - 1.0) / 2.0
        return 0.6 * xi * (1.0 - xi) * (1.5 - (x - 2.4) / 0.6)

    n = 2000  # Simpson's rule on a cubic: exact
    h = 0.6 / n
    expected = h / 3 * sum((1 if k in (0, n) else 4 if k % 2 else 2) * integrand(2.4 + k * h) for k in range(n + 1))
    assert volume == pytest.approx(expected, rel=1e-5)


def border(tag, eta_le, eta_te, *xsis, rel_height=None):
    etas = f"<etaLE><eta>{eta_le}</eta></etaLE><etaTE><eta>{eta_te}</eta></etaTE>"
    named = "".join(f"<{name}><xsi>{xsi}</xsi></{name}>" for name, xsi in xsis)
    height = f"<relHeightLE>{rel_height}</relHeightLE>" if rel_height is not None else ""
    return f"<{tag}>{etas}{named}{height}</{tag}>"


def test_devices_on_a_blended_wing_body_of_many_sections_are_valid_solids(tmp_path):
    # On the 55 sections of a thick blended wing body the skins' split curves leave an oblique
    # border's plane (and a spoiler's outer one) by more than their tolerance; the solids made
    # from the skins were flawed there ("invalid curve on surface"), the Boolean cut is not. The
    # inboard flap's outer border runs inboard (etaTE < etaLE), and its outline closed 5 chords
    # along its chord passed the inner border's plane: the ruled cutter crossed itself and cut
    # nothing out of the wing.
    path = shared_path("data", "cpacs", "component-segment-bwb.xml")
    with open(path) as original:
        text = original.read()
    flap = border("innerBorder", 0.273, 0.308, ("xsiLE", 0.727)) + border("outerBorder", 0.458, 0.458, ("xsiLE", 0.635))
    spoiler = (border("innerBorder", 0.82, 0.82, ("xsiLE", 0.691), ("xsiTE", 0.791), rel_height=0.85) +
               border("outerBorder", 0.946, 0.946, ("xsiLE", 0.488), ("xsiTE", 0.588), rel_height=0.45))
    inboard = border("innerBorder", 0.691, 0.691, ("xsiLE", 0.848)) + border("outerBorder", 0.728, 0.712, ("xsiLE", 0.819))
    devices = (f'<controlSurfaces><trailingEdgeDevices><trailingEdgeDevice uID="Flap"><name>f</name>'
               f'<parentUID>BWB_CST_wing_CS</parentUID><outerShape>{flap}</outerShape>{steps(0, 1)}'
               f'</trailingEdgeDevice><trailingEdgeDevice uID="Inboard"><name>i</name>'
               f'<parentUID>BWB_CST_wing_CS</parentUID><outerShape>{inboard}</outerShape>{steps(0, 1)}'
               f'</trailingEdgeDevice></trailingEdgeDevices><spoilers><spoiler uID="Spoiler"><name>s</name>'
               f'<parentUID>BWB_CST_wing_CS</parentUID><outerShape>{spoiler}</outerShape>{steps(0, 1)}</spoiler>'
               f'</spoilers></controlSurfaces></componentSegment>')
    bwb = tmp_path / "bwb-devices.xml"
    bwb.write_text(text.replace("</componentSegment>", devices, 1))
    built = airshape("build", str(bwb))
    assert built.returncode == 0, built.stdout + built.stderr
    for uid in ("Flap", "Inboard", "Spoiler"):
        assert re.search(rf"control_surface +{uid} +valid solid", built.stdout), built.stdout


# Two slats of a generator on the example airliner: a hollow back at the inner border, a straight
# back at the outer one, their figures as written (rounded, the exact Boolean succeeds).
SLATS = {
    "no solid": ((0.7948988431668046, 0.25401747542327247, 0.765937739088508, 0.5917854534663782),
                 (0.996922652492971, 0.20161098797951943), "left faces it could not place and made no solid"),
    "flawed solid": ((0.23018927943563355, 0.10043895259306589, 0.4969488736638346, 0.36322918552907835),
                     (0.5138875299380804, 0.11399368115195978), "made a flawed solid"),
}


@pytest.mark.parametrize("case", sorted(SLATS))
def test_a_slat_whose_exact_boolean_cut_failed_is_cut_with_a_fuzzy_tolerance(tmp_path, case):
    # OCCT's exact Boolean left faces it could not place and made no solid (the outer border near
    # the tip), or made a solid with a self-intersecting wire; with its fuzzy tolerance it cuts a
    # valid solid, between the slat with two straight backs and the one with two hollow ones,
    # and says so in one warning naming the device and what the exact cut did.
    (inner_eta, inner_xsi, height, middle), (outer_eta, outer_xsi), what = SLATS[case]
    hollow = f"<innerShape><relHeightTE>{height}</relHeightTE><xsiTE>{middle}</xsiTE></innerShape>"

    def slat_volume(inner, outer, name):
        borders = (f"<innerBorder><etaLE><eta>{inner_eta}</eta></etaLE><xsiTE><xsi>{inner_xsi}</xsi></xsiTE>{inner}"
                   f"</innerBorder><outerBorder><etaLE><eta>{outer_eta}</eta></etaLE><xsiTE><xsi>{outer_xsi}</xsi>"
                   f"</xsiTE>{outer}</outerBorder>")
        slat = (f'<leadingEdgeDevices><leadingEdgeDevice uID="Slat"><name>s</name><parentUID>Wing_CS</parentUID>'
                f'<outerShape>{borders}</outerShape>{steps(0, 1)}</leadingEdgeDevice></leadingEdgeDevices>')
        return built_volume(airliner_with(tmp_path, slat, name), "Slat")

    straight, _ = slat_volume("", "", "straight")
    both, _ = slat_volume(hollow, hollow, "both")
    mixed, warnings = slat_volume(hollow, "", "mixed")
    assert both < mixed < straight, (both, mixed, straight)
    fuzzy = [line for line in warnings.splitlines() if "fuzzy tolerance" in line]
    assert len(fuzzy) == 1 and "leadingEdgeDevice[1]/outerShape: cut out of its wing" in fuzzy[0], warnings
    assert fuzzy[0].endswith("without it OCCT's Boolean " + what), fuzzy[0]


def test_a_device_outside_its_wing_is_one_line(tmp_path):
    with open(WITH_DEVICES) as original:
        text = original.read()
    start = text.index('<spoiler uID="Spoiler">')
    end = text.index("</outerShape>", start)
    # The spoiler's lower side above the upper skin: its outline cuts nothing out of the wing.
    shape = text[start:end].replace("<relHeightLE>0.5</relHeightLE>", "<relHeightLE>1.5</relHeightLE>")
    path = tmp_path / "outside.xml"
    path.write_text(text[:start] + shape + text[end:])
    answer = json.loads(airshape("query", str(path), stdin=json.dumps({"op": "component_volume", "uid": "Spoiler"}) +
                                 "\n").stdout)
    assert answer["error"].endswith("spoiler[1]/outerShape: the device's outline cuts nothing out of its wing")


@pytest.mark.parametrize("etas,xsis", [((0.3, 0.6), (0.65, 1.0)), ((0.3, 0.6), (0.0, 0.3)), ((0.0, 0.3), (0.5, 0.65))])
def test_a_spoiler_at_the_wings_edges_and_root_is_the_upper_half_there(tmp_path, etas, xsis):
    # A spoiler reaching the trailing edge (the line there touches the wing in one point), one
    # from the leading edge, and one at the root (its border in the root's cap): the upper half
    # of the wing between its xsi over its span, in closed form.
    with open(WITH_DEVICES) as original:
        text = original.read()
    start = text.index('<spoiler uID="Spoiler">')
    end = text.index("</outerShape>", start)
    shape = text[start:end]
    values = {"<eta>0.3</eta>": etas[0], "<eta>0.6</eta>": etas[1], "<xsi>0.5</xsi>": xsis[0], "<xsi>0.65</xsi>": xsis[1]}
    shape = re.sub("|".join(values), lambda m: re.sub(r">.*<", f">{values[m.group(0)]}<", m.group(0)), shape)
    path = tmp_path / "spoiler.xml"
    path.write_text(text[:start] + shape + text[end:])
    answer = json.loads(airshape("query", str(path), stdin=json.dumps({"op": "component_volume", "uid": "Spoiler"}) +
                                 "\n").stdout)
    span = 5.0 * (etas[1] - etas[0])
    assert answer["ok"] == pytest.approx(span * (section_area_aft(xsis[0]) - section_area_aft(xsis[1])) / 2, rel=1e-5)


def test_a_spoiler_from_a_dihedral_wings_root_to_its_trailing_edge_is_a_valid_solid(tmp_path):
    # The example airliner's wing has dihedral: the spoiler's inner border plane (at eta 0) leans
    # out through the root's cap above the chord, where its line meets the wing on the chord
    # line; the wire was closed at no height above it and no solid joined the borders.
    borders = "".join(f"<{tag}><etaLE><eta>{eta}</eta></etaLE><xsiLE><xsi>0.8</xsi></xsiLE><xsiTE><xsi>1.0</xsi></xsiTE>"
                      f"</{tag}>" for tag, eta in (("innerBorder", 0.0), ("outerBorder", 0.2)))
    spoiler = (f'<spoilers><spoiler uID="Spoiler"><name>s</name><parentUID>Wing_CS</parentUID>'
               f'<outerShape>{borders}</outerShape>{steps(0, 1)}</spoiler></spoilers>')
    built_volume(airliner_with(tmp_path, spoiler, "root-spoiler"), "Spoiler")


def test_borders_that_cross_inside_the_wing_are_one_line(tmp_path):
    # The flap's outer border from (eta 0.5, xsi 0.7) to (eta 0.1, xsi 1) crosses its inner border
    # (eta 0.2 from xsi 0.7 to 1) at eta 0.2, xsi 0.925.
    crossing = ("<outerBorder><etaLE><eta>0.5</eta></etaLE><etaTE><eta>0.1</eta></etaTE><xsiLE><xsi>0.7</xsi></xsiLE>")
    built = airshape("build", str(flap_with_outer_border(tmp_path, crossing, "crossing")))
    assert built.returncode == 1
    assert re.search(r"Flap +FAILED: \S+trailingEdgeDevice\[1\]/outerShape: the inner and the outer border cross inside "
                     r"the wing \(at component segment eta 0.2, xsi 0.925\)", built.stdout), built.stdout
    assert re.search(r"Slat +valid solid", built.stdout), "the other devices build"


def test_a_step_value_that_is_not_finite_is_one_line_naming_it(tmp_path):
    with open(WITH_DEVICES) as original:
        text = original.read()
    path = tmp_path / "nan-step.xml"
    path.write_text(text.replace("<hingeLineRotation>-20</hingeLineRotation>", "<hingeLineRotation>nan</hingeLineRotation>",
                                 1).replace("<controlParameter>1</controlParameter>",
                                            "<controlParameter>inf</controlParameter>", 2))
    queries = [{"op": "control_surface_deflection", "uid": "Slat", "control_parameter": 0.5},
               {"op": "control_surface_parameter_range", "uid": "Flap"}]
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    slat, flap = (json.loads(line) for line in result.stdout.splitlines())
    assert slat["error"].endswith("leadingEdgeDevice[1]/path/steps/step[2]/controlParameter: not a finite number (NaN or INF)")
    assert flap["error"].endswith("/path/steps/step[2]/controlParameter: not a finite number (NaN or INF)")
    path.write_text(text.replace("<hingeLineRotation>-20</hingeLineRotation>", "<hingeLineRotation>nan</hingeLineRotation>",
                                 1))
    result = airshape("query", str(path), stdin=json.dumps(queries[0]) + "\n")
    assert json.loads(result.stdout)["error"].endswith(
        "leadingEdgeDevice[1]/path/steps/step[2]/hingeLineRotation: not a finite number (NaN or INF)")


def test_control_surface_conformance_does_not_regress():
    passed, output = conformance_passed("cases-controlsurfaces.json")
    # 1 of 233 does not pass yet: one aileron's area (docs/controlsurfaces.md). This floor
    # guards what works.
    assert passed >= 232, output[-3000:]
