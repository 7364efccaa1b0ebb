"""Reopens exported files with readers that are not ours: gmsh (STEP, IGES, BREP), VTK
(.vtp), admesh (STL) and the Khronos gltf-validator (glTF/GLB). Each runs in a process of
its own. scripts/test.sh installs them; a missing one fails the test that needs it."""
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

from conftest import BUILD

GMSH_VOLUMES = """
import json, sys, gmsh
gmsh.initialize(["-noenv"])
gmsh.option.setNumber("General.Terminal", 0)
# gmsh converts STEP and IGES into millimetres; STEP can be kept in metres, IGES cannot (gmsh
# refuses the option for it), so IGES volumes are converted back from cubic millimetres.
iges = sys.argv[1].lower().endswith((".iges", ".igs"))
if sys.argv[1].lower().endswith((".step", ".stp")):
    gmsh.option.setString("Geometry.OCCTargetUnit", "M")
gmsh.merge(sys.argv[1])
print(json.dumps([[gmsh.model.getEntityName(3, tag), gmsh.model.occ.getMass(3, tag) * (1e-9 if iges else 1),
                   [c * (1e-3 if iges else 1) for c in gmsh.model.occ.getCenterOfMass(3, tag)]]
                  for _, tag in gmsh.model.getEntities(3)]))
gmsh.finalize()
"""

GMSH_CONFORMITY = """
import json, sys, gmsh
gmsh.initialize(["-noenv"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.option.setString("Geometry.OCCTargetUnit", "M")
gmsh.merge(sys.argv[1])
gmsh.option.setNumber("Mesh.MeshSizeMax", float(sys.argv[2]))
gmsh.model.mesh.generate(2)
tags, coords, _ = gmsh.model.mesh.getNodes()
seen, duplicates = set(), 0
for i in range(len(tags)):
    key = tuple(round(c, 7) for c in coords[3 * i:3 * i + 3])
    duplicates += key in seen
    seen.add(key)
names = sorted({gmsh.model.getEntityName(2, tag) for _, tag in gmsh.model.getEntities(2)})
junctions = sum(len(gmsh.model.getAdjacencies(1, tag)[0]) >= 3 for _, tag in gmsh.model.getEntities(1))
print(json.dumps({"surfaces": len(gmsh.model.getEntities(2)), "nodes": len(tags), "duplicates": duplicates,
                  "junctions": junctions, "names": names}))
gmsh.finalize()
"""

GMSH_SURFACES = """
import json, sys, gmsh
gmsh.initialize(["-noenv"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.option.setString("Geometry.OCCTargetUnit", "M")
gmsh.merge(sys.argv[1])
print(json.dumps([[gmsh.model.getEntityName(2, tag), gmsh.model.occ.getMass(2, tag),
                   list(gmsh.model.getBoundingBox(2, tag))] for _, tag in gmsh.model.getEntities(2)]))
gmsh.finalize()
"""

VTK_ARRAYS = """
import json, sys, vtk
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
data = reader.GetOutput()
cells = data.GetCellData()
arrays = {}
for i in range(cells.GetNumberOfArrays()):
    array = cells.GetAbstractArray(i)
    arrays[array.GetName()] = sorted({array.GetValue(k) for k in range(array.GetNumberOfValues())})
print(json.dumps({"cells": data.GetNumberOfCells(), "points": data.GetNumberOfPoints(), "arrays": arrays}))
"""

VTK_LINE_LENGTHS = """
import json, math, sys, vtk
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
data = reader.GetOutput()
component = data.GetCellData().GetAbstractArray("component")
lengths = {}
for k in range(data.GetNumberOfCells()):
    cell = data.GetCell(k)
    if cell.GetCellType() not in (vtk.VTK_LINE, vtk.VTK_POLY_LINE):
        continue
    points = cell.GetPoints()
    length = sum(math.dist(points.GetPoint(i - 1), points.GetPoint(i)) for i in range(1, points.GetNumberOfPoints()))
    name = component.GetValue(k)
    lengths[name] = lengths.get(name, 0.0) + length
print(json.dumps(lengths))
"""

