"""kinrepro.thermal and a study's thermal drift against the CLI's JSON and
against the study's own statistics."""

import json
import os

import numpy as np
import pytest

import kinrepro
from conftest import ROOT

THERMAL = "scenes/maxwell_thermal_alu_invar.toml"
MU = [0.45, 0.5, 0.55, 0.48, 0.52, 0.47]


@pytest.fixture(scope="module")
def scene():
    os.chdir(ROOT)
    return kinrepro.Scene.load(THERMAL)


def test_thermal_matches_cli(scene, cli):
    t = kinrepro.thermal(scene, mu=MU, cycle=[(5.0, 0.0), (0.0, 0.0)])
    theirs = cli("thermal", THERMAL, "--mu", ",".join(map(str, MU)), "--cycle", "5,0;0,0", "--json")
    assert json.loads(t.to_json()) == theirs
    assert t.point_names == [p["name"] for p in theirs["cycle"][0]["points"]]
    np.testing.assert_array_equal(t.delta_t_k, [c["delta_t_k"] for c in theirs["cycle"]])
    drift = t.drift
    assert drift.shape == (2, len(t.point_names), 6)
    for k, c in enumerate(theirs["cycle"]):
        for j, p in enumerate(c["points"]):
            np.testing.assert_array_equal(drift[k, j], p["displacement_m"] + p["rotation_rad"])
    assert t.first_slip_delta_t_k == theirs["first_slip_delta_t_k"]
    assert t.slipping_contacts == [c["slipping_contacts"] for c in theirs["cycle"]]


def test_thermal_errors(scene):
    with pytest.raises(kinrepro.KinreproError, match=r"\[thermal\]"):
        kinrepro.thermal(kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml"))
    with pytest.raises(kinrepro.KinreproError, match="100 K"):
        kinrepro.thermal(scene, cycle=[(500.0, 0.0)])


def test_study_drift_is_its_statistics(scene):
    s = kinrepro.study(scene, samples=30, sampler="mc", seed=3)
    for point in ["centre", "tool tip"]:
        drift = s.drift(point)
        stats = s.stats(point)["thermal"]
        assert drift.shape == (30, len(stats), 6)
        for k, st in enumerate(stats):
            sigma = np.std(drift[:, k, :], axis=0, ddof=1) * 1e9
            mean = np.mean(drift[:, k, :], axis=0) * 1e9
            keys = ["x_nm", "y_nm", "z_nm", "phi_x_nrad", "phi_y_nrad", "phi_z_nrad"]
            np.testing.assert_allclose(sigma, [st["sigma"][q] for q in keys], rtol=1e-12)
            np.testing.assert_allclose(mean, [st["mean"][q] for q in keys], rtol=1e-9, atol=1e-9)
    with pytest.raises(kinrepro.KinreproError, match="thermal"):
        kinrepro.study(kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml"), samples=6).drift()
