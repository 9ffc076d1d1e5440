"""Collocation (spectral_rod.critical_load) against the paper's characteristic equation (mpmath),
and the characteristic-equation additions: per-family roots, crossings, the paper's 4x4
determinant, the closed-form mode."""

from __future__ import annotations

import itertools
import math

import mpmath as mp
import numpy as np
import pytest

from spectral_rod import buckling_mode, non_planarity
from spectral_rod.rod.characteristic import (
    characteristic_critical_load,
    determinant,
    family_critical_load,
)
from spectral_rod.rod.characteristic_mode import boundary_determinant_4x4, characteristic_mode
from spectral_rod.rod.collocation import collocation_family_load
from spectral_rod.rod.collocation.eigensolver import solve_family
from spectral_rod.rod.collocation.reference import solve_family_eig
from spectral_rod.rod.critical import critical_load
from spectral_rod.rod.crossings import family_crossing, family_slope

#: Omega(L) in [0, 40] (with the special twists pi, 2 pi, 3 pi and the window around pi) and
#: nu in [1, 10]
TWISTS = [0.0, 0.4, 1.5, 2.7, math.pi, 3.3, 5.0, 2 * math.pi, 7.5, 3 * math.pi, 12.0, 17.3,
          23.0, 29.9, 35.0, 40.0]
NUS = [1.0, 1.05, 1.5, 2.0, 3.7, 6.0, 10.0]


def test_solvers_agree_to_1e12_on_the_grid(reference):
    p = critical_load(np.array(TWISTS)[:, None], np.array(NUS)[None, :])
    for (i, om), (j, nu) in itertools.product(enumerate(TWISTS), enumerate(NUS)):
        ref = reference(float(om), float(nu))
        assert abs(p[i, j] - ref) <= 1e-12 * ref, (om, nu, p[i, j], ref)


@pytest.mark.slow
def test_solvers_agree_to_1e12_on_a_dense_random_grid(reference):
    rng = np.random.default_rng(3)
    om = rng.uniform(0, 40, 300)
    nu = np.exp(rng.uniform(0, math.log(10), 300))
    p = critical_load(om, nu)
    for k in range(om.size):
        ref = reference(float(om[k]), float(nu[k]))
        assert abs(p[k] - ref) <= 1e-12 * ref, (om[k], nu[k])


@pytest.mark.parametrize(("twist", "nu"), [(0.7, 1.5), (2.9, 2.0), (6.0, 10.0), (25.0, 1.3),
                                           (3.0, 1.5)])
def test_critical_load_is_the_lower_family_root(twist, nu):
    both = [family_critical_load(f, twist, nu) for f in ("symmetric", "antisymmetric")]
    low = min(both, key=lambda r: r.p_star)
    ref = characteristic_critical_load(twist, nu)
    assert abs(low.p_star - ref.p_star) < mp.mpf("1e-30")
    assert low.family == ref.family
    # each family's root is its lowest: a 16x finer scan finds the same one
    for r in both:
        fine = family_critical_load(r.family, twist, nu, scan_step=1 / 2048)
        assert abs(fine.p_star - r.p_star) < mp.mpf("1e-30")
        assert 1 <= r.p_star <= nu  # Rayleigh bounds of one family


@pytest.mark.parametrize(("twist", "nu"), [(2.0, 1.5), (9.0, 4.0), (30.0, 1.2)])
def test_family_roots_agree_with_collocation_families(twist, nu):
    for fam in ("symmetric", "antisymmetric"):
        lam, _, _ = solve_family(64, fam, np.array([twist]), np.array([nu]))
        ref = float(family_critical_load(fam, twist, nu).p_star)
        assert lam[0] / math.pi**2 == pytest.approx(ref, rel=1e-12)


@pytest.mark.parametrize(("twist", "nu"), [(1e-10, 4.0), (1e-13, 4.0), (1e-7, 4.001),
                                           (1e-7, 4.005)])