VTK_OBJ_COUNTS = """
import json, sys, vtk
reader = vtk.vtkOBJReader()
reader.SetFileName(sys.argv[1])
reader.Update()
data = reader.GetOutput()
print(json.dumps({"triangles": data.GetNumberOfPolys(), "lines": data.GetNumberOfLines()}))
"""


def _require_module(module):
    found = subprocess.run(["/usr/bin/python3", "-c", f"import {module}"], capture_output=True)
    if found.returncode != 0:
        pytest.fail(f"Python module {module} is missing (scripts/test.sh installs it from Debian)")


def _run_python(script, path):
    result = subprocess.run(["/usr/bin/python3", "-c", script, str(path)], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout.strip().splitlines()[-1])


def gmsh_volumes(path):
    """[(entity name, volume)] of the solids gmsh reads from a STEP, IGES or BREP file, in
    cubic metres."""
    return [(name, volume) for name, volume, _ in gmsh_solids(path)]


def gmsh_solids(path):
    """[(entity name, volume, centre of mass)] of the solids gmsh reads from a STEP, IGES or
    BREP file, in metres."""
    _require_module("gmsh")
    return [tuple(v) for v in _run_python(GMSH_VOLUMES, path)]


def gmsh_surfaces(path):
    """[(entity name, area, [xmin, ymin, zmin, xmax, ymax, zmax])] of the surfaces gmsh reads from
    a STEP file, in metres."""
    _require_module("gmsh")
    return [tuple(v) for v in _run_python(GMSH_SURFACES, path)]


def gmsh_mesh_conformity(path, size):
    """gmsh's surface mesh of a STEP file with elements of at most `size` metres: numbers of
    surfaces and nodes, nodes that coincide with another (none when faces share their edges),
    curves where three or more surfaces meet (a web on a skin), and the surface names."""
    _require_module("gmsh")
    result = subprocess.run(["/usr/bin/python3", "-c", GMSH_CONFORMITY, str(path), str(size)], capture_output=True,
                            text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout.strip().splitlines()[-1])


def vtk_polydata(path):
    """Cell count, point count and the distinct values of each cell array of a .vtp file."""
    _require_module("vtk")
    return _run_python(VTK_ARRAYS, path)


def vtk_line_lengths(path):
    """The summed length of the line cells of a .vtp file, by their "component" value."""
    _require_module("vtk")
    return _run_python(VTK_LINE_LENGTHS, path)


def vtk_obj_counts(path):
    """The polygons and the lines VTK's OBJ reader finds in a .obj file."""
    _require_module("vtk")
    return _run_python(VTK_OBJ_COUNTS, path)


def admesh_report(path):
    """admesh's check of an STL: the counts of facets with 1, 2 and 3 disconnected edges
    (before it repairs anything) and its number of parts."""
    if shutil.which("admesh") is None:
        pytest.fail("admesh is missing (scripts/test.sh installs it from Debian)")
    output = subprocess.run(["admesh", str(path)], capture_output=True, text=True, timeout=600).stdout
    disconnected = [int(re.search(rf"Facets with {n} disconnected edges? *: *(\d+)", output).group(1))
                    for n in (1, 2, 3)]
    parts = int(re.search(r"Number of parts *: *(\d+)", output).group(1))
    return {"disconnected": disconnected, "parts": parts}


def gltf_report(path):
    """The gltf-validator's report: numbers of errors and warnings, first messages."""
    module = os.path.join(BUILD, "tools", "node_modules", "gltf-validator")
    if shutil.which("node") is None or not os.path.isdir(module):
        pytest.fail("node or the gltf-validator package is missing (scripts/test.sh installs it with npm)")
    script = os.path.join(os.path.dirname(__file__), "validate_gltf.js")
    result = subprocess.run(["node", script, str(path)], capture_output=True, text=True, timeout=600,
                            env={**os.environ, "GLTF_VALIDATOR_MODULE": module})
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def stl_volume(path):
    """The volume a binary STL encloses (sum of signed tetrahedra) and its triangle count."""
    import struct
    with open(path, "rb") as stl:
        stl.read(80)
        count = struct.unpack("<I", stl.read(4))[0]
        volume = 0.0
        for _ in range(count):
            values = struct.unpack("<12fH", stl.read(50))
            a, b, c = values[3:6], values[6:9], values[9:12]
            volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                       + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return volume, count
