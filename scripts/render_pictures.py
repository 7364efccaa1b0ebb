#!/usr/bin/python3
"""Renders the pictures of docs/structure.md from our own exports: a VTK PolyData file written
by `airshape export` (its cells named by component), some components drawn opaque and
coloured (faces flat shaded, lines as thick strokes), the others as a faint ghost around them,
orthographic, into a PNG. No renderer is needed: a small z-buffer rasteriser in NumPy.

    scripts/render_pictures.py             (writes docs/images/structure-*.png)
"""
import math
import os
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree
import zlib

import numpy as np

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
AIRSHAPE = os.path.join(SOURCE, "build", "bin", "airshape")
EXAMPLE = os.path.join(SOURCE, "tests", "data", "wing-cst-structure.xml")
AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
COLOURS = [(0.85, 0.33, 0.10), (0.00, 0.45, 0.74), (0.47, 0.67, 0.19), (0.93, 0.69, 0.13)]
WIDTH, HEIGHT = 900, 420


class Component:
    """A component's triangles ((n, 3, 3) points) and line segments ((m, 2, 3) points)."""

    def __init__(self):
        self.triangles, self.segments = [], []


def read_vtp(path):
    """{component uID: Component} of an ASCII .vtp file as `airshape export` writes it."""
    piece = ElementTree.parse(path).getroot().find("PolyData/Piece")

    def numbers(element, name, kind):
        array = next(a for a in piece.find(element).iter("DataArray") if a.get("Name") == name)
        return np.array(array.text.split(), dtype=kind)

    points = numbers("Points", "Points", float).reshape(-1, 3)
    codes = next(a for a in piece.find("CellData") if a.get("Name") == "component").text.split()
    names, current = [], []
    for code in codes:  # each string as its character codes, ended by 0
        if code == "0":
            names.append("".join(current))
            current = []
        else:
            current.append(chr(int(code)))
    components, cell = {}, 0
    for element in ("Lines", "Polys"):
        connectivity = numbers(element, "connectivity", int)
        start = 0
        for end in numbers(element, "offsets", int):
            corners = points[connectivity[start:end]]
            component = components.setdefault(names[cell], Component())
            if element == "Lines":
                component.segments.extend(np.stack([corners[:-1], corners[1:]], axis=1))
            else:
                component.triangles.append(corners)
            start, cell = end, cell + 1
    return {name: (np.array(c.triangles).reshape(-1, 3, 3), np.array(c.segments).reshape(-1, 2, 3))
            for name, c in components.items()}


def view(triangles, azimuth, elevation):
    a, e = math.radians(azimuth), math.radians(elevation)
    turn = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])
    tilt = np.array([[1, 0, 0], [0, math.cos(e), -math.sin(e)], [0, math.sin(e), math.cos(e)]])
    return triangles @ (tilt @ turn).T  # screen x, depth y, screen z


def render(groups, opaque, azimuth=-35, elevation=25, colour_of=None, edge_colour=None, edge_width=2):
    """`opaque` components drawn in colour (by their place in the list, or `colour_of[name]`,
    an index into COLOURS), the others as a ghost; their segments in their colour, or in
    `edge_colour` (a mesh's element edges) `edge_width` pixels either side."""
    placed = {name: (view(triangles, azimuth, elevation), view(segments, azimuth, elevation))
              for name, (triangles, segments) in groups.items()}
    every = np.concatenate([part.reshape(-1, 3) for shapes in placed.values() for part in shapes])
    low, high = every.min(axis=0), every.max(axis=0)
    scale = 0.9 * min(WIDTH / (high[0] - low[0]), HEIGHT / (high[2] - low[2]))
    margin = (WIDTH - (high[0] - low[0]) * scale) / 2, (HEIGHT - (high[2] - low[2]) * scale) / 2
    image = np.ones((HEIGHT, WIDTH, 3))
    depth = np.full((HEIGHT, WIDTH), np.inf)
    light = np.array([0.3, -0.8, 0.5]) / np.linalg.norm([0.3, -0.8, 0.5])

    def on_screen(points):
        return (points[..., 0] - low[0]) * scale + margin[0], HEIGHT - ((points[..., 2] - low[2]) * scale + margin[1])

    def draw(triangles, colour, alpha):
        for tri in triangles:
            normal = np.cross(tri[1] - tri[0], tri[2] - tri[0])
            if np.linalg.norm(normal) == 0:
                continue
            shade = 0.35 + 0.65 * abs(normal @ light) / np.linalg.norm(normal)
            xs, ys = on_screen(tri)
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

    def stroke(segments, colour, half_width=2):
        """Line segments as strokes a few pixels wide, in front of what they lie on."""
        for segment in segments:
            xs, ys = on_screen(segment)
            steps = max(2, int(2 * math.hypot(xs[1] - xs[0], ys[1] - ys[0])))
            for share in np.linspace(0.0, 1.0, steps):
                x, y = xs[0] + share * (xs[1] - xs[0]), ys[0] + share * (ys[1] - ys[0])
                z = segment[0, 1] + share * (segment[1, 1] - segment[0, 1]) - 1e-3 * (high[1] - low[1])
                x0, x1 = max(int(x) - half_width, 0), min(int(x) + half_width + 1, WIDTH)
                y0, y1 = max(int(y) - half_width, 0), min(int(y) + half_width + 1, HEIGHT)
                if x0 >= x1 or y0 >= y1:
                    continue
                mask = z < depth[y0:y1, x0:x1]
                depth[y0:y1, x0:x1][mask] = z
                image[y0:y1, x0:x1][mask] = colour

    for k, name in enumerate(opaque):
        triangles, segments = placed[name]
        colour = COLOURS[(colour_of or {}).get(name, k) % len(COLOURS)]
        draw(triangles, colour, 1.0)
        stroke(segments, edge_colour or colour, edge_width)
    for name, (triangles, _) in placed.items():
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


