r"""Cross-section properties behind the paper's constants in Eq. ``constit``.

The paper takes the torsional stiffness A3 = E2 (I1 + I2): the polar moment of inertia, exact
for a circular (or annular) section. For a non-circular section Saint-Venant torsion gives
A3 = G J with J < I1 + I2. For a solid b x h rectangle (h >= b), nu = I2/I1 = (h/b)^2 and

    J = beta h b^3,   beta = 1/3 [1 - (192/pi^5) (b/h) sum_{n odd} tanh(n pi h/(2 b))/n^5],
    I1 + I2 = h b^3 (1 + nu)/12,   so   J/(I1 + I2) = 12 beta/(1 + nu)

(Timoshenko & Goodier; the series converges like n^-5). This ratio is how much the paper's A3
overestimates the torsional stiffness of a rectangular rod with the same nu.

>>> round(rectangle_torsion_ratio(1.0), 4)   # square: J = 0.1406 a^4, I1 + I2 = a^4/6
0.8435
"""

from __future__ import annotations

import math

from spectral_rod._validation import check_nu, scalar_value

__all__ = ["rectangle_torsion_ratio"]


def rectangle_torsion_ratio(nu: float, terms: int = 50) -> float:
    """J/(I1 + I2) of a solid rectangle with I2/I1 = nu >= 1 (module docstring)."""
    v = scalar_value(check_nu(nu), "nu")
    aspect = math.sqrt(v)  # h/b
    series = sum(math.tanh(n * math.pi * aspect / 2) / n**5 for n in range(1, 2 * terms, 2))
    beta = (1.0 - 192.0 / math.pi**5 / aspect * series) / 3.0
    return 12.0 * beta / (1.0 + v)
