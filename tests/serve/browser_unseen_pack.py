#!/usr/bin/python3
"""The play page on a domain nobody has seen, in headless Chromium (issue 62).

The test writes a small domain folder of its own into a temporary directory
(domain.pddl, one problem, pack.json; no plan file, nothing from data/): an
attic whose chest stands in a room with books inside it. It starts the
browser, then `clips serve` on that folder, and plays as a person would:

  * a session on the problem without a plan, the player's goal picked from
    the menu; the first instruction is answered within 2 s of the server's
    "listening" line (the language model is prepared before it listens);
  * a key pressed while the assistant thinks is not played, nor queued;
  * the goal bars and the status say the goals in words, never by label;
  * the text scene draws the chest in its room with the books inside;
  * the readings of the instruction are in words, the PDDL one click away;
  * the human walks (buttons) and waits (W) while the robot works, until
    the player's goal holds;
  * at 390 px the page is no wider than the screen.

Writes screenshots: SCREENSHOT (1120 px wide) and its -390 copy.

usage: browser_unseen_pack.py CLIPS_BINARY SOURCE_DIR SCREENSHOT_PNG
"""
import json
import os
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser_e2e import IDLE, Browser, Checks, click_action, robot_log  # noqa: E402
from serve_harness import Server  # noqa: E402

DOMAIN = """(define (domain attic)
  (:requirements :typing :negative-preconditions :equality)
  (:types agent item room chest colour - object
          book candle - item)
  (:predicates (at ?a - agent ?r - room) (door ?r - room ?s - room) (in ?i - item ?r - room) (inside ?i - item ?c - chest)
               (stands ?c - chest ?r - room) (holding ?a - agent ?i - item) (open ?c - chest)
               (iscolour ?i - item ?c - colour))
  (:action move
   :parameters (?a - agent ?from - room ?to - room)
   :precondition (and (at ?a ?from) (door ?from ?to))
   :effect (and (not (at ?a ?from)) (at ?a ?to)))
  (:action open
   :parameters (?a - agent ?c - chest ?r - room)
   :precondition (and (at ?a ?r) (stands ?c ?r) (not (open ?c)))
   :effect (open ?c))
  (:action take
   :parameters (?a - agent ?i - item ?r - room)
   :precondition (and (at ?a ?r) (in ?i ?r))
   :effect (and (not (in ?i ?r)) (holding ?a ?i)))
  (:action takeout
   :parameters (?a - agent ?i - item ?c - chest ?r - room)
   :precondition (and (at ?a ?r) (stands ?c ?r) (open ?c) (inside ?i ?c))
   :effect (and (not (inside ?i ?c)) (holding ?a ?i)))
  (:action handover
   :parameters (?a - agent ?b - agent ?i - item ?r - room)
   :precondition (and (not (= ?a ?b)) (at ?a ?r) (at ?b ?r) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i))))
"""

PROBLEM = """(define (problem attic-1)
  (:domain attic)
  (:objects human robot - agent
            hall landing attic - room
            chest1 - chest
            book1 book2 book3 - book
            candle1 - candle
            red blue green white - colour)
  (:init (at human hall) (at robot landing)
         (door hall landing) (door landing hall) (door landing attic) (door attic landing)
         (stands chest1 attic)
         (inside book1 chest1) (iscolour book1 red)
         (inside book2 chest1) (iscolour book2 blue)
         (in book3 landing) (iscolour book3 green)
         (in candle1 hall) (iscolour candle1 white)))
"""

PACK = {
    "domain": "attic",
    "roles": {"principal": "human", "assistant": "robot", "turns": "alternate", "horizon": 60},
    "goals": {"source": "objects", "object_type": "book", "condition": "(holding human {})"},
    "language": {
        "salient_actions": [{"action": "take", "agent_arg": 1, "focal_arg": 2},
                            {"action": "takeout", "agent_arg": 1, "focal_arg": 2},
                            {"action": "handover", "agent_arg": 1, "focal_arg": 3}],
        "qualifier": {"predicate": "iscolour"},
        "goal_atoms": {"take": ["(holding $1 $2)"], "takeout": ["(holding $1 $2)"],
                       "handover": ["(holding $2 $3)"]},
    },
}

GOAL = "book1"  # the red book, in the chest in the attic
INSTRUCTION = "Could you bring me the red book from the chest?"


def write_folder(root):
    folder = os.path.join(root, "attic")
    os.makedirs(os.path.join(folder, "problems"))
    with open(os.path.join(folder, "domain.pddl"), "w", encoding="utf-8") as f:
        f.write(DOMAIN)
    with open(os.path.join(folder, "problems", "1.pddl"), "w", encoding="utf-8") as f:
        f.write(PROBLEM)
    with open(os.path.join(folder, "pack.json"), "w", encoding="utf-8") as f:
        json.dump(PACK, f, indent=2)
    return folder


def find_thing(things, name):
    """The thing named `name` among `things` or inside them (contents), else None."""
    for o in things:
        if o["name"] == name:
            return o
        inner = find_thing(o.get("contents", []), name)
        if inner:
            return inner
    return None


