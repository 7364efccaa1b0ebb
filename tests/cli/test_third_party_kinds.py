"""A third party's component kinds, handled like the built-in ones (docs/plugins.md): a plugin built
against the installed package (`cmake --install`, `find_package(airshape)`), outside the source tree,
declares a group (sensor arrays), solids (their boxes), lines (their cables) and a kind that sits
inside a wing (wing sensors, placed through the wing plugin's interface). The installed `airshape`
and the installed Python module list, build, measure, export and show them."""
import json
import math
import os
import re
import shutil
import subprocess

import pytest

from conftest import BUILD, SOURCE
from independent_readers import gmsh_volumes

RADIUS = 0.05
SENSOR = (f'<sensors><sensor uID="WingSensor"><componentSegmentUID>Wing_CS</componentSegmentUID><eta>0.5</eta>'
          f'<xsi>0.3</xsi><radius>{RADIUS}</radius></sensor></sensors>')
ARRAY = ('<sensorArrays><sensorArray uID="Array"><boxes>'
         '<box uID="BoxA"><x>1</x><y>-0.5</y><z>-3</z><dx>2</dx><dy>1</dy><dz>0.5</dz></box>'
         '<box uID="BoxB"><x>4</x><y>-0.5</y><z>-3</z><dx>1</dx><dy>1</dy><dz>1</dz></box></boxes>'
         '<cables><cable uID="Cable"><points>2;0;-3;4.5;0;-3;4.5;0;-2</points></cable></cables>'
         '</sensorArray></sensorArrays>')
NEW_KINDS = {"Array": "sensor_array", "BoxA": "sensor_box", "BoxB": "sensor_box", "Cable": "sensor_cable",
             "WingSensor": "wing_sensor"}


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """The package installed from this build, and the third-party plugin built against it alone."""
    if shutil.which("cmake") is None:
        pytest.skip("cmake is absent")
    prefix = tmp_path_factory.mktemp("prefix")
    install = subprocess.run(["cmake", "--install", BUILD, "--prefix", str(prefix)], capture_output=True, text=True)
    assert install.returncode == 0, install.stdout + install.stderr
    build = tmp_path_factory.mktemp("sensor_array_build")
    configure = subprocess.run(["cmake", "-S", os.path.join(SOURCE, "tests", "third_party_plugin"), "-B", str(build),
                                f"-Dairshape_DIR={prefix}/lib/cmake/airshape", "-DCMAKE_BUILD_TYPE=Release"],
                               capture_output=True, text=True)
    assert configure.returncode == 0, configure.stdout + configure.stderr
    assert str(BUILD) not in open(build / "CMakeCache.txt").read(), "built against the install, not the build tree"
    compile_ = subprocess.run(["cmake", "--build", str(build), "--target", "sensor_array", "wing_tip", "-j", "2"],
                              capture_output=True, text=True)
    assert compile_.returncode == 0, compile_.stdout + compile_.stderr
    plugins = tmp_path_factory.mktemp("plugins")
    shutil.copy(build / "libsensor_array.so", plugins)
    shutil.copy(build / "libwing_tip.so", plugins)  # an op of its own, for the generated methods
    aircraft = tmp_path_factory.mktemp("aircraft") / "sensors.xml"
    text = open(os.path.join(SOURCE, "examples", "generic-airliner.xml")).read()
    text = text.replace("</componentSegments>", "</componentSegments>" + SENSOR, 1).replace("</model>", ARRAY + "</model>")
    aircraft.write_text(text)
    env = {**os.environ, "AIRSHAPE_PLUGIN_PATH": str(plugins)}
    return {"prefix": prefix, "env": env, "aircraft": aircraft}


def run(installed, *arguments, stdin=None, plugin=True):
    env = installed["env"] if plugin else {k: v for k, v in installed["env"].items() if k != "AIRSHAPE_PLUGIN_PATH"}
    return subprocess.run([str(installed["prefix"] / "bin" / "airshape"), *arguments], input=stdin,
                          capture_output=True, text=True, env=env, timeout=600)


def ask(installed, *queries):
    result = run(installed, "query", str(installed["aircraft"]), stdin="".join(json.dumps(q) + "\n" for q in queries))
    assert result.returncode == 0, result.stderr
    return [json.loads(line) for line in result.stdout.splitlines()]


