"""The Python module `airshape`: opening, pythonic wings and fuselages, vectorised points,
editing with incremental rebuilds, saving, exporting, errors, threads."""
import json
import math
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

import airshape
from conftest import AIRLINER, BUILD, SOURCE


@pytest.fixture
def config():
    return airshape.Configuration.open(AIRLINER)


def cli_answers(path, *queries):
    binary = os.path.join(BUILD, "bin", "airshape")
    result = subprocess.run([binary, "query", path], input="".join(json.dumps(q) + "\n" for q in queries),
                            capture_output=True, text=True, check=True)
    return [json.loads(line)["ok"] for line in result.stdout.splitlines()]


def test_components_answer_as_the_query_service_does(config):
    assert [wing.uid for wing in config.wings] == ["Wing", "HTP", "VTP"]
    assert [f.uid for f in config.fuselages] == ["Fuselage"]
    wing, fuselage = config.wings["Wing"], config.fuselages[0]
    volume, area, point, fpoint, span = cli_answers(
        AIRLINER, {"op": "wing_volume", "wing": "Wing"}, {"op": "wing_reference_area", "wing": 1, "plane": "x-y"},
        {"op": "wing_upper_point", "wing": 1, "segment": 2, "eta": 0.3, "xsi": 0.6},
        {"op": "fuselage_point", "fuselage": 1, "segment": 3, "eta": 0.5, "zeta": 0.1},
        {"op": "wing_span", "wing": 1})
    assert wing.volume == volume
    assert wing.reference_area("x-y") == area
    assert wing.upper_point(2, 0.3, 0.6).tolist() == point
    assert fuselage.point(3, 0.5, 0.1).tolist() == fpoint
    assert wing.span == span
    assert wing.symmetry == "x-z" and wing.segment_count == 2 and wing.section_count == 3
    assert config.query("wing_mac", wing="Wing") == wing.mac


def test_points_are_vectorised(config):
    wing = config.wings[0]
    eta = np.linspace(0, 1, 7)
    xsi = np.linspace(0.1, 0.9, 7)
    points = wing.points("lower", 1, eta, xsi)
    assert points.shape == (7, 3)
    for k in range(7):
        assert points[k].tolist() == wing.lower_point(1, eta[k], xsi[k]).tolist()
    ring = config.fuselages[0].points(4, 0.5, np.linspace(0, 1, 5))  # a scalar eta broadcasts
    assert ring.shape == (5, 3)
    assert ring[0].tolist() == pytest.approx(ring[-1].tolist(), abs=1e-9)  # zeta 0 and 1 meet


def test_editing_rebuilds_only_the_edited_wing(config):
    wing, fuselage, htp = config.wings["Wing"], config.fuselages[0], config.wings["HTP"]
    before = (wing.volume, fuselage.volume, htp.volume)
    tip = wing.sections[2].elements[0].transformation.scaling
    assert float(tip.x) == pytest.approx(1.6)
    tip.x = 2.4
    assert tip.x.value == 2.4
    assert wing.volume > before[0]
    assert (fuselage.volume, htp.volume) == before[1:]
    builds = config.cache_statistics()["builds_by_key"]
    assert builds["wing-shape:Wing"] == 2
    assert builds["fuselage-geometry:Fuselage"] == 1
    assert builds["wing-shape:HTP"] == 1
    # The same edit by XPath, and a read back.
    xpath = "/cpacs/vehicles/aircraft/model/wings/wing[@uID='Wing']/sections/section[3]/elements/element/transformation/scaling/x"
    config.set(xpath, 1.6)
    assert config.value(xpath) == "1.6"
    assert wing.volume == pytest.approx(before[0], rel=1e-12)


