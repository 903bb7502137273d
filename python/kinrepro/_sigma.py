"""``sigma`` as numpy arrays in SI: ``Study.sigma()`` is the (6,) array of
one evaluation point, ``Sweep.sigma()`` and ``Prediction.sigma()`` the
(n, 6) arrays of every design point or scene, each row x, y, z [m], phi_x,
phi_y, phi_z [rad].

``Study.sigma()`` was a dict in nm and nrad (keys ``x_nm`` ... ``phi_z_nrad``)
before; for one release the array still answers those keys, ``keys()`` and
``items()``, with a ``DeprecationWarning``: use ``sigma()[i]`` (m, rad), or
``Study.stats()["sigma"]`` for the JSON's nm and nrad.
"""

from __future__ import annotations

import warnings

import numpy as np

#: The keys of the old dict, in the order of the array's DOFs.
KEYS = ("x_nm", "y_nm", "z_nm", "phi_x_nrad", "phi_y_nrad", "phi_z_nrad")


def _warn() -> None:
    warnings.warn(
        "Study.sigma() is an array in SI (m, rad), as Sweep.sigma() and "
        "Prediction.sigma() are; its dict keys (x_nm ... phi_z_nrad, nm and "
        "nrad) go in the next release: use sigma()[i] (m, rad) or "
        "Study.stats()['sigma'] (nm, nrad)",
        DeprecationWarning,
        stacklevel=3,
    )


class Sigma(np.ndarray):
    """The sigma of the six DOFs of one evaluation point, m and rad (a
    numpy array; the old dict keys are deprecated)."""

    def __new__(cls, values):
        return np.asarray(values, dtype=np.float64).view(cls)

    def __getitem__(self, key):
        if isinstance(key, str):
            _warn()
            if key not in KEYS:
                raise KeyError(key)
            return float(np.asarray(self)[KEYS.index(key)]) * 1e9
        return super().__getitem__(key)

    def keys(self):
        """Deprecated: the old dict's keys."""
        _warn()
        return list(KEYS)

    def items(self):
        """Deprecated: the old dict's (key, value in nm or nrad) pairs."""
        _warn()
        return [(k, float(v) * 1e9) for k, v in zip(KEYS, np.asarray(self))]
