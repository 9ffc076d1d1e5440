"""The public entry point for the straight rod's critical load, Eq. ``inst1`` with hinged ends.

:func:`critical_load` validates its input once, asks the router (:mod:`spectral_rod.rod.router`)
which
method answers each point, runs each method on its points, and returns p* with every result
flagged: a tolerance that is not met gives a :class:`spectral_rod.ConvergenceWarning` and
``converged=False``, whatever the method and whether or not the degree was forced.

Bounds: the true p* lies in [1, (1 + nu)/2] (:mod:`spectral_rod.rod.families`), so every computed
value is projected onto that interval and its error estimate capped by the interval's width
(:func:`bounds`). The projection can only bring a value closer to the truth: round-off
(1 - 2e-16 at nu = 1) and an unresolved forced degree (p* = 38 at Omega = 30, n = 8, which is also
flagged and warned about) both end inside the bounds.
"""

from __future__ import annotations

import importlib
import math
import warnings
from typing import Any, NamedTuple, cast

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
from spectral_rod.rod.collocation import collocation_critical_load
from spectral_rod.rod.collocation.arithmetic import ARRAYS, FLOATS, Namespace
from spectral_rod.rod.collocation.driver import collocation_point
from spectral_rod.rod.collocation.resolution import N_MAX, N_MIN
from spectral_rod.rod.collocation.tuning import CHUNK, SMALL_CALL
from spectral_rod.rod.families import FAMILIES, FAMILY_DTYPE
from spectral_rod.rod.results import CriticalLoad, as_output
from spectral_rod.rod.router import METHOD_DTYPE, ROD_METHODS, check_route, route, route_point

__all__ = ["critical_load"]

_EPS = float(np.finfo(float).eps)


class PointResults(NamedTuple):
    """Flat arrays per point: p*, method, resolution, error estimate, family name, engine
    (collocation's "kernel" or "numpy", else the method's name)."""

    p_star: NDArray[np.float64]
    method: NDArray[np.str_]
    n: NDArray[np.int_]
    error_estimate: NDArray[np.float64]
    family: NDArray[np.str_]
    engine: NDArray[np.str_]


#: dtype of the engine names: "kernel", "numpy" or a method of :data:`ROD_METHODS`.
ENGINE_DTYPE = f"<U{max(map(len, ('kernel', 'numpy', *ROD_METHODS)))}"


def _collocation(tw, nv, n, tol):
    r = collocation_critical_load(tw, nv, n=n, tol=tol)
    return r.p_star, r.n, r.error_estimate, np.asarray(FAMILIES)[r.family], r.engine


def _characteristic(tw, nv, n, tol):
    from spectral_rod.rod.characteristic import characteristic_double_batch, double_error_estimate

    p, fam = characteristic_double_batch(tw, nv)
    return p, np.zeros(tw.size, dtype=int), double_error_estimate(tw), np.asarray(FAMILIES)[fam]


def _increment(tw, nv, n, tol):
    from spectral_rod.rod.increment import galerkin_increments, increment_error_estimate

    d, fam, modes = galerkin_increments(tw, nv)
    return 1.0 + d, modes, increment_error_estimate(d), fam


def _ritz(tw, nv, n, tol):
    from spectral_rod.rod.ritz import ritz_point

    p, deg, err, fam = zip(*(ritz_point(a, b, None, tol, None)
                             for a, b in zip(tw, nv, strict=True)), strict=True)
    return np.array(p), np.array(deg), np.array(err), np.array(fam)


_SOLVERS = {"collocation": _collocation, "characteristic": _characteristic,
            "increment": _increment, "ritz": _ritz}
#: the modules each method imports when first used (before the BLAS threads are limited, so
#: that the library a module brings, e.g. scipy.linalg's BLAS, is limited too)
_MODULES = {"collocation": "spectral_rod.rod.collocation",
            "characteristic": "spectral_rod.rod.characteristic",
            "increment": "spectral_rod.rod.increment", "ritz": "spectral_rod.rod.ritz"}
