#!/usr/bin/env python3
"""Issue 39, class 5: a SIGTERM or SIGINT to `assess run ... --pdf/--docx` while
its child (Chromium, here tests/cli/scripts/slow_tool.sh) runs must stop the
child and its own children, remove every temporary file and folder (TMPDIR and
beside the output), and end `assess` with the signal's status. The Word
document runs no program (issue 36, item 7: the library writes it): in docx
mode the run asks for --docx and --pdf, the Word documents written in the
process while the stand-in Chromium runs, and no Word file may be left.

  signal_cleanup.py ASSESS pdf|docx TERM|INT WORK_DIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time

exe, mode, sig_name, work = sys.argv[1:5]
sig = {"TERM": signal.SIGTERM, "INT": signal.SIGINT}[sig_name]
here = os.path.dirname(os.path.abspath(__file__))
shutil.rmtree(work, ignore_errors=True)
tmp = os.path.join(work, "tmp")
os.makedirs(tmp)
pidfile = os.path.join(work, "pids")
env = dict(os.environ, TMPDIR=tmp, ASSESS_TEST_PIDFILE=pidfile)
out = os.path.join(work, "r." + mode)
env["CHROMIUM"] = os.path.join(here, "slow_tool.sh")
outputs = ["--" + mode, out] + (["--pdf", os.path.join(work, "r.pdf")] if mode == "docx" else [])
proc = subprocess.Popen([exe, "run", "mechanisms/two_storey_facade.json"] + outputs, env=env,
                        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def pids():
    try:
        with open(pidfile) as f:
            return [int(x) for x in f.read().split()]
    except (FileNotFoundError, ValueError):
        return []


deadline = time.time() + 120
while len(pids()) < 2 and time.time() < deadline and proc.poll() is None:
    time.sleep(0.05)
if len(pids()) < 2:
    proc.kill()
    sys.exit("the stand-in tool never started: " + proc.stderr.read().decode(errors="replace"))
left_before = sorted(os.listdir(tmp))
proc.send_signal(sig)
try:
    proc.wait(timeout=30)
except subprocess.TimeoutExpired:
    proc.kill()
    sys.exit("assess did not end within 30 s of the signal")


def alive(pid):
    try:
        with open("/proc/%d/status" % pid) as f:
            return "\nState:\tZ" not in f.read()  # a zombie (not reaped in a container) is gone
    except FileNotFoundError:
        return False


time.sleep(0.2)
problems = []
if proc.returncode != -sig:
    problems.append("exit status %s, expected death by signal %d" % (proc.returncode, sig))
for p in pids():
    if alive(p):
        problems.append("process %d still running" % p)
        os.kill(p, signal.SIGKILL)
left = os.listdir(tmp)
if left:
    problems.append("left in TMPDIR: %s" % left)
beside = [f for f in os.listdir(work) if ".tmp." in f or f.endswith(".docx") or f.endswith(".pdf")]
if beside:
    problems.append("left beside the output: %s" % beside)
if problems:
    sys.exit("; ".join(problems) + " (temporaries while it ran: %s)" % left_before)
print("ok: %s during --%s: the tool and its child stopped, %s removed, assess ended by the signal"
      % (sig_name, mode, ", ".join(left_before) or "nothing"))
