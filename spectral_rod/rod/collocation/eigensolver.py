r"""The engine of Eq. ``inst1``'s collocation eigenvalue: the lowest physical eigenpair of both
mode families at points of one degree (:func:`solve_points`; :func:`solve_point` for one point
in Python floats), by shift-and-invert iteration on right and left vectors.

Only the lowest eigenvalue is needed and it is >= pi^2 (:mod:`spectral_rod.rod.families`). In
the modal form of a family (:mod:`.modal_form`) K - SHIFT is inverted once per point
(:mod:`.shifted`); the iteration (:func:`lowest_eigenpair`, contraction 0.01-0.2 per step on
Figure 1's range) gives the eigenvectors, and the eigenvalue is the pencil's two-sided Rayleigh
quotient (:mod:`.quotient`). Where the iteration is rejected (a spurious eigenvalue nearer the
shift than the physical one) the reference, the full ``eig`` with the physical-eigenvalue rule
(:mod:`.reference`), decides.

One algorithm, two implementations: the C kernel of :mod:`.modal_kernel` (the engine,
``modal_points``: both families, 32 points side by side, a last few one lane each, with one
iteration code, ``iterate_lanes``; ``modal_lowest``, one family with its eigenvectors, for
:func:`solve_family`) and this module's numpy code (its executable reference, and the engine
where the kernel is not built), in the same two forms: batched (:func:`_iterate`) and one point
(:func:`_numpy_point`, (K - SHIFT)^{-1} and its transpose as one block-diagonal matrix so that a
step is one product, the test's quotient and bound from one Gram product). Each rule has one
numpy function mirroring the kernel's: the convergence test :func:`converged` (C
``lanes_test``/``iterate_lanes``), the quotient :func:`.quotient.pencil_rayleigh_quotient` (C
``pencil_quotient``) and the tail of :mod:`.resolution` (C ``family_lanes``);
``tests/test_modal_kernel.py``, ``tests/test_engine_contract.py`` and
``tests/test_speed_paths.py`` compare the two, and both with the reference. The choice is
accepted only if the error estimate from the mode's Chebyshev coefficients (:mod:`.resolution`;
a spurious mode is unresolved by construction) meets the tolerance.
"""

from __future__ import annotations

import ctypes
import math
from functools import lru_cache
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.collocation import modal_kernel
from spectral_rod.rod.collocation.arithmetic import ARRAYS, FLOATS, Namespace
from spectral_rod.rod.collocation.discretisation import INST1, term_coefficients
from spectral_rod.rod.collocation.modal_form import (
    MODAL_TERMS,
    ModalFamily,
    _start_vector,
    modal_family,
    modal_parts,
)
from spectral_rod.rod.collocation.quotient import (
    _MASS_TERMS,
    _rayleigh_sums,
    _term_matrices,
    pencil_rayleigh_quotient,
)
from spectral_rod.rod.collocation.reference import solve_family_eig
from spectral_rod.rod.collocation.resolution import mode_tails, tail_from_parts, tail_parts
from spectral_rod.rod.collocation.shifted import (
    _DenseShifted,
    _point_family,
    _point_inverse,
    _shifted,
    _ShiftedModal,
)
from spectral_rod.rod.collocation.stacked_inverse import BACKWARD_TOL
from spectral_rod.rod.collocation.tuning import (
    CALIBRATED_TOL,
    DENSE_ENTRIES,
    KERNEL_MAX_SCHUR,
    LEAN_MAX_DEGREE,
    LONG_TWIST,
    POWER_RTOL,
    POWER_STEPS,
    few_points_limit,
    first_check,
    iteration_allowance,
    iteration_rtol,
    loose_quotient,
)
from spectral_rod.rod.families import CLOSE_REL, FAMILIES, SHIFT

__all__ = ["CALIBRATED_TOL", "KERNEL_MAX_SCHUR", "first_check", "iteration_allowance",
           "iteration_rtol", "kernel_families", "loose_quotient", "lowest_eigenpair",
           "solve_family", "uses_kernel"]


def uses_kernel(k_s: int) -> bool:
    """Whether :func:`lowest_eigenpair` iterates by the C kernel at Schur block size k_s."""
    return k_s <= KERNEL_MAX_SCHUR and modal_kernel.available()


