"""Design studies (docs/studies.md) on a rectangular wing whose volume is known in closed form
(chord c, span b, a parabolic airfoil: V = 0.05 c^2 b): designs, results files, failures,
resuming, exports, the command line, sensitivities and exact derivatives."""
import csv
import json
import math
import os
import subprocess

import numpy
import pytest

import airshape
from airshape.study import StudyError

SOURCE = os.environ.get("AIRSHAPE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("AIRSHAPE_BUILD_DIR", os.path.join(SOURCE, "build"))
WINGS = os.path.join(SOURCE, "tests", "data", "wing-cst-rectangular.xml")
RECT = "/cpacs/vehicles/aircraft/model/wings/wing[@uID='Rect']"
SPAN = RECT + "/positionings/positioning[@uID='RP2']/length"


def scaling(section, axis):
    return f"{RECT}/sections/section[@uID='{section}']/transformation/scaling/{axis}"


def chord_parameters(values=None, range_=None):
    """A chord that scales both sections in x and z (a relation ties the four places to it)."""
    chord = {"name": "chord"}
    chord.update({"values": values} if values is not None else {"range": range_})
    return [chord] + [{"name": f"{s}{a}", "xpath": scaling(s, a), "relation": "chord"}
                      for s in ("R1", "R2") for a in "xz"]


def rectangular_study(**design):
    parameters = [{"name": "span", "xpath": SPAN, "values": [4.0, 5.0, 6.0]}] + chord_parameters([1.5, 2.0])
    outputs = [{"name": "volume", "op": "wing_volume", "args": {"wing": "Rect"}},
               {"name": "tip", "op": "wing_upper_point", "args": {"wing": "Rect", "segment": 1, "eta": 1.0,
                                                                    "xsi": 0.5}}]
    return airshape.Study(WINGS, parameters, outputs, **design)


def without_seconds(rows):
    return [{key: value for key, value in row.items() if key != "seconds"} for row in rows]


def test_a_grid_measures_every_sample_in_closed_form(tmp_path):
    outcome = rectangular_study().run(str(tmp_path / "results.csv"), workers=2, progress=False)
    assert outcome.failed == 0 and not outcome.interrupted and len(outcome.rows) == 6
    for row in outcome.rows:
        assert row["volume"] == pytest.approx(0.05 * row["chord"] ** 2 * row["span"], rel=1e-9)
        assert row["tip"][1] == pytest.approx(row["span"], abs=1e-12)  # the tip section at y = span
        assert row["seconds"] > 0 and row["error"] is None
    assert [row["id"] for row in outcome.rows] == list(range(6))
    assert [(row["span"], row["chord"]) for row in outcome.rows][:2] == [(4.0, 1.5), (4.0, 2.0)]


def test_the_csv_reads_back_to_the_same_bits(tmp_path):
    path = tmp_path / "results.csv"
    outcome = rectangular_study().run(str(path), workers=1, progress=False)
    with open(path, newline="") as file:
        rows = list(csv.DictReader(file))
    assert list(rows[0]) == ["id", "span", "chord", "R1x", "R1z", "R2x", "R2z", "volume", "tip", "seconds", "error",
                             "cpacs_path"]
    for written, row in zip(rows, outcome.rows):
        assert float(written["volume"]) == row["volume"] and json.loads(written["tip"]) == row["tip"]


def test_jsonl_results(tmp_path):
    path = tmp_path / "results.jsonl"
    outcome = rectangular_study().run(str(path), progress=False)
    lines = [json.loads(line) for line in path.read_text().splitlines()]
    assert without_seconds(lines) == without_seconds(outcome.rows)


def test_a_latin_hypercube_uses_each_stratum_once_and_its_seed():
    parameters = [{"name": "span", "xpath": SPAN, "range": [4.0, 6.0]}] + chord_parameters(range_=[1.0, 3.0])
    study = airshape.Study(WINGS, parameters, [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}],
                           design="latin_hypercube", samples=10, seed=7)
    samples = study.samples()
    spans = numpy.array([s.values["span"] for s in samples])
    assert sorted(numpy.floor((spans - 4.0) / 0.2).astype(int)) == list(range(10))
    assert all(s.values["R2z"] == s.values["chord"] for s in samples)
    again = airshape.Study(WINGS, parameters, [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}],
                           design="latin_hypercube", samples=10, seed=7).samples()
    assert [s.values for s in again] == [s.values for s in samples]
    other = airshape.Study(WINGS, parameters, [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}],
                           design="latin_hypercube", samples=10, seed=8).samples()
    assert [s.values for s in other] != [s.values for s in samples]


