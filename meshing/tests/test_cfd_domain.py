"""CFD domains of `airshape mesh --farfield` checked by a real solver's tools: OpenFOAM's
gmshToFoam takes the .msh as written, checkMesh reports it OK, its patches are named farfield,
symmetry and by uID, and potentialFoam converges on it."""
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


@pytest.fixture(scope="module")
def half_domain(tmp_path_factory):
    folder = tmp_path_factory.mktemp("half")
    mesh = folder / "half.msh"
    result = airshape("mesh", AIRLINER, "--farfield", "2L", "--symmetry", "--size", "1.5", "-o", str(mesh),
                      "-o", str(folder / "half.vtu"))
    assert result.returncode == 0, result.stderr
    return folder, mesh, result


def test_summary_counts_tetrahedra(half_domain):
    _, _, result = half_domain
    assert re.match(r"fluid: [\d,]+ nodes, [\d,]+ triangles, [\d,]+ tetrahedra, worst quality 0\.\d+",
                    result.stdout.strip().splitlines()[-1]), result.stdout


def test_openfoam_takes_the_mesh_and_checkmesh_says_ok(half_domain, tmp_path):
    _, mesh, _ = half_domain
    case = tmp_path / "case"
    converted = make_case(case, mesh, ["farfield"])
    assert converted.returncode == 0, converted.stdout[-2000:] + converted.stderr
    patches = boundary_patches(case)
    assert {"farfield", "symmetry", "Fuselage", "Wing", "HTP", "VTP"} <= set(patches), patches
    assert "defaultFaces" not in patches or patches["defaultFaces"] == 0
    checked = run("checkMesh", case)
    assert "Mesh OK." in checked.stdout, checked.stdout[-3000:]
    solved = run("potentialFoam", case, "-writePhi")
    assert solved.returncode == 0, solved.stdout[-2000:] + solved.stderr
    residuals = [float(r) for r in re.findall(r"Solving for Phi, Initial residual = ([\d.e+-]+)", solved.stdout)]
    finals = [float(r) for r in re.findall(r"Solving for Phi, .*Final residual = ([\d.e+-]+)", solved.stdout)]
    assert residuals and finals[-1] < 1e-6 and finals[-1] < residuals[0] * 1e-3, solved.stdout[-2000:]
    potential = (case / "0" / "Phi").read_text()
    values = numpy.array([float(v) for v in re.search(r"internalField\s+nonuniform List<scalar>\s*\d+\s*\(([^)]*)\)",
                                                       potential).group(1).split()])
    assert numpy.isfinite(values).all() and numpy.ptp(values) > 0


def test_symmetry_plane_lies_at_y_zero_and_the_fluid_above_it(half_domain):
    folder, _, _ = half_domain
    points, cells, mesh = meshio_mesh(folder / "half.vtu")
    group = mesh.cell_data["group"]
    symmetry = int(mesh.field_data["group:symmetry"][0])
    triangles = numpy.vstack([block.data for block, tags in zip(mesh.cells, group) if block.type == "triangle"])
    tags = numpy.concatenate([tags for block, tags in zip(mesh.cells, group) if block.type == "triangle"])
    on_plane = points[numpy.unique(triangles[tags == symmetry])]
    assert len(on_plane) > 100 and numpy.abs(on_plane[:, 1]).max() < 1e-9
    assert points[:, 1].min() > -1e-9
    tetrahedra = cells["tetra"]
    a, b, c, d = (points[tetrahedra[:, i]] for i in range(4))
    assert (numpy.einsum("ij,ij->i", b - a, numpy.cross(c - a, d - a)) > 0).all()


def test_a_sphere_around_the_whole_aircraft(tmp_path):
    mesh = tmp_path / "sphere.msh"
    result = airshape("mesh", AIRLINER, "--farfield", "sphere:1L", "--size", "2", "-o", str(mesh))
    assert result.returncode == 0, result.stderr
    case = tmp_path / "case"
    assert make_case(case, mesh, ["farfield"]).returncode == 0
    assert "symmetry" not in boundary_patches(case)
    assert "Mesh OK." in run("checkMesh", case).stdout


def test_d150_half_domain_passes_checkmesh(tmp_path):
    mesh = tmp_path / "d150.msh"
    result = airshape("mesh", shared_path("data", "cpacs", "CPACS_30_D150.xml"), "--farfield", "20L", "--symmetry",
                      "-o", str(mesh))
    assert result.returncode == 0, result.stderr
    case = tmp_path / "case"
    assert make_case(case, mesh, ["farfield"]).returncode == 0
    assert {"farfield", "symmetry", "D150_VAMP_FL1", "D150_VAMP_W1", "D150_VAMP_HL1", "D150_VAMP_SL1"} <= set(
        boundary_patches(case))
    assert "Mesh OK." in run("checkMesh", case).stdout
