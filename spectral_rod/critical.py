"""The public entry point for the straight rod's critical load, Eq. ``inst1`` with hinged ends.

:func:`critical_load` validates its input once, asks the router (:mod:`spectral_rod.router`) which
method answers each point, runs each method on its points, and returns p* with every result
flagged: a tolerance that is not met gives a :class:`spectral_rod.ConvergenceWarning` and
``converged=False``, whatever the method and whether or not the degree was forced.

Bounds: the true p* lies in [1, (1 + nu)/2] (:mod:`spectral_rod.families`), so every computed
value is projected onto that interval and its error estimate capped by the interval's width
(:func:`apply_bounds`). The projection can only bring a value closer to the truth: round-off
(1 - 2e-16 at nu = 1) and an unresolved forced degree (p* = 38 at Omega = 30, n = 8, which is also
flagged and warned about) both end inside the bounds.
"""

from __future__ import annotations

import importlib
import math
import warnings
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod._blas_threads import one_blas_thread
from spectral_rod._validation import (
    NU_MAX,
    TOL_RANGE,
    TWIST_MAX,
    broadcast_points,
    check_nu,
    check_tol,
    check_twist,
)
from spectral_rod.errors import ConvergenceWarning
from spectral_rod.families import FAMILIES, FAMILY_DTYPE
from spectral_rod.results import CriticalLoad, as_output
from spectral_rod.router import METHOD_DTYPE, ROD_METHODS, check_route, route, route_point
from spectral_rod.straight_rod import N_MAX, collocation_critical_load
from spectral_rod.straight_rod.collocation import pick_family_scalar
from spectral_rod.straight_rod.eigensolver import iteration_allowance, iteration_rtol
from spectral_rod.straight_rod.few_points import LEAN_MAX_DEGREE, solve_one
from spectral_rod.straight_rod.resolution import (
    error_estimate_scalar,
    initial_degree_scalar,
    raised_degree,
    shortfall_scalar,
)

__all__ = ["critical_load"]

_EPS = float(np.finfo(float).eps)


class PointResults(NamedTuple):
    """Flat arrays per point: p*, method, resolution, error estimate, family name."""

    p_star: NDArray[np.float64]
    method: NDArray[np.str_]
    n: NDArray[np.int_]
    error_estimate: NDArray[np.float64]
    family: NDArray[np.str_]


def _collocation(tw, nv, n, tol):
    r = collocation_critical_load(tw, nv, n=n, tol=tol)
    return r.p_star, r.n, r.error_estimate, np.asarray(FAMILIES)[r.family]


def _characteristic(tw, nv, n, tol):
    from spectral_rod.characteristic import characteristic_double_batch, double_error_estimate

    p, fam = characteristic_double_batch(tw, nv)
    return p, np.zeros(tw.size, dtype=int), double_error_estimate(tw), np.asarray(FAMILIES)[fam]


def _increment(tw, nv, n, tol):
    from spectral_rod.increment import galerkin_increments, increment_error_estimate

    d, fam, modes = galerkin_increments(tw, nv)
    return 1.0 + d, modes, increment_error_estimate(d), fam


def _ritz(tw, nv, n, tol):
    from spectral_rod.ritz import ritz_point

    p, deg, err, fam = zip(*(ritz_point(a, b, None, tol, None)
                             for a, b in zip(tw, nv, strict=True)), strict=True)
    return np.array(p), np.array(deg), np.array(err), np.array(fam)


_SOLVERS = {"collocation": _collocation, "characteristic": _characteristic,
            "increment": _increment, "ritz": _ritz}
#: the modules each method imports when first used (before the BLAS threads are limited, so
#: that the library a module brings, e.g. scipy.linalg's BLAS, is limited too)
_MODULES = {"collocation": "spectral_rod.straight_rod",
            "characteristic": "spectral_rod.characteristic",
            "increment": "spectral_rod.increment", "ritz": "spectral_rod.ritz"}
assert set(_SOLVERS) == set(ROD_METHODS) == set(_MODULES)


#: Points solved together at most: bounds the memory of a large call (the batched engine holds
#: ~k^2 doubles per point and family, the large-twist scan ~20 grid columns of 257 doubles per
#: point; with 2^12 points a call of 10^6 random points peaks at a few hundred MB, measured by
#: tests/test_safety.py, where 2^15 took 680 MB).
CHUNK = 1 << 12


