"""The paper's ring result: Eq. ``crit2`` and the "threshold twist" it implies.

Drozdov & Rabin, section "Stability of a ring": a circular ring of radius R whose cross-section
turns N times around the centreline (Omega(s) = N s / R, N an integer for closure) under a
radially inward load q per unit length.  A one-mode Galerkin estimate gives, Eq. ``crit2``,

    q_cr = E2 (I1 + I2) / (2 R^3) * [3 - (I2 - I1)/(I2 + I1) * (N^2 + 1)],

and the text states that for N^2 >= 3 (I1 + I2)/(I2 - I1) - 1 the ring "becomes unstable ...
even in the absence of external forces".

Normalisation used throughout this package: loads as q R^3 / (E1 I1), nu = I2/I1 >= 1 (the paper
sets A1 <= A2), e = E2/E1.  In these units Eq. ``crit2`` reads

    q_cr R^3/(E1 I1) = e (1 + nu)/2 * [3 - (nu - 1)/(nu + 1) * (N^2 + 1)]
                     = e/2 * [3 (1 + nu) - (nu - 1)(N^2 + 1)].

Whether this estimate is *right* is answered numerically in
:mod:`spectral_rod.ring.second_variation`.
"""

from __future__ import annotations

import math
import numbers
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from spectral_rod._validation import as_float, check_nu, real_array

#: Largest twist (number of turns N) accepted by the ring functions.
MAX_TWIST = 1000
#: Accepted range of e = E2/E1.
E_RATIO_RANGE = (1.0e-6, 1.0e6)


def check_twist_count(N: object, name: str = "N", maximum: int = MAX_TWIST) -> int:
    """N, the number of turns of the cross-section around the ring: an integer in [0, maximum].

    Integer-valued floats (``2.0``) are accepted; ``2.5``, negative values, bools and
    non-numbers are not (closure of the ring requires an integer number of turns).
    """
    if isinstance(N, bool) or not isinstance(N, numbers.Real):
        raise TypeError(f"{name} (number of turns of the cross-section) must be an integer in "
                        f"[0, {maximum}], got {type(N).__name__}")
    value = as_float(N, f"{name} (number of turns of the cross-section)",
                     f"an integer in [0, {maximum}]")
    if not math.isfinite(value) or value != math.floor(value):
        raise ValueError(f"{name} (number of turns of the cross-section) must be an integer in "
                         f"[0, {maximum}] (the ring closes only for whole turns), got {N!r}")
    if value < 0 or value > maximum:
        raise ValueError(f"{name} (number of turns of the cross-section) must be an integer in "
                         f"[0, {maximum}], got {N!r}")
    return int(value)


def check_scalar_nu(nu: object, name: str = "nu") -> float:
    """A scalar nu = I2/I1 >= 1 (see :func:`spectral_rod._validation.check_nu`)."""
    arr = check_nu(nu, name)  # type: ignore[arg-type]
    if arr.ndim != 0:
        raise TypeError(f"{name} must be a scalar (nu = I2/I1 >= 1), got shape {arr.shape}")
    return float(arr)


def check_e_ratio(e_ratio: object, name: str = "e_ratio") -> float:
    """A scalar e = E2/E1 in (0, 1e6] (E2 enters the torsional stiffness A3 = E2 (I1 + I2))."""
    arr = real_array(e_ratio, name)  # type: ignore[arg-type]
    if arr.ndim != 0:
        raise TypeError(f"{name} must be a scalar (e = E2/E1 > 0), got shape {arr.shape}")
    value = float(arr)
    lo, hi = E_RATIO_RANGE
    if not (lo <= value <= hi):
        raise ValueError(f"{name} = E2/E1 must be > 0 (in [{lo:g}, {hi:g}]), got {value!r}")
    return value


def _crit2(N, nu: float, e_ratio: float):
    return 0.5 * e_ratio * (3.0 * (1.0 + nu) - (nu - 1.0) * (N * N + 1.0))


