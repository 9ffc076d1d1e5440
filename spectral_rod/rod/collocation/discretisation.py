r"""Eq. ``inst1`` declared term by term, and its collocation pencil per mode family.

The problem is *declared* once, as data (:data:`INST1`), and everything else -- the pencil, the
modal form of the fast eigensolver, the extended-precision Rayleigh quotient -- is built from it.

Discretisation: each mode family (:mod:`spectral_rod.rod.families`) is represented in the parity
integration bases of :mod:`.chebyshev` (degree n; n/2 and n/2 - 1 unknowns per field): c are the
Chebyshev coefficients of (omega1'', omega2''), omega1 block first, and with d/ds = 2 d/dx the
collocated equations form the generalised eigenproblem A(Omega, nu) c = lambda B c,

    A = sum over the terms of INST1:  coefficient(Omega, nu) * 2^order * (d/dx)^order basis,
    B = diag(V_1, V_2)   (the basis values at the equations' points),

e.g. A = [[-4 D2_1 + Omega^2 V_1, 4 nu Omega D1_2], [-4 Omega D1_1, nu (-4 D2_2 + Omega^2 V_2)]].
All its matrices are O(1), so round-off does not grow like n^4 as with differentiation matrices.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property, lru_cache
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod.rod.collocation.chebyshev import ParityBasis, parity_basis
from spectral_rod.rod.families import check_family

__all__ = ["INST1", "FamilyOperator", "Term", "family_operator", "term_coefficients"]


@dataclass(frozen=True)
class Term:
    """One term of Eq. ``inst1``: in `equation`, coefficient(Omega, nu) d^k `field`/ds^k."""

    equation: int  # 0: the omega1 equation, 1: the omega2 equation
    field: int     # 0: omega1, 1: omega2
    order: int     # k, the derivative order in s
    coefficient: Callable[[Any, Any], Any]


#: Eq. ``inst1`` divided by A1, as  sum of terms = lambda * (omega1, omega2):
#:     -omega1'' + Omega^2 omega1 + 2 nu Omega omega2'      = lambda omega1
#:     -nu omega2'' + nu Omega^2 omega2 - 2 Omega omega1'   = lambda omega2
INST1 = (
    Term(0, 0, 2, lambda om, nu: -1.0 + 0.0 * om),
    Term(0, 0, 0, lambda om, nu: om * om),
    Term(0, 1, 1, lambda om, nu: 2.0 * nu * om),
    Term(1, 1, 2, lambda om, nu: -nu + 0.0 * om),
    Term(1, 1, 0, lambda om, nu: nu * om * om),
    Term(1, 0, 1, lambda om, nu: -2.0 * om),
)


def term_coefficients(twist_angle: ArrayLike, nu: ArrayLike) -> NDArray[Any]:
    """The coefficients of :data:`INST1` at broadcast points, shape (..., len(INST1)); the dtype
    follows the input (float64, or longdouble for the extended-precision Rayleigh quotient)."""
    om, nv = np.asarray(twist_angle), np.asarray(nu)
    if om.ndim == nv.ndim == 0 and om.dtype == nv.dtype == np.float64:  # one point: floats
        a, b = float(om), float(nv)
        return np.array([t.coefficient(a, b) for t in INST1])
    out = np.empty((*np.broadcast_shapes(om.shape, nv.shape), len(INST1)),
                   dtype=np.result_type(om, nv, 1.0))
    for i, t in enumerate(INST1):
        out[..., i] = t.coefficient(om, nv)
    return out


@dataclass(frozen=True)
class FamilyOperator:
    """The collocation pencil A(Omega, nu) c = lambda B c of one parity family at degree n."""

    n: int
    family: str
    bases: tuple[tuple[ParityBasis, ParityBasis], tuple[ParityBasis, ParityBasis]]
    # bases[e][f]: the basis of field f at the collocation points of equation e

    @property
    def sizes(self) -> tuple[int, int]:
        """Unknowns per field (omega1, omega2)."""
        return self.bases[0][0].value.shape[1], self.bases[1][1].value.shape[1]

    @cached_property
    def pieces(self) -> NDArray[np.float64]:
        """A = sum_i coefficient_i P_i over the terms of :data:`INST1`: the constant matrices
        P_i, shape (len(INST1), m, m)."""
        k1, k2 = self.sizes
        cols = (slice(0, k1), slice(k1, k1 + k2))
        p = np.zeros((len(INST1), k1 + k2, k1 + k2))
        for i, t in enumerate(INST1):
            b = self.bases[t.equation][t.field]
            block = (b.value, b.d1, b.d2)[t.order] * 2.0**t.order  # d/ds = 2 d/dx
            p[i, cols[t.equation], cols[t.field]] = block
        return p

    @cached_property
    def term_blocks(self) -> tuple[tuple[int, int, tuple[int, ...], NDArray[np.float64]], ...]:
        """A's nonzero blocks, per (equation e, field f): (e, f, the indices of the terms of
        :data:`INST1` there, their blocks 2^order (d/dx)^order basis stacked, shape
        (terms * rows of e, unknowns of f)): products with A that skip its zero blocks."""
        groups: dict[tuple[int, int], list[int]] = {}
        for i, t in enumerate(INST1):
            groups.setdefault((t.equation, t.field), []).append(i)
        out = []
        for (e, f), idx in groups.items():
            b = self.bases[e][f]
            out.append((e, f, tuple(idx), np.vstack([(b.value, b.d1, b.d2)[INST1[i].order]
                                                     * 2.0 ** INST1[i].order for i in idx])))
        return tuple(out)

    @cached_property
    def mass(self) -> NDArray[np.float64]:
        """B = diag(V_1, V_2), shape (m, m)."""
        k1, k2 = self.sizes
        b = np.zeros((k1 + k2, k1 + k2))
        b[:k1, :k1] = self.bases[0][0].value
        b[k1:, k1:] = self.bases[1][1].value
        return b

    @cached_property
    def tail_rows(self) -> NDArray[np.float64]:
        """Rows mapping an eigenvector c to the Chebyshev coefficients of its fields' own
        parity, the tail first: the last two of omega1, the last two of omega2, then the rest
        (the layout :func:`spectral_rod.rod.collocation.resolution.tails_of` reads)."""
        k1 = self.sizes[0]
        blocks = []
        for f, b in enumerate((self.bases[0][0], self.bases[1][1])):
            rows = np.zeros((b.coefficients.shape[0], self.mass.shape[0]))
            rows[:, slice(0, k1) if f == 0 else slice(k1, None)] = b.coefficients
            blocks.append(rows[b.parity::2])
        return np.vstack([blk[-2:] for blk in blocks] + [blk[:-2] for blk in blocks])

    def pencil(self, twist_angle: ArrayLike, nu: ArrayLike
               ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """A for broadcast arrays `twist_angle`, `nu` (shape (..., m, m)), and B (m, m)."""
        coef = term_coefficients(np.asarray(twist_angle, dtype=float),
                                 np.asarray(nu, dtype=float))
        m = self.mass.shape[0]
        a = (coef.reshape(-1, len(INST1)) @ self.pieces.reshape(len(INST1), m * m))
        return a.reshape(*coef.shape[:-1], m, m), self.mass

    def split(self, c: NDArray[np.generic]) -> tuple[NDArray[np.generic], NDArray[np.generic]]:
        """Chebyshev coefficients (in x) of (omega1, omega2) from an eigenvector."""
        k1 = self.sizes[0]
        return (self.bases[0][0].chebyshev_coefficients(c[:k1]),
                self.bases[1][1].chebyshev_coefficients(c[k1:]))


@lru_cache(maxsize=128)
def family_operator(n: int, family: str) -> FamilyOperator:
    """Assemble the (n, family) pieces once (they do not depend on Omega or nu).

    Symmetric family: omega1 even (its equation collocated at all half points), omega2 odd (at
    the points x > 0, where an odd equation is not trivially satisfied); antisymmetric: the
    reverse.
    """
    check_family(family)
    parity = (0, 1) if family == "symmetric" else (1, 0)
    points = tuple("all" if p == 0 else "positive" for p in parity)
    bases = tuple(tuple(parity_basis(n, parity[f], points[e]) for f in range(2))
                  for e in range(2))
    return FamilyOperator(n=n, family=family, bases=bases)  # type: ignore[arg-type]
