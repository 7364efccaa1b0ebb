"""The browser viewer (docs/viewer.md): `airshape export -o page.html` opens from disk in
headless Chromium with every component in its tree and the aircraft drawn; `airshape view`
serves a live page that follows edits of the file, says when the file no longer loads (keeping
the last geometry), and ends when the page asks."""
import json
import os
import re
import shutil
import subprocess
import time
import urllib.error
import urllib.request

import pytest

from conftest import BINARY, SOURCE, airshape
from headless_browser import HeadlessBrowser, drawn_share

AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
VIEW = (0, 0, 900, 800)  # the drawing, left of the 300 px panel


def tree_names(browser):
    return browser.evaluate("[...document.querySelectorAll('#tree li')].map(li => li.dataset.name)")


def written_components(stdout):
    """The components an export wrote, from its summary (between the header and the total)."""
    lines = stdout.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("component"))
    return [re.split(r"\s{2,}", line.strip())[0] for line in lines[start + 1:] if not line.startswith("total time")]


def test_an_exported_page_opens_from_disk_and_shows_every_component(tmp_path):
    page = tmp_path / "airliner.html"
    result = airshape("export", AIRLINER, "-o", str(page), "--mirror")
    assert result.returncode == 0, result.stderr
    text = page.read_text()
    # Self-contained: no script, style or model fetched from anywhere.
    assert not re.search(r"<script[^>]+src=|<link[^>]+href=", text)
    components = written_components(result.stdout)
    assert "Wing (mirrored)" in components and "Fuselage" in components
    with HeadlessBrowser(page.as_uri()) as browser:
        browser.wait_for("document.body.dataset.state === 'loaded'")
        assert tree_names(browser) == components
        share, colours = drawn_share(browser.screenshot(), VIEW)
        assert share > 0.03 and colours > 50, (share, colours)
        # The face under the pointer is named (the middle of the view: the fuselage at the wing).
        browser.evaluate("document.querySelector('#view canvas').dispatchEvent(new PointerEvent('pointermove', "
                         "{clientX: 450, clientY: 400, bubbles: true}))")
        hovered = browser.evaluate("document.getElementById('hover').textContent")
        assert re.fullmatch(r"(Fuselage|Wing|Wing \(mirrored\)) · \S+/\w+( \(mirrored\))?", hovered), hovered
        # Picking a component shows its measures; isolating it leaves it alone in the picture.
        browser.evaluate("[...document.querySelectorAll('#tree li')].find(li => li.dataset.name === 'Wing').click()")
        assert "type     wing" in browser.evaluate("document.getElementById('info').textContent")
        whole = share
        browser.evaluate("[...document.querySelectorAll('#tree li')].find(li => li.dataset.name === 'Wing')"
                         ".dispatchEvent(new MouseEvent('dblclick'))")
        alone, _ = drawn_share(browser.screenshot(), VIEW)
        assert 0 < alone < whole
        faces = browser.evaluate("Object.fromEntries(window.AIRSHAPE.components.map(c => [c.name, c.faces.length]))")
        # Edges (section profiles, guide curves, borders) as lines, in the page's frame: the
        # fuselage's lie in its box with CPACS (x, y, z) drawn as (x, z, -y), spanning it (up to
        # where the skin bulges between sections).
        fuselage = browser.evaluate("window.AIRSHAPE.components.find(c => c.name === 'Fuselage')")
        points = [polyline[i:i + 3] for polyline in fuselage["edges"] for i in range(0, len(polyline), 3)]
        low, high = fuselage["box"]["min"], fuselage["box"]["max"]
        length = high[0] - low[0]
        for axis, (lowest, highest) in enumerate([(low[0], high[0]), (low[2], high[2]), (-high[1], -low[1])]):
            drawn = [p[axis] for p in points]
            assert lowest - 1e-4 <= min(drawn) <= lowest + 0.02 * length, (axis, min(drawn), lowest)
            assert highest - 0.02 * length <= max(drawn) <= highest + 1e-4, (axis, max(drawn), highest)
        browser.evaluate("document.getElementById('show-all').click(); document.getElementById('edges').click()")
        with_edges, _ = drawn_share(browser.screenshot(), VIEW)
        assert with_edges > whole
    # The page's face lists follow the glTF primitives, one per face, as the .glb writes them.
    glb_path = tmp_path / "airliner.glb"
    airshape("export", AIRLINER, "-o", str(glb_path), "--mirror", "--quiet")
    glb = glb_path.read_bytes()
    document = json.loads(glb[20:20 + int.from_bytes(glb[12:16], "little")])
    primitives = {mesh["name"]: len(mesh["primitives"]) for mesh in document["meshes"]}
    assert faces == primitives