def crit2(N: ArrayLike, nu: object, e_ratio: object = 1.0):
    """Eq. ``crit2``, q_cr R^3/(E1 I1), as a function of a *real* N in [0, MAX_TWIST] (an array
    for smooth curves; the ring closes only for integer N, see :func:`ring_formula_load`).

    Returns
    -------
    ndarray of float
        q_cr R^3/(E1 I1) of Eq. ``crit2`` at each N (the broadcast shape of the inputs).

    Examples
    --------
    >>> crit2([0.0, 1.5], 1.5).tolist()
    [3.5, 2.9375]
    """
    n = real_array(N, "N")
    if np.any(n < 0) or np.any(n > MAX_TWIST):
        raise ValueError(f"N (turns of the cross-section) must be in [0, {MAX_TWIST}], "
                         f"got min {np.min(n):g}, max {np.max(n):g}")
    out = _crit2(n, check_scalar_nu(nu), check_e_ratio(e_ratio))
    return float(out) if out.ndim == 0 else out


def ring_formula_load(N: object, nu: object, *, e_ratio: object = 1.0) -> float:
    """The paper's Galerkin estimate of the ring's critical load, Eq. ``crit2``.

    Parameters
    ----------
    N : int >= 0
        Number of turns of the cross-section around the ring, Omega(s) = N s / R.
    nu : float >= 1
        nu = I2/I1 (A2/A1).
    e_ratio : float > 0
        e = E2/E1; the torsional stiffness is A3 = E2 (I1 + I2) = e (1 + nu) E1 I1.

    Returns
    -------
    float
        q_cr R^3/(E1 I1) = e/2 * [3 (1 + nu) - (nu - 1)(N^2 + 1)].  It is negative beyond the
        threshold twist (:func:`threshold_twist`); the value is returned as the formula gives it.

    Examples
    --------
    >>> ring_formula_load(0, 1.0)   # e/2 * 3 (1 + nu) at e = nu = 1
    3.0
    >>> ring_formula_load(2, 1.5) == float(crit2(2.0, 1.5))   # the integer N of the curve
    True
    """
    n = check_twist_count(N)
    return float(_crit2(float(n), check_scalar_nu(nu), check_e_ratio(e_ratio)))


class ThresholdTwist(NamedTuple):
    """Where Eq. ``crit2`` reaches zero, the paper's "threshold twist for spontaneous instability".

    continuous : the real N* >= 0 with crit2(N*) = 0, N*^2 = 3 (nu + 1)/(nu - 1) - 1
                 = (2 nu + 4)/(nu - 1); ``math.inf`` for nu = 1 (crit2 = 3 e > 0 for every N).
    integer    : the smallest integer N with crit2(N) <= 0 (the paper's "N^2 >= ..."), i.e.
                 ceil(N*); ``math.inf`` for nu = 1.

    Examples
    --------
    >>> import spectral_rod as sr
    >>> sr.threshold_twist(1.0)   # circular section: never unstable without load
    ThresholdTwist(continuous=inf, integer=inf)
    """

    continuous: float
    integer: int | float


def threshold_twist(nu: object) -> ThresholdTwist:
    """The twist at which Eq. ``crit2`` predicts instability without load (independent of e).

    N^2 >= 3 (I1 + I2)/(I2 - I1) - 1 = (2 nu + 4)/(nu - 1).  For nu = 1 (circular section) the
    formula never reaches zero and both fields are ``math.inf``.

    Returns
    -------
    ThresholdTwist
        The real root N* of Eq. ``crit2`` and the smallest integer N at or beyond it.

    Examples
    --------
    >>> t = threshold_twist(1.5)
    >>> round(t.continuous ** 2, 12), t.integer   # N^2 = (2 nu + 4)/(nu - 1) = 14 at nu = 1.5
    (14.0, 4)
    >>> ring_formula_load(4, 1.5) < 0 < ring_formula_load(3, 1.5)
    True
    """
    v = check_scalar_nu(nu)
    if v == 1.0:
        return ThresholdTwist(math.inf, math.inf)
    n_sq = (2.0 * v + 4.0) / (v - 1.0)
    cont = math.sqrt(n_sq)
    k = max(0, math.ceil(cont) - 1)
    while k * k * (v - 1.0) < 2.0 * v + 4.0:  # exact test of N^2 (nu - 1) >= 2 nu + 4
        k += 1
    return ThresholdTwist(cont, k)
