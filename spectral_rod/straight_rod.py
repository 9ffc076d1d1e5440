r"""Critical load of a hinged, spontaneously twisted straight rod by Chebyshev collocation.

The physics (paper, section "Stability of a rectilinear rod", Eq. ``inst1``)
-----------------------------------------------------------------------------
With s/L in [0, 1], the total twist angle Omega = omega30 L, nu = A2/A1 = I2/I1 >= 1 and the
load lambda = P L^2 / A1 = pi^2 p*, Eq. ``inst1`` for the curvatures omega1, omega2 reads

    -omega1'' + Omega^2 omega1 + 2 nu Omega omega2'          = lambda omega1
    -nu omega2'' + nu Omega^2 omega2 - 2 Omega omega1'       = lambda omega2

Hinged ends: x1 = x2 = 0 and x1'' = x2'' = 0 at s = 0, L. Since x'' is omega rotated by the
twist angle (the paper's geometric relations), x'' = 0 <=> omega1 = omega2 = 0. The conditions
x = 0 are then implied: moment balance of the rod between an end and s, with the end moments
zero, gives A1 omega1 = -P xi and A2 omega2 = -P eta, where (xi, eta) are the displacement
components along (u0, v0); omega = 0 at an end is therefore x = 0 there, and conversely any
solution of ``inst1`` with omega = 0 at both ends gives a centreline with x = x'' = 0 at both ends
(see :func:`buckling_mode`, which integrates x'' = R(Omega s) omega and checks this). So:

    hinged ends  <=>  omega1 = omega2 = 0 at s = 0 and s = L.

Multiplied by A1 and A2 the equations form a self-adjoint, positive definite pencil, so all
eigenvalues are real and positive; the Rayleigh quotient of the energy gives the rigorous
bounds 1 <= p* <= (1 + nu)/2 (Wirtinger's inequality below, planar trial modes above).

Discretisation
--------------
Reflection s -> 1 - s maps solutions to solutions with (omega1, omega2)(s) -> (omega1, -omega2)
(1 - s), so every mode is *symmetric* (omega1 even, omega2 odd about s = 1/2; the Euler mode's
family) or *antisymmetric* (omega1 odd, omega2 even). Each family is discretised separately
in the parity integration bases of :mod:`spectral_rod.chebyshev` (degree n; n/2 and n/2 - 1
unknowns per field), which gives a generalised eigenproblem A c = lambda B c with square B
(the collocation values of the basis); all its matrices are O(1), so round-off does not grow
like n^4 as it does with differentiation matrices. The reference solution of the discrete
problem is the full ``eig`` of the inverse pencil A^{-1} B (theta = 1/lambda).

Fast solution (issue 5): only the lowest eigenvalue is needed and it is >= pi^2. The
uncoupled operators -d^2/ds^2 of each field are diagonalised once per degree
(:class:`ModalFamily`); in that basis the family is K z = lambda z with K diagonal plus an
Omega-proportional coupling, so K - SHIFT (SHIFT = 0.95 pi^2) is inverted through a Schur
complement of half the size, for all points of a degree at once. Shift-and-invert iteration
on right and left vectors (:func:`lowest_eigenpair`, contraction 0.01-0.2 per step on
Figure 1's range) gives the eigenvectors, and the eigenvalue is the two-sided Rayleigh
quotient of the O(1) pencil (A, B) itself (error = product of the two vectors' errors).

Choosing the physical eigenvalue (the rule)
-------------------------------------------
The continuous spectrum is real and >= pi^2. Collocation adds spurious eigenvalues that are
complex or very large (theta near 0). The rule: from each family keep theta with
|Im theta| <= 1e-8 |theta| and Re theta > 0 and take the largest (the smallest lambda); p* is
the smaller of the two families. The fast path returns the eigenvalue nearest above SHIFT;
as every physical eigenvalue is >= pi^2 > SHIFT this is the rule's choice unless a spurious
eigenvalue is nearer to SHIFT, in which case the iteration does not converge to a real value
>= SHIFT and the full ``eig`` with the rule decides (the two are compared on a grid in
``tests/test_accuracy_control.py``). The choice is accepted only if the error estimate from
the mode's Chebyshev coefficients (:func:`error_estimate`; a spurious mode is unresolved by
construction) meets the tolerance; otherwise the resolution is increased or the result is
flagged as not converged.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np
import numpy.polynomial.chebyshev as C
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import (
    check_nu,
    check_resolution,
    check_tol,
    check_twist,
    real_array,
)
from spectral_rod.chebyshev import ParityBasis, parity_basis

FAMILIES = ("symmetric", "antisymmetric")
N_MIN, N_MAX = 8, 512
#: Eigenvalues with |Im| above this fraction of |lambda| are complex, i.e. not physical.
IMAG_REL = 1.0e-8
EPS = float(np.finfo(float).eps)
#: Error model of :func:`error_estimate` (calibrated against the mpmath reference).
ERR_LINEAR, ERR_QUADRATIC, ROUNDOFF_TWIST = 5.0e-4, 200.0, 0.3
#: Shift of the inverse iteration: below every physical eigenvalue (lambda >= pi^2, p* >= 1).
SHIFT = 0.95 * math.pi**2
#: Inverse iteration: first-order error bound of lambda accepted (relative), and step cap.
POWER_RTOL, POWER_STEPS, FIRST_CHECK = 1.0e-15, 40, 6
#: Above this |Omega| the final Rayleigh quotient is accumulated in extended precision.
LONG_TWIST = 20.0
#: Largest product handed to BLAS in one call (see :func:`_rows_matmul`).
BLAS_BLOCK = 1 << 17
#: Up to this many points per degree and family, and degree, the full eig is cheaper than the
#: iteration (measured: 0.7 vs 1.3 ms for one point at n = 20; the other way round at n = 94).
SMALL_BATCH, SMALL_DEGREE = 4, 40


def _rows_matmul(a: NDArray[np.floating], b: NDArray[np.floating]) -> NDArray[np.floating]:
    """a @ b for a tall a (points x k) and a small b (k x m), as a stack of small products.

    One large product would be handed to the multithreaded BLAS; its worker threads then spin
    between calls and, on a machine whose cores are busy, slow every later call down (measured
    2-6x on the Figure 1 sweep with one core loaded). Blocks of at most BLAS_BLOCK
    multiply-adds stay on the calling thread.
    """
    p, k = a.shape
    most = max(1, BLAS_BLOCK // max(1, k * b.shape[1]))
    if p <= most:
        return a @ b
    blocks = -(-p // most)
    rows = -(-p // blocks)
    pad = blocks * rows - p
    if pad:
        a = np.concatenate([a, np.zeros((pad, k), dtype=a.dtype)])
    return (a.reshape(-1, rows, k) @ b).reshape(-1, b.shape[1])[:p]


class ConvergenceWarning(RuntimeWarning):
    """The requested tolerance was not met (resolution cap or round-off)."""


@dataclass(frozen=True)
class FamilyOperator:
    """The collocation pencil A(Omega, nu) c = lambda B c of one parity family at degree n.

    c are the Chebyshev coefficients of (omega1'', omega2'') in the integration bases of
    :mod:`spectral_rod.chebyshev` (omega1 block first); with d/ds = 2 d/dx,

        A = [[-4 D2_1 + Omega^2 V_1,   4 nu Omega D1_2   ],
             [-4 Omega D1_1,           nu (-4 D2_2 + Omega^2 V_2)]],   B = diag(V_1, V_2),

    where V, D1, D2 are values and x-derivatives of the bases at the equations' points.
    """

    n: int
    family: str
    basis1: ParityBasis  # omega1's basis at equation-1 points
    basis2: ParityBasis  # omega2's basis at equation-2 points
    coupling12: NDArray[np.float64]  # d/dx of omega2's basis at equation-1 points
    coupling21: NDArray[np.float64]  # d/dx of omega1's basis at equation-2 points

    @property
    def sizes(self) -> tuple[int, int]:
        return self.basis1.value.shape[1], self.basis2.value.shape[1]

    @cached_property
    def pieces(self) -> NDArray[np.float64]:
        """A = sum_i coef_i P_i with coef = (1, Omega^2, nu, nu Omega^2, nu Omega, Omega):
        the six constant matrices P_i, shape (6, m, m)."""
        k1, k2 = self.sizes
        b1, b2 = self.basis1, self.basis2
        p = np.zeros((6, k1 + k2, k1 + k2))
        p[0, :k1, :k1] = -4.0 * b1.d2
        p[1, :k1, :k1] = b1.value
        p[2, k1:, k1:] = -4.0 * b2.d2
        p[3, k1:, k1:] = b2.value
        p[4, :k1, k1:] = 4.0 * self.coupling12
        p[5, k1:, :k1] = -4.0 * self.coupling21
        return p

    @cached_property
    def mass(self) -> NDArray[np.float64]:
        """B = diag(V_1, V_2), shape (m, m)."""
        k1, k2 = self.sizes
        b = np.zeros((k1 + k2, k1 + k2))
        b[:k1, :k1] = self.basis1.value
        b[k1:, k1:] = self.basis2.value
        return b

    def pencil(self, twist_angle: ArrayLike, nu: ArrayLike
               ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """A for broadcast arrays `twist_angle`, `nu` (shape (..., m, m)), and B (m, m)."""
        om, nu = np.broadcast_arrays(np.asarray(twist_angle, dtype=float),
                                     np.asarray(nu, dtype=float))
        coef = np.stack([np.ones_like(om), om**2, nu, nu * om**2, nu * om, om], axis=-1)
        m = self.mass.shape[0]
        a = (coef.reshape(-1, 6) @ self.pieces.reshape(6, m * m)).reshape(*om.shape, m, m)
        return a, self.mass

    def split(self, c: NDArray[np.generic]) -> tuple[NDArray[np.generic], NDArray[np.generic]]:
        """Chebyshev coefficients (in x) of (omega1, omega2) from an eigenvector."""
        k1 = self.sizes[0]
        return (self.basis1.chebyshev_coefficients(c[:k1]),
                self.basis2.chebyshev_coefficients(c[k1:]))


@lru_cache(maxsize=128)
def family_operator(n: int, family: str) -> FamilyOperator:
    """Assemble the (n, family) pieces once (they do not depend on Omega or nu)."""
    if family == "symmetric":  # omega1 even: equation 1 at all half points; omega2 odd
        p1, pts1, p2, pts2 = 0, "all", 1, "positive"
    elif family == "antisymmetric":  # omega1 odd, omega2 even
        p1, pts1, p2, pts2 = 1, "positive", 0, "all"
    else:
        raise ValueError(f"family must be one of {FAMILIES}, got {family!r}")
    return FamilyOperator(
        n=n, family=family,
        basis1=parity_basis(n, p1, pts1), basis2=parity_basis(n, p2, pts2),
        coupling12=parity_basis(n, p2, pts1).d1, coupling21=parity_basis(n, p1, pts2).d1)


@dataclass(frozen=True)
class CriticalLoad:
    """Result of :func:`critical_load` with ``full_output=True`` (arrays broadcast like input).

    p_star: P_cr / (pi^2 A1 / L^2); n: Chebyshev degree used; error_estimate: estimated relative
    error of p_star (:func:`error_estimate`: calibrated model of the buckling mode's Chebyshev
    tail plus the round-off floor; measured to bound the actual error); family: 'symmetric'
    (omega1 even about the mid-point) or 'antisymmetric'; converged: error_estimate <= tol.
    """

    p_star: NDArray[np.float64]
    n: NDArray[np.int_]
    error_estimate: NDArray[np.float64]
    family: NDArray[np.str_]
    converged: NDArray[np.bool_]
    tol: float


def initial_degree(twist_angle: NDArray[np.float64], nu: NDArray[np.float64],
                   tol: float) -> NDArray[np.int_]:
    """A priori Chebyshev degree for relative accuracy `tol` (fitted, see below).

    The critical mode is a sum of cos/sin(beta_k s) with beta_k <= sqrt(X_+) ~ |Omega| + pi
    (:func:`critical_wavenumbers`); on x = 2 s - 1 that is frequency k ~ |Omega| / 2, which
    Chebyshev series resolve from degree ~ k on, with a transition layer ~ k^(1/3) wide. With
    L = log10(1/tol),

        n0 = |Omega|/2 + 3.5 + 0.5 L + 1.3 (1 + |Omega|)^(1/3) sqrt(L)   (rounded up to even)

    is the smallest degree whose :func:`error_estimate` meets `tol`, fitted on Omega in
    [0, 300], nu in [1, 100], tol in [1e-12, 1e-4] (exact or 2 above in 90 % of the cases, 2-4
    below in 3 of 153; the a-posteriori check then raises the degree). ``nu`` does not enter:
    the needed degree varies by at most 2 over nu in [1, 100].
    """
    om = np.abs(np.asarray(twist_angle, dtype=float))
    big_l = -math.log10(tol)
    x = om / 2 + 3.5 + 0.5 * big_l + 1.3 * np.cbrt(1.0 + om) * math.sqrt(big_l)
    return np.clip(2 * np.ceil(x / 2).astype(int), N_MIN, N_MAX) + 0 * np.asarray(nu, int)


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
    return np.maximum(ERR_LINEAR * t, ERR_QUADRATIC * t**2) + roundoff_floor(om)


def roundoff_floor(twist_angle: ArrayLike) -> NDArray[np.float64]:
    """Round-off part of :func:`error_estimate`: eps (32 + 0.3 Omega^2), measured (see there)."""
    om = np.asarray(twist_angle, dtype=float)
    return EPS * (32.0 + ROUNDOFF_TWIST * om**2)


def _lowest_physical(theta: NDArray[np.complex128]) -> NDArray[np.int_]:
    """Index of the largest real positive theta = 1/lambda in each row (the rule above)."""
    ok = (np.abs(theta.imag) <= IMAG_REL * np.abs(theta)) & (theta.real > 0)
    return np.argmax(np.where(ok, theta.real, -np.inf), axis=-1)


def _physical_eig(m: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
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

        K z = lambda z,   K = diag(Lambda_1 + Omega^2, nu (Lambda_2 + Omega^2))
                              + Omega [[0, 4 nu G12], [-4 G21, 0]],

    G12 = U_1^{-1} V_1^{-1} C12 U_2, G21 = U_2^{-1} V_2^{-1} C21 U_1 (C = the coupling blocks of
    :class:`FamilyOperator`): diagonal plus an Omega-proportional coupling, so shifted solves
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


@lru_cache(maxsize=64)
def modal_family(n: int, family: str) -> ModalFamily:
    """Diagonalise the uncoupled operators of (n, family) once (see :class:`ModalFamily`)."""
    op = family_operator(n, family)
    b1, b2 = op.basis1, op.basis2
    lam1, u1 = _real_eig(-4.0 * np.linalg.solve(b1.value, b1.d2))
    lam2, u2 = _real_eig(-4.0 * np.linalg.solve(b2.value, b2.d2))
    left1 = np.linalg.solve(u1, np.linalg.inv(b1.value))
    left2 = np.linalg.solve(u2, np.linalg.inv(b2.value))
    g12 = left1 @ op.coupling12 @ u2
    g21 = left2 @ op.coupling21 @ u1
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


@dataclass(frozen=True)
class _ShiftedModal:
    """K - SHIFT at a batch of points, factorised through a Schur complement.

    In block form K - SHIFT = [[D_e - SHIFT, a G_es], [b G_se, D_s - SHIFT]] with D_e diagonal
    (the eliminated block), so (K - SHIFT)^{-1} needs only the inverse of

        S = D_s - SHIFT - a b G_se (D_e - SHIFT)^{-1} G_es   (one LAPACK inverse per point).

    Block 1 (omega1) has a = 4 nu Omega in front of G12, block 2 has -4 Omega in front of G21.
    Vectors are rows of one array (points x (k1 + k2)), omega1 block first.
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
        om, nu = twist[:, None], nu[:, None]
        d1, d2 = mf.lam1 + om**2, nu * (mf.lam2 + om**2)
        a1, a2 = 4.0 * nu * om, -4.0 * om
        k1 = mf.lam1.size
        if mf.schur == 2:
            elim, kept, d_e, d_s, a, b, g_es, g_se = (slice(0, k1), slice(k1, None), d1, d2,
                                                      a1, a2, mf.g12, mf.g21)
        else:
            elim, kept, d_e, d_s, a, b, g_es, g_se = (slice(k1, None), slice(0, k1), d2, d1,
                                                      a2, a1, mf.g21, mf.g12)
        r_e = 1.0 / (d_e - SHIFT)
        k_s = d_s.shape[1]
        schur = _rows_matmul(-a * b * r_e, mf.outer).reshape(-1, k_s, k_s)
        schur[:, np.arange(k_s), np.arange(k_s)] += d_s - SHIFT
        return cls(elim, kept, r_e, a, b, g_es, g_se,
                   np.linalg.inv(schur))  # LinAlgError if singular

    def take(self, idx: NDArray[np.int_]) -> _ShiftedModal:
        """The points `idx` only."""
        return _ShiftedModal(self.elim, self.kept, self.r_e[idx], self.a[idx], self.b[idx],
                             self.g_es, self.g_se, self.schur_inv[idx])

    def _assemble(self, z_e: NDArray[np.float64], z_s: NDArray[np.float64]
                  ) -> NDArray[np.float64]:
        out = np.empty((z_e.shape[0], z_e.shape[1] + z_s.shape[1]))
        out[:, self.elim], out[:, self.kept] = z_e, z_s
        return out

    def solve(self, v: NDArray[np.float64]) -> NDArray[np.float64]:
        """(K - SHIFT)^{-1} v for each row v."""
        u = v[:, self.elim] * self.r_e
        z_s = np.matvec(self.schur_inv, v[:, self.kept] - self.b * _rows_matmul(u, self.g_se.T))
        return self._assemble(u - self.a * _rows_matmul(z_s, self.g_es.T) * self.r_e, z_s)

    def solve_transposed(self, v: NDArray[np.float64]) -> NDArray[np.float64]:
        """(K - SHIFT)^{-T} v for each row v (its Schur complement is S^T)."""
        u = v[:, self.elim] * self.r_e
        z_s = np.vecmat(v[:, self.kept] - self.a * _rows_matmul(u, self.g_es), self.schur_inv)
        return self._assemble(u - self.b * _rows_matmul(z_s, self.g_se) * self.r_e, z_s)


