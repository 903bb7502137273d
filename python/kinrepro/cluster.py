"""Studies, sweeps and optimisations split into shards on a Dask cluster
(docs/python.md).

Each shard is one task, ``kinrepro.study(..., shard=(i, n))`` (or
``kinrepro.sweep``, ``kinrepro.optimize``) run on a worker; :func:`kinrepro.merge` of the results
equals the unsharded run. ``client`` is a ``dask.distributed.Client`` of any
cluster: a ``LocalCluster`` on one machine, dask-jobqueue's
``SLURMCluster`` on a Slurm cluster; only the cluster differs, the code path
is this one. Dask itself is not imported here (``pip install
"dask[distributed]"``).
"""

from __future__ import annotations

from typing import Any, Mapping

from . import Optimization, Scene, Study, Sweep, merge
from . import optimize as _optimize
from . import study as _study
from . import sweep as _sweep


def _sharded(client: Any, run: Any, shards: int, args: tuple, options: Mapping[str, Any]) -> Any:
    if shards < 1:
        raise ValueError(f"shards={shards}: need at least 1")
    futures = [
        client.submit(run, *args, shard=(i, shards), pure=False, **options)
        for i in range(1, shards + 1)
    ]
    return merge(client.gather(futures))


def study(client: Any, scene: Scene, shards: int, **options: Any) -> Study:
    """``kinrepro.study(scene, **options)`` as ``shards`` tasks on the
    cluster of ``client``, merged: equal to the study run in one piece.
    Give ``jobs`` (threads per task) to match the workers' cores."""
    return _sharded(client, _study, shards, (scene,), options)


def sweep(client: Any, scene: Scene, sets: Mapping[str, Any], shards: int, **options: Any) -> Sweep:
    """``kinrepro.sweep(scene, sets, **options)`` with its design points in
    ``shards`` tasks on the cluster of ``client``, merged."""
    return _sharded(client, _sweep, shards, (scene, sets), options)


def optimize(client: Any, scene: Scene, vary: Mapping[str, Any], shards: int,
             **options: Any) -> Optimization:
    """``kinrepro.optimize(scene, vary, **options)`` with its searches
    (combinations of listed values x ``starts``) in ``shards`` tasks on
    the cluster of ``client``, merged: equal to the optimisation run in
    one piece."""
    return _sharded(client, _optimize, shards, (scene, vary), options)
