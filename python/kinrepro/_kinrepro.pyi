"""Type stubs of the compiled module (the API is re-exported by ``kinrepro``)."""

from __future__ import annotations

import os
from typing import Any, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
"""Version of the kinrepro library (``kinrepro_version`` of every document)."""
SCHEMA_VERSION: int
"""Version of the study document's layout (docs/output.md)."""

Array = npt.NDArray[np.float64]
Shard = Union[str, tuple[int, int]]
"""``"INDEX/COUNT"`` (1-based, e.g. ``"2/4"``) or ``(index, count)``."""

class KinreproError(ValueError):
    """A bad input (scene, option, document): the library's one-line message,
    e.g. ``file:line: field: reason`` for a scene."""

class Scene:
    """A scene file's text, validated and assembled like ``kinrepro check``.
    Immutable: :meth:`set` returns a new scene. Picklable."""

    @staticmethod
    def load(path: Union[str, os.PathLike[str]]) -> Scene:
        """Read and validate a scene file (TOML). Raises KinreproError."""
    @staticmethod
    def from_toml(text: str, file: str = "<string>") -> Scene:
        """A scene from TOML text; ``file`` names it in messages and documents."""
    def to_toml(self) -> str:
        """The scene's TOML text."""
    def expand(self) -> str:
        """The explicit form (``kinrepro expand``)."""
    def set(self, field: str, value: Union[float, str]) -> Scene:
        """A new scene with the field at TOML path ``field`` (the paths of
        ``kinrepro sweep --set``, e.g. ``"preload.force"`` [N],
        ``"friction.mu_static"``, ``"coupling.ball_radius"`` [m]) set to
        ``value`` (SI number, material name or a string of the scene format
        such as ``"kelvin"``)."""
    @property
    def file(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def evaluation_points(self) -> list[str]:
        """Names of the evaluation points, the centre of the moving half first."""

class Seating:
    """One seating (``kinrepro run --json``), SI units."""

    @property
    def point_names(self) -> list[str]: ...
    @property
    def poses(self) -> Array:
        """(n_points, 6): x, y, z [m], phi_x, phi_y, phi_z [rad] of each
        evaluation point relative to the touching pose."""
    @property
    def poses_rel_nominal(self) -> Array:
        """(n_points, 6), m and rad, relative to the nominal seating."""
    @property
    def normal_forces(self) -> Array:
        """(n_contacts,) normal force of each contact [N]."""
    @property
    def tangential_forces(self) -> Array:
        """(n_contacts, 3) friction force on the moving half [N]."""
    @property
    def states(self) -> list[str]:
        """``"stick"`` or ``"slip"`` per contact."""
    @property
    def mu_static(self) -> list[float]: ...
    def to_json(self) -> str:
        """The document of ``kinrepro run --json``."""
    def table(self) -> str: ...

class Study:
    """A reproducibility study: the document of ``kinrepro study --format
    json`` with numpy views of its samples. Picklable; ``==`` compares the
    whole document."""

    @staticmethod
    def from_json(text: str) -> Study:
        """Read a study document (a whole study, a shard or a merge)."""
    def to_json(self) -> str:
        """The document of ``kinrepro study --format json`` (same options,
        same numbers)."""
    def to_dict(self) -> dict[str, Any]: ...
    def table(self) -> str:
        """The text table of ``kinrepro study`` (nm, nrad)."""
    def csv(self) -> str:
        """The summary CSV of ``kinrepro study --format csv`` (SI)."""
    def poses(
        self, point: str | None = None, variant: int = 0, interchange: bool = False
    ) -> Array:
        """(n, 6) pose of ``point`` (None: the first evaluation point) per
        sample relative to the nominal seating: x, y, z [m], phi_x, phi_y,
        phi_z [rad]. ``np.std(poses, axis=0, ddof=1)`` is ``sigma``."""
    def along(
        self,
        direction: str,
        point: str | None = None,
        variant: int = 0,
        interchange: bool = False,
    ) -> Array:
        """(n,) translation of ``point`` (None: the first point with the
        direction) along its named direction per sample [m]: the pose
        projected on the direction's unit vector; its statistics (nm) are
        ``stats(point)["directions"]``."""
    def about(
        self,
        direction: str,
        point: str | None = None,
        variant: int = 0,
        interchange: bool = False,
    ) -> Array:
        """(n,) rotation of the moving half about a frame's axis (e.g.
        ``"tool.z"``) at ``point`` per sample [rad], as :meth:`along`."""
    def drift(self, point: str | None = None, variant: int = 0) -> Array:
        """A scene with ``[thermal]``: (n, n_cycle_points, 6) drift of
        ``point`` (None: the first) from each sample's own seated pose at
        each cycle point: x, y, z [m], phi_x, phi_y, phi_z [rad]; its
        statistics (nm, nrad) are ``stats(point)["thermal"]``."""
    def inputs(self, variant: int = 0) -> Array:
        """(n, k) physical value of each varied input per sample (SI;
        mu dimensionless); columns named by :meth:`input_names`."""
    def input_names(self, variant: int = 0) -> list[str]: ...
    def indices(self, variant: int = 0) -> list[int]:
        """Design row of each sample (rows of ``poses`` and ``inputs``)."""
    def sigma(
        self, point: str | None = None, variant: int = 0, interchange: bool = False
    ) -> Array:
        """(6,) sample standard deviation (n - 1) per DOF: x, y, z [m], phi_x,
        phi_y, phi_z [rad], as ``Sweep.sigma`` and ``Prediction.sigma`` give
        theirs (``stats()["sigma"]`` holds the document's nm and nrad). The
        old dict keys (``x_nm`` ...) still read, deprecated."""
    def stats(
        self, point: str | None = None, variant: int = 0, interchange: bool = False
    ) -> dict[str, Any]:
        """The JSON's ``points`` entry: n, sigma and its 90 % interval,
        three_sigma, mean, min, max (nm, nrad), and ``directions``: the
        same per named direction of the point."""
    @property
    def shard(self) -> tuple[int, int]: ...
    def __len__(self) -> int: ...

class ThermalPath:
    """A thermal path (``kinrepro thermal --json``): the seating, then the
    scene's temperature cycle."""

    @property
    def point_names(self) -> list[str]: ...
    @property
    def delta_t_k(self) -> Array:
        """(n_cycle_points, 2) temperature changes [K] of the moving and
        the fixed body."""
    @property
    def drift(self) -> Array:
        """(n_cycle_points, n_points, 6) drift of each evaluation point
        from where it was seated: x, y, z [m] (rigid motion and the body's
        expansion), phi_x, phi_y, phi_z [rad]; the last point back at
        [0, 0] is the residual."""
    @property
    def first_slip_delta_t_k(self) -> float | None: ...
    @property
    def slipping_contacts(self) -> list[list[int]]: ...
    @property
    def path_error(self) -> list[float | None]: ...
    def to_json(self) -> str: ...
    def table(self) -> str: ...

def thermal(
    scene: Scene,
    mu: Sequence[float] | None = None,
    cycle: Sequence[tuple[float, float]] | None = None,
    increments: int | None = None,
    path_tolerance: float | None = None,
) -> ThermalPath:
    """Seat the coupling and follow its ``[thermal]`` temperature cycle
    (``kinrepro thermal``); ``cycle`` replaces the scene's, pairs
    (dT_moving, dT_fixed) in K."""

class Sweep:
    """A sweep (``kinrepro sweep --format json``) with numpy views over its
    design points (rows, in document order). Picklable; ``==`` compares
    the whole document."""

    @staticmethod
    def from_json(text: str) -> Sweep: ...
    def to_json(self) -> str: ...
    def to_dict(self) -> dict[str, Any]:
        """The document; ``designs`` holds every design point (sigma in nm
        and nrad, stiffness, safety, Pareto flag)."""
    def table(self) -> str: ...
    def csv(self) -> str: ...
    def names(self) -> list[str]:
        """The swept fields (TOML paths): the columns of :meth:`values`."""
    def values(self) -> Array:
        """(n_designs, k) value of each swept field per design point, in the
        scene file's SI units (N, m, ...); NaN for a field swept over names
        (materials, arrangements: see :meth:`to_dict`)."""
    def indices(self) -> list[int]:
        """Row of each design point in the whole design (a shard holds some)."""
    def status(self) -> list[str]:
        """``"ok"`` or why the design point was not evaluated."""
    def sigma(self, point: str | None = None) -> Array:
        """(n_designs, 6) sample standard deviation (n - 1) at evaluation
        point ``point`` (None: the Pareto point, by default the scene's
        first) per design point: x, y, z [m], phi_x, phi_y, phi_z [rad]; a
        row of NaN where the point was not evaluated."""
    def __len__(self) -> int: ...

class Calibration:
    """A calibration (``kinrepro calibrate --out``)."""

    @staticmethod
    def from_json(text: str, file: str = "<string>") -> Calibration: ...
    @staticmethod
    def load(path: Union[str, os.PathLike[str]]) -> Calibration: ...
    def to_json(self) -> str: ...
    def to_dict(self) -> dict[str, Any]: ...
    @property
    def estimates(self) -> dict[str, float]:
        """Fitted value of each parameter (``spread``, ...)."""
    def table(self) -> str: ...

class Prediction:
    """Predicted scatter of other designs (``kinrepro predict``)."""

    def to_json(self) -> str:
        """The document of ``kinrepro predict --format json``."""
    def to_dict(self) -> dict[str, Any]: ...
    def table(self) -> str: ...
    def scenes(self) -> list[str]:
        """The scene file of each prediction: the rows of :meth:`sigma`."""
    def sigma(self, point: str | None = None) -> Array:
        """(n_scenes, 6) predicted sigma at ``point`` (None: the first
        evaluation point): x, y, z [m], phi_x, phi_y, phi_z [rad]."""
    def interval(self, point: str | None = None) -> Array:
        """(n_scenes, 2, 6) 90 % prediction interval of sigma (low, high),
        m and rad; NaN where there is none."""
    def __len__(self) -> int: ...

def seat(
    scene: Scene,
    mu: Sequence[float] | None = None,
    solver: str = "quasi-static",
    increments: int | None = None,
    path_tolerance: float | None = None,
) -> Seating:
    """Seat the coupling once; ``mu``: static friction coefficient per
    contact (None: the scene's ``mu_static``). Quasi-static solver: the load
    path is error-controlled to ``path_tolerance`` (the estimated error of
    the seated pose relative to the seating's motion, None: 1e-5), or
    ``increments`` fixed load increments (not error-controlled; give one of
    the two). GIL released."""

def stiffness(
    scene: Scene,
    at: str | Sequence[float] | None = None,
    mu: Sequence[float] | None = None,
) -> Array:
    """6x6 stiffness of the seated coupling, (u [m], phi [rad]) -> (F [N],
    M [N m]) about ``at``: an evaluation point's name, a point (x, y, z) [m]
    of the moving half, or None (the first evaluation point)."""

def study(
    scene: Scene | Sequence[Scene],
    samples: int | None = None,
    sampler: str | None = None,
    seed: int | None = None,
    vary: Sequence[str] = ("friction",),
    shard: Shard | None = None,
    jobs: int | None = None,
    solver: str = "quasi-static",
    increments: int | None = None,
    path_tolerance: float | None = None,
    replicates: int | None = None,
    sensitivity: bool = False,
    sobol_samples: int | None = None,
    offset_bounds: Sequence[float] | None = None,
    tilt_bounds: Sequence[float] | None = None,
    lanes: str = "auto",
) -> Study:
    """A reproducibility study (``kinrepro study``). ``samples``,
    ``sampler`` (``"lhs"``, ``"mc"``, ``"corners"``) and ``seed``: None takes
    the scene's ``[study]`` values. ``vary``: any of ``"friction"``,
    ``"preload"``, ``"start"``, ``"tolerances"``; ``"start"`` needs
    ``solver="dynamic"`` and ``offset_bounds`` (x, y half-widths and the
    largest height z [m]) and/or ``tilt_bounds`` (half-widths [rad]).
    ``solver``: ``"quasi-static"`` (load path error-controlled to
    ``path_tolerance``, None: 1e-5 of the seating's motion; or
    ``increments`` fixed load increments) or ``"dynamic"``. ``sensitivity``: SRC and Sobol
    indices (``sobol_samples``: base sample size N, None: 32768).
    ``shard``: run one part (merge the parts with :func:`merge`).
    ``jobs``: worker threads (None: all cores). ``lanes``: ``"auto"``
    (quasi-static samples four at a time in SIMD lanes where the build has
    AVX), ``"on"`` or ``"off"``; the results are the same bits either way.
    The options are checked by
    the library, as the CLI's flags are: a bad one raises KinreproError
    with the CLI's message, naming the flag (``--samples`` for
    ``samples``). GIL released; Ctrl-C raises KeyboardInterrupt."""

def merge(parts: Sequence[Study | str] | Sequence[Sweep] | Sequence[Optimization]) -> Any:
    """Merge the shards of a study (``Study`` objects or JSON texts; returns
    a ``Study`` equal to the unsharded run), of a sweep (``Sweep``) or of an
    optimisation (``Optimization``)."""

def sweep(
    scene: Scene,
    sets: list[str],
    points: int | None = None,
    pareto_point: str | None = None,
    samples: int | None = None,
    sampler: str | None = None,
    seed: int | None = None,
    shard: Shard | None = None,
    jobs: int | None = None,
    increments: int | None = None,
    path_tolerance: float | None = None,
    replicates: int | None = None,
    objectives: Sequence[str] = (),
    constraints: Sequence[str] = (),
) -> Sweep:
    """The compiled sweep: ``sets`` as ``"FIELD=VALUES"`` strings
    (``kinrepro.sweep`` takes a dict)."""

class Optimization:
    """An optimisation: the document of ``kinrepro optimize --json``."""
    @staticmethod
    def from_json(text: str) -> Optimization: ...
    def to_json(self) -> str: ...
    def to_dict(self) -> dict[str, Any]: ...
    def table(self) -> str: ...
    def __eq__(self, other: object) -> bool: ...
    @property
    def optimum(self) -> dict[str, Any] | None:
        """``fields``, ``objective``, ``constraint_margins``, ``design``,
        ``statistical_error``; None when no candidate met every constraint."""

def optimize(
    scene: Scene,
    vary: list[str],
    objective: str | None = None,
    constraints: Sequence[str] = (),
    samples: int | None = None,
    sampler: str | None = None,
    seed: int | None = None,
    jobs: int | None = None,
    increments: int | None = None,
    path_tolerance: float | None = None,
    replicates: int | None = None,
    max_iterations: int = 200,
    starts: int = 1,
    shard: Shard | None = None,
) -> Optimization:
    """The compiled optimisation: ``vary`` as ``"FIELD=VALUES"`` strings
    (``kinrepro.optimize`` takes a dict)."""

def calibrate(
    scene: Scene,
    measured: Union[str, os.PathLike[str], npt.ArrayLike],
    fit: Sequence[str] = (),
    noise: str | None = None,
    point: str | None = None,
    model_samples: int = 2000,
    seed: int = 15015,
    delimiter: str | None = None,
    jobs: int | None = None,
    dofs: Sequence[str] | None = None,
) -> Calibration:
    """Fit the scale of the friction distribution (``spread`` for a uniform
    one, ``sd`` for a normal or lognormal one; the default ``()``) and
    optionally ``mu_static``, ``dynamic_ratio``, ``support_compliance``
    to the measured re-seating
    scatter (``kinrepro calibrate``). ``measured``: a measurement file
    (docs/measurements.md; ``delimiter`` as ``--delimiter``), or an
    (n_cycles, k) array of the readings of each re-seating cycle in SI
    (x, y, z [m], phi_x, phi_y, phi_z [rad]) whose columns are the DOFs
    ``dofs`` (None: all six in that order), checked like a file's rows.
    ``noise``: sensor noise sigma as ``"x=1nm,phi_x=20nrad"`` (a number
    without unit is SI). ``point``: the evaluation point measured (None:
    the file's, else the scene's first). GIL released; Ctrl-C raises
    KeyboardInterrupt."""

def predict(
    scenes: Scene | Sequence[Scene],
    calibration: Calibration,
    samples: int = 2000,
    seed: int = 15015,
    jobs: int | None = None,
) -> Prediction:
    """Predicted scatter of other designs (``kinrepro predict``):
    ``Prediction.to_dict()`` is ``kinrepro predict --format json``,
    ``sigma()`` and ``interval()`` numpy arrays in SI. GIL released;
    Ctrl-C raises KeyboardInterrupt."""
