r"""The lowest physical eigenpair of the collocation pencil of Eq. ``inst1``, fast: the engine's
entry points (:func:`solve_points`, :func:`solve_point`) and its numpy reference.

Only the lowest eigenvalue is needed and it is >= pi^2 (:mod:`spectral_rod.rod.families`). The
uncoupled operators -d^2/ds^2 of each field are diagonalised once per degree
(:class:`ModalFamily`); in that basis the family is K z = lambda z with K diagonal plus an
Omega-proportional coupling, so K - SHIFT is inverted through a Schur complement of the smaller
block, for all points of a degree at once (:class:`_ShiftedModal`; for a few points as dense
inverses, :class:`_DenseShifted`). Shift-and-invert iteration on right and left vectors
(:func:`lowest_eigenpair`, contraction 0.01-0.2 per step on Figure 1's range) gives the
eigenvectors, and the eigenvalue is the two-sided Rayleigh quotient of the O(1) pencil (A, B)
itself (error = product of the two vectors' errors).

One algorithm, two implementations: the C kernel of :mod:`.modal_kernel` (the engine: 32
points side by side, or one point at a time with the same code, ``solve_group``) and this
module's numpy code (its executable reference, and the engine where the kernel is not built).
Each rule has one numpy function mirroring the kernel's: the convergence test
:func:`converged` (with :func:`_lanes_test`, C ``lanes_test``), the pencil's quotient
:func:`pencil_rayleigh_quotient` (C ``pencil_quotient``, its precision a parameter) and the
tail :func:`.resolution.mode_tails` (C ``family_point``); ``tests/test_modal_kernel.py``,
``tests/test_engine_contract.py`` and ``tests/test_speed_paths.py`` compare the two. A scalar
call without the kernel takes the numpy reference's one-point form of ``modal_points``
(:func:`_numpy_point`): (K - SHIFT)^{-1} and its transpose as one block-diagonal matrix, so that
a step is one product, the same test from one Gram product (:func:`_point_iterate`), and the
pencil's quotient above LONG_TWIST from exact split BLAS products (:func:`_split_terms`) rather
than ``longdouble`` loops.

Choosing the physical eigenvalue (the rule)
-------------------------------------------
The continuous spectrum is real and >= pi^2. Collocation adds spurious eigenvalues that are
complex or very large (theta = 1/lambda near 0). The rule: from each family keep theta with
|Im theta| <= 1e-8 |theta| and Re theta > 0 and take the largest (the smallest lambda); p* is
the smaller of the two families. The fast path returns the eigenvalue nearest above SHIFT;
as every physical eigenvalue is >= pi^2 > SHIFT this is the rule's choice unless a spurious
eigenvalue is nearer to SHIFT, in which case the iteration does not converge to a real value
>= SHIFT and the full ``eig`` of the inverse pencil A^{-1} B with the rule decides (the two are
compared on a grid in ``tests/test_accuracy_control.py``). The choice is accepted only if the
error estimate from the mode's Chebyshev coefficients (:mod:`.resolution`; a spurious mode is
unresolved by construction) meets the tolerance.
"""

from __future__ import annotations

import ctypes
import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, NamedTuple, cast

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.collocation import modal_kernel
from spectral_rod.rod.collocation.discretisation import (
    INST1,
    FamilyOperator,
    family_operator,
    term_coefficients,
)
from spectral_rod.rod.collocation.resolution import mode_tails, tail_from_parts, tail_parts
from spectral_rod.rod.collocation.stacked_inverse import BACKWARD_TOL, stacked_inverse
from spectral_rod.rod.collocation.tuning import (
    CALIBRATED_TOL,
    DENSE_ENTRIES,
    KERNEL_MAX_SCHUR,
    LEAN_MAX_DEGREE,
    LONG_TWIST,
    POINT_SCHUR_DEGREE,
    POWER_RTOL,
    POWER_STEPS,
    few_points_limit,
    first_check,
    iteration_allowance,
    iteration_rtol,
    loose_quotient,
)
from spectral_rod.rod.families import CLOSE_REL, FAMILIES, SHIFT

__all__ = ["CALIBRATED_TOL", "ISOLATION_GAP", "KERNEL_MAX_SCHUR", "ModalFamily", "ModalParts",
           "first_check", "iteration_allowance", "iteration_rtol", "kernel_families",
           "loose_quotient", "lowest_eigenpair", "lowest_gap", "modal_family", "modal_parts",
           "pencil_rayleigh_quotient",
           "physical_eig", "solve_family", "solve_family_eig", "uses_kernel"]

#: Eigenvalues with |Im| above this fraction of |lambda| are complex, i.e. not physical.
IMAG_REL = 1.0e-8


def _modal_terms() -> tuple[tuple[int, int, int], tuple[int, int, int]]:
    """Indices in INST1 of (second-order own, zero-order own, first-order coupling) term per
    equation: the structure the modal form relies on (checked here, once)."""
    out = []
    for e in range(2):
        idx = {(t.field == e, t.order): i for i, t in enumerate(INST1) if t.equation == e}
        if set(idx) != {(True, 2), (True, 0), (False, 1)}:
            raise ArithmeticError("the modal eigensolver needs, per equation, a 2nd- and a "
                                  "0th-order own term and a 1st-order coupling term")
        out.append((idx[True, 2], idx[True, 0], idx[False, 1]))
    return out[0], out[1]


MODAL_TERMS = _modal_terms()