def _rowdot(a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """Row-wise dot products (numpy >= 2.0 has ``np.vecdot``; this works on older numpy too)."""
    return np.einsum("ij,ij->i", a, b)


def lowest_eigenpair(mf: ModalFamily, twist: NDArray[np.float64], nu: NDArray[np.float64],
                     rtol: float = POWER_RTOL, ceiling: NDArray[np.float64] | None = None,
                     max_steps: int = POWER_STEPS, kernel_out: NDArray[np.bool_] | None = None
                     ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64],
                                NDArray[np.bool_], NDArray[np.bool_]]:
    """Eigenvalue lambda of K nearest above SHIFT = 0.95 pi^2, its right and left eigenvectors
    z, w, and whether it converged or was shown to lie above ``ceiling``, for a batch of points.

    Shift-and-invert power iteration on right and left vectors together: the contraction per
    step is (lambda_1 - SHIFT) / (lambda_2 - SHIFT) (0.01-0.2 on Figure 1's range). The
    eigenvalue is the two-sided Rayleigh quotient w^T K z / w^T z; its error is estimated to
    first order by |r| |l| / |w^T z| with the residuals r = K z - lambda z, l = K^T w - lambda w
    (unit z, w). K z needs no product with K: z = (K - SHIFT)^{-1} z_prev gives
    K z = SHIFT z + z_prev. A point is done when that estimate is <= rtol lambda and
    lambda >= SHIFT (converged), or when lambda - 100 estimate is above ``ceiling`` (only
    needed to be shown higher than another family's eigenvalue: "above", lambda approximate).
    Points are dropped from the iteration as they finish.

    Where the Schur block is small enough (:func:`uses_kernel`) the iteration is the C kernel's
    (:mod:`.modal_kernel`: the same algorithm, 32 points side by side, 3-5 times faster at
    Figure 1's degrees), with this function's numpy iteration (:func:`_iterate`) for any point
    whose unpivoted factors the kernel rejects; elsewhere, and where the kernel is not
    installed, the numpy iteration alone.

    The estimate assumes the eigenvalue is isolated: for two of the family's eigenvalues a gap
    delta apart it is ~delta^2 |mix|^2 while the error is ~delta |mix|^2, so a mixed vector
    passes once delta^2 < rtol lambda. Seen only in the antisymmetric family near nu = 4 at
    small twist (Euler loads 4 and nu: 15 of 800 random family loads at n = 80 erred by up to
    2.0e-8 against the 40-digit family root, all with nu within 2e-7 of 4 and
    |Omega(L)| < 3e-7; the other 785 agreed to <= 1e-11). There the
    symmetric family (p* ~ 1) is far lower, so :func:`spectral_rod.critical_load` stops the
    antisymmetric iteration at "above" and is unaffected; a family on its own
    (:func:`.collocation.collocation_family_load`) is first checked by :func:`lowest_gap`
    against :data:`ISOLATION_GAP`.

    In the numpy iteration the right and left solves are separate calls: a stored transpose
    S^{-T} would double the memory each step reads.
    """
    pt = modal_parts(mf, twist, nu)
    start = _start_vector(mf.lam1.size + mf.lam2.size)
    first = first_check(rtol, ceiling is not None)
    by_kernel = uses_kernel(pt.d_s.shape[1])
    if kernel_out is not None:
        kernel_out[:] = by_kernel
    if not by_kernel:
        return _iterate(_shifted(mf, pt), start, rtol, ceiling, first, max_steps)
    res = modal_kernel.modal_lowest(pt.r_e, pt.a, pt.b, pt.d_s, pt.g_es, pt.g_se,
                                    start[pt.elim], start[pt.kept], ceiling, shift=SHIFT,
                                    rtol=rtol, first=first, max_steps=max_steps,
                                    backward_tol=BACKWARD_TOL)
    size = start.size
    vec, left = np.empty((twist.size, size)), np.empty((twist.size, size))
    vec[:, pt.elim], vec[:, pt.kept], left[:, pt.elim], left[:, pt.kept] = \
        res.x_e, res.x_s, res.y_e, res.y_s
    lam = res.lam
    ok, above = res.status == modal_kernel.CONVERGED, res.status == modal_kernel.ABOVE
    rejected = np.flatnonzero(res.status == modal_kernel.REJECTED)
    if rejected.size:  # the numpy iteration, with LAPACK's pivoted inverse where needed
        if kernel_out is not None:
            kernel_out[rejected] = False
        sub = _iterate(_shifted(mf, pt.take(rejected)), start, rtol,
                       None if ceiling is None else ceiling[rejected], first, max_steps)
        lam[rejected], vec[rejected], left[rejected], ok[rejected], above[rejected] = sub
    return lam, vec, left, ok, above


