"""Collocation solver of Eq. inst1 against closed forms and the characteristic equation."""

from __future__ import annotations

import itertools
import math
import warnings

import numpy as np
import pytest

from spectral_rod import (
    ConvergenceWarning,
    buckling_mode,
    critical_load,
    critical_wavenumbers,
)

TWISTS = [0.0, 0.3, 1.0, 2.0, 2.8, np.pi, 4.0, 5.5, 2 * np.pi, 7.0, 8.5, 3 * np.pi, 10.0]
NUS = [1.0, 1.05, 1.1, 1.3, 1.5, 1.8, 2.0]


@pytest.mark.parametrize("twist", [0.0, 0.5, np.pi, 7.3, 25.0, 80.0])
def test_isotropic_section_gives_euler_load_for_every_twist(twist):
    # closed form: nu = 1 makes the section isotropic, so twist is a mere relabelling of axes
    assert critical_load(twist, 1.0) == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize("nu", [1.0, 1.1, 1.5, 3.0, 50.0])
def test_zero_twist_gives_euler_load_and_planar_euler_mode(nu):
    assert critical_load(0.0, nu) == pytest.approx(1.0, rel=1e-12)
    mode = buckling_mode(0.0, nu)
    assert np.max(np.abs(mode.omega2)) < 1e-12  # planar: no bending about the stiff axis
    assert np.allclose(mode.omega1, np.sin(np.pi * mode.s), atol=1e-12)
    assert np.max(np.abs(mode.x2)) < 1e-12


def test_agrees_with_characteristic_equation_on_figure1_range(reference):
    worst = 0.0
    for twist, nu in itertools.product(TWISTS, NUS):
        ref = reference(float(twist), float(nu))
        rel = abs(critical_load(twist, nu) - ref) / ref
        worst = max(worst, rel)
        assert rel <= 1e-12, (twist, nu, rel)
    assert worst < 1e-12


def test_array_input_broadcasts_and_scalar_gives_float(reference):
    twist = np.array([[0.5], [3.0], [9.0]])
    nu = np.array([1.1, 1.5])
    p = critical_load(twist, nu)
    assert p.shape == (3, 2)
    assert isinstance(critical_load(3.0, 1.5), float)
    assert p[1, 1] == pytest.approx(reference(3.0, 1.5), rel=1e-12)


def test_negative_twist_is_the_mirror_image(reference):
    assert critical_load(-4.2, 1.4) == pytest.approx(reference(4.2, 1.4), rel=1e-12)


@pytest.mark.parametrize("twist,nu", [(2.0, 1.5), (6.0, 1.3), (10.0, 1.1), (30.0, 2.0)])
def test_spectral_convergence_in_n(reference, twist, nu):
    ref = reference(twist, nu)
    ns = np.arange(8, 62, 4)
    err = np.array([abs(critical_load(twist, nu, n=int(n)) / ref - 1) for n in ns])
    # in the asymptotic range (error < 1e-2, above round-off) each 4 extra degrees gain at
    # least a factor 5: exponential convergence
    pre = err[(err > 1e-13) & (err < 1e-2)]
    assert len(pre) >= 2
    assert np.all(pre[1:] < pre[:-1] / 5)
    assert err[-1] < 1e-13


def test_automatic_resolution_reports_and_meets_tolerance(reference):
    for twist, nu, tol in [(1.0, 1.5, 1e-6), (9.0, 1.3, 1e-10), (20.0, 2.0, 1e-12)]:
        res = critical_load(twist, nu, tol=tol, full_output=True)
        assert bool(res.converged)
        assert float(res.error_estimate) <= tol
        assert abs(float(res.p_star) / reference(twist, nu) - 1) <= tol
    coarse = critical_load(9.0, 1.3, tol=1e-6, full_output=True)
    fine = critical_load(9.0, 1.3, tol=1e-12, full_output=True)
    assert int(coarse.n) < int(fine.n)  # the resolution follows the tolerance


def test_explicit_n_is_used_and_flagged_when_too_coarse():
    res = critical_load(30.0, 1.5, n=16, full_output=True)
    assert int(res.n) == 16
    assert not bool(res.converged)  # under-resolved: flagged, not silently returned


def test_unreachable_tolerance_warns():
    # collocation alone (the public critical_load routes this twist to the characteristic
    # equation): n would have to exceed the cap of 512
    with pytest.warns(ConvergenceWarning):
        res = critical_load(2000.0, 1.5, method="collocation", tol=1e-12, full_output=True)
    assert not bool(res.converged)