@pytest.mark.parametrize("p_max", [None, 20.0])
def test_family_root_of_a_pair_split_by_small_twist(twist, nu, p_max):
    """At nu near 4 the antisymmetric family's two lowest Euler loads (4 and nu) coincide, and a
    small twist splits them into two roots inside one scan step: the scan raised
    RootNotFoundError, or with p_max = 20 silently returned the next root, 16. The reference is
    the family's collocation eigenvalue (another formulation) by the full eig, which needs no
    gap to the next eigenvalue (the iteration does)."""
    lam, _, _ = solve_family_eig(24, "antisymmetric", np.array([twist]), np.array([nu]))
    r = family_critical_load("antisymmetric", twist, nu, p_max=p_max)
    assert float(r.p_star) == pytest.approx(lam[0] / math.pi**2, rel=1e-13)
    assert 1 <= r.p_star <= nu


def test_one_family_by_collocation_at_a_near_double_root():
    """The iteration's convergence test assumes an isolated eigenvalue: at this random point of
    2026-12-04 (Euler loads 4 and nu 1.9e-8 apart) the antisymmetric family's load at n = 80
    came out 4.7e-9 high through it; collocation_family_load now takes the full eig."""
    twist, nu = 7.650810037481772e-11, 4.000000019061659
    ref = float(family_critical_load("antisymmetric", twist, nu).p_star)
    for n in (24, 80):
        assert collocation_family_load(twist, nu, "antisymmetric", n) == pytest.approx(
            ref, rel=1e-13)


def test_closed_form_mode_of_a_split_pair():
    """The lower root's mode at nu = 4: at Omega(L) = 1e-3 the closed form equals the
    collocation eigenvector (the gap, 2e-3, is far above round-off there), and at 1e-13 (where
    collocation's eigenvector is only good to eps / gap ~ 1e-3) it differs from that by the
    O(Omega) change of the mode (measured 8.8e-5), not by O(1) as the upper root's would."""
    assert _closed_form_vs_collocation("antisymmetric", 1e-3, 4.0) < 1e-12
    s = np.linspace(0.0, 1.0, 61)
    a = characteristic_mode(family_critical_load("antisymmetric", 1e-13, 4.0), 1e-13, 4.0,
                            points=61)
    from spectral_rod.rod.mode import _collocation_fields
    _, _, x1, x2 = _collocation_fields(1e-3, 4.0, 40, "antisymmetric", s)
    u, v = np.concatenate([a.x1, a.x2]), np.concatenate([x1, x2])
    u, v = u / np.linalg.norm(u), v / np.linalg.norm(v)
    assert min(np.abs(u - v).max(), np.abs(u + v).max()) < 2e-4


def test_split_pair_root_is_linear_in_tiny_twist():
    """At nu = 4 the lower root is 4 - c Omega + O(Omega^2): (4 - p)/Omega at Omega(L) = 1e-20
    and 1e-60 (the pair's separation, 80 digits) equals its value at 1e-6, where the ordinary
    scan resolves the pair (a grid point falls between the roots) and collocation confirms it,
    to the O(Omega) correction (measured 1.7e-7 between 1e-6 and 1e-10)."""
    c = [(4 - family_critical_load("antisymmetric", om, 4.0, dps=80).p_star) / om
         for om in (1e-6, 1e-20, 1e-60)]
    lam, _, _ = solve_family_eig(24, "antisymmetric", np.array([1e-6]), np.array([4.0]))
    assert float(c[0]) == pytest.approx((4 - lam[0] / math.pi**2) / 1e-6, rel=1e-8)
    for ci in c[1:]:
        assert abs(ci / c[0] - 1) <= 1e-6


@pytest.mark.parametrize(("lam", "om", "nu"), [(12, 3, 1.5), (11, 2.5, 2), (20, 7, 3),
                                               (10.5, 3.0, 1.5), (15, 0.5, 4), (40, 0.1, 9)])
def test_paper_4x4_determinant_factorises(lam, om, nu):
    with mp.workdps(30):
        lam, om, nu = mp.mpf(lam), mp.mpf(om), mp.mpf(nu)
        d4 = boundary_determinant_4x4(lam, om, nu)
        prod = determinant("symmetric", lam, om, nu) * determinant("antisymmetric", lam, om, nu)
        assert abs(d4 - 16 * om**2 * prod) < mp.mpf("1e-20") * max(1, abs(d4))


