"""No silent miss on the forced routes: regression tests and a small sample of the random hunt
(tests/bench/hunt_routes.py runs >= 1,000 points a route)."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import spectral_rod.increment as increment
from spectral_rod import ConvergenceWarning, critical_load
from spectral_rod.characteristic import characteristic_critical_load
from spectral_rod.closed_form import characteristic_mode

sys.path.insert(0, str(Path(__file__).parent / "bench"))
import hunt_routes

#: A point where the increment route errs 5.5e-14 (tol 1e-14 cannot be met there).
MISS = (840.689, 1.000954)


def _error(twist: float, nu: float, p: float) -> float:
    return abs(p / float(characteristic_critical_load(twist, nu, dps=40).p_star) - 1)


def test_increment_route_flags_what_it_cannot_certify():
    with pytest.warns(ConvergenceWarning, match="method increment"):
        res = critical_load(*MISS, method="increment", tol=1e-14, full_output=True)
    err = _error(*MISS, res.p_star)
    assert err > 1e-14 and not bool(res.converged)  # the miss is real, and it is flagged
    assert err <= res.error_estimate
    # at the default tol the same point is met and says so
    with warnings.catch_warnings():
        warnings.simplefilter("error", ConvergenceWarning)
        assert bool(critical_load(*MISS, method="increment", full_output=True).converged)


def test_without_the_twist_term_the_miss_is_silent(monkeypatch):
    # the evidence perturbed: an estimate without its twist term reports the miss converged
    monkeypatch.setattr(increment, "TWIST_ERROR", 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ConvergenceWarning)
        res = critical_load(*MISS, method="increment", tol=1e-14, full_output=True)
    assert bool(res.converged) and _error(*MISS, res.p_star) > 1e-14


@pytest.mark.parametrize("route", hunt_routes.ROUTES)
def test_a_sample_of_the_hunt_finds_no_miss(route):
    r = hunt_routes.hunt(route, 12, seed=5)
    assert r.silent_misses == 0 and r.estimate_misses == 0, r
    assert r.max_error <= 1e-13, r


def test_characteristic_mode_accepts_every_reference_root():
    # the reference solves up to |Omega(L)| = 1e6; its mode must accept what it returns
    root = characteristic_critical_load(2e4, 1.5, dps=30)
    mode = characteristic_mode(root, 2e4, 1.5, points=11)
    assert np.isfinite(mode.x1).all() and abs(mode.x1[0]) < 1e-10 and abs(mode.x1[-1]) < 1e-10
    with pytest.raises(ValueError, match="twist_angle"):
        characteristic_mode(root, 2e6, 1.5)
