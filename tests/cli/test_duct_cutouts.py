"""Duct cut-outs, opt-in: the duct assemblies cut out of the wings and fuselages they pass
through, from the command line, the query service and Python. A file of our own, where what is
cut has a closed form in the ducts' own measures: a pipe along the axis of a cylindrical hull
and longer than it (the hull loses the pipe's cross-section times its length, and gains the
pipe's wall as skin), and a tunnel lying wholly inside a wing (the wing loses the tunnel's
volume and gains its whole surface as the cavity's walls)."""
import json
import math
import os
import re
import subprocess

from conftest import BUILD, DATA, airshape, query_answers as ask
from independent_readers import gmsh_volumes

with open(os.path.join(DATA, "wing-cst-rectangular.xml")) as source:
    WINGS = source.read()


def circle(count=64):
    angles = [2 * math.pi * i / count for i in range(count + 1)]
    return (f"<pointList><x>{';'.join('0' for _ in angles)}</x>"
            f"<y>{';'.join(f'{math.sin(a):.17g}' for a in angles)}</y>"
            f"<z>{';'.join(f'{math.cos(a):.17g}' for a in angles)}</z></pointList>")


def body(kind, uid, stations, radius, placement=""):
    """A fuselage or duct of circles of `radius` at x = stations, placed by `placement`."""
    scaling = f"<scaling><x>1</x><y>{radius}</y><z>{radius}</z></scaling>"
    sections = "".join(
        f'<section uID="{uid}S{i}"><name>s</name><transformation><translation><x>{x}</x></translation>'
        f'</transformation><elements><element uID="{uid}E{i}"><name>e</name><profileUID>Circle</profileUID>'
        f"<transformation>{scaling}</transformation></element></elements></section>" for i, x in enumerate(stations))
    segments = "".join(f'<segment uID="{uid}G{i}"><name>g</name><fromElementUID>{uid}E{i}</fromElementUID>'
                       f"<toElementUID>{uid}E{i + 1}</toElementUID></segment>" for i in range(len(stations) - 1))
    return (f'<{kind} uID="{uid}"><name>b</name><transformation>{placement}</transformation>'
            f"<sections>{sections}</sections><segments>{segments}</segments></{kind}>")


ABOVE = "<translation><x>0</x><y>0</y><z>5</z></translation>"  # the hull lies clear of the wings
# Spanwise in the wing Rect (chord 2 from x = 1, 0.15 thick at mid-chord): along y from 1 to 4.
SPANWISE = "<rotation><x>0</x><y>0</y><z>90</z></rotation><translation><x>2</x><y>1</y><z>0</z></translation>"
ACROSS = "<rotation><x>0</x><y>0</y><z>90</z></rotation><translation><x>5</x><y>-3</y><z>5</z></translation>"
DUCTS = ("<ducts>" + body("duct", "Pipe", [-1, 5, 11], 0.25, ABOVE) + body("duct", "Tunnel", [0, 3], 0.03, SPANWISE) +
         body("duct", "Cross", [0, 6], 0.2, ACROSS) +
         '<ductAssembly uID="Ducts"><name>a</name><ductUIDs><uID>Pipe</uID><uID>Tunnel</uID></ductUIDs></ductAssembly>'
         '<ductAssembly uID="Crossing"><name>a</name><excludeObjectUIDs><uID>Hull</uID></excludeObjectUIDs>'
         "<ductUIDs><uID>Cross</uID></ductUIDs></ductAssembly></ducts>")


def write(path):
    # The swept wing is moved aft of everything else: no duct reaches it.
    swept = "<name>swept, tapered, dihedral, twist</name>\n            <transformation/>"
    assert swept in WINGS
    text = WINGS.replace(swept, swept.replace("<transformation/>", "<transformation><translation><x>20</x>"
                                              "</translation></transformation>"))
    text = text.replace("</wings>", "</wings><fuselages>" + body("fuselage", "Hull", [0, 5, 10], 1.0, ABOVE) +
                         "</fuselages>" + DUCTS)
    text = text.replace("</wingAirfoils>", "</wingAirfoils><fuselageProfiles><fuselageProfile uID=\"Circle\">"
                        f"<name>c</name>{circle()}</fuselageProfile></fuselageProfiles>")
    path.write_text(text)
    return path


MEASURES = [{"op": "fuselage_volume", "fuselage": "Hull"}, {"op": "fuselage_surface_area", "fuselage": "Hull"},
            {"op": "wing_volume", "wing": "Rect"}, {"op": "wing_surface_area", "wing": "Rect"},
            {"op": "component_volume", "uid": "Hull"}, {"op": "wing_volume", "wing": "Swept"}]


