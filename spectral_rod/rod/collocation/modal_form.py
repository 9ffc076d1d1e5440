r"""The modal form of Eq. ``inst1``'s collocation pencil, per mode family and degree.

The uncoupled operators -d^2/ds^2 of each field are diagonalised once per degree
(:class:`ModalFamily`); in that basis a family is K z = lambda z with K diagonal plus an
Omega-proportional coupling. :func:`modal_parts` evaluates K - SHIFT at a batch of points in the
blocks the shifted solves need (:mod:`.shifted`, the C kernel of :mod:`.modal_kernel`), and
:func:`_start_vector` is the iteration's fixed start vector.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any, NamedTuple, cast

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.collocation.discretisation import (
    INST1,
    FamilyOperator,
    family_operator,
    term_coefficients,
)
from spectral_rod.rod.families import SHIFT

__all__ = ["ModalFamily", "ModalParts", "modal_family", "modal_parts"]


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


@lru_cache(maxsize=64)
def _start_vector(k: int) -> NDArray[np.float64]:
    """A fixed generic unit start vector (no special structure that could be orthogonal to a
    mode); read-only, as it is cached."""
    v = np.random.default_rng(20240607).standard_normal(k)
    v /= np.linalg.norm(v)
    v.setflags(write=False)
    return v