def _iterate(op: _ShiftedModal | _DenseShifted, start: NDArray[np.float64], rtol: float,
             ceiling: NDArray[np.float64] | None, first: int, max_steps: int
             ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64],
                        NDArray[np.bool_], NDArray[np.bool_]]:
    """The iteration of :func:`lowest_eigenpair` in numpy (the C kernel's ``iterate_lanes``),
    from a unit start vector, with the first test at step `first` (then every 2 steps). The
    right and left vectors travel stacked, v (2, points, m), so that the test
    (:func:`_lanes_test`) is one set of numpy calls for both."""
    points = op.pair.shape[1] if isinstance(op, _DenseShifted) else op.r_e.shape[0]
    v = np.broadcast_to(start, (2, points, start.size))
    lam = np.full(points, np.nan)
    vecs = np.zeros((2, points, start.size))
    ok = np.zeros(points, dtype=bool)
    above = np.zeros(points, dtype=bool)
    active = np.arange(points)
    for step in range(1, max_steps + 1):
        # each step scales by <= ~1/(0.05 pi^2) and >= ~1/lambda_max: normalising at the
        # checks (every 2 steps) keeps the vectors far from overflow and underflow
        prev = v
        v = op.solve_pair(v)
        if step < first or step % 2:
            continue
        v, rq, bound = _lanes_test(v, prev)
        conv = converged(rq, bound, rtol)
        high = conv if ceiling is None else ~conv & (rq - 100.0 * bound > ceiling[active])
        done = np.ones_like(conv) if step + 2 > max_steps else conv | high
        every = bool(done.all())
        fin, sub = (active, slice(None)) if every else (active[done], done)
        lam[fin], ok[fin], above[fin] = rq[sub], conv[sub], high[sub] & ~conv[sub]
        vecs[:, fin] = v[:, sub]
        if every:
            break
        keep = np.flatnonzero(~done)
        active = active[keep]
        op = op.take(keep)
        v = v[:, keep]
    return lam, vecs[0], vecs[1], ok, above


