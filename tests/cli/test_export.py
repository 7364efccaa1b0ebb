"""`airshape export`: every format reopens in a reader that is not ours, names survive,
volumes agree, triangulations are closed, and a file that cannot be written is a clear
error that leaves nothing behind. Also the fused aircraft and `intersection_curves`."""
import json
import math
import os
import re

import pytest

from conftest import EXAMPLE, SOURCE, airshape, query_answers, shared_path
from independent_readers import (admesh_report, gltf_report, gmsh_volumes, stl_volume, vtk_line_lengths, vtk_obj_counts,
                                 vtk_polydata)

AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
FORMATS = ("step", "iges", "brep", "stl", "vtp", "glb", "gltf", "obj")


def source_file(name):
    return AIRLINER if name == "generic-airliner.xml" else shared_path("data", "cpacs", name)


def export(source, folder, *options, formats=FORMATS):
    """Exports to every format in one run; returns the paths and the summary's exact volume
    of each solid, by name."""
    paths = {f: os.path.join(folder, f"out.{f}") for f in formats}
    arguments = [a for f in formats for a in ("-o", paths[f])]
    result = airshape("export", source, *arguments, *options)
    assert result.returncode == 0, result.stderr
    summary = result.stdout.split("area [m2]\n", 1)[1].split("total time")[0]
    volumes = {}
    for line in summary.strip().splitlines():
        name, volume, _area = line.rsplit(None, 2)
        volumes[name.strip()] = float(volume)
    return paths, volumes


@pytest.mark.parametrize("name", ["generic-airliner.xml", "CPACS_30_D150.xml", "D150WithGuides.xml",
                                  "simpletest.cpacs.xml"])
def test_every_format_reopens_with_names_and_volumes(tmp_path, name):
    paths, volumes = export(source_file(name), tmp_path)
    uids = set(volumes)

    # BREP is OCCT's own dump of the solids in memory: gmsh's volumes of it stand for ours.
    brep = gmsh_volumes(paths["brep"])
    assert len(brep) == len(uids)
    in_memory = [volume for _, volume in brep]
    # gmsh measures with OCCT's fixed Gauss rule per face (not per knot span, not adaptive):
    # up to a few percent off the exact volumes on wing skins whatever file the solid came
    # from, so the exact volumes are only compared loosely; the file-to-file checks below
    # compare like with like.
    for measured, exact in zip(in_memory, volumes.values()):
        assert measured == pytest.approx(exact, rel=0.05)

    # STEP: one product per component named by its uID, face names as STEP names, and the
    # same solids as in memory.
    step = gmsh_volumes(paths["step"])
    assert [entity.rsplit("/", 1)[-1] for entity, _ in step] == list(volumes)
    for (_, volume), memory in zip(step, in_memory):
        assert volume == pytest.approx(memory, rel=1e-6)
    text = open(paths["step"]).read()
    assert set(re.findall(r"PRODUCT\('([^']*)'", text)) == uids | {os.path.splitext(os.path.basename(name))[0]}
    assert re.search(r"ADVANCED_FACE\('[^']+/(upper|skin)'", text)

    iges = gmsh_volumes(paths["iges"])
    assert len(iges) == len(uids)
    # IGES labels each manifold solid (entity 186, the second line of its directory entry)
    # with the component's name, cut to the format's 8 characters.
    entries = re.findall(r"^ {5}186.{48}(.{8}).{8}D(\d{7})$", open(paths["iges"]).read(), re.M)
    labels = [label.strip() for label, number in entries if int(number) % 2 == 0]
    assert sorted(labels) == sorted(uid[:8] for uid in uids)
    for (_, volume), memory in zip(iges, in_memory):
        assert volume == pytest.approx(memory, rel=1e-6)

    # STL: closed, and its enclosed volume within 1 % of the exact one.
    report = admesh_report(paths["stl"])
    assert report["disconnected"] == [0, 0, 0], report
    enclosed, _ = stl_volume(paths["stl"])
    assert enclosed == pytest.approx(sum(volumes.values()), rel=0.01)

    polydata = vtk_polydata(paths["vtp"])
    assert polydata["cells"] > 0
    assert set(polydata["arrays"]["component"]) == uids
    assert all(face.split("/")[0] for face in polydata["arrays"]["face"])

    for gltf in (paths["glb"], paths["gltf"]):
        report = gltf_report(gltf)
        assert (report["errors"], report["warnings"]) == (0, 0), report
    nodes = {node.get("name") for node in json.load(open(paths["gltf"]))["nodes"]}
    assert uids <= nodes

    groups = re.findall(r"^g .*/(.+)$", open(paths["obj"]).read(), re.M)
    assert set(groups) == uids


