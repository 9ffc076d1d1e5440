"""Small dense products kept off the multithreaded BLAS (a speed policy of the eigensolver)."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

#: Largest product handed to BLAS in one call (see :func:`rows_matmul`).
BLAS_BLOCK = 1 << 17


def rows_matmul(a: NDArray[np.floating], b: NDArray[np.floating]) -> NDArray[np.floating]:
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
