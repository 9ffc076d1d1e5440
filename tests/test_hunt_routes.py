"""No silent miss on the forced routes: regression tests and a small sample of the random hunt
(tests/bench/hunt_routes.py runs >= 1,000 points a route)."""

from __future__ import annotations

import functools
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import spectral_rod.rod.increment as increment
from spectral_rod import ConvergenceWarning, critical_load
from spectral_rod.rod.characteristic import characteristic_critical_load
from spectral_rod.rod.characteristic_mode import characteristic_mode

sys.path.insert(0, str(Path(__file__).parent / "bench"))
import hunt_routes

#: The increment route's silent miss in the energy form: error 5.5e-14 at tol 1e-14 with an
#: estimate of 4.8e-16, reported converged.
MISS = (840.689, 1.000954)


def _error(twist: float, nu: float, p: float) -> float:
    return abs(p / float(characteristic_critical_load(twist, nu, dps=40).p_star) - 1)


def test_increment_route_holds_at_the_former_miss():
    # the compliance form carries p* - 1 to ~1e-14 relative at any twist: tol 1e-14 is met
    with warnings.catch_warnings():
        warnings.simplefilter("error", ConvergenceWarning)
        res = critical_load(*MISS, method="increment", tol=1e-14, full_output=True)
    assert bool(res.converged)
    assert _error(*MISS, res.p_star) <= res.error_estimate <= 1e-14


def test_the_estimate_is_that_of_the_compliance_form(monkeypatch):
    # the evidence perturbed: the energy form (coupling nu - 1, p* - 1 to 1e-10 relative at
    # this twist) under the compliance form's estimate is a silent miss again
    energy = functools.partial(increment.galerkin_increments, compliance=False)
    monkeypatch.setattr(increment, "galerkin_increments", energy)
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
