"""Ctrl-C stops a long study, sweep or calibration with KeyboardInterrupt,
promptly, and the next call runs (the library's stop request is withdrawn)."""

import os
import signal
import subprocess
import sys
import time

import pytest

SCRIPT = r"""
import sys, time, kinrepro
scene = kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml")
print("ready", flush=True)
try:
    # Minutes to hours of seatings: only Ctrl-C ends it.
    CALL
except KeyboardInterrupt:
    print("interrupted", flush=True)
    # The next call runs to its end, with the numbers of a fresh process.
    again = kinrepro.study(scene, samples=20, sampler="mc", seed=5)
    print(repr(float(again.sigma()[0])), flush=True)
    sys.exit(0)
print("finished", flush=True)
sys.exit(1)
"""

CALLS = {
    "study": 'kinrepro.study(scene, samples=100_000_000, sampler="mc", seed=1)',
    "sweep": 'kinrepro.sweep(scene, sets={"preload.force": "5:50:40"}, samples=100_000, sampler="mc")',
    "calibrate": (
        "import numpy as np; kinrepro.calibrate(scene, np.random.default_rng(1).normal(0, 1e-8, (50, 6)), "
        "noise='x=1nm', model_samples=1_000_000)"
    ),
}

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(code):
    return subprocess.Popen([sys.executable, "-c", code], cwd=ROOT, stdout=subprocess.PIPE,
                            text=True)


@pytest.mark.parametrize("call", sorted(CALLS))
def test_sigint_raises_keyboard_interrupt(call):
    p = run(SCRIPT.replace("CALL", CALLS[call]))
    assert p.stdout.readline().strip() == "ready"
    time.sleep(1.5)
    t = time.monotonic()
    p.send_signal(signal.SIGINT)
    assert p.stdout.readline().strip() == "interrupted"
    elapsed = time.monotonic() - t
    out, _ = p.communicate(timeout=60)
    assert p.returncode == 0, out
    assert elapsed < 5, elapsed
    # The study after the interrupt is the one a fresh process computes.
    fresh = subprocess.run(
        [sys.executable, "-c", 'import kinrepro; s = kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml"); '
         'print(repr(float(kinrepro.study(s, samples=20, sampler="mc", seed=5).sigma()[0])))'],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout
    assert float(out.strip()) == pytest.approx(float(fresh.strip()), rel=1e-12)
