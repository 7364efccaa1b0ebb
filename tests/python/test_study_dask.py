"""Studies on a real Dask distributed cluster on the loopback address (a scheduler and two
worker processes): the same table as the local pool, every row despite a worker killed in the
middle, and the command line pointed at the scheduler."""
import csv
import os
import signal
import subprocess

import pytest

import airshape

distributed = pytest.importorskip("distributed", reason="scripts/test.sh installs python3-distributed")

from test_study import BUILD, WINGS, rectangular_study, without_seconds  # noqa: E402


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None, silence_logs=40) as local:
        with distributed.Client(local) as client:
            yield local, client


def test_the_cluster_gives_the_local_pools_table_bit_for_bit(cluster, tmp_path):
    _, client = cluster
    on_cluster = rectangular_study().run(str(tmp_path / "cluster.csv"), client=client, progress=False)
    local = rectangular_study().run(str(tmp_path / "local.csv"), workers=2, progress=False)
    assert on_cluster.failed == 0 and without_seconds(on_cluster.rows) == without_seconds(local.rows)
    assert cells_but_seconds(tmp_path / "cluster.csv") == cells_but_seconds(tmp_path / "local.csv")


def cells_but_seconds(path):
    """The file's cells as written, the time each sample took left out."""
    with open(path, newline="") as file:
        rows = list(csv.reader(file))
    seconds = rows[0].index("seconds")
    return [row[:seconds] + row[seconds + 1:] for row in rows]


def test_a_worker_killed_in_the_middle_loses_no_row(cluster, tmp_path):
    _, client = cluster
    spans = [4.0 + 0.05 * i for i in range(40)]
    study = airshape.Study(WINGS, [{"name": "span", "xpath": rectangular_study().parameters[0].xpath,
                                    "values": spans}],
                           [{"name": "v", "op": "wing_volume", "args": {"wing": "Rect"}}])
    killed = []

    def kill_one_worker(row):
        if not killed:
            pids = client.run(os.getpid)
            victim = sorted(pids.values())[0]
            os.kill(victim, signal.SIGKILL)
            killed.append(victim)

    outcome = study.run(str(tmp_path / "r.csv"), client=client, progress=False, on_row=kill_one_worker)
    assert killed and len(outcome.rows) == 40 and outcome.failed == 0, [r["error"] for r in outcome.rows]
    assert [row["v"] for row in outcome.rows] == pytest.approx([0.05 * 4.0 * s for s in spans])
    client.wait_for_workers(2, timeout=60)  # the nanny starts it again, for the other tests


def test_the_command_line_runs_on_the_scheduler(cluster, tmp_path):
    local, _ = cluster
    study = tmp_path / "study.toml"
    study.write_text(f"""file = "{WINGS}"
[[parameter]]
name = "span"
xpath = "{rectangular_study().parameters[0].xpath}"
values = [4.0, 5.0]
[[output]]
name = "v"
op = "wing_volume"
args = {{ wing = "Rect" }}
""")
    result = subprocess.run([os.path.join(BUILD, "bin", "airshape"), "study", str(study), "-o",
                             str(tmp_path / "r.jsonl"), "--scheduler", local.scheduler_address, "--quiet"],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert len((tmp_path / "r.jsonl").read_text().splitlines()) == 2


def test_no_scheduler_at_the_address_is_said_in_one_line(tmp_path):
    with pytest.raises(airshape.study.StudyError, match="no Dask scheduler answers"):
        rectangular_study().run(str(tmp_path / "r.csv"), scheduler="tcp://127.0.0.1:9", progress=False)


def test_a_study_interrupted_on_the_cluster_resumes_from_its_results(cluster, tmp_path):
    _, client = cluster
    path = str(tmp_path / "r.csv")
    seen = []

    def interrupt_after_two(row):
        seen.append(row["id"])
        if len(seen) == 2:
            raise KeyboardInterrupt

    first = rectangular_study().run(path, client=client, progress=False, on_row=interrupt_after_two)
    assert first.interrupted and len(first.rows) == 2
    rerun = []
    second = rectangular_study().run(path, client=client, progress=False, on_row=lambda row: rerun.append(row["id"]))
    assert sorted(rerun) == sorted(set(range(6)) - set(seen)) and len(second.rows) == 6