assert set(_SOLVERS) == set(ROD_METHODS) == set(_MODULES)


def solve_points(tw: NDArray[np.float64], nv: NDArray[np.float64], methods: NDArray[np.str_],
                 n: int | None, tol: float) -> PointResults:
    """Run each method on its points (flat, validated arrays; methods from the router), in
    chunks of at most :data:`CHUNK` points, with small dense linear algebra on one BLAS thread
    (:mod:`spectral_rod._blas_threads`)."""
    if tw.size > CHUNK:
        parts = [solve_points(tw[i:i + CHUNK], nv[i:i + CHUNK], methods[i:i + CHUNK], n, tol)
                 for i in range(0, tw.size, CHUNK)]
        return PointResults(*(np.concatenate(v) for v in zip(*parts, strict=True)))
    names = _methods_present(methods)
    for name in names:
        importlib.import_module(_MODULES[name])
    with one_blas_thread():
        if len(names) == 1:  # one method answers every point: no index arrays
            return _results(names[0], tw, nv, methods, n, tol)
        p, deg, err = np.empty(tw.size), np.zeros(tw.size, dtype=int), np.empty(tw.size)
        fam = np.empty(tw.size, dtype=FAMILY_DTYPE)
        engine = methods.astype(ENGINE_DTYPE)  # a route other than collocation is its own engine
        for name in names:
            idx = np.flatnonzero(methods == name)
            out = _SOLVERS[name](tw[idx], nv[idx], n, tol)
            p[idx], deg[idx], err[idx], fam[idx] = out[:4]
            if len(out) > 4:
                engine[idx] = out[4]
    return PointResults(p, methods, deg, err, fam, engine)


def _methods_present(methods: NDArray[np.str_]) -> list[str]:
    """The methods of :data:`ROD_METHODS` that answer some point (np.unique on strings sorts:
    0.17 ms for Figure 1's 1,201 points; one comparison where the first answers all)."""
    if methods.size and (methods == methods[0]).all():
        return [str(methods[0])]
    return [name for name in ROD_METHODS if np.any(methods == name)]


def _results(name: str, tw: NDArray[np.float64], nv: NDArray[np.float64],
             methods: NDArray[np.str_], n: int | None, tol: float) -> PointResults:
    """:func:`solve_points` where method `name` answers every point."""
    out = _SOLVERS[name](tw, nv, n, tol)
    p, deg, err, fam = out[:4]
    engine = out[4] if len(out) > 4 else methods
    # p* and the estimates as new arrays: apply_bounds writes into them
    return PointResults(np.array(p, dtype=float), methods, np.asarray(deg, dtype=int),
                        np.array(err, dtype=float), np.asarray(fam, dtype=FAMILY_DTYPE),
                        np.asarray(engine, dtype=ENGINE_DTYPE))


def bounds(p: Any, err: Any, nv: Any, xp: Namespace = ARRAYS) -> tuple[Any, Any]:
    """p* projected onto its rigorous bounds [1, (1 + nu)/2] and the error estimate capped by
    the bounds' width: the truth lies in the bounds, so neither can make p* worse. The width is
    widened by eps, the rounding of (1 + nu)/2 (at nu = 1 + 2^-52 it rounds to 1, a width of
    0, while p* - 1 = 1.1e-16). Arrays, or one point in Python floats with ``xp`` =
    :data:`spectral_rod.rod.collocation.arithmetic.FLOATS` (the scalar paths').

    >>> bounds(1.3, 0.5, 1.5, FLOATS)
    (1.25, 0.2500000000000002)
    """
    hi = (1.0 + nv) / 2.0
    return xp.minimum(xp.maximum(p, 1.0), hi), xp.minimum(err, (hi - 1.0) + _EPS)


def apply_bounds(res: PointResults, nv: NDArray[np.float64]) -> None:
    """:func:`bounds` applied to a result's p* and error estimates, in place."""
    res.p_star[:], res.error_estimate[:] = bounds(res.p_star, res.error_estimate, nv)


