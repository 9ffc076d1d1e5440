"""Gauss-Legendre quadrature to a few ulp (used by :mod:`spectral_rod.rod.ritz` and
:mod:`spectral_rod.rod.increment`).

numpy's ``leggauss`` and scipy's ``roots_legendre`` solve an eigenproblem; their weights were
measured wrong by 1e-11 (q = 120) to 5e-10 (q = 400) and 8e-9 (q = 1000) relative, enough to
spoil a 1e-12 result. Here the nodes come from Newton's method on the three-term recurrence.

>>> x, w = gauss_legendre(2)
>>> [round(v, 15) for v in x.tolist()], [round(v, 15) for v in w.tolist()]
([-0.577350269189626, 0.577350269189626], [1.0, 1.0])
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import NDArray

__all__ = ["gauss_legendre", "gauss_legendre_unit"]

EPS = float(np.finfo(float).eps)


def _legendre_pair(x: NDArray[np.float64], q: int) -> tuple[NDArray[np.float64], ...]:
    """(P_{q-1}(x), P_q(x)) by the three-term recurrence (stable on [-1, 1])."""
    p0, p1 = np.ones_like(x), x.copy()
    for j in range(1, q):
        p0, p1 = p1, ((2 * j + 1) * x * p1 - j * p0) / (j + 1)
    return p0, p1


@lru_cache(maxsize=16)
def gauss_legendre(q: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Gauss–Legendre nodes and weights on [-1, 1] (q >= 2) to a few ulp.

    Newton's method on P_q from the asymptotic guess -cos(pi (k - 1/4)/(q + 1/2)), weights
    2 / ((1 - x^2) P_q'(x)^2) with 1 - x^2 = (1 - x)(1 + x); symmetrised. Example:
    ``gauss_legendre(2)`` gives nodes -+1/sqrt(3) and weights 1, 1.
    """
    k = np.arange(1, q + 1)
    x = -np.cos(np.pi * (k - 0.25) / (q + 0.5))
    for _ in range(30):
        p0, p1 = _legendre_pair(x, q)
        dx = p1 / (q * (x * p1 - p0) / ((x - 1) * (x + 1)))
        x = x - dx
        if np.max(np.abs(dx)) <= 4 * EPS:
            break
    p0, p1 = _legendre_pair(x, q)
    dp = q * (x * p1 - p0) / ((x - 1) * (x + 1))
    w = 2.0 / ((1 - x) * (1 + x) * dp * dp)
    x, w = (x - x[::-1]) / 2, (w + w[::-1]) / 2
    x.flags.writeable = w.flags.writeable = False
    return x, w


@lru_cache(maxsize=64)
def gauss_legendre_unit(q: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """:func:`gauss_legendre` mapped to s in [0, 1] (nodes (x + 1)/2, weights w/2)."""
    x, w = gauss_legendre(q)
    return (x + 1) / 2, w / 2