def solve_points(tw: NDArray[np.float64], nv: NDArray[np.float64], methods: NDArray[np.str_],
                 n: int | None, tol: float) -> PointResults:
    """Run each method on its points (flat, validated arrays; methods from the router), in
    chunks of at most :data:`CHUNK` points, with small dense linear algebra on one BLAS thread
    (:mod:`spectral_rod._blas_threads`)."""
    if tw.size > CHUNK:
        parts = [solve_points(tw[i:i + CHUNK], nv[i:i + CHUNK], methods[i:i + CHUNK], n, tol)
                 for i in range(0, tw.size, CHUNK)]
        return PointResults(*(np.concatenate(v) for v in zip(*parts, strict=True)))
    p, deg, err = np.empty(tw.size), np.zeros(tw.size, dtype=int), np.empty(tw.size)
    fam = np.empty(tw.size, dtype=FAMILY_DTYPE)
    # the methods present (np.unique on strings sorts: 0.17 ms for Figure 1's 1,201 points)
    names = [name for name in ROD_METHODS if np.any(methods == name)]
    for name in names:
        importlib.import_module(_MODULES[name])
    with one_blas_thread():
        for name in names:
            idx = np.flatnonzero(methods == name)
            p[idx], deg[idx], err[idx], fam[idx] = _SOLVERS[name](tw[idx], nv[idx], n, tol)
    return PointResults(p, methods, deg, err, fam)


def apply_bounds(res: PointResults, nv: NDArray[np.float64]) -> None:
    """Project p* onto its rigorous bounds [1, (1 + nu)/2] and cap the error estimate by the
    bounds' width (in place): the truth lies in the bounds, so neither can make p* worse.
    The width is widened by eps, the rounding of (1 + nu)/2 (at nu = 1 + 2^-52 it rounds to 1,
    a width of 0, while p* - 1 = 1.1e-16)."""
    lo, hi = 1.0, (1.0 + nv) / 2.0
    res.p_star[:] = np.clip(res.p_star, lo, hi)
    res.error_estimate[:] = np.minimum(res.error_estimate, (hi - lo) / lo + _EPS)


def bounded_point(p: float, err: float, nv: float) -> tuple[float, float]:
    """:func:`apply_bounds` for one point in Python floats (the scalar paths'): p* projected
    onto [1, (1 + nu)/2], the estimate capped by the width plus eps.

    >>> bounded_point(1.3, 0.5, 1.5)
    (1.25, 0.2500000000000002)
    """
    hi = (1.0 + nv) / 2.0
    return min(max(p, 1.0), hi), min(err, (hi - 1.0) + _EPS)


def warn_unconverged(where: str, converged: NDArray[np.bool_], res: PointResults,
                     tw: NDArray[np.float64], nv: NDArray[np.float64], tol: float) -> None:
    """One ConvergenceWarning naming the worst point, if any point missed `tol`."""
    bad = np.flatnonzero(~converged)
    if not bad.size:
        return
    worst = bad[np.argmax(res.error_estimate[bad])]
    warnings.warn(
        f"{where}: tol={tol:g} not met at {bad.size} point(s); worst error estimate "
        f"{res.error_estimate[worst]:.2e} at twist_angle={tw[worst]:g}, nu={nv[worst]:g} "
        f"(method {res.method[worst]}, n={res.n[worst]}); flagged converged=False",
        ConvergenceWarning, stacklevel=3)


