#!/usr/bin/python3
"""End-to-end test of the play page in headless Chromium, driven through the
DevTools protocol (Debian python3-websocket), the way a person uses it.

Doors-Keys-Gems, problem 2 (plan 2.1.keys), exactly as the README's quick
start says: type "Can you pass me the red key?", press Enter and, without
clicking anywhere, press the arrow keys (up three times, left six times) in
turn, then W once. A key pressed while the robot thinks is not played (the
page says it is thinking); the robot picks up the red key and hands it over.
Then the instruction box's byte limit (300 x "é" is refused visibly, and a
server rejection keeps the text), the chart's legend, the rest of the
human's plan to the goal (buttons and keys; the board then takes no more
moves), and "Why it acted" after undo and a method switch.

Then two packs without pictures, in the page's text scene: the workshop
dataset (problem 1) and the kitchen of docs/domains.md served from a folder
without any plan file (problem 2, tests/serve/kitchen-2.pddl): action
buttons, an instruction, the robot answering. Writes screenshots
(SCREENSHOT, its -small copy for docs/img/serve.png, -workshop, -kitchen).

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

KEYS = {"up": ("ArrowUp", 38), "down": ("ArrowDown", 40), "left": ("ArrowLeft", 37), "right": ("ArrowRight", 39),
        "w": ("w", 87)}

# The README's quick start, key by key (checked against the README's words below).
QUICK_START_WORDS = "up three times, then left six times, then W once"
QUICK_START_KEYS = ["up"] * 3 + ["left"] * 6 + ["w"]


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

    def enter(self):
        """Enter as typed (keydown with its text, so that the form submits)."""
        self.call("Input.dispatchKeyEvent", type="keyDown", key="Enter", code="Enter", windowsVirtualKeyCode=13,
                  text="\r", unmodifiedText="\r")
        self.call("Input.dispatchKeyEvent", type="keyUp", key="Enter", code="Enter", windowsVirtualKeyCode=13)

    def type_into(self, element_id, text):
        """Click into a text box and type (insertText, as an input method does)."""
        self.js("document.getElementById(%s).focus()" % json.dumps(element_id))
        self.call("Input.insertText", text=text)

    def screenshot(self, path, clip=None):
        params = {"format": "png"}
        if clip:
            params["clip"] = clip
        png = self.call("Page.captureScreenshot", **params)
        with open(path, "wb") as f:
            f.write(base64.b64decode(png["data"]))
        print("screenshot: " + path)

    def close(self):
        try:
            self.ws.close()
        finally:
            self.proc.kill()
            self.proc.wait()
            shutil.rmtree(self.profile, ignore_errors=True)


IDLE = "window.clips && window.clips.session && !window.clips.busy && window.clips.queue.length === 0"
FOCUS_ON_BOARD = "document.activeElement && document.activeElement.id === 'board'"


class Checks:
    def __init__(self):
        self.failures = []

    def __call__(self, ok, what):
        if not ok:
            print("FAIL: " + what)
            self.failures.append(what)
        return ok


def kitchen_folder(source_dir, root):
    """The kitchen of docs/domains.md without any plan file, plus problem 2."""
    sys.path.insert(0, os.path.join(source_dir, "tests", "domains"))
    from docs_example_test import extract  # noqa: E402
    with open(os.path.join(source_dir, "docs", "domains.md"), encoding="utf-8") as f:
        files = extract(f.read())
    for path, body in files.items():
        if "/plans/" in path:
            continue
        full = os.path.join(root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w", encoding="utf-8") as out:
            out.write(body)
    shutil.copy(os.path.join(source_dir, "tests", "serve", "kitchen-2.pddl"),
                os.path.join(root, "kitchen", "problems", "2.pddl"))
    return os.path.join(root, "kitchen")


def start_session(browser, dataset, problem, plan=None, method="clips"):
    old = browser.js("window.clips.session")
    browser.js("""(() => {
        const set = (id, v) => { const s = document.getElementById(id); s.value = v; s.dispatchEvent(new Event('change')); };
        set('dataset', %s); set('problem', %s); if (%s !== null) set('plan', %s); set('method', %s); })()""" % (
        json.dumps(dataset), json.dumps(problem), json.dumps(plan), json.dumps(plan), json.dumps(method)))
    # A method switch on the running session keeps the page thinking (and
    # Start disabled) for a moment.
    browser.wait_for("window.clips && !window.clips.busy && !document.getElementById('start').disabled",
                     "the page to take Start")
    browser.js("document.getElementById('start').click()")
    browser.wait_for(IDLE + " && window.clips.state && window.clips.session !== %s" % json.dumps(old),
                     "the session on %s problem %s to start" % (dataset, problem))
    return browser.js("window.clips.state")


def robot_log(browser):
    return browser.js("[...document.querySelectorAll('#log li.robot')].map(li => li.textContent)")


def click_action(browser, action):
    """Clicks the button of an action; False when the page shows none."""
    return browser.js("(() => { const b = [...document.querySelectorAll('#verbs button')]"
                      ".find(b => b.dataset.action === %s); if (!b || b.disabled) return false; b.click(); return true; })()"
                      % json.dumps(action))


def play_quick_start(browser, source_dir, dkg, shot, check):
    """The README's quick start on mDKG problem 2, then the page's details."""
    with open(os.path.join(source_dir, "README.md"), encoding="utf-8") as f:
        readme = " ".join(f.read().split())
    check(QUICK_START_WORDS in readme, "the README's quick start no longer says '%s'" % QUICK_START_WORDS)
    completed = [l.strip() for l in open(os.path.join(dkg, "plans", "completed", "2.1.keys.pddl"))
                 if l.strip().startswith("(")]
    state = start_session(browser, "doors-keys-gems", "2", "2.1.keys")
    true_goal = state["true_goal"]
    # The player's goal: the plan's by default, offered among the problem's
    # candidate goals, kept from the assistant and shown to the player only.
    choices = browser.js("[...document.getElementById('goal').options].map(o => o.value)")
    goals = [g["goal"] for g in state["posterior"]["goals"]]
    check(choices == ["plan", "none"] + goals, "the goal menu offers %s, not the plan's, none and %s" % (choices, goals))
    check(state["player_goal"] == true_goal, "the player's goal is %s, not the plan's %s" % (state["player_goal"], true_goal))
    # Goals in words, from their conditions and the scene; the label is the tooltip.
    words = browser.js("[...document.querySelectorAll('#bars .bar')].map(b => [b.dataset.goal, "
                       "b.querySelector('.label').textContent, b.querySelector('.label').title])")
    for goal, text, title in words:
        check(text.startswith("human has the ") and text.endswith(" gem") and title.startswith(goal),
              "goal %s reads '%s' (tooltip '%s'), not in words" % (goal, text, title))
    # The status names the player's goal in the same words, not by its label.
    said = dict((g, t) for g, t, _ in words).get(true_goal, "?")
    status = browser.js("document.getElementById('status').textContent")
    check(("Your goal: %s " % said) in status and true_goal not in status,
          "the status does not say the player's goal in words: " + status)

    # Type the instruction and press Enter: the focus is back on the board.
    # While the assistant thinks the page plays no key and keeps none for
    # later: two keys in one go play once, and the page says it is thinking.
    browser.type_into("utterance", "Can you pass me the red key?")
    browser.enter()
    check(browser.js(FOCUS_ON_BOARD), "after Enter in the instruction box the focus is not on the board")
    browser.wait_for(IDLE, "the instruction to be heard")
    t0 = browser.js("window.clips.state.t")
    thinking = browser.js("(() => { for (let i = 0; i < 2; ++i) document.dispatchEvent(new KeyboardEvent('keydown', "
                          "{key: 'ArrowUp', bubbles: true})); return [window.clips.busy, window.clips.ignoredKeys, "
                          "!document.getElementById('thinking').hidden, document.getElementById('send').disabled, "
                          "document.getElementById('start').disabled]; })()")
    check(thinking == [True, 1, True, True, True],
          "a key pressed while thinking: [busy, ignored keys, 'thinking' shown, Say disabled, Start disabled] = %s"
          % thinking)
    browser.wait_for(IDLE + " && window.clips.state.t > %d" % t0, "the first key and the robot's reply")
    check(browser.js("document.getElementById('thinking').hidden"), "the page still says it is thinking")
    for k in QUICK_START_KEYS[1:-1]:
        t = browser.js("window.clips.state.t")
        browser.key(k)
        browser.wait_for(IDLE + " && window.clips.state.t > %d" % t, "the key '%s' and the robot's reply" % k)
    state = browser.js("window.clips.state")
    humans = [a for a in browser.js("[...document.querySelectorAll('#log li:not(.robot):not(.say):not(.err)')]"
                                    ".map(li => li.textContent)") if a.startswith("(")]
    moves = ["(%s human)" % k for k in QUICK_START_KEYS[:-1]]
    check(humans == moves, "the keys were not all applied in order: %s" % humans)
    check(state["t"] == 2 * len(moves), "after %d keys the step is %d, not %d" % (len(moves), state["t"], 2 * len(moves)))
    check(browser.js("window.clips.maxQueued") == 0, "keys were queued while the assistant thought (maxQueued %s)"
          % browser.js("window.clips.maxQueued"))
    check(state["reading"] is not None and state["reading"]["utterance"] == "Can you pass me the red key?",
          "the instruction was not heard")
    check(browser.js("document.getElementById('utterance').value") == "", "a heard instruction stayed in the box")
    browser.key(QUICK_START_KEYS[-1])  # W: wait
    browser.wait_for(IDLE + " && window.clips.state.t > %d" % state["t"], "the wait and the robot's reply")
    log = robot_log(browser)
    print("assistant actions: " + " ".join(log))
    check("(pickup robot key2)" in log and "(handover robot human key2)" in log,
          "the quick start did not reach the hand-over of the red key: %s" % log)
    browser.screenshot(shot)
    # A smaller copy of the page area for the README (docs/img/serve.png).
    browser.screenshot(shot[:-4] + "-small.png", {"x": 0, "y": 0, "width": 1090, "height": 800, "scale": 0.6})

    # The chart's legend: one entry per goal, every line drawn differently.
    legend = browser.js("[...document.querySelectorAll('#legend .key')].map(k => [k.dataset.goal, k.dataset.dash, k.dataset.marker])")
    goals = [g["goal"] for g in browser.js("window.clips.state.posterior.goals")]
    check([l[0] for l in legend] == goals, "the legend lists %s, not the goals %s" % (legend, goals))
    check(len({(l[1], l[2]) for l in legend}) == len(legend), "two lines of the chart look alike: %s" % legend)

    # The instruction box counts UTF-8 bytes as the server does: 300 x "é" is
    # 600 bytes, refused visibly and kept.
    t = browser.js("window.clips.state.t")
    history = len(browser.js("window.clips.state.history"))
    browser.type_into("utterance", "\u00e9" * 300)
    check(browser.js("document.getElementById('bytes').textContent") == "600/500 bytes", "the byte counter says %s"
          % browser.js("document.getElementById('bytes').textContent"))
    check(browser.js("document.getElementById('send').disabled"), "Say is enabled for 600 bytes")
    check(not browser.js("document.getElementById('say-error').hidden") and
          "Too long" in browser.js("document.getElementById('say-error').textContent"), "no visible 'too long' note")
    browser.enter()
    browser.wait_for(IDLE, "the page to settle")
    check(len(browser.js("window.clips.state.history")) == history, "an over-long instruction was sent")
    check(browser.js("document.getElementById('utterance').value") == "\u00e9" * 300, "an over-long instruction was lost")
    # Should the server refuse one anyway, the text stays and the reason shows.
    browser.js("window.clips.utteranceBytes = 100000; document.getElementById('utterance').dispatchEvent(new Event('input'))")
    browser.js("document.getElementById('utterance').focus()")
    browser.enter()
    browser.wait_for(IDLE + " && !document.getElementById('say-error').hidden && "
                     "document.getElementById('say-error').textContent.includes('Not heard')", "the server's refusal")
    check("500 bytes" in browser.js("document.getElementById('say-error').textContent"),
          "the refusal does not say the limit: " + browser.js("document.getElementById('say-error').textContent"))
    check(browser.js("document.getElementById('utterance').value") == "\u00e9" * 300, "a refused instruction was cleared")
    browser.js("window.clips.utteranceBytes = window.clips.catalogue.limits.utterance_bytes;"
               "document.getElementById('utterance').value = ''; document.getElementById('utterance').dispatchEvent(new Event('input'))")
    check(browser.js("window.clips.state.t") == t, "the refused instructions moved the game")

    # The rest of the human's part of the completed plan, after the hand-over:
    # buttons and keys; the focus returns to the board after each click.
    rest = completed[completed.index("(handover robot human key2)") + 1:]
    rest = [a for a in rest if a.split()[1].rstrip(")") == "human"]
    steps = 0
    while rest and steps < 30 and not browser.js("window.clips.state.reached_goal"):
        action = rest[0] if rest[0] in browser.js("window.clips.state.actions") else "(wait human)"
        if action == rest[0]:
            rest.pop(0)
        t0 = browser.js("window.clips.state.t")
        verb = action[1:-1].split()[0]
        if verb in KEYS:
            browser.key(verb)
        elif verb == "wait":
            browser.key("w")
        else:
            check(click_action(browser, action), "no button for " + action)
            check(browser.js(FOCUS_ON_BOARD), "after clicking %s the focus is not on the board" % action)
        browser.wait_for(IDLE + " && window.clips.state.t > %d" % t0, "the turn after " + action)
        steps += 1
    final = browser.js("window.clips.state")
    bars = browser.js("[...document.querySelectorAll('#bars .bar')].map(b => [b.dataset.goal, parseFloat(b.dataset.p)])")
    print("posterior bars: " + ", ".join("%s=%.3f" % (g, p) for g, p in bars))
    print("goal reached: %s after %d steps" % (final["reached_goal"], final["t"]))
    check(final["reached_goal"] == true_goal, "the game did not end at the true goal %s" % true_goal)
    check(max(bars, key=lambda b: b[1])[0] == true_goal, "the bars do not put the true goal %s ahead" % true_goal)

    # After the goal the board takes no more moves, and says so.
    status = browser.js("document.getElementById('status').textContent")
    check(status.startswith("Goal reached: %s " % said), "the status does not say the goal reached in words: " + status)
    # Each reading of the instruction in words, the PDDL form one click away.
    rows = browser.js("[...document.querySelectorAll('#reading details.pddl')].map(d => "
                      "[d.querySelector('summary').textContent, d.querySelector('code').textContent])")
    print("readings: " + " | ".join(w for w, _ in rows))
    check(rows and all(not w.startswith("(") and "?" not in w and p.startswith("(") for w, p in rows),
          "the readings are not in words: %s" % rows)
    check(any(w.startswith("robot: ") and "red key" in w for w, _ in rows),
          "no reading says the robot should fetch the red key: %s" % rows)
    check(browser.js("[...document.querySelectorAll('#controls button')].every(b => b.disabled)"),
          "buttons stay live after the goal")
    browser.key("up")
    browser.wait_for("[...document.querySelectorAll('#log li.err')].some(li => li.textContent.includes('goal is reached'))",
                     "the page to refuse a move after the goal")
    browser.wait_for(IDLE, "the page to settle")
    check(browser.js("window.clips.state.t") == final["t"], "a key moved the human after the goal")

    # "Why it acted" keeps the decision still in the history after undo and a method switch.
    browser.js("document.getElementById('undo').click()")
    browser.wait_for(IDLE + " && window.clips.state.t < %d" % final["t"], "the undo")
    state = browser.js("window.clips.state")
    text = browser.js("document.getElementById('decision').textContent")
    check(state["decision"] is not None and "has not acted" not in text and "Decided after step" in text,
          "after undo 'Why it acted' says: " + text[:120])
    browser.js("(() => { const s = document.getElementById('method'); s.value = 'lang_only';"
               " s.dispatchEvent(new Event('change')); })()")
    browser.wait_for(IDLE + " && window.clips.state.method === 'lang_only'", "the method switch")
    text = browser.js("document.getElementById('decision').textContent")
    check("before the switch to language-only" in text, "after a method switch 'Why it acted' says: " + text[:160])
    check(browser.js(FOCUS_ON_BOARD), "after the method switch the focus is not on the board")


def play_text_scene(browser, dataset, problem, plan, first, instruction, second, shot, check):
    """A pack without pictures: its text scene, buttons, an instruction, the robot answering."""
    state = start_session(browser, dataset, problem, plan)
    check(state["scene"]["kind"] == "text", "%s: the scene is %s" % (dataset, state["scene"]["kind"]))
    check(not browser.js("document.getElementById('textscene').hidden"), dataset + ": the text scene is hidden")
    check(browser.js("document.getElementById('grid').hidden"), dataset + ": the grid is shown")
    place = first.split()[-1].rstrip(")")
    check(browser.js("!!document.querySelector('#textscene .card[data-place=%s]')" % json.dumps(place)),
          "%s: no card for %s" % (dataset, place))
    robot_before = len(robot_log(browser))
    check(click_action(browser, first), "%s: no button for %s" % (dataset, first))
    check(browser.js(FOCUS_ON_BOARD), dataset + ": after clicking a button the focus is not on the board")
    browser.wait_for(IDLE + " && window.clips.state.t >= 2", dataset + ": the robot's reply")
    browser.type_into("utterance", instruction)
    started = time.time()
    browser.enter()
    browser.wait_for(IDLE + " && window.clips.state.reading", dataset + ": the instruction to be heard")
    # The server prepared the domain's language model before it listened.
    heard = time.time() - started
    print("%s: the first instruction answered in %.2f s" % (dataset, heard))
    check(heard < 2, "%s: the first instruction took %.1f s" % (dataset, heard))
    check(browser.js("document.getElementById('utterance').value") == "", dataset + ": the heard instruction stayed")
    t0 = browser.js("window.clips.state.t")
    check(click_action(browser, second), "%s: no button for %s" % (dataset, second))
    browser.wait_for(IDLE + " && window.clips.state.t > %d" % t0, dataset + ": the robot's reply to " + second)
    state = browser.js("window.clips.state")
    log = robot_log(browser)
    print("%s problem %s: assistant actions %s; reading %s" % (
        dataset, problem, " ".join(log), state["reading"]["commands"][:1]))
    check(len(log) >= robot_before + 2, dataset + ": the robot did not answer both moves")
    check(state["decision"] is not None and state["decision"]["candidates"], dataset + ": no decision with candidates")
    check(state["turn"] == state["principal"], dataset + ": not the human's turn after the robot")
    changed = browser.js("document.getElementById('changed').textContent")
    check("+ " in changed, dataset + ": the scene does not show what changed: " + changed)
    browser.screenshot(shot)


def main():
    clips, source_dir, shot = sys.argv[1], sys.argv[2], sys.argv[3]
    dkg = os.path.join(dataset_root(source_dir), "doors-keys-gems")
    if not os.path.exists(os.path.join(dkg, "domain.pddl")):
        print("skipped: no dataset at " + dkg)
        return SKIP
    workshop = os.path.join(source_dir, "data", "datasets", "workshop")
    tmp = tempfile.mkdtemp(prefix="clips-e2e-kitchen-")
    kitchen = kitchen_folder(source_dir, tmp)
    check = Checks()
    server = Server(clips, [dkg, workshop, kitchen])
    browser = Browser()
    try:
        browser.call("Page.enable")
        browser.call("Runtime.enable")
        browser.call("Emulation.setDeviceMetricsOverride", width=1120, height=820, deviceScaleFactor=1, mobile=False)
        browser.call("Page.navigate", url=server.url)
        browser.wait_for("window.clips && window.clips.catalogue !== null && document.querySelectorAll('#problem option').length > 0",
                         "the dataset list")
        play_quick_start(browser, source_dir, dkg, shot, check)
        play_text_scene(browser, "workshop", "1", "1.1.table", "(move human bench rack)",
                        "Can you bring the big plank over to the bench?", "(move human rack toolwall)",
                        shot[:-4] + "-workshop.png", check)
        browser.js("(() => { const s = document.getElementById('dataset'); s.value = 'kitchen';"
                   " s.dispatchEvent(new Event('change')); })()")
        check(browser.js("[...document.querySelectorAll('#problem option')].map(o => o.value)") == ["1", "2"],
              "the kitchen's problems are not listed")
        play_text_scene(browser, "kitchen", "2", "", "(move cook counter pantry)", "Can you fetch the milk?",
                        "(take cook flour1 pantry)", shot[:-4] + "-kitchen.png", check)
        # A phone's width: the page fits 390 px without scrolling sideways.
        browser.call("Emulation.setDeviceMetricsOverride", width=390, height=844, deviceScaleFactor=1, mobile=True)
        time.sleep(0.3)
        wide = browser.js("document.documentElement.scrollWidth")
        check(wide <= 390, "at 390 px wide the page is %s px wide" % wide)
        browser.screenshot(shot[:-4] + "-390.png", {"x": 0, "y": 0, "width": 390, "height": 844, "scale": 1})
    finally:
        browser.close()
        shutil.rmtree(tmp, ignore_errors=True)
        code = server.stop()
        if code != 0:
            check(False, "server exit code %d" % code)
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
