#!/usr/bin/env python3
"""Builds the worked example of docs/domains.md from the page itself and runs
it: every block under a "<!-- file: PATH -->" line is written to PATH in a
fresh folder, then `clips validate`, `clips plan`, `clips infer` and
`clips bench` must succeed on it, and CLIPS (actions and words together)
must put more probability on the true goal of plan 1.1 than either
modality alone.

usage: docs_example_test.py CLIPS_BINARY SOURCE_DIR
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile


def extract(doc):
    files = {}
    pattern = re.compile(r"<!-- file: (\S+) -->\s*\n```[a-z]*\n(.*?)```", re.S)
    for path, body in pattern.findall(doc):
        files[path] = body
    return files


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        sys.exit("FAILED (rc %d): %s\nstdout:\n%s\nstderr:\n%s" % (p.returncode, " ".join(cmd), p.stdout, p.stderr))
    return p.stdout


def main():
    clips, source = sys.argv[1], sys.argv[2]
    with open(os.path.join(source, "docs", "domains.md"), encoding="utf-8") as f:
        files = extract(f.read())
    expected = {"kitchen/domain.pddl", "kitchen/pack.json", "kitchen/fewshot.tsv", "kitchen/problems/1.pddl"}
    missing = expected - set(files)
    if missing:
        sys.exit("docs/domains.md lacks the example files %s" % sorted(missing))
    with tempfile.TemporaryDirectory() as tmp:
        for path, body in files.items():
            full = os.path.join(tmp, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w", encoding="utf-8") as out:
                out.write(body)
        out = run([clips, "validate", "--dataset", "kitchen"], tmp)
        if "0 failed" not in out:
            sys.exit("validate:\n" + out)
        out = run([clips, "plan", "--domain", "kitchen/domain.pddl", "--problem", "kitchen/problems/1.pddl",
                   "--goal", "(made cake)"], tmp)
        if "cook-dish" not in out:
            sys.exit("plan did not cook:\n" + out)
        inferred = json.loads(run([clips, "infer", "--dataset", "kitchen", "--plan", "1.1.cake", "--json"], tmp))
        if not inferred:
            sys.exit("infer printed nothing")
        run([clips, "bench", "--dataset", "kitchen", "--out", "results", "--no-progress", "-j", "1"], tmp)
        with open(os.path.join(tmp, "results", "results.csv"), encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        p = {(r["plan"], r["method"]): float(r["p_true_goal"]) for r in rows if r["p_true_goal"]}
        methods = {r["method"] for r in rows}
        for m in ("clips", "lang_only", "action_only", "literal"):
            if m not in methods:
                sys.exit("bench has no %s rows: %s" % (m, sorted(methods)))
        clips_p = p[("1.1.cake", "clips")]
        print("P(cake | 1.1): clips %.3f, lang_only %.3f, action_only %.3f" %
              (clips_p, p[("1.1.cake", "lang_only")], p[("1.1.cake", "action_only")]))
        if not (clips_p > 0.5 and clips_p > p[("1.1.cake", "lang_only")] and clips_p > p[("1.1.cake", "action_only")]):
            sys.exit("CLIPS should single out cake in plan 1.1")
    print("docs/domains.md example: ok")


if __name__ == "__main__":
    main()
