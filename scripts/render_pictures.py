#!/usr/bin/python3
"""Renders the pictures of docs/structure.md from our own exports: an OBJ file written by
`airshape export` (one group per component), some components drawn opaque and coloured, the
others as a faint ghost around them, orthographic, flat shaded, into a PNG. No renderer is
needed: a small z-buffer rasteriser in NumPy.

    scripts/render_pictures.py             (writes docs/images/structure-*.png)
"""
import math
import os
import struct
import subprocess
import sys
import tempfile
import zlib

import numpy as np

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
AIRSHAPE = os.path.join(SOURCE, "build", "bin", "airshape")
EXAMPLE = os.path.join(SOURCE, "tests", "data", "wing-cst-structure.xml")
AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
COLOURS = [(0.85, 0.33, 0.10), (0.00, 0.45, 0.74), (0.47, 0.67, 0.19), (0.93, 0.69, 0.13)]
WIDTH, HEIGHT = 900, 420


def read_obj(path):
    """{group name: (n, 3, 3) triangles}."""
    vertices, groups, current = [], {}, None
    with open(path) as obj:
        for line in obj:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts[0] in ("g", "o"):
                current = parts[1].rsplit("/", 1)[-1]
                groups.setdefault(current, [])
            elif parts[0] == "f":
                corners = [int(p.split("/")[0]) - 1 for p in parts[1:]]
                for k in range(1, len(corners) - 1):
                    groups[current].append([corners[0], corners[k], corners[k + 1]])
    points = np.array(vertices)
    return {name: points[np.array(faces)] for name, faces in groups.items() if faces}


def view(triangles, azimuth, elevation):
    a, e = math.radians(azimuth), math.radians(elevation)
    turn = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])
    tilt = np.array([[1, 0, 0], [0, math.cos(e), -math.sin(e)], [0, math.sin(e), math.cos(e)]])
    return triangles @ (tilt @ turn).T  # screen x, depth y, screen z


def render(groups, opaque, azimuth=-35, elevation=25):
    placed = {name: view(t, azimuth, elevation) for name, t in groups.items()}
    every = np.concatenate(list(placed.values())).reshape(-1, 3)
    low, high = every.min(axis=0), every.max(axis=0)
    scale = 0.9 * min(WIDTH / (high[0] - low[0]), HEIGHT / (high[2] - low[2]))
    image = np.ones((HEIGHT, WIDTH, 3))
    depth = np.full((HEIGHT, WIDTH), np.inf)
    light = np.array([0.3, -0.8, 0.5]) / np.linalg.norm([0.3, -0.8, 0.5])

    def draw(triangles, colour, alpha):
        for tri in triangles:
            normal = np.cross(tri[1] - tri[0], tri[2] - tri[0])
            if np.linalg.norm(normal) == 0:
                continue
            shade = 0.35 + 0.65 * abs(normal @ light) / np.linalg.norm(normal)
            xs = (tri[:, 0] - low[0]) * scale + 0.05 * WIDTH
            ys = HEIGHT - ((tri[:, 2] - low[2]) * scale + 0.05 * HEIGHT)
            x0, x1 = int(max(xs.min(), 0)), int(min(xs.max() + 1, WIDTH))
            y0, y1 = int(max(ys.min(), 0)), int(min(ys.max() + 1, HEIGHT))
            if x0 >= x1 or y0 >= y1:
                continue
            gx, gy = np.meshgrid(np.arange(x0, x1) + 0.5, np.arange(y0, y1) + 0.5)
            d = (xs[1] - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (ys[1] - ys[0])
            if d == 0:
                continue
            w1 = ((gx - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (gy - ys[0])) / d
            w2 = ((xs[1] - xs[0]) * (gy - ys[0]) - (gx - xs[0]) * (ys[1] - ys[0])) / d
            inside = (w1 >= 0) & (w2 >= 0) & (w1 + w2 <= 1)
            z = tri[0, 1] + w1 * (tri[1, 1] - tri[0, 1]) + w2 * (tri[2, 1] - tri[0, 1])
            region = depth[y0:y1, x0:x1]
            if alpha == 1.0:
                mask = inside & (z < region)
                region[mask] = z[mask]
                image[y0:y1, x0:x1][mask] = np.array(colour) * shade
            else:
                mask = inside & (z < region)
                image[y0:y1, x0:x1][mask] = (1 - alpha) * image[y0:y1, x0:x1][mask] + alpha * np.array(colour) * shade

    for k, name in enumerate(opaque):
        draw(placed[name], COLOURS[k % len(COLOURS)], 1.0)
    for name, triangles in placed.items():
        if name not in opaque:
            draw(triangles, (0.5, 0.5, 0.55), 0.18)
    return image


def write_png(image, path):
    pixels = (np.clip(image, 0, 1) * 255).astype(np.uint8)
    raw = b"".join(b"\x00" + row.tobytes() for row in pixels)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as png:
        png.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 2, 0, 0, 0)) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def exported(source, components, deflection, profiles=False):
    """The groups of an OBJ export of some components of a file (frames and stringers with their
    profiles swept, with `profiles`)."""
    with tempfile.TemporaryDirectory() as folder:
        obj = os.path.join(folder, "structure.obj")
        subprocess.run([AIRSHAPE, "export", source, "--components", ",".join(components), "--deflection",
                        str(deflection), "-q", "-o", obj] + (["--profiles"] if profiles else []), check=True)
        return read_obj(obj)


def main():
    images = os.path.join(SOURCE, "docs", "images")
    groups = exported(EXAMPLE, ["Rect", "Front", "Rear", "Ribs", "UpperCell"], 0.0005)
    for name, opaque in (("spars", ["Front", "Rear"]), ("ribs", ["Ribs"]), ("cells", ["UpperCell"]),
                         ("all", ["Front", "Rear", "Ribs", "UpperCell"])):
        write_png(render(groups, opaque), os.path.join(images, f"structure-{name}.png"))
    # The example aircraft's fuselage structure and wing fuel tanks, in their ghosted body.
    groups = exported(AIRLINER, ["Fuselage", "Rear_Bulkhead", "Cargo_Door"], 0.05)
    write_png(render(groups, ["Rear_Bulkhead", "Cargo_Door"], azimuth=-60, elevation=15),
              os.path.join(images, "structure-fuselage.png"))
    # The frames round the cargo door with their Z profiles swept along them, and the door.
    groups = exported(AIRLINER, ["Frame_Door_Front", "Frame_Door_Rear", "Cargo_Door"], 0.002, profiles=True)
    write_png(render(groups, ["Frame_Door_Front", "Frame_Door_Rear", "Cargo_Door"], azimuth=-60, elevation=15),
              os.path.join(images, "structure-frames.png"))
    # A flap's own structure, where the shared D250 file is at hand.
    d250 = os.path.join(SOURCE, "..", "shared", "data", "cpacs", "CPACS_30_D250_10.xml")
    if os.path.exists(d250):
        flap = ["T1Spar1_IF", "T1Spar2_IF", "TED1R1", "TED1R2"]
        groups = exported(d250, ["D250_InnerFlap"] + flap, 0.005)
        write_png(render(groups, flap, azimuth=-30, elevation=35), os.path.join(images, "structure-device.png"))
    groups = exported(AIRLINER, ["Wing", "Wing_InnerTank", "Wing_OuterTank"], 0.02)
    write_png(render(groups, ["Wing_InnerTank", "Wing_OuterTank"], azimuth=-20, elevation=50),
              os.path.join(images, "structure-tanks.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