@pytest.mark.parametrize(("twist", "nu"), [(1.0, 1.5), (3.0, 1.5), (8.0, 3.0), (20.0, 10.0)])
def test_paper_4x4_determinant_vanishes_at_the_critical_load(twist, nu):
    with mp.workdps(40):
        p = characteristic_critical_load(twist, nu).p_star
        om, nuv = mp.mpf(twist), mp.mpf(nu)

        def d4(q):
            return boundary_determinant_4x4(mp.pi**2 * q, om, nuv)

        root = mp.findroot(d4, p + mp.mpf("1e-6"))
        assert abs(root - p) < mp.mpf("1e-25")
        assert abs(d4(p + mp.mpf("1e-3"))) > mp.mpf("1e-10")


def test_crossing_slopes_agree_with_collocation_differences():
    c = family_crossing(2 * math.pi, 1.5)
    assert c.kind == "corner maximum" and c.left == "symmetric" and c.right == "antisymmetric"
    h = 1e-5
    for fam, slope in c.slopes.items():
        lam = [solve_family(48, fam, np.array([float(c.twist) + s]), np.array([1.5]))[0][0]
               for s in (h, -h)]
        fd = (lam[0] - lam[1]) / (2 * h) / math.pi**2
        assert float(slope) == pytest.approx(fd, rel=1e-6)
    with mp.workdps(30):
        assert family_slope("symmetric", c.p_star, c.twist, mp.mpf(1.5)) > 0


@pytest.mark.parametrize(("twist", "nu"), [(5.0, 1.5), (3.0, 1.5), (9.0, 10.0), (20.0, 2.0)])
def test_closed_form_mode_matches_collocation_mode(twist, nu):
    root = characteristic_critical_load(twist, nu)
    cm = characteristic_mode(root, twist, nu, points=101)
    col = buckling_mode(twist, nu, points=101)
    assert col.family == root.family
    xc = np.column_stack([col.x1, col.x2])
    xm = np.column_stack([cm.x1, cm.x2])
    scale = np.sum(xc * xm) / np.sum(xc * xc)
    assert np.max(np.abs(xc * scale - xm)) < 1e-10
    # hinged ends
    assert abs(cm.x1[0]) + abs(cm.x2[0]) + abs(cm.x1[-1]) + abs(cm.x2[-1]) < 1e-12


def test_closed_form_mode_needs_twist():
    root = characteristic_critical_load(0.0, 1.5)
    with pytest.raises(ValueError):
        characteristic_mode(root, 0.0, 1.5)
    with pytest.raises(ValueError):
        family_critical_load("even", 1.0, 1.5)


def _closed_form_vs_collocation(family: str, twist: float, nu: float, n: int = 40) -> float:
    """Max difference (up to sign) of the unit-norm centrelines (x1, x2) of the closed-form mode
    of family_critical_load's 40-digit root and of the family's collocation eigenvector at
    degree n: two independent solutions of inst1's mode."""
    from spectral_rod.rod.mode import _collocation_fields

    s = np.linspace(0.0, 1.0, 61)
    cm = characteristic_mode(family_critical_load(family, twist, nu), twist, nu, points=61)
    _, _, x1, x2 = _collocation_fields(twist, nu, n, family, s)
    a, b = np.concatenate([cm.x1, cm.x2]), np.concatenate([x1, x2])
    a, b = a / np.linalg.norm(a), b / np.linalg.norm(b)
    return float(min(np.abs(a - b).max(), np.abs(a + b).max()))


@pytest.mark.parametrize("nu", [1.0009, 1.5, 30.0])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_closed_form_mode_at_tiny_twist(family, nu):
    """Down to subnormal twist (found 2026-12-04: before, wrong (O(1)) for |Omega(L)| <= 1e-40
    and nan in buckling_mode at 1e-322, the weights underflowing)."""
    for twist in (5e-324, 1e-100, 1e-40, 1e-20, 0.3):
        assert _closed_form_vs_collocation(family, twist, nu) < 1e-13, twist


@pytest.mark.parametrize(("twist", "nu"), [(3.412869764455022e-117, 12.580203262025508),
                                         (2.190036320285023e-171, 237.5240541225538)])
