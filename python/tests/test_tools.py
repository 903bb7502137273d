"""seat, stiffness, sweep, calibrate and predict against the CLI's JSON and
against closed-form properties."""

import json

import numpy as np
import pytest

import kinrepro

S01 = "scenes/01_maxwell_vgroove_steel.toml"
S02 = "scenes/02_maxwell_pins_steel.toml"
DOF6 = ["x_m", "y_m", "z_m", "phi_x_rad", "phi_y_rad", "phi_z_rad"]


def test_seat_matches_cli_run(scene01, cli):
    s = kinrepro.seat(scene01)
    theirs = cli("run", S01, "--json")
    assert json.loads(s.to_json()) == theirs
    assert s.point_names == [p["name"] for p in theirs["points"]]
    np.testing.assert_array_equal(
        s.poses, [[p["pose"][k] for k in DOF6] for p in theirs["points"]]
    )
    np.testing.assert_array_equal(s.normal_forces, [c["normal_force_n"] for c in theirs["contacts"]])
    assert s.states == [c["state"] for c in theirs["contacts"]]
    assert s.tangential_forces.shape == (6, 3)
    # At nominal friction the seating is the nominal one.
    np.testing.assert_array_equal(s.poses_rel_nominal, np.zeros_like(s.poses))


def test_seat_with_mu_moves_the_pose(scene01):
    mu = [0.45, 0.55, 0.5, 0.5, 0.55, 0.45]
    s = kinrepro.seat(scene01, mu=mu)
    assert s.mu_static == mu
    assert np.abs(s.poses_rel_nominal).max() > 0
    with pytest.raises(kinrepro.KinreproError):
        kinrepro.seat(scene01, mu=[0.5])


def test_stiffness_is_symmetric_and_the_clis(scene01, cli):
    k = kinrepro.stiffness(scene01)
    assert k.shape == (6, 6)
    np.testing.assert_allclose(k, k.T, rtol=1e-12, atol=1e-9 * np.abs(k).max())
    theirs = cli("stiffness", S01, "--json")
    np.testing.assert_array_equal(k, np.array(theirs["points"][0]["matrix"]))
    assert np.all(np.linalg.eigvalsh(k[:3, :3]) > 0)
    at = kinrepro.stiffness(scene01, at=(0.0, 0.0, 0.01))
    theirs_at = cli("stiffness", S01, "--at", "0,0,0.01", "--json")
    np.testing.assert_array_equal(at, np.array(theirs_at["points"][0]["matrix"]))
    with pytest.raises(kinrepro.KinreproError, match="evaluation point"):
        kinrepro.stiffness(scene01, at="nowhere")


def test_sweep_matches_cli(scene01, cli):
    sw = kinrepro.sweep(scene01, sets={"preload.force": [10, 20]}, samples=20, seed=4)
    theirs = cli("sweep", S01, "--set", "preload.force=10,20", "--samples", 20, "--seed", 4,
                 "--format", "json")
    assert sw.to_dict() == theirs
    # A design point equal to the scene gives the scene's study.
    st = kinrepro.study(scene01, samples=20, seed=4)
    d20 = [d for d in sw.to_dict()["designs"] if d["values"]["preload.force"] == 20.0][0]
    assert d20["points"][0]["sigma"] == pytest.approx(st.sigma(), rel=1e-12)
    # Shards of the sweep merge to the one run.
    parts = [kinrepro.sweep(scene01, sets={"preload.force": "10,20"}, samples=20, seed=4,
                            shard=(i, 2)) for i in (1, 2)]
    assert kinrepro.merge(parts) == sw


def test_calibrate_and_predict_match_cli(cli, tmp_path):
    scene02 = kinrepro.Scene.load(S02)
    cal = kinrepro.calibrate(scene02, "docs/calibration/measured_02.csv", model_samples=200)
    theirs = cli("calibrate", S02, "--measured", "docs/calibration/measured_02.csv",
                 "--model-samples", 200, "--format", "json")
    assert cal.to_dict() == theirs
    assert 0 < cal.estimates["spread"] < 0.5
    f = tmp_path / "cal.json"
    f.write_text(cal.to_json())
    again = kinrepro.Calibration.load(f)
    pred = kinrepro.predict(kinrepro.Scene.load(S02), again, samples=100)
    theirs = cli("predict", S02, "--calibration", f, "--samples", 100, "--format", "json")
    # The calibration file name is the one given to each.
    pred["calibration"]["file"] = theirs["calibration"]["file"]
    assert pred == theirs
