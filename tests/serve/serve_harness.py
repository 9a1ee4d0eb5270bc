"""Shared helpers of the `clips serve` script tests: start the server on a
free loopback port and talk JSON to it (standard library only)."""
import http.client
import json
import os
import re
import signal
import subprocess
import threading
import time

SKIP = 77  # CTest SKIP_RETURN_CODE: the paper's dataset is not beside the checkout


class Server:
    def __init__(self, clips, datasets, *extra, env=None):
        args = [clips, "serve", "--port", "0"]
        for d in datasets:
            args += ["--dataset", d]
        args += list(extra)
        self.proc = subprocess.Popen(args, stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True,
                                     env=env or os.environ.copy())
        self.log = []
        self.port = None
        # Before it listens the server trains (or loads from the cache) each
        # dataset's language model: a cold cache takes up to a minute per domain.
        deadline = time.time() + 300
        while time.time() < deadline:
            line = self.proc.stderr.readline()
            if not line:
                break
            self.log.append(line)
            m = re.search(r"listening on http://([^:]+):(\d+)/", line)
            if m:
                self.host, self.port = m.group(1), int(m.group(2))
                break
        if self.port is None:
            self.proc.kill()
            raise RuntimeError("clips serve did not start: " + "".join(self.log))
        # Keep draining stderr so the server never blocks on a full pipe.
        threading.Thread(target=self._drain, daemon=True).start()

    def _drain(self):
        for line in self.proc.stderr:
            self.log.append(line)

    @property
    def url(self):
        return "http://%s:%d/" % (self.host, self.port)

    def request(self, method, path, body=None, timeout=120):
        conn = http.client.HTTPConnection(self.host, self.port, timeout=timeout)
        data = json.dumps(body) if body is not None else None
        headers = {"Content-Type": "application/json"} if data is not None else {}
        conn.request(method, path, body=data, headers=headers)
        res = conn.getresponse()
        raw = res.read()
        conn.close()
        try:
            payload = json.loads(raw) if raw else None
        except ValueError:
            payload = raw.decode("utf-8", "replace")
        return res.status, payload

    def rss_kib(self):
        with open("/proc/%d/status" % self.proc.pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        return 0

    def stop(self, timeout=30):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        return self.proc.wait(timeout=timeout)


def dataset_root(source_dir):
    root = os.environ.get("CLIPS_DATASET") or os.path.join(source_dir, "..", "shared", "dataset")
    return os.path.abspath(root)
