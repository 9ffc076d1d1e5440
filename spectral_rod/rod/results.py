"""The result objects of the straight-rod entry points (``full_output=True`` and modes).

Scalar input gives Python scalars in the fields, array input arrays of the broadcast shape; the
``repr`` stays short for arrays (shape and range, not every value).
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray

__all__ = ["BucklingMode", "CriticalLoad", "as_output"]


def as_output(value: Any, shape: tuple[int, ...]) -> Any:
    """`value` (flat array) reshaped to `shape`; shape () gives a Python scalar."""
    arr = np.asarray(value).reshape(shape)
    return arr.item() if shape == () else arr


def _short(value: Any) -> str:
    if isinstance(value, np.ndarray) and value.size > 4:
        if value.dtype.kind in "fiu":
            return f"array(shape={value.shape}, min={value.min():.6g}, max={value.max():.6g})"
        return f"array(shape={value.shape}, values={sorted(set(value.ravel().tolist()))})"
    return repr(value)


class _ShortRepr:
    def __repr__(self) -> str:
        body = ", ".join(f"{f.name}={_short(getattr(self, f.name))}"
                         for f in fields(cast(Any, self)))
        return f"{type(self).__name__}({body})"


@dataclass(frozen=True, repr=False)
class CriticalLoad(_ShortRepr):
    """Result of :func:`spectral_rod.critical_load` with ``full_output=True``.

    p_star: P_cr / (pi^2 A1 / L^2); method: the method that computed it (one of
    :data:`spectral_rod.ROD_METHODS`, chosen per point by :func:`spectral_rod.choose_method`);
    n: that method's resolution (Chebyshev degree for collocation, sine modes per field for the
    increment, Legendre degree for Rayleigh-Ritz, 0 for the characteristic equation, which has no
    discretisation); error_estimate: estimated relative error of p_star (each method's error
    model, see its module); family: 'symmetric' (omega1 even about the mid-point) or
    'antisymmetric'; converged: error_estimate <= tol; tol: the requested tolerance; engine:
    what computed it, "kernel" (the C kernel) or "numpy" (its numpy reference) for collocation,
    the method's name for the other methods (None where a caller did not record it).

    Examples
    --------
    >>> import spectral_rod as sr
    >>> r = sr.critical_load(0.0, 1.5, full_output=True)
    >>> round(float(r.p_star), 12), r.family, r.converged
    (1.0, 'symmetric', True)
    """

    p_star: Any
    method: Any
    n: Any
    error_estimate: Any
    family: Any
    converged: Any
    tol: float
    engine: Any = None


@dataclass(frozen=True, repr=False)
class BucklingMode(_ShortRepr):
    """The critical mode of the hinged twisted rod on a uniform grid s/L in [0, 1].

    omega1, omega2: curvatures in the body frame (u0, v0), scaled so that max |omega| = 1 on a
    fixed fine grid of s <= 1/2 (SCALE_POINTS in [0, 1]), the largest entry there positive:
    the same normalisation whatever the output grid (whose own maximum differs from 1 by the
    fixed grid's sampling: 0.5 % at Omega(L) = 53, nu = 273); x1, x2: the centreline
    displacement in the fixed frame (e1, e2), x'' = R(Omega s) omega with x = 0 at both ends
    (units of L when omega is in units of 1/L);
    p_star, method, n, error_estimate, converged: as in :class:`CriticalLoad` (the mode is
    computed by the method that computed p*, see :func:`spectral_rod.buckling_mode`); beta1,
    beta2: the critical wavenumbers times L (beta1 complex when imaginary); family: 'symmetric'
    or 'antisymmetric' about s = L/2.

    Examples
    --------
    >>> import spectral_rod as sr
    >>> m = sr.buckling_mode(5.0, 1.5, points=11)
    >>> m.s.shape, m.family, m.converged
    ((11,), 'symmetric', True)
    """

    s: NDArray[np.float64]
    omega1: NDArray[np.float64]
    omega2: NDArray[np.float64]
    x1: NDArray[np.float64]
    x2: NDArray[np.float64]
    p_star: float
    twist_angle: float
    nu: float
    family: str
    method: str
    n: int
    error_estimate: float
    converged: bool
    beta1: complex | float
    beta2: float
