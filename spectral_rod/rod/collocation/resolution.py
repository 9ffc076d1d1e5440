r"""Resolution of the collocation solver: the a priori degree, the mode's coefficient tail and
the error model (Eq. ``inst1``; calibrated against the characteristic equation).

Resolution is judged as in Chebfun, simplified: a resolved mode has Chebyshev coefficients that
have decayed to the tolerance by the end of the expansion; the estimate of p*'s error is a
calibrated function of that tail and the degree plus a measured round-off floor
(:func:`error_estimate`).

The degree is chosen for the tail's part of the estimate to be at most a share of the requested
tol (:func:`.tuning.truncation_share`; :func:`initial_degree`, :func:`shortfall`): a tenth up to
tol 1e-10, where the estimate is a bound with safety factors but where it lands just below tol
the error itself can come close to it (on the collocation part of a 200 x 200 map, Omega(L) <
50, nu in [1, 100], against the characteristic equation at tol 1e-12: with the degree held to
the whole estimate, errors up to 1.6e-13 and 226 of 20,000 points above 1e-13, all at Omega(L)
> 30; with the share at most 4.6e-14 there: ``python tests/bench/accuracy_at_tol.py`` prints
these); 0.9 above, so that a loose tol buys a lower degree and delivers errors within ~100x of
tol rather than 1e4x (``python tests/bench/hunt_tol.py`` hunts for misses at every tol;
``tests/test_accuracy_control.py`` checks a sample). A point is converged where the whole
estimate is <= tol.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod.rod.collocation.arithmetic import ARRAYS, FLOATS, Namespace
from spectral_rod.rod.collocation.discretisation import FamilyOperator
from spectral_rod.rod.collocation.tuning import TIGHT_TOL, TRUNCATION_SHARE, truncation_share

__all__ = ["ARRAYS", "ERR_LINEAR", "ERR_QUADRATIC", "FLOATS", "N_MAX", "N_MIN", "ROUNDOFF_DEGREE",
           "ROUNDOFF_TWIST", "TAIL_UNRESOLVED", "TRUNCATION_SHARE",
           "error_estimate", "initial_degree", "mode_tails", "raised_degree", "roundoff_floor",
           "shortfall", "tail_for_tolerance", "tail_from_parts", "tail_parts", "tails_of",
           "truncation_error"]

N_MIN, N_MAX = 8, 512
EPS = float(np.finfo(float).eps)
#: Error model of :func:`error_estimate` (calibrated against the characteristic equation:
#: ERR_LINEAR and the round-off constants see there, ERR_QUADRATIC and TAIL_UNRESOLVED
#: ``python tests/bench/tol_model_fit.py``).
ERR_LINEAR, ERR_QUADRATIC, ROUNDOFF_BASE, ROUNDOFF_TWIST = 5.0e-4, 0.01, 32.0, 0.3
#: From this tail on the mode is not resolved: the truncation part is inf (not calibrated).
TAIL_UNRESOLVED = 0.1
#: The degree's part of the round-off floor, eps (n / ROUNDOFF_DEGREE)^4 (:func:`roundoff_floor`).
ROUNDOFF_DEGREE = 64.0
#: The a priori degree's constants c0..c3 (:func:`initial_degree`; fitted, see there).
DEGREE_FIT = (5.0, 0.4, 0.3, 1.0)
#: Above :data:`.tuning.TIGHT_TOL` the a priori degree's L is log10(1/t) less LOOSE_L_OFFSET,
#: and at least LOOSE_L_MIN (:func:`initial_degree`; ``tests/bench/degree_fit.py``).
LOOSE_L_OFFSET, LOOSE_L_MIN = 1.0, 1.0


def initial_degree(twist_angle: ArrayLike, tol: float, xp: Namespace = ARRAYS):
    """A priori Chebyshev degree for relative accuracy `tol`: the fit below at t =
    truncation_share(tol) tol (the module docstring says why); an int array (``xp`` =
    :data:`.arithmetic.ARRAYS`) or an int for one point in Python floats
    (:data:`.arithmetic.FLOATS`).

    The critical mode is a sum of cos/sin(beta_k s) with beta_k <= sqrt(X_+) ~ |Omega| + pi
    (:func:`spectral_rod.critical_wavenumbers`); on x = 2 s - 1 that is frequency k ~ |Omega| / 2,
    which Chebyshev series resolve from degree ~ k on, with a transition layer ~ k^(1/3) wide,
    and each further digit costs a few degrees more the wider that layer is. With
    L = log10(1/t) >= 3.5, t = truncation_share(tol) tol and (c0, c1, c2, c3) = DEGREE_FIT,

        n0 = |Omega|/2 + c0 + c1 L + (c2 L + c3) (1 + |Omega|)^(1/3)   (rounded up to even)

    is fitted to the degree from which the tail's part of the estimate stays <= t
    (``tests/bench/degree_fit.py``: Omega(L) = 0..49, nu 1.05..100, tol 1e-2..1e-12; the
    expected cost, ~n0^2 plus a second solve where n0 falls short, at 1.06-1.17 of the ideal
    and short at none of the 300 points at any tol; the a-posteriori check raises the degree
    where it is). ``nu`` does not enter: the needed degree varies by at most 2 over nu in
    [1, 100]. Big L is taken >= 3.5: a fit to tol <= 1e-4 falls short at looser ones, each
    shortfall a second solve (``tests/bench/degree_fit.py`` prints the shortfalls per tol).

    Above TIGHT_TOL the tail part's target is LOOSE_SHARE tol and its quadratic term
    ERR_QUADRATIC (n tail)^2 (:func:`truncation_error`) decides: there L = log10(1/t) -
    LOOSE_L_OFFSET, at least LOOSE_L_MIN (the same four constants; ``tests/bench/degree_fit.py``,
    the loose tols 1e-2..1e-9: short at no point of the grid at tol 1e-2..1e-8, cost 1.07-1.16
    of the ideal). At tol <= TIGHT_TOL the degree is that of the fit.

    >>> initial_degree(3.0, 1e-12, FLOATS), initial_degree(np.array([3.0]), 1e-12).tolist()
    (20, [20])
    """
    om = xp.abs(xp.asfloat(twist_angle))
    big_l = _big_l(tol)
    c0, c1, c2, c3 = DEGREE_FIT
    x = om / 2 + c0 + c1 * big_l + (c2 * big_l + c3) * xp.cbrt(1.0 + om)
    return xp.clip(2 * xp.to_int(xp.ceil(x / 2)), N_MIN, N_MAX)


def _big_l(tol: float) -> float:
    """L of :func:`initial_degree`'s formula for `tol` (see there)."""
    big_l = -math.log10(truncation_share(tol) * tol)
    if tol <= TIGHT_TOL:
        return max(big_l, 3.5)
    return max(big_l - LOOSE_L_OFFSET, LOOSE_L_MIN)


