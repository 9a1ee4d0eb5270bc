#!/usr/bin/env python3
"""A robot's control loop against `clips-assist serve --stdio`, without ROS.

The robot starts the server as a child process and talks JSON lines with it
(one request per line on its stdin, one reply per line on its stdout; the
messages are those of the HTTP API, data/schema/serve-api.openapi.json). Each
turn it reports what the human did (an observation: the action as PDDL text),
passes on what the human said, and asks the server for its own next action,
which it "executes" (here: prints) and reports back by `apply`. A ROS node
would do the same in its callbacks: an action observed -> /act, speech
recognised -> /hear, its turn -> /assist with apply, the reply's action ->
the robot's controller.

Usage: robot_loop.py [--clips PATH] [--dataset DIR] [--max-turns N]
(default: clips-assist on PATH, else build/clips; the example dataset that
comes with it.) Exit 0 when the robot handed the human the key asked for.
"""
import argparse
import json
import os
import pathlib
import shutil
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent


class StdioServer:
    """`clips serve --stdio` as a child process: request() sends one line and reads one."""

    def __init__(self, clips, dataset):
        self.proc = subprocess.Popen([clips, "serve", "--stdio", "--dataset", dataset], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, text=True, bufsize=1)

    def request(self, method, path, body=None):
        line = {"method": method, "path": path}
        if body is not None:
            line["body"] = body
        self.proc.stdin.write(json.dumps(line) + "\n")
        self.proc.stdin.flush()
        reply = json.loads(self.proc.stdout.readline())
        if reply["status"] >= 400:
            raise RuntimeError(f"{method} {path}: {reply['status']} {reply['body']['error']}")
        return reply["body"]

    def close(self):
        self.proc.stdin.close()
        return self.proc.wait(timeout=30)


def default_clips():
    return shutil.which("clips-assist") or str(HERE.parent / "build" / "clips")


def default_dataset():
    for d in ("/usr/share/clips-assist/examples/doors-keys-gems", HERE.parent / "data/examples/doors-keys-gems"):
        if (pathlib.Path(d) / "domain.pddl").exists():
            return str(d)
    sys.exit("no example dataset found; give --dataset")


def human_script(dataset, plan, human):
    """The human's moves in a recorded plan, and [(moves left after it, utterance)] for what they said."""
    moves, said = [], []
    for part in ("observed", "completed"):
        path = dataset / "plans" / part / f"{plan}.pddl"
        for line in path.read_text().splitlines():
            line = line.strip()
            if line.startswith(";"):
                said.append((len(moves), line[1:].strip()))
            elif line.startswith("(") and line[1:-1].split()[1:2] == [human]:  # the human acts
                moves.append(line)
    return moves, [(len(moves) - n, text) for n, text in said]


def top_goal(state):
    best = max(state["posterior"]["goals"], key=lambda g: g["p"])
    return f"{best['goal']} ({best['p']:.2f})"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--clips", default=os.environ.get("CLIPS_ASSIST", default_clips()))
    ap.add_argument("--dataset", default=default_dataset())
    ap.add_argument("--max-turns", type=int, default=40)
    args = ap.parse_args()

    server = StdioServer(args.clips, args.dataset)
    name = pathlib.Path(args.dataset).name
    state = server.request("POST", "/api/sessions", {"dataset": name, "problem": "e1"})
    session = f"/api/sessions/{state['id']}"
    print(f"session {state['id']} on {name} problem e1: the human is {state['principal']}, "
          f"the robot {state['assistant']}")

    # What the robot's perception reports: the human's moves and words, here
    # those of the recorded plan e1.1.keys (the robot's own moves are its own).
    moves, said = human_script(pathlib.Path(args.dataset), "e1.1.keys", state["principal"])
    handed_over = False
    for _ in range(args.max_turns):
        if state["reached_goal"] is not None:
            break
        if state["turn"] == state["assistant"]:
            reply = server.request("POST", f"{session}/assist", {"apply": True})
            decision, state = reply["decision"], reply["state"]
            print(f"t={decision['t']:2d} robot does {decision['action']:<28} "
                  f"({decision['reason']}); most likely goal {top_goal(state)}")
            handed_over |= decision["action"].startswith("(handover")
            continue
        # The human's turn: the next move perception reports (a wait when the
        # scripted one does not apply where the robot's moves led).
        action = moves.pop(0) if moves else state["noop_action"]
        if action not in state["actions"]:
            action = state["noop_action"]
        done = len(said) and len(moves) == said[0][0]
        state = server.request("POST", f"{session}/act", {"action": action})
        print(f"t={state['t']:2d} human does {action:<28} most likely goal {top_goal(state)}")
        if done:
            utterance = said.pop(0)[1]
            state = server.request("POST", f"{session}/hear", {"utterance": utterance})
            print(f'      human says "{utterance}"; most likely goal {top_goal(state)}')
    server.request("DELETE", session)
    code = server.close()
    print(f"goal reached: {state['reached_goal']}; the robot handed a key over: {handed_over}")
    sys.exit(0 if handed_over and state["reached_goal"] == "gem3" and code == 0 else 1)


if __name__ == "__main__":
    main()
