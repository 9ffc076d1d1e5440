"""The Chebyshev kernel of the collocation solver (Eq. ``inst1``): points and parity bases on
x in [-1, 1], in an integration basis.

The hinged rod is symmetric under s -> 1 - s, so every mode has a definite parity about the
mid-point and each field is an even or an odd polynomial. Following Greengard's spectral
integration, a field w that vanishes at x = +-1 is represented by its second derivative,

    w'' = sum_j c_j T_j     (j of w's parity, j <= n - 2),     w = G w'',

where G is the double integral from x = 0 (numpy.polynomial.chebyshev.chebint) corrected by
T_0 or T_1 so that w(+-1) = 0. The basis functions G T_j span exactly the polynomials of degree
<= n and parity p vanishing at +-1 -- Trefethen's collocation space of degree n restricted to one
parity class -- but every matrix built from them has O(1) entries, where differentiation
matrices grow like n^4. Equations are collocated at the Chebyshev points x_j = cos(j pi/n),
j = 1..n/2, the non-negative half of the interior points (even equations at all of them, odd
ones at the n/2 - 1 points with x > 0; at x = 0 an odd equation holds trivially).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import numpy.polynomial.chebyshev as C
from numpy.typing import NDArray


def interpolation_coefficients(values: NDArray[np.float64]) -> NDArray[np.float64]:
    """Chebyshev coefficients of the polynomial interpolating `values` at the m Chebyshev
    points of the second kind in ascending order (``numpy.polynomial.chebyshev.chebpts2(m)``):
    a DCT-I, O(m log m) (a least-squares fit would be O(m^3)).

    >>> x = C.chebpts2(5)
    >>> (np.round(interpolation_coefficients(2 * x**2 - 1), 14) + 0.0).tolist()  # T_2
    [0.0, 0.0, 1.0, 0.0, 0.0]
    """
    from scipy.fft import dct

    n = values.size - 1
    c = dct(values[::-1], type=1) / n  # x_j = cos(j pi / n), j = 0..n: descending
    c[[0, -1]] /= 2
    return c


def half_points(n: int) -> NDArray[np.float64]:
    """The n/2 Chebyshev points cos(j pi / n), j = 1..n/2, in (0, 1), with x = 0 last."""
    return np.cos(np.pi * np.arange(1, n // 2 + 1) / n)


@dataclass(frozen=True)
class ParityBasis:
    """Basis w_k = G T_{j_k} of one parity at degree n, evaluated at collocation points.

    ``coefficients[:, k]`` are the Chebyshev coefficients of w_k (length n + 1);
    ``value``, ``d1``, ``d2`` are w_k, w_k' and w_k'' = T_{j_k} at the points.
    """

    parity: int  # 0 even, 1 odd
    coefficients: NDArray[np.float64]
    value: NDArray[np.float64]  # (points, basis)
    d1: NDArray[np.float64]
    d2: NDArray[np.float64]

    def chebyshev_coefficients(self, c: NDArray[np.generic]) -> NDArray[np.generic]:
        """Chebyshev coefficients of the field sum_k c_k w_k."""
        return np.matmul(self.coefficients, c)


@lru_cache(maxsize=16)
def integration_coefficients(n: int, parity: int) -> NDArray[np.float64]:
    """Chebyshev coefficients (n + 1, basis) of G T_j, j = parity, parity + 2, ..., <= n - 2."""
    js = np.arange(parity, n - 1, 2)
    unit = np.zeros((n - 1, js.size))
    unit[js, np.arange(js.size)] = 1.0
    w = C.chebint(unit, 2, lbnd=0.0, axis=0)  # (n + 1, basis): degree j + 2 <= n
    w[parity, :] -= C.chebval(1.0, w)  # T_0(1) = T_1(1) = 1; parity makes w(-1) = 0 too
    return np.asarray(w, dtype=float)


@lru_cache(maxsize=64)
def parity_basis(n: int, parity: int, points: str) -> ParityBasis:
    """The parity basis at degree n at the half points: ``points`` is 'all' or 'positive'."""
    x = half_points(n) if points == "all" else half_points(n)[:-1]
    coef = integration_coefficients(n, parity)
    # chebval with 2-D coefficients returns (basis, points)
    value = C.chebval(x, coef).T
    d1 = C.chebval(x, C.chebder(coef, 1, axis=0)).T
    d2 = C.chebval(x, C.chebder(coef, 2, axis=0)).T
    return ParityBasis(parity, coef, value, d1, d2)