def test_a_table_of_samples(tmp_path):
    table = tmp_path / "samples.csv"
    table.write_text("span,chord,note\n4.5,1.0,a\n5.5,2.5,b\n")
    parameters = [{"name": "span", "xpath": SPAN}] + [{"name": "chord"}] + chord_parameters([1.0])[1:]
    study = airshape.Study(WINGS, parameters, [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}],
                           design="table", table=str(table))
    outcome = study.run(str(tmp_path / "r.csv"), progress=False)
    assert [row["v"] for row in outcome.rows] == pytest.approx([0.05 * 4.5, 0.05 * 2.5 ** 2 * 5.5])


def test_a_failing_sample_keeps_its_row_with_the_error_and_path(tmp_path):
    parameters = [{"name": "tip", "values": [1.0, 0.0, 2.0]}] + [
        {"name": f"tip{a}", "xpath": scaling("R2", a), "relation": "tip"} for a in "xyz"]
    study = airshape.Study(WINGS, parameters, [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}])
    outcome = study.run(str(tmp_path / "r.csv"), workers=2, progress=False)
    assert outcome.failed == 1 and len(outcome.rows) == 3
    failed = outcome.rows[1]
    assert failed["v"] is None and "planar" in failed["error"] and "/segments/segment" in failed["cpacs_path"]
    assert outcome.rows[0]["v"] > 0 and outcome.rows[2]["v"] > 0  # the worker goes on after a failure


class StopAfter:
    """Ctrl-C after a number of rows, as the user's key would raise it."""

    def __init__(self, count):
        self.count = count
        self.seen = []

    def __call__(self, row):
        self.seen.append(row["id"])
        if len(self.seen) == self.count:
            raise KeyboardInterrupt


def test_an_interrupted_study_resumes_and_runs_only_what_is_missing(tmp_path):
    path = str(tmp_path / "r.csv")
    stop = StopAfter(2)
    first = rectangular_study().run(path, workers=1, progress=False, on_row=stop)
    assert first.interrupted and len(first.rows) == 2
    with open(path) as file:
        assert len(file.read().splitlines()) == 3  # the header and the two rows done
    seen = []
    second = rectangular_study().run(path, workers=2, progress=False, on_row=lambda row: seen.append(row["id"]))
    assert sorted(seen) == sorted(set(range(6)) - set(stop.seen))
    fresh = rectangular_study().run(str(tmp_path / "fresh.csv"), workers=1, progress=False)
    assert without_seconds(second.rows) == without_seconds(fresh.rows)


def test_results_of_another_study_are_not_resumed(tmp_path):
    path = str(tmp_path / "r.csv")
    rectangular_study().run(path, progress=False)
    parameters = [{"name": "span", "xpath": SPAN, "values": [7.0, 8.0, 9.0]}] + chord_parameters([1.5, 2.0])
    other = airshape.Study(WINGS, parameters, rectangular_study().outputs)
    with pytest.raises(StudyError, match="not this study's"):
        other.run(path, progress=False)
    assert len(other.run(path, progress=False, restart=True).rows) == 6


def test_exports_per_sample(tmp_path):
    study = airshape.Study(WINGS, [{"name": "span", "xpath": SPAN, "values": [4.0, 6.0]}], [],
                           exports=[{"path": str(tmp_path / "rect_{id}.stl"), "components": ["Rect"]}])
    assert study.run(str(tmp_path / "r.csv"), progress=False).failed == 0
    assert (tmp_path / "rect_0.stl").stat().st_size > 0 and (tmp_path / "rect_1.stl").exists()


@pytest.mark.parametrize("change, said", [
    ({"design": {"kind": "sobol"}}, "none of grid"),
    ({"parameter": [{"name": "a", "relation": "b + 1"}, {"name": "b", "relation": "a"}]}, "cycle"),
    ({"parameter": [{"name": "a", "relation": "c * 2"}]}, "names no parameter c"),
    ({"parameter": [{"name": "a", "relation": "__import__('os')"}]}, "may hold numbers"),
    ({"parameter": [{"name": "id", "values": [1]}]}, "cannot name"),
    ({"output": [{"name": "v"}]}, "give one of op, measure, points"),
    ({"colour": "red"}, "unknown key colour"),
    ({"export": [{"path": "a.stl"}]}, "must hold {id}"),
])
def test_a_study_that_cannot_run_is_refused_in_one_line(change, said):
    data = {"file": WINGS, "parameter": [{"name": "span", "xpath": SPAN, "values": [4.0]}],
            "output": [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}]}
    data.update(change)
    with pytest.raises(StudyError, match=said.replace("(", r"\(").replace("{", r"\{")):
        airshape.Study.from_dict(data)


def run_cli(*arguments):
    return subprocess.run([os.path.join(BUILD, "bin", "airshape"), "study", *arguments], capture_output=True,
                          text=True, timeout=300)


