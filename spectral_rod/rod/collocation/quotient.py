r"""The pencil's two-sided Rayleigh quotient y^T A x / y^T B x of Eq. ``inst1``'s collocation
pencil: the eigenvalue the engine reports (error = product of the two vectors' errors).

:func:`pencil_rayleigh_quotient` is the one quotient of the numpy engine (the C kernel's
``pencil_quotient``), its precision a parameter: double up to |Omega| = LONG_TWIST, above it the
terms in extended precision, from the kernel's double-double products where it is built, else
from exact split BLAS products for a few points (:func:`_split_terms`) or ``longdouble``
products for many (:func:`_rayleigh_sums`).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.collocation import modal_kernel
from spectral_rod.rod.collocation.discretisation import INST1, FamilyOperator, family_operator
from spectral_rod.rod.collocation.modal_form import _coefficients
from spectral_rod.rod.collocation.tuning import DENSE_ENTRIES, LONG_TWIST

__all__ = ["pencil_rayleigh_quotient"]


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