def start_view(path):
    process = subprocess.Popen([BINARY, "view", str(path), "--no-browser"], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    line = process.stdout.readline()
    match = re.search(r"http://127\.0\.0\.1:\d+/", line)
    assert match, (line, process.stderr.read() if process.poll() is not None else "")
    return process, match.group(0)


def get_json(url):
    with urllib.request.urlopen(url, timeout=30) as answer:
        return json.load(answer)


def test_the_live_page_follows_the_file_and_keeps_the_last_geometry(tmp_path):
    path = tmp_path / "live.xml"
    shutil.copy(AIRLINER, path)
    process, url = start_view(path)
    try:
        assert get_json(url + "version") == {"version": 0, "error": None, "leftOut": []}
        before = {c["name"]: c for c in get_json(url + "components.json")}
        with HeadlessBrowser(url) as browser:
            browser.wait_for("document.body.dataset.version === '0' && document.body.dataset.state === 'loaded'")
            assert tree_names(browser) == list(before)
            # An edit: the main wing's tip section twice as thick; the page reloads by itself.
            text = path.read_text()
            scaling = text.index("<z>", text.index('uID="Wing_S3_E_T"'))
            thickness = float(text[scaling + 3:text.index("</z>", scaling)])
            path.write_text(text[:scaling] + f"<z>{2 * thickness}</z>" + text[text.index("</z>", scaling) + 4:])
            browser.wait_for("document.body.dataset.version === '1'")
            after = {c["name"]: c for c in get_json(url + "components.json")}
            assert after["Wing"]["volume"] > before["Wing"]["volume"]
            assert after["Fuselage"]["volume"] == pytest.approx(before["Fuselage"]["volume"], rel=1e-12)
            # A control device's slider: let go at 1, the flap is built deflected and shown.
            devices = {d["uid"]: d for d in get_json(url + "devices")}
            assert devices["InnerFlap"]["min"] == 0 and devices["InnerFlap"]["max"] == 1
            assert "Spoiler" in devices and "InnerFlap" not in tree_names(browser)
            browser.evaluate("const s = document.querySelector('#devices input[data-uid=\"InnerFlap\"]'); "
                             "s.value = 1; s.dispatchEvent(new Event('change'))")
            browser.wait_for("document.body.dataset.version === '2'")
            browser.wait_for("[...document.querySelectorAll('#tree li')].some(li => li.dataset.name === 'InnerFlap')")
            assert {d["uid"]: d["value"] for d in get_json(url + "devices")}["InnerFlap"] == 1
            bad = urllib.request.Request(url + "deflect?uid=InnerFlap&parameter=7", method="POST")
            with pytest.raises(urllib.error.HTTPError, match="400"):
                urllib.request.urlopen(bad, timeout=30)
            # A file that no longer loads: said in the page, the geometry stays.
            path.write_text("<cpacs")
            error = browser.wait_for("!document.getElementById('error').hidden && "
                                     "document.getElementById('error').textContent")
            assert "not well-formed XML" in error
            assert "InnerFlap" in tree_names(browser) and "Fuselage" in tree_names(browser)
            assert get_json(url + "version")["version"] == 2
            # The page ends the server.
            browser.evaluate("[...document.querySelectorAll('button')].find(b => b.textContent === 'stop the server')"
                             ".click()")
            assert process.wait(timeout=30) == 0
    finally:
        if process.poll() is None:
            process.kill()


def test_view_refuses_what_it_cannot_show(tmp_path):
    missing = airshape("view", str(tmp_path / "none.xml"), "--no-browser")
    assert missing.returncode == 2 and "none.xml" in missing.stderr and len(missing.stderr.splitlines()) == 1
    port = airshape("view", AIRLINER, "--port", "eighty", "--no-browser")
    assert port.returncode == 2 and "--port: 'eighty' is not a port number" in port.stderr