def _unit_rows(v: NDArray[np.float64]) -> NDArray[np.float64]:
    """1 / |v| per row, as a column."""
    return 1.0 / np.sqrt(np.vecdot(v, v))[:, None]


def lowest_eigenpair(mf: ModalFamily, twist: NDArray[np.float64], nu: NDArray[np.float64],
                     rtol: float = POWER_RTOL, ceiling: NDArray[np.float64] | None = None,
                     max_steps: int = POWER_STEPS
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
    """
    sk = _ShiftedModal.at(mf, twist, nu)
    start = _start_vector(mf.lam1.size + mf.lam2.size)
    x = np.broadcast_to(start / np.linalg.norm(start), (twist.size, start.size))
    y = x
    lam = np.full(twist.size, np.nan)
    vec = np.zeros((twist.size, start.size))
    left = np.zeros_like(vec)
    ok = np.zeros(twist.size, dtype=bool)
    above = np.zeros(twist.size, dtype=bool)
    active = np.arange(twist.size)
    for step in range(1, max_steps + 1):
        # each step scales by <= ~1/(0.05 pi^2) and >= ~1/lambda_max: normalising at the
        # checks (every 2 steps) keeps the vectors far from overflow and underflow
        x_prev, y_prev = x, y
        x, y = sk.solve(x), sk.solve_transposed(y)
        if step < (FIRST_CHECK if ceiling is None else 4) or step % 2:
            continue
        sx, sy = _unit_rows(x), _unit_rows(y)
        x, y = x * sx, y * sy
        kx, ky = SHIFT * x + x_prev * sx, SHIFT * y + y_prev * sy  # K x, K^T y
        yx = np.vecdot(y, x)
        rq = np.vecdot(y, kx) / yx
        rx, ry = kx - rq[:, None] * x, ky - rq[:, None] * y
        bound = np.sqrt(np.vecdot(rx, rx) * np.vecdot(ry, ry)) / np.abs(yx)
        conv = (bound <= rtol * np.abs(rq)) & (rq >= SHIFT)
        high = np.zeros_like(conv) if ceiling is None else \
            ~conv & (rq - 100.0 * bound > ceiling[active])
        done = conv | high
        if step + 2 > max_steps:
            done[:] = True
        fin = active[done]
        lam[fin], ok[fin], above[fin] = rq[done], conv[done], high[done]
        vec[fin], left[fin] = x[done], y[done]
        if done.all():
            break
        keep = np.flatnonzero(~done)
        active = active[keep]
        sk = sk.take(keep)
        x, y = x[keep], y[keep]
    return lam, vec, left, ok, above


@lru_cache(maxsize=64)
def _start_vector(k: int) -> NDArray[np.float64]:
    """A fixed generic start vector (no special structure that could be orthogonal to a mode)."""
    return np.random.default_rng(20240607).standard_normal(k)


def mode_tails(op: FamilyOperator, vectors: NDArray[np.float64]) -> NDArray[np.float64]:
    """Coefficient tail (:func:`spectral_rod.chebyshev.tail`) of each mode (omega1, omega2),
    the larger of the two fields' tails, each relative to the larger field's maximum.

    A field that vanishes (omega2 at zero twist) has no meaningful tail of its own.
    """
    k1 = op.sizes[0]
    c1 = _rows_matmul(vectors[:, :k1], op.basis1.coefficients.T)  # (P, n + 1) Chebyshev
    c2 = _rows_matmul(vectors[:, k1:], op.basis2.coefficients.T)
    a1 = np.abs(c1[:, op.basis1.parity::2])
    a2 = np.abs(c2[:, op.basis2.parity::2])
    scale = np.maximum(a1.max(axis=1), a2.max(axis=1))
    last = np.maximum(a1[:, -2:].max(axis=1), a2[:, -2:].max(axis=1))
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(scale > 0, last / scale, np.inf)


def _pencil_rayleigh_quotient(op: FamilyOperator, twist: NDArray[np.float64],
                              nu: NDArray[np.float64], left: NDArray[np.float64],
                              right: NDArray[np.float64]) -> NDArray[np.float64]:
    """y^T A x / y^T B x per point, with A = sum_i coef_i P_i (:attr:`FamilyOperator.pieces`).

    For |Omega| > LONG_TWIST the Omega^2 terms cancel against the others to ~lambda/Omega^2,
    and the sums are accumulated in extended precision (``np.longdouble``): this halves the
    round-off there (measured at Omega in [40, 100]: 0.39 -> 0.19 eps Omega^2).
    """
    out = _rayleigh_sums(op, twist, nu, left, right, np.float64)
    big = np.flatnonzero(np.abs(twist) > LONG_TWIST)
    if big.size:
        out[big] = _rayleigh_sums(op, twist[big], nu[big], left[big], right[big],
                                  np.longdouble)
    return out


def _rayleigh_sums(op: FamilyOperator, twist: NDArray[np.float64], nu: NDArray[np.float64],
                   left: NDArray[np.float64], right: NDArray[np.float64], dtype: type
                   ) -> NDArray[np.float64]:
    m = right.shape[1]
    x, y = right.astype(dtype), left.astype(dtype)
    px = _rows_matmul(x, op.pieces.astype(dtype).reshape(6 * m, m).T).reshape(-1, 6, m)
    om, nv = twist.astype(dtype), nu.astype(dtype)
    coef = np.stack([np.ones_like(om), om**2, nv, nv * om**2, nv * om, om], axis=1)
    num = (coef * np.einsum("pj,pij->pi", y, px)).sum(axis=1)
    den = np.einsum("pj,pj->p", y, _rows_matmul(x, op.mass.astype(dtype).T))
    return (num / den).astype(np.float64)


def solve_family(n: int, family: str, twist: NDArray[np.float64], nu: NDArray[np.float64],
                 *, rtol: float = POWER_RTOL, ceiling: NDArray[np.float64] | None = None
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
    lambda = inf where no eigenvalue passes the rule.
    """
    if twist.size <= SMALL_BATCH and n <= SMALL_DEGREE:  # the full eig is cheaper here
        return _solve_family_eig(n, family, twist, nu)
    mf = modal_family(n, family)
    op = mf.op
    try:
        lam, z, w, ok, above = lowest_eigenpair(mf, twist, nu, rtol=rtol, ceiling=ceiling)
    except np.linalg.LinAlgError:  # SHIFT an eigenvalue of some point (spurious): the rule
        return _solve_family_eig(n, family, twist, nu)
    k1 = mf.lam1.size
    vec = np.hstack([_rows_matmul(z[:, :k1], mf.u1.T), _rows_matmul(z[:, k1:], mf.u2.T)])
    # the eigenvalue from the O(1) pencil itself: the two-sided Rayleigh quotient (its error is
    # the product of the vectors' errors; K carries round-off ~ eps n^4 in its diagonal)
    good = np.flatnonzero(ok)
    w = w[good]
    left = np.hstack([_rows_matmul(w[:, :k1], mf.left1), _rows_matmul(w[:, k1:], mf.left2)])
    lam[good] = _pencil_rayleigh_quotient(op, twist[good], nu[good], left, vec[good])
    bad = np.flatnonzero(~(ok | above))
    if bad.size:  # the full eig with the rule decides
        a, b = op.pencil(twist[bad], nu[bad])
        theta, vec[bad] = _physical_eig(np.linalg.solve(a, b))
        valid = np.isfinite(theta) & (theta > 0)
        lam[bad] = np.where(valid, 1.0 / np.where(valid, theta, 1.0), np.inf)
    tails = np.full(twist.size, np.inf)
    resolved = np.flatnonzero(~above & np.isfinite(lam))
    tails[resolved] = mode_tails(op, vec[resolved])
    return lam, tails, vec


def _solve_family_eig(n: int, family: str, twist: NDArray[np.float64], nu: NDArray[np.float64]
                      ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """:func:`solve_family` by the full ``eig`` of A^{-1} B and the rule (the reference path)."""
    op = family_operator(n, family)
    a, b = op.pencil(twist, nu)
    theta, vec = _physical_eig(np.linalg.solve(a, b))
    valid = np.isfinite(theta) & (theta > 0)
    lam = np.where(valid, 1.0 / np.where(valid, theta, 1.0), np.inf)
    return lam, np.where(valid, mode_tails(op, vec), np.inf), vec


def _solve_points(twist: NDArray[np.float64], nu: NDArray[np.float64], n: NDArray[np.int_],
                  tol: float = 1e-12):
    """p*, family index and tail for flat arrays of points at the given degrees.

    The symmetric family first; the antisymmetric one then only has to be resolved where it
    is not clearly above (1 + 1e-6 times) the symmetric eigenvalue.
    """
    p = np.empty(twist.size)
    fam = np.empty(twist.size, dtype=int)
    tails = np.empty(twist.size)
    rtol = max(0.01 * tol, POWER_RTOL)
    for deg in np.unique(n):
        sel = np.flatnonzero(n == deg)
        lam = np.empty((2, sel.size))
        tl = np.empty((2, sel.size))
        lam[0], tl[0], _ = solve_family(int(deg), FAMILIES[0], twist[sel], nu[sel], rtol=rtol)
        lam[1], tl[1], _ = solve_family(int(deg), FAMILIES[1], twist[sel], nu[sel], rtol=rtol,
                                        ceiling=lam[0] * (1 + 1e-6))
        # a tie to round-off (e.g. nu = 1 at zero twist: the Euler mode in either plane) goes
        # to the symmetric family, whose mode is the planar one in the (u0) plane
        best = (lam[1] < lam[0] * (1.0 - 1e-14)).astype(int)
        cols = np.arange(sel.size)
        p[sel] = lam[best, cols] / np.pi**2
        fam[sel] = best
        # if the two families are within 1e-6 of each other either could be lowest;
        # both must then be resolved
        tails[sel] = np.where(np.abs(lam[0] - lam[1]) <= 1e-6 * lam.min(axis=0),
                              tl.max(axis=0), tl[best, cols])
    return p, fam, tails


def collocation_critical_load(twist_angle: ArrayLike, nu: ArrayLike, *, n: int | None = None,
                              tol: float = 1e-12, full_output: bool = False):
    """Critical load p* = P_cr / (pi^2 A1 / L^2) of the hinged twisted rod (Eq. ``inst1``)
    by Chebyshev collocation (the public :func:`spectral_rod.critical_load` routes here).

    Parameters
    ----------
    twist_angle : total spontaneous twist Omega(L) = omega30 L in radians (|.| <= 1e4).
        p* is even in it (reflection of the twist sense), so negative angles are allowed.
    nu : I2 / I1 = A2 / A1 >= 1 (the paper's convention A1 <= A2).
    n : Chebyshev degree (even, 8..512). ``None`` chooses it automatically: an a priori degree
        from the mode's wavenumber (:func:`initial_degree`), then the error estimate from the
        Chebyshev coefficients of the computed buckling mode (:func:`error_estimate`) must be
        <= ``tol``; if not, the degree is raised by ~12 % until it is or n = 512 (no raise
        where the round-off floor eps (32 + 0.3 Omega^2) alone exceeds ``tol``).
    tol : requested relative accuracy of p* (1e-14..1e-2).
    full_output : return a :class:`CriticalLoad` with the degree used, the error estimate,
        the mode family and a converged flag, instead of p* alone.

    Returns p* as a float for scalar input, otherwise an ndarray of the broadcast shape.
    If ``tol`` is not met (cap or round-off floor), a :class:`ConvergenceWarning` is issued
    and the result is flagged ``converged=False`` in the full output; it is never returned
    silently.
    """
    twist = check_twist(twist_angle)
    nu_arr = check_nu(nu)
    tol = check_tol(tol)
    shape = np.broadcast_shapes(twist.shape, nu_arr.shape)
    tw = np.abs(np.broadcast_to(twist, shape).ravel())
    nv = np.broadcast_to(nu_arr, shape).ravel()
    if n is not None:
        deg = np.full(tw.size, check_resolution(n, minimum=N_MIN, maximum=N_MAX))
        p, fam, tails = _solve_points(tw, nv, deg, tol)
        err = error_estimate(tails, tw)
    else:
        deg = initial_degree(tw, nv, tol)
        p, fam, tails = _solve_points(tw, nv, deg, tol)
        err = error_estimate(tails, tw)
        # raise the degree where the estimate misses tol, unless round-off alone does
        todo = np.flatnonzero((err > tol) & (deg < N_MAX) & (roundoff_floor(tw) < tol))
        while todo.size:
            deg[todo] = np.minimum(N_MAX, deg[todo] + 2 * np.ceil(0.06 * deg[todo] + 1)
                                   .astype(int))
            p[todo], fam[todo], tails[todo] = _solve_points(tw[todo], nv[todo], deg[todo],
                                                            tol)
            err[todo] = error_estimate(tails[todo], tw[todo])
            todo = todo[(err[todo] > tol) & (deg[todo] < N_MAX)]
    converged = err <= tol
    if n is None and not converged.all():
        bad = np.flatnonzero(~converged)
        warnings.warn(
            f"critical_load: tol={tol:g} not met at {bad.size} point(s) (n capped at {N_MAX}, "
            f"round-off floor eps (32 + 0.3 Omega^2); worst error estimate {err[bad].max():.2e} "
            f"at twist_angle={tw[bad[0]]:g}, nu={nv[bad[0]]:g})", ConvergenceWarning,
            stacklevel=2)
    if full_output:
        return CriticalLoad(p_star=p.reshape(shape), n=deg.reshape(shape),
                            error_estimate=err.reshape(shape),
                            family=np.asarray(FAMILIES)[fam].reshape(shape),
                            converged=converged.reshape(shape), tol=tol)
    return float(p[0]) if shape == () else p.reshape(shape)


def critical_wavenumbers(p_star: float, twist_angle: float, nu: float
                         ) -> tuple[complex | float, complex | float]:
    """The paper's wavenumbers (beta_1 L, beta_2 L), beta_1 <= beta_2, at load p*.

    beta_k^2 L^2 = X_-, X_+ are the roots of the characteristic equation of ``inst1``,
    (lambda - Omega^2 - X)(lambda/nu - Omega^2 - X) = 4 Omega^2 X with lambda = pi^2 p*.
    When X_- < 0 (lambda/nu < Omega^2 < lambda) beta_1 is imaginary and returned as a complex
    number i sqrt(-X_-).
    """
    p = real_array(p_star, "p_star")
    if p.shape != () or not p > 0:
        raise ValueError(f"p_star must be a positive real number, got {p_star!r}")
    om = float(check_twist(twist_angle))
    nu_f = float(check_nu(nu))
    lam = np.pi**2 * float(p)
    mu = lam / nu_f
    s = lam + mu + 2 * om**2
    x_plus = 0.5 * (s + math.sqrt((lam - mu) ** 2 + 8 * om**2 * (lam + mu)))
    x_minus = (lam - om**2) * (mu - om**2) / x_plus
    beta1 = math.sqrt(x_minus) if x_minus >= 0 else complex(0.0, math.sqrt(-x_minus))
    return beta1, math.sqrt(x_plus)


@dataclass(frozen=True)
class BucklingMode:
    """The critical mode of the hinged twisted rod on a uniform grid s/L in [0, 1].

    omega1, omega2: curvatures in the body frame (u0, v0), scaled so that max |omega| = 1;
    x1, x2: the centreline displacement in the fixed frame (e1, e2), obtained by integrating the
    paper's geometric relations x'' = R(Omega s) omega with x = 0 at both ends (units of L when
    omega is in units of 1/L); beta1, beta2: the critical wavenumbers times L (beta1 complex when
    imaginary); family: 'symmetric' or 'antisymmetric' about s = L/2.
    """

    s: NDArray[np.float64]
    omega1: NDArray[np.float64]
    omega2: NDArray[np.float64]
    x1: NDArray[np.float64]
    x2: NDArray[np.float64]
    p_star: float
    twist_angle: float
    nu: float
    family: str
    n: int
    beta1: complex | float
    beta2: float


def _centreline(c1: NDArray[np.float64], c2: NDArray[np.float64], twist: float, n: int
                ) -> tuple[C.Chebyshev, C.Chebyshev]:
    """x1, x2 (Chebyshev series in x = 2s - 1) from x'' = R(Omega s) omega, x(0) = x(1) = 0."""
    m = 2 * (n + int(abs(twist)) + 16)
    xs = C.chebpts2(m)
    s = (xs + 1) / 2
    w1, w2 = C.chebval(xs, c1), C.chebval(xs, c2)
    rot = ((w1 * np.cos(twist * s) - w2 * np.sin(twist * s)),
           (w1 * np.sin(twist * s) + w2 * np.cos(twist * s)))
    out = []
    for f in rot:
        g = C.Chebyshev(C.chebint(C.chebfit(xs, f / 4.0, m - 1), 2))  # d2/ds2 = 4 d2/dx2
        left, right = g(-1.0), g(1.0)
        out.append(g - C.Chebyshev([(left + right) / 2, (right - left) / 2]))
    return out[0], out[1]


def buckling_mode(twist_angle: float, nu: float, *, n: int | None = None, tol: float = 1e-12,
                  points: int = 201) -> BucklingMode:
    """The buckling mode at p* (Eq. ``inst1``): curvatures, centreline and wavenumbers.

    Resolution as in :func:`critical_load`; ``points`` is the size of the output grid.
    """
    res = collocation_critical_load(twist_angle, nu, n=n, tol=tol, full_output=True)
    if isinstance(points, bool) or not isinstance(points, int) or points < 2:
        raise ValueError(f"points must be an integer >= 2, got {points!r}")
    twist = float(twist_angle)
    deg, family = int(res.n), str(res.family)
    op = family_operator(deg, family)
    a, b = op.pencil(abs(twist), float(nu))
    _, vec = _physical_eig(np.linalg.solve(a, b)[None])  # full eig: an exact eigenvector
    c1, c2 = op.split(vec[0])
    if twist < 0:  # p* is even in Omega; the mode of -Omega is the mirror image (omega2 -> -)
        c2 = -c2
    s = np.linspace(0.0, 1.0, points)
    xs = 2 * s - 1
    w1, w2 = C.chebval(xs, c1), C.chebval(xs, c2)
    scale = np.max(np.abs(np.concatenate([w1, w2])))
    k = int(np.argmax(np.abs(np.concatenate([w1, w2]))))
    scale *= np.sign(np.concatenate([w1, w2])[k])
    x1, x2 = _centreline(c1 / scale, c2 / scale, twist, deg)
    beta1, beta2 = critical_wavenumbers(float(res.p_star), twist, float(nu))
    return BucklingMode(s=s, omega1=w1 / scale, omega2=w2 / scale, x1=x1(xs), x2=x2(xs),
                        p_star=float(res.p_star), twist_angle=twist, nu=float(nu),
                        family=family, n=deg, beta1=beta1, beta2=beta2)
