"""The seating against a second solver: tools/numpy_seating.py, an
independent numpy model of scene 01's quasi-static seating written from
docs/model.md (Hertz, Mindlin's K_t of an increment, Coulomb stick/slip
with the sudden switch, Newton on the finite-rotation pose, the 3 + 6
error-controlled levels and their Richardson pose). Both seat on the same
schedule to the same Newton tolerance, so the poses agree to the Newton
floor (measured 2e-9 of the displacement); 1e-6 is two orders above it and
two below a different load path's difference (~1e-4)."""

import importlib.util

import numpy as np

import kinrepro

from conftest import ROOT


def numpy_model():
    spec = importlib.util.spec_from_file_location("numpy_seating", ROOT / "tools" / "numpy_seating.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.MaxwellPlanes(ROOT / "scenes" / "01_maxwell_vgroove_steel.toml")


def test_numpy_model_seats_as_kinrepro_does(scene01):
    model = numpy_model()
    rng = np.random.default_rng(20261129)
    length = model.L
    for mu in model.draw(rng, 12):
        theirs = np.asarray(model.seat(mu))
        ours = kinrepro.seat(scene01, mu=list(mu)).poses_rel_nominal[0]
        scale = np.r_[np.ones(3), np.full(3, length)]
        size = np.abs(ours * scale).max()
        assert size > 1e-11, "a friction vector that moves the pose by picometres only"
        diff = np.abs((theirs - ours) * scale).max()
        assert diff <= 1e-6 * size, f"mu {mu}: {diff:.3e} m of {size:.3e} m"