def _one_point(twist_angle: object, nu: object, n: object, tol: object, method: object,
               full_output: object):
    """The scalar fast path: p* (or its CriticalLoad) for one point given as Python or numpy
    floats on the collocation or the large-twist route, or None wherever the general path must
    answer (any other input, the increment route, a forced degree, a point the lean solver does
    not accept or whose estimate misses tol). The computation is the general path's for one
    point, without its array bookkeeping: collocation calls
    :func:`spectral_rod.straight_rod.few_points.solve_one` with Python floats (measured
    2026-12-05 by the benchmarks: 26.4-26.5 us a scalar call in a loop over Figure 1's points
    where it runs on the C kernel, 58-60 us by the dense pencils; 2026-12-02: 210 us a one-point
    array call by the general path), the large-twist route :func:`_one_characteristic`;
    `python -m pytest -m bench` measures both scalar loops."""
    if not (isinstance(twist_angle, (float, int)) and isinstance(nu, (float, int))
            and isinstance(tol, float) and n is None
            and method in ("auto", "collocation", "characteristic")
            and isinstance(full_output, (bool, np.bool_))) or isinstance(twist_angle, bool) \
            or isinstance(nu, bool):
        return None
    try:
        om, nv = abs(float(twist_angle)), float(nu)
    except OverflowError:  # an int beyond float range: the general path names it
        return None
    if not (om <= TWIST_MAX and 1.0 <= nv <= NU_MAX and TOL_RANGE[0] <= tol <= TOL_RANGE[1]):
        return None  # includes NaN: the general path names the bad argument
    chosen = route_point(om, nv, None, method)
    if chosen == "characteristic":
        return _one_characteristic(om, nv, tol, full_output)
    if chosen != "collocation":
        return None
    deg = initial_degree_scalar(om, tol)
    if error_estimate_scalar(0.0, om) >= tol:
        return None  # tol below the round-off floor: unconverged, the general path flags it
    rtol, allowance = iteration_rtol(tol), iteration_allowance(tol)
    while True:  # the degree loop of collocation_critical_load, for one point
        if deg > LEAN_MAX_DEGREE:
            return None
        # no BLAS thread limit here: the lean solver's matrices (m < 100) are below
        # OpenBLAS's threading thresholds, and the limit would cost 4 us of a ~60 us call
        lam, tails, ok = solve_one(deg, om, nv, rtol)
        if not ok:
            return None
        best, tail = pick_family_scalar(lam, tails)
        short = shortfall_scalar(tail, tol)
        if short <= 1.0:
            break
        if deg >= N_MAX:
            return None  # unconverged: the general path warns and flags it
        deg = int(raised_degree(deg, short))
    err = error_estimate_scalar(tail, om) + allowance
    if err > tol:
        return None  # unconverged (round-off with the allowance): the general path flags it
    p, err = bounded_point(lam[best] / math.pi**2, err, nv)
    if not full_output:
        return p
    return CriticalLoad(p, "collocation", deg, err, FAMILIES[best], converged=True, tol=tol)


def _one_characteristic(om: float, nv: float, tol: float, full_output: bool):
    """:func:`_one_point` on the large-twist route: the characteristic equation in double
    precision for one point (its refinement in Python floats: 0.19 ms a call against 1.2 ms by
    the array path, measured 2026-12-05 on 30 random points, Omega(L) in [50, 1000]), bounds and
    estimate as :func:`solve_points` and :func:`apply_bounds` give them; None where the estimate
    misses tol (the general path warns and flags)."""
    from spectral_rod.characteristic import characteristic_double, double_error_estimate

    _, err = bounded_point(1.0, float(double_error_estimate(om)), nv)  # it does not need p*
    if err > tol:
        return None
    p, family = characteristic_double(om, nv)
    p, _ = bounded_point(p, err, nv)
    if not full_output:
        return p
    return CriticalLoad(p, "characteristic", 0, err, family, converged=True, tol=tol)


def _one_element(twist_angle: object, nu: object, n: object, tol: object, method: object,
                 full_output: object):
    """One point given as arrays of one element (e.g. the (1,) vectors that
    ``scipy.optimize.least_squares`` and ``fsolve`` pass): :func:`_one_point`'s answer, shaped
    and typed as the general path returns it (``tests/test_speed_paths.py`` compares the two),
    or None wherever the general path must answer. A one-point array call took 480 us by the
    general path against 110 us for a scalar call (measured 2026-12-03)."""
    if not (isinstance(twist_angle, np.ndarray) or isinstance(nu, np.ndarray)):
        return None
    point = []
    for value in (twist_angle, nu):
        if isinstance(value, np.ndarray):
            if value.size != 1 or value.dtype.kind not in "fiu":  # no bool, complex, object
                return None
            value = value.item()  # a Python float or int (np.longdouble stays, and fails)
        point.append(value)
    one = _one_point(*point, n, tol, method, full_output)
    if one is None:
        return None
    shape = (1,) * max(np.ndim(twist_angle), np.ndim(nu))  # the broadcast of two sizes of 1
    if not full_output:
        return as_output(np.array([one]), shape)
    fields = [as_output(np.array([value], dtype=dtype), shape) for value, dtype in (
        (one.p_star, np.float64), (one.method, METHOD_DTYPE), (one.n, int),
        (one.error_estimate, np.float64), (one.family, FAMILY_DTYPE), (True, bool))]
    return CriticalLoad(*fields[:5], converged=fields[5], tol=one.tol)


