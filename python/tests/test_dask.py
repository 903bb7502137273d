"""A study split into shards run as tasks on a dask.distributed cluster,
merged: equal to one run. The workers are separate processes, as on a
cluster, so scenes and studies cross a pickle boundary. The example of
docs/python.md is run as written; its Slurm example calls the same
function, with only the cluster made differently."""

import pathlib
import re

import numpy as np
import pytest

import kinrepro
import kinrepro.cluster
from conftest import run_script

distributed = pytest.importorskip("distributed")

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"


def doc_blocks():
    text = DOC.read_text()
    section = text.split("## Studies on a Dask cluster", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", section, re.S)


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        yield client


def test_four_shards_on_a_local_cluster_merge_to_one_run(client, scene01, study01):
    merged = kinrepro.cluster.study(client, scene01, shards=4, samples=400, sampler="mc", seed=9,
                                    jobs=1)
    np.testing.assert_array_equal(merged.sigma("centre"), study01.sigma("centre"))
    np.testing.assert_array_equal(merged.poses(), study01.poses())
    assert merged.to_json() == kinrepro.merge([study01]).to_json()


def test_sweep_shards_on_a_local_cluster(client, scene01):
    sets = {"preload.force": [10, 20, 40]}
    one = kinrepro.sweep(scene01, sets=sets, samples=10, seed=4)
    assert kinrepro.cluster.sweep(client, scene01, sets, shards=2, samples=10, seed=4, jobs=1) == one


def test_optimisation_searches_on_a_local_cluster(client, scene01):
    """Two materials x two starts: four searches in three tasks, merged:
    the optimisation run in one piece (the same document)."""
    vary = {"preload.force": (5, 40), "coupling.ball_material": ["steel", "silicon-carbide"]}
    options = dict(objective="k_min:max", constraints=["sigma:centre:x<=5e-9"], samples=10,
                   sampler="mc", seed=3, max_iterations=20, starts=2)
    one = kinrepro.optimize(scene01, vary, **options)
    assert one.to_dict()["searches"] == 4
    merged = kinrepro.cluster.optimize(client, scene01, vary, shards=3, jobs=1, **options)
    assert merged == one
    assert merged.to_json() == one.to_json()


def test_the_doc_example_runs_and_the_slurm_one_is_the_same_call(study01, tmp_path):
    """The LocalCluster example saved to a file and run by a fresh
    interpreter, as a user runs it (its workers import the script)."""
    local, slurm = doc_blocks()
    assert "LocalCluster(" in local and "SLURMCluster(" in slurm
    call = "kinrepro.cluster.study(client, scene, shards="
    assert call in local and call in slurm
    out = run_script(local, tmp_path)
    assert out.returncode == 0, out.stderr[-2000:]
    assert (tmp_path / "study.json").read_text() == kinrepro.merge([study01]).to_json()