def where_is(scene, name):
    """('agent', AGENT) when carried, ('place', PLACE) when at a place (or in a thing there), else None."""
    for a in scene["agents"]:
        if find_thing(a["holds"], name):
            return "agent", a["name"]
    for p in scene["places"]:
        if find_thing(p["objects"], name):
            return "place", p["name"]
    return None


ROOMS = ["hall", "landing", "attic"]  # in a line, as the doors of PROBLEM join them


def human_move(state, robot_busy, waited):
    """The human's next action towards the goal object, as a person who asked
    for it plays: wait while the robot works on it (it has moved, opened or
    carries the book: it hands it over), else walk to it, open its chest and
    take it."""
    scene, acts = state["scene"], state["actions"]
    here = next(a["at"] for a in scene["agents"] if a["name"] == state["principal"])
    loc = where_is(scene, GOAL)
    if (robot_busy or (loc and loc[0] == "agent")) and waited < 8:
        return None
    if loc and loc[0] == "agent":
        there = next(a["at"] for a in scene["agents"] if a["name"] == loc[1])
    else:
        there = loc[1] if loc else here
    if there != here:
        step = 1 if ROOMS.index(there) > ROOMS.index(here) else -1
        return "(move human %s %s)" % (here, ROOMS[ROOMS.index(here) + step])
    for a in acts:
        if a.startswith("(takeout human %s " % GOAL) or a.startswith("(take human %s " % GOAL):
            return a
    opening = [a for a in acts if a.startswith("(open human ")]
    return opening[0] if opening else None