def critical_load(twist_angle: ArrayLike, nu: ArrayLike, *, n: int | None = None,
                  tol: float = 1e-12, method: str = "auto", full_output: bool = False):
    """Critical load p* = P_cr / (pi^2 A1 / L^2) of the hinged, spontaneously twisted rod.

    Parameters
    ----------
    twist_angle : Omega(L) = omega30 L in radians, |Omega(L)| <= 1e4 (p* is even in it:
        p*(-Omega) = p*(Omega), the mirror image of the mode).
    nu : I2/I1 in [1, 1e4] (the paper's convention A1 <= A2; for I2 < I1 swap the axes and
        pass 1/nu).
    n : Chebyshev degree (even, 8..512): forces collocation at that degree.
    tol : requested relative accuracy (1e-14..1e-2).
    method : "auto" (default; :func:`spectral_rod.choose_method` decides per point) or one of
        :data:`spectral_rod.ROD_METHODS`.
    full_output : return a :class:`spectral_rod.CriticalLoad` (method, resolution, error
        estimate, mode family, converged flag) instead of p* alone.

    Returns p* as a float for scalar input, otherwise an ndarray of the broadcast shape. A
    point whose error estimate exceeds ``tol`` gives a :class:`spectral_rod.ConvergenceWarning`
    and ``converged=False``; it is never returned silently. A collocation estimate is the
    calibrated model of the mode's Chebyshev tail and round-off
    (:func:`spectral_rod.straight_rod.resolution.error_estimate`) plus, for tol > 1e-12, what
    the looser eigenvalue iteration may add, 0.01 tol - 1e-14
    (:func:`spectral_rod.straight_rod.eigensolver.iteration_allowance`).

    Scalar and array calls: a collocation point is solved by the lean solver
    (:mod:`spectral_rod.straight_rod.few_points`) in a scalar call and whenever at most
    ``few_points_limit(n)`` (12 up to n = 30, fewer above) points of a call share its degree, by
    the batched engine otherwise; an array call pools degree groups at a higher degree where a
    measured cost model says that is cheaper
    (:func:`spectral_rod.straight_rod.collocation.solve_degrees`; per chunk of :data:`CHUNK`
    points). A scalar call and a one-point array call give identical results (the latter, e.g.
    scipy.optimize's (1,) vectors, takes the scalar path, at about its cost, and returns
    arrays). A point in a larger call differs from its scalar call by at most the larger of the
    two error estimates; where both use the same degree, by at most the round-off part
    eps (32 + 0.3 Omega^2) at the default tol (the two engines round the same Rayleigh quotient
    differently), and at a looser tol by at most that plus the eigenvalue iteration's tolerance
    ``iteration_rtol(tol)`` = max(0.01 tol, 1e-15) (the engines stop their iterations
    differently: from tol = 1e-8 on the round-off part alone is exceeded, 4.6 times at 1e-8 and
    7.5e5 times at 1e-4 on Figure 1's points). Measured 2026-12-02: on Figure 1's 1,201 points
    in one call (601 pooled) <= 7.1e-15, 0.54 of the round-off part; on 3,000 random points with
    |Omega(L)| < 50, nu <= 100 (1,585 pooled) <= 8.8e-14, 0.61 of the larger estimate, and 0.77
    of the round-off part at equal degree; at tol 1e-8 and 1e-4 on both sets, <= 0.74 of the
    larger estimate and, at equal degree, <= 0.015 of round-off plus iteration tolerance
    (``tests/test_safety.py`` computes and prints these).

    >>> round(critical_load(6.283185307179586, 1.5), 9)
    1.195993681
    """
    one = _one_point(twist_angle, nu, n, tol, method, full_output)
    if one is None:
        one = _one_element(twist_angle, nu, n, tol, method, full_output)
    if one is not None:
        return one
    twist, nu_arr = check_twist(twist_angle), check_nu(nu)
    tol = check_tol(tol)
    n, method = check_route(n, method)
    if not isinstance(full_output, (bool, np.bool_)):
        raise TypeError(f"full_output must be True or False, got {type(full_output).__name__}")
    shape = broadcast_points(twist_angle=twist, nu=nu_arr)
    tw = np.abs(np.broadcast_to(twist, shape).ravel())
    nv = np.broadcast_to(nu_arr, shape).ravel()
    res = solve_points(tw, nv, route(tw, nv, n, method), n, tol)
    apply_bounds(res, nv)
    converged = res.error_estimate <= tol
    warn_unconverged("critical_load", converged, res, tw, nv, tol)
    if not full_output:
        return as_output(res.p_star, shape)
    return CriticalLoad(*(as_output(v, shape) for v in (res.p_star, res.method, res.n,
                                                          res.error_estimate, res.family)),
                        converged=as_output(converged, shape), tol=tol)
