#!/usr/bin/python3
"""Renders the pictures of docs/meshing.md from meshes `airshape mesh` writes (.vtu, read with
meshio): the example airliner's surface mesh coloured by component, the half CFD domain's
mesh on its symmetry plane around the aircraft, and the wing box's FEM shells coloured by
element set; element edges drawn. Uses the rasteriser of render_pictures.py.

    scripts/render_mesh_pictures.py        (writes docs/images/mesh-*.png)
"""
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_pictures import AIRLINER, AIRSHAPE, EXAMPLE, SOURCE, render, write_png  # noqa: E402


def meshed(source, *options, by="group"):
    """The .vtu `airshape mesh` writes with these options: per group (by its cell array "group",
    or "part") its triangles ((n, 3, 3) points; quadrilaterals split) and element edges
    ((m, 2, 3) points)."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "mesh.vtu")
        subprocess.run([AIRSHAPE, "mesh", source, "-o", path, "-q", *options], check=True, capture_output=True)
        mesh = meshio.read(path)
    names = {int(value[0]): name[len("group:"):] for name, value in mesh.field_data.items()}
    groups = {}
    for block, tags in zip(mesh.cells, mesh.cell_data[by]):
        if block.type not in ("triangle", "quad"):
            continue
        corners = block.data[:, :3] if block.type == "triangle" else block.data[:, :4]
        for tag in np.unique(tags[tags >= 0]):
            cells = corners[tags == tag]
            triangles = mesh.points[cells[:, [0, 1, 2]]]
            if cells.shape[1] == 4:
                triangles = np.concatenate([triangles, mesh.points[cells[:, [0, 2, 3]]]])
            rolled = np.roll(cells, -1, axis=1)
            edges = mesh.points[np.stack([cells, rolled], axis=2).reshape(-1, 2)]
            old = groups.get(names[int(tag)], (np.zeros((0, 3, 3)), np.zeros((0, 2, 3))))
            groups[names[int(tag)]] = (np.concatenate([old[0], triangles]), np.concatenate([old[1], edges]))
    return groups


def inside(groups, low, high):
    """The groups' triangles and edges whose first corner lies in the box [low, high]."""
    kept = {}
    for name, (triangles, edges) in groups.items():
        keep_t = ((triangles[:, 0] >= low) & (triangles[:, 0] <= high)).all(axis=1)
        keep_e = ((edges[:, 0] >= low) & (edges[:, 0] <= high)).all(axis=1)
        kept[name] = (triangles[keep_t], edges[keep_e])
    return kept


def main():
    images = os.path.join(SOURCE, "docs", "images")
    dark = (0.15, 0.15, 0.18)
    surface = meshed(AIRLINER, "--size", "1.5")
    components = [name for name in surface if "/" not in name]
    write_png(render({name: surface[name] for name in components}, components, colour_of={},
                     edge_colour=dark, edge_width=0), os.path.join(images, "mesh-surface.png"))
    fluid = meshed(AIRLINER, "--farfield", "2L", "--symmetry", "--size", "1.5")
    near = inside({name: groups for name, groups in fluid.items() if name != "farfield"},
                  np.array([-4.0, -1.0, -5.0]), np.array([44.0, 1.0, 9.0]))
    near = {name: parts for name, parts in near.items() if len(parts[0])}
    write_png(render(near, list(near), azimuth=0, elevation=0, colour_of={"symmetry": 1},
                     edge_colour=dark, edge_width=0), os.path.join(images, "mesh-symmetry-plane.png"))
    shells = meshed(EXAMPLE, "--structure", "--size", "0.1", by="part")
    inner = ["Front", "Rear", "Ribs"]  # drawn in colour, the skin (RS) as a ghost around them
    write_png(render({name: shells[name] for name in inner + ["RS"]}, inner, azimuth=-30, elevation=35,
                     edge_colour=dark, edge_width=0), os.path.join(images, "mesh-fem-shells.png"))


if __name__ == "__main__":
    main()
