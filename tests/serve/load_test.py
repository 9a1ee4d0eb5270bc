#!/usr/bin/python3
"""Load test of `clips serve` on loopback: SESSIONS concurrent sessions, each
taking STEPS actions: the human's (a seeded random walk over their applicable
actions, one instruction first) alternating with the assistant's (assist with
apply); GET state about every 10 steps; then every session is deleted.

Reports p50/p99 latency per request kind and the server's resident set size
(VmRSS) before any session, at its peak and after all sessions are deleted,
and fails on any failed request or when the RSS after deletion exceeds the
RSS before by more than GROWTH_BOUND_MIB. Bounded: a fixed number of requests,
and the whole run must end within TIME_LIMIT seconds.

usage: load_test.py CLIPS_BINARY SOURCE_DIR [--sessions N] [--steps N]
"""
import argparse
import os
import random
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_harness import SKIP, Server, dataset_root  # noqa: E402

GROWTH_BOUND_MIB = 64
TIME_LIMIT = 540
UTTERANCES = ["Can you pass me the red key?", "Could you get the blue key for me?", "Please unlock the yellow door.",
              "I need the green key."]


def percentile(xs, q):
    xs = sorted(xs)
    return xs[min(len(xs) - 1, int(round(q * (len(xs) - 1))))]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("clips")
    ap.add_argument("source_dir")
    ap.add_argument("--sessions", type=int, default=50)
    ap.add_argument("--steps", type=int, default=60)
    ap.add_argument("--budget", type=int, default=512, help="A* expansions per search (server --max-nodes)")
    args = ap.parse_args()
    dkg = os.path.join(dataset_root(args.source_dir), "doors-keys-gems")
    if not os.path.exists(os.path.join(dkg, "domain.pddl")):
        print("skipped: no dataset at " + dkg)
        return SKIP

    # Small search budgets: a random walk sends the human's policies far off
    # any plan, and every request's compute is bounded by these (the belief
    # stays exact; only lookahead is cut, which the state reports).
    # Every player connects from 127.0.0.1: one client, so its quota is the server's.
    server = Server(args.clips, [dkg], "--max-sessions", str(args.sessions + 4),
                    "--max-client-sessions", str(args.sessions + 4), "--threads", "8",
                    "--max-nodes", str(args.budget), "--assist-nodes", str(args.budget), "--max-seconds", "1")
    latencies = {}
    failures = []
    lock = threading.Lock()
    peak = [0]
    done = threading.Event()
    t_start = time.time()

    def call(kind, method, path, body=None):
        t0 = time.perf_counter()
        status, payload = server.request(method, path, body)
        dt = time.perf_counter() - t0
        with lock:
            latencies.setdefault(kind, []).append(dt)
            if status >= 300:
                failures.append("%s %s -> %d %s" % (method, path, status, payload))
        return status, payload

    def monitor():
        while not done.is_set():
            peak[0] = max(peak[0], server.rss_kib())
            time.sleep(0.05)

    try:
        _, catalogue = server.request("GET", "/api/datasets")
        problems = [p["id"] for p in catalogue["datasets"][0]["problems"] if not p["id"].startswith("demo")]
        # Warm up: the first instruction loads the language model, which the
        # server keeps for all sessions; "before" is measured after it.
        _, w = server.request("POST", "/api/sessions", {"dataset": "doors-keys-gems", "problem": problems[0]})
        server.request("POST", "/api/sessions/%s/hear" % w["id"], {"utterance": UTTERANCES[0]})
        server.request("DELETE", "/api/sessions/" + w["id"])
        time.sleep(0.5)
        rss_before = server.rss_kib()
        threading.Thread(target=monitor, daemon=True).start()
        ids = [None] * args.sessions

        def player(k):
            rng = random.Random(k)
            problem = problems[k % len(problems)]
            status, s = call("create", "POST", "/api/sessions", {"dataset": "doors-keys-gems", "problem": problem})
            if status != 201:
                return
            ids[k] = s["id"]
            url = "/api/sessions/" + s["id"]
            step = 0
            while step < args.steps:  # a step is one action: the human's or the assistant's
                if time.time() - t_start > TIME_LIMIT:
                    with lock:
                        failures.append("time limit of %d s reached" % TIME_LIMIT)
                    return
                if step == 0:
                    status, s = call("hear", "POST", url + "/hear", {"utterance": rng.choice(UTTERANCES)})
                if s.get("reached_goal") or not s.get("actions"):
                    status, s = call("reset", "POST", url + "/reset")
                status, s = call("act", "POST", url + "/act", {"action": rng.choice(s["actions"])})
                if status != 200:
                    return
                step += 1
                if s["turn"] == s["assistant"] and not s["reached_goal"]:
                    status, r = call("assist", "POST", url + "/assist", {"apply": True})
                    if status != 200:
                        return
                    s = r["state"]
                    step += 1
                if step % 10 in (0, 1):
                    status, s = call("state", "GET", url)

        threads = [threading.Thread(target=player, args=(k,)) for k in range(args.sessions)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        rss_peak_live = max(peak[0], server.rss_kib())
        for i in ids:
            if i:
                call("delete", "DELETE", "/api/sessions/" + i)
        time.sleep(0.5)
        rss_after = server.rss_kib()
        done.set()
        _, health = server.request("GET", "/api/health")
    finally:
        done.set()
        code = server.stop()
    wall = time.time() - t_start

    total = sum(len(v) for v in latencies.values())
    print("load test: %d sessions x %d steps, %d requests in %.1f s (%.0f req/s)" %
          (args.sessions, args.steps, total, wall, total / wall))
    print("%-8s %7s %9s %9s %9s" % ("kind", "count", "p50 ms", "p99 ms", "max ms"))
    for kind in ["create", "hear", "act", "assist", "state", "reset", "delete"]:
        xs = latencies.get(kind)
        if xs:
            print("%-8s %7d %9.1f %9.1f %9.1f" % (kind, len(xs), 1000 * percentile(xs, 0.5),
                                                 1000 * percentile(xs, 0.99), 1000 * max(xs)))
    print("server RSS: before %.1f MiB, peak %.1f MiB, after deleting all sessions %.1f MiB (bound: before + %d MiB)"
          % (rss_before / 1024, rss_peak_live / 1024, rss_after / 1024, GROWTH_BOUND_MIB))
    print("live sessions after deletion: %d; server exit code %d" % (health["sessions"], code))
    if health["sessions"] != 0:
        failures.append("%d sessions still live after deletion" % health["sessions"])
    if rss_after > rss_before + GROWTH_BOUND_MIB * 1024:
        failures.append("RSS grew by %.1f MiB after deleting every session (bound %d MiB)"
                        % ((rss_after - rss_before) / 1024, GROWTH_BOUND_MIB))
    if code != 0:
        failures.append("server exit code %d" % code)
    expected = args.sessions * (args.steps + 3)  # at least: create, hear, one request per step, delete
    if total < expected:
        failures.append("only %d requests made (expected at least %d)" % (total, expected))
    for f in failures[:20]:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