def test_mode_centreline_satisfies_moment_balance_and_hinged_ends():
    # independent check of "hinged ends <=> omega = 0 at the ends": integrating the geometric
    # relations with x = 0 at the ends must reproduce the moment balance A omega = -P x_body
    for twist, nu in [(1.5, 1.3), (5.0, 1.5), (12.0, 2.0)]:
        m = buckling_mode(twist, nu)
        lam = np.pi**2 * m.p_star
        xi, eta = -m.omega1 / lam, -nu * m.omega2 / lam
        c, s = np.cos(twist * m.s), np.sin(twist * m.s)
        assert np.allclose(m.x1, xi * c - eta * s, atol=1e-12)
        assert np.allclose(m.x2, xi * s + eta * c, atol=1e-12)
        assert abs(m.omega1[0]) < 1e-12 and abs(m.omega2[-1]) < 1e-12
        # three-dimensional: both curvatures and both displacement components non-zero
        assert min(np.abs(m.omega1).max(), np.abs(m.omega2).max()) > 1e-3
        assert min(np.abs(m.x1).max(), np.abs(m.x2).max()) > 1e-5


def test_mode_parity_matches_family():
    m = buckling_mode(5.0, 1.5)
    flip = slice(None, None, -1)
    sign = 1 if m.family == "symmetric" else -1
    assert np.allclose(m.omega1[flip], sign * m.omega1, atol=1e-12)
    assert np.allclose(m.omega2[flip], -sign * m.omega2, atol=1e-12)


def test_wavenumbers_solve_the_characteristic_equation():
    for twist, nu in [(1.0, 1.5), (2.9, 1.3), (8.0, 1.1)]:
        p = critical_load(twist, nu)
        lam, mu = math.pi**2 * p, math.pi**2 * p / nu
        for b in critical_wavenumbers(p, twist, nu):
            x = (b * b).real if isinstance(b, complex) else b * b
            lhs = (lam - twist**2 - x) * (mu - twist**2 - x)
            assert lhs == pytest.approx(4 * twist**2 * x, abs=1e-9 * lam**2)
    # inside mu < Omega^2 < lambda, beta_1 is imaginary
    b1, _ = critical_wavenumbers(critical_load(3.0, 1.5), 3.0, 1.5)
    assert isinstance(b1, complex) and b1.real == 0.0


@pytest.mark.parametrize("kwargs,exc,word", [
    (dict(twist_angle=float("nan"), nu=1.5), ValueError, "twist_angle"),
    (dict(twist_angle=1.0, nu=float("inf")), ValueError, "nu"),
    (dict(twist_angle="1.0", nu=1.5), TypeError, "twist_angle"),
    (dict(twist_angle=1.0, nu=0.5), ValueError, "nu"),
    (dict(twist_angle=1.0, nu=0.0), ValueError, "nu"),
    (dict(twist_angle=1.0, nu=1.5, n=7), ValueError, "n"),
    (dict(twist_angle=1.0, nu=1.5, n=2.5), TypeError, "n"),
    (dict(twist_angle=1.0, nu=1.5, n=1024), ValueError, "n"),
    (dict(twist_angle=1.0, nu=1.5, tol=0.0), ValueError, "tol"),
    (dict(twist_angle=1e9, nu=1.5), ValueError, "twist_angle"),
    (dict(twist_angle=[1.0, None], nu=1.5), TypeError, "twist_angle"),
])
def test_bad_input_names_the_argument(kwargs, exc, word):
    with pytest.raises(exc, match=word):
        critical_load(**kwargs)


def test_no_warning_on_figure1_range():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        critical_load(np.linspace(0, 10, 41), np.array([[1.1], [1.3], [1.5]]))


@pytest.mark.parametrize("args,exc,word", [
    ((float("nan"), 1.0, 1.5), ValueError, "p_star"),
    ((-1.0, 1.0, 1.5), ValueError, "p_star"),
    (("1", 1.0, 1.5), TypeError, "p_star"),
    ((1.1, float("inf"), 1.5), ValueError, "twist_angle"),
    ((1.1, 1.0, 0.5), ValueError, "nu"),
])
def test_wavenumbers_bad_input_names_the_argument(args, exc, word):
    with pytest.raises(exc, match=word):
        critical_wavenumbers(*args)
