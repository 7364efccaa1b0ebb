"""Control devices that need no geometry to answer (QUERY-components §3.1, §3.3): which devices
a wing counts and in which order, their kinds and control parameter ranges."""
import json

from conftest import EXAMPLE, airshape

with open(EXAMPLE) as example:
    AIRCRAFT = example.read()


def steps(*parameters):
    return ("<path><steps>" + "".join(f"<step><controlParameter>{p}</controlParameter></step>" for p in parameters) +
            "</steps></path>")


def device(kind, uid, path=""):
    return f'<{kind} uID="{uid}"><name>d</name><parentUID>CS</parentUID>{path}</{kind}>'


SEGMENTS = f"""<componentSegments>
  <componentSegment uID="CS"><name>inner</name><fromElementUID>WS1_E1</fromElementUID><toElementUID>WS2_E1</toElementUID>
    <controlSurfaces>
      <leadingEdgeDevices>{device("leadingEdgeDevice", "Slat", steps(0, 1))}</leadingEdgeDevices>
      <trailingEdgeDevices>{device("trailingEdgeDevice", "Flap", steps(-1, 0, 2))}</trailingEdgeDevices>
      <spoilers>{device("spoiler", "Spoiler", steps(0, 1))}</spoilers>
    </controlSurfaces>
  </componentSegment>
  <componentSegment uID="CS2"><name>outer</name><fromElementUID>WS2_E1</fromElementUID><toElementUID>WS3_E1</toElementUID>
    <controlSurfaces><trailingEdgeDevices>{device("trailingEdgeDevice", "Aileron", steps(25, -25))}
    {device("trailingEdgeDevice", "Stepless")}</trailingEdgeDevices></controlSurfaces>
  </componentSegment>
</componentSegments></wing>"""


def ask(tmp_path, *queries):
    path = tmp_path / "devices.xml"
    path.write_text(AIRCRAFT.replace("</wing>", SEGMENTS, 1))
    result = airshape("query", str(path), stdin="".join(json.dumps(q) + "\n" for q in queries))
    return [json.loads(line) for line in result.stdout.splitlines()]


def test_devices_in_the_protocols_order_without_spoilers(tmp_path):
    answers = ask(tmp_path, {"op": "control_surface_count", "wing": "MainWing"},
                  *({"op": "control_surface_uid", "wing": 1, "index": i} for i in range(1, 6)))
    # Trailing-edge devices before leading-edge devices within a component segment.
    assert [a.get("ok") for a in answers[:5]] == [4, "Flap", "Slat", "Aileron", "Stepless"], answers
    assert "out of range" in answers[5]["error"]


def test_kinds_and_control_parameter_ranges(tmp_path):
    answers = ask(tmp_path, *({"op": "control_surface_type", "uid": uid} for uid in ("Flap", "Slat", "Spoiler")),
                  *({"op": "control_surface_parameter_range", "uid": uid} for uid in ("Flap", "Aileron")),
                  {"op": "control_surface_type", "uid": "MainWing"},
                  {"op": "control_surface_parameter_range", "uid": "Stepless"})
    assert [a["ok"] for a in answers[:3]] == ["trailing_edge_device", "leading_edge_device", "spoiler"]
    assert answers[3]["ok"] == {"min": -1, "max": 2}
    assert answers[4]["ok"] == {"min": 25, "max": -25}, "first and last step, in document order"
    assert answers[5] == {"error": "no control surface with uID 'MainWing'"}
    assert "trailingEdgeDevice[2]/path: the control surface has no path steps" in answers[6]["error"]


def test_spoilers_are_counted_on_their_own(tmp_path):
    answers = ask(tmp_path, {"op": "spoiler_count", "wing": 1}, {"op": "spoiler_uid", "wing": 1, "index": 1},
                  {"op": "spoiler_uid", "wing": 1, "index": 2}, {"op": "control_surface_uid", "wing": 1, "index": "Flap"})
    assert answers[0] == {"ok": 1} and answers[1] == {"ok": "Spoiler"}
    assert "out of range" in answers[2]["error"]
    assert answers[3] == {"error": "argument 'index' must be a 1-based integer"}
