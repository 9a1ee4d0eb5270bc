#!/usr/bin/python3
"""End-to-end test of the play page in headless Chromium, driven through the
DevTools protocol (Debian python3-websocket): load the page, start mDKG
problem 2 (reference plan 2.1.keys), type "Can you pass me the red key?",
play the human's observed moves with the arrow keys, then keep playing the
human's part of the completed plan (waiting when a move does not apply).
Checks that the assistant picks up and hands over the key the true goal needs
and that the posterior bars put the true gem ahead. Writes a screenshot.

usage: browser_e2e.py CLIPS_BINARY SOURCE_DIR SCREENSHOT_PNG
"""
import base64
import itertools
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.request

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_harness import SKIP, Server, dataset_root  # noqa: E402

import websocket  # Debian python3-websocket

KEYS = {"up": ("ArrowUp", 38), "down": ("ArrowDown", 40), "left": ("ArrowLeft", 37), "right": ("ArrowRight", 39)}


class Browser:
    def __init__(self):
        exe = shutil.which("chromium") or shutil.which("chromium-browser")
        if not exe:
            raise RuntimeError("chromium is not installed (scripts/install-deps.sh installs it)")
        self.profile = tempfile.mkdtemp(prefix="clips-e2e-")
        self.proc = subprocess.Popen(
            [exe, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-extensions",
             "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0",
             "--user-data-dir=" + self.profile, "--window-size=1200,900", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        port = None
        deadline = time.time() + 60
        while time.time() < deadline and port is None:
            line = self.proc.stderr.readline()
            m = re.search(r"DevTools listening on ws://127\.0\.0\.1:(\d+)/", line)
            if m:
                port = int(m.group(1))
        if port is None:
            raise RuntimeError("chromium did not start")
        targets = json.load(urllib.request.urlopen("http://127.0.0.1:%d/json/list" % port))
        page = next(t for t in targets if t["type"] == "page")
        self.ws = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=120, suppress_origin=True)
        self.ids = itertools.count(1)

    def call(self, method, **params):
        i = next(self.ids)
        self.ws.send(json.dumps({"id": i, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == i:
                if "error" in msg:
                    raise RuntimeError("%s: %s" % (method, msg["error"]))
                return msg.get("result", {})

    def js(self, expr):
        r = self.call("Runtime.evaluate", expression=expr, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in r:
            raise RuntimeError("JS error in %s: %s" % (expr, r["exceptionDetails"]))
        return r["result"].get("value")

    def wait_for(self, expr, what, timeout=120):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if self.js(expr):
                return
            time.sleep(0.05)
        raise AssertionError("timed out waiting for " + what)

    def key(self, name):
        key, code = KEYS[name]
        for kind in ("rawKeyDown", "keyUp"):
            self.call("Input.dispatchKeyEvent", type=kind, key=key, code=key, windowsVirtualKeyCode=code)

    def close(self):
        try:
            self.ws.close()
        finally:
            self.proc.kill()
            self.proc.wait()
            shutil.rmtree(self.profile, ignore_errors=True)


IDLE = "window.clips && window.clips.session && !window.clips.busy"


def main():
    clips, source_dir, shot = sys.argv[1], sys.argv[2], sys.argv[3]
    dkg = os.path.join(dataset_root(source_dir), "doors-keys-gems")
    if not os.path.exists(os.path.join(dkg, "domain.pddl")):
        print("skipped: no dataset at " + dkg)
        return SKIP
    completed = [l.strip() for l in open(os.path.join(dkg, "plans", "completed", "2.1.keys.pddl"))
                 if l.strip().startswith("(")]
    needed = [a for a in completed if re.match(r"\((pickup|handover) robot", a)]

    server = Server(clips, [dkg])
    browser = Browser()
    failures = []
    try:
        browser.call("Page.enable")
        browser.call("Runtime.enable")
        browser.call("Emulation.setDeviceMetricsOverride", width=1120, height=820, deviceScaleFactor=1, mobile=False)
        browser.call("Page.navigate", url=server.url)
        browser.wait_for("window.clips && window.clips.catalogue !== null && document.querySelectorAll('#problem option').length > 0",
                         "the dataset list")
        browser.js("""(() => {
            const set = (id, v) => { const s = document.getElementById(id); s.value = v; s.dispatchEvent(new Event('change')); };
            set('dataset', 'doors-keys-gems'); set('problem', '2'); set('plan', '2.1.keys'); set('method', 'clips');
            document.getElementById('start').click(); })()""")
        browser.wait_for(IDLE + " && window.clips.state", "the session to start")
        state = browser.js("window.clips.state")
        true_goal = state["true_goal"]
        moves = state["observed_moves"]
        print("true goal %s; observed human moves %s" % (true_goal, moves))

        # Type the instruction like a person: focus the box, insert the text, press the Say button.
        browser.js("document.getElementById('utterance').focus()")
        browser.call("Input.insertText", text="Can you pass me the red key?")
        browser.js("document.getElementById('send').click()")
        browser.wait_for(IDLE + " && window.clips.state.reading", "the instruction to be heard")

        def play(action):
            t0 = browser.js("window.clips.state.t")
            verb = action[1:-1].split()[0]
            if verb in KEYS:
                browser.js("document.activeElement && document.activeElement.blur()")
                browser.key(verb)
            else:
                ok = browser.js("(() => { const b = [...document.querySelectorAll('#verbs button')]"
                                ".find(b => b.dataset.action === %s); if (!b) return false; b.click(); return true; })()"
                                % json.dumps(action))
                if not ok:
                    raise AssertionError("no button for " + action)
            browser.wait_for(IDLE + " && window.clips.state.t > %d && (window.clips.state.turn === 'human' "
                             "|| window.clips.state.reached_goal)" % t0, "the turn after " + action)

        for a in moves:
            play(a)
        # The rest of the human's part of the completed plan, in order; wait when a step does not apply yet.
        rest = [a for a in completed if " human" in a.split(")")[0] and a.startswith("(") and a.split()[1].startswith("human")]
        steps = 0
        shot_taken = False

        def screenshot():
            png = browser.call("Page.captureScreenshot", format="png")
            with open(shot, "wb") as f:
                f.write(base64.b64decode(png["data"]))
            # A smaller copy of the page area for the README (docs/img/serve.png).
            small = browser.call("Page.captureScreenshot", format="png",
                                 clip={"x": 0, "y": 0, "width": 1090, "height": 800, "scale": 0.6})
            with open(shot[:-4] + "-small.png", "wb") as f:
                f.write(base64.b64decode(small["data"]))
            print("screenshot: " + shot)

        while rest and steps < 40 and not browser.js("window.clips.state.reached_goal"):
            legal = browser.js("window.clips.state.actions")
            if rest[0] in legal:
                play(rest.pop(0))
            else:
                play("(wait human)")
            steps += 1
            # The picture right after the hand-over shows the assistant's reasons for it.
            if not shot_taken and browser.js("[...document.querySelectorAll('#log li.robot')]"
                                             ".some(li => li.textContent.startsWith('(handover'))"):
                screenshot()
                shot_taken = True

        log = browser.js("[...document.querySelectorAll('#log li.robot')].map(li => li.textContent)")
        bars = browser.js("[...document.querySelectorAll('#bars .bar')].map(b => [b.dataset.goal, parseFloat(b.dataset.p)])")
        final = browser.js("window.clips.state")
        print("assistant actions: " + " ".join(log))
        print("posterior bars: " + ", ".join("%s=%.3f" % (g, p) for g, p in bars))
        print("goal reached: %s after %d steps" % (final["reached_goal"], final["t"]))
        for a in needed:
            if a not in log:
                failures.append("the assistant never did " + a)
        if needed and all(a in log for a in needed) and log.index(needed[0]) > log.index(needed[-1]):
            failures.append("hand-over before pick-up")
        top = max(bars, key=lambda b: b[1])
        if top[0] != true_goal:
            failures.append("posterior bars put %s ahead, not the true goal %s" % (top[0], true_goal))
        if not shot_taken:
            screenshot()
    finally:
        browser.close()
        code = server.stop()
        if code != 0:
            failures.append("server exit code %d" % code)
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