def test_sections_and_segments_are_removed_and_added(config):
    wing = config.wings["Wing"]
    volume, fuselage_volume = wing.volume, config.fuselages[0].volume
    # The wing box runs to the tip section: it goes first and comes back last.
    boxes = config.node("/cpacs/vehicles/aircraft/model/wings/wing[@uID='Wing']").componentSegments
    box = boxes[0].xml
    boxes[0].remove()
    outer = wing.segments[1], wing.positionings[2], wing.sections[2]
    saved = [node.xml for node in outer]
    with pytest.raises(airshape.ArgumentError):  # the outer segment still refers to it
        wing.sections[2].remove()
    for node in outer:
        node.remove()
    assert (wing.segment_count, wing.section_count) == (1, 2)
    assert wing.volume < volume
    wing.sections.append(saved[2])
    wing.positionings.append(saved[1])
    wing.segments.append(saved[0])
    assert (wing.segment_count, wing.section_count) == (2, 3)
    boxes.append(box)
    assert len(wing.component_segments) == 1
    assert wing.volume == pytest.approx(volume, rel=1e-12)
    inner, outer = wing.component_segments[0].fuel_tanks
    assert (inner.uid, inner.type) == ("Wing_InnerTank", "tank")
    assert 0 < inner.volume < outer.volume < wing.volume
    assert config.fuselages[0].volume == fuselage_volume
    assert config.cache_statistics()["builds_by_key"]["fuselage-geometry:Fuselage"] == 1


def test_a_refused_edit_raises_with_the_path_and_changes_nothing(config):
    node = config.wings["Wing"].sections[0].elements[0].transformation.scaling
    with pytest.raises(airshape.ArgumentError) as refused:
        node.x = "wide"
    assert "scaling/x" in refused.value.cpacs_path
    assert float(node.x) == pytest.approx(7.2)
    with pytest.raises(airshape.ArgumentError):
        config.wings["Wing"].sections[7]
    with pytest.raises(airshape.ArgumentError):
        config.set("/cpacs/vehicles/aircraft/model/wings/wing[9]/name", "x")


def test_errors_are_airshape_errors(tmp_path):
    with pytest.raises(airshape.FileError) as missing:
        airshape.Configuration.open(tmp_path / "missing.xml")
    assert missing.value.file.endswith("missing.xml")
    with pytest.raises(airshape.FileError):
        airshape.Configuration.from_string("<cpacs>", "broken")
    config = airshape.Configuration.open(AIRLINER)
    with pytest.raises(airshape.ArgumentError):
        config.wings[0].upper_point(1, 1.5, 0.3)
    with pytest.raises(airshape.WriteError):
        config.export(tmp_path / "no" / "folder" / "x.step")
    assert issubclass(airshape.WriteError, airshape.Error)


def test_save_and_export_after_an_edit(config, tmp_path):
    config.wings["HTP"].sections[1].elements[0].transformation.scaling.x = 1.8
    config.save(tmp_path / "edited.xml")
    reopened = airshape.Configuration.open(tmp_path / "edited.xml")
    assert reopened.wings["HTP"].volume == pytest.approx(config.wings["HTP"].volume, rel=1e-12)
    config.export(tmp_path / "htp.step", components=["HTP"])
    assert "PRODUCT('HTP'" in (tmp_path / "htp.step").read_text()
    # The browser page (docs/viewer.md) carries the edited tail and its measures.
    config.export(tmp_path / "htp.html", components=["HTP"], mirror=True)
    page = (tmp_path / "htp.html").read_text()
    assert '"name":"HTP (mirrored)"' in page and '"type":"wing"' in page


def test_configurations_work_from_several_threads():
    results, errors = {}, []

    def run(name):
        try:
            config = airshape.Configuration.open(AIRLINER)
            results[name] = config.wings["Wing"].points("upper", 1, np.linspace(0, 1, 50), 0.5)
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert not errors
    for k in range(1, 4):
        assert np.array_equal(results[k], results[0])


