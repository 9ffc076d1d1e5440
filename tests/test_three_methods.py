"""Issue 11: the three straight-rod methods -- collocation (Eq. inst1), the characteristic
equation (Eq. inst1, double precision) and Rayleigh-Ritz on the lab-frame energy (no inst1) --
agree to relative 1e-12 over Omega(L) in [0, 100], nu in [1, 100]; the mpmath characteristic
equation is the independent reference for all three."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from spectral_rod import critical_load

TWISTS = (0.0, 0.3, 2 * np.pi, 9.0, 25.0, 49.0, 70.0, 100.0)
NUS = (1.0, 1.0 + 1e-6, 1.3, 4.0, 30.0, 100.0)


@pytest.mark.parametrize("method", ["collocation", "characteristic", "ritz"])
def test_each_method_matches_the_reference(method, reference):
    tw, nv = (np.array(v) for v in zip(*itertools.product(TWISTS, NUS), strict=True))
    res = critical_load(tw, nv, method=method, full_output=True)
    ref = np.array([reference(float(a), float(b)) for a, b in zip(tw, nv, strict=True)])
    assert np.all(res.method == method) and res.converged.all()
    assert np.max(np.abs(res.p_star / ref - 1)) <= 1e-12


def test_the_three_methods_agree_with_each_other():
    tw, nv = (np.array(v) for v in zip(*itertools.product(TWISTS, NUS), strict=True))
    p = {m: critical_load(tw, nv, method=m) for m in ("collocation", "characteristic", "ritz")}
    for a, b in itertools.combinations(p, 2):
        assert np.max(np.abs(p[a] / p[b] - 1)) <= 1e-12, (a, b)


def test_ritz_is_an_upper_bound_that_the_inst1_solvers_reach_from_below_or_equal():
    # Rayleigh-Ritz values bound each family's load from above; p* = min over families
    tw = np.array([3.0, 12.0, 40.0])
    coarse = critical_load(tw, 1.5, method="ritz", tol=1e-3)
    fine = critical_load(tw, 1.5, method="collocation")
    assert np.all(coarse >= fine * (1 - 1e-14))
