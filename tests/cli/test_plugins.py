"""The plugin host: built-in plugins, a third-party plugin built outside the tree, and bad plugins."""
import json
import os
import shutil
import subprocess

import pytest

from conftest import BUILD, EXAMPLE, SOURCE, airshape


def test_built_in_plugins_are_listed():
    result = airshape("plugins")
    assert result.returncode == 0, result.stderr
    for name, version in (("wing", "0.1.0"), ("fuselage", "0.3.0"), ("controlsurfaces", "0.3.0"),
                          ("structure", "0.7.0"), ("nacelle", "0.2.0"), ("rotor", "0.2.0"), ("tank", "0.2.0"),
                          ("landinggear", "0.1.0")):
        assert f"\n{name} {version}" in result.stdout
    assert "wing_count" in result.stdout and "bounding_box" in result.stdout


@pytest.fixture(scope="module")
def third_party(tmp_path_factory):
    """Builds tests/third_party_plugin against this build tree, without touching the core."""
    if shutil.which("cmake") is None:
        pytest.skip("cmake is absent")
    build = tmp_path_factory.mktemp("third_party_build")
    configure = subprocess.run(["cmake", "-S", os.path.join(SOURCE, "tests", "third_party_plugin"), "-B", str(build),
                                f"-Dairshape_DIR={BUILD}", "-DCMAKE_BUILD_TYPE=Release"], capture_output=True, text=True)
    assert configure.returncode == 0, configure.stdout + configure.stderr
    compile_ = subprocess.run(["cmake", "--build", str(build), "-j", "2"], capture_output=True, text=True)
    assert compile_.returncode == 0, compile_.stdout + compile_.stderr
    return build


def plugin_folder(tmp_path, build, *names):
    folder = tmp_path / "plugins"
    folder.mkdir()
    for name in names:
        shutil.copy(build / f"lib{name}.so", folder)
    return folder


def loaded_cleanly(tmp_path, build, name):
    """The environment that loads one third-party plugin, and `airshape plugins` under it,
    which must have loaded every plugin without a message."""
    env = {"AIRSHAPE_PLUGIN_PATH": str(plugin_folder(tmp_path, build, name))}
    listing = airshape("plugins", env=env)
    assert listing.returncode == 0 and listing.stderr == "", listing.stderr
    return env, listing


def test_third_party_node_type_and_op_appear(tmp_path, third_party):
    env, listing = loaded_cleanly(tmp_path, third_party, "sensor_pod")
    assert "sensorpods 1.2.3" in listing.stdout and "sensorPod" in listing.stdout
    assert "sensor_pod_count" in listing.stdout
    pod = '<sensorPods><sensorPod uID="Pod"><name>p</name><parentUID>Fuselage</parentUID></sensorPod></sensorPods>'
    aircraft = tmp_path / "with-pod.xml"
    aircraft.write_text(open(EXAMPLE).read().replace("</wings>", "</wings>" + pod))
    info = airshape("info", str(aircraft), env=env)
    assert "sensorPod Pod  parent: Fuselage  plugin: sensorpods (no builder yet)" in info.stdout, info.stdout
    without = airshape("info", str(aircraft))  # without the plugin, its kind is no component
    assert "Pod" not in without.stdout, without.stdout
    built = airshape("build", str(aircraft), env=env)
    assert "no builder yet for sensorPod (plugin sensorpods)" in built.stdout, built.stdout
    queries = '{"op":"sensor_pod_count"}\n{"op":"bounding_box","uid":"Pod"}\n'
    answer = airshape("query", str(aircraft), stdin=queries, env=env)
    count, box = (json.loads(line) for line in answer.stdout.splitlines())
    assert count == {"ok": 1}
    assert box == {"error": "no builder yet for sensorPod"}, "a component type nobody builds says so"


