r"""Cross-section properties behind the paper's constants in Eq. ``constit``.

The paper takes the torsional stiffness A3 = E2 (I1 + I2): the polar moment of inertia, exact
for a circular (or annular) section. For a non-circular section Saint-Venant torsion gives
A3 = G J with J < I1 + I2. For a solid b x h rectangle (h >= b), nu = I2/I1 = (h/b)^2 and

    J = beta h b^3,   beta = 1/3 [1 - (192/pi^5) (b/h) sum_{n odd} tanh(n pi h/(2 b))/n^5],
    I1 + I2 = h b^3 (1 + nu)/12,   so   J/(I1 + I2) = 12 beta/(1 + nu)

(Timoshenko & Goodier). The series converges like n^-5; with x_n = n pi h/(2 b) it is summed as
sum_{n odd} 1/n^5 - sum_{n odd} (1 - tanh x_n)/n^5, where sum_{n odd} 1/n^5 = (31/32) zeta(5)
and 1 - tanh x_n = 2 exp(-2 x_n)/(1 + exp(-2 x_n)) <= 2 exp(-n pi) (h >= b), so the odd
n = 1..21 give full double precision. This ratio is how much the paper's A3 overestimates the
torsional stiffness of a rectangular rod with the same nu.

>>> round(rectangle_torsion_ratio(1.0), 4)   # square: J = 0.1406 a^4, I1 + I2 = a^4/6
0.8435
"""

from __future__ import annotations

import math

from spectral_rod._validation import scalar_nu

__all__ = ["rectangle_torsion_ratio"]

#: zeta(5) = sum of 1/n^5 over n >= 1 (checked against mpmath in the tests).
ZETA5 = 1.0369277551433699263
#: Odd n = 1, 3, ..., 21 of the exponentially small correction (the next term is < 1e-30).
_ODD = range(1, 22, 2)


def rectangle_torsion_ratio(nu: float) -> float:
    """J/(I1 + I2) of a solid rectangle with I2/I1 = nu >= 1 (module docstring).

    Returns
    -------
    float
        J/(I1 + I2).

    Examples
    --------
    >>> round(rectangle_torsion_ratio(4.0) * 5 / 12, 4)   # h/b = 2: beta = 0.229 (Timoshenko)
    0.2287
    """
    v = scalar_nu(nu)
    aspect = math.sqrt(v)  # h/b
    tail = sum(2.0 * (x := math.exp(-n * math.pi * aspect)) / (1.0 + x) / n**5 for n in _ODD)
    series = 31.0 / 32.0 * ZETA5 - tail
    beta = (1.0 - 192.0 / math.pi**5 / aspect * series) / 3.0
    return 12.0 * beta / (1.0 + v)
