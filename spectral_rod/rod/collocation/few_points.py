r"""The lowest eigenvalue of both mode families for one point or a few (Eq. ``inst1``), lean.

The batched engine (:mod:`.eigensolver`) pays a fixed cost per degree group of ~0.5 ms of array
bookkeeping, which dominates for a scalar call or a batch of ten. Two implementations avoid it:
the C kernel on one lane (the engine), and, without the kernel, dense pencils in numpy. The
second is a different iteration from the kernel's; it exists because the benchmark rows "a loop
of scalar calls" and "batches of 10" without the kernel need it (the numpy reference of the
kernel's algorithm, :func:`.eigensolver.lowest_eigenpair`, costs ~0.4 ms a family for one point,
slower than the baseline's ~0.3 ms; ``python -m pytest -m bench -k scalar_loop`` with
``SPECTRAL_ROD_NO_KERNEL=1`` measures the row).

Where the C kernel is installed (:mod:`.modal_kernel`), the kernel solves the points one at a
time in one call (``modal_points``): the batched engine's own algorithm and test with one lane
(the Schur complement of the shifted modal form, two-sided shift-and-invert steps, the pencil's
Rayleigh quotient, the mode's tail), and, as there, the antisymmetric family only until it is
shown above the symmetric one (its tail is then inf). Above |Omega| = LONG_TWIST at tight tol
the quotient, whose terms cancel to ~lambda/Omega^2, is summed in double-double from the
coefficients in long double (the batched engine sums the same double-double forms in long
double). At rtol = 1e-8 (modal quotient, as the batched engine's) it is within 1.2e-10 of the
discrete eigenvalue on the 71 points of step 3 below (the largest at n = 64: K's round-off).

Where the kernel is not installed each (point, family) keeps the dense collocation pencil
(A, B) of :mod:`.discretisation` (m = n - 1 unknowns, both families the same size, so they are
stacked), and:

1. F = A - SHIFT B is factorised and inverted once by LAPACK (``dgetrf``/``dgetri`` called
   directly: 5 us for m = 21, where ``numpy.linalg.inv`` takes 20 us);
2. M = F^{-1} B, the shift-and-invert matrix, is squared 3 or 4 times: M^k x0 and x0^T M^k
   (k = 8 or 16) are the right and left power iterates of k steps, for a handful of batched
   matrix products instead of 2k solves (above m = SQUARING_MAX the steps are taken one by one
   with the vectors, cheaper there);
3. the eigenvalue is the two-sided Rayleigh quotient of the pencil itself, y^T A x / y^T B x
   (x = M x_k, y^T = x0^T M^{k+1} F^{-1}: its error is the product of the vectors' errors),
   accumulated in extended precision above |Omega| = LONG_TWIST as in the batched engine
   (without it the round-off reached 0.33 eps Omega^2 on Omega(L) in [40, 50], above the error
   model's 0.3). From rtol = LOOSE_RTOL on (tol >= 1e-6), as in the batched engine, the
   eigenvalue is instead SHIFT + 1/theta_2k (step 4), without the left vector: on 71 points
   (Figure 1's and random ones, Omega(L) < 50, nu <= 100) at their a priori degree and n = 64,
   where accepted at rtol = 1e-8 (276 of 284 families) it differs from the discrete eigenvalue
   (the full ``eig`` of the pencil) by <= 4.4e-11 (``tests/test_speed_paths.py`` computes and
   prints it);
4. convergence is judged from the power estimates theta_k = x0^T M^{k+1} x0 / x0^T M^k x0 of
   1/(lambda - SHIFT) at k and 2k: their relative difference delta measures the vectors' error
   after k steps (~ the contraction^k), so the quotient's error is ~ delta^2; a point is
   accepted when delta^2 <= rtol, lambda >= SHIFT and its mode's tail parts are finite (and
   not both zero). Anything else (a slow contraction, a
   spurious eigenvalue nearest the shift) goes back to the batched engine, which decides with
   its own iteration or the full ``eig``.

Both families are solved by the dense pencils (no "ceiling" shortcut: the second family costs
one LAPACK pair). At the default tol the result differs from the batched engine's only by the
rounding of two different computations of the same Rayleigh quotient; at a looser tol also by
the two iterations' different stopping, up to the iteration tolerance (measured: see
:func:`spectral_rod.critical_load`).

One point (a scalar call, or an array of one point) is :func:`solve_one`'s: the same steps on
Python floats and (family, m, m) stacks, without the per-point index arrays of a batch (a scalar
call's cost is mostly numpy's per-call overhead). Steps 1-3 leave only the few scalars step 4
needs (:class:`_Iterates`: four dot products and two tail maxima per family), so that for one
point step 4 runs in Python floats (:func:`_judge_one`, the rule of :func:`_judge`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray
from scipy.linalg.lapack import dgetrf, dgetri  # at import: before BLAS threads are limited

from spectral_rod.rod.collocation import modal_kernel
from spectral_rod.rod.collocation.discretisation import INST1, family_operator, term_coefficients
from spectral_rod.rod.collocation.eigensolver import (
    _start_vector,
    kernel_families,
    pencil_rayleigh_quotient,
)
from spectral_rod.rod.collocation.resolution import tail_from_parts, tail_parts
from spectral_rod.rod.collocation.stacked_inverse import BACKWARD_TOL
from spectral_rod.rod.collocation.tuning import (
    LEAN_MAX_DEGREE,
    LONG_TWIST,
    LOOSE_RTOL,
    POWER_STEPS,
    SQUARING_MAX,
    first_check,
    loose_quotient,
    power_steps,
)
from spectral_rod.rod.families import CLOSE_REL, FAMILIES, SHIFT

__all__ = ["LEAN_MAX_DEGREE", "SQUARING_MAX", "DensePencils", "dense_pencils", "solve_few",
           "solve_one"]

@dataclass(frozen=True)
class DensePencils:
    """Both families' pencils at degree n, stored for the lean solver (see module docstring).

    ``pieces``: (len(INST1) + 1, 2 * 3 m m): coefficients (those of :data:`INST1`, then 1) @
    pieces gives, per family, [F^T, A^T, B^T] with F = A - SHIFT B, each in C order (= the
    matrix in Fortran order, which LAPACK reads without a copy); ``mass`` B (2, m, m);
    ``tail_rows`` (2, n + 1, m): the Chebyshev coefficients of the fields' own parity, the two
    last of each field first; ``start`` the start vector x0.
    """

    n: int
    pieces: NDArray[np.float64]
    mass: NDArray[np.float64]
    tail_rows: NDArray[np.float64]
    start: NDArray[np.float64]


@lru_cache(maxsize=64)
def dense_pencils(n: int) -> DensePencils:
    """Assemble :class:`DensePencils` for degree n once (from :func:`family_operator`)."""
    ops = [family_operator(n, f) for f in FAMILIES]
    m, k = ops[0].mass.shape[0], len(INST1)
    pieces = np.zeros((k + 1, 2, 3, m, m))
    for f, op in enumerate(ops):
        p_t, b_t = np.swapaxes(op.pieces, 1, 2), op.mass.T
        pieces[:k, f, 0] = pieces[:k, f, 1] = p_t
        pieces[k, f, 0], pieces[k, f, 2] = -SHIFT * b_t, b_t
    return DensePencils(n, pieces.reshape(k + 1, -1), np.stack([op.mass for op in ops]),
                        np.stack([op.tail_rows for op in ops]), _start_vector(m))


def _inverses(f_t: NDArray[np.float64]) -> NDArray[np.float64] | None:
    """F^{-1} for each matrix of a stack given as F^T in C order (LU and inverse by LAPACK,
    overwriting the input), or None if any F is singular (the caller then falls back)."""
    flat = f_t.reshape(-1, *f_t.shape[-2:])
    for j in range(flat.shape[0]):
        # flat[j].T is F in Fortran order, which f2py hands to LAPACK without a copy: the LU
        # and then the inverse overwrite it, so flat[j] ends as F^{-T} (no output array). The
        # inverse, not dgesv with B's m columns: OpenBLAS's solve with m columns costs more
        lu, piv, info = dgetrf(flat[j].T, overwrite_a=1)
        if info != 0:
            return None
        _, info = dgetri(lu, piv, overwrite_lu=1)
        if info != 0:
            return None
    return np.swapaxes(flat, -1, -2).reshape(f_t.shape)


def _power_iterates(mat: NDArray[np.float64], start: NDArray[np.float64], steps: int
                    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """x = M^k x0 (a column, (..., m, 1)) and u^T = x0^T M^k (k = steps) for a stack of M
    (module docstring, step 2)."""
    if mat.shape[-1] <= SQUARING_MAX:  # log2(steps) products of matrices
        power = mat
        for _ in range(steps.bit_length() - 1):
            power = power @ power
        return power @ start[:, None], start @ power
    x = u = np.broadcast_to(start, mat.shape[:-1])  # steps products with vectors
    for _ in range(steps):
        x, u = (mat @ x[..., None])[..., 0], (u[..., None, :] @ mat)[..., 0, :]
    return x[..., None], u


def _pencil_quotient(mats: NDArray[np.float64], f_inv: NDArray[np.float64],
                     mat: NDArray[np.float64], x1: NDArray[np.float64], u: NDArray[np.float64]
                     ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The pencil's left vector y and its quotient y^T A x1 / y^T B x1 in double precision
    (module docstring, step 3), for stacks (..., family) of the pencils [F^T, A^T, B^T]
    (`mats`), F^{-1}, M and the iterates."""
    y = ((u[..., None, :] @ mat) @ f_inv)[..., 0, :]  # left eigenvector of the pencil
    ab_x = (x1[..., None, None, :] @ mats[..., 1:, :, :])[..., 0, :]  # (A x1, B x1)
    num_den = (ab_x @ y[..., None])[..., 0]  # (y^T A x1, y^T B x1)
    return y, num_den[..., 0] / num_den[..., 1]