def main():
    clips, source_dir, shot = sys.argv[1], sys.argv[2], sys.argv[3]
    tmp = tempfile.mkdtemp(prefix="clips-e2e-unseen-")
    folder = write_folder(tmp)
    check = Checks()
    # The browser first, so that the time from the server's start-up to the
    # first answer is the server's and the page's, not Chromium's start.
    browser = Browser()
    server = None
    try:
        browser.call("Page.enable")
        browser.call("Runtime.enable")
        browser.call("Emulation.setDeviceMetricsOverride", width=1120, height=900, deviceScaleFactor=1, mobile=False)
        server = Server(clips, [folder])
        listening = time.time()  # Server() returns on the "listening" line
        browser.call("Page.navigate", url=server.url)
        browser.wait_for("window.clips && window.clips.catalogue !== null && "
                         "document.querySelectorAll('#goal option').length > 0", "the dataset list", timeout=30)
        # A problem without a plan: no plan, the goal menu offers none and the books.
        choices = browser.js("[...document.getElementById('goal').options].map(o => o.value)")
        check(choices == ["none", "book1", "book2", "book3"], "the goal menu offers %s" % choices)
        check(browser.js("[...document.getElementById('plan').options].map(o => o.value)") == [""],
              "a plan is offered for a problem without one")
        browser.js("(() => { const s = document.getElementById('goal'); s.value = %s;"
                   " s.dispatchEvent(new Event('change')); document.getElementById('start').click(); })()"
                   % json.dumps(GOAL))
        browser.wait_for(IDLE + " && window.clips.state", "the session to start", timeout=30)
        browser.type_into("utterance", INSTRUCTION)
        said = time.time()
        browser.enter()
        browser.wait_for(IDLE + " && window.clips.state.reading", "the first instruction to be answered", timeout=30)
        answered = time.time()
        from_start, from_enter = answered - listening, answered - said
        print("first instruction answered %.2f s after the server listened (%.2f s after Enter)"
              % (from_start, from_enter))
        check(from_start < 2.0, "the first instruction was answered %.2f s after the server listened" % from_start)
        state = browser.js("window.clips.state")
        check(state["plan"] is None and state["player_goal"] == GOAL, "plan %s, player's goal %s"
              % (state["plan"], state["player_goal"]))

        # Goals in words on the bars and in the status, the labels as tooltips.
        bars = browser.js("[...document.querySelectorAll('#bars .bar')].map(b => [b.dataset.goal, "
                          "b.querySelector('.label').textContent, b.querySelector('.label').title])")
        colours = {"book1": "red", "book2": "blue", "book3": "green"}
        for goal, text, title in bars:
            check(text == "human holding the %s book" % colours[goal] and title.startswith(goal),
                  "goal %s reads '%s' (tooltip '%s')" % (goal, text, title))
        menu = browser.js("[...document.getElementById('goal').options].map(o => [o.value, o.textContent])")
        for value, text in menu:
            if value in colours:
                check(text == "human holding the %s book" % colours[value],
                      "the goal menu reads %s as '%s'" % (value, text))
        status = browser.js("document.getElementById('status').textContent")
        check("Your goal: human holding the red book" in status and "book1" not in status,
              "the status does not say the goal in words: " + status)

        # The chest stands in the attic with the books inside it; nothing is a loose fact.
        chest = browser.js("(() => { const c = document.querySelector('#textscene .card[data-place=attic]');"
                           " return c ? c.textContent : null; })()")
        check(chest is not None and "chest1" in chest and "inside: book1 (red)" in chest,
              "the attic card does not show the books in the chest: %s" % chest)
        check(not browser.js("!!document.querySelector('#textscene .card[data-place=chest1]')"),
              "the chest is drawn as a place")
        check(browser.js("document.querySelectorAll('#textscene ul.facts li').length") == 0,
              "facts listed: %s" % browser.js("document.getElementById('textscene').textContent"))

        # The readings in words; the PDDL form opens with a click.
        rows = browser.js("[...document.querySelectorAll('#reading details.pddl')].map(d => "
                          "[d.querySelector('summary').textContent, d.querySelector('code').textContent, d.open])")
        check(len(rows) >= 1, "no readings shown")
        for words, pddl, opened in rows:
            check(not words.startswith("(") and "?" not in words and not opened and pddl.startswith("("),
                  "a reading reads '%s' (PDDL '%s', open %s)" % (words, pddl, opened))
        print("readings: " + " | ".join(w for w, _, _ in rows))
        check(any("red book" in w and w.startswith("robot:") for w, _, _ in rows),
              "no reading says what the robot should do with the red book: %s" % [w for w, _, _ in rows])
        browser.js("document.querySelector('#reading details.pddl summary').click()")
        check(browser.js("document.querySelector('#reading details.pddl').open"), "a click does not open the PDDL form")

        # Play to the goal. The first move: a key pressed while the robot
        # thinks is not played, nor kept for later.
        waited, moves = 0, 0
        while not browser.js("window.clips.state.reached_goal") and moves < 40:
            state = browser.js("window.clips.state")
            t0 = state["t"]
            log = robot_log(browser)
            action = human_move(state, bool(log) and not log[-1].startswith("(wait "), waited)
            if action is None:
                waited += 1
                browser.key("w")
            else:
                waited = 0
                if moves == 0:
                    busy = browser.js("(() => { const b = [...document.querySelectorAll('#verbs button')].find(b => "
                                      "b.dataset.action === %s); if (!b) return null; b.click();"
                                      " document.dispatchEvent(new KeyboardEvent('keydown', {key: 'w', bubbles: true}));"
                                      " return [window.clips.busy, window.clips.ignoredKeys,"
                                      " document.querySelectorAll('#verbs button:not([disabled])').length]; })()"
                                      % json.dumps(action))
                    check(busy is not None and busy[0] and busy[1] == 1 and busy[2] == 0,
                          "a key pressed while thinking: [busy, ignored keys, live buttons] = %s" % busy)
                else:
                    check(click_action(browser, action), "no button for " + action)
            browser.wait_for(IDLE + " && window.clips.state.t > %d" % t0, "the turn after %s" % action)
            moves += 1
        final = browser.js("window.clips.state")
        log = robot_log(browser)
        humans = [li for li in browser.js("[...document.querySelectorAll('#log li:not(.robot):not(.say):not(.err)')]"
                                          ".map(li => li.textContent)") if li.startswith("(")]
        print("human: %s\nrobot: %s" % (" ".join(humans), " ".join(log)))
        print("goal reached: %s after %d steps" % (final["reached_goal"], final["t"]))
        check(final["reached_goal"] == GOAL, "the game did not reach the player's goal %s" % GOAL)
        check(browser.js("window.clips.maxQueued") == 0, "keys were queued while the assistant thought")
        check(final["t"] == 2 * len(humans) or final["t"] == 2 * len(humans) - 1,
              "%d steps for %d human moves: a key pressed while thinking was played" % (final["t"], len(humans)))
        menu = browser.js("[...document.getElementById('goal').options].map(o => [o.value, o.textContent])")
        for value, text in menu:
            if value in colours:
                check(text == "human holding the %s book" % colours[value],
                      "the goal menu reads %s as '%s'" % (value, text))
        status = browser.js("document.getElementById('status').textContent")
        check(status.startswith("Goal reached: human holding the red book"), "the status says: " + status)
        # The screenshot shows the top reading's PDDL form opened.
        browser.js("document.querySelector('#reading details.pddl summary').click()")
        check(browser.js("document.querySelector('#reading details.pddl').open"), "a click does not open the PDDL form")
        browser.screenshot(shot)

        # A phone's width: the page fits 390 px without scrolling sideways.
        browser.call("Emulation.setDeviceMetricsOverride", width=390, height=844, deviceScaleFactor=1, mobile=True)
        time.sleep(0.3)
        wide = browser.js("document.documentElement.scrollWidth")
        check(wide <= 390, "at 390 px wide the page is %s px wide" % wide)
        browser.screenshot(shot[:-4] + "-390.png", {"x": 0, "y": 0, "width": 390, "height": 844, "scale": 1})
    finally:
        browser.close()
        shutil.rmtree(tmp, ignore_errors=True)
        if server:
            code = server.stop()
            if code != 0:
                check(False, "server exit code %d" % code)
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
