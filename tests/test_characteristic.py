"""The extended-precision characteristic-equation solver against closed forms."""

from __future__ import annotations

import mpmath as mp
import pytest

from spectral_rod.characteristic import characteristic_critical_load, determinant


def test_zero_twist_determinants_vanish_at_euler_loads():
    with mp.workdps(30):
        nu = mp.mpf("1.7")
        pi2 = mp.pi**2
        for fam, lam in [("symmetric", pi2), ("symmetric", 4 * nu * pi2),
                         ("antisymmetric", 4 * pi2), ("antisymmetric", nu * pi2)]:
            assert abs(determinant(fam, lam, mp.mpf(0), nu)) < mp.mpf("1e-25")
        assert abs(determinant("symmetric", 2 * pi2, mp.mpf(0), nu)) > 1e-3


def test_isotropic_rod_root_is_euler_at_any_twist():
    # nu = 1 slightly perturbed: the scan must still find the root next to p = 1
    r = characteristic_critical_load(7.0, 1.0 + 1e-12)
    assert float(r.p_star) == pytest.approx(1.0, abs=1e-10)


def test_root_is_lowest_with_finer_scan():
    for twist, nu in [(2.8, 1.5), (6.5, 1.3), (40.0, 10.0)]:
        a = characteristic_critical_load(twist, nu)
        b = characteristic_critical_load(twist, nu, scan_step=1.0 / 2048)
        assert abs(a.p_star - b.p_star) < mp.mpf("1e-25")


def test_small_twist_matches_its_limit():
    # p* - 1 = O(Omega^2): continuous at zero twist (the removable singularity is handled)
    r = characteristic_critical_load(1e-4, 1.5)
    assert 0 < float(r.p_star) - 1 < 1e-6
