"""Debian's Chromium, headless, driven through its DevTools protocol: open a page, run script
in it, wait for what the page says, take a screenshot. WebGL runs on SwiftShader (software)."""
import base64
import io
import json
import os
import shutil
import subprocess
import tempfile
import time
import urllib.request

import websocket
from PIL import Image


class HeadlessBrowser:
    def __init__(self, url, width=1200, height=800):
        chromium = shutil.which("chromium")
        assert chromium, "chromium is missing: scripts/test.sh installs it (apt install chromium)"
        self.profile = tempfile.mkdtemp(prefix="airshape-chromium-")
        self.process = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu-sandbox", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--no-first-run", "--remote-debugging-port=0",
             f"--user-data-dir={self.profile}", f"--window-size={width},{height}", url],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        port = self._devtools_port()
        page = self._page_target(port)
        self.socket = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=60)
        self.next_id = 0

    def _devtools_port(self):
        marker = os.path.join(self.profile, "DevToolsActivePort")
        deadline = time.time() + 60
        while time.time() < deadline:
            if os.path.exists(marker):
                with open(marker) as f:
                    lines = f.read().split()
                if lines:
                    return int(lines[0])
            time.sleep(0.1)
        raise AssertionError("chromium did not start its DevTools server")

    @staticmethod
    def _page_target(port):
        deadline = time.time() + 60
        while time.time() < deadline:
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list") as answer:
                pages = [t for t in json.load(answer) if t["type"] == "page"]
            if pages:
                return pages[0]
            time.sleep(0.1)
        raise AssertionError("chromium opened no page")

    def call(self, method, **params):
        self.next_id += 1
        self.socket.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.socket.recv())
            if message.get("id") == self.next_id:
                assert "error" not in message, message
                return message["result"]

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        return result["result"].get("value")

    def wait_for(self, expression, timeout=90):
        """Waits until the expression is truthy in the page; returns its value."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            value = self.evaluate(expression)
            if value:
                return value
            time.sleep(0.2)
        raise AssertionError(f"the page never gave {expression}")

    def screenshot(self):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        return Image.open(io.BytesIO(base64.b64decode(data))).convert("RGB")

    def close(self):
        try:
            self.socket.close()
        finally:
            self.process.terminate()
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()
            shutil.rmtree(self.profile, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()


def drawn_share(image, box):
    """The share of pixels in a box of the picture that differ clearly from the background
    (the colour at the left end of their row: the page's background is a vertical gradient),
    and the number of colours there: a blank view has neither."""
    region = image.crop(box)
    width, height = region.size
    pixels = region.load()
    drawn, colours = 0, set()
    for y in range(0, height, 2):
        background = pixels[2, y]
        for x in range(0, width, 2):
            colour = pixels[x, y]
            colours.add(colour)
            drawn += sum(abs(a - b) for a, b in zip(colour, background)) > 30
    return drawn / ((height + 1) // 2 * ((width + 1) // 2)), len(colours)
