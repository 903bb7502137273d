"""Ctrl-C stops a long study with KeyboardInterrupt, promptly."""

import os
import signal
import subprocess
import sys
import time

SCRIPT = r"""
import sys, time, kinrepro
scene = kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml")
print("ready", flush=True)
t = time.monotonic()
try:
    # Hours of seatings: only Ctrl-C ends it.
    kinrepro.study(scene, samples=100_000_000, sampler="mc", seed=1)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(0)
print("finished", flush=True)
sys.exit(1)
"""


def test_sigint_raises_keyboard_interrupt():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    p = subprocess.Popen([sys.executable, "-c", SCRIPT], cwd=root, stdout=subprocess.PIPE,
                         text=True)
    assert p.stdout.readline().strip() == "ready"
    time.sleep(1.5)
    t = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=30)
    assert p.returncode == 0, out
    assert out.strip() == "interrupted"
    assert time.monotonic() - t < 10