def test_info_and_build_list_the_new_kinds_with_their_parents(installed):
    info = run(installed, "info", str(installed["aircraft"]))
    assert info.returncode == 0, info.stderr
    for line in ("wing_sensor WingSensor  parent: Wing  plugin: sensorarrays",
                 "sensor_array Array  parent: -  plugin: sensorarrays",
                 "sensor_box BoxA  parent: Array  plugin: sensorarrays",
                 "sensor_cable Cable  parent: Array  plugin: sensorarrays"):
        assert line in info.stdout, info.stdout
    without = run(installed, "info", str(installed["aircraft"]), plugin=False)
    assert "BoxA" not in without.stdout and "WingSensor" not in without.stdout, "without the plugin, no such kinds"
    built = run(installed, "build", str(installed["aircraft"]))
    assert built.returncode == 0, built.stdout + built.stderr
    assert re.search(r"sensor_cable\s+Cable\s+valid lines, length 3.5\b", built.stdout), built.stdout
    assert re.search(r"sensor_box\s+BoxA\s+valid solid, volume 1\b", built.stdout), built.stdout
    assert re.search(r"sensor_array\s+Array\s+valid solid, volume 2\b", built.stdout), built.stdout


def test_every_component_op_answers_for_them(installed):
    sphere = 4.0 / 3.0 * math.pi * RADIUS ** 3
    answers = ask(installed,
                  *({"op": "component_type", "uid": uid} for uid in NEW_KINDS),
                  {"op": "component_volume", "uid": "BoxA"}, {"op": "component_surface_area", "uid": "BoxA"},
                  {"op": "component_volume", "uid": "Array"}, {"op": "component_surface_area", "uid": "Array"},
                  {"op": "component_volume", "uid": "Cable"}, {"op": "component_volume", "uid": "WingSensor"},
                  {"op": "component_surface_area", "uid": "WingSensor"},
                  {"op": "bounding_box", "uid": "Cable"}, {"op": "bounding_box", "uid": "WingSensor"},
                  {"op": "bounding_box", "uid": "Wing"},
                  {"op": "cross_section_area", "uid": "Array", "point": [2, 0, -3], "normal": [1, 0, 0]},
                  {"op": "component_children", "uid": "Array"}, {"op": "component_faces", "uid": "BoxB"},
                  {"op": "intersection_count", "uid1": "BoxA", "uid2": "BoxB"}, {"op": "component_list"})
    types = [a["ok"] for a in answers[:len(NEW_KINDS)]]
    assert types == list(NEW_KINDS.values())
    (box_volume, box_area, array_volume, array_area, cable_volume, sensor_volume, sensor_area, cable_box, sensor_box,
     wing_box, section, children, faces, crossings, listing) = (a["ok"] for a in answers[len(NEW_KINDS):])
    assert box_volume == pytest.approx(1.0, abs=1e-12) and box_area == pytest.approx(7.0, abs=1e-12)
    assert array_volume == pytest.approx(2.0, abs=1e-12) and array_area == pytest.approx(13.0, abs=1e-12)
    assert cable_volume == 0.0
    assert sensor_volume == pytest.approx(sphere, rel=1e-9)
    assert sensor_area == pytest.approx(4 * math.pi * RADIUS ** 2, rel=1e-9)
    assert cable_box == {"min": [2.0, 0.0, -3.0], "max": [4.5, 0.0, -2.0]}
    # Inside its wing, of its diameter.
    assert all(hi - lo == pytest.approx(2 * RADIUS, abs=1e-9) for lo, hi in zip(sensor_box["min"], sensor_box["max"]))
    assert all(w_lo < lo and hi < w_hi for w_lo, lo, hi, w_hi in
               zip(wing_box["min"], sensor_box["min"], sensor_box["max"], wing_box["max"]))
    assert section == pytest.approx(0.5, abs=1e-12), "BoxA's section: 1 m by 0.5 m"
    assert children == [{"type": "sensor_box", "uid": "BoxA"}, {"type": "sensor_box", "uid": "BoxB"},
                        {"type": "sensor_cable", "uid": "Cable"}]
    assert sorted(face["name"] for face in faces) == [f"BoxB/side{i}" for i in range(1, 7)]
    assert sum(face["area"] for face in faces) == pytest.approx(6.0, abs=1e-12)
    assert crossings == 0
    listed = {entry["uid"]: entry["type"] for entry in listing}
    assert {uid: listed.get(uid) for uid in NEW_KINDS} == NEW_KINDS


