r"""p* of Eq. ``inst1`` by Chebyshev collocation for arrays of points, with automatic resolution.

For each point: an a priori degree from the mode's wavenumber (in an array call, small degree
groups may be pooled at a higher degree of the call where that is cheaper,
:func:`solve_degrees`), the lowest eigenvalue of both mode families at that degree
(:mod:`.eigensolver`, or :mod:`.few_points` for a few points), the error estimate from the
computed mode's Chebyshev coefficients (:mod:`.resolution`), plus, above the default tol, the
eigenvalue iteration's allowance (:func:`.eigensolver.iteration_allowance`); where the estimate's
tail part misses a tenth of the tolerance (:func:`.resolution.shortfall`) the degree is raised,
by 2 per factor 10 short and at most ~12 % (:func:`.resolution.raised_degree`), until it is met or
n = :data:`N_MAX` (no raise where the round-off floor alone exceeds the tolerance); a point is
converged where the whole estimate is <= tol. Inputs are validated by the caller
(:func:`spectral_rod.critical_load`).
"""

from __future__ import annotations

import math
from typing import NamedTuple, cast

import numpy as np
from numpy.typing import NDArray

from spectral_rod._blas_threads import one_blas_thread
from spectral_rod._validation import check_resolution, scalar_nu, scalar_twist
from spectral_rod.rod.collocation import modal_kernel
from spectral_rod.rod.collocation.arithmetic import FLOATS
from spectral_rod.rod.collocation.discretisation import family_operator
from spectral_rod.rod.collocation.eigensolver import (
    ISOLATION_GAP,
    lowest_gap,
    physical_eig,
    solve_family,
)
from spectral_rod.rod.collocation.few_points import solve_few, solve_one
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
    FEW_POINTS,
    FIXED_COST,
    LEAN_FACTOR,
    LEAN_MAX_DEGREE,
    POINT_COST,
    few_points_limit,
    iteration_allowance,
    iteration_rtol,
)
from spectral_rod.rod.families import CLOSE_REL, FAMILIES, TIE_REL, check_family

