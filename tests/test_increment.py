"""critical_load_increment: p* - 1 to full relative accuracy.

References are independent of the code under test: the paper's characteristic equation in
mpmath at 60 digits, and closed-form leading terms of the two perturbation expansions.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

from spectral_rod.rod.characteristic import characteristic_critical_load
from spectral_rod.rod.increment import critical_load_increment, galerkin_increments

sys.path.insert(0, str(Path(__file__).parent / "bench"))
import hunt_increment

NU_MINUS_1 = (1e-8, 1e-6, 1e-4, 1e-2, 0.5, 9.0, 9999.0)
TWISTS = (1e-6, 1e-4, 1e-2, 1.0, 3.0, 10.0, 30.0)


def ref_increment(twist: float, nu: float, dps: int = 60) -> float:
    """p* - 1 from the characteristic equation at `dps` digits (subtraction done in mpmath)."""
    return float(characteristic_critical_load(twist, nu, dps=dps).p_star - 1)


@pytest.mark.parametrize("twist", TWISTS)
def test_relative_accuracy_on_the_grid(twist):
    for e in NU_MINUS_1:
        ref = ref_increment(twist, 1 + e)
        got = critical_load_increment(twist, 1 + e)
        # documented to 1e-12 over the whole range
        assert abs(got / ref - 1) <= 1e-12, (twist, e, got, ref)


def test_corner_matches_double_expansion():
    # nu -> 1, Omega -> 0: p* - 1 = (nu - 1) Omega^2 (pi^2 - 6)/(12 pi^2) (1 + O(nu-1, Omega^2))
    e, om = 1e-8, 1e-6
    lead = e * om**2 * (math.pi**2 - 6) / (12 * math.pi**2)
    assert abs(critical_load_increment(om, 1 + e) / lead - 1) < 1e-7


def test_small_twist_matches_second_order_perturbation():
    # Omega -> 0 at fixed nu: p* - 1 = Omega^2 l2 / pi^2 with (k = pi/sqrt(nu))
    # l2 = 1 - 4 pi^2/(pi^2 - k^2) + 16 pi^2 k cot(k/2)/(pi^2 - k^2)^2 (body-frame perturbation)
    with mp.workdps(40):
        for nu in (1.5, 3.0, 1e4):
            k = mp.pi / mp.sqrt(nu)
            pi2 = mp.pi**2
            l2 = 1 - 4 * pi2 / (pi2 - k**2) + 16 * pi2 * k * mp.cot(k / 2) / (pi2 - k**2) ** 2
            om = 1e-5
            lead = float(om**2 * l2 / pi2)
            assert abs(critical_load_increment(om, nu) / lead - 1) < 1e-8


def test_first_order_in_nu_minus_one_at_large_twist():
    # p* - 1 = (nu - 1)(1/2 - |J|) + O((nu-1)^2), J = pi^2 sin(Om)/(2 Om (pi^2 - Om^2))
    e = 1e-7
    for om in (0.5, 2.0, 7.0, 40.0):
        j = math.pi**2 * math.sin(om) / (2 * om * (math.pi**2 - om**2))
        lead = e * (0.5 - abs(j))
        assert abs(critical_load_increment(om, 1 + e) / lead - 1) < 1e-5


def test_exact_zeros_evenness_and_broadcasting():
    assert critical_load_increment(0.0, 2.0) == 0.0
    assert critical_load_increment(5.0, 1.0) == 0.0
    assert critical_load_increment(-0.3, 1.2) == critical_load_increment(0.3, 1.2)
    out = critical_load_increment(np.array([[1e-3], [2.0]]), np.array([1 + 1e-6, 1.5]))
    assert out.shape == (2, 2)
    assert np.all(out > 0)


def test_large_twist_small_anisotropy_uses_the_increment_formulation():
    # p* - 1 ~ 5e-5 < 1e-3: computed directly, not as critical_load - 1
    ref = ref_increment(100.0, 1 + 1e-4, dps=50)
    assert abs(critical_load_increment(100.0, 1 + 1e-4) / ref - 1) <= 1e-9


@pytest.mark.slow
def test_increment_at_twist_1000():
    for e in (1e-8, 1e-4):
        ref = ref_increment(1000.0, 1 + e, dps=50)
        assert abs(critical_load_increment(1000.0, 1 + e) / ref - 1) <= 1e-9


@pytest.mark.parametrize("twist", [1e-6, 0.3, 2 * math.pi, 17.77, 49.0, 300.0])
def test_closed_form_moments_equal_the_quadrature(twist):
    # the batched route's closed forms (sinc sums) against the Gauss-Legendre quadrature of the
    # same integrals: two independent evaluations of every omega2 moment
    from spectral_rod.rod.increment import _moments_closed, _moments_dense, bucket

    n = bucket(twist)
    om = np.array([twist, 0.5 * twist])
    a, b = _moments_dense(om, n), _moments_closed(om, n)
    # 1e-13 of the largest entry: round-off of sums over q ~ 1.6 N + Omega/2 + 40 nodes
    for i in range(om.size):
        scale = np.abs(a.g22(i)).max()
        assert np.abs(a.g22(i) - b.g22(i)).max() <= 1e-13 * scale
        assert np.abs(a.g21[i] - b.g21[i]).max() <= 1e-13 * scale
        assert np.abs(a.g11[i] - b.g11[i]).max() <= 1e-13  # entries ~0.5
    y = np.random.default_rng(1).standard_normal((om.size, a.dense.shape[1], 2))
    assert np.abs(a.g22_times(y) - b.g22_times(y)).max() <= 1e-13 * np.abs(a.g22_times(y)).max()


def test_a_point_does_not_depend_on_the_other_points_of_the_call():
    # stacks iterate until their slowest point converges; a finished point must keep its value,
    # so on one route (here the closed forms: > DENSE_POINTS points share each bucket) a point's
    # result is the same to the last bit whatever else is in the call
    from spectral_rod.rod.increment import DENSE_POINTS, bucket, galerkin_increments

    rng = np.random.default_rng(3)
    tw, nu = rng.uniform(20.0, 23.0, 40), 1.0 + 10.0 ** rng.uniform(-8.0, -3.0, 40)
    assert len({bucket(t) for t in tw}) == 1 and tw.size // 2 > DENSE_POINTS
    whole = galerkin_increments(tw, nu)[0]
    np.testing.assert_array_equal(whole[::2], galerkin_increments(tw[::2], nu[::2])[0])
    np.testing.assert_array_equal(whole[::-1], galerkin_increments(tw[::-1], nu[::-1])[0])
    # a point alone takes the few-point route (quadrature moments): equal to rounding
    alone = np.array([galerkin_increments(tw[i:i + 1], nu[i:i + 1])[0][0] for i in range(9)])
    assert np.max(np.abs(alone / whole[:9] - 1)) <= 1e-13


@pytest.mark.parametrize("twist", TWISTS)
def test_relative_accuracy_of_a_stack(twist):
    # the same grid as one array call: more than DENSE_POINTS points share each bucket, so the
    # stacked route (closed-form moments) answers; reference: mpmath characteristic equation
    from spectral_rod.rod.increment import DENSE_POINTS

    small = [e for e in NU_MINUS_1 if e <= 1e-3]
    nu = 1.0 + np.repeat(small, 2)
    assert nu.size > DENSE_POINTS
    got = critical_load_increment(np.full(nu.size, twist), nu)
    ref = np.repeat([ref_increment(twist, 1 + e) for e in small], 2)
    assert np.max(np.abs(got / ref - 1)) <= 1e-12


@pytest.mark.parametrize(("twist", "nu"), [(1e-144, 1 + 1e-14), (1e-146, 1 + 1e-14),
                                           (1e-148, 1 + 1e-14), (1e-153, 1e4), (1e-159, 1e4),
                                           (1e-160, 101.0), (1e-101, 101.0)])
def test_increment_at_vanishing_twist_is_quadratic(twist, nu):
    """Far below any validated twist p* - 1 = c(nu) Omega^2 (p* is even and analytic in Omega;
    the quartic term is ~1e-12 relative at 1e-6): the reference is c from the mpmath
    characteristic equation at Omega(L) = 1e-6. Down to the subnormal range (where the spacing
    of doubles, 4.9e-324, limits any answer) the increment keeps it, and it is never negative
    (unscaled moments give -3.7e-4 relative at 1e-146, 0.0 at 1e-148, -1.7e-316 at 1e-159)."""
    c = ref_increment(1e-6, nu, dps=80) / 1e-12
    ref = c * twist * twist
    got = critical_load_increment(twist, nu)
    assert got >= 0.0
    assert abs(got - ref) <= 1e-9 * ref + 8 * 5e-324, (got, ref)


def test_a_sample_of_the_random_hunt_holds_1e_12():
    # tests/bench/hunt_increment.py runs 1,000 points; here 30 of its range
    h = hunt_increment.hunt(30, seed=7)
    assert h.misses == 0 and h.error.max() <= hunt_increment.GAIN_TOL, h.error.max()


@pytest.mark.parametrize(("twist", "nu"),
                         [(2e-3, 9e3), (2.98128e-06, 3948.27), (840.689, 1.000954)])
def test_the_compliance_form_holds_where_the_energy_form_loses_digits(twist, nu):
    # the energy form's coupling nu - 1 (up to 1e4) cancels in its Schur complement, and its
    # moments lose accuracy at large twist: 5e-12..1e-10 relative here; the compliance form's
    # coupling 1 - 1/nu < 1 does not
    ref = ref_increment(twist, nu)
    tw, nv = np.array([twist]), np.array([nu])
    energy = galerkin_increments(tw, nv, compliance=False)[0][0]
    compliance = galerkin_increments(tw, nv)[0][0]
    assert abs(energy / ref - 1) > 1e-12
    assert abs(compliance / ref - 1) <= 1e-13