def test_the_example_sweep_rebuilds_only_the_wing():
    script = os.path.join(SOURCE, "examples", "python", "tip_chord_sweep.py")
    output = subprocess.run([sys.executable, script], capture_output=True, text=True, check=True,
                            env=os.environ).stdout
    lines = output.splitlines()
    rows = [line.split() for line in lines if len(line.split()) == 4 and line.split()[0][0].isdigit()]
    assert len(rows) == 50
    volumes = [float(row[1]) for row in rows]
    assert volumes == sorted(volumes) and volumes[0] < volumes[-1]  # a longer tip chord, a larger wing
    assert "fuselage-geometry:Fuselage       built 1 time" in output
    assert "wing-shape:Wing                  built 50 times" in output


def test_installs_with_cmake(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", BUILD, "--prefix", str(prefix)], check=True, capture_output=True)
    package = prefix / "lib" / "python3" / "dist-packages"
    code = ("import airshape; c = airshape.Configuration.open(%r); print(c.wings[0].uid, airshape.__file__)"
            % AIRLINER)
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            env={"PATH": os.environ["PATH"], "PYTHONPATH": str(package)})
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("Wing ") and str(prefix) in result.stdout


WITH_DEVICES = os.path.join(SOURCE, "tests", "data", "wing-cst-devices.xml")


def test_control_surfaces_of_a_wing(tmp_path):
    config = airshape.Configuration.open(WITH_DEVICES)
    wing = config.wings["Rect"]
    assert [device.uid for device in wing.control_surfaces] == ["Flap", "Tab", "Slat"]
    assert [device.uid for device in wing.spoilers] == ["Spoiler"]
    flap = wing.control_surfaces["Flap"]
    assert flap.type == "trailing_edge_device" and wing.spoilers[0].type == "spoiler"
    assert flap.parameter_range == (0, 1)
    motion = flap.deflection(1.0)
    assert motion["rotation"] == pytest.approx(20) and motion["matrix"].shape == (3, 4)
    # Aft of xsi 0.7 of parabolic arcs on a chord of 2, over 3 m of span (closed form).
    at_rest = 3.0 * 0.3 * 4 * (1 / 6 - 0.49 / 2 + 0.343 / 3)
    assert flap.volume() == pytest.approx(at_rest, rel=1e-6) and flap.volume(0.5) == pytest.approx(at_rest, rel=1e-7)
    assert flap.bounding_box(1.0)["min"][2] < flap.bounding_box()["min"][2]
    with pytest.raises(airshape.ArgumentError, match="outside the range"):
        flap.deflection(3.0)
    with pytest.raises(airshape.ArgumentError, match="has no control surface 'Spoiler'"):
        wing.control_surfaces["Spoiler"]

    deflected = tmp_path / "deflected.brep"
    config.export(str(deflected), components=["Rect"], deflect={"Flap": 1.0, "Slat": "max"})
    assert deflected.stat().st_size > 0
    with pytest.raises(airshape.ArgumentError, match="names no moving component"):
        config.export(str(tmp_path / "bad.brep"), deflect={"Rect": 1})


def test_a_further_deflected_export_reuses_the_wings_cut_until_an_edit(tmp_path):
    # The cut-outs lie where the devices are at rest: the wing's cut is made once for any
    # deflections, the same file comes out whatever was exported before, and an edit forgets it.
    config = airshape.Configuration.open(WITH_DEVICES)
    def cuts():
        return sum(count for key, count in config.cache_statistics()["builds_by_key"].items()
                   if key.startswith("cut-outs of Rect"))
    config.export(str(tmp_path / "max.brep"), components=["Rect"], deflect={"all": "max"})
    config.export(str(tmp_path / "min.brep"), components=["Rect"], deflect={"all": "min"})
    assert cuts() == 1
    fresh = airshape.Configuration.open(WITH_DEVICES)
    fresh.export(str(tmp_path / "min-fresh.brep"), components=["Rect"], deflect={"all": "min"})
    assert (tmp_path / "min.brep").read_bytes() == (tmp_path / "min-fresh.brep").read_bytes()
    config.set("/cpacs/vehicles/aircraft/model/wings/wing[@uID='Rect']/componentSegments/componentSegment/controlSurfaces"
               "/trailingEdgeDevices/trailingEdgeDevice[@uID='Flap']/outerShape/innerBorder/xsiLE/xsi", 0.65)
    config.export(str(tmp_path / "edited.brep"), components=["Rect"], deflect={"all": "min"})
    assert cuts() == 2


