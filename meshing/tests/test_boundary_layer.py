"""Prism layers of `airshape mesh --boundary-layer COUNT,FIRST[,GROWTH]` under the fluid's
tetrahedra: as many prisms as layers times wall triangles, the first layer as high as asked,
every cell positive (read back from VTK's node order by meshio), the layers' sides in
the symmetry plane, and OpenFOAM's tools take the mesh and solve on it."""
import os
import re
import sys

import numpy
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "cli"))
from conftest import SOURCE, airshape, shared_path  # noqa: E402
from mesh_readers import meshio_mesh  # noqa: E402
from openfoam_case import boundary_patches, make_case, run  # noqa: E402

AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
LAYERS, FIRST, GROWTH = 3, 0.002, 1.3


@pytest.fixture(scope="module")
def layered(tmp_path_factory):
    folder = tmp_path_factory.mktemp("layered")
    result = airshape("mesh", AIRLINER, "--farfield", "2L", "--symmetry", "--size", "1.5", "--boundary-layer",
                      f"{LAYERS},{FIRST},{GROWTH}", "-o", str(folder / "half.msh"), "-o", str(folder / "half.vtu"),
                      "-o", str(folder / "half.su2"), "-o", str(folder / "half.inp"))
    assert result.returncode == 0, result.stderr
    points, cells, mesh = meshio_mesh(folder / "half.vtu")
    return folder, result, points, cells, mesh


def cells_of_group(mesh, kind, *names):
    """The cells of one kind whose group is one of `names` (or, without names, any but the
    far field's and the symmetry plane's)."""
    boundary = {int(mesh.field_data[f"group:{name}"][0]) for name in ("farfield", "symmetry")
                if f"group:{name}" in mesh.field_data}
    wanted = {int(mesh.field_data[f"group:{name}"][0]) for name in names}
    chosen = [block.data[numpy.isin(tags, list(wanted)) if names else ~numpy.isin(tags, list(boundary))]
              for block, tags in zip(mesh.cells, mesh.cell_data["group"]) if block.type == kind]
    return numpy.vstack(chosen) if chosen else numpy.zeros((0, 3), dtype=int)


def test_a_prism_per_layer_over_every_wall_triangle(layered):
    _, result, _, cells, mesh = layered
    walls = cells_of_group(mesh, "triangle")
    assert len(walls) > 1000 and len(cells["wedge"]) == LAYERS * len(walls)
    summary = result.stdout.strip().splitlines()[-1]
    assert f"{LAYERS * len(walls):,} prisms" in summary, summary


def test_the_first_layer_is_as_high_as_asked(layered):
    _, _, points, cells, mesh = layered
    wall_nodes = numpy.unique(cells_of_group(mesh, "triangle"))
    wedges = cells["wedge"]
    first = wedges[numpy.isin(wedges[:, :3], wall_nodes).all(axis=1)]
    assert len(first) == len(cells_of_group(mesh, "triangle"))
    heights = numpy.linalg.norm(points[first[:, 3:]] - points[first[:, :3]], axis=2).ravel()
    # At least the height over a node's triangles (more where the wall bends), at most twice;
    # thinner only where the wall's elements are short or fold (said in a note).
    assert FIRST <= numpy.median(heights) <= 1.1 * FIRST
    assert heights.min() > 0 and heights.max() <= 2 * FIRST * (1 + 1e-9)


def test_every_prism_and_tetrahedron_is_positive(layered):
    _, _, points, cells, _ = layered
    wedges = points[cells["wedge"]]
    # Our .vtu writes VTK's order (a wedge's base turned away from its top); meshio reads it
    # back into Gmsh's order, the base's normal towards the top.
    for corner in range(3):
        base = wedges[:, corner]
        normal = numpy.cross(wedges[:, (corner + 1) % 3] - base, wedges[:, (corner + 2) % 3] - base)
        assert (numpy.einsum("ij,ij->i", normal, wedges[:, corner + 3] - base) > 0).all()
        top = wedges[:, corner + 3]
        normal = numpy.cross(wedges[:, 3 + (corner + 1) % 3] - top, wedges[:, 3 + (corner + 2) % 3] - top)
        assert (numpy.einsum("ij,ij->i", normal, top - base) > 0).all()
    a, b, c, d = (points[cells["tetra"][:, i]] for i in range(4))
    assert (numpy.einsum("ij,ij->i", b - a, numpy.cross(c - a, d - a)) > 0).all()


def test_the_layers_sides_stand_in_the_symmetry_plane(layered):
    _, _, points, _, mesh = layered
    sides = cells_of_group(mesh, "quad", "symmetry")
    assert len(sides) > 0 and len(sides) % LAYERS == 0
    assert numpy.abs(points[sides][:, :, 1]).max() < 1e-12
    assert points[:, 1].min() > -1e-9


