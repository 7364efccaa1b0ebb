"""Configuration.mesh (docs/meshing.md): the same meshes as `airshape mesh`, from Python, with
the report as a dict; bad options are the binding's exceptions."""
import os

import meshio
import numpy
import pytest

import airshape

SOURCE = os.environ.get("AIRSHAPE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")


@pytest.fixture(scope="module")
def config():
    return airshape.Configuration.open(AIRLINER)


def test_mesh_writes_the_file_and_reports_it(config, tmp_path):
    path = tmp_path / "tail.vtu"
    report = config.mesh(path, components=["HTP", "VTP"], size=1.0, sizes={"VTP": 0.3})
    assert report["failures"] == [] and report["meshes"][0]["name"] == "surface"
    mesh = meshio.read(str(path))
    triangles = numpy.vstack([block.data for block in mesh.cells if block.type == "triangle"])
    assert report["meshes"][0]["elements"]["triangles"] == len(triangles)
    assert {"group:HTP", "group:VTP"} <= set(mesh.field_data)


def test_structure_shells_of_order_two(config, tmp_path):
    report = config.mesh(tmp_path / "wing.inp", structure=True, components=["Wing"], size=0.5, order=2)
    assert "quadrilaterals (8 nodes)" in report["meshes"][0]["elements"]
    assert "TYPE=S8" in (tmp_path / "wing.inp").read_text()


def test_bad_options_raise(config, tmp_path):
    with pytest.raises(airshape.ArgumentError):
        config.mesh(tmp_path / "a.cgns")
    with pytest.raises(airshape.ArgumentError):
        config.mesh(tmp_path / "a.msh", farfield="cube:3L")
    assert not os.listdir(tmp_path)


def test_boundary_layer_from_python(config, tmp_path):
    path = tmp_path / "htp.vtu"
    report = config.mesh(path, components=["HTP"], size=0.5, farfield="sphere:1L", boundary_layer=(2, 0.001, 1.5))
    elements = report["meshes"][0]["elements"]
    mesh = meshio.read(str(path))
    walls = sum(int((group == mesh.field_data["group:HTP"][0]).sum())
                for block, group in zip(mesh.cells, mesh.cell_data["group"]) if block.type == "triangle")
    assert walls > 0 and elements["prisms"] == 2 * walls
    with pytest.raises(airshape.ArgumentError):
        config.mesh(tmp_path / "b.msh", farfield="1L", boundary_layer=(2.5, 0.001))
