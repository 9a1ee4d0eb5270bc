#!/usr/bin/python3
"""Soak test of `clips serve` on loopback: honest players and hostile clients
at once, for a given time.

Honest clients (each from an address of its own, 127.0.1.K, as separate
users are) play sessions of the repo's small Doors-Keys-Gems example, over
and over: create, hear an instruction, act as the human, ask for assistance
(applied), read the state now and then, delete. Every honest reply must be
right: the status the API documents (201 for a create, 200 otherwise) and a
JSON body with the fields the client reads. The run has three phases: quiet
(honest players only, the first and last fifth of the time) and attacked
(the rest), whose honest latency p95 must stay within P95_FACTOR times the
quiet one.

While attacked (issue 61), besides the hostile clients below:
  idle          IDLE_CONNECTIONS connections from 127.0.0.3-6 opened and left
                silent, opened again as soon as the server drops one (more
                than --max-connections allows: the server must drop the idle
                ones for new ones, not turn players away)
  filler        sessions created from 127.0.0.2 as fast as the server allows
                and never deleted (-> 201 until its per-client quota, then 429)

Hostile clients (from 127.0.0.2, so that the per-address connection bound of
one does not fall on the other) each repeat one misbehaviour:
  slow-header   half a request line, then a byte now and then (-> 408)
  slow-body     a body that stops short of its Content-Length (-> 408)
  cross-origin  a create from another web site's page, JSON or text/plain (-> 403)
  wrong-host    a request for another host name (DNS rebinding) (-> 403)
  big-body      a body over --max-body (-> 413)
  big-header    a 100 kB header line (-> 431)
  bad-json      malformed JSON, duplicate keys, a form body (-> 400, 415)
  bad-http      a request line without a version, binary noise (-> 400)
  flood         sessions created as fast as the server allows and abandoned
                (-> 201 until the address's quota, then 429)
An owner (the server's owner token) lists the sessions every second, as an
operator would, and deletes whatever is left at the end.

Checked: every honest request answered rightly, every hostile one with its
expected status (or a connection the server closed, where a refusal may come
before the client has sent everything), the server alive to the end and
exiting 0 on SIGTERM, no session left, and its resident set (VmRSS) after the
sessions are gone within GROWTH_BOUND_MIB of the value after warm-up.
Prints requests by kind, failures, honest latency p50/p95, RSS start/peak/end.
Bounded: every client stops at the deadline, and the run fails if it lasts
more than SECONDS + 180.

usage: soak.py CLIPS_BINARY SOURCE_DIR [--seconds 75] [--honest 40] [--hostile 20]
"""
import argparse
import http.client
import json
import os
import random
import re
import selectors
import socket
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_harness import Server  # noqa: E402

GROWTH_BOUND_MIB = 64
HONEST_ADDR = "127.0.0.1"   # the server's address, and the owner's
HOSTILE_ADDR = "127.0.0.2"
IDLE_ADDRS = ["127.0.0.3", "127.0.0.4", "127.0.0.5", "127.0.0.6"]
IDLE_CONNECTIONS = 200
CLIENT_SESSIONS = 16  # the server's --max-client-sessions
P95_FACTOR = 2.0
READ_TIMEOUT = 3  # the server's --read-timeout in this test
UTTERANCES = ["Can you pass me the red key?", "Could you get the blue key for me?", "Please unlock the door.",
              "I need a key.", "Get me the yellow key please"]
HOSTILE_KINDS = ["slow-header", "slow-body", "cross-origin", "wrong-host", "big-body", "big-header", "bad-json",
                 "bad-http", "flood"]