__all__ = [
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
    "collocation_critical_load",
    "collocation_family_load",
    "collocation_mode_coefficients",
    "collocation_point",
    "few_points_limit",
    "pick_family",
    "pick_family_scalar",
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
        return LEAN_FACTOR * points * per_point
    return FIXED_COST + points * per_point


def solve_degrees(n: NDArray[np.int_]) -> NDArray[np.int_]:
    """The degree each point of an array call is solved at (>= its own n, a degree the call has).

    The call's degree groups, in ascending order, are pooled with the next group and solved at
    its degree while :func:`solve_cost` says that is cheaper than two solves (a higher degree is
    at least as accurate; its error estimate is the one reported), up to
    :data:`~spectral_rod.rod.collocation.few_points.LEAN_MAX_DEGREE`.

    >>> solve_degrees(np.repeat([16, 18, 20], [50, 50, 300])).tolist() == [20] * 400
    True
    >>> solve_degrees(np.repeat([16, 28], [150, 1])).tolist() == [16] * 150 + [28]
    True
    """
    degs, counts = np.unique(n, return_counts=True)
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
    return target[np.searchsorted(degs, n)]


def _solve_points(twist: NDArray[np.float64], nu: NDArray[np.float64], n: NDArray[np.int_],
                  tol: float = 1e-12, by_kernel: NDArray[np.bool_] | None = None):
    """p*, family index and tail for flat arrays of points at the given degrees.

    Per degree: up to :func:`few_points_limit` points by the lean solver (both families, dense LU
    and matrix powers), more by the batched engine: the symmetric family first, the
    antisymmetric one then only resolved where it is not clearly above (1 + CLOSE_REL times) the
    symmetric eigenvalue. Points the lean solver does not accept go to the batched engine.
    ``by_kernel`` (bool, one per point), if given, is set True where the C kernel computed both
    families' results.

    The two families are iterated one after the other, so that the antisymmetric family can
    stop at its ceiling and a point leaves the iteration as soon as its family is done.
    """
    p = np.empty(twist.size)
    fam = np.empty(twist.size, dtype=int)
    tails = np.empty(twist.size)
    rtol = iteration_rtol(tol)
    kernel = modal_kernel.available()
    for deg in np.unique(n):
        sel = np.flatnonzero(n == deg)
        if sel.size <= few_points_limit(int(deg)):
            lam, tl, ok = solve_few(int(deg), twist[sel], nu[sel], rtol)
            p[sel], fam[sel], tails[sel] = pick_family(lam, tl)
            if by_kernel is not None:
                by_kernel[sel] = kernel
            sel = sel[~ok]
            if not sel.size:
                continue
        lam = np.empty((2, sel.size))
        tl = np.empty((2, sel.size))
        used = np.empty((2, sel.size), dtype=bool)
        lam[0], tl[0], _ = solve_family(int(deg), FAMILIES[0], twist[sel], nu[sel], rtol=rtol,
                                        kernel_out=used[0])
        lam[1], tl[1], _ = solve_family(int(deg), FAMILIES[1], twist[sel], nu[sel], rtol=rtol,
                                        ceiling=lam[0] * (1 + CLOSE_REL), kernel_out=used[1])
        p[sel], fam[sel], tails[sel] = pick_family(lam, tl)
        if by_kernel is not None:
            by_kernel[sel] = used.all(axis=0)
    return p, fam, tails


class PointResult(NamedTuple):
    """One point's :class:`CollocationResult` in Python scalars, and whether its estimate is
    <= tol."""

    p_star: float
    n: int
    error_estimate: float
    family: int
    engine: str
    converged: bool


def collocation_point(twist: float, nu: float, tol: float, n: int | None = None
                      ) -> PointResult | None:
    """The driver's lean path: :func:`collocation_critical_load` for one point given as Python
    floats (validated; |Omega|; ``n`` None or a validated degree) by the same degree loop and
    rules in Python floats, without a batch's array bookkeeping (a scalar call's cost is mostly
    numpy's per-call overhead); ``tests/test_speed_paths.py`` checks that both answer alike.

    A forced degree is solved once; where the round-off floor alone exceeds tol the a priori
    degree is kept, as in the array path; either may end with an estimate above tol, returned
    with ``converged`` False (the caller warns and flags). None wherever the array path must
    answer: a degree above :data:`.tuning.LEAN_MAX_DEGREE` or a point the lean solver does not
    accept.
    """
    rtol, allowance = iteration_rtol(tol), iteration_allowance(tol)
    if n is None:
        deg = initial_degree(twist, tol, FLOATS)
        # no raise where round-off alone decides (the array path's rule)
        raise_degree = roundoff_floor(twist, 0, FLOATS) < tol
    else:
        deg, raise_degree = n, False
    while True:  # the degree loop of _collocation_critical_load, for one point
        if deg > LEAN_MAX_DEGREE:
            return None
        # no BLAS thread limit here: the lean solver's matrices (m < 100) are below
        # OpenBLAS's threading thresholds, and the limit costs more than they do
        lam, tails, ok = solve_one(deg, twist, nu, rtol)
        if not ok:
            return None
        best, tail = pick_family_scalar(lam, tails)
        if not raise_degree:
            break
        short = shortfall(tail, tol, deg, FLOATS)
        if short <= 1.0 or deg >= N_MAX:
            break
        deg = raised_degree(deg, short, FLOATS)
    err = error_estimate(tail, twist, deg, FLOATS) + allowance
    return PointResult(lam[best] / math.pi**2, deg, err, best, modal_kernel.engine_name(),
                       err <= tol)


def pick_family(lam: NDArray[np.float64], tails: NDArray[np.float64]
                ) -> tuple[NDArray[np.float64], NDArray[np.int_], NDArray[np.float64]]:
    """p*, family index and the tail that judges it, from both families' lambda and tails
    (arrays (2, points)).

    A tie to round-off (e.g. nu = 1 at zero twist: the Euler mode in either plane) goes to the
    symmetric family, whose mode is the planar one in the (u0) plane. If the two families are
    within CLOSE_REL of each other either could be lowest, and both must be resolved.
    :func:`pick_family_scalar` is the same rule for one point in Python floats.
    """
    best = (lam[1] < lam[0] * (1.0 - TIE_REL)).astype(int)
    cols = np.arange(lam.shape[1])
    close = np.abs(lam[0] - lam[1]) <= CLOSE_REL * lam.min(axis=0)
    return (lam[best, cols] / np.pi**2, best,
            np.where(close, tails.max(axis=0), tails[best, cols]))


def pick_family_scalar(lam: list[float], tails: list[float]) -> tuple[int, float]:
    """:func:`pick_family` for one point (the scalar path's): the family index and the tail
    that judges it, from both families' lambda and tails (``tests/test_speed_paths.py`` checks
    that the two agree, ties and near-ties included).

    >>> pick_family_scalar([10.0, 10.0], [1e-9, 2e-9])  # a tie: symmetric, the larger tail
    (0, 2e-09)
    >>> pick_family_scalar([10.0, 9.0], [1e-9, 3e-9])
    (1, 3e-09)
    """
    (l0, l1), (t0, t1) = lam, tails
    best = 1 if l1 < l0 * (1.0 - TIE_REL) else 0
    return best, max(t0, t1) if abs(l0 - l1) <= CLOSE_REL * min(l0, l1) else (t0, t1)[best]


def collocation_critical_load(twist: NDArray[np.float64], nu: NDArray[np.float64], *,
                              n: int | None = None, tol: float = 1e-12) -> CollocationResult:
    """p* at flat arrays of points (|Omega|, nu), at degree ``n`` or chosen automatically for
    relative accuracy ``tol`` (module docstring); validated input expected. Runs on one BLAS
    thread (:func:`spectral_rod._blas_threads.one_blas_thread`: its products are small).
    Without the C kernel the first call warns (:func:`.modal_kernel.warn_if_missing`)."""
    modal_kernel.warn_if_missing()
    with one_blas_thread():
        return _collocation_critical_load(np.abs(twist), nu, n, tol)


def _collocation_critical_load(tw: NDArray[np.float64], nu: NDArray[np.float64],
                               n: int | None, tol: float) -> CollocationResult:
    allowance = iteration_allowance(tol)  # the eigenvalue iteration's share beyond the model
    by_kernel = np.zeros(tw.size, dtype=bool)
    if n is not None:
        deg = np.full(tw.size, int(n))
        p, fam, tails = _solve_points(tw, nu, deg, tol, by_kernel)
        return CollocationResult(p, deg, error_estimate(tails, tw, deg) + allowance, fam,
                                 _engine_names(by_kernel))
    deg = solve_degrees(initial_degree(tw, tol))
    p, fam, tails = _solve_points(tw, nu, deg, tol, by_kernel)
    # raise the degree where the tail's part of the estimate misses its share of tol, unless
    # round-off alone decides
    short = shortfall(tails, tol, deg)
    todo = np.flatnonzero((short > 1.0) & (deg < N_MAX) & (roundoff_floor(tw) < tol))
    while todo.size:
        deg[todo] = raised_degree(deg[todo], short[todo])
        used = np.zeros(todo.size, dtype=bool)
        p[todo], fam[todo], tails[todo] = _solve_points(tw[todo], nu[todo], deg[todo], tol,
                                                        used)
        by_kernel[todo] = used
        short[todo] = shortfall(tails[todo], tol, deg[todo])
        todo = todo[(short[todo] > 1.0) & (deg[todo] < N_MAX)]
    return CollocationResult(p, deg, error_estimate(tails, tw, deg) + allowance, fam,
                             _engine_names(by_kernel))


def _engine_names(by_kernel: NDArray[np.bool_]) -> NDArray[np.str_]:
    """ "kernel" where True, "numpy" where False."""
    return np.where(by_kernel, ENGINES[0], ENGINES[1])


def collocation_family_load(twist_angle: float, nu: float, family: str, n: int) -> float:
    """Lowest p of one mode family by collocation at degree n (one point; no resolution loop).

    Used where the two families are needed separately, e.g. to locate their crossings
    (:func:`spectral_rod.rod.crossings.collocation_crossing`). The iteration's convergence test
    assumes the family's lowest eigenvalue is isolated, which a family on its own need not be
    (the antisymmetric family near nu = 4 at small twist: 2e-8 off at n = 80 through the
    iteration); the full ``eig`` checks the gap first, and below
    :data:`~.eigensolver.ISOLATION_GAP` its own eigenvalue is returned (elsewhere the
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
