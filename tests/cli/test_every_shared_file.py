"""Every wing and fuselage of every shared CPACS file builds or fails with a clear message; nothing crashes."""
import glob
import json
import os

import pytest

from conftest import SHARED, airshape, shared_path

FILES = sorted(glob.glob(os.path.join(SHARED, "data", "cpacs", "*.xml")) +
               glob.glob(os.path.join(SHARED, "data", "cpacs-examples", "*.xml")))
# What does not build yet, and why (docs/wing.md, docs/fuselage.md list the same).
KNOWN = {"NACA0012": "nacaProfile airfoils (not CPACS 3.5)"}


def answers(path, queries):
    result = airshape("query", path, stdin="".join(json.dumps(q) + "\n" for q in queries))
    return result, [json.loads(line) for line in result.stdout.splitlines()]


@pytest.mark.parametrize("path", FILES or ["absent"], ids=lambda p: os.path.basename(p))
def test_components_build_or_fail_clearly(path):
    shared_path("data", "cpacs")
    result, counts = answers(path, [{"op": "wing_count"}, {"op": "fuselage_count"}])
    if result.returncode == 2:
        assert len(result.stderr.strip().splitlines()) >= 1 and path in result.stderr
        return  # not a CPACS 3 file: refused with one line
    assert result.returncode == 0, result.stderr
    queries = [{"op": "wing_volume", "wing": i} for i in range(1, counts[0]["ok"] + 1)]
    queries += [{"op": "fuselage_volume", "fuselage": i} for i in range(1, counts[1]["ok"] + 1)]
    result, replies = answers(path, queries)
    assert result.returncode == 0 and len(replies) == len(queries), result.stderr[-500:]
    for query, reply in zip(queries, replies):
        if "ok" in reply:
            assert reply["ok"] >= 0, (query, reply)  # 0 for a wing without segments (W13_EmptyWing)
        else:
            assert any(known in reply["error"] for known in KNOWN), (query, reply)