def test_lines_go_to_vtk_polydata_gltf_and_obj_and_stl_says_it_leaves_them_out(tmp_path):
    # The front door frame is the fuselage's circle of radius 2 at x = 7; the side stringer
    # runs along the skin. In VTK PolyData both are polylines named by their uIDs, the frame's
    # a little shorter than its circle (chords).
    lines = ["Frame_Door_Front", "Stringer_Side"]
    vtp = tmp_path / "lines.vtp"
    result = airshape("export", AIRLINER, "--components", ",".join(lines), "-q", "-o", str(vtp))
    assert result.returncode == 0, result.stderr
    lengths = vtk_line_lengths(vtp)
    assert sorted(lengths) == lines
    assert 4 * math.pi * (1 - 1e-3) < lengths["Frame_Door_Front"] <= 4 * math.pi + 1e-9
    assert lengths["Stringer_Side"] > 20

    # glTF holds them as LINE_STRIP primitives of their components' nodes, with the solids'
    # triangles or alone; the validator finds nothing wrong.
    for name, components in (("lines", lines), ("mixed", ["Wing"] + lines)):
        gltf = tmp_path / f"{name}.gltf"
        result = airshape("export", AIRLINER, "--components", ",".join(components), "-q", "-o", str(gltf),
                          "-o", str(tmp_path / f"{name}.glb"))
        assert result.returncode == 0, result.stderr
        for path in (gltf, tmp_path / f"{name}.glb"):
            report = gltf_report(path)
            assert (report["errors"], report["warnings"]) == (0, 0), report
        document = json.load(open(gltf))
        meshes = {node["name"]: document["meshes"][node["mesh"]] for node in document["nodes"] if "mesh" in node}
        assert set(meshes) == set(components)
        for uid in lines:
            assert {primitive["mode"] for primitive in meshes[uid]["primitives"]} == {3}

    # OBJ holds them as `l` records in groups of their own, after the solids' triangles.
    obj = tmp_path / "mixed.obj"
    assert airshape("export", AIRLINER, "--components", ",".join(["Wing"] + lines), "-q", "-o", str(obj)).returncode == 0
    counts = vtk_obj_counts(obj)
    assert counts["triangles"] > 0 and counts["lines"] >= 2, counts
    assert set(re.findall(r"^g .*/(.+)$", open(obj).read(), re.M)) == {"Wing"} | set(lines)

    # STL holds triangles only: lines alone are a clear error and no file, lines among solids
    # a note naming them.
    stl = tmp_path / "lines.stl"
    result = airshape("export", AIRLINER, "--components", ",".join(lines), "-q", "-o", str(stl))
    assert result.returncode == 2
    assert "STL holds triangles only" in result.stderr and ".vtp" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not stl.exists()
    result = airshape("export", AIRLINER, "--components", ",".join(["Wing"] + lines), "-o", str(stl))
    assert result.returncode == 0, result.stderr
    note = re.search(f"{re.escape(str(stl))} leaves out (.+): lines, which STL cannot hold", result.stderr)
    assert note and sorted(note.group(1).split(", ")) == sorted(lines), result.stderr  # in document order
    assert stl_volume(stl)[1] > 0


def test_mirrored_halves_and_chosen_components(tmp_path):
    _, volumes = export(AIRLINER, tmp_path, "--mirror", "--components", "Wing,VTP", formats=("brep",))
    assert list(volumes) == ["Wing", "Wing (mirrored)", "VTP"]
    assert volumes["Wing (mirrored)"] == pytest.approx(volumes["Wing"], rel=1e-12)


def test_fused_aircraft_keeps_face_names(tmp_path):
    paths, volumes = export(AIRLINER, tmp_path, "--fused", "--mirror", formats=("step", "stl", "vtp"))
    (name, fused), = volumes.items()
    _, separate = export(AIRLINER, tmp_path / ".." / tmp_path.name, "--mirror", "--force", formats=("brep",))
    assert name == "generic-airliner (fused)"
    # The union is smaller than the sum (the wings' roots lie inside the fuselage) and larger
    # than its largest part.
    assert separate["Fuselage"] < fused < sum(separate.values())
    step = gmsh_volumes(paths["step"])
    assert len(step) == 1
    faces = set(vtk_polydata(paths["vtp"])["arrays"]["face"])
    assert {"Fus_Seg4/skin", "Wing_Seg2/upper", "Wing_Seg2/upper (mirrored)", "VTP_Seg1/lower", "HTP/tip"} <= faces
    assert "Wing/root" not in faces  # inside the fuselage: gone in the union
    assert admesh_report(paths["stl"])["disconnected"] == [0, 0, 0]


