"""spectral_rod.observed_order: the log-log slope the pipeline's decay-order verdicts use."""

from __future__ import annotations

import numpy as np
import pytest

import spectral_rod as sr


def test_observed_order_recovers_a_power_and_ignores_the_sign_and_scale() -> None:
    x = np.array([16.0, 64.0, 256.0, 1024.0])
    assert sr.observed_order(x, 7.0 * x**-2) == pytest.approx(-2.0, abs=1e-12)
    assert sr.observed_order(x, -0.5 * x**3) == pytest.approx(3.0, abs=1e-12)
    # a power with a subdominant term: the fit measures the dominant one over the range
    assert sr.observed_order(x, x**-2 * (1 + 1 / x)) == pytest.approx(-2.0, abs=0.05)


def test_observed_order_is_the_least_squares_slope_of_the_logs() -> None:
    # the closed-form least-squares slope cov(u, v)/var(u) of v = log err on u = log x
    x, err = np.array([2.0, 3.0, 5.0, 9.0]), np.array([0.3, 0.11, 0.05, 0.01])
    u, v = np.log(x), np.log(err)
    slope = np.sum((u - u.mean()) * (v - v.mean())) / np.sum((u - u.mean()) ** 2)
    assert sr.observed_order(x, err) == pytest.approx(slope, rel=1e-13)


@pytest.mark.parametrize(("x", "err", "match"), [
    ([1.0, 2.0], [1.0, 0.0], "err must be non-zero"),
    ([0.0, 2.0], [1.0, 0.5], "x must be positive"),
    ([2.0, 2.0], [1.0, 0.5], "spread"),
    ([10.0, 10.0 * (1 + 1e-15)], [1.0, 2.0], "spread"),  # a RankWarning and slope 0.075 before
    ([1.0], [1.0], "length >= 2"),
    ([1.0, 2.0, 3.0], [1.0, 0.5], "equal length"),
])
def test_observed_order_rejects_what_has_no_order(x, err, match) -> None:
    with pytest.raises(ValueError, match=match):
        sr.observed_order(x, err)