def warn_unconverged(where: str, converged: NDArray[np.bool_], res: PointResults,
                     tw: NDArray[np.float64], nv: NDArray[np.float64], tol: float) -> None:
    """One ConvergenceWarning naming the worst point, if any point missed `tol` (pointing at
    the caller of the function that calls this one)."""
    bad = np.flatnonzero(~converged)
    if not bad.size:
        return
    worst = bad[np.argmax(res.error_estimate[bad])]
    warnings.warn(_unconverged(where, bad.size, float(res.error_estimate[worst]),
                               float(tw[worst]), float(nv[worst]), str(res.method[worst]),
                               int(res.n[worst]), tol),
                  ConvergenceWarning, stacklevel=3)


def _unconverged(where: str, count: int, err: float, om: float, nv: float, method: str, n: int,
                 tol: float) -> str:
    """The text of the warning for `count` points that missed `tol`, the worst (largest error
    estimate `err`) at (om, nv) by `method` at resolution `n`."""
    return (f"{where}: tol={tol:g} not met at {count} point(s); worst error estimate {err:.2e} "
            f"at twist_angle={om:g}, nu={nv:g} (method {method}, n={n}); flagged "
            f"converged=False")


class _Point(NamedTuple):
    """One point's answer on the scalar path (the fields of :class:`CriticalLoad`, bounds
    applied, ``converged`` judged after them)."""

    p_star: float
    method: str
    n: int
    error_estimate: float
    family: str
    converged: bool
    engine: str


def _one_point(twist_angle: object, nu: object, n: object, tol: object, method: object,
               full_output: object):
    """The scalar fast path: p* (or its CriticalLoad) for one point given as Python or numpy floats
    on the collocation or the large-twist route, or None wherever the general path must answer
    (any other input, the increment route). A forced degree, or an estimate that misses tol (tol
    below the round-off floor), stays here: warned and flagged as the general path does (one
    call must not cost the array path's several times for it). The computation is the general
    path's for one point, without its array bookkeeping (:func:`_point`); ``python -m pytest -m
    bench`` measures the scalar loops."""
    if not isinstance(full_output, (bool, np.bool_)):
        return None
    point = _point(twist_angle, nu, n, tol, method)
    if point is None:
        return None
    _warn_points([point], [twist_angle], [nu], tol)
    if not full_output:
        return point.p_star
    return CriticalLoad(*point[:5], converged=point.converged, tol=cast(float, tol),
                        engine=point.engine)


def _point(twist_angle: object, nu: object, n: object, tol: object, method: object
           ) -> _Point | None:
    """One point given as Python floats or ints on the collocation or the large-twist route, or
    None wherever the general path must answer (any other input, the increment route, the
    large-twist route where its estimate misses tol): collocation by the driver's degree loop
    for one point (:func:`spectral_rod.rod.collocation.driver.collocation_point`), the
    large-twist route by :func:`_one_characteristic`."""
    if not (isinstance(twist_angle, (float, int)) and isinstance(nu, (float, int))
            and isinstance(tol, float) and _lean_degree(n)
            and method in ("auto", "collocation", "characteristic")) \
            or isinstance(twist_angle, bool) or isinstance(nu, bool):
        return None
    try:
        om, nv = abs(float(twist_angle)), float(nu)
    except OverflowError:  # an int beyond float range: the general path names it
        return None
    if not (om <= TWIST_MAX and 1.0 <= nv <= NU_MAX and TOL_RANGE[0] <= tol <= TOL_RANGE[1]):
        return None  # includes NaN: the general path names the bad argument
    chosen = route_point(om, nv, n if isinstance(n, int) else None, cast(str, method))
    if chosen == "characteristic":
        return _one_characteristic(om, nv, tol)
    if chosen != "collocation":
        return None
    point = collocation_point(om, nv, tol, n if isinstance(n, int) else None)
    p, err = bounds(point.p_star, point.error_estimate, nv, FLOATS)
    # converged after the bounds, as the general path judges it
    return _Point(p, "collocation", point.n, err, FAMILIES[point.family], err <= tol,
                  point.engine)


