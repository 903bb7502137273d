"""A study split into shards run as tasks on a dask.distributed cluster,
merged: equal to one run (docs/python.md). The workers are separate
processes, as on a cluster, so scenes and studies cross a pickle boundary."""

import pytest

import kinrepro

distributed = pytest.importorskip("distributed")


def test_four_shards_on_a_local_cluster_merge_to_one_run(scene01, study01):
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        futures = [
            client.submit(
                kinrepro.study, scene01, samples=400, sampler="mc", seed=9,
                shard=f"{i}/4", jobs=1, pure=False,
            )
            for i in range(1, 5)
        ]
        parts = client.gather(futures)
    assert sorted(p.shard for p in parts) == [(i, 4) for i in range(1, 5)]
    merged = kinrepro.merge(parts)
    assert merged.sigma("centre") == study01.sigma("centre")
    assert merged.poses().tolist() == study01.poses().tolist()
    assert merged.to_json() == kinrepro.merge([study01]).to_json()
