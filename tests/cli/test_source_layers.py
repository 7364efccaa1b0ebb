"""The core's folders import in one direction (docs/plugins.md, "Layers"): the geometry module is the
bottom floor, including nothing of the model, the configuration, the plugin host or the query
service, and no folder of the core includes, through its own headers and sources, a folder that
includes it back (directly or through others)."""
import os
import re

from conftest import SOURCE

CORE = os.path.join(SOURCE, "core")
INCLUDE = re.compile(r'^#include "airshape/([^"]+)"', re.MULTILINE)
# The headers at the top of airshape/ that any floor may use: errors, problems, threads, isolated
# calls and the core's modules; everything else there (the configuration, shapes, caches) sits on top.
BASE_HEADERS = {"error.h", "problem.h", "parallel_for.h", "isolated_call.h", "core_module.h", "output_file.h"}


def core_files():
    """(folder, included airshape path) for every include of the core's own sources and headers;
    the folder of a file directly in airshape/ or src/ is "(top)"."""
    for base in (os.path.join(CORE, "src"), os.path.join(CORE, "include", "airshape")):
        for folder, _, names in os.walk(base):
            for name in names:
                if not name.endswith((".cpp", ".h")):
                    continue
                relative = os.path.relpath(os.path.join(folder, name), base).split(os.sep)
                owner = relative[0] if len(relative) > 1 else "(top)"
                with open(os.path.join(folder, name)) as source:
                    for included in INCLUDE.findall(source.read()):
                        yield owner, included, os.path.join(folder, name)


def floor_of(included):
    parts = included.split("/")
    if len(parts) > 1:
        return parts[0]
    return "(base)" if parts[0] in BASE_HEADERS else "(top)"


def test_geometry_is_the_bottom_floor():
    offending = [(path, included) for owner, included, path in core_files()
                 if owner == "geometry" and floor_of(included) not in ("geometry", "(base)")]
    assert not offending, offending


def test_no_two_core_folders_include_each_other():
    # The files at the top of airshape/ (the configuration and what it holds) are not a folder: they
    # tie the folders together.
    edges = {}
    for owner, included, _ in core_files():
        target = floor_of(included)
        if owner != "(top)" and target not in (owner, "(base)", "(top)"):
            edges.setdefault(owner, set()).add(target)

    def reaches(start, goal):
        seen, stack = set(), [start]
        while stack:
            node = stack.pop()
            for following in edges.get(node, ()):
                if following == goal:
                    return True
                if following not in seen:
                    seen.add(following)
                    stack.append(following)
        return False

    loops = sorted((a, b) for a in edges for b in edges[a] if reaches(b, a))
    assert not loops, loops