def test_landing_gears_are_listed_and_say_why_they_are_not_built(tmp_path):
    gear = ('<landingGears><landingGear uID="NoseGear"><name>n</name><parentUID>Fuselage</parentUID>'
            '</landingGear></landingGears>')
    aircraft = tmp_path / "with-gear.xml"
    aircraft.write_text(open(EXAMPLE).read().replace("</wings>", "</wings>" + gear))
    why = "not built: CPACS 3.5 gives its struts no frame, and its one public example is in millimetres, not metres"
    info = airshape("info", str(aircraft))
    assert f"landing_gear NoseGear  parent: Fuselage  plugin: landinggear ({why}" in info.stdout, info.stdout
    built = airshape("build", str(aircraft))
    assert built.returncode == 0, built.stdout + built.stderr  # left unbuilt on purpose: no failure
    line = next(line for line in built.stdout.splitlines() if "NoseGear" in line)
    assert line.split()[0] == "landing_gear" and why in line and "(plugin landinggear)" in line, line
    box = airshape("query", str(aircraft), stdin='{"op":"bounding_box","uid":"NoseGear"}\n')
    assert json.loads(box.stdout) == {"error": f"'NoseGear' is {why} (docs/landinggear.md)"}
    exported = airshape("export", str(aircraft), "-o", str(tmp_path / "a.step"))
    assert exported.returncode == 0 and "1 geometric elements are not built and not written" in exported.stderr
    rotorcraft = tmp_path / "rotorcraft-gear.xml"  # a rotorcraft's gears, kind by kind
    with open(os.path.join(SOURCE, "tests", "data", "rotorcraft-two-blades.xml")) as source:
        text = source.read()
    rotorcraft.write_text(text.replace("</model>", '<landingGear><skidGears><skidGear uID="Skid"><name>s</name>'
                                       '</skidGear></skidGears></landingGear></model>', 1))
    listed = airshape("info", str(rotorcraft))
    assert listed.returncode == 0 and "landing_gear Skid  parent: -  plugin: landinggear (not built" in listed.stdout, \
        listed.stdout


def test_a_plugin_that_builds_on_the_wing_plugin_uses_its_interface(tmp_path, third_party):
    env, listing = loaded_cleanly(tmp_path, third_party, "wing_tip")
    assert "wingtip 0.3.0" in listing.stdout and "requires:   wing (version >= 0.1.0, < 1.0.0)" in listing.stdout
    segment = ('<componentSegments><componentSegment uID="CS"><name>cs</name><fromElementUID>WS1_E1</fromElementUID>'
               '<toElementUID>WS3_E1</toElementUID></componentSegment></componentSegments></wing>')
    aircraft = tmp_path / "with-segment.xml"
    aircraft.write_text(open(EXAMPLE).read().replace("</wing>", segment, 1))
    answer = airshape("query", str(aircraft), env=env, stdin='{"op":"component_segment_tip","component_segment":"CS"}\n'
                      '{"op":"wing_chord_point","wing":1,"segment":2,"eta":1,"xsi":0}\n')
    tip, chord = (json.loads(line)["ok"] for line in answer.stdout.splitlines())
    assert all(abs(a - b) < 1e-12 for a, b in zip(tip, chord)), (tip, chord)


def test_a_plugin_whose_requirement_is_missing_or_too_old_is_refused_alone(tmp_path, third_party):
    folder = plugin_folder(tmp_path, third_party, "wing_tip_future", "wing_tip_orphan")
    result = airshape("plugins", env={"AIRSHAPE_PLUGIN_PATH": str(folder)})
    assert result.returncode == 0
    messages = result.stderr.strip().splitlines()
    assert len(messages) == 2, messages
    assert any("plugin wingtip requires plugin wing (version >= 9.0, < 1.0.0), but version 0.1.0 is loaded; skipped"
               in m for m in messages), messages
    assert any("plugin wingtip requires plugin nosuch (version >= 0.1.0, < 1.0.0), which is not loaded; skipped"
               in m for m in messages), messages
    assert "wing 0.1.0" in result.stdout and "wingtip" not in result.stdout


def test_bad_plugins_get_one_message_each_and_the_rest_works(tmp_path, third_party):
    folder = plugin_folder(tmp_path, third_party, "sensor_pod_old_abi", "wing_claimer")
    (folder / "libbroken.so").write_bytes(b"\x7fELF this is not a shared object")
    (folder / "libnotaplugin.so").write_bytes(open("/lib/x86_64-linux-gnu/libm.so.6", "rb").read()
                                              if os.path.exists("/lib/x86_64-linux-gnu/libm.so.6") else b"")
    result = airshape("plugins", env={"AIRSHAPE_PLUGIN_PATH": str(folder)})
    assert result.returncode == 0
    messages = result.stderr.strip().splitlines()
    assert any("libbroken.so: cannot be loaded as a plugin" in m for m in messages), messages
    assert any("built for plugin ABI version 999, this core has 10" in m for m in messages), messages
    assert any("claims node type 'wing', which plugin wing builds already" in m for m in messages), messages
    assert "wing 0.1.0" in result.stdout and "wing_count" in result.stdout
    query = airshape("query", EXAMPLE, stdin='{"op":"wing_count"}\n', env={"AIRSHAPE_PLUGIN_PATH": str(folder)})
    assert query.stdout.strip() == '{"ok":1}'
