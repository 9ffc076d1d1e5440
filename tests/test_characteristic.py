"""The extended-precision characteristic-equation solver against closed forms."""

from __future__ import annotations

import mpmath as mp
import pytest

from spectral_rod.rod.characteristic import (
    characteristic_critical_load,
    determinant,
    family_critical_load,
)


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


def test_family_double_batch_gives_each_familys_lowest_root():
    """Both families, the higher one too, against the mpmath sign scan of each family (20
    digits, its default finer step): one batch call, points spread over Figure 1's range and
    beyond (1.1 <= nu <= 10), including near the family crossings 2 pi and 3 pi."""
    import numpy as np

    from spectral_rod.rod.characteristic import family_double_batch

    rng = np.random.default_rng(11)
    tw = np.concatenate([rng.uniform(0.1, 20.0, 12), [6.275, 2 * np.pi + 1e-3, 9.43]])
    nu = np.concatenate([rng.uniform(1.1, 10.0, 12), [1.3, 1.5, 1.5]])
    p_sym, p_anti = family_double_batch(tw, nu)
    for i in range(tw.size):
        for fam, got in (("symmetric", p_sym[i]), ("antisymmetric", p_anti[i])):
            ref = float(family_critical_load(fam, float(tw[i]), float(nu[i]), dps=20).p_star)
            assert got == pytest.approx(ref, rel=1e-12), (fam, tw[i], nu[i])


def test_double_determinants_follow_mpmath_in_both_precisions():
    """The one double-precision kernel against the mpmath determinant: float64 to round-off,
    float32 to its own precision, and real wavenumbers NaN exactly where beta_1 is imaginary
    (X_- < 0 well beyond rounding), the same values elsewhere."""
    import numpy as np

    from spectral_rod.rod.characteristic import determinants
    from spectral_rod.rod.wavenumbers import characteristic_roots

    p, om, nu = np.linspace(0.8, 1.6, 17), 3.0, 1.5  # beta_1 imaginary for 0.912 < p < 1.368
    with mp.workdps(30):
        ref = np.array([[float(determinant(f, mp.pi**2 * mp.mpf(float(v)), mp.mpf(om),
                                           mp.mpf(nu))) for v in p]
                        for f in ("symmetric", "antisymmetric")])
    scale = np.abs(ref).max()
    for dtype, tol in ((np.float64, 1e-13), (np.float32, 1e-5)):
        got = np.array(determinants(p, om, nu, dtype=dtype))
        assert got.dtype == dtype and np.abs(got - ref).max() < tol * scale
    # single precision throughout, not float64 cast at the end (that is 1e-7 * scale off at most)
    cast = np.array(determinants(p, om, nu)).astype(np.float32)
    assert np.abs(np.array(determinants(p, om, nu, dtype=np.float32)) - cast).max() > 1e-9 * scale
    lam = np.pi**2 * p
    imaginary = characteristic_roots(lam, lam / nu, om)[0] < -1e-9
    assert imaginary.any() and (~imaginary).any()
    real = np.array(determinants(p, om, nu, real_wavenumbers=True))
    assert (np.isnan(real).all(axis=0) == imaginary).all()
    assert (real[:, ~imaginary] == np.array(determinants(p, om, nu))[:, ~imaginary]).all()
    for bad in (np.float16, None, "foo"):
        with pytest.raises(ValueError, match="dtype"):
            determinants(p, om, nu, dtype=bad)
    with pytest.raises(TypeError, match="real_wavenumbers"):
        determinants(p, om, nu, real_wavenumbers="no")


# --- the certified brackets of the double-precision route ---------------------------------

def _points():
    import numpy as np

    rng = np.random.default_rng(37)
    return np.exp(rng.uniform(np.log(50.0), np.log(1e4), 12)), np.exp(rng.uniform(0, 9.2, 12))


def test_large_twist_brackets_are_certified_and_meet_the_reference():
    import numpy as np

    from spectral_rod.rod.characteristic import _bracketed_batch, characteristic_double

    tw, nv = _points()
    p, fam, ok = _bracketed_batch(tw, nv)
    assert ok.all()
    for i in range(0, tw.size, 3):
        r = characteristic_critical_load(float(tw[i]), float(nv[i]), dps=40)
        assert abs(p[i] / float(r.p_star) - 1) <= 4 * np.finfo(float).eps
        assert ("symmetric", "antisymmetric")[fam[i]] == r.family
        # the scalar path runs the same algorithm in Python floats
        p_one, family = characteristic_double(float(tw[i]), float(nv[i]))
        assert p_one == pytest.approx(p[i], rel=4e-16) and family == r.family


def test_a_bracket_that_misses_the_root_is_not_certified(monkeypatch):
    # the evidence perturbed: expansions shifted by 1e-3 (far beyond the bracket's half-width)
    # leave no sign change in the brackets, the points go to the scan, and p* stays right
    import numpy as np

    import spectral_rod.rod.closed_form as asymptotics
    from spectral_rod.rod.characteristic import (
        _bracketed_batch,
        _bracketed_point,
        characteristic_double_batch,
        double_error_estimate,
    )

    tw, nv = _points()
    right = characteristic_double_batch(tw, nv)[0]
    real = asymptotics.family_expansions
    monkeypatch.setattr(asymptotics, "family_expansions",
                        lambda om, nu: tuple(p + 1e-3 for p in real(om, nu)))
    assert not _bracketed_batch(tw, nv)[2].any()
    assert _bracketed_point(float(tw[0]), float(nv[0])) is None
    scanned = characteristic_double_batch(tw, nv)[0]
    assert np.all(np.abs(scanned / right - 1) <= double_error_estimate(tw))


def test_family_bound_brackets_near_nu_1():
    import numpy as np

    from spectral_rod.rod.characteristic import _family_bound_batch

    tw = np.array([0.0, 1e-6, 0.5, 3.0, 20.0, 49.0])
    nv = 1.0 + np.array([1e-3, 1e-12, 1e-8, 1e-5, 1e-4, 1e-3])
    p, _, ok = _family_bound_batch(tw, nv)
    assert ok.all()
    for i in range(tw.size):
        r = characteristic_critical_load(float(tw[i]), float(nv[i]), dps=40)
        assert abs(p[i] / float(r.p_star) - 1) <= 8 * np.finfo(float).eps, i
