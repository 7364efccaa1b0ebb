#!/usr/bin/python3
"""Design-study throughput (docs/performance.md, "Design studies"): a 200-sample grid of D150's
outer wing span and sweep (20 x 10) with the wing's volume, wetted area, MAC and 100 upper-skin
points per sample, run by the local pool with 1 and 2 workers, against a loop of separate
`airshape query` processes, each on the file with that sample's values written into it.

    PYTHONPATH=build/python /usr/bin/python3 bench/study_throughput.py [../shared] [build]
"""
import json
import os
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree

SHARED = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "shared")
BUILD = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "build")
sys.path.insert(0, os.path.join(BUILD, "python"))
import airshape  # noqa: E402

D150 = os.path.join(SHARED, "data", "cpacs", "CPACS_30_D150.xml")
WING = "/cpacs/vehicles/aircraft/model/wings/wing[@uID='D150_VAMP_W1']"
OUTER = WING + "/positionings/positioning[4]"
SPANS = [11.0 + 0.1 * i for i in range(20)]
SWEEPS = [22.0 + 1.0 * i for i in range(10)]


def study(wetted=True):
    outputs = [
        {"name": "volume", "op": "wing_volume", "args": {"wing": "D150_VAMP_W1"}},
        {"name": "wetted_area", "op": "wing_wetted_area", "args": {"wing": "D150_VAMP_W1"}},
        {"name": "mac", "measure": "D150_VAMP_W1.mac", "key": "mac"},
        {"name": "points", "points": {"wing": "D150_VAMP_W1", "side": "upper", "segment": 3,
                                      "eta": {"linspace": [0.0, 1.0, 100]}, "xsi": 0.25}},
    ]
    return airshape.Study(D150, [
        {"name": "span", "xpath": OUTER + "/length", "values": SPANS},
        {"name": "sweep", "xpath": OUTER + "/sweepAngle", "values": SWEEPS},
    ], [output for output in outputs if wetted or output["name"] != "wetted_area"])


def pool_run(workers, folder, wetted=True):
    start = time.perf_counter()
    outcome = study(wetted).run(os.path.join(folder, f"pool{workers}{wetted}.csv"), workers=workers,
                                progress=False)
    assert outcome.failed == 0, [row["error"] for row in outcome.rows if row["error"]][:3]
    return time.perf_counter() - start, outcome.rows


def query_loop(samples, folder, wetted=True):
    """Each sample as a user without studies would run it: write the file, start `airshape query`."""
    tree = ElementTree.parse(D150)
    outer = tree.getroot().find("./vehicles/aircraft/model/wings/wing[@uID='D150_VAMP_W1']/positionings")[3]
    queries = [{"op": "wing_volume", "wing": "D150_VAMP_W1"}, {"op": "wing_mac", "wing": "D150_VAMP_W1"}]
    if wetted:
        queries.append({"op": "wing_wetted_area", "wing": "D150_VAMP_W1"})
    queries += [{"op": "wing_upper_point", "wing": "D150_VAMP_W1", "segment": 3, "eta": i / 99, "xsi": 0.25}
                for i in range(100)]
    stdin = "\n".join(json.dumps(q) for q in queries) + "\n"
    start = time.perf_counter()
    for span, sweep in samples:
        outer.find("length").text = repr(span)
        outer.find("sweepAngle").text = repr(sweep)
        path = os.path.join(folder, "sample.xml")
        tree.write(path, xml_declaration=True, encoding="utf-8")
        answer = subprocess.run([os.path.join(BUILD, "bin", "airshape"), "query", path], input=stdin,
                                capture_output=True, text=True, check=True)
        assert answer.stdout.count('"ok"') == len(queries), answer.stdout[:300]
    return time.perf_counter() - start


def main():
    if not os.path.exists(D150):
        print(f"skipped: {D150} is not there")
        return
    with tempfile.TemporaryDirectory() as folder:
        one, rows = pool_run(1, folder)
        two, _ = pool_run(2, folder)
        loop_samples = [(row["span"], row["sweep"]) for row in rows[::10]]  # 20 of the 200
        loop = query_loop(loop_samples, folder) / len(loop_samples)
        light, _ = pool_run(1, folder, wetted=False)
        light_loop = query_loop(loop_samples, folder, wetted=False) / len(loop_samples)
    per_sample = [row["seconds"] for row in rows]
    print(f"200 samples, 1 worker: {one:.1f} s ({200 / one:.1f} samples/s; in the worker "
          f"{sum(per_sample) / len(per_sample) * 1000:.0f} ms per sample, median "
          f"{sorted(per_sample)[100] * 1000:.0f} ms)")
    print(f"200 samples, 2 workers: {two:.1f} s ({200 / two:.1f} samples/s, {one / two:.2f}x of 1 worker)")
    print(f"separate `airshape query` processes: {loop * 1000:.0f} ms per sample ({1 / loop:.1f} samples/s); "
          f"the pool's worker is {loop / (one / 200):.1f}x as fast per core")
    print(f"without the wetted area (a Boolean with the fuselage per sample): 1 worker {light / 200 * 1000:.0f} ms "
          f"per sample, separate processes {light_loop * 1000:.0f} ms: {light_loop / (light / 200):.1f}x")


if __name__ == "__main__":
    main()
