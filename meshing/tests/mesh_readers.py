"""Reading written meshes back with readers that share nothing with Airshape: meshio (Debian's
python3-meshio) for .su2, .vtu and .inp, Gmsh's Python module for .msh, admesh for .stl; and
what a surface mesh is checked for (enclosed volume, free edges)."""
import collections
import json
import subprocess

import numpy


def meshio_mesh(path):
    """The mesh meshio reads: points and {cell type: connectivity}, and its cell sets' names."""
    import meshio
    mesh = meshio.read(str(path))
    cells = collections.defaultdict(list)
    for block in mesh.cells:
        cells[block.type].append(block.data)
    return mesh.points, {kind: numpy.vstack(blocks) for kind, blocks in cells.items()}, mesh


def enclosed_volume(points, triangles):
    """The volume a closed, outward-turned triangle mesh encloses (signed tetrahedra)."""
    a, b, c = (points[triangles[:, i]] for i in range(3))
    return float(numpy.einsum("ij,ij->i", a, numpy.cross(b, c)).sum() / 6)


def edge_use(triangles):
    """How many triangles use each edge: (free edges, edges of three or more)."""
    edges = numpy.sort(numpy.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    _, counts = numpy.unique(edges, axis=0, return_counts=True)
    return int((counts == 1).sum()), int((counts > 2).sum())


def free_edges(path):
    """The element edges of a mesh file (meshio) that only one element uses."""
    points, cells, _ = meshio_mesh(path)
    edges = []
    for kind, connectivity in cells.items():
        corners = {"triangle": 3, "quad": 4, "triangle6": 3, "quad8": 4}.get(kind)
        if corners:
            ring = connectivity[:, :corners]
            edges.append(numpy.stack([ring, numpy.roll(ring, -1, axis=1)], axis=2).reshape(-1, 2))
    _, counts = numpy.unique(numpy.sort(numpy.vstack(edges), axis=1), axis=0, return_counts=True)
    return int((counts == 1).sum())


GMSH_GROUPS = r"""
import json, sys, gmsh
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
gmsh.open(sys.argv[1])
groups = {}
for dim, tag in gmsh.model.getPhysicalGroups():
    name = gmsh.model.getPhysicalName(dim, tag)
    count = 0
    for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
        types, tags, nodes = gmsh.model.mesh.getElements(dim, entity)
        count += sum(len(t) for t in tags)
    groups[name] = [dim, count]
print(json.dumps(groups))
"""


def gmsh_groups(path):
    """{group name: [dimension, elements]} of a .msh file as Gmsh reads it."""
    result = subprocess.run(["/usr/bin/python3", "-c", GMSH_GROUPS, str(path)], capture_output=True, text=True,
                            timeout=600)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout.strip().splitlines()[-1])