def raised_degree(n, shortfall, xp: Namespace = ARRAYS):
    """The next degree tried where the tail's part of the estimate misses its target by the
    factor `shortfall` (> 1; :func:`shortfall`): 2 higher per factor 10 of it, at most ~12 %
    higher, even, <= N_MAX (an int array, or an int with ``xp`` = FLOATS). The 2 per factor 10
    is empirical: a step of 2 divided the tail's part by 9.0 at least and 32 in the median
    (``tests/bench/degree_fit.py``, Omega(L) < 50, parts in [1e-14, 1e-3]); where it falls
    short the loop raises again.

    >>> raised_degree(20, 50.0, FLOATS), raised_degree(np.array([20, 60]), np.inf).tolist()
    (24, [26, 70])
    """
    tens = xp.ceil(xp.log10(xp.maximum(shortfall, 10.0)))
    return xp.minimum(N_MAX, n + 2 * xp.to_int(xp.minimum(tens, xp.ceil(0.06 * n + 1))))


def shortfall(tail_value: ArrayLike, tol: float, n: ArrayLike, xp: Namespace = ARRAYS):
    """The tail's part of the estimate at degree `n` over its target truncation_share(tol) tol:
    the degree loop raises the degree where it is > 1 (while round-off alone does not
    decide)."""
    return truncation_error(tail_value, n, xp) / (truncation_share(tol) * tol)


def truncation_error(tail_value: ArrayLike, n: ArrayLike, xp: Namespace = ARRAYS):
    """The tail's part of :func:`error_estimate` at degree `n`: ERR_LINEAR tail + ERR_QUADRATIC
    (n tail)^2, inf from tail TAIL_UNRESOLVED on (see there)."""
    t = xp.asfloat(tail_value)
    nt = xp.asfloat(n) * t
    return xp.where(t < TAIL_UNRESOLVED, ERR_LINEAR * t + ERR_QUADRATIC * (nt * nt), math.inf)