WITH_STRUCTURE = os.path.join(SOURCE, "tests", "data", "wing-cst-structure.xml")


def test_structure_of_a_flap(tmp_path):
    # A spar of the flap at its own xsi 0.5 (x 2.7 on the test wing), from its inner to its outer
    # border (y 1 to 4).
    positions = "".join(f'<sparPosition uID="P{eta}"><sparPositionEtaXsi><eta>{eta}</eta><xsi>0.5</xsi>'
                        f"<referenceUID>Flap</referenceUID></sparPositionEtaXsi></sparPosition>" for eta in (0, 1))
    structure = (f"<structure><spars><sparPositions>{positions}</sparPositions><sparSegments>"
                 '<sparSegment uID="FlapSpar"><name>s</name><sparPositionUIDs><sparPositionUID>P0</sparPositionUID>'
                 "<sparPositionUID>P1</sparPositionUID></sparPositionUIDs></sparSegment></sparSegments></spars>"
                 "</structure>")
    with open(WITH_DEVICES) as original:
        text = original.read()
    at = text.index("<path>", text.index('<trailingEdgeDevice uID="Flap">'))
    path = tmp_path / "flap.xml"
    path.write_text(text[:at] + structure + text[at:])
    flap = airshape.Configuration.open(str(path)).wings[0].control_surfaces["Flap"]
    spar, = flap.spars
    assert spar.uid == "FlapSpar" and spar.type == "wing_spar" and flap.ribs == [] and flap.cells == []
    assert spar.bounding_box["min"][0] == pytest.approx(2.7, abs=1e-5)
    assert spar.surface_area == pytest.approx(3 * 0.6 * 0.85 * 0.15, rel=1e-5)


def test_structure_of_a_component_segment(tmp_path):
    config = airshape.Configuration.open(WITH_STRUCTURE)
    segment, = config.wings["Rect"].component_segments
    assert segment.uid == "RectCS" and segment.type == "wing_component_segment"
    assert [spar.uid for spar in segment.spars] == ["Front", "Rear"]
    assert [ribs.uid for ribs in segment.ribs] == ["Ribs"] and [c.uid for c in segment.cells] == ["UpperCell"]
    front = segment.spars[0]
    # A plane web at ξ 0.2 over the 5 m span, 0.6·ξ(1−ξ) high.
    assert front.type == "wing_spar" and front.volume == 0
    assert front.surface_area == pytest.approx(5 * 0.6 * 0.2 * 0.8, rel=1e-7)
    assert front.bounding_box["min"][0] == pytest.approx(1.4, abs=1e-6)
    assert config.component("Ribs").type == "wing_rib"
    web = tmp_path / "front.brep"
    front.export(str(web))
    assert web.stat().st_size > 0
    with pytest.raises(airshape.ArgumentError, match="no component with uID 'Nowhere'"):
        config.component("Nowhere")
    model = tmp_path / "wing_box.brep"
    config.export(str(model), structure=True)
    assert model.stat().st_size > web.stat().st_size