def test_triangulation_follows_the_deflection(tmp_path):
    (tmp_path / "coarse").mkdir()
    (tmp_path / "fine").mkdir()
    coarse, volumes = export(AIRLINER, tmp_path / "coarse", "--components", "Wing", "--deflection", "0.02,0.5",
                             formats=("stl",))
    fine, _ = export(AIRLINER, tmp_path / "fine", "--components", "Wing", "--deflection", "0.001,0.1",
                     formats=("stl",))
    coarse_volume, coarse_count = stl_volume(coarse["stl"])
    fine_volume, fine_count = stl_volume(fine["stl"])
    assert fine_count > 2 * coarse_count
    assert abs(fine_volume - volumes["Wing"]) < abs(coarse_volume - volumes["Wing"])


def test_intersection_curves_of_wing_and_fuselage(tmp_path):
    # The small example aircraft with every fuselage section a circle of radius 1: its
    # fuselage is the cylinder y² + z² = 1 (up to the 25-point profile's interpolation,
    # 3e-5), which the wing's root pierces.
    cylinder = tmp_path / "cylinder.xml"
    text = open(EXAMPLE).read()
    cylinder.write_text(re.sub(r"<y>0\.[46]</y><z>0\.[46]</z>", "<y>2.0</y><z>2.0</z>", text))
    curves, mirrored = query_answers(cylinder, {"op": "intersection_curves", "uid": "Fuselage", "other": "MainWing",
                                                "deflection": 1e-3},
                                     {"op": "intersection_curves", "uid": "Fuselage", "other": "MainWing",
                                      "other_mirrored": True})
    for loops, side in ((curves, 1), (mirrored, -1)):
        assert len(loops) == 1
        junction = loops[0]
        assert len(junction) > 20
        assert junction[0] == pytest.approx(junction[-1], abs=1e-6)  # a closed loop round the wing root
        for x, y, z in junction:
            assert 9 - 1e-6 <= x <= 14 + math.tan(math.radians(25))  # root chord, swept out to |y| < 1
            assert side * y > 0
            assert math.hypot(y, z) == pytest.approx(1.0, abs=1e-4)
    apart, = query_answers(AIRLINER, {"op": "intersection_curves", "uid": "HTP", "other": "Wing"})
    assert apart == []


def test_unwritable_outputs_are_clear_errors_and_leave_nothing(tmp_path):
    missing = airshape("export", AIRLINER, "-o", str(tmp_path / "no" / "such" / "folder" / "x.step"))
    assert missing.returncode == 2
    assert "x.step" in missing.stderr and "does not exist" in missing.stderr

    existing = tmp_path / "taken.stl"
    existing.write_text("keep me")
    refused = airshape("export", AIRLINER, "-o", str(existing))
    assert refused.returncode == 2 and "--force" in refused.stderr
    assert existing.read_text() == "keep me"

    unknown = airshape("export", AIRLINER, "-o", str(tmp_path / "x.dwg"))
    assert unknown.returncode == 2 and ".dwg" in unknown.stderr

    nobody = airshape("export", AIRLINER, "--components", "Nobody", "-o", str(tmp_path / "x.step"))
    assert nobody.returncode == 2 and "Nobody" in nobody.stderr

    a_folder = tmp_path / "folder.step"
    a_folder.mkdir()
    over_folder = airshape("export", AIRLINER, "--force", "-o", str(a_folder))
    assert over_folder.returncode == 2 and "folder" in over_folder.stderr

    assert sorted(os.listdir(tmp_path)) == ["folder.step", "taken.stl"]  # no temporary left behind


def test_components_that_fail_are_left_out_and_said(tmp_path):
    source = shared_path("data", "cpacs", "multiple_wings.xml")
    result = airshape("export", source, "-o", str(tmp_path / "wings.step"), "--quiet")
    assert result.returncode == 1  # written, with problems
    assert "left out W13_EmptyWing: the wing has no segments" in result.stderr
    assert (tmp_path / "wings.step").exists()
    named = airshape("export", source, "--components", "W13_EmptyWing", "-o", str(tmp_path / "empty.step"))
    assert named.returncode == 1 and "W13_EmptyWing" in named.stderr  # a component failed: 1, as in build
    assert "no file written" in named.stderr
    assert not (tmp_path / "empty.step").exists()


def test_sliver_faces_are_triangulated_and_the_mesh_stays_closed(tmp_path):
    # crm.xml's fuselage ends in a rear cap 0.8 mm high and 1.2 m wide, which the mesher
    # leaves empty at the default deflection; the component is meshed again, finer.
    source = shared_path("data", "cpacs", "crm.xml")
    paths, volumes = export(source, tmp_path, "--components", "NASA_CRM_fuselage1", formats=("stl",))
    assert admesh_report(paths["stl"])["disconnected"] == [0, 0, 0]
    assert stl_volume(paths["stl"])[0] == pytest.approx(volumes["NASA_CRM_fuselage1"], rel=0.01)