def _lean_degree(n: object) -> bool:
    """Whether the scalar path takes degree `n`: None, or a valid degree (an even int in
    [N_MIN, N_MAX]; the general path names a bad one)."""
    return n is None or (type(n) is int and N_MIN <= n <= N_MAX and n % 2 == 0)


def _one_characteristic(om: float, nv: float, tol: float) -> _Point | None:
    """:func:`_point` on the large-twist route: the characteristic equation in double
    precision for one point (its refinement in Python floats; the benchmark row "a loop of
    scalar calls, Omega(L) in [50, 1000]" measures it), bounds and estimate as
    :func:`solve_points` and :func:`bounds` give them; None where the estimate misses tol
    (the general path warns and flags)."""
    from spectral_rod.rod.characteristic import characteristic_double, double_error_estimate

    _, err = bounds(1.0, float(double_error_estimate(om)), nv, FLOATS)  # it needs no p*
    if err > tol:
        return None
    p, family = characteristic_double(om, nv)
    p, _ = bounds(p, err, nv, FLOATS)
    return _Point(p, "characteristic", 0, err, family, True, "characteristic")


def _few_points(twist_angle: object, nu: object, n: object, tol: object, method: object,
                full_output: object):
    """Arrays of at most :data:`.tuning.SMALL_CALL` points (e.g. the (1,) vectors that
    ``scipy.optimize.least_squares`` and ``fsolve`` pass, or a few points of a curve): each
    point answered by :func:`_point` as its scalar call is, the results shaped and typed as the
    general path returns them, one warning for the points that missed tol; or None wherever the
    general path must answer (more points, or a point :func:`_point` does not take). The
    general path's numpy calls cost more than a loop of scalar calls on a few points (``python
    tests/bench/tuning_crossovers.py``, part 6; ``tests/test_speed_paths.py`` compares the two
    paths' outputs)."""
    shape = _small_shape(twist_angle, nu)
    if shape is None or not isinstance(full_output, (bool, np.bool_)):
        return None
    size = math.prod(shape)
    tws, nus = (_point_values(v, shape, size) for v in (twist_angle, nu))
    points = []
    for om, nv in zip(tws, nus, strict=True):
        point = _point(om, nv, n, tol, method)
        if point is None:
            return None
        points.append(point)
    _warn_points(points, tws, nus, tol)
    if not full_output:
        return as_output(np.array([point.p_star for point in points]), shape)
    dtypes: tuple[Any, ...] = (np.float64, METHOD_DTYPE, int, np.float64, FAMILY_DTYPE, bool,
                               ENGINE_DTYPE)
    fields = [as_output(np.array(values, dtype=dtype), shape)
              for values, dtype in zip(zip(*points, strict=True), dtypes, strict=True)]
    return CriticalLoad(fields[0], fields[1], fields[2], fields[3], fields[4],
                        converged=fields[5], tol=cast(float, tol), engine=fields[6])


def _warn_points(points: list[_Point], tws: list[Any], nus: list[Any], tol: object) -> None:
    """:func:`warn_unconverged` for the scalar path's points (twist and nu as given): one
    warning naming the worst point, if any missed `tol`, pointing at the caller of
    :func:`critical_load` (through :func:`_one_point` or :func:`_few_points`)."""
    missed = [i for i, point in enumerate(points) if not point.converged]
    if not missed:
        return
    i = max(missed, key=lambda j: points[j].error_estimate)
    worst = points[i]
    warnings.warn(_unconverged("critical_load", len(missed), worst.error_estimate,
                               abs(float(tws[i])), float(nus[i]), worst.method, worst.n,
                               cast(float, tol)),
                  ConvergenceWarning, stacklevel=4)