def test_the_cut_outs_are_off_by_default_and_take_out_what_the_ducts_hold(tmp_path):
    path = write(tmp_path / "ducts.xml")
    pipe_section, pipe_area, tunnel_volume, tunnel_area = ask(
        path, {"op": "cross_section_area", "uid": "Pipe", "point": [5, 0, 5], "normal": [1, 0, 0]},
        {"op": "component_surface_area", "uid": "Pipe"}, {"op": "component_volume", "uid": "Tunnel"},
        {"op": "component_surface_area", "uid": "Tunnel"})
    pipe_wall_per_metre = (pipe_area - 2 * pipe_section) / 12  # the pipe is 12 long, its caps pipe_section each
    clean = ask(path, *MEASURES)
    assert math.isclose(clean[0], math.pi * 10, rel_tol=1e-4)  # the whole hull: nothing cut by default
    assert math.isclose(clean[4], clean[0], rel_tol=1e-12)
    lines = "".join(json.dumps(q) + "\n" for q in [{"op": "set_option", "name": "duct_cutouts", "on": True}] + MEASURES +
                    [{"op": "set_option", "name": "duct_cutouts", "on": False}] + MEASURES[:1])
    answers = [json.loads(line) for line in airshape("query", str(path), stdin=lines).stdout.splitlines()]
    assert answers[0] == {"ok": {"name": "duct_cutouts", "on": True, "was": False}}, answers[0]
    cut = [answer["ok"] for answer in answers[1:7]]
    assert math.isclose(cut[0], clean[0] - 10 * pipe_section, rel_tol=1e-9), (cut[0], clean[0], pipe_section)
    assert math.isclose(cut[1], clean[1] + 10 * pipe_wall_per_metre, rel_tol=1e-7), (cut[1], clean[1])
    assert math.isclose(cut[2], clean[2] - tunnel_volume, rel_tol=1e-9), (cut[2], clean[2], tunnel_volume)
    assert math.isclose(cut[3], clean[3] + tunnel_area, rel_tol=1e-7), (cut[3], clean[3], tunnel_area)
    assert math.isclose(cut[4], cut[0], rel_tol=1e-12)  # component ops measure the same solid
    assert cut[5] == clean[5]  # no duct reaches the swept wing
    # Crossing passes through the hull, but names it in its excludeObjectUIDs: the hull keeps its
    # inside there (the pipe alone accounts for what it lost).
    assert answers[7]["ok"]["was"] is True and answers[8] == {"ok": clean[0]}  # off again: the clean hull
    # The flag on the command line does the same for the whole session.
    flagged = airshape("query", str(path), "--duct-cutouts", stdin=json.dumps(MEASURES[0]) + "\n")
    assert json.loads(flagged.stdout) == {"ok": cut[0]}, flagged.stdout + flagged.stderr


def test_an_unknown_option_is_refused_with_the_known_ones(tmp_path):
    path = write(tmp_path / "ducts.xml")
    answer = airshape("query", str(path), stdin='{"op":"set_option","name":"duct_cutout","on":true}\n')
    assert "no build option 'duct_cutout' (the loaded plugins declare duct_cutouts)" in json.loads(answer.stdout)["error"]
    bad = airshape("build", str(path), "--duct-cutout")
    assert bad.returncode == 2 and "--duct-cutout" in bad.stderr


def volumes_of(stdout):
    """The volumes `build` prints, by uID."""
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^\s+\S+\s+(\S+)\s+valid solid, volume (\S+),", stdout,
                                                              re.MULTILINE)}


def test_build_and_export_cut_with_the_flag(tmp_path):
    path = write(tmp_path / "ducts.xml")
    plain, flagged = airshape("build", str(path)), airshape("build", str(path), "--duct-cutouts")
    assert plain.returncode == 0 and flagged.returncode == 0, flagged.stdout + flagged.stderr
    before, after = volumes_of(plain.stdout), volumes_of(flagged.stdout)
    assert after["Hull"] < before["Hull"] - 1.9 and after["Rect"] < before["Rect"] - 0.008, (before, after)
    assert after["Swept"] == before["Swept"] and after["Pipe"] == before["Pipe"]
    step = tmp_path / "hull.step"
    exported = airshape("export", str(path), "--duct-cutouts", "--components", "Hull", "-o", str(step))
    assert exported.returncode == 0, exported.stderr
    [(_, volume)] = gmsh_volumes(step)  # read back by an independent reader, in the unit STEP declares
    queried = airshape("query", str(path), "--duct-cutouts", stdin=json.dumps(MEASURES[0]) + "\n")
    # gmsh integrates with OCCT's fixed Gauss rule per face: close, not exact.
    assert math.isclose(volume, json.loads(queried.stdout)["ok"], rel_tol=1e-5), (volume, queried.stdout)


def test_python_turns_the_cut_outs_on_and_off(tmp_path):
    path = write(tmp_path / "ducts.xml")
    script = f"""
import airshape
config = airshape.Configuration.open({str(path)!r})
assert config.duct_cutouts is False and config.options() == {{"duct_cutouts": False}}
clean = config.fuselages["Hull"].volume
config.duct_cutouts = True
cut = config.fuselages["Hull"].volume
config.duct_cutouts = False
print(clean, cut, config.fuselages["Hull"].volume)
"""
    result = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True, text=True,
                            env={**os.environ, "PYTHONPATH": os.path.join(BUILD, "python")})
    assert result.returncode == 0, result.stderr
    clean, cut, again = (float(word) for word in result.stdout.split())
    assert cut < clean - 1.9 and again == clean