@pytest.mark.parametrize("extension", ["su2", "inp"])
def test_su2_and_abaqus_hold_the_same_cells(layered, extension):
    folder, _, points, cells, _ = layered
    import meshio
    read = meshio.read(folder / f"half.{extension}")
    counts = {}
    for block in read.cells:
        counts[block.type] = counts.get(block.type, 0) + len(block.data)
    assert counts.get("wedge") == len(cells["wedge"]) and counts.get("tetra") == len(cells["tetra"])
    wedges = numpy.vstack([block.data for block in read.cells if block.type == "wedge"])
    corner = read.points[wedges]  # as the file has them: meshio turns neither
    normal = numpy.cross(corner[:, 1] - corner[:, 0], corner[:, 2] - corner[:, 0])
    rise = numpy.einsum("ij,ij->i", normal, corner[:, 3] - corner[:, 0])
    # SU2 numbers a prism as VTK does (the base's normal away from the top), Abaqus as Gmsh does.
    assert (rise < 0).all() if extension == "su2" else (rise > 0).all()


def test_openfoam_takes_the_layers_and_solves(layered, tmp_path):
    folder, _, _, _, _ = layered
    case = tmp_path / "case"
    converted = make_case(case, folder / "half.msh", ["farfield"])
    assert converted.returncode == 0, converted.stdout[-2000:] + converted.stderr
    assert {"farfield", "symmetry", "Fuselage", "Wing", "HTP", "VTP"} <= set(boundary_patches(case))
    checked = run("checkMesh", case).stdout
    # Thin prisms are meant to be flat (checkMesh flags aspect ratios over 1000 and the skew
    # side faces at sharp edges, docs/meshing.md); the cells themselves must be sound.
    for sound in ("Boundary definition OK", "Cell to face addressing OK", "Number of regions: 1 (OK)",
                  "Point usage OK", "Face pyramids OK", "Cell volumes OK", "Face area magnitudes OK"):
        assert sound in checked, sound + "\n" + checked[-3000:]
    assert re.search(r"Boundary openness .* OK", checked) and re.search(r"Max cell openness = .* OK", checked)
    solved = run("potentialFoam", case)
    finals = [float(r) for r in re.findall(r"Solving for Phi, .*Final residual = ([\d.e+-]+)", solved.stdout)]
    assert solved.returncode == 0 and finals and finals[-1] < 1e-6, solved.stdout[-2000:]


def test_a_whole_domain_without_symmetry(tmp_path):
    mesh = tmp_path / "whole.vtu"
    result = airshape("mesh", AIRLINER, "--farfield", "sphere:1L", "--size", "1.5", "--boundary-layer", "2,0.001",
                      "-o", str(mesh))
    assert result.returncode == 0, result.stderr
    points, cells, read = meshio_mesh(mesh)
    assert len(cells["wedge"]) == 2 * len(cells_of_group(read, "triangle")) and "quad" not in cells
    assert points[:, 1].min() < -1


@pytest.mark.parametrize("value, said", [("3", "COUNT,FIRST_HEIGHT"), ("2.5,0.001", "whole number"),
                                         ("3,0.001,0.9", "GROWTH is at least 1"), ("3,-1", "FIRST_HEIGHT")])
def test_a_malformed_layer_is_refused_in_one_line(value, said, tmp_path):
    result = airshape("mesh", AIRLINER, "--boundary-layer", value, "-o", str(tmp_path / "x.msh"))
    assert result.returncode != 0 and said in result.stderr and len(result.stderr.strip().splitlines()) == 1, \
        result.stderr
    assert not (tmp_path / "x.msh").exists()


def test_a_wall_the_layer_cannot_rise_from_is_named(tmp_path):
    # Coarse elements on the engine's pylon fold the wall onto itself at the junction.
    result = airshape("mesh", AIRLINER, "--farfield", "sphere:1L", "--size", "2", "--boundary-layer", "3,0.002",
                      "-o", str(tmp_path / "x.msh"))
    assert result.returncode != 0 and re.search(r"cannot rise from the wall at \(.*\)", result.stderr), result.stderr
    assert not (tmp_path / "x.msh").exists()


def test_d150_half_domain_with_layers_passes_openfoams_cell_checks(tmp_path):
    # D150's wing root and tail are concave and close: the layer's top would cross itself there
    # (Gmsh refused the fluid) until it is thinned where it does.
    d150 = shared_path("data", "cpacs", "CPACS_30_D150.xml")
    mesh = tmp_path / "d150.msh"
    result = airshape("mesh", d150, "--farfield", "20L", "--symmetry", "--boundary-layer", "4,0.001", "-o", str(mesh))
    assert result.returncode == 0, result.stderr[-2000:]
    assert "thinner than asked at" in result.stderr
    case = tmp_path / "case"
    # gmshToFoam's own inside-out test turns one thin, twisted prism of this mesh whose Jacobian is
    # positive at every corner; -keepOrientation keeps the elements as written (docs/meshing.md).
    assert make_case(case, mesh, ["farfield"], keep_orientation=True).returncode == 0
    checked = run("checkMesh", case).stdout
    for sound in ("Boundary definition OK", "Cell to face addressing OK", "Number of regions: 1 (OK)",
                  "Face pyramids OK", "Cell volumes OK"):
        assert sound in checked, sound + "\n" + checked[-3000:]
    assert "Open cells found" not in checked, checked[-3000:]  # said with the aspect ratios, when they fail
