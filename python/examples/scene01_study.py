"""Worked example: the re-seating scatter of scene 01 in a notebook style.

Run from the repository root:

    python python/examples/scene01_study.py

It loads scene 01 (a Maxwell coupling of three V-grooves, steel on steel),
runs a Monte Carlo study of 400 re-seatings with random friction, plots the
x-y scatter of the centre with its sigma (if matplotlib is installed; the
figure goes to $KINREPRO_EXAMPLE_OUT or the current folder), and sweeps the
preload. Every number comes from the kinrepro library: the same as
`kinrepro study scenes/01_maxwell_vgroove_steel.toml --sampler mc
--samples 400 --seed 9`.
"""

import os
import pathlib

import numpy as np

import kinrepro

print(f"kinrepro {kinrepro.__version__}")

# 1. The scene: a TOML file, validated on load (a bad file raises
#    kinrepro.KinreproError with the file, line and reason).
scene = kinrepro.Scene.load("scenes/01_maxwell_vgroove_steel.toml")
print(scene.name, "- evaluation points:", scene.evaluation_points)

# 2. One seating at nominal friction: forces [N] and stick/slip per contact.
seating = kinrepro.seat(scene)
print("normal forces [N]:", np.round(seating.normal_forces, 3))
print("contact states:", seating.states)

# 3. The study: 400 re-seatings, mu_s of each contact uniform in mu0 +- spread.
study = kinrepro.study(scene, samples=400, sampler="mc", seed=9)
poses = study.poses("centre")  # (400, 6): x, y, z [m], phi_x, phi_y, phi_z [rad]
sigma = study.sigma("centre")  # (6,): x, y, z [m], phi_x, phi_y, phi_z [rad]
print(f"sigma_x = {sigma[0] * 1e9:.3f} nm, sigma_y = {sigma[1] * 1e9:.3f} nm, "
      f"sigma_z = {sigma[2] * 1e9:.3f} nm, sigma_phi_z = {sigma[5] * 1e9:.3f} nrad")
# sigma is the sample standard deviation (n - 1) of the poses:
assert np.allclose(poses.std(axis=0, ddof=1), sigma, rtol=1e-9)

# Which friction coefficient drives x? Correlate inputs with outputs.
mu = study.inputs()
corr = [np.corrcoef(mu[:, k], poses[:, 0])[0, 1] for k in range(mu.shape[1])]
print("corr(mu_k, x):", dict(zip(study.input_names(), np.round(corr, 2))))

# 4. The x-y scatter with its 90 % covariance ellipse: the mean and the
# sample covariance S of (x, y), the points m + c L (cos t, sin t) with
# L L^T = S and c^2 = -2 ln(0.1), the chi-square quantile of 2 degrees of
# freedom (as the report's scatter draws it).
try:
    import matplotlib

    matplotlib.use(os.environ.get("MPLBACKEND", "Agg"))
    import matplotlib.pyplot as plt
except ImportError:
    plt = None
    print("matplotlib not installed: no plot (pip install matplotlib)")
if plt is not None:
    out = pathlib.Path(os.environ.get("KINREPRO_EXAMPLE_OUT", "."))
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.scatter(poses[:, 0] * 1e9, poses[:, 1] * 1e9, s=6, alpha=0.6, label="re-seatings")
    t = np.linspace(0, 2 * np.pi, 200)
    xy = poses[:, :2] * 1e9                                      # nm
    L = np.linalg.cholesky(np.cov(xy.T, ddof=1))
    c = np.sqrt(-2 * np.log(1 - 0.90))
    ellipse = xy.mean(axis=0)[:, None] + c * L @ np.vstack([np.cos(t), np.sin(t)])
    ax.plot(ellipse[0], ellipse[1], label="90 % covariance ellipse")
    ax.set_xlabel("x [nm]")
    ax.set_ylabel("y [nm]")
    ax.set_title(scene.name, fontsize=8)
    ax.set_aspect("equal")
    ax.legend()
    path = out / "scene01_scatter.png"
    fig.savefig(path, dpi=100)
    print("wrote", path)

# 5. A small sweep: sigma over the preload (same seed: common random numbers).
sweep = kinrepro.sweep(scene, sets={"preload.force": [10, 20, 40]}, samples=50, seed=9)  # 50 LHS samples in 5 replicates
force = sweep.values()[:, sweep.names().index("preload.force")]   # N
sigma_z = sweep.sigma("centre")[:, 2]                              # m
for f, s in zip(force, sigma_z):
    print(f"preload.force = {f:5.1f} N: sigma_z = {s * 1e9:.3f} nm")
# Scene 01 slides at every contact: sigma_z grows as F^(2/3).
print("sigma_z / F^(2/3):", sigma_z / force ** (2 / 3))
