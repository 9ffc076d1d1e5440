"""Closed forms of spectral_rod.rod.closed_form against the characteristic equation (mpmath).

The references are the extended-precision roots of the paper's characteristic equation, never
the collocation solver and never the formulas under test.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from spectral_rod.rod.characteristic import characteristic_critical_load, family_critical_load
from spectral_rod.rod.closed_form import (
    crossing_closed_form,
    crossing_twist_asymptotic,
    imaginary_beta1_window,
    large_twist_coefficients,
    large_twist_expansion,
    large_twist_limit,
    large_twist_wavenumbers,
)
from spectral_rod.rod.crossings import collocation_crossing, family_crossing

EPS = float(np.finfo(float).eps)


@pytest.mark.parametrize("nu", [1.0, 1.1, 1.5, 3.0, 10.0, 1e3])
def test_limit_is_harmonic_mean_within_rayleigh_bounds(nu):
    p_inf = large_twist_limit(nu)
    assert p_inf == pytest.approx(2 * nu / (1 + nu), rel=1e-15)
    assert 1.0 <= p_inf <= (1 + nu) / 2 + 1e-15  # harmonic <= arithmetic mean
    assert 1 / p_inf == pytest.approx(0.5 * (1 + 1 / nu), rel=1e-15)  # averaged compliance


def _family_p(twist: float, nu: float, family: str) -> float:
    return float(family_critical_load(family, twist, nu, dps=30, scan_step=1 / 256).p_star)


@pytest.mark.parametrize("nu", [1.5, 4.0])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_expansion_error_decays_like_its_first_neglected_order(nu, family):
    # Omega = pi/2 + 2 pi j keeps sin(Omega) = 1: the error ratios then measure the order alone
    twists = [math.pi / 2 + 2 * math.pi * j for j in (8, 16, 32)]
    for order, expected in ((2, 3), (4, 5)):
        err = [abs(_family_p(om, nu, family)
                   - large_twist_expansion(om, nu, order=order, family=family)) for om in twists]
        slope = np.polyfit(np.log(twists), np.log(err), 1)[0]
        assert slope == pytest.approx(-expected, abs=0.2), (order, err)


def test_expansion_at_moderate_twist_is_accurate_to_its_stated_size():
    om, nu = 20 * math.pi + 0.7, 1.5
    exact = float(characteristic_critical_load(om, nu, dps=30).p_star)
    assert abs(exact - large_twist_expansion(om, nu)) < 50 / om**5
    assert exact < large_twist_limit(nu)  # approached from below
    c = large_twist_coefficients(nu)
    assert c.a2 < 0 and c.b3 > 0


def test_p_star_expansion_takes_the_lower_family():
    om, nu = 30.0, 2.0
    assert large_twist_expansion(om, nu) == min(
        large_twist_expansion(om, nu, family=f) for f in ("symmetric", "antisymmetric"))


def test_wavenumber_expansion_error_is_fourth_order():
    nu = 2.0
    twists = [math.pi / 2 + 2 * math.pi * j for j in (8, 16, 32)]
    err = []
    for om in twists:
        r = characteristic_critical_load(om, nu, dps=30)
        b1, b2 = float(mp.sqrt(r.x_minus)), float(mp.sqrt(r.x_plus))
        a1, a2 = large_twist_wavenumbers(om, nu)
        err.append(max(abs(b1 - a1), abs(b2 - a2)))
    assert np.polyfit(np.log(twists), np.log(err), 1)[0] < -3.7


@pytest.mark.parametrize("nu", [1.1, 1.5, 2.0, 5.0, 10.0])
def test_beta1_window_ends_are_where_x_minus_vanishes_on_the_critical_curve(nu):
    w = imaginary_beta1_window(nu)
    assert 0.5 * math.pi < w.y <= math.pi
    assert w.omega_a < math.pi < w.omega_b
    for om, p_closed in ((w.omega_a, w.p_a), (w.omega_b, w.p_b)):
        r = characteristic_critical_load(om, nu, dps=30)
        assert float(r.p_star) == pytest.approx(p_closed, abs=1e-13)
        assert r.family == "symmetric"
        assert abs(float(r.x_minus)) < 1e-12
    inside = characteristic_critical_load(0.5 * (w.omega_a + w.omega_b), nu, dps=30)
    before = characteristic_critical_load(w.omega_a - 1e-3, nu, dps=30)
    after = characteristic_critical_load(w.omega_b + 1e-3, nu, dps=30)
    assert inside.x_minus < 0 < before.x_minus and after.x_minus > 0


def test_window_degenerates_to_pi_for_isotropic_section():
    w = imaginary_beta1_window(1.0)
    assert w.omega_a == pytest.approx(math.pi) and w.omega_b == pytest.approx(math.pi)


@pytest.mark.parametrize(("nu", "n"), [(1.1, 2), (1.5, 2), (1.5, 3), (1.5, 12), (5.0, 4),
                                      (10.0, 2), (10.0, 3)])
def test_crossing_closed_form_matches_newton_on_the_determinants(nu, n):
    closed = crossing_closed_form(n, nu)
    newton = family_crossing(n * math.pi, nu, dps=30)  # verified lowest in both families
    assert float(newton.twist) == pytest.approx(closed.twist, abs=1e-12)
    assert float(newton.p_star) == pytest.approx(closed.p_star, abs=1e-12)
    r = characteristic_critical_load(float(newton.twist), nu, dps=30)
    assert float(mp.sqrt(r.x_minus)) == pytest.approx((n - 1) * math.pi, abs=1e-9)
    assert float(mp.sqrt(r.x_plus)) == pytest.approx((n + 1) * math.pi, abs=1e-9)


def _printed_crossing(n: int, nu: float) -> tuple[mp.mpf, mp.mpf]:
    """Omega_n and p*_n by the module docstring's printed form, p* = 2 nu (N - w)/(nu + 1), in
    60-digit arithmetic (where its cancellation costs nothing)."""
    with mp.workdps(60):
        nu, big_n, big_m = mp.mpf(nu), mp.mpf(n) ** 2 + 1, (mp.mpf(n) ** 2 - 1) ** 2
        den = (3 * nu + 1) * (nu + 3)
        w = (big_n * (nu**2 + 6 * nu + 1)
             + mp.sqrt(big_n**2 * (nu**2 - 1) ** 2 + big_m * (nu + 1) ** 2 * den)) / den
        return mp.pi * mp.sqrt(w), 2 * nu * (big_n - w) / (nu + 1)


@pytest.mark.parametrize("n", [2, 3, 12, 33, 1000, 10_000])
@pytest.mark.parametrize("nu", [1.0, 1.0 + 2**-52, 1.0001, 1.5, 10.0, 1e4])
def test_crossing_closed_form_is_accurate_to_round_off_for_every_n(n, nu):
    # the double-precision form avoids N - w (it lost ~n^2 eps: p* = 1 + 2.3e-13 > (1 + nu)/2
    # at n = 33, nu = 1 + eps, found by the fuzz suite)
    closed = crossing_closed_form(n, nu)
    twist, p = _printed_crossing(n, nu)
    assert abs(closed.twist - twist) <= 4 * EPS * twist
    assert abs(closed.p_star - p) <= 4 * EPS * p
    assert 1.0 <= closed.p_star <= (1.0 + nu) / 2 * (1 + 2 * EPS)


def test_crossing_closed_form_rationalisation_identity():
    # the module docstring's a^2 - R^2 = 4 n^2 (nu + 1)^2 (3 nu + 1)(nu + 3), in sympy
    import sympy as sp

    n, nu = sp.symbols("n nu", positive=True)
    big_n, big_m, den = n**2 + 1, (n**2 - 1) ** 2, (3 * nu + 1) * (nu + 3)
    a, r2 = 2 * big_n * (nu + 1) ** 2, big_n**2 * (nu**2 - 1) ** 2 + big_m * (nu + 1) ** 2 * den
    assert sp.expand(a**2 - r2 - 4 * n**2 * (nu + 1) ** 2 * den) == 0
    # N - w = (N den - N (nu^2 + 6 nu + 1) - R) / den = (a - R) / den:
    assert sp.expand(den - (nu**2 + 6 * nu + 1) - 2 * (nu + 1) ** 2) == 0


def test_crossing_offset_from_n_pi_shrinks_like_n_cubed():
    ns = np.arange(10, 41, 5)
    off = [crossing_closed_form(int(n), 1.5).twist - n * math.pi for n in ns]
    assert all(o > 0 for o in off)
    assert np.polyfit(np.log(ns), np.log(off), 1)[0] == pytest.approx(-3.0, abs=0.05)


def test_input_validation():
    with pytest.raises(ValueError):
        large_twist_expansion(10.0, 1.5, order=1)
    # a complex, float or str order is a type error naming the parameter, whatever its value
    for bad in (4 + 0j, 4.0, "4", None, True):
        with pytest.raises(TypeError, match="order must be an integer"):
            large_twist_expansion(10.0, 1.5, order=bad)
    assert large_twist_expansion(10.0, 1.5, order=np.int64(4)) == large_twist_expansion(
        10.0, 1.5, order=4)
    with pytest.raises(ValueError):
        large_twist_expansion(0.0, 1.5)
    with pytest.raises(ValueError):
        large_twist_expansion(10.0, 1.5, family="even")
    with pytest.raises(ValueError):
        crossing_closed_form(1, 1.5)
    with pytest.raises(ValueError):
        large_twist_limit(0.5)


@pytest.mark.parametrize("nu", [1.5, 10.0])
def test_crossing_offset_asymptotics_has_error_of_order_n_to_the_minus_five(nu):
    ns = np.array([8, 16, 32])
    err = [abs(crossing_closed_form(int(n), nu).twist - crossing_twist_asymptotic(int(n), nu))
           for n in ns]
    assert np.polyfit(np.log(ns), np.log(err), 1)[0] == pytest.approx(-5.0, abs=0.3)
    # and the leading offset itself against the Newton solution of the determinants
    newton = family_crossing(12 * math.pi, nu)
    off = float(newton.twist) - 12 * math.pi
    assert off == pytest.approx(crossing_twist_asymptotic(12, nu) - 12 * math.pi, rel=0.05)


def test_collocation_crossing_error_estimates_bound_the_closed_form_errors():
    """40 random crossings (n = 2..59, nu = 1 + 1e-6 .. 1e3; fixed seed): the collocation
    crossing is within its twist_error and p_error of the closed form, and twist_error is inf
    (not resolved) only where the branches are nearly parallel, nu - 1 < 1e-3 (on 200 random
    crossings: twist errors there up to 3.0e-7 relative; elsewhere err/estimate <= 0.18)."""
    rng = np.random.default_rng(2026)
    unresolved = 0
    for _ in range(40):
        n, nu = int(rng.integers(2, 60)), float(1 + 10 ** rng.uniform(-6, 3))
        closed = crossing_closed_form(n, nu)
        c = collocation_crossing(closed.twist, nu)
        assert abs(c.twist - closed.twist) <= c.twist_error, (n, nu)
        assert abs(c.p_star - closed.p_star) <= c.p_error, (n, nu)
        if math.isinf(c.twist_error):
            assert math.isinf(c.p_error)  # not nan (0 * inf): found by CI at numpy's floor
            unresolved += 1
            assert nu - 1 < 1e-3, (n, nu)
    assert 0 < unresolved < 20


def test_collocation_crossing_flags_an_ill_conditioned_twist():
    """nu = 1 + 1e-6 near 42 pi: the two branches' slopes differ by ~1e-12 and the twist came out
    3.0e-7 (relative) off; its error estimate says it is not resolved. At nu = 1.5, 2 pi it is
    resolved to ~1e-12."""
    bad = collocation_crossing(crossing_closed_form(42, 1.0000010313611107).twist,
                               1.0000010313611107)
    assert math.isinf(bad.twist_error)
    good = collocation_crossing(2 * math.pi, 1.5)
    assert good.twist_error < 1e-11
    assert abs(good.twist - crossing_closed_form(2, 1.5).twist) <= good.twist_error
