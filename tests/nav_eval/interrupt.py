#!/usr/bin/env python3
"""Ctrl-C stops scripts/nav-eval: SIGINT one second into an evaluation of 4 runs (2 at a time,
each 3 s in slow_cogmap) must start no further run, exit 130 with a one-line message and no
traceback, and leave a directory the same command resumes (to exit 0 with all 4 runs).

    interrupt.py NAV_EVAL WORK_DIR

It used to keep starting every queued run after the Ctrl-C (the thread pool waited for them all),
then print a KeyboardInterrupt traceback."""
import os
import shutil
import signal
import subprocess
import sys
import time

NAV_EVAL, WORK = sys.argv[1:3]
FAKE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "slow_cogmap")
out = os.path.join(WORK, "interrupt")
log = os.path.join(WORK, "interrupt.log")
shutil.rmtree(out, ignore_errors=True)
if os.path.exists(log):
    os.unlink(log)
env = dict(os.environ, NAV_EVAL_FAKE_LOG=log)
command = [sys.executable, NAV_EVAL, "--buildings", "random:2:1", "--seeds", "1-2", "--jobs",
           "2", "--out", out, "--cogmap", FAKE]
child = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         text=True, preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
deadline = time.time() + 30
while not (os.path.exists(log) and open(log).read().count("start") >= 2):
    if time.time() > deadline or child.poll() is not None:
        sys.exit(f"FAIL: nav-eval did not start its first two runs: {child.stderr.read()}")
    time.sleep(0.05)
time.sleep(1)
child.send_signal(signal.SIGINT)
try:
    _, err = child.communicate(timeout=20)
except subprocess.TimeoutExpired:
    child.kill()
    sys.exit("FAIL: nav-eval still running 20 s after SIGINT")
time.sleep(0.5)
starts = open(log).read().count("start")
failures = []
if child.returncode != 130:
    failures.append(f"exit {child.returncode}, want 130")
if "Traceback" in err or "interrupted" not in err:
    failures.append(f"stderr: {err!r}")
if starts != 2:
    failures.append(f"{starts} runs started, want the 2 running at the SIGINT")
again = subprocess.run(command, env=env, capture_output=True, text=True)
if again.returncode != 0:
    failures.append(f"the same command again: exit {again.returncode}: {again.stderr}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
