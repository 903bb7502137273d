"""kinrepro: friction-induced re-seating scatter of kinematic couplings.

Python bindings of the kinrepro library (docs/python.md). Every number comes
from the library; every document (``Study.to_json()``, ``Sweep.to_json()``)
is the JSON the ``kinrepro`` command line writes. Units are SI (m, rad, N)
for arrays and inputs: ``sigma`` of a ``Study``, ``Sweep`` or ``Prediction``
is a numpy array in m and rad; the statistics of the study document as
dicts (``Study.stats()``, ``to_dict()``) are in nm and nrad, as their keys
say (``x_nm``, ``phi_x_nrad``).
``kinrepro.cluster`` runs studies and sweeps in shards on a Dask cluster.
"""

from __future__ import annotations

from typing import Iterable, List, Mapping, Optional, Sequence, Tuple, Union

from ._kinrepro import (
    SCHEMA_VERSION,
    Calibration,
    KinreproError,
    Prediction,
    Scene,
    Seating,
    Study,
    Sweep,
    ThermalPath,
    __version__,
    calibrate,
    merge,
    predict,
    seat,
    stiffness,
    study,
    thermal,
)
from ._kinrepro import Optimization
from ._kinrepro import optimize as _optimize
from ._kinrepro import sweep as _sweep

__all__ = [
    "SCHEMA_VERSION",
    "Calibration",
    "KinreproError",
    "Optimization",
    "Prediction",
    "Scene",
    "Seating",
    "Study",
    "Sweep",
    "ThermalPath",
    "__version__",
    "calibrate",
    "merge",
    "optimize",
    "predict",
    "seat",
    "stiffness",
    "study",
    "sweep",
    "thermal",
]

SetValues = Union[str, float, int, Iterable[Union[float, int, str]]]


def _set_arg(field: str, values: SetValues) -> str:
    """One ``--set FIELD=VALUES`` argument: a string is passed as written
    (``"5,10,20"``, ``"5:20:4"``, ``"log:1e-3:1e-1:5"``); a number or a list
    of numbers or names is joined by commas, each name quoted so that it
    stays a string (``"316"``)."""
    if isinstance(values, str):
        return f"{field}={values}"
    if isinstance(values, (int, float)):
        return f"{field}={values}"
    return f"{field}=" + ",".join(f'"{v}"' if isinstance(v, str) else str(v) for v in values)


def sweep(
    scene: Scene,
    sets: Mapping[str, SetValues],
    points: Optional[int] = None,
    pareto_point: Optional[str] = None,
    samples: Optional[int] = None,
    sampler: Optional[str] = None,
    seed: Optional[int] = None,
    shard: Union[str, Tuple[int, int], None] = None,
    jobs: Optional[int] = None,
    increments: Optional[int] = None,
    path_tolerance: Optional[float] = None,
    replicates: Optional[int] = None,
    objectives: Sequence[str] = (),
    constraints: Sequence[str] = (),
) -> Sweep:
    """Sweep scene fields (``kinrepro sweep``): every design point's
    reproducibility study (friction varied, the same seed for all: common
    random numbers), nominal stiffness, safety and friction limit.

    ``sets`` maps a TOML path (the fields of ``Scene.set``, e.g.
    ``"preload.force"`` [N]) to its values: a list of numbers (SI),
    material names or strings (``["maxwell", "kelvin"]``), or a string in the CLI's syntax (``"5,10,20"``, a range
    ``"5:20:4"``, ``"log:1e-3:1e-1:5"``). The grid of all combinations, or
    an LHS of ``points`` design points. ``pareto_point``: the evaluation
    point of the Pareto objective (None: the first). ``samples``,
    ``sampler``, ``seed``, ``shard``, ``jobs``, ``increments``,
    ``path_tolerance``, ``replicates``: as for :func:`study`, checked by the library as the
    CLI's flags are. ``objectives`` (``"OUTPUT:min"``, ``"OUTPUT:max"``) and
    ``constraints`` (``"OUTPUT>=VALUE"``, SI) choose the front's objectives
    and the designs it is drawn from, as :func:`optimize` takes them. ``Sweep.names()`` and ``Sweep.values()`` (n_designs,
    k) give the design points, ``Sweep.sigma(point)`` (n_designs, 6) their
    sigma in m and rad; ``Sweep.to_dict()["designs"]`` holds everything
    (sigma in nm and nrad). GIL released; Ctrl-C raises KeyboardInterrupt.
    """
    args: List[str] = [_set_arg(f, v) for f, v in sets.items()]
    return _sweep(
        scene, args, points=points, pareto_point=pareto_point, samples=samples,
        sampler=sampler, seed=seed, shard=shard, jobs=jobs, increments=increments,
        path_tolerance=path_tolerance, replicates=replicates,
        objectives=list(objectives), constraints=list(constraints),
    )


VaryValues = Union[str, Tuple[float, float], Iterable[Union[float, int, str]]]


def optimize(
    scene: Scene,
    vary: Mapping[str, VaryValues],
    objective: Optional[str] = None,
    constraints: Sequence[str] = (),
    samples: Optional[int] = None,
    sampler: Optional[str] = None,
    seed: Optional[int] = None,
    jobs: Optional[int] = None,
    increments: Optional[int] = None,
    path_tolerance: Optional[float] = None,
    replicates: Optional[int] = None,
    max_iterations: int = 200,
    starts: int = 1,
    shard: Union[str, Tuple[int, int], None] = None,
) -> Optimization:
    """The best design within bounds (``kinrepro optimize``): one
    ``objective`` (``"OUTPUT:min"`` or ``"OUTPUT:max"``; None: the scene's
    ``[goals]``) under ``constraints`` (``"OUTPUT<=VALUE"``,
    ``"OUTPUT>=VALUE"``, SI units; empty: the scene's), by
    Nelder-Mead over the fields of ``vary``, every candidate's study on the
    same friction draws (common random numbers).

    OUTPUT is ``sigma:POINT:DOF`` or ``pm3sigma:POINT:DOF`` (DOF ``x`` ...
    ``phi_z`` or a direction's name at the point; m, rad), ``k_min`` (N/m),
    ``sf_p``, ``friction_margin`` or a varied field. ``vary`` maps a TOML
    path to a ``(low, high)`` range (searched) or a list of values (each
    tried: materials, keywords), or a string in the CLI's syntax
    (``"5:40"``, ``"log:1e-9:1e-6"``). ``Optimization.optimum["fields"]``
    holds the optimum's values; ``to_dict()["history"]`` every candidate.

    ``starts`` searches per combination of listed values: from the centre
    of the ranges, then from ``starts - 1`` points of a Latin hypercube
    (seeded by ``seed``). ``shard`` (``(index, count)`` or ``"I/N"``)
    makes only that shard of the searches; :func:`merge` of every shard's
    result is the whole optimisation (:func:`kinrepro.cluster.optimize`).
    """
    def arg(field: str, values: VaryValues) -> str:
        if isinstance(values, tuple) and len(values) == 2 and all(
            isinstance(v, (int, float)) and not isinstance(v, bool) for v in values
        ):
            return f"{field}={values[0]}:{values[1]}"
        return _set_arg(field, values)  # type: ignore[arg-type]

    return _optimize(
        scene, [arg(f, v) for f, v in vary.items()], objective, constraints=list(constraints),
        samples=samples, sampler=sampler, seed=seed, jobs=jobs, increments=increments,
        path_tolerance=path_tolerance, replicates=replicates, max_iterations=max_iterations,
        starts=starts, shard=shard,
    )
