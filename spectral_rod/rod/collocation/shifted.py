r"""(K - SHIFT)^{-1} of the modal form (:mod:`.modal_form`) for the numpy reference of the
eigenvalue iteration (Eq. ``inst1``): through a Schur complement of the smaller block for many
points (:class:`_ShiftedModal`), as dense inverses for a few (:class:`_DenseShifted`,
:data:`.tuning.DENSE_ENTRIES`), and for one point as one block-diagonal matrix holding the
inverse and its transpose (:func:`_point_inverse`). The C kernel of :mod:`.modal_kernel` forms
the same Schur complement in C.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.collocation.discretisation import FamilyOperator
from spectral_rod.rod.collocation.modal_form import (
    MODAL_TERMS,
    ModalFamily,
    ModalParts,
    _start_vector,
    modal_family,
    modal_parts,
)
from spectral_rod.rod.collocation.stacked_inverse import stacked_inverse
from spectral_rod.rod.collocation.tuning import DENSE_ENTRIES, POINT_SCHUR_DEGREE
from spectral_rod.rod.families import SHIFT

__all__: list[str] = []


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


class _PointFamily(NamedTuple):
    """A family at degree n laid out for the numpy reference's one-point path
    (:func:`_numpy_point`): the modal unknowns in the order (eliminated block, Schur block) of
    :class:`ModalParts`, as the kernel's ``family_lanes`` holds them."""

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
        inverse = _lu_inverse(shifted)
        if inverse is None:
            return None
        pair = np.zeros((2 * m, 2 * m))
        pair[:m, :m], pair[m:, m:] = inverse, inverse.T
        return pair
    r = 1.0 / d_e
    g_r = pf.g_se * r  # G_se R
    schur = (-a * b) * (g_r @ pf.g_es)
    schur.flat[::k_s + 1] += d_s
    schur_inv = _lu_inverse(schur)
    if schur_inv is None:
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


def _lu_inverse(matrix: NDArray[np.float64]) -> NDArray[np.float64] | None:
    """The inverse by LAPACK's pivoted LU (``dgetrf``, ``dgetri``; `matrix` is overwritten),
    None where it is singular."""
    from scipy.linalg.lapack import dgetrf, dgetri

    lu, piv, info = dgetrf(matrix, overwrite_a=1)
    if info == 0:
        inverse, info = dgetri(lu, piv, overwrite_lu=1)
    return inverse if info == 0 else None
