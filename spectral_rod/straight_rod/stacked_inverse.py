r"""Inverses of a stack of small matrices, for the batched engine's Schur complements (``inst1``).

``numpy.linalg.inv`` calls LAPACK once per matrix, and at the sizes of the batched engine
(k = 10..30 at Figure 1's and the (Omega, nu) map's degrees) that per-call cost, not the
arithmetic, is most of its time. :func:`block_inverse` does the same arithmetic as a few
products of whole stacks, by the 2 x 2 block (Schur complement) formula

    [[P, Q], [R, T]]^{-1} = [[P^-1 + X S^-1 Y, -X S^-1], [-S^-1 Y, S^-1]],
    X = P^-1 Q,  Y = R P^-1,  S = T - R X,

recursively down to 2 x 2 blocks, which are inverted in closed form. There is no pivoting:
the matrices it is given are Schur complements of K - SHIFT with SHIFT below every physical
eigenvalue (:class:`.eigensolver._ShiftedModal`), whose leading blocks are far from singular.
:func:`stacked_inverse` checks every result anyway (one product with a fixed probe vector) and
redoes any matrix whose backward error is not small by LAPACK, with partial pivoting.

Measured 2026-12-05 (interleaved minima, one BLAS thread, random well-conditioned stacks), the
time per matrix relative to ``numpy.linalg.inv``: k = 10: 0.84, 0.74, 0.66 at 100, 300, 1,200
matrices; k = 14: 0.77, 0.65, 0.66; k = 22: 0.74, 0.60, 0.63; k = 27: 0.63, 0.52, 0.59; k = 7-9:
0.97-1.14 at 100 matrices but 0.65-0.84 from 300 on; k = 6: 1.27 at 100, hence
:func:`uses_blocks`. The check adds 10-25 % of the block inverse's time. In the engine (15
interleaved rounds, 2026-12-05): the Figure 1 batch 0.95 of its time with LAPACK's inverse, one
call per curve 0.90, the (Omega, nu) map's collocation points 0.90, batches of 100 unchanged. On
the engine's own Schur complements (n = 8..128, both families, 400 random points each,
Omega(L) up to 50, nu up to 1e4, condition numbers up to 5e8) it agreed with LAPACK's inverse
to <= 4.3e-14 relative, with backward errors <= 5.5e-16.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import NDArray

__all__ = ["BACKWARD_TOL", "BLOCK_MIN", "LARGE_STACK", "block_inverse", "stacked_inverse",
           "uses_blocks"]

#: :func:`stacked_inverse` uses :func:`block_inverse` from size BLOCK_MIN[0] on, and from size
#: BLOCK_MIN[1] on in stacks of at least LARGE_STACK matrices (measured crossovers, module
#: docstring); LAPACK below.
BLOCK_MIN, LARGE_STACK = (10, 7), 300
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
    if k <= 2:
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
    """Closed-form inverse of 1 x 1 or 2 x 2 matrices (a stack)."""
    if a.shape[-1] == 1:
        return 1.0 / a
    p, q, r, t = a[..., 0, 0], a[..., 0, 1], a[..., 1, 0], a[..., 1, 1]
    det = 1.0 / (p * t - q * r)
    out = np.empty_like(a)
    out[..., 0, 0], out[..., 0, 1] = t * det, -q * det
    out[..., 1, 0], out[..., 1, 1] = -r * det, p * det
    return out


def uses_blocks(k: int, count: int) -> bool:
    """Whether :func:`stacked_inverse` inverts `count` matrices of size k by blocks."""
    return k >= BLOCK_MIN[0] or (k >= BLOCK_MIN[1] and count >= LARGE_STACK)


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
        return np.linalg.inv(a)
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