def player_addr(k):
    """Player k's own loopback address: 127.0.1.1, 127.0.1.2, ..."""
    return "127.0.%d.%d" % (1 + k // 250, 1 + k % 250)


def percentile(xs, q):
    xs = sorted(xs)
    return xs[min(len(xs) - 1, int(round(q * (len(xs) - 1))))] if xs else float("nan")


class Stats:
    def __init__(self):
        self.lock = threading.Lock()
        self.count = {}      # kind -> requests
        self.statuses = {}   # kind -> {status: n}
        self.latency = {}    # honest kind -> [seconds]
        self.phase_latency = {"quiet": [], "attacked": []}  # honest, by phase
        self.phase = "quiet"
        self.failures = []

    def record(self, kind, status, seconds=None):
        with self.lock:
            self.count[kind] = self.count.get(kind, 0) + 1
            per = self.statuses.setdefault(kind, {})
            per[status] = per.get(status, 0) + 1
            if seconds is not None:
                self.latency.setdefault(kind, []).append(seconds)
                self.phase_latency[self.phase].append(seconds)

    def fail(self, text):
        with self.lock:
            self.failures.append(text)


def raw_exchange(port, data, timeout=30, chunks=None):
    """Sends `data` (then each of `chunks` after its delay) from HOSTILE_ADDR;
    returns the reply's status, or "closed" when the server closed the
    connection without a status line (or reset it while we were sending)."""
    s = socket.create_connection((HONEST_ADDR, port), timeout=timeout, source_address=(HOSTILE_ADDR, 0))
    reply = b""
    try:
        try:
            s.sendall(data)
            for delay, piece in chunks or []:
                time.sleep(delay)
                s.sendall(piece)
        except (BrokenPipeError, ConnectionResetError):
            pass
        try:
            while True:
                b = s.recv(65536)
                if not b:
                    break
                reply += b
                if b"\r\n\r\n" in reply:
                    head, _, rest = reply.partition(b"\r\n\r\n")
                    m = re.search(rb"content-length: *(\d+)", head, re.I)
                    if m and len(rest) >= int(m.group(1)):
                        break
        except ConnectionResetError:
            pass
    finally:
        s.close()
    m = re.match(rb"HTTP/1\.[01] (\d{3})", reply)
    return int(m.group(1)) if m else "closed"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("clips")
    ap.add_argument("source_dir")
    ap.add_argument("--seconds", type=float, default=75)
    ap.add_argument("--honest", type=int, default=40)
    ap.add_argument("--hostile", type=int, default=20)
    ap.add_argument("--budget", type=int, default=256, help="A* expansions per search (server --max-nodes)")
    args = ap.parse_args()
    if args.honest + args.hostile < 50:
        print("soak: at least 50 clients, please")
        return 2
    dkg = os.path.join(args.source_dir, "data", "examples", "doors-keys-gems")
    # Slots for every honest player and the hostile address's quota, which
    # the filler and the flood keep full.
    max_sessions = args.honest + CLIENT_SESSIONS
    server = Server(args.clips, [dkg], "--max-sessions", str(max_sessions), "--threads", "8",
                    "--max-client-sessions", str(CLIENT_SESSIONS),
                    "--read-timeout", str(READ_TIMEOUT), "--max-nodes", str(args.budget),
                    "--assist-nodes", str(args.budget), "--max-seconds", "1")
    token = None
    for line in server.log:
        m = re.search(r"owner token (\S+)", line)
        if m:
            token = m.group(1)
    port = server.port
    stats = Stats()
    honest_ids = set()
    ids_lock = threading.Lock()
    stop = threading.Event()
    attacked = threading.Event()  # the hostile, idle and filler clients run while it is set
    idle_opened = [0]
    rss = {"start": 0, "peak": 0, "end": 0}
    t_start = time.time()

    def honest_call(kind, method, path, body=None, expect=(200,), addr=HONEST_ADDR):
        conn = http.client.HTTPConnection(HONEST_ADDR, port, timeout=120, source_address=(addr, 0))
        t0 = time.perf_counter()
        try:
            headers = {"Content-Type": "application/json"} if body is not None else {}
            conn.request(method, path, body=json.dumps(body) if body is not None else None, headers=headers)
            res = conn.getresponse()
            raw = res.read()
            status = res.status
        except (OSError, http.client.HTTPException) as e:
            stats.record(kind, "error")
            stats.fail("honest %s %s: %s" % (method, path, e))
            return None, None
        finally:
            conn.close()
        dt = time.perf_counter() - t0
        try:
            payload = json.loads(raw)
        except ValueError:
            payload = None
        stats.record(kind, status, dt)
        if status not in expect or not isinstance(payload, dict):
            stats.fail("honest %s %s -> %s %s" % (method, path, status, raw[:200]))
            return None, None
        return status, payload

    def owner_call(method, path):
        conn = http.client.HTTPConnection(HONEST_ADDR, port, timeout=60)
        try:
            conn.request(method, path, headers={"Authorization": "Bearer " + token})
            res = conn.getresponse()
            raw = res.read()
            return res.status, json.loads(raw)
        finally:
            conn.close()

    def state_ok(s):
        return isinstance(s, dict) and isinstance(s.get("actions"), list) and "turn" in s and "assistant" in s

    def honest(k):
        rng = random.Random(k)
        addr = player_addr(k)
        while not stop.is_set():
            status, s = honest_call("create", "POST", "/api/sessions",
                                    {"dataset": "doors-keys-gems", "problem": rng.choice(["e1", "e2"])}, expect=(201,),
                                    addr=addr)
            if s is None:
                time.sleep(0.5)
                continue
            sid = s.get("id")
            if not isinstance(sid, str) or len(sid) != 32 or not state_ok(s):
                stats.fail("honest create: bad reply %s" % str(s)[:200])
                continue
            with ids_lock:
                honest_ids.add(sid)
            url = "/api/sessions/" + sid
            _, s = honest_call("hear", "POST", url + "/hear", {"utterance": rng.choice(UTTERANCES)}, addr=addr)
            for step in range(rng.randint(3, 8)):
                if stop.is_set() or not state_ok(s) or s.get("reached_goal"):
                    break
                if s["turn"] == s["assistant"]:
                    _, r = honest_call("assist", "POST", url + "/assist", {"apply": True}, addr=addr)
                    s = r.get("state") if r else None
                elif s["actions"]:
                    _, s = honest_call("observe", "POST", url + "/act", {"action": rng.choice(s["actions"])}, addr=addr)
                else:
                    break
                if step % 3 == 2 and s is not None:
                    _, s = honest_call("state", "GET", url, addr=addr)
            honest_call("delete", "DELETE", url, addr=addr)
            with ids_lock:
                honest_ids.discard(sid)

    create = json.dumps({"dataset": "doors-keys-gems", "problem": "e1"}).encode()
    host = ("Host: %s:%d\r\n" % (HONEST_ADDR, port)).encode()

    def post(path, body, ctype=b"application/json", extra=b""):
        return (b"POST " + path.encode() + b" HTTP/1.1\r\n" + host + b"Content-Type: " + ctype + b"\r\n" + extra +
                b"Content-Length: " + str(len(body)).encode() + b"\r\n\r\n" + body)

    def hostile_once(kind, rng):
        """One misbehaviour: returns (status, the statuses that are right)."""
        if kind == "slow-header":
            drip = [(0.5, b"H")] * rng.randint(2, 4)
            return raw_exchange(port, b"GET /api/hea", timeout=READ_TIMEOUT + 30, chunks=drip), {408, "closed"}
        if kind == "slow-body":
            head = post("/api/sessions", b"x" * 200)[:-200]
            return raw_exchange(port, head + b'{"dataset"', timeout=READ_TIMEOUT + 30), {408}
        if kind == "cross-origin":
            ctype = rng.choice([b"application/json", b"text/plain"])
            origin = rng.choice([b"https://evil.example", b"null", b"http://127.0.0.1.evil.example:80"])
            return raw_exchange(port, post("/api/sessions", create, ctype, b"Origin: " + origin + b"\r\n")), {403}
        if kind == "wrong-host":
            name = rng.choice([b"attacker.example", b"127.0.0.1.nip.io", b"evil"])
            req = post("/api/sessions", create).replace(host, b"Host: " + name + b":" + str(port).encode() + b"\r\n")
            return raw_exchange(port, req), {403}
        if kind == "big-body":
            return raw_exchange(port, post("/api/sessions", b"{" + b" " * 70000 + b"}")), {413, "closed"}
        if kind == "big-header":
            return raw_exchange(port, b"GET /api/health HTTP/1.1\r\n" + host + b"X-Big: " + b"b" * 100000 +
                                b"\r\n\r\n"), {431, "closed"}
        if kind == "bad-json":
            body, ctype, want = rng.choice([
                (b'{"dataset": "doors-keys-gems", "problem":', b"application/json", {400}),
                (b'{"dataset":"doors-keys-gems","problem":"e1","problem":"e2"}', b"application/json", {400}),
                (b'[1, 2, {"x": nul}]', b"application/json", {400}),
                (b"\xff\xfe{}", b"application/json", {400}),
                (b"dataset=doors-keys-gems&problem=e1", b"application/x-www-form-urlencoded", {415}),
            ])
            return raw_exchange(port, post("/api/sessions", body, ctype)), want
        if kind == "bad-http":
            req, want = rng.choice([
                (b"GET /api/health\r\n\r\n", {400}),
                (bytes(rng.randrange(256) for _ in range(300)) + b"\r\n\r\n", {400, 405, 414, "closed"}),
                (b"POST /api/sessions HTTP/1.1\r\n" + host + b"Content-Type: application/json\r\n\r\n", {411}),
                (b"BREW /api/sessions HTTP/1.1\r\n" + host + b"Content-Length: 0\r\n\r\n", {405}),
            ])
            return raw_exchange(port, req), want
        if kind == "flood":
            return raw_exchange(port, post("/api/sessions", create)), {201, 429}
        raise ValueError(kind)

    def hostile(k):
        rng = random.Random(1000 + k)
        kind = HOSTILE_KINDS[k % len(HOSTILE_KINDS)]
        while not stop.is_set():
            if not attacked.wait(0.2):
                continue
            try:
                status, want = hostile_once(kind, rng)
            except OSError as e:
                status, want = "error: %s" % e, set()
            stats.record(kind, status)
            if status not in want:
                stats.fail("hostile %s -> %s (expected one of %s)" % (kind, status, sorted(map(str, want))))
            if kind == "flood" and status == 429:
                time.sleep(0.05)  # the address's quota is full: try again soon

    def filler():
        """Creates sessions from HOSTILE_ADDR and never deletes them."""
        while not stop.is_set():
            if not attacked.wait(0.2):
                continue
            try:
                status = raw_exchange(port, post("/api/sessions", create))
            except OSError as e:
                status = "error: %s" % e
            stats.record("filler", status)
            if status not in (201, 429):
                stats.fail("filler -> %s (expected 201 or 429)" % status)
            if status == 429:
                time.sleep(0.05)

    def idle():
        """Keeps IDLE_CONNECTIONS silent connections open from IDLE_ADDRS."""
        sel = selectors.DefaultSelector()
        opened = 0
        while not stop.is_set():
            if not attacked.is_set():
                for key in list(sel.get_map().values()):
                    sel.unregister(key.fileobj)
                    key.fileobj.close()
                attacked.wait(0.2)
                continue
            while len(sel.get_map()) < IDLE_CONNECTIONS:
                addr = IDLE_ADDRS[opened % len(IDLE_ADDRS)]
                try:
                    c = socket.create_connection((HONEST_ADDR, port), timeout=5, source_address=(addr, 0))
                except OSError:
                    time.sleep(0.05)
                    break
                c.setblocking(False)
                sel.register(c, selectors.EVENT_READ)
                opened += 1
            for key, _ in sel.select(timeout=0.1):  # readable: the server replied or closed it
                sel.unregister(key.fileobj)
                key.fileobj.close()
                stats.record("idle", "dropped")
        for key in list(sel.get_map().values()):
            key.fileobj.close()
        idle_opened[0] = opened

    def owner():
        while not stop.wait(1.0):
            try:
                status, listing = owner_call("GET", "/api/sessions")
                stats.record("owner-list", status)
                if status != 200:
                    stats.fail("owner list -> %s" % status)
                elif len(listing.get("sessions", [])) > max_sessions:
                    stats.fail("owner list: %d sessions, more than %d" % (len(listing["sessions"]), max_sessions))
            except (OSError, ValueError, http.client.HTTPException) as e:
                stats.fail("owner: %s" % e)

    def monitor():
        while not stop.is_set():
            if server.proc.poll() is not None:
                stats.fail("the server exited during the run (code %s)" % server.proc.returncode)
                stop.set()
                return
            rss["peak"] = max(rss["peak"], server.rss_kib())
            time.sleep(0.1)

    code = None
    health = {}
    try:
        if token is None:
            raise RuntimeError("no owner token in the server's log: " + "".join(server.log))
        # Warm up (the first instruction loads the language model, kept for
        # every session), then take the starting RSS.
        _, w = server.request("POST", "/api/sessions", {"dataset": "doors-keys-gems", "problem": "e1"})
        server.request("POST", "/api/sessions/%s/hear" % w["id"], {"utterance": UTTERANCES[0]})
        server.request("POST", "/api/sessions/%s/assist" % w["id"], {"apply": True})
        server.request("DELETE", "/api/sessions/" + w["id"])
        time.sleep(0.5)
        rss["start"] = rss["peak"] = server.rss_kib()
        t_load = time.time()
        threads = [threading.Thread(target=monitor, daemon=True), threading.Thread(target=owner, daemon=True),
                   threading.Thread(target=filler, daemon=True), threading.Thread(target=idle, daemon=True)]
        threads += [threading.Thread(target=honest, args=(k,), daemon=True) for k in range(args.honest)]
        threads += [threading.Thread(target=hostile, args=(k,), daemon=True) for k in range(args.hostile)]
        for t in threads:
            t.start()
        # Quiet, attacked, quiet.
        stop.wait(args.seconds * 0.2)
        with stats.lock:
            stats.phase = "attacked"
        attacked.set()
        stop.wait(args.seconds * 0.6)
        attacked.clear()
        with stats.lock:
            stats.phase = "quiet"
        stop.wait(args.seconds * 0.2)
        stop.set()
        hard_end = t_start + args.seconds + 180
        for t in threads:
            t.join(max(0.0, hard_end - time.time()))
            if t.is_alive():
                stats.fail("a client was still running %d s after the deadline" % 180)
                break
        load_seconds = time.time() - t_load
        if server.proc.poll() is None:
            status, gone = owner_call("DELETE", "/api/sessions")  # whatever the flood left since the last sweep
            if status != 200:
                stats.fail("owner delete-all -> %s" % status)
            time.sleep(1.0)
            rss["end"] = server.rss_kib()
            _, health = server.request("GET", "/api/health")
    finally:
        stop.set()
        if server.proc.poll() is None:
            code = server.stop()
        else:
            code = server.proc.returncode
    wall = time.time() - t_start

    total = sum(stats.count.values())
    print("soak: %d honest + %d hostile clients, %.0f s of load (%.0f s in all), %d requests (%.0f req/s)"
          % (args.honest, args.hostile, load_seconds, wall, total, total / max(load_seconds, 1e-9)))
    print("%-14s %8s  %s" % ("kind", "requests", "statuses"))
    for kind in ["create", "hear", "observe", "assist", "state", "delete"] + HOSTILE_KINDS + \
            ["filler", "idle", "owner-list"]:
        if kind in stats.count:
            per = ", ".join("%s: %d" % (k, v) for k, v in sorted(stats.statuses[kind].items(), key=lambda kv: str(kv[0])))
            print("%-14s %8d  %s" % (kind, stats.count[kind], per))
    honest_lat = [x for k in ["create", "hear", "observe", "assist", "state", "delete"] for x in stats.latency.get(k, [])]
    print("honest latency: p50 %.1f ms, p95 %.1f ms, max %.1f ms over %d requests" %
          (1000 * percentile(honest_lat, 0.5), 1000 * percentile(honest_lat, 0.95),
           1000 * max(honest_lat or [float("nan")]), len(honest_lat)))
    for k in ["create", "hear", "observe", "assist", "state", "delete"]:
        xs = stats.latency.get(k)
        if xs:
            print("  %-8s p50 %8.1f ms  p95 %8.1f ms" % (k, 1000 * percentile(xs, 0.5), 1000 * percentile(xs, 0.95)))
    quiet, under = stats.phase_latency["quiet"], stats.phase_latency["attacked"]
    q95, a95 = percentile(quiet, 0.95), percentile(under, 0.95)
    print("honest p95 quiet %.1f ms (%d requests), attacked %.1f ms (%d requests): ratio %.2f (bound %.1f)" %
          (1000 * q95, len(quiet), 1000 * a95, len(under), a95 / q95 if q95 > 0 else float("nan"), P95_FACTOR))
    if not quiet or not under:
        stats.fail("no honest requests in a phase (quiet %d, attacked %d)" % (len(quiet), len(under)))
    elif a95 > P95_FACTOR * q95:
        stats.fail("honest p95 attacked %.1f ms is more than %.1f x the quiet %.1f ms" % (1000 * a95, P95_FACTOR, 1000 * q95))
    print("idle connections opened: %d (at most %d at once), dropped by the server: %d" %
          (idle_opened[0], IDLE_CONNECTIONS, stats.count.get("idle", 0)))
    if idle_opened[0] < IDLE_CONNECTIONS:
        stats.fail("only %d idle connections were opened" % idle_opened[0])
    if stats.statuses.get("filler", {}).get(429, 0) == 0:
        stats.fail("the filler never reached its quota (429)")
    print("server RSS: start %.1f MiB, peak %.1f MiB, end %.1f MiB (bound: start + %d MiB); live sessions at the end: "
          "%s; exit code %s" % (rss["start"] / 1024, rss["peak"] / 1024, rss["end"] / 1024, GROWTH_BOUND_MIB,
                                health.get("sessions"), code))
    if health.get("sessions") != 0:
        stats.fail("%s sessions live at the end" % health.get("sessions"))
    if rss["end"] > rss["start"] + GROWTH_BOUND_MIB * 1024:
        stats.fail("RSS grew by %.1f MiB (bound %d MiB)" % ((rss["end"] - rss["start"]) / 1024, GROWTH_BOUND_MIB))
    if code != 0:
        stats.fail("server exit code %s" % code)
    # Not vacuous: honest sessions ran to the end, and every hostile kind was tried.
    if stats.count.get("delete", 0) < args.honest:
        stats.fail("only %d honest sessions completed" % stats.count.get("delete", 0))
    for kind in HOSTILE_KINDS[:args.hostile]:
        if stats.count.get(kind, 0) == 0:
            stats.fail("no %s request was made" % kind)
    print("failures: %d" % len(stats.failures))
    for f in stats.failures[:30]:
        print("FAIL: " + f)
    return 1 if stats.failures else 0


if __name__ == "__main__":
    sys.exit(main())