def _point_values(value: object, shape: tuple[int, ...], size: int) -> list[Any]:
    """`value` (a plain numpy array or a Python number) at the `size` points of the broadcast
    `shape`, as Python numbers (an np.longdouble stays one, and :func:`_point` refuses it)."""
    if type(value) is not np.ndarray:
        return [value] * size
    return (value if value.shape == shape else np.broadcast_to(value, shape)).ravel().tolist()


def _small_shape(twist_angle: object, nu: object) -> tuple[int, ...] | None:
    """The broadcast shape of a call :func:`_few_points` takes: plain numpy arrays of real
    numbers (no bool or complex, no subclass such as a masked array) and Python floats or ints,
    at least one array, at most :data:`.tuning.SMALL_CALL` points in all; else None."""
    shapes = []
    for value in (twist_angle, nu):
        if type(value) is np.ndarray:
            if value.dtype.kind not in "fiu":
                return None
            shapes.append(value.shape)
        elif not isinstance(value, (float, int)):
            return None
    if not shapes:
        return None
    try:
        shape = (shapes[0] if len(shapes) == 1 or shapes[0] == shapes[1]
                 else np.broadcast_shapes(*shapes))
    except ValueError:  # the general path names the arguments
        return None
    return shape if 0 < math.prod(shape) <= SMALL_CALL else None


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

    Returns
    -------
    float, ndarray or CriticalLoad
        p* as a float for scalar input, otherwise an ndarray of the broadcast shape; with
        ``full_output=True`` a :class:`spectral_rod.CriticalLoad` of such values whose
        ``engine`` says what computed each point ("kernel" or "numpy" for collocation, the
        method's name otherwise).

    Raises
    ------
    ValueError, TypeError
        An argument outside its range or of the wrong type (the message names it).

    Warns
    -----
    ConvergenceWarning
        A point whose error estimate exceeds ``tol``; it is flagged ``converged=False`` and
        never returned silently.
    PerformanceWarning
        Once per process, at the first solve, where the C kernel is not available.

    Notes
    -----
    A collocation estimate is the calibrated model of the mode's Chebyshev tail and round-off
    (:func:`spectral_rod.rod.collocation.resolution.error_estimate`) plus, for tol > 1e-12, what
    the looser eigenvalue iteration may add, 0.01 tol - 1e-14
    (:func:`spectral_rod.rod.collocation.tuning.iteration_allowance`; every setting ``tol`` sets is
    listed by :func:`spectral_rod.rod.collocation.tuning.solver_settings`).

    One driver (:func:`spectral_rod.rod.collocation.driver.collocation_critical_load`) serves
    every call shape; a scalar call, and each point of an array call of at most
    :data:`~spectral_rod.rod.collocation.tuning.SMALL_CALL` = 8 points (e.g. scipy.optimize's
    (1,) vectors), take its one-point path and give identical results. A point in a larger call
    differs from its scalar call by at most the larger of the two error estimates; where both
    use the same degree, by at most the round-off part eps (32 + 0.3 Omega^2) at the default tol
    (two computations round the same Rayleigh quotient differently), and at a looser tol by at
    most that plus the iteration's tolerance ``iteration_rtol(tol)`` = max(0.01 tol, 1e-15).
    ``tests/test_safety.py`` computes and prints these differences on Figure 1's points and on
    3,000 random points.

    Examples
    --------
    >>> round(critical_load(6.283185307179586, 1.5), 9)
    1.195993681
    """
    if isinstance(twist_angle, np.ndarray) or isinstance(nu, np.ndarray):
        one = _few_points(twist_angle, nu, n, tol, method, full_output)
    else:
        one = _one_point(twist_angle, nu, n, tol, method, full_output)
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
    return CriticalLoad(as_output(res.p_star, shape), as_output(res.method, shape),
                        as_output(res.n, shape), as_output(res.error_estimate, shape),
                        as_output(res.family, shape), converged=as_output(converged, shape),
                        tol=tol,
                        engine=as_output(res.engine, shape))