def _extended_quotient(n: int, family: int, twist: NDArray[np.float64],
                       nu: NDArray[np.float64], y: NDArray[np.float64], x1: NDArray[np.float64]
                       ) -> NDArray[np.float64]:
    """The pencil's quotient of one family in extended precision, as the batched engine's
    (:func:`.eigensolver.pencil_rayleigh_quotient`), for |Omega| > LONG_TWIST."""
    return pencil_rayleigh_quotient(family_operator(n, FAMILIES[family]), twist, nu, y, x1)


class _Iterates(NamedTuple):
    """What steps 1-3 of the module docstring leave for the judgement of step 4, per (...,
    family): ``sums`` (..., 4) = (x0.x, x0.x1, u.x, u.x1) with x = M^k x0, x1 = M x, u^T =
    x0^T M^k (so theta_k = sums[1] / sums[0], theta_2k = sums[3] / sums[2]); ``tails`` (..., 2)
    = :func:`.resolution.tail_parts` of x1's mode; ``quotient`` the pencil's Rayleigh quotient
    (None from rtol = LOOSE_RTOL on, where lambda = SHIFT + 1/theta_2k)."""

    sums: NDArray[np.float64]
    tails: NDArray[np.float64]
    quotient: NDArray[np.float64] | None


def _solve_pencils(dp: DensePencils, mats: NDArray[np.float64], rtol: float,
                   extend: Callable[..., None]) -> _Iterates | None:
    """Steps 1-3 of the module docstring for stacks (..., family) of the pencils [F^T, A^T, B^T]
    (`mats`); None if some F is singular. ``extend(quotient, y, x1)`` puts the
    extended-precision quotient into ``quotient`` where |Omega| is large.
    """
    f_inv = _inverses(mats[..., 0, :, :])  # overwrites F^T (not needed after)
    if f_inv is None:
        return None
    with np.errstate(all="ignore"):  # overflow (a spurious eigenvalue at SHIFT): rejected later
        mat = f_inv @ dp.mass
        x, u = _power_iterates(mat, dp.start, power_steps(rtol))
        x1 = mat @ x
        both = np.concatenate((x, x1), axis=-1)  # (..., m, 2)
        sums = np.concatenate((dp.start @ both, (u[..., None, :] @ both)[..., 0, :]), axis=-1)
        tails = tail_parts((dp.tail_rows @ x1)[..., 0])
        quotient = None
        if rtol < LOOSE_RTOL:  # else the power estimate is accurate enough (docstring, step 3)
            x1 = x1[..., 0]
            y, quotient = _pencil_quotient(mats, f_inv, mat, x1, u)
            extend(quotient, y, x1)
    return _Iterates(sums, tails, quotient)


