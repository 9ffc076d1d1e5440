r"""Inverses of a stack of small matrices, for the batched engine's Schur complements (``inst1``).

Used by the numpy iteration of :func:`.eigensolver.lowest_eigenpair`: where the C kernel
(:mod:`.modal_kernel`) is built, only for degrees above its range (Schur blocks of more than
:data:`.tuning.KERNEL_MAX_SCHUR` unknowns) and for points whose unpivoted factors the
kernel rejects; everywhere where it is not.

``numpy.linalg.inv`` calls LAPACK once per matrix, and at the sizes of the batched engine
(k = 10..30 at Figure 1's and the (Omega, nu) map's degrees) that per-call cost, not the
arithmetic, is most of its time. :func:`block_inverse` does the same arithmetic as a few
products of whole stacks, by the 2 x 2 block (Schur complement) formula

    [[P, Q], [R, T]]^{-1} = [[P^-1 + X S^-1 Y, -X S^-1], [-S^-1 Y, S^-1]],
    X = P^-1 Q,  Y = R P^-1,  S = T - R X,

recursively down to blocks of 3 x 3 or smaller, which are inverted in closed form. There is no
pivoting: the matrices it is given are Schur complements of K - SHIFT with SHIFT below every
physical eigenvalue (:class:`.shifted._ShiftedModal`), whose leading blocks are far from
singular.
:func:`stacked_inverse` checks every result anyway (one product with a fixed probe vector) and
redoes any matrix whose backward error is not small by LAPACK, with partial pivoting.

Whether it pays depends on the machine's numpy and LAPACK: it is used from
:data:`.tuning.BLOCK_ENTRIES` entries per stack on, where ``python
tests/bench/tuning_crossovers.py`` (part 3) puts the crossover with ``numpy.linalg.inv`` (the
check included; the constant's comment gives the measured ratios). On the engine's own Schur
complements (n = 8..128, both families, 400 random points each, Omega(L) up to 50, nu up to
1e4, condition numbers up to 5e8) it agreed with LAPACK's inverse to <= 4.3e-14 relative, with
backward errors <= 5.5e-16 (``tests/test_stacked_inverse.py`` holds n = 16..128 to 1e-12).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.collocation.tuning import BLOCK_ENTRIES

__all__ = ["BACKWARD_TOL", "BLOCK_ENTRIES", "block_inverse", "stacked_inverse", "uses_blocks"]

#: A block inverse X of S is accepted where |S (X v) - v| <= BACKWARD_TOL d |X v| (max norms,
#: v a fixed probe vector, d the largest |diagonal entry| of S, which is <= |S|: the test is at
#: least as strict as one relative to |S| |X v|): a backward error far above a pivoted LU's
#: (~k eps; measured <= 5.5e-16 on the engine's Schur complements) but far below what would
#: move an eigenvector of the iteration noticeably.
BACKWARD_TOL = 1e-10


def block_inverse(a: NDArray[np.float64]) -> NDArray[np.float64]:
    """Inverse of each matrix of a stack (..., k, k) by 2 x 2 block recursion, no pivoting.

    A zero leading pivot gives inf or nan (no exception): :func:`stacked_inverse` checks.

    >>> a = np.array([[[4.0, 1.0, 0.5], [2.0, 5.0, 1.0], [0.0, 1.0, 3.0]]])
    >>> bool(np.allclose(block_inverse(a) @ a, np.eye(3)))
    True
    """
    k = a.shape[-1]
    if k <= 3:
        return _small_inverse(a)
    h = k // 2
    p_inv = block_inverse(a[..., :h, :h])
    x = p_inv @ a[..., :h, h:]
    y = a[..., h:, :h] @ p_inv
    s_inv = block_inverse(a[..., h:, h:] - a[..., h:, :h] @ x)
    out = np.empty_like(a)
    xs = x @ s_inv
    out[..., :h, :h] = p_inv + xs @ y
    out[..., :h, h:] = -xs
    out[..., h:, :h] = -(s_inv @ y)
    out[..., h:, h:] = s_inv
    return out


def _small_inverse(a: NDArray[np.float64]) -> NDArray[np.float64]:
    """Closed-form inverse (adjugate over determinant) of 1 x 1, 2 x 2 or 3 x 3 matrices (a
    stack)."""
    k = a.shape[-1]
    if k == 1:
        return 1.0 / a
    out = np.empty_like(a)
    if k == 2:
        p, q, r, t = a[..., 0, 0], a[..., 0, 1], a[..., 1, 0], a[..., 1, 1]
        det = 1.0 / (p * t - q * r)
        out[..., 0, 0], out[..., 0, 1] = t * det, -q * det
        out[..., 1, 0], out[..., 1, 1] = -r * det, p * det
        return out
    m = np.moveaxis(a, (-2, -1), (0, 1))  # m[i][j]: the stack of entries (i, j)
    for i in range(3):
        for j in range(3):  # cofactor of entry (j, i) = adjugate entry (i, j)
            r0, r1 = (j + 1) % 3, (j + 2) % 3
            c0, c1 = (i + 1) % 3, (i + 2) % 3
            out[..., i, j] = m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
    det = 1.0 / (m[0][0] * out[..., 0, 0] + m[0][1] * out[..., 1, 0] + m[0][2] * out[..., 2, 0])
    out *= det[..., None, None]
    return out


def uses_blocks(k: int, count: int) -> bool:
    """Whether :func:`stacked_inverse` inverts `count` matrices of size k by blocks.

    >>> uses_blocks(10, 9_999), uses_blocks(10, 10_000), uses_blocks(28, 1_300)
    (False, True, True)
    """
    return count * k * k >= BLOCK_ENTRIES


@lru_cache(maxsize=64)
def _probe(k: int) -> NDArray[np.float64]:
    """A fixed generic probe vector of length k (entries in [1, 2], alternating sign)."""
    return (1.0 + np.arange(k) / max(k - 1, 1)) * (-1.0) ** np.arange(k)


def stacked_inverse(a: NDArray[np.float64]) -> NDArray[np.float64]:
    """Inverse of each matrix of a stack (points, k, k): :func:`block_inverse` where
    :func:`uses_blocks`, checked by a probe's backward error (:data:`BACKWARD_TOL`); LAPACK
    (``numpy.linalg.inv``) elsewhere and for every matrix the check rejects. Raises
    ``numpy.linalg.LinAlgError`` where LAPACK finds a matrix singular.

    >>> a = np.eye(12)[None] * 3.0 + 0.1
    >>> bool(np.allclose(stacked_inverse(a)[0] @ a[0], np.eye(12)))
    True
    """
    k = a.shape[-1]
    if not uses_blocks(k, a.shape[0]):
        return np.asarray(np.linalg.inv(a), dtype=float)
    with np.errstate(all="ignore"):  # a zero pivot: inf/nan, rejected below
        inv = block_inverse(a)
        v = _probe(k)
        xv = inv @ v
        residual = np.abs((a @ xv[..., None])[..., 0] - v).max(axis=-1)
        diagonal = np.abs(a[..., np.arange(k), np.arange(k)]).max(axis=-1)
        scale = diagonal * np.abs(xv).max(axis=-1)
        bad = ~(residual <= BACKWARD_TOL * scale)  # nan-safe: a nan is rejected
    if bad.any():
        inv[bad] = np.linalg.inv(a[bad])
    return inv
