#!/usr/bin/python3
"""Takes the pictures of docs/viewer.md with headless Chromium: the example airliner exported
as a page, as it opens, and with its wing picked; and the live page of `airshape view` after
the file was broken (the error above the last geometry). Needs chromium, python3-pil and
python3-websocket (scripts/test.sh installs them).

    scripts/render_viewer_pictures.py      (writes docs/images/viewer-*.png)
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(SOURCE, "tests", "cli"))
from headless_browser import HeadlessBrowser  # noqa: E402

AIRSHAPE = os.path.join(SOURCE, "build", "bin", "airshape")
AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
IMAGES = os.path.join(SOURCE, "docs", "images")
PICK_WING = "[...document.querySelectorAll('#tree li')].find(li => li.dataset.name === 'Wing').click()"


def main():
    folder = tempfile.mkdtemp()
    try:
        page = os.path.join(folder, "airliner.html")
        subprocess.run([AIRSHAPE, "export", AIRLINER, "-o", page, "--mirror", "--quiet"], check=True)
        with HeadlessBrowser("file://" + page, 1100, 640) as browser:
            browser.wait_for("document.body.dataset.state === 'loaded'")
            browser.screenshot().save(os.path.join(IMAGES, "viewer-page.png"))
            browser.evaluate(PICK_WING)
            browser.evaluate("document.getElementById('edges').click()")
            browser.screenshot().save(os.path.join(IMAGES, "viewer-picked.png"))
        live = os.path.join(folder, "live.xml")
        shutil.copy(AIRLINER, live)
        server = subprocess.Popen([AIRSHAPE, "view", live, "--no-browser"], stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL, text=True)
        url = re.search(r"http://\S+/", server.stdout.readline()).group(0)
        with HeadlessBrowser(url, 1100, 640) as browser:
            browser.wait_for("document.body.dataset.state === 'loaded'")
            with open(live, "w") as broken:
                broken.write("<cpacs")
            browser.wait_for("!document.getElementById('error').hidden")
            browser.screenshot().save(os.path.join(IMAGES, "viewer-live-error.png"))
        server.terminate()
        server.wait()
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