def clipped(polygon, x, keep_above):
    """The part of a convex polygon (three or more points in order) on one side of the plane at
    station x."""
    inside = (lambda p: p[0] >= x) if keep_above else (lambda p: p[0] <= x)
    kept = []
    for k, point in enumerate(polygon):
        previous = polygon[k - 1]
        if inside(point) != inside(previous):
            share = (x - previous[0]) / (point[0] - previous[0])
            kept.append(previous + share * (point - previous))
        if inside(point):
            kept.append(point)
    return kept


def cropped(groups, x_from, x_to):
    """Each component's triangles and line segments cut to the stations between x_from and x_to."""
    def cut_triangles(triangles):
        pieces = []
        for triangle in triangles:
            polygon = clipped(clipped(list(triangle), x_from, True), x_to, False)
            pieces.extend([polygon[0], polygon[k], polygon[k + 1]] for k in range(1, len(polygon) - 1))
        return np.array(pieces).reshape(-1, 3, 3)

    def cut_segments(segments):
        pieces = []
        for a, b in segments:
            low, high = (a, b) if a[0] <= b[0] else (b, a)
            if high[0] < x_from or low[0] > x_to:
                continue
            at = lambda x: low + (x - low[0]) / (high[0] - low[0]) * (high - low) if high[0] > low[0] else low
            pieces.append([at(x_from) if low[0] < x_from else low, at(x_to) if high[0] > x_to else high])
        return np.array(pieces).reshape(-1, 2, 3)
    return {name: (cut_triangles(triangles), cut_segments(segments)) for name, (triangles, segments) in groups.items()}


def exported(source, components, deflection, profiles=False):
    """The components of a VTK PolyData export of some components of a file (frames and
    stringers with their profiles swept, with `profiles`)."""
    with tempfile.TemporaryDirectory() as folder:
        vtp = os.path.join(folder, "structure.vtp")
        subprocess.run([AIRSHAPE, "export", source, "--components", ",".join(components), "--deflection",
                        str(deflection), "-q", "-o", vtp] + (["--profiles"] if profiles else []), check=True)
        return read_vtp(vtp)


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
    # The cargo floor's cross beams (orange), struts (blue) and long floor beams (green), lines,
    # in the fuselage between x = 5 and 11.
    floor = {"Cargo_Floor_Beam_Front": 0, "Cargo_Floor_Beam_Rear": 0, "Cargo_Strut_Front_Left": 1,
             "Cargo_Strut_Front_Right": 1, "Cargo_Floor_Rail_Left": 2, "Cargo_Floor_Rail_Right": 2}
    groups = exported(AIRLINER, ["Fuselage"] + list(floor), 0.05)
    write_png(render(cropped(groups, 5.0, 11.0), list(floor), azimuth=-50, elevation=20, colour_of=floor),
              os.path.join(images, "structure-floor.png"))
    # The two stringers (lines) and the cabin divider, a wall, in the whole fuselage.
    groups = exported(AIRLINER, ["Fuselage", "Stringer_Side", "Stringer_Low", "Cabin_Divider"], 0.05)
    write_png(render(groups, ["Stringer_Side", "Stringer_Low", "Cabin_Divider"], azimuth=-60, elevation=15),
              os.path.join(images, "structure-stringers-wall.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