def error_estimate(tail_value: ArrayLike, twist_angle: ArrayLike, n: ArrayLike,
                   xp: Namespace = ARRAYS):
    """Estimated relative error of p* from the mode's Chebyshev tail at degree `n` (see module
    docstring).

        estimate = ERR_LINEAR tail + ERR_QUADRATIC (n tail)^2     (tail < TAIL_UNRESOLVED)
                   + eps (32 + 0.3 Omega^2 + (n / ROUNDOFF_DEGREE)^4)

    and inf from tail TAIL_UNRESOLVED = 0.1 on (the mode is not resolved; the error is not
    calibrated there). The linear term: calibrated against the mpmath characteristic equation
    (:mod:`spectral_rod.rod.characteristic`) for Omega in {0, 0.5, ..., 300}, nu in {1, 1.1,
    1.5, 2, 4, 10, 100} and every even degree from 8 until the tail is below 1e-13 (2,120
    cases): the discretisation error was at most 3.3e-4 tail for tail < 1e-5 (safety factor
    1.5). The quadratic term (an eigenvalue's error goes as the square of its mode's, and the
    tail's weight in it grows with the degree) is empirical, fitted on Omega(L) in {0, 0.5,
    ..., 49.5}, 14 nu from 1.0011 to 1e4, every even degree 8..60 (37,800 cases, against the
    characteristic equation in double precision): (error - ERR_LINEAR tail) / (n tail)^2 was
    at most 4.3e-3 for tail < TAIL_UNRESOLVED (0.0095 for tail < 0.3), so ERR_QUADRATIC = 0.01
    carries a safety factor 2.3 (``python tests/bench/tol_model_fit.py`` recomputes both and
    the ratio error / estimate). On 2,000 random points outside that grid (Omega(L) to 800, nu
    to 1e4, nu - 1 log-spaced from 1e-3) at every tol from 1e-2 to 1e-12 the error was at
    most 0.73 of the estimate and no converged point erred above tol (``python
    tests/bench/hunt_tol.py``, 40-digit references). The round-off floor (the Omega^2 terms of the
    pencil cancel to ~lambda) is measured for this solver (shift-and-invert, final
    Rayleigh quotient in extended precision above |Omega| = LONG_TWIST) on Omega in [40, 100]:
    at most 0.19 eps Omega^2 (0.22 with the full ``eig``), hence the 0.3. The degree's part
    eps (n/64)^4 covers a forced degree far above the one the tail needs: the operator's
    round-off grows with n, beyond the model's first two terms from n ~ 440 on (on 300 random
    points, Omega(L) in [1e-3, 50] log-uniform, nu in [1, 1e4]: error less those terms at most
    77, 293 and 690 eps at n = 448, 496, 512, none above 0 at n = 16..384); without it an
    explicit n = 512 at tol 1e-14 erred by up to 14x the estimate (1.7e-13) while reported
    converged. ``python tests/bench/hunt_forced_degree.py`` recomputes the error over the
    estimate at 1,000 random points and degrees. At the automatic degrees (n <= ~70 for
    |Omega| < 50) it adds at most 1.5 eps. ``xp`` = FLOATS computes it for one point in Python
    floats (the same operations in the same order: the same bits).
    """
    return truncation_error(tail_value, n, xp) + roundoff_floor(twist_angle, n, xp)


def tail_for_tolerance(tol: float) -> float:
    """The level a mode's coefficients must have decayed to for `tol`: the tail at which the
    linear term of :func:`error_estimate` equals the tail's share of tol, truncation_share(tol)
    tol / ERR_LINEAR (the degree loop's target, :func:`shortfall`, where the linear term
    decides: at tol <= 1e-10; above, the quadratic term asks for a smaller tail).

    Returns
    -------
    float
        The coefficient level (relative to the mode's largest).

    Examples
    --------
    >>> tail_for_tolerance(1e-12)
    2e-10
    """
    from spectral_rod._validation import check_tol

    return truncation_share(check_tol(tol)) * tol / ERR_LINEAR


def roundoff_floor(twist_angle: ArrayLike, n: ArrayLike = 0, xp: Namespace = ARRAYS):
    """Round-off part of :func:`error_estimate` at degree `n`: eps (32 + 0.3 Omega^2 +
    (n / ROUNDOFF_DEGREE)^4), measured (see there); n = 0 gives the twist's part alone."""
    om = xp.asfloat(twist_angle)
    q = xp.asfloat(n) / ROUNDOFF_DEGREE
    return EPS * (ROUNDOFF_BASE + ROUNDOFF_TWIST * (om * om) + (q * q) * (q * q))


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