def _judge(it: _Iterates, rtol: float
           ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """Step 4 of the module docstring on arrays: lambda, the tails and whether each (point,
    family) was accepted (:func:`_judge_one` is the same rule in Python floats)."""
    with np.errstate(all="ignore"):
        s = it.sums
        theta_k, theta_2k = s[..., 1] / s[..., 0], s[..., 3] / s[..., 2]
        lam = SHIFT + 1.0 / theta_2k if it.quotient is None else it.quotient
        delta = np.abs(theta_2k - theta_k) / np.abs(theta_2k)
        tails = tail_from_parts(it.tails)
        ok = ((delta * delta <= rtol) & (theta_2k > 0) & (lam >= SHIFT) & np.isfinite(tails)
              & np.isfinite(it.tails).all(axis=-1))  # an infinite coefficient: no mode
    return lam, tails, ok


def _judge_one(sums: list[float], tail: list[float], quotient: float | None, rtol: float
               ) -> tuple[float, float, bool]:
    """:func:`_judge` for one family in Python floats (the scalar path's): lambda, the tail and
    whether it was accepted (``tests/test_speed_paths.py`` checks the two agree)."""
    last, other = tail
    try:
        theta_k, theta_2k = sums[1] / sums[0], sums[3] / sums[2]
        lam = SHIFT + 1.0 / theta_2k if quotient is None else quotient
        delta = abs(theta_2k - theta_k) / abs(theta_2k)
        t = last / max(last, other)
    except ZeroDivisionError:  # a zero iterate or mode: not accepted
        return math.nan, math.inf, False
    ok = (delta * delta <= rtol and theta_2k > 0 and lam >= SHIFT and math.isfinite(last)
          and math.isfinite(other))  # both parts: max() would pass over a nan `other`
    return lam, t, ok


def _solve_kernel(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
                  ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """lambda and tails (points, 2) of both families and whether both were accepted, by the C
    kernel one point at a time (the batched engine's algorithm and test; the antisymmetric
    family stopped where shown above the symmetric one, its tail then inf). At |Omega| >
    LONG_TWIST and tight tol the pencil's quotient is summed in double-double, from the
    coefficients in extended precision (as the batched engine's, which sums in long double)."""
    loose, big = loose_quotient(rtol, n), _extended(twist, n, rtol)
    lam, tails = np.empty((twist.size, 2)), np.empty((twist.size, 2))
    status = np.empty((twist.size, 2), dtype=np.int32)
    for sel, dtype in ((np.flatnonzero(~big), float), (np.flatnonzero(big), np.longdouble)):
        if sel.size:
            coef = term_coefficients(twist[sel].astype(dtype), nu[sel].astype(dtype))
            lam[sel], tails[sel], status[sel] = _kernel_points(n, coef, rtol, loose)
    return lam, tails, _accepted(status)


def _extended(twist, n: int, rtol: float):
    """Where the pencil's quotient is summed in extended precision: |Omega| > LONG_TWIST at a
    tight tol (a bool, or a bool array for an array `twist`)."""
    return (np.abs(twist) > LONG_TWIST) & (not loose_quotient(rtol, n))


def _kernel_points(n: int, coef: NDArray, rtol: float, loose: bool
                   ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int32]]:
    """:func:`.modal_kernel.modal_points` at points given by their INST1 coefficients (points,
    terms): in long double, the quotient is summed in double-double."""
    families, _arrays = kernel_families(n)  # _arrays: what the structs point to, kept alive
    hi = coef.astype(float)
    return modal_kernel.modal_points(
        families, hi, shift=SHIFT, rtol=rtol, first=first_check(rtol, False),
        max_steps=POWER_STEPS, backward_tol=BACKWARD_TOL, close_rel=CLOSE_REL, loose=loose,
        coef_lo=None if coef.dtype == np.float64 else (coef - hi).astype(float))


def _accepted(status: NDArray[np.int32]) -> NDArray[np.bool_]:
    """Both families accepted: the symmetric converged, the antisymmetric converged or above."""
    return (status[:, 0] == modal_kernel.CONVERGED) & (
        (status[:, 1] == modal_kernel.CONVERGED) | (status[:, 1] == modal_kernel.ABOVE))


def solve_one(n: int, twist: float, nu: float, rtol: float
              ) -> tuple[list[float], list[float], bool]:
    """The lean solver for one point given as Python floats: lambda = pi^2 p and the tail of
    both families (lists [symmetric, antisymmetric]) and whether both were accepted. It skips
    a batch's per-point arrays (a scalar call's cost is mostly numpy's per-call overhead).

    >>> lam, tails, ok = solve_one(22, 3.0, 1.5, 1e-14)
    >>> ok, round(min(lam) / 9.869604401089358, 9)
    (True, 1.078092611)
    """
    if modal_kernel.available():
        dtype = np.longdouble if _extended(twist, n, rtol) else float
        om, nv = dtype(twist), dtype(nu)
        lam1, tails1, status = _kernel_points(
            n, np.array([[t.coefficient(om, nv) for t in INST1]], dtype=dtype), rtol,
            loose_quotient(rtol, n))
        return lam1[0].tolist(), tails1[0].tolist(), bool(_accepted(status)[0])
    modal_kernel.warn_if_missing()
    dp = dense_pencils(n)
    m = dp.mass.shape[1]
    coef = np.array([*(t.coefficient(twist, nu) for t in INST1), 1.0])

    def extend(lam, y, x1):
        if abs(twist) > LONG_TWIST:
            for f in range(2):
                lam[f] = _extended_quotient(n, f, np.array([twist]), np.array([nu]),
                                            y[f:f + 1], x1[f:f + 1])[0]

    it = _solve_pencils(dp, (coef @ dp.pieces).reshape(2, 3, m, m), rtol, extend)
    if it is None:
        return [math.nan, math.nan], [math.inf, math.inf], False
    quot = [None, None] if it.quotient is None else it.quotient.tolist()
    out = [_judge_one(s, t, q, rtol) for s, t, q in zip(it.sums.tolist(), it.tails.tolist(),
                                                         quot, strict=True)]
    return [o[0] for o in out], [o[1] for o in out], out[0][2] and out[1][2]


def solve_few(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
              ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """lambda = pi^2 p of both families, the modes' coefficient tails (both (2, points)) and
    whether both families converged, at flat arrays of points at degree n (module docstring).

    ``rtol`` is the accepted relative error of lambda (as ``POWER_RTOL`` of the batched
    engine); 3 squarings (8 steps) where rtol >= LOOSE_RTOL = 1e-8, else 4 (16). One point is
    :func:`solve_one`'s (so a one-point array and a scalar call agree bit for bit).
    """
    if twist.size == 1:
        lam1, tails1, ok1 = solve_one(n, float(twist[0]), float(nu[0]), rtol)
        return np.array(lam1)[:, None], np.array(tails1)[:, None], np.array([ok1])
    solve = _few_by_kernel if modal_kernel.available() else _few_dense
    return solve(n, twist, nu, rtol)


def _few_by_kernel(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
                   ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """:func:`solve_few` by the C kernel (:func:`_solve_kernel`)."""
    lam, tails, ok = _solve_kernel(n, twist, nu, rtol)
    return lam.T, tails.T, ok


def _few_dense(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
               ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """:func:`solve_few` by the dense pencils (steps 1-4 of the module docstring)."""
    dp = dense_pencils(n)
    pts, m = twist.size, dp.mass.shape[1]
    coef = np.hstack([term_coefficients(twist, nu), np.ones((pts, 1))])
    big = np.flatnonzero(np.abs(twist) > LONG_TWIST)

    def extend(lam, y, x1):
        if big.size:  # as the batched engine: extended precision
            for f in range(2):
                lam[big, f] = _extended_quotient(n, f, twist[big], nu[big], y[big, f],
                                                 x1[big, f])

    it = _solve_pencils(dp, (coef @ dp.pieces).reshape(pts, 2, 3, m, m), rtol, extend)
    if it is None:
        return np.full((2, pts), np.nan), np.full((2, pts), np.inf), np.zeros(pts, bool)
    lam, tails, ok = _judge(it, rtol)
    return lam.T, tails.T, np.asarray(ok.all(axis=1))