def _lowest_physical(theta: NDArray[np.complex128]) -> NDArray[np.int_]:
    """Index of the largest real positive theta = 1/lambda in each row (the rule above)."""
    ok = (np.abs(theta.imag) <= IMAG_REL * np.abs(theta)) & (theta.real > 0)
    return np.argmax(np.where(ok, theta.real, -np.inf), axis=-1)


def physical_eig(m: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Largest real positive theta of each matrix and its eigenvector by full ``eig`` (the rule).

    theta = nan where no eigenvalue passes the rule.
    """
    theta, vec = np.linalg.eig(m)
    idx = _lowest_physical(theta)
    rows = np.arange(theta.shape[0])
    th = theta[rows, idx]
    valid = (np.abs(th.imag) <= IMAG_REL * np.abs(th)) & (th.real > 0)
    return np.where(valid, th.real, np.nan), vec[rows, :, idx].real


@dataclass(frozen=True)
class ModalFamily:
    """One parity family in the eigenbasis of its uncoupled second-derivative operators.

    S_i = -4 V_i^{-1} D2_i (the collocated -d^2/ds^2 with omega = 0 at the ends; real spectrum
    ~ (j pi)^2, eigenvector matrices U_i with condition numbers <= 21 up to n = 256) is
    diagonalised once per degree: S_i = U_i diag(Lambda_i) U_i^{-1}. With c_i = U_i z_i and the
    rows multiplied by U_i^{-1} V_i^{-1}, the pencil (A, B) becomes the similar standard problem

        K z = lambda z,   K = diag(c0_1 - c2_1 Lambda_1, c0_2 - c2_2 Lambda_2)
                              + [[0, 2 c1_1 G12], [2 c1_2 G21, 0]],

    with c2_i, c0_i, c1_i the coefficients of equation i's second-order, zero-order and coupling
    terms in :data:`INST1` (for ``inst1``: diag(Lambda_1 + Omega^2, nu (Lambda_2 + Omega^2)) +
    Omega [[0, 4 nu G12], [-4 G21, 0]]), G12 = U_1^{-1} V_1^{-1} C12 U_2, G21 = U_2^{-1} V_2^{-1}
    C21 U_1 (C = d/dx of the other field's basis at the equation's points): diagonal plus an
    Omega-proportional coupling, so shifted solves
    need only a Schur complement of one block. It is taken on the smaller block (``schur``:
    1 or 2), because its per-point inverse is the largest single cost of the fast path.
    """

    op: FamilyOperator
    lam1: NDArray[np.float64]  # Lambda_1 (k1,)
    lam2: NDArray[np.float64]  # Lambda_2 (k2,)
    u1: NDArray[np.float64]  # c1 = U_1 z1
    u2: NDArray[np.float64]
    left1: NDArray[np.float64]  # U_1^{-1} V_1^{-1}: left eigenvectors y1^T = w1^T left1
    left2: NDArray[np.float64]
    g12: NDArray[np.float64]  # (k1, k2)
    g21: NDArray[np.float64]  # (k2, k1)
    schur: int  # the block (1 or 2) that carries the Schur complement; the other is eliminated
    outer: NDArray[np.float64]  # (k_e, k_s^2): G_se[:, j] (x) G_es[j, :], e eliminated, s Schur

    def right_vectors(self, z: NDArray[np.float64]) -> NDArray[np.float64]:
        """The pencil's right vectors (coefficients c, rows) from modal ones z: c_i = U_i z_i."""
        k1 = self.lam1.size
        return np.hstack([z[:, :k1] @ self.u1.T, z[:, k1:] @ self.u2.T])

    def left_vectors(self, w: NDArray[np.float64]) -> NDArray[np.float64]:
        """The pencil's left vectors (rows) from modal ones w: y_i^T = w_i^T U_i^{-1} V_i^{-1}."""
        k1 = self.lam1.size
        return np.hstack([w[:, :k1] @ self.left1, w[:, k1:] @ self.left2])


@lru_cache(maxsize=64)
def modal_family(n: int, family: str) -> ModalFamily:
    """Diagonalise the uncoupled operators of (n, family) once (see :class:`ModalFamily`)."""
    op = family_operator(n, family)
    b1, b2 = op.bases[0][0], op.bases[1][1]
    lam1, u1 = _real_eig(cast(NDArray[np.float64], -4.0 * np.linalg.solve(b1.value, b1.d2)))
    lam2, u2 = _real_eig(cast(NDArray[np.float64], -4.0 * np.linalg.solve(b2.value, b2.d2)))
    left1 = np.linalg.solve(u1, np.linalg.inv(b1.value))
    left2 = np.linalg.solve(u2, np.linalg.inv(b2.value))
    g12 = left1 @ op.bases[0][1].d1 @ u2
    g21 = left2 @ op.bases[1][0].d1 @ u1
    schur = 2 if lam2.size <= lam1.size else 1
    g_es, g_se = (g12, g21) if schur == 2 else (g21, g12)
    outer = np.einsum("ij,jk->jik", g_se, g_es).reshape(g_es.shape[0], -1)
    return ModalFamily(op, lam1, lam2, u1, u2, left1, left2, g12, g21, schur, outer)


def _real_eig(s: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Eigen-decomposition of a matrix with a real spectrum, ascending."""
    lam, u = np.linalg.eig(s)
    if np.abs(lam.imag).max() > 1e-8 * np.abs(lam).max():
        raise ArithmeticError("second-derivative collocation operator with complex spectrum")
    order = np.argsort(lam.real)
    return lam.real[order], u.real[:, order]


class ModalParts(NamedTuple):
    """K - SHIFT at a batch of points in the blocks of :class:`_ShiftedModal`, before its Schur
    complement is formed: the columns of the eliminated (e) and Schur (s) blocks, r_e (P, k_e) =
    1 / (D_e - SHIFT), the coupling factors a, b (P, 1), d_s (P, k_s) = D_s - SHIFT and the
    shared G_es (k_e, k_s), G_se (k_s, k_e)."""

    elim: slice
    kept: slice
    r_e: NDArray[np.float64]
    a: NDArray[np.float64]
    b: NDArray[np.float64]
    d_s: NDArray[np.float64]
    g_es: NDArray[np.float64]
    g_se: NDArray[np.float64]

    def take(self, idx: NDArray[np.int_]) -> ModalParts:
        """The points `idx` only."""
        return self._replace(r_e=self.r_e[idx], a=self.a[idx], b=self.b[idx],
                             d_s=self.d_s[idx])


def _coefficients(twist: NDArray[np.floating], nu: NDArray[np.floating]) -> NDArray[Any]:
    """:func:`.discretisation.term_coefficients` (points, terms); one point in scalars (Python
    floats, or numpy ``longdouble`` scalars: the same operations, a few us instead of ~20 us
    of per-term array calls, for scalar calls)."""
    if twist.size == 1 and twist.dtype == nu.dtype == np.float64:
        return term_coefficients(float(twist[0]), float(nu[0]))[None]
    if twist.size == 1:
        kind = np.result_type(twist, nu, 1.0).type
        om, nv = kind(twist.reshape(-1)[0]), kind(nu.reshape(-1)[0])
        return np.array([[t.coefficient(om, nv) for t in INST1]], dtype=kind)
    return term_coefficients(twist, nu)


def modal_parts(mf: ModalFamily, twist: NDArray[np.float64], nu: NDArray[np.float64]
                ) -> ModalParts:
    """:class:`ModalParts` of family `mf` at the points (twist, nu)."""
    coef = _coefficients(twist, nu)[:, :, None]  # (P, terms, 1)
    (s1, z1, c1), (s2, z2, c2) = MODAL_TERMS
    d1, d2 = coef[:, z1] - coef[:, s1] * mf.lam1, coef[:, z2] - coef[:, s2] * mf.lam2
    a1, a2 = 2.0 * coef[:, c1], 2.0 * coef[:, c2]  # d/ds = 2 d/dx
    k1 = mf.lam1.size
    if mf.schur == 2:
        return ModalParts(slice(0, k1), slice(k1, None), 1.0 / (d1 - SHIFT), a1, a2,
                          d2 - SHIFT, mf.g12, mf.g21)
    return ModalParts(slice(k1, None), slice(0, k1), 1.0 / (d2 - SHIFT), a2, a1, d1 - SHIFT,
                      mf.g21, mf.g12)


@dataclass(frozen=True)
class _ShiftedModal:
    """K - SHIFT at a batch of points, factorised through a Schur complement.

    In block form K - SHIFT = [[D_e - SHIFT, a G_es], [b G_se, D_s - SHIFT]] with D_e diagonal
    (the eliminated block), so (K - SHIFT)^{-1} needs only the inverse of

        S = D_s - SHIFT - a b G_se (D_e - SHIFT)^{-1} G_es   (one inverse per point).

    Block 1 (omega1) has a = 2 c1_1 (4 nu Omega for ``inst1``) in front of G12, block 2 has
    2 c1_2 (-4 Omega) in front of G21.
    Vectors are rows of one array (points x (k1 + k2)), omega1 block first.

    The per-point inverse of S is the numpy reference's largest single cost
    (``tests/bench/instruction_counts.py --inverse-share`` measures its share); large stacks are
    inverted by the checked 2 x 2-block recursion of :func:`.stacked_inverse.stacked_inverse`,
    small ones by LAPACK (:data:`.tuning.BLOCK_ENTRIES`).
    """

    elim: slice  # columns of the eliminated block
    kept: slice  # columns of the Schur block
    r_e: NDArray[np.float64]  # (P, k_e): 1 / (D_e - SHIFT)
    a: NDArray[np.float64]  # (P, 1)
    b: NDArray[np.float64]  # (P, 1)
    g_es: NDArray[np.float64]  # (k_e, k_s)
    g_se: NDArray[np.float64]  # (k_s, k_e)
    schur_inv: NDArray[np.float64]  # (P, k_s, k_s)

    @classmethod
    def at(cls, mf: ModalFamily, twist: NDArray[np.float64], nu: NDArray[np.float64]
           ) -> _ShiftedModal:
        return cls.from_parts(mf, modal_parts(mf, twist, nu))

    @classmethod
    def from_parts(cls, mf: ModalFamily, pt: ModalParts) -> _ShiftedModal:
        k_s = pt.d_s.shape[1]
        schur = ((-pt.a * pt.b * pt.r_e) @ mf.outer).reshape(-1, k_s, k_s)
        schur[:, np.arange(k_s), np.arange(k_s)] += pt.d_s
        return cls(pt.elim, pt.kept, pt.r_e, pt.a, pt.b, pt.g_es, pt.g_se,
                   stacked_inverse(schur))  # LinAlgError if singular

    def take(self, idx: NDArray[np.int_]) -> _ShiftedModal:
        """The points `idx` only."""
        return _ShiftedModal(self.elim, self.kept, self.r_e[idx], self.a[idx], self.b[idx],
                             self.g_es, self.g_se, self.schur_inv[idx])

    def _assemble(self, z_e: NDArray[np.float64], z_s: NDArray[np.float64],
                  out: NDArray[np.float64] | None = None) -> NDArray[np.float64]:
        if out is None:
            out = np.empty((z_e.shape[0], z_e.shape[1] + z_s.shape[1]))
        out[:, self.elim], out[:, self.kept] = z_e, z_s
        return out

    def solve(self, v: NDArray[np.float64], out: NDArray[np.float64] | None = None
              ) -> NDArray[np.float64]:
        """(K - SHIFT)^{-1} v for each row v (into `out` if given)."""
        u = v[:, self.elim] * self.r_e
        z_s = (self.schur_inv @ (v[:, self.kept] - self.b * (u @ self.g_se.T))[:, :, None]
               )[:, :, 0]
        return self._assemble(u - self.a * (z_s @ self.g_es.T) * self.r_e, z_s, out)

    def solve_transposed(self, v: NDArray[np.float64], out: NDArray[np.float64] | None = None
                         ) -> NDArray[np.float64]:
        """(K - SHIFT)^{-T} v for each row v (its Schur complement is S^T; into `out` if
        given)."""
        u = v[:, self.elim] * self.r_e
        z_s = ((v[:, self.kept] - self.a * (u @ self.g_es))[:, None, :] @ self.schur_inv
               )[:, 0, :]
        return self._assemble(u - self.b * (z_s @ self.g_se) * self.r_e, z_s, out)

    def solve_pair(self, v: NDArray[np.float64]) -> NDArray[np.float64]:
        """((K - SHIFT)^{-1} v[0], (K - SHIFT)^{-T} v[1]) per point, v (2, P, m); as separate
        calls: a stored transpose S^{-T} would double the memory each step reads."""
        out = np.empty(v.shape)
        self.solve(v[0], out[0])
        self.solve_transposed(v[1], out[1])
        return out


@dataclass(frozen=True)
class _DenseShifted:
    """(K - SHIFT)^{-1} and its transpose at a few points as dense matrices, ``pair`` (2, P, m,
    m), inverted by LAPACK (pivoted): the same operator as :class:`_ShiftedModal`, applied in one
    call per step. For a few points numpy's per-call cost, not the arithmetic, decides, and a
    step is then one batched product instead of ~16 calls (:data:`.tuning.DENSE_ENTRIES`)."""

    pair: NDArray[np.float64]

    @classmethod
    def from_parts(cls, pt: ModalParts) -> _DenseShifted:
        points, k_e = pt.r_e.shape
        m = k_e + pt.d_s.shape[1]
        shifted = np.zeros((points, m, m))
        cols = np.arange(m)
        e, s = cols[pt.elim], cols[pt.kept]
        shifted[:, e, e], shifted[:, s, s] = 1.0 / pt.r_e, pt.d_s
        shifted[:, pt.elim, pt.kept] = pt.a[:, :, None] * pt.g_es
        shifted[:, pt.kept, pt.elim] = pt.b[:, :, None] * pt.g_se
        return cls(_inverse_pair(shifted))

    def take(self, idx: NDArray[np.int_]) -> _DenseShifted:
        """The points `idx` only."""
        return _DenseShifted(self.pair[:, idx])

    def solve_pair(self, v: NDArray[np.float64]) -> NDArray[np.float64]:
        """As :meth:`_ShiftedModal.solve_pair`."""
        return np.matmul(self.pair, v[..., None])[..., 0]


def _inverse_pair(mats: NDArray[np.float64]) -> NDArray[np.float64]:
    """(M^{-1}, M^{-T}) stacked, (2, P, m, m), by LAPACK's pivoted LU (``dgetrf``, ``dgetri``
    called directly: numpy.linalg.inv's wrapper costs several times their work at m ~ 20);
    LinAlgError if some M is singular (SHIFT an eigenvalue)."""
    from scipy.linalg.lapack import dgetrf, dgetri

    pair = np.empty((2, *mats.shape))
    for j, mat in enumerate(mats):
        lu, piv, info = dgetrf(mat)
        if info == 0:
            inverse, info = dgetri(lu, piv, overwrite_lu=1)
        if info != 0:
            raise np.linalg.LinAlgError("K - SHIFT is singular at a point")
        pair[0, j], pair[1, j] = inverse, inverse.T
    return pair


def _shifted(mf: ModalFamily, pt: ModalParts) -> _ShiftedModal | _DenseShifted:
    """The numpy reference's (K - SHIFT)^{-1} at the points of `pt`: dense up to
    :data:`.tuning.DENSE_ENTRIES` matrix entries (points m^2), else through the Schur complement."""
    if pt.r_e.shape[0] * (pt.r_e.shape[1] + pt.d_s.shape[1]) ** 2 <= DENSE_ENTRIES:
        return _DenseShifted.from_parts(pt)
    return _ShiftedModal.from_parts(mf, pt)


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
    """The iteration of :func:`lowest_eigenpair` in numpy (the C kernel's ``solve_group``),
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
        conv = converged(rq, bound, rtol, np)
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


def converged(rq, bound, rtol: float, xp=np):
    """The convergence test of the eigenvalue iteration (the kernel's ``solve_group``):
    the first-order error bound is <= rtol |rq| and rq >= SHIFT. `xp` is numpy for arrays,
    :mod:`math` (or anything with ``fabs``) for Python floats.

    >>> converged(10.0, 1e-14, 1e-14, math), converged(5.0, 0.0, 1e-14, math)
    (True, False)
    """
    if xp is np:
        return (bound <= rtol * np.abs(rq)) & (rq >= SHIFT)
    return bound <= rtol * xp.fabs(rq) and rq >= SHIFT


@lru_cache(maxsize=64)
def _start_vector(k: int) -> NDArray[np.float64]:
    """A fixed generic unit start vector (no special structure that could be orthogonal to a
    mode); read-only, as it is cached."""
    v = np.random.default_rng(20240607).standard_normal(k)
    v /= np.linalg.norm(v)
    v.setflags(write=False)
    return v


def pencil_rayleigh_quotient(op: FamilyOperator, twist: NDArray[np.float64],
                              nu: NDArray[np.float64], left: NDArray[np.float64],
                              right: NDArray[np.float64]) -> NDArray[np.float64]:
    """y^T A x / y^T B x per point, with A = sum_i coef_i P_i (:attr:`FamilyOperator.pieces`).

    For |Omega| > LONG_TWIST the Omega^2 terms cancel against the others to ~lambda/Omega^2,
    and the sums are accumulated in extended precision (``np.longdouble``): this halves the
    round-off there (measured at Omega in [40, 100]: 0.39 -> 0.19 eps Omega^2).
    """
    out = np.empty(twist.size)
    big = np.abs(twist) > LONG_TWIST
    for sel, dtype in ((np.flatnonzero(~big), np.float64), (np.flatnonzero(big), np.longdouble)):
        if sel.size:
            out[sel] = _rayleigh_sums(op, twist[sel], nu[sel], left[sel], right[sel], dtype)
    return out


#: The terms of INST1 whose blocks are B's (the own field, order 0): y^T B x is their sum.
_MASS_TERMS = [i for i, t in enumerate(INST1) if t.field == t.equation and t.order == 0]
_MASS_INDEX = np.array(_MASS_TERMS)


@lru_cache(maxsize=128)
def _term_blocks(n: int, family: str, dtype: type) -> tuple:
    """:attr:`FamilyOperator.term_blocks` transposed, in `dtype` (converted once)."""
    return tuple((e, f, idx, np.ascontiguousarray(blocks.astype(dtype).T))
                 for e, f, idx, blocks in family_operator(n, family).term_blocks)


def _rayleigh_sums(op: FamilyOperator, twist: NDArray[np.float64], nu: NDArray[np.float64],
                   left: NDArray[np.float64], right: NDArray[np.float64], dtype: type
                   ) -> NDArray[np.float64]:
    """y^T A x / y^T B x in `dtype` from the products y_e^T P_i x_f of A's nonzero blocks
    (:attr:`FamilyOperator.term_blocks`; a quarter of the work of the full pieces).

    In extended precision the products are the C kernel's double-double ones where it is
    installed (:func:`.modal_kernel.pencil_terms`; this function 0.4-1.6 µs a point at n = 24-56
    with them against 2.8-14 µs with numpy's ``longdouble`` products,
    ``tests/bench/kernel_range.py``), without it for a few points (:data:`.tuning.DENSE_ENTRIES`)
    the split products of :func:`_split_terms` (as accurate, in a few BLAS calls), else numpy's
    ``longdouble`` products; summed in ``dtype``."""
    few = right.shape[0] * right.shape[1] ** 2 <= DENSE_ENTRIES
    if dtype is np.longdouble and (few or modal_kernel.available()):
        hi, lo = (modal_kernel.pencil_terms(*_term_matrices(op.n, op.family), right, left)
                  if modal_kernel.available() else _split_terms(op.n, op.family, right, left))
        terms = hi.astype(dtype) + lo.astype(dtype)
    elif dtype is np.float64 and few:
        # a few points: every term as a full (m, m) matrix, two calls instead of ~4 a block
        pieces = _dense_terms(op.n, op.family)
        px = (right @ pieces).reshape(right.shape[0], len(INST1), -1)
        terms = np.einsum("pj,pij->pi", left, px)
    else:
        k1 = op.sizes[0]
        cols = (slice(0, k1), slice(k1, None))
        x: NDArray[np.floating] = right.astype(dtype)
        y: NDArray[np.floating] = left.astype(dtype)
        terms = np.empty((x.shape[0], len(INST1)), dtype=dtype)
        for e, f, idx, blocks in _term_blocks(op.n, op.family, dtype):
            px = (x[:, cols[f]] @ blocks).reshape(x.shape[0], len(idx), -1)
            terms[:, idx] = np.einsum("pj,pij->pi", y[:, cols[e]], px)
    coef = _coefficients(twist.astype(dtype), nu.astype(dtype))
    return ((coef * terms).sum(axis=1) / terms[:, _MASS_INDEX].sum(axis=1)).astype(np.float64)


@lru_cache(maxsize=128)
def _dense_terms(n: int, family: str) -> NDArray[np.float64]:
    """The terms P_i of :data:`INST1` as full (m, m) matrices, laid out (m, terms m) so that
    x @ it gives every P_i x (for :func:`_rayleigh_sums` at a few points)."""
    op = family_operator(n, family)
    return np.ascontiguousarray(np.swapaxes(op.pieces, 1, 2).transpose(1, 0, 2).reshape(
        op.pieces.shape[1], -1))


def _split_bits(m: int) -> int:
    """Bits kept in the leading part of each factor of :func:`_split_terms`: a sum of m^2
    products of three such parts is exact in double where 3 bits + 2 log2(m) <= 53."""
    return (53 - 2 * math.ceil(math.log2(max(m, 2)))) // 3


def _split(v: NDArray[np.float64], sizes: tuple[int, int], bits: int
           ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """v = v1 + v2 exactly, per row and field (the two column blocks of `sizes`): v1 is v
    rounded to a multiple of 2^(E - bits), with 2^E > the field's max |v| (at most 2^bits such
    units), v2 the rest (|v2| <= 2^(E - bits - 1)): per field, so that a small field (omega2
    at large nu) keeps its own relative accuracy. The rounding is the addition of
    sigma = 1.5 2^(E + 52 - bits), whose binade has that unit as its spacing, and its exact
    subtraction."""
    top = np.maximum.reduceat(np.abs(v), (0, sizes[0]), axis=-1)
    sigma = np.repeat(np.ldexp(0.75, np.frexp(top)[1] + (53 - bits)), sizes, axis=-1)
    v1 = (v + sigma) - sigma
    return v1, v - v1


@lru_cache(maxsize=128)
def _split_pieces(n: int, family: str) -> tuple[NDArray[np.float64], NDArray[np.float64], int]:
    """:func:`_dense_terms` split as P = P1 + P2 exactly, each term's block P1_i rounded to a
    multiple of its own 2^(E_i - bits) (:func:`_split_bits`), and the bits."""
    pieces = _dense_terms(n, family)
    m = pieces.shape[0]
    bits = _split_bits(m)
    blocks = pieces.reshape(m, len(INST1), -1)
    unit = np.ldexp(1.0, np.frexp(np.abs(blocks).max(axis=(0, 2)))[1] - bits)[:, None]
    lead = (np.rint(blocks / unit) * unit).reshape(pieces.shape)
    lead.setflags(write=False)
    return lead, pieces - lead, bits


def _split_terms(n: int, family: str, right: NDArray[np.float64], left: NDArray[np.float64]
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The bilinear forms y^T P_i x of :func:`_rayleigh_sums` as hi + lo (points, terms), to
    double-double accuracy from BLAS products in double (the numpy engine's form of the
    kernel's :func:`.modal_kernel.pencil_terms`): with x = x1 + x2, y = y1 + y2 (per field)
    and P_i = P1_i + P2_i split exactly (:func:`_split`, :func:`_split_pieces`),
    hi = y1^T P1_i x1 is exact in double (P_i couples one field of y to one of x, so every
    product and partial sum is a multiple of one unit, below 2^53 of them), and
    lo = y2^T P_i x + y1^T (P2_i x + P1_i x2), whose parts are 2^-bits of the whole, carries
    an error within 4 2^-bits m eps sum |y| |P_i| |x| (bits = 13-14 at n = 24-64: below the
    ~m 2^-64 sum |y| |P_i| |x| of ``longdouble`` sums). ``tests/test_modal_kernel.py`` compares
    the terms and the quotient with 50-digit sums."""
    lead, rest, bits = _split_pieces(n, family)
    points, m = right.shape
    (x1, y1), (x2, y2) = (part.reshape(2, points, m) for part in
                          _split(np.concatenate((right, left)), family_operator(n, family).sizes,
                                 bits))
    # P1 x1, P1 x, P1 x2 (rows: terms m) in one product (concatenate: cheaper than stack)
    prod = (np.concatenate((x1, right, x2)) @ lead).reshape(3, points, -1)
    px2 = right @ rest
    shape = (points, len(INST1), m)
    # (P1 x1, P2 x + P1 x2) . y1 in one product, a stack of (terms, m) @ (m, 1) per point
    by_y1 = (np.concatenate((prod[0], px2 + prod[2])).reshape(2, *shape)
             @ y1[:, :, None])[..., 0]
    lo = by_y1[1] + ((prod[1] + px2).reshape(shape) @ y2[:, :, None])[..., 0]
    return by_y1[0], lo


@lru_cache(maxsize=128)
def _term_matrices(n: int, family: str) -> tuple[NDArray[np.int32], NDArray[np.float64]]:
    """Each term of INST1 as a block of the pencil, in the layout of
    :func:`.modal_kernel.pencil_terms`: (row offset, rows, column offset, columns, data
    offset) per term, in INST1's order, and the blocks' matrices concatenated."""
    op = family_operator(n, family)
    offset = (0, op.sizes[0])
    shape = np.zeros((len(INST1), 5), dtype=np.int32)
    mats, start = [], 0
    for e, f, idx, blocks in op.term_blocks:
        rows = blocks.shape[0] // len(idx)
        for i, term in enumerate(idx):
            block = blocks[i * rows:(i + 1) * rows]
            shape[term] = (offset[e], rows, offset[f], block.shape[1], start)
            mats.append(block.ravel())
            start += block.size
    return shape, np.concatenate(mats)


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


def solve_family_eig(n: int, family: str, twist: NDArray[np.float64], nu: NDArray[np.float64]
                      ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """:func:`solve_family` by the full ``eig`` of A^{-1} B and the rule (the reference path).

    Unlike the iteration it needs no gap below the family's next eigenvalue (but its round-off
    is larger: the inverse pencil carries cond(A) ~ n^4)."""
    op = family_operator(n, family)
    a, b = op.pencil(twist, nu)
    # B broadcast to A's stack: numpy < 2.0 would read a (m, m) right-hand side against a
    # (k, m, m) stack as a stack of m-vectors, not as one right-hand matrix per system
    theta, vec = physical_eig(cast(NDArray[np.float64],
                                   np.linalg.solve(a, np.broadcast_to(b, a.shape))))
    valid = np.isfinite(theta) & (theta > 0)
    lam = np.where(valid, 1.0 / np.where(valid, theta, 1.0), np.inf)
    return lam, np.where(valid, mode_tails(op, vec), np.inf), vec


#: The family's lowest eigenvalue counts as isolated, so that the iteration's convergence test
#: holds, if the next physical one is at least this far above it, relatively: the test passes a
#: mixed vector once the gap is below ~sqrt(rtol / lambda) (2e-8 at POWER_RTOL); a margin of 50.
ISOLATION_GAP = 1e-6


def lowest_gap(n: int, family: str, twist: float, nu: float) -> tuple[float, float]:
    """(lambda_1, (lambda_2 - lambda_1) / lambda_1) of one point: the family's two lowest
    physical eigenvalues by the full ``eig`` of A^{-1} B and the rule (inf gap if only one)."""
    a, b = family_operator(n, family).pencil(np.array([twist]), np.array([nu]))
    theta = np.linalg.eigvals(np.linalg.solve(a[0], b))
    ok = (np.abs(theta.imag) <= IMAG_REL * np.abs(theta)) & (theta.real > 0)
    lam = np.sort(1.0 / theta.real[ok])
    if not lam.size:
        return math.inf, math.inf
    return float(lam[0]), float((lam[1] - lam[0]) / lam[0]) if lam.size > 1 else math.inf


class PointsSolution(NamedTuple):
    """Both families at points of one degree: lambda = pi^2 p and the mode's tail, each
    (2, points) (symmetric first; the antisymmetric tail inf where that family was only shown
    above the symmetric one), and True where the C kernel computed both families."""

    lam: NDArray[np.float64]
    tails: NDArray[np.float64]
    by_kernel: NDArray[np.bool_]


def solve_points(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
                 ) -> PointsSolution:
    """Both families' lowest eigenvalue and tail at flat arrays of points of degree n, by the
    engine: the C kernel one lane at a time up to :func:`.tuning.few_points_limit` points
    (``modal_points``), else 32 lanes a family (:func:`solve_family`); without the kernel the
    numpy reference (:func:`solve_family`; one point up to DENSE_ENTRIES matrix entries by its
    one-point form of ``modal_points``, :func:`_numpy_point`, so that a scalar call and a
    one-element array get the same bits). The symmetric family first, the antisymmetric one
    then only until it is shown above (1 + CLOSE_REL) times the symmetric eigenvalue. Points
    the one-lane forms do not accept are solved by :func:`solve_family`."""
    lam, tails = np.empty((2, twist.size)), np.empty((2, twist.size))
    by_kernel = np.zeros(twist.size, dtype=bool)
    rest = np.arange(twist.size)
    if twist.size == 1 and not modal_kernel.available() and (n - 1) ** 2 <= DENSE_ENTRIES:
        lean = _numpy_point(n, float(twist[0]), float(nu[0]), rtol)
        if lean is not None:
            return PointsSolution(np.array(lean[0])[:, None], np.array(lean[1])[:, None],
                                  by_kernel)
    elif modal_kernel.available() and twist.size <= few_points_limit(n):
        lam1, tails1, status = _solve_lanes(n, twist, nu, rtol)
        lam[:], tails[:] = lam1.T, tails1.T
        by_kernel = _accepted(status)
        rest = np.flatnonzero(~by_kernel)
        if not rest.size:
            return PointsSolution(lam, tails, by_kernel)
    used = np.empty((2, rest.size), dtype=bool)
    tw, nv = twist[rest], nu[rest]
    lam[0, rest], tails[0, rest], _ = solve_family(n, FAMILIES[0], tw, nv, rtol=rtol,
                                                   kernel_out=used[0])
    lam[1, rest], tails[1, rest], _ = solve_family(n, FAMILIES[1], tw, nv, rtol=rtol,
                                                   ceiling=lam[0, rest] * (1 + CLOSE_REL),
                                                   kernel_out=used[1])
    by_kernel[rest] = used.all(axis=0)
    return PointsSolution(lam, tails, by_kernel)


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
        if _accepted(status)[0]:
            return lam1[0].tolist(), tails1[0].tolist(), True
    sol = solve_points(n, np.array([twist]), np.array([nu]), rtol)
    return sol.lam[:, 0].tolist(), sol.tails[:, 0].tolist(), bool(sol.by_kernel[0])


class _PointFamily(NamedTuple):
    """A family at degree n laid out for the numpy reference's one-point path
    (:func:`_numpy_point`): the modal unknowns in the order (eliminated block, Schur block) of
    :class:`ModalParts`, as the kernel's ``family_point`` holds them."""

    op: FamilyOperator
    lam_e: NDArray[np.float64]  # Lambda of the eliminated block
    lam_s: NDArray[np.float64]  # Lambda of the Schur block
    equations: tuple[int, int]  # the equations (0: omega1) of the e and s blocks
    g_es: NDArray[np.float64]
    g_se: NDArray[np.float64]
    start: NDArray[np.float64]  # the start vector, right and left, (2 m,)
    right: NDArray[np.float64]  # c = right @ z
    left: NDArray[np.float64]  # y = w @ left


@lru_cache(maxsize=64)
def _point_family(n: int, family: str) -> _PointFamily:
    """:class:`_PointFamily` of (n, family), built once from :func:`modal_family`."""
    mf = modal_family(n, family)
    k1, m = mf.lam1.size, mf.lam1.size + mf.lam2.size
    order = np.arange(m) if mf.schur == 2 else np.r_[np.arange(k1, m), np.arange(k1)]
    g_es, g_se = (mf.g12, mf.g21) if mf.schur == 2 else (mf.g21, mf.g12)
    right, left = np.zeros((m, m)), np.zeros((m, m))
    right[:k1, :k1], right[k1:, k1:] = mf.u1, mf.u2
    left[:k1, :k1], left[k1:, k1:] = mf.left1, mf.left2
    start = _start_vector(m)[order]
    lams = (mf.lam1, mf.lam2) if mf.schur == 2 else (mf.lam2, mf.lam1)
    return _PointFamily(mf.op, lams[0], lams[1], (0, 1) if mf.schur == 2 else (1, 0),
                        g_es, g_se, np.concatenate((start, start)),
                        np.ascontiguousarray(right[:, order]), np.ascontiguousarray(left[order]))


def _point_inverse(pf: _PointFamily, coef: list[float]) -> NDArray[np.float64] | None:
    """((K - SHIFT)^{-1}, (K - SHIFT)^{-T}) of one point as one block-diagonal (2 m, 2 m)
    matrix, so that a step of right and left vectors is one product. K - SHIFT =
    [[D_e - SHIFT, a G_es], [b G_se, D_s - SHIFT]] (:class:`_ShiftedModal`) is inverted by
    LAPACK's pivoted LU, whole up to degree :data:`.tuning.POINT_SCHUR_DEGREE` (fewer numpy
    calls), above it through its Schur complement S (a quarter of the LU's work):

        (K - SHIFT)^{-1} = [[R + a b Y G_se R, -a Y], [-b S^{-1} G_se R, S^{-1}]],
        R = (D_e - SHIFT)^{-1},  Y = R G_es S^{-1}.

    None where the matrix inverted is singular (SHIFT an eigenvalue)."""
    from scipy.linalg.lapack import dgetrf, dgetri

    (s1, z1, c1), (s2, z2, c2) = MODAL_TERMS
    own2, own0, cpl = (coef[s1], coef[s2]), (coef[z1], coef[z2]), (coef[c1], coef[c2])
    qe, qs = pf.equations
    a, b = 2.0 * cpl[qe], 2.0 * cpl[qs]  # d/ds = 2 d/dx
    d_e = own0[qe] - own2[qe] * pf.lam_e - SHIFT
    d_s = own0[qs] - own2[qs] * pf.lam_s - SHIFT
    k_e, k_s = pf.g_es.shape
    m = k_e + k_s
    if pf.op.n <= POINT_SCHUR_DEGREE:
        shifted = np.zeros((m, m))
        shifted[:k_e, k_e:], shifted[k_e:, :k_e] = a * pf.g_es, b * pf.g_se
        shifted.flat[::m + 1] = np.concatenate((d_e, d_s))
        lu, piv, info = dgetrf(shifted, overwrite_a=1)
        if info == 0:
            inverse, info = dgetri(lu, piv, overwrite_lu=1)
        if info != 0:
            return None
        pair = np.zeros((2 * m, 2 * m))
        pair[:m, :m], pair[m:, m:] = inverse, inverse.T
        return pair
    r = 1.0 / d_e
    g_r = pf.g_se * r  # G_se R
    schur = (-a * b) * (g_r @ pf.g_es)
    schur.flat[::k_s + 1] += d_s
    lu, piv, info = dgetrf(schur, overwrite_a=1)
    if info == 0:
        schur_inv, info = dgetri(lu, piv, overwrite_lu=1)
    if info != 0:
        return None
    pair = np.zeros((2 * m, 2 * m))
    y = (r[:, None] * pf.g_es) @ schur_inv
    pair[:k_e, :k_e] = (a * b) * (y @ g_r)
    pair.flat[:(2 * m + 1) * k_e:2 * m + 1] += r
    pair[:k_e, k_e:m] = -a * y
    pair[k_e:m, :k_e] = -b * (schur_inv @ g_r)
    pair[k_e:m, k_e:m] = schur_inv
    pair[m:, m:] = pair[:m, :m].T
    return pair


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
        conv = converged(rq, bound, rtol, math)
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
    """One family at one point by the numpy reference, as the kernel's ``family_point``:
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
    until shown above (1 + CLOSE_REL) times it, its first test at step <= 4; None where a
    family is not accepted (:func:`solve_points` then decides, with the full ``eig``)."""
    coef = term_coefficients(twist, nu).tolist()
    ext = bool(_extended(twist, n, rtol))
    first = first_check(rtol, False)
    lam0, tail0, status0 = _point_family_solve(n, FAMILIES[0], coef, ext, twist, nu, rtol, None,
                                               first)
    if status0 != modal_kernel.CONVERGED:
        return None
    lam1, tail1, status1 = _point_family_solve(n, FAMILIES[1], coef, ext, twist, nu, rtol,
                                               lam0 * (1 + CLOSE_REL), min(first, 4))
    if status1 not in (modal_kernel.CONVERGED, modal_kernel.ABOVE):
        return None
    return [lam0, lam1], [tail0, tail1]


def _solve_lanes(n: int, twist: NDArray[np.float64], nu: NDArray[np.float64], rtol: float
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int32]]:
    """lambda, tails and status (points, 2) of both families by the C kernel one point at a
    time (``modal_points``: the 32-lane iteration on one lane; the antisymmetric family stopped
    where shown above the symmetric one, its tail then inf). At |Omega| > LONG_TWIST and tight
    tol the pencil's quotient is summed in double-double, from the coefficients in extended
    precision (as :func:`pencil_rayleigh_quotient`, which sums in long double)."""
    loose, big = loose_quotient(rtol, n), _extended(twist, n, rtol)
    lam, tails = np.empty((twist.size, 2)), np.empty((twist.size, 2))
    status = np.empty((twist.size, 2), dtype=np.int32)
    for sel, dtype in ((np.flatnonzero(~big), float), (np.flatnonzero(big), np.longdouble)):
        if sel.size:
            coef = term_coefficients(twist[sel].astype(dtype), nu[sel].astype(dtype))
            lam[sel], tails[sel], status[sel] = _kernel_points(n, coef, rtol, loose)
    return lam, tails, status


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
