r"""p* of Eq. ``inst1`` by Chebyshev collocation for any call shape, with automatic resolution:
the one driver and its one degree loop (:func:`_degree_loop`).

For each point: an a priori degree from the mode's wavenumber (in an array call, small degree
groups may be pooled at a higher degree of the call where that is cheaper,
:func:`solve_degrees`), the lowest eigenvalue of both mode families at that degree
(:func:`.eigensolver.solve_points`, the engine), the family rule (:func:`pick_family`), the
error estimate from the computed mode's Chebyshev coefficients (:mod:`.resolution`), plus,
above the default tol, the eigenvalue iteration's allowance
(:func:`.tuning.iteration_allowance`); where the estimate's tail part misses its share of the
tolerance (:func:`.tuning.truncation_share`; :func:`.resolution.shortfall`) the degree is raised,
by 2 per factor 10 short and at most ~12 % (:func:`.resolution.raised_degree`), until it is met or
n = :data:`N_MAX` (no raise where the round-off floor alone exceeds the tolerance); a point is
converged where the whole estimate is <= tol. Inputs are validated by the caller
(:func:`spectral_rod.critical_load`).

The loop is written once against a namespace of its operations: :class:`_Arrays` for flat
arrays (:func:`collocation_critical_load`) and :class:`_OnePoint` for one point in Python
floats (:func:`collocation_point`, a scalar call: a batch of one without numpy's per-call
cost); the rules themselves are written against the arithmetic of :mod:`.arithmetic`.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple, cast

import numpy as np
from numpy.typing import NDArray

from spectral_rod._blas_threads import one_blas_thread
from spectral_rod._validation import check_resolution, scalar_nu, scalar_twist
from spectral_rod.rod.collocation import modal_kernel
from spectral_rod.rod.collocation.arithmetic import ARRAYS, FLOATS, Namespace
from spectral_rod.rod.collocation.discretisation import family_operator
from spectral_rod.rod.collocation.eigensolver import solve_family, solve_point, solve_points
from spectral_rod.rod.collocation.reference import ISOLATION_GAP, lowest_gap, physical_eig
from spectral_rod.rod.collocation.resolution import (
    N_MAX,
    N_MIN,
    error_estimate,
    initial_degree,
    raised_degree,
    roundoff_floor,
    shortfall,
)
from spectral_rod.rod.collocation.tuning import (
    CALL_COST,
    FEW_POINTS,
    FIXED_COST,
    LEAN_FACTOR,
    LEAN_MAX_DEGREE,
    POINT_COST,
    few_points_limit,
    iteration_allowance,
    iteration_rtol,
)
from spectral_rod.rod.families import CLOSE_REL, TIE_REL, check_family

__all__ = [
    "CALL_COST",
    "CLOSE_REL",
    "FEW_POINTS",
    "FIXED_COST",
    "LEAN_FACTOR",
    "N_MAX",
    "N_MIN",
    "POINT_COST",
    "SMALL_PART",
    "TIE_REL",
    "CollocationResult",
    "PointResult",
    "collocation_critical_load",
    "collocation_family_load",
    "collocation_mode_coefficients",
    "collocation_point",
    "few_points_limit",
    "pick_family",
    "solve_cost",
    "solve_degrees",
]


class CollocationResult(NamedTuple):
    """Flat arrays per point: p*, degree n, error estimate, family index (0 symmetric), and the
    engine that computed it ("kernel" where the C kernel computed both families' results,
    else "numpy")."""

    p_star: NDArray[np.float64]
    n: NDArray[np.int_]
    error_estimate: NDArray[np.float64]
    family: NDArray[np.int_]
    engine: NDArray[np.str_]


#: The engines' names (:data:`CollocationResult.engine`).
ENGINES = ("kernel", "numpy")


def solve_cost(points: int, degree: int) -> float:
    """Modelled seconds to solve `points` points of one degree (:data:`.tuning.FIXED_COST`)."""
    per_point = POINT_COST * (degree / 22.0) ** 2
    if points <= few_points_limit(degree):
        return CALL_COST + LEAN_FACTOR * points * per_point
    return FIXED_COST + points * per_point


def solve_degrees(n: NDArray[np.int_]) -> NDArray[np.int_]:
    """The degree each point of an array call is solved at (>= its own n, a degree the call has).

    The call's degree groups, in ascending order, are pooled with the next group and solved at
    its degree while :func:`solve_cost` says that is cheaper than two solves (a higher degree is
    at least as accurate; its error estimate is the one reported), up to
    :data:`.tuning.LEAN_MAX_DEGREE`.

    >>> solve_degrees(np.repeat([16, 18, 20], [50, 50, 300])).tolist() == [20] * 400
    True
    >>> solve_degrees(np.repeat([16, 28], [150, 1])).tolist() == [16] * 150 + [28]
    True
    """
    counts = np.bincount(n)  # degrees are ints in [N_MIN, N_MAX]: a count per degree
    degs = np.flatnonzero(counts)
    if degs.size <= 1:
        return n
    counts = counts[degs]
    target = degs.copy()
    start = 0  # the pool: degree groups start..i
    for i in range(degs.size):
        pooled = int(counts[start:i + 1].sum())
        if i + 1 < degs.size and degs[i + 1] <= LEAN_MAX_DEGREE:
            d, k = int(degs[i + 1]), int(counts[i + 1])
            if solve_cost(pooled + k, d) < solve_cost(pooled, int(degs[i])) + solve_cost(k, d):
                continue  # the pool joins the next group
        target[start:i + 1] = degs[i]
        start = i + 1
    lookup = np.empty(degs[-1] + 1, dtype=target.dtype)
    lookup[degs] = target
    return lookup[n]


class PointResult(NamedTuple):
    """One point's :class:`CollocationResult` in Python scalars, and whether its estimate is
    <= tol."""

    p_star: float
    n: int
    error_estimate: float
    family: int
    engine: str
    converged: bool


class _Arrays:
    """How the degree loop holds flat arrays of points: the rules' arithmetic ``xp``
    (:data:`.arithmetic.ARRAYS`), the set of points still to raise (``todo``: an index array),
    and the engine called once per degree of the call."""

    xp = ARRAYS
    nonzero = staticmethod(np.flatnonzero)

    @staticmethod
    def pooled(deg: NDArray[np.int_]) -> NDArray[np.int_]:
        return solve_degrees(deg)

    @staticmethod
    def full(tw: NDArray[np.float64], n: int) -> NDArray[np.int_]:
        return np.full(tw.size, n)

    @staticmethod
    def size(todo: NDArray[np.int_]) -> int:
        return todo.size

    @staticmethod
    def take(a: NDArray, todo: NDArray[np.int_]) -> NDArray:
        return a[..., todo]

    @staticmethod
    def put(a: NDArray, todo: NDArray[np.int_], value: Any) -> NDArray:
        a[..., todo] = value
        return a

    @staticmethod
    def subset(todo: NDArray[np.int_], keep: NDArray[np.bool_]) -> NDArray[np.int_]:
        return todo[keep]

    @staticmethod
    def engine_names(by_kernel: NDArray[np.bool_]) -> NDArray[np.str_]:
        return np.where(by_kernel, ENGINES[0], ENGINES[1])

    @staticmethod
    def solve(tw: NDArray[np.float64], nu: NDArray[np.float64], deg: NDArray[np.int_],
              rtol: float) -> tuple[NDArray[np.float64], NDArray[np.float64],
                                    NDArray[np.bool_]]:
        """Both families' lambda and tails (2, points) and whether the kernel computed them,
        one engine call per degree of the call."""
        if deg.size and deg.min() == deg.max():  # one degree: no regrouping
            return solve_points(int(deg[0]), tw, nu, rtol)
        lam, tails = np.empty((2, tw.size)), np.empty((2, tw.size))
        by_kernel = np.empty(tw.size, dtype=bool)
        for d in np.flatnonzero(np.bincount(deg)):  # the call's degrees, ascending
            sel = np.flatnonzero(deg == d)
            lam[:, sel], tails[:, sel], by_kernel[sel] = solve_points(int(d), tw[sel], nu[sel],
                                                                      rtol)
        return lam, tails, by_kernel


class _OnePoint:
    """How the degree loop holds one point in Python floats, without numpy's per-call cost: the
    rules' arithmetic ``xp`` (:data:`.arithmetic.FLOATS`), ``todo`` a bool, and the engine's
    one-point entry (:func:`.eigensolver.solve_point`)."""

    xp = FLOATS

    @staticmethod
    def pooled(deg: int) -> int:
        return deg

    @staticmethod
    def full(tw: float, n: int) -> int:
        return n

    @staticmethod
    def nonzero(todo: bool) -> bool:
        return todo

    size = nonzero

    @staticmethod
    def take(a: Any, todo: bool) -> Any:
        return a

    @staticmethod
    def put(a: Any, todo: bool, value: Any) -> Any:
        return value

    @staticmethod
    def subset(todo: bool, keep: bool) -> bool:
        return todo and keep

    @staticmethod
    def engine_names(by_kernel: bool) -> str:
        return ENGINES[0] if by_kernel else ENGINES[1]

    @staticmethod
    def solve(tw: float, nu: float, deg: int, rtol: float
              ) -> tuple[list[float], list[float], bool]:
        if deg <= LEAN_MAX_DEGREE:  # small matrices: below OpenBLAS's threading thresholds
            return solve_point(deg, tw, nu, rtol)
        with one_blas_thread():
            return solve_point(deg, tw, nu, rtol)


def _degree_loop(points: Any, tw: Any, nu: Any, n: int | None, tol: float
                 ) -> tuple[Any, Any, Any, Any, Any]:
    """The degree loop (module docstring) for points `tw` (|Omega|), `nu` held as `points` holds
    them (:class:`_Arrays` or :class:`_OnePoint`: one interface, two representations of the
    points, hence typed Any; the rules' arithmetic is its ``xp``): p*,
    degree, error estimate, family index and engine name per point."""
    xp = points.xp
    rtol = iteration_rtol(tol)
    if n is None:
        deg = points.pooled(initial_degree(tw, tol, xp))
        may_raise = roundoff_floor(tw, 0, xp) < tol  # no raise where round-off alone decides
    else:  # a forced degree is solved once
        deg, may_raise = points.full(tw, n), False
    lam, tails, by_kernel = points.solve(tw, nu, deg, rtol)
    p, fam, tail = pick_family(lam, tails, xp)
    short = shortfall(tail, tol, deg, xp)
    todo = points.nonzero(may_raise & (short > 1.0) & (deg < N_MAX))
    while points.size(todo):
        deg = points.put(deg, todo, raised_degree(points.take(deg, todo),
                                                  points.take(short, todo), xp))
        lam, tails, kernel = points.solve(points.take(tw, todo), points.take(nu, todo),
                                          points.take(deg, todo), rtol)
        sub = pick_family(lam, tails, xp)
        p, fam, tail = (points.put(old, todo, new) for old, new in zip((p, fam, tail), sub,
                                                                       strict=True))
        by_kernel = points.put(by_kernel, todo, kernel)
        short = points.put(short, todo, shortfall(sub[2], tol, points.take(deg, todo), xp))
        todo = points.subset(todo, (points.take(short, todo) > 1.0)
                             & (points.take(deg, todo) < N_MAX))
    err = error_estimate(tail, tw, deg, xp) + iteration_allowance(tol)
    return p, deg, err, fam, points.engine_names(by_kernel)


def collocation_point(twist: float, nu: float, tol: float, n: int | None = None
                      ) -> PointResult:
    """:func:`collocation_critical_load` for one point given as Python floats (validated;
    |Omega|; ``n`` None or a validated degree): the same degree loop in Python floats
    (:class:`_OnePoint`), without a batch's array bookkeeping; ``tests/test_speed_paths.py``
    checks that both answer alike. The estimate may exceed tol (a forced degree, or round-off
    above tol): ``converged`` is then False and the caller warns and flags."""
    modal_kernel.warn_if_missing()
    p, deg, err, fam, engine = _degree_loop(_OnePoint, twist, nu, n, tol)
    return PointResult(p, deg, err, fam, engine, err <= tol)


def pick_family(lam: Any, tails: Any, xp: Namespace = ARRAYS) -> tuple[Any, Any, Any]:
    """p*, family index and the tail that judges it, from both families' lambda and tails
    (``lam[0]``, ``lam[1]``: arrays of points for ``xp`` = :data:`.arithmetic.ARRAYS`, floats
    for :data:`.arithmetic.FLOATS`).

    A tie to round-off (e.g. nu = 1 at zero twist: the Euler mode in either plane) goes to the
    symmetric family, whose mode is the planar one in the (u0) plane. If the two families are
    within CLOSE_REL of each other either could be lowest, and both must be resolved.

    >>> pick_family([10.0, 10.0], [1e-9, 2e-9], FLOATS)[1:]  # a tie: symmetric, larger tail
    (0, 2e-09)
    >>> pick_family([10.0, 9.0], [1e-9, 3e-9], FLOATS)[1:]
    (1, 3e-09)
    """
    (l0, l1), (t0, t1) = lam, tails
    best = xp.where(l1 < l0 * (1.0 - TIE_REL), 1, 0)
    close = xp.abs(l0 - l1) <= CLOSE_REL * xp.minimum(l0, l1)
    return (xp.where(best, l1, l0) / math.pi**2, best,
            xp.where(close, xp.maximum(t0, t1), xp.where(best, t1, t0)))


def collocation_critical_load(twist: NDArray[np.float64], nu: NDArray[np.float64], *,
                              n: int | None = None, tol: float = 1e-12) -> CollocationResult:
    """p* at flat arrays of points (|Omega|, nu), at degree ``n`` or chosen automatically for
    relative accuracy ``tol`` (module docstring); validated input expected. Runs on one BLAS
    thread (:func:`spectral_rod._blas_threads.one_blas_thread`: its products are small).
    Without the C kernel the first call warns (:func:`.modal_kernel.warn_if_missing`)."""
    modal_kernel.warn_if_missing()
    with one_blas_thread():
        return CollocationResult(*_degree_loop(_Arrays, np.abs(twist), nu, n, tol))


def collocation_family_load(twist_angle: float, nu: float, family: str, n: int) -> float:
    """Lowest p of one mode family by collocation at degree n (one point; no resolution loop).

    Used where the two families are needed separately, e.g. to locate their crossings
    (:func:`spectral_rod.rod.crossings.collocation_crossing`). The iteration's convergence test
    assumes the family's lowest eigenvalue is isolated, which a family on its own need not be
    (the antisymmetric family near nu = 4 at small twist: 2e-8 off at n = 80 through the
    iteration); the full ``eig`` checks the gap first, and below
    :data:`~.reference.ISOLATION_GAP` its own eigenvalue is returned (elsewhere the
    iteration's, whose two-sided quotient has the smaller round-off: a crossing twist of
    Figure 1 moved by 3.5e-9 with eig's).
    """
    om, nv = abs(float(twist_angle)), float(nu)
    lam1, gap = lowest_gap(n, family, om, nv)
    if gap < ISOLATION_GAP:
        return lam1 / math.pi**2
    lam, _, _ = solve_family(n, family, np.array([om]), np.array([nv]))
    return float(lam[0]) / math.pi**2


#: A field of the mode counts as its small part if its largest coefficient is below this
#: fraction of the other field's (:func:`collocation_mode_coefficients`).
SMALL_PART = 1e-3


def collocation_mode_coefficients(twist_angle: float, nu: float, n: int, family: str
                                  ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Chebyshev coefficients (in x = 2 s - 1) of (omega1, omega2) of the family's lowest mode at
    degree n, from the full ``eig`` (an exact eigenvector of the discrete pencil), for
    Omega(L) >= 0 (the mode of -Omega is the mirror image, omega2 -> -omega2).

    At small twist one field is O(Omega) (omega2 in the symmetric family). ``eig`` gets it to
    an absolute error ~eps times the mode, so relative to itself it is off by ~1e-17/Omega
    (non_planarity of the centreline 1.6e-9 off at Omega(L) = 1e-6, 5e-6 at 1e-12, nu = 1.5;
    0.35 at 1e-12, nu = 1.0009). Where it is below SMALL_PART of the other field it is
    therefore solved again from its own block row of the pencil, (A_ss - lambda V_s) c_s =
    -A_sb c_b, which carries the relative error of c_b and lambda instead.

    Returns
    -------
    tuple of two ndarray of float
        The Chebyshev coefficients (c1, c2) of omega1 and omega2, degree 0 to n.

    Examples
    --------
    >>> c1, c2 = collocation_mode_coefficients(5.0, 1.5, 24, "symmetric")
    >>> bool(abs(c1[-2:]).max() < 1e-9 * abs(c1).max())   # the tail has decayed at n = 24
    True
    """
    om, nu = abs(scalar_twist(twist_angle)), scalar_nu(nu)
    op = family_operator(check_resolution(n, minimum=N_MIN, maximum=N_MAX), check_family(family))
    a, b = op.pencil(om, nu)
    theta, vec = physical_eig(cast(NDArray[np.float64], np.linalg.solve(a, b)[None]))
    c = vec[0]
    k1 = op.sizes[0]
    part = (slice(0, k1), slice(k1, None))
    size = [float(np.abs(c[f]).max()) for f in part]
    small, big = (part[0], part[1]) if size[0] < size[1] else (part[1], part[0])
    if min(size) < SMALL_PART * max(size) and np.isfinite(theta[0]):
        c = c.copy()
        c[small] = -np.linalg.solve(a[small, small] - b[small, small] / theta[0],
                                    a[small, big] @ c[big])
    return cast(tuple[NDArray[np.float64], NDArray[np.float64]], op.split(c))