def _lanes_test(v: NDArray[np.float64], prev: NDArray[np.float64]
                ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """The kernel's ``lanes_test`` in numpy: the unit right and left vectors v (2, points, m)
    from the step's v and its input `prev`, the two-sided quotient rq = y^T K x / y^T x and its
    first-order error bound |r| |l| / |y^T x| (K x = SHIFT x + prev, as the step solved
    (K - SHIFT) x = prev)."""
    scale = 1.0 / np.sqrt(np.einsum("kpi,kpi->kp", v, v))[..., None]
    v = v * scale
    kv = SHIFT * v + prev * scale  # (K x, K^T y)
    yx = np.einsum("pi,pi->p", v[1], v[0])
    rq = np.einsum("pi,pi->p", v[1], kv[0]) / yx
    res = kv - rq[:, None] * v
    norms = np.einsum("kpi,kpi->kp", res, res)
    return v, rq, np.sqrt(norms[0] * norms[1]) / np.abs(yx)


def converged(rq: Any, bound: Any, rtol: float, xp: Namespace = ARRAYS) -> Any:
    """The convergence test of the eigenvalue iteration (the kernel's ``iterate_lanes``): the
    first-order error bound is <= rtol |rq| and rq >= SHIFT; arrays, or one point in Python
    floats with ``xp`` = :data:`.arithmetic.FLOATS`.

    >>> converged(10.0, 1e-14, 1e-14, FLOATS), converged(5.0, 0.0, 1e-14, FLOATS)
    (True, False)
    """
    return (bound <= rtol * xp.abs(rq)) & (rq >= SHIFT)


@lru_cache(maxsize=64)
def kernel_families(n: int) -> tuple[ctypes.Array, tuple]:
    """Both families at degree n as the C kernel's :class:`.modal_kernel.Family` structs (for
    :func:`.modal_kernel.modal_points`), and the arrays they point to (kept alive with them)."""
    fams = (modal_kernel.Family * 2)()
    keep = []
    mass = np.zeros(len(INST1), dtype=np.int32)
    mass[_MASS_TERMS] = 1
    for q, name in enumerate(FAMILIES):
        mf = modal_family(n, name)
        shape, mats = _term_matrices(n, name)
        arrays = {key: np.ascontiguousarray(value) for key, value in (
            ("lam1", mf.lam1), ("lam2", mf.lam2), ("g12", mf.g12), ("g21", mf.g21),
            ("u1", mf.u1), ("u2", mf.u2), ("left1", mf.left1), ("left2", mf.left2),
            ("start", _start_vector(mf.lam1.size + mf.lam2.size)),
            ("tail_rows", mf.op.tail_rows),
            ("term_shape", shape), ("term_mats", mats), ("mass", mass))}
        f = fams[q]
        f.k1, f.k2, f.schur = mf.lam1.size, mf.lam2.size, mf.schur
        for e, (own2, own0, coupling) in enumerate(MODAL_TERMS):
            f.own2[e], f.own0[e], f.coupling[e] = own2, own0, coupling
        f.tail_count = mf.op.tail_rows.shape[0]
        for key, value in arrays.items():
            setattr(f, key, value.ctypes.data)
        keep.append(arrays)
    return fams, tuple(keep)


def solve_family(n: int, family: str, twist: NDArray[np.float64], nu: NDArray[np.float64],
                 *, rtol: float = POWER_RTOL, ceiling: NDArray[np.float64] | None = None,
                 kernel_out: NDArray[np.bool_] | None = None
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Lowest physical lambda = pi^2 p, its mode's coefficient tail, and the eigenvectors
    (coefficients c of :class:`FamilyOperator`), for arrays of points at degree n.

    All points at once by shift-and-invert iteration in the modal form of the family
    (:func:`lowest_eigenpair`, relative accuracy `rtol`): the eigenvalue nearest above
    SHIFT = 0.95 pi^2. Every physical eigenvalue is >= pi^2 (p* >= 1), so that is the lowest
    physical one unless a spurious eigenvalue is nearer; where the iteration has not converged
    to a real value >= SHIFT, the full ``eig`` of the inverse pencil A^{-1} B with the rule of
    the module docstring decides (tests compare both on a grid). Points whose eigenvalue is
    shown to lie above ``ceiling`` (e.g. the other family's) stop early: their lambda and mode
    are then only approximate (lambda above ``ceiling``) and their tail is not computed (inf),
    as no caller uses either. Returns
    lambda = inf where no eigenvalue passes the rule. ``kernel_out`` (bool, one per point), if
    given, is set True where the C kernel computed the result, False where numpy did.
    """
    if kernel_out is not None:
        kernel_out[:] = False
    mf = modal_family(n, family)
    op = mf.op
    try:
        lam, z, w, ok, above = lowest_eigenpair(mf, twist, nu, rtol=rtol, ceiling=ceiling,
                                                kernel_out=kernel_out)
    except np.linalg.LinAlgError:  # SHIFT an eigenvalue of some point (spurious): the rule
        if kernel_out is not None:
            kernel_out[:] = False
        return solve_family_eig(n, family, twist, nu)
    vec = mf.right_vectors(z)
    # the eigenvalue from the O(1) pencil itself: the two-sided Rayleigh quotient (its error is
    # the product of the vectors' errors; K carries round-off ~ eps n^4 in its diagonal)
    tails = np.full(twist.size, np.inf)
    if ok.all():  # the common case, without index arrays (a scalar call's cost is per call)
        if not loose_quotient(rtol, n):
            lam = pencil_rayleigh_quotient(op, twist, nu, mf.left_vectors(w), vec)
        tails[:] = mode_tails(op, vec)
        return lam, tails, vec
    good = np.flatnonzero(ok)
    if good.size and not loose_quotient(rtol, n):
        lam[good] = pencil_rayleigh_quotient(op, twist[good], nu[good],
                                             mf.left_vectors(w[good]), vec[good])
    bad = np.flatnonzero(~(ok | above))
    resolved = good[np.isfinite(lam[good])]
    if resolved.size:
        tails[resolved] = mode_tails(op, vec[resolved])
    if bad.size:  # the full eig with the rule decides
        if kernel_out is not None:
            kernel_out[bad] = False
        lam[bad], tails[bad], vec[bad] = solve_family_eig(n, family, twist[bad], nu[bad])
    return lam, tails, vec


class PointsSolution(NamedTuple):
    """Both families at points of one degree: lambda = pi^2 p and the mode's tail, each
    (2, points) (symmetric first; the antisymmetric tail inf where that family was only shown
    above the symmetric one), and True where the C kernel computed both families."""

    lam: NDArray[np.float64]
    tails: NDArray[np.float64]
    by_kernel: NDArray[np.bool_]


def kernel_degree(n: int) -> bool:
    """Whether the C kernel answers degree n: :func:`uses_kernel` for the larger of both
    families' Schur blocks."""
    return uses_kernel(_schur_size(n))


@lru_cache(maxsize=64)
def _schur_size(n: int) -> int:
    """The larger of the two families' Schur block sizes at degree n."""
    return max(min(mf.lam1.size, mf.lam2.size) for mf in (modal_family(n, f) for f in FAMILIES))


def solve_points(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
                 ) -> PointsSolution:
    """Both families' lowest eigenvalue and tail at flat arrays of points of degree n, by the
    engine: the C kernel (``modal_points``: 32 points side by side, a last few,
    :func:`.tuning.few_points_limit`, one lane each) where it answers the degree
    (:func:`kernel_degree`); else the numpy reference (:func:`solve_family`; one point up to
    DENSE_ENTRIES matrix entries by its one-point form of ``modal_points``,
    :func:`_numpy_point`, so that a scalar call and a one-element array get the same bits). The
    symmetric family first, the antisymmetric one then only until it is shown above
    (1 + CLOSE_REL) times the symmetric eigenvalue. Points the kernel or the one-point form do
    not accept are solved by :func:`solve_family` (the full ``eig`` where the iteration is
    rejected)."""
    lam, tails = np.empty((2, twist.size)), np.empty((2, twist.size))
    by_kernel = np.zeros(twist.size, dtype=bool)
    rest = np.arange(twist.size)
    if kernel_degree(n):
        lam1, tails1, status = _solve_lanes(n, twist, nu, rtol)
        lam[:], tails[:] = lam1.T, tails1.T
        by_kernel = _accepted(status[:, 0], status[:, 1])
        rest = np.flatnonzero(~by_kernel)
        if not rest.size:
            return PointsSolution(lam, tails, by_kernel)
    elif (twist.size == 1 and not modal_kernel.available()
          and (n - 1) ** 2 <= DENSE_ENTRIES):
        lean = _numpy_point(n, float(twist[0]), float(nu[0]), rtol)
        if lean is not None:
            return PointsSolution(np.array(lean[0])[:, None], np.array(lean[1])[:, None],
                                  by_kernel)
    lam[:, rest], tails[:, rest], by_kernel[rest] = _by_family(n, twist[rest], nu[rest], rtol)
    return PointsSolution(lam, tails, by_kernel)


def _by_family(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
               ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """:func:`solve_points` by :func:`solve_family`, 32 lanes a family (the full ``eig`` where
    the iteration is rejected): the symmetric family, then the antisymmetric one until shown
    above (1 + CLOSE_REL) times it; lambda and tails (2, points), and where the kernel computed
    both."""
    lam, tails = np.empty((2, twist.size)), np.empty((2, twist.size))
    used = np.empty((2, twist.size), dtype=bool)
    lam[0], tails[0], _ = solve_family(n, FAMILIES[0], twist, nu, rtol=rtol, kernel_out=used[0])
    lam[1], tails[1], _ = solve_family(n, FAMILIES[1], twist, nu, rtol=rtol,
                                       ceiling=lam[0] * (1 + CLOSE_REL), kernel_out=used[1])
    return lam, tails, used[0] & used[1]


def solve_point(n: int, twist: float, nu: float, rtol: float
                ) -> tuple[list[float], list[float], bool]:
    """:func:`solve_points` for one point given as Python floats, without a batch's arrays
    where the kernel is installed (a scalar call's cost is mostly numpy's per-call overhead):
    lambda and the tail of both families as lists [symmetric, antisymmetric], and whether the
    kernel computed them. Without the kernel :func:`solve_points` answers (its one-point form,
    :func:`_numpy_point`).

    >>> lam, tails, _ = solve_point(22, 3.0, 1.5, 1e-14)
    >>> round(min(lam) / 9.869604401089358, 9)
    1.078092611
    """
    if modal_kernel.available() and n <= LEAN_MAX_DEGREE:
        dtype = np.longdouble if _extended(twist, n, rtol) else float
        om, nv = dtype(twist), dtype(nu)
        lam1, tails1, status = _kernel_points(
            n, np.array([[t.coefficient(om, nv) for t in INST1]], dtype=dtype), rtol,
            loose_quotient(rtol, n))
        if _accepted(*status[0].tolist()):
            return lam1[0].tolist(), tails1[0].tolist(), True
        # rejected by the one-lane kernel: the batched engine and the reference decide (not
        # solve_points, which would repeat the same one-lane call)
        lam, tails, by_kernel = _by_family(n, np.array([twist]), np.array([nu]), rtol)
        return lam[:, 0].tolist(), tails[:, 0].tolist(), bool(by_kernel[0])
    sol = solve_points(n, np.array([twist]), np.array([nu]), rtol)
    return sol.lam[:, 0].tolist(), sol.tails[:, 0].tolist(), bool(sol.by_kernel[0])


def _point_iterate(pair: NDArray[np.float64], start: NDArray[np.float64], rtol: float,
                   ceiling: float | None, first: int, max_steps: int
                   ) -> tuple[float, NDArray[np.float64], int]:
    """:func:`_iterate` for one point, right and left vectors as one (2 m,) vector: lambda,
    the unit vectors (2, m) and the kernel's status code. The test is :func:`_lanes_test`'s
    from one Gram product: with K x = SHIFT x + p (p the step's input), rq = SHIFT + y.p / y.x
    and the residuals are p - (rq - SHIFT) x and q - (rq - SHIFT) y up to the vectors' scales,
    so |r| |l| / |y.x| needs no normalisation (the vectors are normalised at each test)."""
    m = start.size // 2
    v = start
    for step in range(1, max_steps + 1):
        prev, v = v, pair @ v
        if step < first or step % 2:
            continue
        both = np.concatenate((v, prev)).reshape(4, m)
        (xx, _, _, _), (yx, yy, yp, _) = (both[:2] @ both.T).tolist()
        mu = yp / yx if yx else math.nan
        rq = SHIFT + mu
        res = both[2:] - mu * both[:2]
        rx, ry = np.einsum("ij,ij->i", res, res).tolist()
        bound = math.sqrt(rx * ry) / abs(yx) if yx else math.nan
        conv = converged(rq, bound, rtol, FLOATS)
        high = not conv and ceiling is not None and rq - 100.0 * bound > ceiling
        unit = both[:2] * np.array([[_inverse_norm(xx)], [_inverse_norm(yy)]])
        if conv or high or step + 2 > max_steps:
            status = (modal_kernel.CONVERGED if conv else modal_kernel.ABOVE if high
                      else modal_kernel.NOT_CONVERGED)
            return rq, unit, status
        v = unit.reshape(-1)
    raise AssertionError("unreachable: the last step is a test")  # max_steps >= first


def _inverse_norm(square: float) -> float:
    """1 / sqrt(square), nan for a zero vector (as numpy's 1 / 0 * 0)."""
    return 1.0 / math.sqrt(square) if square > 0.0 else math.nan


def _point_family_solve(n: int, family: str, coef: list[float], extended: bool, twist: float,
                        nu: float, rtol: float, ceiling: float | None, first: int
                        ) -> tuple[float, float, int]:
    """One family at one point by the numpy reference, as the kernel's ``family_lanes``:
    lambda, the tail (inf unless converged) and the status code; `extended`: the pencil's
    quotient is summed in extended precision (:func:`_extended`)."""
    pf = _point_family(n, family)
    pair = _point_inverse(pf, coef)
    if pair is None:
        return math.nan, math.inf, modal_kernel.NOT_CONVERGED
    lam, unit, status = _point_iterate(pair, pf.start, rtol, ceiling, first, POWER_STEPS)
    if status != modal_kernel.CONVERGED:
        return lam, math.inf, status
    vec = pf.right @ unit[0]
    parts = tail_parts(pf.op.tail_rows @ vec)  # the tail's one definition (:mod:`.resolution`)
    if not np.isfinite(parts).all():
        return lam, math.inf, modal_kernel.NOT_CONVERGED
    tail = float(tail_from_parts(parts))
    if not loose_quotient(rtol, n):
        dtype = np.longdouble if extended else np.float64
        lam = float(_rayleigh_sums(pf.op, np.array([twist]), np.array([nu]),
                                   (unit[1] @ pf.left)[None], vec[None], dtype)[0])
        if not lam >= SHIFT:  # a nan quotient is not an answer
            return lam, tail, modal_kernel.NOT_CONVERGED
    return lam, tail, status


def _numpy_point(n: int, twist: float, nu: float, rtol: float
                 ) -> tuple[list[float], list[float]] | None:
    """:func:`solve_point` by the numpy reference without a batch's arrays (the kernel's
    ``modal_points`` on one point, in numpy): the symmetric family, then the antisymmetric one
    until shown above (1 + CLOSE_REL) times it (its first test at :func:`.tuning.first_check`
    with a ceiling); None where a family is not accepted (:func:`solve_points` then decides,
    with the full ``eig``)."""
    coef = term_coefficients(twist, nu).tolist()
    ext = bool(_extended(twist, n, rtol))
    first = first_check(rtol, False)
    lam0, tail0, status0 = _point_family_solve(n, FAMILIES[0], coef, ext, twist, nu, rtol, None,
                                               first)
    if status0 != modal_kernel.CONVERGED:
        return None
    lam1, tail1, status1 = _point_family_solve(n, FAMILIES[1], coef, ext, twist, nu, rtol,
                                               lam0 * (1 + CLOSE_REL), first_check(rtol, True))
    if status1 not in (modal_kernel.CONVERGED, modal_kernel.ABOVE):
        return None
    return [lam0, lam1], [tail0, tail1]


def _solve_lanes(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int32]]:
    """lambda, tails and status (points, 2) of both families by the C kernel (``modal_points``:
    32 points side by side, a last few one lane each; the antisymmetric family stopped where
    shown above the symmetric one, its tail then inf). At |Omega| > LONG_TWIST and tight
    tol the pencil's quotient is summed in double-double, from the coefficients in extended
    precision (as :func:`pencil_rayleigh_quotient`, which sums in long double)."""
    loose, big = loose_quotient(rtol, n), _extended(twist, n, rtol)
    if not np.any(big):  # the common case: one call, no index arrays
        return _kernel_points(n, term_coefficients(twist, nu), rtol, loose)
    lam, tails = np.empty((twist.size, 2)), np.empty((twist.size, 2))
    status = np.empty((twist.size, 2), dtype=np.int32)
    for sel, dtype in ((np.flatnonzero(~big), float), (np.flatnonzero(big), np.longdouble)):
        if sel.size:
            coef = term_coefficients(twist[sel].astype(dtype), nu[sel].astype(dtype))
            lam[sel], tails[sel], status[sel] = _kernel_points(n, coef, rtol, loose)
    return lam, tails, status


def _extended(twist, n: int, rtol: float):
    """Where the pencil's quotient is summed in extended precision: |Omega| > LONG_TWIST at a
    tight tol (a bool, or a bool array for an array `twist`; False at a loose one)."""
    if loose_quotient(rtol, n):
        return False
    return np.abs(twist) > LONG_TWIST


def _kernel_points(n: int, coef: NDArray, rtol: float, loose: bool
                   ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int32]]:
    """:func:`.modal_kernel.modal_points` at points given by their INST1 coefficients (points,
    terms): in long double, the quotient is summed in double-double."""
    families, _arrays = kernel_families(n)  # _arrays: what the structs point to, kept alive
    hi = coef.astype(float, copy=False)
    return modal_kernel.modal_points(
        families, hi, shift=SHIFT, rtol=rtol, first=first_check(rtol, False),
        max_steps=POWER_STEPS, backward_tol=BACKWARD_TOL, close_rel=CLOSE_REL, loose=loose,
        few=few_points_limit(n),
        coef_lo=None if coef.dtype == np.float64 else (coef - hi).astype(float))


def _accepted(symmetric: Any, antisymmetric: Any) -> Any:
    """Both families accepted, from their status codes (arrays of points, or one point's ints):
    the symmetric converged, the antisymmetric converged or above."""
    return (symmetric == modal_kernel.CONVERGED) & (
        (antisymmetric == modal_kernel.CONVERGED) | (antisymmetric == modal_kernel.ABOVE))
