"""Starting and stopping `ris serve` for the browser test, the load test and
the benchmark (tests/serve/, bench/serve_bench.py): a free loopback port
(--port 0, the URL read from the first line printed), a fresh --out folder,
SIGINT to stop (as Ctrl-C does), and HTTP helpers on urllib (no packages).
"""
import json
import os
import re
import signal
import subprocess
import time
import urllib.error
import urllib.request


class Server:
    def __init__(self, ris_exe, out_dir, extra_args=(), env=None):
        self.proc = subprocess.Popen(
            [ris_exe, "serve", "--port", "0", "--out", str(out_dir), *extra_args],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            env=None if env is None else {**os.environ, **env})
        line = self.proc.stdout.readline()
        m = re.search(r"open (http://\S+)", line)
        if not m:
            rest = self.proc.stdout.read() if self.proc.poll() is not None else ""
            raise RuntimeError(f"ris serve did not start: {line}{rest}")
        self.url = m.group(1).rstrip("/")

    def request(self, method, path, body=None, timeout=60):
        """(status, bytes) of one request; HTTP errors are returned, not raised."""
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(self.url + path, data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as r:
                return r.status, r.read()
        except urllib.error.HTTPError as e:
            return e.code, e.read()

    def post(self, path, body):
        status, data = self.request("POST", path, body)
        return status, json.loads(data)

    def rss_kib(self):
        with open(f"/proc/{self.proc.pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        return 0

    def stop(self):
        """SIGINT, as Ctrl-C; returns the exit code and the rest of the output."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
        try:
            out, _ = self.proc.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            out, _ = self.proc.communicate()
        return self.proc.returncode, out


def percentile(values, p):
    """The p-th percentile (nearest rank) of a list of numbers."""
    s = sorted(values)
    if not s:
        return float("nan")
    k = max(0, min(len(s) - 1, int(round(p / 100.0 * len(s) + 0.5)) - 1))
    return s[k]


def wait_until(predicate, timeout_s=30, what="condition"):
    t0 = time.time()
    while time.time() - t0 < timeout_s:
        v = predicate()
        if v:
            return v
        time.sleep(0.1)
    raise AssertionError(f"timed out after {timeout_s} s waiting for {what}")