def test_closed_form_mode_load_refinement(twist, nu):
    """Random cases where a refinement by mpmath's secant (from one start, then from two) left
    the root, so the 40-digit root's error (9e-47 >> Omega) decided the mode: x2 of O(1) at the
    hinges (found 2026-12-04 by comparing 500 random closed-form modes with collocation)."""
    assert _closed_form_vs_collocation("antisymmetric", twist, nu) < 1e-13


@pytest.mark.parametrize("nu", [1.0009, 1.5, 30.0])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_collocation_mode_small_part_at_tiny_twist(family, nu):
    """The O(Omega) field of the collocation eigenvector, relative to itself: non_planarity of
    the centreline against the closed form's (whose out-of-plane part is checked by its Omega
    scaling). Before 2026-12-04 eig's small field was noise ~1e-17 relative to the mode:
    off by 1.1e-5 at Omega(L) = 1e-12 (symmetric, nu = 1.5), 0.41 at nu = 1.0009, 7e25 at
    1e-200 (antisymmetric); now solved from its own block row (measured <= 7e-15; 1.3e-9 at
    nu = 1.0009, where the mode is near-degenerate)."""
    from spectral_rod.rod.mode import _collocation_fields

    s = np.linspace(0.0, 1.0, 201)
    for twist in (1e-6, 1e-12, 1e-200):
        cm = characteristic_mode(family_critical_load(family, twist, nu), twist, nu, points=201)
        _, _, x1, x2 = _collocation_fields(twist, nu, 40, family, s)
        assert non_planarity(x1, x2) == pytest.approx(non_planarity(cm.x1, cm.x2),
                                                      rel=1e-8 if nu < 1.01 else 1e-13), twist


def test_buckling_mode_at_subnormal_twist():
    """The fuzz finding of 2026-12-04 (twist 5e-324, nu 1.00095: nan mode, converged=True):
    the mode is Euler's planar one to within O(twist)."""
    euler = buckling_mode(0.0, 1.0009486502877003, points=51)
    for twist in (5e-324, 1e-322, 1e-300):
        m = buckling_mode(twist, 1.0009486502877003, points=51)
        for f in ("omega1", "omega2", "x1", "x2"):
            assert np.abs(getattr(m, f) - getattr(euler, f)).max() < 1e-15, (twist, f)


def test_closed_form_modes_random_sample():
    """200 random closed-form modes (both families, Omega(L) from 1e-200 to 45, nu from
    1 + 1e-6 to 1e3) against the collocation eigenvectors: the sample that found the load
    refinement's failures on 2026-12-04 (then up to 0.18; now <= 8.5e-15 on 1,100 modes)."""
    rng = np.random.default_rng(21)
    worst = 0.0
    for _ in range(200):
        family = str(rng.choice(["symmetric", "antisymmetric"]))
        twist = float(10 ** rng.uniform(-200, 0)) if rng.random() < 0.3 else \
            float(rng.uniform(0.01, 45))
        nu = float(1 + 10 ** rng.uniform(-6, -1)) if rng.random() < 0.3 else \
            float(10 ** rng.uniform(0, 3))
        n = int(min(96, 40 + 1.2 * twist))
        worst = max(worst, _closed_form_vs_collocation(family, twist, nu, n - n % 2))
    assert worst < 1e-13


@pytest.mark.parametrize("nu", [1.5, 1.0005, 30.0])
def test_closed_form_out_of_plane_part_is_linear_in_tiny_twist(nu):
    """As Omega -> 0 the centreline's out-of-plane part x2 is O(Omega): x2 / Omega has a limit
    (measured: reached to <= 1.4e-12 already at 1e-7, the reference here). Before the working
    precision grew with 2 log10 (1/Omega) it was off by 2e-2 at 1e-20 and 0.3 at 1e-200."""
    def shape(twist):
        m = buckling_mode(twist, nu, points=41, method="characteristic" if nu > 1.001 else "auto")
        assert m.method in ("characteristic", "increment")
        return m.x2 / twist / m.x1[20]  # the mid-span in-plane deflection as the unit

    limit = shape(1e-7)
    assert np.abs(limit).max() > 1e-3  # a genuine O(Omega) part
    for twist in (5e-300, 1e-200, 1e-100, 1e-40, 1e-20, 1e-12):
        assert np.abs(shape(twist) - limit).max() <= 1e-10 * np.abs(limit).max(), twist
