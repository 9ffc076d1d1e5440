r"""Resolution of the collocation solver: the a priori degree, the mode's coefficient tail and
the error model (Eq. ``inst1``; calibrated against the mpmath characteristic equation).

Resolution is judged as in Chebfun, simplified: a resolved mode has Chebyshev coefficients that
have decayed to the tolerance by the end of the expansion; the estimate of p*'s error is a
calibrated function of that tail plus a measured round-off floor (:func:`error_estimate`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod.straight_rod.discretisation import FamilyOperator

__all__ = ["ERR_LINEAR", "ERR_QUADRATIC", "N_MAX", "N_MIN", "ROUNDOFF_TWIST", "error_estimate",
           "error_estimate_scalar", "initial_degree", "initial_degree_scalar", "mode_tails",
           "raised_degree", "roundoff_floor", "tail_for_tolerance", "tail_from_parts", "tail_parts",
           "tails_of"]

N_MIN, N_MAX = 8, 512
EPS = float(np.finfo(float).eps)
#: Error model of :func:`error_estimate` (calibrated against the mpmath reference).
ERR_LINEAR, ERR_QUADRATIC, ROUNDOFF_BASE, ROUNDOFF_TWIST = 5.0e-4, 200.0, 32.0, 0.3


def initial_degree(twist_angle: NDArray[np.float64], tol: float) -> NDArray[np.int_]:
    """A priori Chebyshev degree for relative accuracy `tol` (fitted, see below).

    The critical mode is a sum of cos/sin(beta_k s) with beta_k <= sqrt(X_+) ~ |Omega| + pi
    (:func:`spectral_rod.critical_wavenumbers`); on x = 2 s - 1 that is frequency k ~ |Omega| / 2,
    which Chebyshev series resolve from degree ~ k on, with a transition layer ~ k^(1/3) wide.
    With L = log10(1/tol),

        n0 = |Omega|/2 + 3.5 + 0.5 L + 1.3 (1 + |Omega|)^(1/3) sqrt(L)   (rounded up to even)

    is the smallest degree whose :func:`error_estimate` meets `tol`, fitted on Omega in
    [0, 300], nu in [1, 100], tol in [1e-12, 1e-4] (exact or 2 above in 90 % of the cases, 2-4
    below in 3 of 153; the a-posteriori check then raises the degree). ``nu`` does not enter:
    the needed degree varies by at most 2 over nu in [1, 100].
    """
    om = np.abs(np.asarray(twist_angle, dtype=float))
    x = _degree_formula(om, -math.log10(tol), np.cbrt)
    return np.clip(2 * np.ceil(x / 2).astype(int), N_MIN, N_MAX)


def raised_degree(n):
    """The next degree tried where the estimate misses tol: ~12 % higher, even, <= N_MAX (works
    on ints and on integer arrays)."""
    return np.minimum(N_MAX, n + 2 * np.ceil(0.06 * np.asarray(n) + 1).astype(int))


def initial_degree_scalar(twist_angle: float, tol: float) -> int:
    """:func:`initial_degree` for one point, in Python floats (the scalar path's)."""
    x = _degree_formula(abs(twist_angle), -math.log10(tol), lambda v: v ** (1.0 / 3.0))
    return min(N_MAX, max(N_MIN, 2 * math.ceil(x / 2)))


def _degree_formula(om, big_l: float, cbrt):
    """n0 of :func:`initial_degree` before rounding (om = |Omega|, big_l = log10(1/tol)).

    The fit was made for tol <= 1e-4; for looser tolerances it fell short (at tol 1e-2 the
    degree had to be raised at 427 of Figure 1's 1,201 points, each raise a second solve), so
    big_l is taken >= 3.5 (measured: 0 raises at 1e-2, 4 at 1e-3).
    """
    big_l = max(big_l, 3.5)
    return om / 2 + 3.5 + 0.5 * big_l + 1.3 * cbrt(1.0 + om) * math.sqrt(big_l)


def error_estimate_scalar(tail_value: float, twist_angle: float) -> float:
    """:func:`error_estimate` for one point, in Python floats (the scalar path's)."""
    t = tail_value  # the same operations in the same order as error_estimate (bit-equal)
    return max(ERR_LINEAR * t, ERR_QUADRATIC * (t * t)) + EPS * (
        ROUNDOFF_BASE + ROUNDOFF_TWIST * (twist_angle * twist_angle))


def error_estimate(tail_value: ArrayLike, twist_angle: ArrayLike) -> NDArray[np.float64]:
    """Estimated relative error of p* from the mode's Chebyshev tail (see module docstring).

        estimate = max(ERR_LINEAR * tail, ERR_QUADRATIC * tail^2) + eps (32 + 0.3 Omega^2)

    Calibrated against the mpmath characteristic equation (:mod:`spectral_rod.characteristic`)
    for Omega in {0, 0.5, ..., 300}, nu in {1, 1.1, 1.5, 2, 4, 10, 100} and every even degree
    from 8 until the tail is below 1e-13 (2,120 cases): the discretisation error was at most
    3.3e-4 tail for tail < 1e-5 and at most 33 tail^2 for 1e-5 <= tail < 1e-2, so the two
    constants carry safety factors 1.5 and 6. The round-off floor (the Omega^2 terms of the
    pencil cancel to ~lambda) was re-measured for the solver as it is (shift-and-invert, final
    Rayleigh quotient in extended precision above |Omega| = 20) on Omega in [40, 100]: at most
    0.19 eps Omega^2 (0.22 with the full ``eig``), hence the 0.3. With tail >= 1e-2 the mode
    is not resolved and the estimate (>= 2e-2) only says so.
    """
    t = np.asarray(tail_value, dtype=float)
    om = np.asarray(twist_angle, dtype=float)
    return np.maximum(ERR_LINEAR * t, ERR_QUADRATIC * (t * t)) + roundoff_floor(om)


def tail_for_tolerance(tol: float) -> float:
    """The coefficient tail at which the linear branch of :func:`error_estimate` equals `tol`
    (tol / ERR_LINEAR): the level a resolved mode's coefficients must have decayed to."""
    from spectral_rod._validation import check_tol

    return check_tol(tol) / ERR_LINEAR


def roundoff_floor(twist_angle: ArrayLike) -> NDArray[np.float64]:
    """Round-off part of :func:`error_estimate`: eps (32 + 0.3 Omega^2), measured (see there)."""
    om = np.asarray(twist_angle, dtype=float)
    return EPS * (ROUNDOFF_BASE + ROUNDOFF_TWIST * (om * om))


#: tail_parts' split of the last axis: the four tail coefficients first, then the others.
_TAIL_SPLIT = np.array([0, 4])


def tail_parts(coefficients: NDArray[np.float64]) -> NDArray[np.float64]:
    """The largest |coefficient| of the four tail ones and of the others (a new last axis of
    2), from coefficients laid out as ``FamilyOperator.tail_rows`` gives them (last axis): the
    parts of :func:`tails_of` (the lean solver's one-point path finishes them in floats)."""
    return np.maximum.reduceat(np.abs(coefficients), _TAIL_SPLIT, axis=-1)


def tail_from_parts(parts: NDArray[np.float64]) -> NDArray[np.float64]:
    """:func:`tails_of` from its :func:`tail_parts`: the tail part over the larger part; inf
    where the mode is zero."""
    last, scale = parts[..., 0], np.maximum.reduce(parts, axis=-1)
    if scale.all():  # no zero mode: skip the guarded division
        return last / scale
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(scale > 0, last / scale, np.inf)


def tails_of(coefficients: NDArray[np.float64]) -> NDArray[np.float64]:
    """The coefficient tail from coefficients laid out as ``FamilyOperator.tail_rows`` gives
    them (last axis): the largest of the four tail coefficients relative to the largest of all;
    inf where the mode is zero."""
    return tail_from_parts(tail_parts(coefficients))


def mode_tails(op: FamilyOperator, vectors: NDArray[np.float64]) -> NDArray[np.float64]:
    """Coefficient tail of each mode (omega1, omega2): the largest of the last two Chebyshev
    coefficients of each field's parity, relative to the largest coefficient of both fields.

    A field that vanishes (omega2 at zero twist) has no meaningful tail of its own.

    The same numbers as ``tails_of(vectors @ op.tail_rows.T)``, with the coefficients laid out
    (rows, points) so that the maxima run along the points (2.5 times faster on Figure 1's
    1,201 points: a reduction over a short last axis is slow in numpy).
    """
    a = np.abs(op.tail_rows @ vectors.T)
    last, other = a[:_TAIL_SPLIT[1]].max(axis=0), a[_TAIL_SPLIT[1]:].max(axis=0)
    scale = np.maximum(last, other)
    if scale.all():  # no zero mode: skip the guarded division
        return last / scale
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(scale > 0, last / scale, np.inf)