def step_solids(path):
    """The volumes of the solids of a STEP file, read by gmsh (an independent reader)."""
    return sorted(volume for _, volume in gmsh_volumes(path))


FORMATS = ("step", "iges", "brep", "stl", "vtp", "gltf", "glb", "obj", "html")


def test_every_format_exports_them_by_default_and_when_named(installed, tmp_path):
    everything = [str(tmp_path / f"all.{extension}") for extension in FORMATS]
    result = run(installed, "export", str(installed["aircraft"]), *sum((["-o", p] for p in everything), []))
    assert result.returncode == 0, result.stderr
    assert all(os.path.getsize(path) > 0 for path in everything)
    assert "leaves out Cable: lines, which STL cannot hold" in result.stderr, result.stderr
    step = open(tmp_path / "all.step").read()
    products = set(re.findall(r"PRODUCT\('([^']*)'", step))
    # By default the members are written; the group and what lies inside a wing only when named.
    assert {"BoxA", "BoxB", "Cable"} <= products and not {"Array", "WingSensor"} & products, products
    nodes = {node.get("name") for node in json.load(open(tmp_path / "all.gltf"))["nodes"]}
    assert {"BoxA", "BoxB", "Cable"} <= nodes and not {"Array", "WingSensor"} & nodes
    assert {"BoxA", "BoxB", "Cable"} <= set(re.findall(r"^g .*/(.+)$", open(tmp_path / "all.obj").read(), re.M))

    named = [str(tmp_path / f"named.{extension}") for extension in FORMATS if extension != "stl"]
    result = run(installed, "export", str(installed["aircraft"]), "--components", "WingSensor,Array,Cable",
                 *sum((["-o", p] for p in named), []))
    assert result.returncode == 0, result.stderr
    products = set(re.findall(r"PRODUCT\('([^']*)'", open(tmp_path / "named.step").read()))
    assert {"WingSensor", "Array", "Cable"} <= products, products
    nodes = {node.get("name") for node in json.load(open(tmp_path / "named.gltf"))["nodes"]}
    assert {"WingSensor", "Array", "Cable"} <= nodes
    page = open(tmp_path / "named.html").read()
    assert all(uid in page for uid in ("WingSensor", "Array", "Cable")), "the viewer's page lists them"
    # Read back by an independent reader: the sphere and the array's two boxes.
    sphere = 4.0 / 3.0 * math.pi * RADIUS ** 3
    assert step_solids(tmp_path / "named.step") == pytest.approx([sphere, 1.0, 1.0], rel=1e-6)


def test_python_handles_them_like_any_component(installed, tmp_path):
    python = "/usr/bin/python3"
    site = installed["prefix"] / "lib" / "python3" / "dist-packages"
    if not os.path.exists(python) or not (site / "airshape").exists():
        pytest.skip("the installed Python module or /usr/bin/python3 is absent")
    script = f"""
import json, airshape
config = airshape.Configuration.open({str(installed["aircraft"])!r})
out = {{}}
for uid in ("WingSensor", "Array", "BoxA", "Cable"):
    c = config.component(uid)
    out[uid] = [c.type, c.volume, c.surface_area, [child.uid for child in c.children]]
config.component("Array").export({str(tmp_path / "array.step")!r})
# A third-party plugin's op is a method too, with no line written for it.
out["tip"] = [config.ops.component_segment_tip(component_segment="Wing_CS"),
              config.query("component_segment_tip", component_segment="Wing_CS"),
              config.ops.component_segment_tip.__doc__]
print(json.dumps(out))
"""
    result = subprocess.run([python, "-c", script], capture_output=True, text=True, timeout=300,
                            env={**installed["env"], "PYTHONPATH": str(site)})
    assert result.returncode == 0, result.stderr
    out = json.loads(result.stdout)
    assert out["Array"][0] == "sensor_array" and out["Array"][3] == ["BoxA", "BoxB", "Cable"]
    assert out["BoxA"][1:3] == pytest.approx([1.0, 7.0])
    assert out["Cable"][1:3] == [0.0, 0.0]
    assert out["WingSensor"][1] == pytest.approx(4.0 / 3.0 * math.pi * RADIUS ** 3, rel=1e-9)
    assert step_solids(tmp_path / "array.step") == pytest.approx([1.0, 1.0], rel=1e-9)
    method, query, doc = out["tip"]
    assert method == query and len(method) == 3
    assert "leading edge at its outer end (op of plugin wingtip)" in doc
