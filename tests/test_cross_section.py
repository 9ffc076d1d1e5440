"""rectangle_torsion_ratio: its zeta(5) constant and its summed series against mpmath, and
Timoshenko & Goodier's tabulated torsion constants."""

from __future__ import annotations

import math

import mpmath
import pytest

from spectral_rod.ring import cross_section
from spectral_rod.ring.cross_section import rectangle_torsion_ratio


def test_zeta5_constant() -> None:
    with mpmath.workdps(40):
        exact = mpmath.zeta(5)
        assert abs(mpmath.mpf(cross_section.ZETA5) - exact) / exact < 1e-16


def _ratio_mpmath(nu: float) -> mpmath.mpf:
    """J/(I1 + I2) from the printed series, sum over odd n of tanh(n pi h/(2 b))/n^5, summed
    term by term by mpmath (no zeta(5), no split into 1/n^5 and an exponential tail)."""
    with mpmath.workdps(40):
        aspect = mpmath.sqrt(nu)
        series = mpmath.nsum(
            lambda k: mpmath.tanh((2 * k + 1) * mpmath.pi * aspect / 2) / (2 * k + 1) ** 5,
            [0, mpmath.inf])
        beta = (1 - 192 / mpmath.pi**5 / aspect * series) / 3
        return 12 * beta / (1 + nu)


@pytest.mark.parametrize("nu", [1.0, 1.0 + 1e-9, 1.5, 2.25, 4.0, 10.0, 123.4, 1e4])
def test_ratio_against_mpmath_series(nu: float) -> None:
    exact = _ratio_mpmath(nu)
    assert abs(rectangle_torsion_ratio(nu) - float(exact)) <= 1e-14 * float(exact)


@pytest.mark.parametrize(("aspect", "beta"), [  # Timoshenko & Goodier, table of beta = J/(h b^3)
    (1.0, 0.1406), (1.5, 0.196), (2.0, 0.229), (3.0, 0.263), (5.0, 0.291), (10.0, 0.312)])
def test_timoshenko_table(aspect: float, beta: float) -> None:
    nu = aspect**2
    got = rectangle_torsion_ratio(nu) * (1 + nu) / 12
    digits = len(str(beta).split(".")[1])
    assert round(got, digits) == beta


def test_square() -> None:
    # J = 0.1406 a^4 and I1 + I2 = a^4/6: J/(I1 + I2) = 0.8435
    assert round(rectangle_torsion_ratio(1.0), 4) == 0.8435


def test_thin_strip_limit() -> None:
    # h >> b: beta -> 1/3 (1 - 0.630 b/h) (Timoshenko's thin-strip coefficient 0.630, typed
    # from the book, not from the code); at h/b = 100 the remainder is exponentially small
    nu = 1e4
    beta = rectangle_torsion_ratio(nu) * (1 + nu) / 12
    assert beta == pytest.approx((1 - 0.630 / math.sqrt(nu)) / 3, abs=1e-6)

