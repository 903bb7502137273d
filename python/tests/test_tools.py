"""seat, stiffness, sweep, calibrate and predict against the CLI's JSON and
against closed-form properties."""

import json

import numpy as np
import pytest

import kinrepro

S01 = "scenes/01_maxwell_vgroove_steel.toml"
S02 = "scenes/02_maxwell_pins_steel.toml"
DOF6 = ["x_m", "y_m", "z_m", "phi_x_rad", "phi_y_rad", "phi_z_rad"]
DOFS_JSON = ["x_nm", "y_nm", "z_nm", "phi_x_nrad", "phi_y_nrad", "phi_z_nrad"]


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
    assert d20["points"][0]["sigma"] == pytest.approx(st.stats()["sigma"], rel=1e-12)
    # numpy views: the swept values, and sigma of each design point in SI.
    assert sw.names() == ["preload.force"] and len(sw) == 2
    np.testing.assert_array_equal(sw.values(), [[d["values"]["preload.force"]] for d in theirs["designs"]])
    assert sw.status() == ["ok", "ok"] and sw.indices() == [0, 1]
    sigma = sw.sigma("centre")
    assert sigma.shape == (2, 6)
    for row, d in zip(sigma, theirs["designs"]):
        np.testing.assert_allclose(row, [d["points"][0]["sigma"][k] * 1e-9 for k in DOFS_JSON],
                                   rtol=1e-12)
    np.testing.assert_array_equal(sw.sigma(), sigma)  # None: the Pareto point, the centre
    # Scene 01 slides everywhere: sigma scales as F^(2/3) across the sweep.
    np.testing.assert_allclose(sigma[1] / sigma[0], (20 / 10) ** (2 / 3), rtol=1e-6)
    with pytest.raises(kinrepro.KinreproError, match="nowhere"):
        sw.sigma("nowhere")
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
    prediction = kinrepro.predict(kinrepro.Scene.load(S02), again, samples=100)
    theirs = cli("predict", S02, "--calibration", f, "--samples", 100, "--format", "json")
    pred = prediction.to_dict()
    # The calibration file name is the one given to each.
    pred["calibration"]["file"] = theirs["calibration"]["file"]
    assert pred == theirs
    # The arrays are the document's sigma and interval in SI (m, rad).
    point = theirs["variants"][0]["points"][0]
    assert prediction.scenes() == [S02] and len(prediction) == 1
    sigma = prediction.sigma()
    assert sigma.shape == (1, 6)
    np.testing.assert_allclose(sigma[0], [point["sigma"][k] * 1e-9 for k in DOFS_JSON], rtol=1e-12)
    interval = prediction.interval("centre")
    assert interval.shape == (1, 2, 6)
    np.testing.assert_allclose(
        interval[0], [[point[f"sigma_ci90_{e}"][k] * 1e-9 for k in DOFS_JSON] for e in ("low", "high")],
        rtol=1e-12,
    )
    assert np.all(interval[0, 0] < sigma[0]) and np.all(sigma[0] < interval[0, 1])


def measured_02_si():
    """The cycles of docs/calibration/measured_02.csv as an (n, 6) array in
    m and rad (its columns are nm and nrad), read by numpy, not by kinrepro."""
    rows = np.loadtxt("docs/calibration/measured_02.csv", delimiter=",", comments="#", skiprows=5)
    return rows * 1e-9


def test_calibrate_from_an_array_equals_the_file():
    scene02 = kinrepro.Scene.load(S02)
    from_file = kinrepro.calibrate(scene02, "docs/calibration/measured_02.csv", model_samples=200)
    cycles = measured_02_si()
    assert cycles.shape == (50, 6)
    # The file's `# noise:` line, given as the keyword.
    noise = "x=1nm,y=1nm,z=1nm,phi_x=20nrad,phi_y=20nrad,phi_z=20nrad"
    from_array = kinrepro.calibrate(scene02, cycles, noise=noise, model_samples=200)
    for k, v in from_file.estimates.items():
        assert from_array.estimates[k] == pytest.approx(v, rel=1e-12), k
    a, b = from_array.to_dict(), from_file.to_dict()
    for doc in (a, b):
        doc.pop("measured_file", None)
        doc.pop("metadata", None)
    assert json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)
    # Three columns named by `dofs`: a calibration on x, y, z alone.
    xyz = kinrepro.calibrate(scene02, cycles[:, :3], dofs=["x", "y", "z"], noise="x=1nm,y=1nm,z=1nm",
                             model_samples=200)
    assert 0 < xyz.estimates["spread"] < 0.5


def test_calibrate_array_errors():
    scene02 = kinrepro.Scene.load(S02)
    cycles = measured_02_si()
    with pytest.raises(kinrepro.KinreproError, match="dofs"):
        kinrepro.calibrate(scene02, cycles[:, :3])
    bad = cycles.copy()
    bad[4, 1] = 2.0  # 2 m: a unit slip, refused like in a file
    with pytest.raises(kinrepro.KinreproError, match=r"row 5, y_m: 2e0 m"):
        kinrepro.calibrate(scene02, bad)
    bad[4, 1] = np.nan
    with pytest.raises(kinrepro.KinreproError, match="not a finite"):
        kinrepro.calibrate(scene02, bad)
    with pytest.raises(kinrepro.KinreproError, match="need at least 3"):
        kinrepro.calibrate(scene02, cycles[:2])
    with pytest.raises(kinrepro.KinreproError, match="measured twice"):
        kinrepro.calibrate(scene02, cycles[:, :2], dofs=["x", "x"])
    # The message names the Python keyword (the CLI's says --model-samples 10).
    with pytest.raises(kinrepro.KinreproError, match="model_samples=10: need at least 100") as e:
        kinrepro.calibrate(scene02, cycles, model_samples=10)
    assert "--" not in str(e.value)