def test_structure_of_a_fuselage(tmp_path):
    config = airshape.Configuration.open(AIRLINER)
    kinds = {element.uid: element.type for element in config.fuselages[0].structure}
    assert kinds["Cargo_Door"] == "cargo_door" and kinds["Rear_Bulkhead"] == "pressure_bulkhead"
    assert kinds["Stringer_Side"] == "stringer" and kinds["Frame_Door_Front"] == "frame"
    door = config.component("Cargo_Door")
    # The skin between the frames at x = 7 and 9, on the −y side below the stringer at 90°.
    assert door.volume == 0 and door.surface_area > 0
    assert door.bounding_box["min"][0] == pytest.approx(7, abs=1e-6)
    assert door.bounding_box["max"][0] == pytest.approx(9, abs=1e-6) and door.bounding_box["max"][1] < 0
    assert config.component("Stringer_Side").surface_area == 0
    # Exported with its Z profile swept along it: the three sheets' surfaces, not a line.
    lines, swept = tmp_path / "lines.brep", tmp_path / "swept.brep"
    config.export(str(lines), components=["Frame_Door_Front"])
    config.export(str(swept), components=["Frame_Door_Front"], profiles=True)
    assert swept.stat().st_size > 3 * lines.stat().st_size


def test_rotors_of_a_rotorcraft():
    # Rectangular blades, chord 0.3, from 0.5 m to 4.5 m off the hub (tests/cli/test_rotor.py).
    config = airshape.Configuration.open(os.path.join(SOURCE, "tests", "data", "rotorcraft-two-blades.xml"))
    assert [rotor.uid for rotor in config.rotors] == ["Main", "Clockwise", "Orphan"]
    main = config.rotors["Main"]
    assert main.type == "rotor" and main.blade_count == 2
    radius = math.hypot(0.3 / 4, 4.5)
    assert main.radius == pytest.approx(radius, rel=1e-9)
    assert main.solidity == pytest.approx(main.total_blade_planform_area / (math.pi * radius ** 2), rel=1e-12)
    assert main.tip_speed == pytest.approx(10 * math.pi * radius, rel=1e-9)
    assert main.volume == pytest.approx(2 * 0.05 * 0.09 * 4, rel=1e-6)
    assert isinstance(config.component("Clockwise"), airshape.Rotor)
    with pytest.raises(airshape.ModelError, match="rotorBladeUID"):
        config.rotors["Orphan"].radius


def test_engines_and_pylons_as_components():
    config = airshape.Configuration.open(os.path.join(SOURCE, "tests", "data", "wing-with-engines.xml"))
    engines = {engine.uid: engine for engine in config.engines}
    pylons = {pylon.uid: pylon for pylon in config.pylons}
    assert sorted(engines) == ["Chevron", "High", "Hollow", "Lofted", "Low", "Spun"] and sorted(pylons) == ["Bare", "Pylon"]
    # The tapered pylon: chord 1 to 3 over 2 m of the parabolic airfoil (area 0.05 c²).
    assert pylons["Pylon"].volume == pytest.approx(0.05 * 26 / 3, rel=1e-9)
    assert engines["Low"].type == "engine_nacelle" and engines["Low"].volume > 0
    with pytest.raises(airshape.ModelError, match="has no nacelle"):
        engines["Hollow"].volume


def test_every_family_of_the_example_as_components(config):
    tanks, ducts = config.tanks, config.ducts
    assert [tank.uid for tank in tanks] == ["CentreTank", "Wing_InnerTank", "Wing_OuterTank"]
    # The centre tank: a cylinder of radius 0.6 and length 2.4 between half ellipsoids 0.3 deep.
    assert tanks[0].volume == pytest.approx(math.pi * 0.36 * 2.4 + 4 / 3 * math.pi * 0.36 * 0.3, rel=1e-6)
    assert sorted(duct.uid for duct in ducts) == ["APU_Ducts", "APU_Exhaust"]
    assert ducts[0].volume == pytest.approx(ducts[1].volume, rel=1e-9)  # the assembly of the one duct
    # Cargo cross beams have the reference library's type, generic_system.
    assert [system.uid for system in config.systems] == ["Cargo_Floor_Beam_Front", "Cargo_Floor_Beam_Rear"]
    assert config.decks == [] and config.external_objects == []
