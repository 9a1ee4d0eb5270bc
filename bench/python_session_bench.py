#!/usr/bin/env python3
"""observe() + assist() through the Python binding against the same calls in C++.

Replays one dataset plan (the paper's 2.1.keys when ../shared/dataset is there,
else the repo example e2.2.keys): a fresh session per repetition (not timed),
then observe() and assist() after every action. The C++ figure is the median
of BM_SessionObserveAssist (bench/session_bench.cpp) over as many repetitions.
Usage: python_session_bench.py BUILD_DIR [REPETITIONS]
"""
import json
import os
import pathlib
import statistics
import subprocess
import sys
import time

build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build").resolve()
reps = int(sys.argv[2]) if len(sys.argv) > 2 else 15
sys.path.insert(0, str(build / "python"))
import clips_assist  # noqa: E402

root = pathlib.Path(__file__).resolve().parents[1]
shared = pathlib.Path(os.environ.get("CLIPS_DATASET", root.parent / "shared" / "dataset")) / "doors-keys-gems"
dataset, plan = (shared, "2.1.keys") if (shared / "domain.pddl").exists() else (
    root / "data" / "examples" / "doors-keys-gems", "e2.2.keys")
actions = [l.strip() for l in (dataset / "plans" / "observed" / f"{plan}.pddl").read_text().splitlines()
           if l.strip() and not l.strip().startswith(";")]


def replay_once():
    s = clips_assist.Session.open_dataset(str(dataset), plan)
    t0 = time.perf_counter()
    for a in actions:
        s.observe(a)
        s.assist()
    return time.perf_counter() - t0


replay_once()  # warm-up (first-touch allocations)
py_ms = statistics.median(replay_once() * 1e3 for _ in range(reps))

out = subprocess.run([str(build / "clips_bench"), "--benchmark_filter=BM_SessionObserveAssist",
                      f"--benchmark_repetitions={reps}", "--benchmark_format=json"],
                     check=True, capture_output=True, text=True).stdout
cpp_ms = next(b["real_time"] for b in json.loads(out)["benchmarks"]
              if b.get("aggregate_name") == "median")
overhead = (py_ms - cpp_ms) / cpp_ms * 100
print(f"session observe+assist on {plan} ({len(actions)} actions), median of {reps}: "
      f"C++ {cpp_ms:.2f} ms, Python {py_ms:.2f} ms, overhead {overhead:+.1f}% (target <= 10%)")
