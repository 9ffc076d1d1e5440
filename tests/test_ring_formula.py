"""Eq. crit2 and the threshold twist, against hand-computed values and the paper's dimensional
form (q R^3/(E1 I1), nu = I2/I1, e = E2/E1)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from spectral_rod.ring.formula import ThresholdTwist, ring_formula_load, threshold_twist


def crit2_dimensional(E1: float, E2: float, I1: float, I2: float, R: float, N: int) -> float:
    """Eq. crit2 exactly as printed, in physical units."""
    return E2 * (I1 + I2) / (2 * R**3) * (3 - (I2 - I1) / (I2 + I1) * (N**2 + 1))


@pytest.mark.parametrize(("N", "nu", "e", "expected"), [
    (0, 1.0, 1.0, 3.0),        # e/2 [3 * 2 - 0] = 3
    (7, 1.0, 1.0, 3.0),        # independent of N for nu = 1
    (0, 2.0, 1.0, 4.0),        # 1/2 [9 - 1] = 4
    (3, 2.0, 1.0, -0.5),       # 1/2 [9 - 10] = -0.5
    (1, 3.0, 0.5, 2.0),        # 1/4 [12 - 4] = 2
    (2, 4.0, 1.0, 0.0),        # 1/2 [15 - 15] = 0: the threshold itself
    (10, 1.5, 2.0, -43.0),     # 1 * [7.5 - 0.5 * 101] = -43
])
def test_formula_hand_values(N: int, nu: float, e: float, expected: float) -> None:
    assert ring_formula_load(N, nu, e_ratio=e) == pytest.approx(expected, abs=1e-14)


def test_formula_matches_dimensional_form() -> None:
    rng = np.random.default_rng(1)
    for _ in range(20):
        E1, E2, I1, R = rng.uniform(0.5, 3.0, 4)
        nu = rng.uniform(1.0, 5.0)
        N = int(rng.integers(0, 12))
        q = crit2_dimensional(E1, E2, I1, nu * I1, R, N) * R**3 / (E1 * I1)
        assert ring_formula_load(N, nu, e_ratio=E2 / E1) == pytest.approx(q, rel=1e-12, abs=1e-12)


def test_circular_limit_is_3_e_not_3() -> None:
    # crit2 at I1 = I2 gives 3 E2 I1/R^3; the text's 3 E1 I1/R^3 only when E2 = E1
    assert ring_formula_load(5, 1.0, e_ratio=1 / 2.6) == pytest.approx(3 / 2.6)
    assert ring_formula_load(5, 1.0) == pytest.approx(3.0)


def test_threshold_nu_one_is_infinite() -> None:
    th = threshold_twist(1.0)
    assert isinstance(th, ThresholdTwist)
    assert th.continuous == math.inf and th.integer == math.inf


@pytest.mark.parametrize(("nu", "cont", "integer"), [
    (2.0, math.sqrt(8.0), 3),      # N^2 = (2*2 + 4)/(2 - 1) = 8
    (4.0, 2.0, 2),                 # N^2 = 12/3 = 4: crit2(2) = 0 counts ("N^2 >= ...")
    (1.1, math.sqrt(62.0), 8),     # 6.2/0.1 = 62
    (3.0, math.sqrt(5.0), 3),      # 10/2 = 5
    (1.5, math.sqrt(14.0), 4),     # 7/0.5 = 14
])
def test_threshold_hand_values(nu: float, cont: float, integer: int) -> None:
    th = threshold_twist(nu)
    assert th.continuous == pytest.approx(cont, rel=1e-14)
    assert th.integer == integer


@pytest.mark.parametrize("nu", [1.01, 1.1, 1.3, 1.5, 2.0, 3.7, 4.0, 10.0, 100.0])
def test_threshold_is_where_crit2_changes_sign(nu: float) -> None:
    th = threshold_twist(nu)
    # the continuous root: 3 (1 + nu) = (nu - 1)(N^2 + 1)
    assert 3 * (1 + nu) == pytest.approx((nu - 1) * (th.continuous**2 + 1), rel=1e-12)
    k = th.integer
    assert ring_formula_load(k, nu) <= 1e-12
    assert ring_formula_load(k - 1, nu) > 0
    # independent of e
    assert ring_formula_load(k, nu, e_ratio=0.3) <= 1e-12


@pytest.mark.parametrize(("kwargs", "exc", "word"), [
    ({"N": -1, "nu": 2.0}, ValueError, "N"),
    ({"N": 2.5, "nu": 2.0}, ValueError, "N"),
    ({"N": "3", "nu": 2.0}, TypeError, "N"),
    ({"N": True, "nu": 2.0}, TypeError, "N"),
    ({"N": 1, "nu": 0.5}, ValueError, "nu"),
    ({"N": 1, "nu": float("nan")}, ValueError, "nu"),
    ({"N": 1, "nu": 2.0, "e_ratio": 0.0}, ValueError, "e_ratio"),
    ({"N": 1, "nu": 2.0, "e_ratio": -1.0}, ValueError, "e_ratio"),
    ({"N": 1, "nu": 2.0, "e_ratio": "1"}, TypeError, "e_ratio"),
])
def test_formula_bad_input(kwargs: dict, exc: type[Exception], word: str) -> None:
    N, nu = kwargs.pop("N"), kwargs.pop("nu")
    with pytest.raises(exc, match=word):
        ring_formula_load(N, nu, **kwargs)


def test_formula_accepts_integer_valued_float() -> None:
    assert ring_formula_load(3.0, 2.0) == ring_formula_load(3, 2.0)


def test_threshold_bad_input() -> None:
    with pytest.raises(ValueError, match="nu"):
        threshold_twist(0.9)
    with pytest.raises(TypeError, match="nu"):
        threshold_twist([1.5, 2.0])