def test_the_command_line_runs_a_toml_study_and_plots_it(tmp_path):
    (tmp_path / "study.toml").write_text(f"""file = "{WINGS}"
[[parameter]]
name = "span"
xpath = "{SPAN}"
range = [4.0, 6.0]
steps = 3
[[parameter]]
name = "tip"
values = [1.0, 0.0]
[[parameter]]
name = "tipx"
xpath = "{scaling('R2', 'x')}"
relation = "2 * tip"
[[parameter]]
name = "tipz"
xpath = "{scaling('R2', 'z')}"
relation = "2 * tip"
[[parameter]]
name = "tipy"
xpath = "{scaling('R2', 'y')}"
relation = "2 * tip"
[[output]]
name = "volume"
op = "wing_volume"
args = {{ wing = "Rect" }}
[plot]
x = "span"
y = ["volume"]
""")
    result = run_cli(str(tmp_path / "study.toml"), "-o", str(tmp_path / "r.csv"), "--workers", "2")
    assert result.returncode == 1, result.stderr  # the samples with tip 0 fail
    assert result.stderr.count("failed: ") == 3 and "study: 6/6 samples done, 3 failed" in result.stderr
    rows = list(csv.DictReader(open(tmp_path / "r.csv")))
    assert len(rows) == 6 and sum(1 for row in rows if row["error"]) == 3
    assert (tmp_path / "r.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_command_line_refuses_a_missing_study_in_one_line(tmp_path):
    result = run_cli(str(tmp_path / "none.toml"), "-o", str(tmp_path / "r.csv"))
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1
    assert "none.toml" in result.stderr and not (tmp_path / "r.csv").exists()


def sensitivity_study(outputs, extra=()):
    parameters = [{"name": "span", "xpath": SPAN, "range": [4.0, 6.0]}] + chord_parameters(range_=[1.5, 2.5])
    return airshape.Study(WINGS, parameters + list(extra), outputs)


def test_volume_sensitivities_match_the_closed_form():
    study = sensitivity_study([{"name": "volume", "op": "wing_volume", "args": {"wing": "Rect"}}])
    answers = {a["parameter"]: a for a in airshape.sensitivities(study, at={"span": 5.0, "chord": 2.0})}
    assert answers["span"]["derivative"] == pytest.approx(0.05 * 2.0 ** 2, rel=1e-6)  # dV/db = 0.05 c^2
    assert answers["chord"]["derivative"] == pytest.approx(0.1 * 2.0 * 5.0, rel=1e-6)  # dV/dc = 0.1 c b
    assert all(a["agrees"] and a["method"] == "central difference" for a in answers.values())


def test_a_kink_inside_the_step_is_said():
    # The tip's thickness grows only beyond thick = 0.0075: the long step spans the kink, the short does not.
    extra = [{"name": "thick", "range": [0.0, 1.0]},
             {"name": "tipz", "xpath": scaling("R2", "z"), "relation": "2 + max(thick - 0.0075, 0) * 100"}]
    study = sensitivity_study([{"name": "volume", "op": "wing_volume", "args": {"wing": "Rect"}}], extra)
    answer = next(a for a in airshape.sensitivities(study, at={"span": 5.0, "chord": 2.0, "thick": 0.0},
                                                   parameters=["thick"], step=0.01))
    assert answer["check"] == pytest.approx(0.0, abs=1e-6) and abs(answer["derivative"]) > 1
    assert not answer["agrees"]


def test_exact_derivatives_of_points_against_translations_agree_with_differences():
    swept = "/cpacs/vehicles/aircraft/model/wings/wing[@uID='Swept']"
    parameters = [
        {"name": "wing_x", "xpath": RECT + "/transformation/translation/x", "range": [0.0, 2.0]},
        {"name": "tip_z", "xpath": RECT + "/sections/section[@uID='R2']/transformation/translation/z",
         "range": [-1.0, 1.0]},
        {"name": "element_x", "xpath": swept + "/sections/section[@uID='S2']/elements/element[@uID='S2E']"
                                               "/transformation/translation/x", "range": [-1.0, 1.0]},
    ]
    outputs = [{"name": "rect", "op": "wing_upper_point", "args": {"wing": "Rect", "segment": 1, "eta": 0.25,
                                                                     "xsi": 0.4}},
               {"name": "rect_tip", "op": "wing_lower_point", "args": {"wing": "Rect", "segment": 1, "eta": 1.0,
                                                                         "xsi": 0.7}},
               {"name": "swept", "points": {"wing": "Swept", "side": "lower", "segment": 1,
                                            "eta": {"linspace": [0.0, 1.0, 5]}, "xsi": 0.3}}]
    study = airshape.Study(WINGS, parameters, outputs)
    answers = {(a["output"], a["parameter"]): a for a in airshape.sensitivities(study, at={
        "wing_x": 1.0, "tip_z": 0.0, "element_x": 0.0})}
    assert answers[("rect", "wing_x")]["derivative"] == [1.0, 0.0, 0.0]  # the wing moves its points one for one
    assert answers[("rect", "tip_z")]["derivative"] == pytest.approx([0.0, 0.0, 0.25])  # eta of the tip's move
    assert answers[("rect_tip", "tip_z")]["derivative"] == [0.0, 0.0, 1.0]  # on the tip: one for one
    assert answers[("rect", "element_x")]["derivative"] == [0.0, 0.0, 0.0]  # another wing's element
    # The tip element's move turned by its section's rotation (y: -3 degrees) and scaled by 2.
    turned = 2 * numpy.array([math.cos(math.radians(-3)), 0.0, -math.sin(math.radians(-3))])
    expected = numpy.outer(numpy.linspace(0, 1, 5), turned)
    assert numpy.allclose(answers[("swept", "element_x")]["derivative"], expected, atol=1e-12)
    for answer in answers.values():
        assert answer["method"] == "exact"
        assert numpy.allclose(answer["derivative"], answer["finite_difference"], atol=1e-6), answer


def test_the_example_study_runs_and_plots(tmp_path):
    example = os.path.join(SOURCE, "examples", "studies", "wing-sweep.toml")
    result = run_cli(example, "-o", str(tmp_path / "results.csv"), "--quiet")
    assert result.returncode == 0 and result.stderr == "", result.stderr
    rows = list(csv.DictReader(open(tmp_path / "results.csv")))
    assert len(rows) == 8 and all(not row["error"] for row in rows)
    assert all(len(json.loads(row["quarter_chord"])) == 20 for row in rows)
    by_span = {}
    for row in rows:
        by_span.setdefault(float(row["span"]), []).append(float(row["volume"]))
    assert min(by_span[14.0]) > max(by_span[12.0])  # a longer outer panel holds more
    assert (tmp_path / "results.png").stat().st_size > 10000


def test_ctrl_c_on_the_command_line_keeps_what_is_done_and_the_same_command_resumes(tmp_path):
    import signal
    import time
    study = tmp_path / "slow.toml"
    study.write_text(f"""file = "{os.path.join(SOURCE, 'examples', 'generic-airliner.xml')}"
[[parameter]]
name = "sweep"
path = 'wings["Wing"].positionings[1].sweepAngle'
range = [20.0, 35.0]
steps = 60
[[output]]
name = "wetted"
op = "wing_wetted_area"
args = {{ wing = "Wing" }}
""")
    command = [os.path.join(BUILD, "bin", "airshape"), "study", str(study), "-o", str(tmp_path / "r.csv"),
               "--workers", "2"]
    # As from a terminal: a test runner started in the background may pass SIGINT on ignored.
    running = subprocess.Popen(command, stderr=subprocess.PIPE, text=True,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    while not (tmp_path / "r.csv").exists() or len((tmp_path / "r.csv").read_text().splitlines()) < 4:
        time.sleep(0.1)
    running.send_signal(signal.SIGINT)
    _, stderr = running.communicate(timeout=120)
    assert running.returncode == 130 and "study: interrupted: " in stderr, stderr[-500:]
    kept = len((tmp_path / "r.csv").read_text().splitlines()) - 1
    assert 3 <= kept < 60
    resumed = subprocess.run(command + ["--quiet"], capture_output=True, text=True, timeout=300)
    assert resumed.returncode == 0, resumed.stderr
    ids = [int(row["id"]) for row in csv.DictReader(open(tmp_path / "r.csv"))]
    assert ids == list(range(60))


def test_a_place_no_sample_could_set_and_a_bad_results_file_fail_before_any_sample(tmp_path):
    nowhere = RECT.replace("'Rect'", "'Nope'") + "/transformation/translation/x"
    study = airshape.Study(WINGS, [{"name": "x", "xpath": nowhere, "values": [1.0, 2.0]}],
                           [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}])
    with pytest.raises(StudyError, match="parameter x: XPath .* names no element to make"):
        study.run(str(tmp_path / "r.csv"), progress=False)
    with pytest.raises(StudyError, match=r"written as \.csv or \.jsonl, not '\.txt'"):
        rectangular_study().run(str(tmp_path / "r.txt"), progress=False)
    assert not os.listdir(tmp_path)
    # A place the document lacks but can be made is made: a section without a translation.
    made = airshape.Study(WINGS, [{"name": "z", "xpath": RECT + "/sections/section[@uID='R2']/transformation"
                                                          "/translation/z", "values": [0.5]}],
                          [{"name": "tip", "op": "wing_upper_point", "args": {"wing": "Rect", "segment": 1,
                                                                               "eta": 1.0, "xsi": 0.0}}])
    assert made.run(str(tmp_path / "m.csv"), progress=False).rows[0]["tip"][2] == pytest.approx(0.5)
