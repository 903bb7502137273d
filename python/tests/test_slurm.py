"""docs/python.md's SLURMCluster example, saved as a file and run as it
stands against a real (single-node) Slurm, gives the unsharded study.
It runs where a Slurm is up: `tools/slurm-test` starts one and sets
KINREPRO_SLURM=1 (then a missing scheduler or dask-jobqueue fails the
test); elsewhere it is skipped."""

import os

import pytest

import kinrepro
from conftest import run_script
from test_dask import DOC, doc_blocks

REQUIRED = os.environ.get("KINREPRO_SLURM") == "1"


def test_the_slurm_example_runs_against_slurm(tmp_path):
    if not REQUIRED:
        pytest.skip("no local Slurm here: tools/slurm-test runs this test against one")
    import dask_jobqueue  # noqa: F401  (the example needs it; a failure here is the test's)

    _, slurm = doc_blocks()
    out = run_script(slurm, tmp_path, timeout=600)
    assert out.returncode == 0, out.stderr[-3000:]
    scene = kinrepro.Scene.load(str(DOC.parents[1] / "scenes" / "01_maxwell_vgroove_steel.toml"))
    one = kinrepro.study(scene, samples=4000, sampler="mc", seed=9)
    got = kinrepro.Study.from_json((tmp_path / "study.json").read_text())
    assert (got.sigma() == one.sigma()).all()
    assert got.poses().tolist() == one.poses().tolist()
