#!/usr/bin/env python3
"""Plans, with the clips CLI, for every candidate goal of a dataset laid out
with goals/sets/<P>.txt and goals/definitions/<label>.pddl (VirtualHome, the
workshop dataset), and checks each completed plan against an optimal plan
from where its observed plan ends.

    scripts/check-goal-sets.py [--clips build/clips] DATASET

Prints one line per search. Exits 1 if a goal is unsolvable or a completion
is longer than optimal (counting actions: use it on datasets without declared
action costs), 0 otherwise.
"""
import argparse
import json
import pathlib
import subprocess
import sys


def plan(clips, dataset, goal, problem=None, from_plan=None):
    cmd = [clips, "plan", "--dataset", str(dataset), "--goal", goal, "--json"]
    cmd += ["--problem", problem] if problem else ["--from-plan", from_plan]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0 and not out.stdout.strip():
        return {"status": "error: " + out.stderr.strip(), "cost": None, "expanded": 0, "seconds": 0}
    return json.loads(out.stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--clips", default="build/clips")
    ap.add_argument("dataset", type=pathlib.Path)
    args = ap.parse_args()
    d = args.dataset
    definitions = {p.stem: p.read_text().strip() for p in (d / "goals" / "definitions").glob("*.pddl")}
    failures = 0
    for s in sorted((d / "goals" / "sets").glob("*.txt")):
        for label in s.read_text().split():
            r = plan(args.clips, d, definitions[label], problem=s.stem)
            ok = r["status"] == "success"
            failures += not ok
            print(f"problem {s.stem:<4} {label:<12} {r['status']:<8} cost {r['cost']} "
                  f"expanded {r['expanded']} {r['seconds']:.3f} s")
    for c in sorted((d / "plans" / "completed").glob("*.pddl")):
        plan_id = c.stem
        label = plan_id.split(".", 2)[2]
        length = sum(1 for line in c.read_text().splitlines() if line.strip().startswith("("))
        r = plan(args.clips, d, definitions[label], from_plan=plan_id)
        ok = r["status"] == "success" and length <= r["cost"]
        failures += not ok
        print(f"plan {plan_id:<20} completion {length:<3} optimal {r['cost']} {'ok' if ok else 'LONGER'}")
    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
