"""kinrepro: friction-induced re-seating scatter of kinematic couplings.

Python bindings of the kinrepro library (docs/python.md). Every number comes
from the library; every document (``Study.to_json()``, ``Sweep.to_json()``)
is the JSON the ``kinrepro`` command line writes. Units are SI (m, rad, N)
for arrays and inputs; the statistics of the study document (``sigma``) are
in nm and nrad, as their keys say (``x_nm``, ``phi_x_nrad``).
"""

from __future__ import annotations

from typing import Any, Iterable, Mapping, Sequence, Union

from ._kinrepro import (
    SCHEMA_VERSION,
    Calibration,
    KinreproError,
    Scene,
    Seating,
    Study,
    Sweep,
    __version__,
    calibrate,
    merge,
    predict,
    seat,
    stiffness,
    study,
)
from ._kinrepro import sweep as _sweep

__all__ = [
    "SCHEMA_VERSION",
    "Calibration",
    "KinreproError",
    "Scene",
    "Seating",
    "Study",
    "Sweep",
    "__version__",
    "calibrate",
    "merge",
    "predict",
    "seat",
    "stiffness",
    "study",
    "sweep",
]

SetValues = Union[str, float, int, Iterable[Union[float, int, str]]]


def _set_arg(field: str, values: SetValues) -> str:
    """One ``--set FIELD=VALUES`` argument: a string is passed as written
    (``"5,10,20"``, ``"5:20:4"``, ``"log:1e-3:1e-1:5"``); a number or a list
    of numbers or names is joined by commas."""
    if isinstance(values, str):
        return f"{field}={values}"
    if isinstance(values, (int, float)):
        return f"{field}={values}"
    return f"{field}=" + ",".join(str(v) for v in values)


def sweep(scene: Scene, sets: Mapping[str, SetValues], **options: Any) -> Sweep:
    """Sweep scene fields (``kinrepro sweep``).

    ``sets`` maps a TOML path (the fields of ``Scene.set``) to its values:
    a list of numbers or material names, or a string in the CLI's syntax
    (``"5,10,20"``, a range ``"5:20:4"``, ``"log:1e-3:1e-1:5"``). Keyword
    options: ``points`` (an LHS of that many design points instead of the
    grid), ``pareto_point``, ``samples``, ``sampler``, ``seed``, ``shard``,
    ``jobs``, ``increments``, ``replicates`` (as for :func:`study`).
    """
    args: Sequence[str] = [_set_arg(f, v) for f, v in sets.items()]
    return _sweep(scene, list(args), **options)
