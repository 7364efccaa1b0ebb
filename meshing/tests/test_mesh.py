"""`airshape mesh` (docs/meshing.md): surface meshes written in every format and read back by
independent readers (closed, enclosed volume within 0.5 % of the exact solid's, a group per
component), CFD domains that OpenFOAM's own tools accept and solve on, and clear refusals."""
import os
import re
import sys

import numpy
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "cli"))
from conftest import SOURCE, airshape  # noqa: E402
from independent_readers import admesh_report, stl_volume  # noqa: E402
from mesh_readers import edge_use, enclosed_volume, gmsh_groups, meshio_mesh  # noqa: E402

AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
FORMATS = ("msh", "su2", "vtu", "inp", "stl")


def exact_volume(path, *options):
    """The fused solid's volume from `airshape export --fused` (OCCT's exact integration)."""
    result = airshape("export", path, "--fused", "-o", os.devnull + ".brep", "--force", *options)
    line = [line for line in result.stdout.splitlines() if "(fused)" in line][0]
    return float(line.split()[-2])


def components_of(path):
    """The uIDs `airshape build` builds as components on their own (not parts, not inside others)."""
    result = airshape("export", path, "-o", os.devnull + ".stl", "--force")
    table = result.stdout.splitlines()
    return {line.split()[0] for line in table[1:] if not line.startswith("total")}


@pytest.fixture(scope="module")
def airliner_surface(tmp_path_factory):
    folder = tmp_path_factory.mktemp("surface")
    paths = {fmt: folder / f"airliner.{fmt}" for fmt in FORMATS}
    outputs = [arg for fmt in FORMATS for arg in ("-o", str(paths[fmt]))]
    result = airshape("mesh", AIRLINER, *outputs)
    assert result.returncode == 0, result.stderr
    return paths, result


def test_summary_line_says_nodes_elements_quality_and_time(airliner_surface):
    _, result = airliner_surface
    summary = result.stdout.strip().splitlines()[-1]
    match = re.match(r"surface: ([\d,]+) nodes, ([\d,]+) triangles, worst quality ([\d.]+), ([\d.]+) s", summary)
    assert match, summary
    assert 0 < float(match.group(3)) <= 1


@pytest.mark.parametrize("fmt", ["su2", "vtu", "inp"])
def test_surface_is_closed_and_encloses_the_solid_volume(airliner_surface, fmt):
    paths, _ = airliner_surface
    points, cells, _ = meshio_mesh(paths[fmt])
    triangles = cells["triangle"]
    if fmt == "su2":  # meshio lists the markers' triangles after the mesh's own
        triangles = triangles[: len(triangles) // 3]
    free, nonmanifold = edge_use(triangles)
    assert (free, nonmanifold) == (0, 0)
    exact = exact_volume(AIRLINER)
    assert enclosed_volume(points, triangles) == pytest.approx(exact, rel=5e-3)


def test_stl_is_closed_with_the_same_volume(airliner_surface):
    paths, _ = airliner_surface
    report = admesh_report(paths["stl"])
    assert report["disconnected"] == [0, 0, 0] and report["parts"] == 1
    volume, _ = stl_volume(paths["stl"])
    assert volume == pytest.approx(exact_volume(AIRLINER), rel=5e-3)


def test_every_component_has_a_group_with_elements(airliner_surface):
    paths, _ = airliner_surface
    wanted = components_of(AIRLINER) - {"CentreTank"}  # inside the fuselage and wing: no surface of its own
    groups = gmsh_groups(paths["msh"])
    assert wanted <= set(groups), sorted(wanted - set(groups))
    assert all(groups[uid] == [2, groups[uid][1]] and groups[uid][1] > 0 for uid in wanted)
    assert groups["Wing_Seg1/upper"][1] > 0  # named faces have groups of their own
    _, _, inp = meshio_mesh(paths["inp"])
    assert {uid for uid in wanted} <= set(inp.cell_sets)
    assert all(sum(len(block) for block in inp.cell_sets[uid]) > 0 for uid in wanted)


def test_mirrored_halves_join_their_components_group(tmp_path):
    path = tmp_path / "mirrored.vtu"
    result = airshape("mesh", AIRLINER, "--mirror", "--size", "2", "-o", str(path))
    assert result.returncode == 0, result.stderr
    points, cells, mesh = meshio_mesh(path)
    wing = int(mesh.field_data["group:Wing"][0])
    group = mesh.cell_data["group"][0]
    wing_points = points[numpy.unique(cells["triangle"][group == wing])]
    assert wing_points[:, 1].min() < -5 and wing_points[:, 1].max() > 5  # both halves, one group
    assert edge_use(cells["triangle"]) == (0, 0)


def test_a_components_size_makes_its_surface_finer(tmp_path):
    coarse, fine = tmp_path / "coarse.vtu", tmp_path / "fine.vtu"
    coarsely = ("--size", "2", "--curvature", "6")  # sizes by curvature would refine the tail anyway
    assert airshape("mesh", AIRLINER, *coarsely, "-o", str(coarse)).returncode == 0
    result = airshape("mesh", AIRLINER, *coarsely, "--size", "VTP=0.1", "-o", str(fine))
    assert result.returncode == 0, result.stderr

    def count(path, uid):
        _, cells, mesh = meshio_mesh(path)
        return int((mesh.cell_data["group"][0] == int(mesh.field_data[f"group:{uid}"][0])).sum())

    assert count(fine, "VTP") > 3 * count(coarse, "VTP")
    assert count(fine, "Wing") == pytest.approx(count(coarse, "Wing"), rel=0.2)


def test_bad_requests_are_one_line_errors_and_write_nothing(tmp_path):
    cgns = airshape("mesh", AIRLINER, "-o", str(tmp_path / "a.cgns"))
    assert cgns.returncode == 2 and "without CGNS" in cgns.stderr and len(cgns.stderr.splitlines()) == 1
    unknown = airshape("mesh", AIRLINER, "--size", "Nothing=0.1", "-o", str(tmp_path / "a.msh"))
    assert unknown.returncode == 2 and "'Nothing'" in unknown.stderr
    existing = tmp_path / "exists.msh"
    existing.write_text("keep me")
    refused = airshape("mesh", AIRLINER, "-o", str(existing))
    assert refused.returncode == 2 and "--force" in refused.stderr and existing.read_text() == "keep me"
    farfield = airshape("mesh", AIRLINER, "--farfield", "cube:3L", "-o", str(tmp_path / "b.msh"))
    assert farfield.returncode == 2 and "box or sphere" in farfield.stderr
    assert sorted(os.listdir(tmp_path)) == ["exists.msh"]


def test_a_component_that_cannot_be_built_is_said_with_its_path_and_the_rest_meshed(tmp_path):
    source = tmp_path / "with-empty-wing.xml"
    text = open(AIRLINER).read()
    at = text.index("</wings>")
    source.write_text(text[:at] + '<wing uID="EmptyWing"><name>e</name><transformation/><sections/><segments/></wing>'
                      + text[at:])
    result = airshape("mesh", str(source), "--size", "3", "-o", str(tmp_path / "rest.vtu"))
    assert result.returncode == 1
    failed = [line for line in result.stderr.splitlines() if line.startswith("mesh: failed:")]
    assert len(failed) == 1 and "EmptyWing" in failed[0] and "/cpacs/vehicles/aircraft/model" in failed[0], failed
    _, _, mesh = meshio_mesh(tmp_path / "rest.vtu")
    assert {"group:Wing", "group:Fuselage"} <= set(mesh.field_data)
