#!/usr/bin/env python3
"""What the page `dinam view` writes costs: its size, and how long a frame takes to draw in
Debian's chromium, headless (WebGL on SwiftShader, the CPU: a machine with a GPU draws faster).

    python3 bench/view_page.py build/dinam [--keep DIR]

Simulates a 100 x 100 cloth falling onto a pole (10 000 points, 48 frames) and the end-to-end
flag of the tests, writes each page, and opens it at #bench: the page draws every frame in turn
for two seconds, each drawing finished (gl.finish), and writes the median time on its body.
Prints one line per page: its size in MB and the median draw in ms (and frames per second).
The targets (issue 53): the cloth's page at most 3 MB and drawn at 30 frames per second or more.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

CLOTH = """version: 1
name: cloth_100
duration: 2.4
fps: 20
timestep: auto
gravity: [0, 0, -9.81]
objects:
  - name: cloth
    mesh:
      grid: {width: 1.0, height: 1.0, columns: 99, rows: 99, diagonals: one}
      translation: [0, 0, 1.0]
    material: {preset: cotton}
    pinned: {box: {min: [-0.51, 0.49, 0.9], max: [0.51, 0.51, 1.1]}}
"""

CHROMIUM = ["/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
            "--no-first-run", "--disable-background-networking", "--disable-component-update",
            "--disable-sync", "--hide-scrollbars", "--window-size=960,540"]


def page_of(dinam, scene, work, name):
    cache = os.path.join(work, name)
    subprocess.run([dinam, "simulate", scene, "-o", cache, "--format", "pc2", "--quiet",
                    "--force"], check=True)
    subprocess.run([dinam, "view", cache, "--quiet"], check=True)
    return cache + ".html"


class Browser:
    """Chromium driven over its DevTools protocol on a pipe (--remote-debugging-pipe: it reads
    commands on fd 3 and answers on fd 4, each a JSON message ended by a NUL), in real time, so
    that the page's own clock measures its drawing."""

    def __init__(self, work):
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()
        os.set_inheritable(to_chrome_r, True)
        os.set_inheritable(from_chrome_w, True)

        def fds():  # the child's fds 3 and 4
            os.dup2(to_chrome_r, 3)
            os.dup2(from_chrome_w, 4)

        self.process = subprocess.Popen(
            CHROMIUM + [f"--user-data-dir={work}/profile", "--remote-debugging-pipe",
                        "about:blank"],
            preexec_fn=fds, pass_fds=(3, 4),  # kept open after fds() made them
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.next_id = 0
        self.pending = b""

    def call(self, method, session=None, **params):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = session
        os.write(self.to_chrome, json.dumps(message).encode() + b"\0")
        while True:
            while b"\0" not in self.pending:
                chunk = os.read(self.from_chrome, 1 << 20)
                if not chunk:
                    raise SystemExit("chromium closed its pipe")
                self.pending += chunk
            text, self.pending = self.pending.split(b"\0", 1)
            answer = json.loads(text)
            if answer.get("id") == self.next_id:
                if "error" in answer:
                    raise SystemExit(f"{method}: {answer['error']}")
                return answer["result"]

    def close(self):
        self.process.kill()
        self.process.wait()


def measure(browser, page):
    target = browser.call("Target.createTarget", url=f"file://{page}#bench&controls=no")
    session = browser.call("Target.attachToTarget", targetId=target["targetId"],
                           flatten=True)["sessionId"]
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        body = browser.call("Runtime.evaluate", session,
                            expression="JSON.stringify(document.body.dataset)",
                            returnByValue=True)["result"].get("value")
        data = json.loads(body) if body else {}
        if data.get("errors", "0") != "0":
            raise SystemExit(f"{page}: {data.get('lastError')}")
        if data.get("status") == "ready" and "drawMs" in data:
            browser.call("Target.closeTarget", targetId=target["targetId"])
            return float(data["drawMs"])
        time.sleep(0.2)
    raise SystemExit(f"{page}: the page did not measure itself in two minutes")


def main():
    dinam = os.path.abspath(sys.argv[1])
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    work = tempfile.mkdtemp(prefix="dinam-view-bench-")
    try:
        cloth_scene = os.path.join(work, "cloth_100.yaml")
        with open(cloth_scene, "w") as f:
            f.write(CLOTH)
        browser = Browser(work)
        for name, scene in (("cloth_100", cloth_scene),
                            ("end_to_end_flag",
                             os.path.join(source, "tests", "data", "end_to_end_flag.yaml"))):
            page = page_of(dinam, scene, work, name)
            ms = measure(browser, page)
            print(f"{name}: page {os.path.getsize(page) / 1e6:.2f} MB, a frame drawn in "
                  f"{ms:.1f} ms ({1000 / ms:.0f} frames per second)")
        browser.close()
    finally:
        if "--keep" not in sys.argv:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
