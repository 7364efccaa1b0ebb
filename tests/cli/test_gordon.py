"""`airshape gordon` on every curve network of ../shared/data/curve-networks."""
import glob
import json
import os
import time

import pytest

from conftest import EXAMPLE, SHARED, airshape, shared_path

NETWORKS = sorted(os.path.dirname(p) for p in glob.glob(os.path.join(SHARED, "data", "curve-networks", "*", "profiles.brep")))
CLOSED = {"fuselage1", "fuselage2", "full_nacelle", "helibody"}  # profiles all round: no seam kink allowed


@pytest.mark.parametrize("network", NETWORKS or ["absent"], ids=lambda p: os.path.basename(p))
def test_network_lies_on_its_gordon_surface(tmp_path, network):
    shared_path("data", "curve-networks")
    out = tmp_path / "surface.brep"
    result = airshape("gordon", os.path.join(network, "profiles.brep"), os.path.join(network, "guides.brep"), "-o", str(out),
                      "--report")
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    diagonal = report["bbox_diagonal"]
    assert report["max_profile_distance"] <= 1e-4 * diagonal, report
    assert report["max_guide_distance"] <= 1e-4 * diagonal, report
    assert report["max_intersection_distance"] <= 1e-6 * diagonal, report
    assert report["degree_u"] >= 1 and report["poles_u"] > report["degree_u"]
    assert out.exists() and out.stat().st_size > 0
    if os.path.basename(network) in CLOSED:
        assert report["periodic_u"] or report["periodic_v"], "a closed network gives a periodic, seamless surface"


def test_the_accuracy_report_is_asked_for(tmp_path):
    network = shared_path("data", "curve-networks", "helibody")
    result = airshape("gordon", os.path.join(network, "profiles.brep"), os.path.join(network, "guides.brep"),
                      "-o", str(tmp_path / "surface.brep"))
    report = json.loads(result.stdout)
    assert result.returncode == 0 and report["poles_u"] > 0 and report["max_crossing_gap"] >= 0
    assert "max_profile_distance" not in report, "sampling the curves is for --report"


def test_bad_input_is_one_line_and_exit_2(tmp_path):
    not_brep = tmp_path / "text.brep"
    not_brep.write_text("hello")
    for arguments in (["missing.brep", "missing.brep", "-o", str(tmp_path / "o.brep")],
                      [str(not_brep), str(not_brep), "-o", str(tmp_path / "o.brep")],
                      ["only-one.brep"]):
        result = airshape("gordon", *arguments)
        assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    profiles = shared_path("data", "curve-networks", "wing2", "profiles.brep")
    result = airshape("gordon", profiles, profiles, "-o", str(tmp_path / "o.brep"))
    assert result.returncode == 2 and "misses" in result.stderr, result.stderr
    assert not (tmp_path / "o.brep").exists()


def damaged_breps(tmp_path):
    """BREP files of the project's example aircraft, damaged as the fuzzing round damaged them:
    a vertex's tolerance line removed (OCCT's reader then loops forever), an edge's removed
    (it aborts the process with an uncaught exception), the file cut off inside a curve record."""
    whole = tmp_path / "aircraft.brep"
    exported = airshape("export", EXAMPLE, "-o", str(whole), "--quiet")
    assert exported.returncode == 0, exported.stderr
    lines = whole.read_text().split("\n")
    vertex, edge = lines.index("Ve"), lines.index("Ed")
    curve = next(i for i, line in enumerate(lines) if line.startswith("7 ") and i > next(k for k, text in enumerate(lines) if text.startswith("Curves ")))
    damaged = {"no-vertex-tolerance": lines[:vertex + 1] + lines[vertex + 2:],
               "no-edge-tolerance": lines[:edge + 1] + lines[edge + 2:],
               "cut-off": lines[:curve] + [lines[curve][:len(lines[curve]) // 2]]}
    for name, content in damaged.items():
        (tmp_path / f"{name}.brep").write_text("\n".join(content))
    return [tmp_path / f"{name}.brep" for name in damaged]


def test_a_damaged_brep_file_is_one_line_and_never_crashes_or_hangs(tmp_path):
    for damaged in damaged_breps(tmp_path):
        start = time.monotonic()
        result = airshape("gordon", str(damaged), str(damaged), "-o", str(tmp_path / "o.brep"))
        assert time.monotonic() - start < 60, f"{damaged.name}: the reader was not stopped"
        assert result.returncode == 2, (damaged.name, result.stderr)
        assert len(result.stderr.strip().splitlines()) == 1 and str(damaged) in result.stderr, result.stderr
        assert "BREP" in result.stderr, result.stderr
    assert not (tmp_path / "o.brep").exists()
