"""Accuracy control of the collocation solver (issue 5): ``tol`` is met, the error estimate is
honest, and the fast eigenvalue path picks the same eigenvalue as the full ``eig`` rule.

Reference: the paper's characteristic equation in mpmath (``reference`` fixture), never the
collocation itself.
"""

from __future__ import annotations

import itertools
import warnings

import numpy as np
import pytest

from spectral_rod import ConvergenceWarning, critical_load
from spectral_rod.rod.collocation.discretisation import family_operator
from spectral_rod.rod.collocation.eigensolver import iteration_allowance, solve_family
from spectral_rod.rod.collocation.reference import physical_eig
from spectral_rod.rod.collocation.resolution import error_estimate, roundoff_floor
from spectral_rod.rod.families import FAMILIES


def collocation_load(*args, **kwargs):
    """The collocation method of the router (forced)."""
    return critical_load(*args, method="collocation", **kwargs)


TWISTS = (0.0, 0.7, 3.1, 9.5, 24.0, 55.0, 100.0)
NUS = (1.0, 1.3, 4.0, 17.0, 100.0)


def _check_grid(reference, twists, nus, tols):
    tw, nv = (np.array(a, dtype=float) for a in zip(*itertools.product(twists, nus),
                                                       strict=True))
    ref = np.array([reference(float(a), float(b)) for a, b in zip(tw, nv, strict=True)])
    for tol in tols:
        with warnings.catch_warnings():
            warnings.simplefilter("error", ConvergenceWarning)  # tol must be reachable here
            res = collocation_load(tw, nv, tol=tol, full_output=True)
        err = np.abs(res.p_star / ref - 1)
        assert res.converged.all()
        bad = np.flatnonzero(err > tol)
        assert bad.size == 0, [(tw[i], nv[i], err[i]) for i in bad]
        # the reported estimate is an upper bound of the actual error
        assert np.all(err <= res.error_estimate), np.max(err / res.error_estimate)


def test_tol_met_on_grid_over_twist_0_100_and_nu_1_100(reference):
    _check_grid(reference, TWISTS, NUS, (1e-6, 1e-10, 1e-12))


@pytest.mark.slow
def test_tol_met_on_dense_grid(reference):
    _check_grid(reference, np.linspace(0.0, 100.0, 23), np.geomspace(1.0, 100.0, 7),
                (1e-4, 1e-8, 1e-12))


#: A loose tol delivers errors within this factor of itself on the random sample below (issue
#: 37: the degree falls with tol; measured largest error / tol there: printed by the test).
DELIVERY_FACTOR = 300.0


def _random_points(size: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    tw, nv = rng.uniform(0.0, 50.0, size), 10.0 ** rng.uniform(0.0, 4.0, size)
    nv[: size // 10] = 1.0 + 10.0 ** rng.uniform(-3.0, 0.0, size // 10)
    return tw, nv


@pytest.mark.parametrize("tol", [1e-12, 1e-10])
def test_error_is_a_tenth_of_tol_on_random_points(tol):
    # up to tuning.TIGHT_TOL the degree holds the tail's part of the estimate to a tenth of tol
    # (resolution's docstring): without it, at tol 1e-12, 226 of the 20,000 collocation points
    # of a 200 x 200 map erred by 1.0-1.6e-13 (Omega(L) > 30), ~1 % of points like these.
    # Reference: the characteristic equation in double precision (its error <= eps (8 +
    # |Omega|), 1.3e-14).
    from spectral_rod.rod.characteristic import double_error_estimate

    tw, nv = _random_points(1500, 20261205)
    res = critical_load(tw, nv, tol=tol, full_output=True)
    ref = critical_load(tw, nv, tol=1e-12, method="characteristic")
    err = np.abs(res.p_star / ref - 1) - double_error_estimate(tw)
    assert set(res.method) <= {"collocation", "increment"} and res.converged.all()
    assert err.max() <= 0.1 * tol, (tw[np.argmax(err)], nv[np.argmax(err)], err.max())


def _loose_tol_evidence(tol: float, tw: np.ndarray, nv: np.ndarray, ref: np.ndarray
                        ) -> tuple[float, float, int]:
    """Largest error / estimate, largest error / tol of forced collocation at `tol`, and its
    silent misses (error > tol while converged). Each point is solved on its own (a scalar
    call): the degree the error model allows for it, without the degree pooling of an array
    call, which solves a group at a higher degree where the cost model finds that cheaper and
    so may deliver more than tol asks."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        res = [collocation_load(float(a), float(b), tol=tol, full_output=True)
               for a, b in zip(tw, nv, strict=True)]
    p, est, conv = (np.array([getattr(r, f) for r in res], dtype=float)
                    for f in ("p_star", "error_estimate", "converged"))
    err, conv = np.abs(p / ref - 1), conv.astype(bool)
    return (float(np.max(err / est)), float(np.max(err[conv]) / tol),
            int(np.sum((err > tol) & conv)))


@pytest.mark.parametrize("tol", [1e-2, 1e-4, 1e-6, 1e-8])
def test_loose_tol_is_met_honestly_and_closely(tol, monkeypatch):
    # issue 37 item 3: above tuning.TIGHT_TOL the degree falls with tol, as far as the error
    # model allows: the estimate bounds the error, no point converged with an error above tol,
    # and the error is within DELIVERY_FACTOR of tol (it was 1e4-1e5 below it). 400 random
    # points, Omega(L) < 50 and nu up to 1e4; tests/bench/hunt_tol.py hunts 2,000 to Omega(L)
    # 800. Reference: the characteristic equation in double precision (an independent
    # formulation; its error <= 1.3e-14 is far below these tols' errors).
    from spectral_rod.rod.collocation import resolution

    tw, nv = _random_points(400, 37)
    ref = critical_load(tw, nv, method="characteristic")
    over_estimate, over_tol, silent = _loose_tol_evidence(tol, tw, nv, ref)
    print(f"tol {tol:g}: error / estimate <= {over_estimate:.3g}, error / tol <= {over_tol:.3g}")
    assert over_estimate <= 1.0 and silent == 0 and over_tol >= 1.0 / DELIVERY_FACTOR
    # the quadratic term carries the bound: at tol 1e-2 a tenth of it leaves errors above the
    # estimate (the evidence this test can fail on; at tighter tols the raised degree hides it
    # on this sample)
    if tol == 1e-2:
        monkeypatch.setattr(resolution, "ERR_QUADRATIC", resolution.ERR_QUADRATIC / 10)
        assert _loose_tol_evidence(tol, tw, nv, ref)[0] > 1.0


def test_estimate_covers_the_eigen_iteration_above_the_default_tol(reference):
    # At a degree far above the a priori one (forced here; pooling does the same) the tail part
    # of the estimate is tiny, and what is left is the eigenvalue iteration's error, which may be
    # up to iteration_rtol(tol): the estimate adds iteration_allowance(tol) for it. Without the
    # allowance the estimate would undercut the error by up to ~6e4 at tol 1e-4 (asserted: this
    # test fails without it), with it the error is <= 0.21 of the estimate (measured 2026-12-02).
    tw, nv = (np.array(a, dtype=float) for a in zip(*itertools.product(
        (55.0, 59.0, 64.0, 73.0, 82.0), (2.15, 10.0, 100.0)), strict=True))
    ref = np.array([reference(float(a), float(b)) for a, b in zip(tw, nv, strict=True)])
    # At 1e-8 the iteration often stops inside the tail part (error / tail part 0.80 on one
    # install, 3.6-4.4 on others: where it stops depends on the engine's rounding), so there
    # only the bound is asserted.
    for tol, undercut in ((1e-4, 1e3), (1e-6, 10.0), (1e-8, None)):
        res = collocation_load(tw, nv, n=64, tol=tol, full_output=True)
        err = np.abs(res.p_star / ref - 1)
        tail_part = res.error_estimate - iteration_allowance(tol)
        print(f"tol {tol:g}: error <= {err.max():.2e}, tail part >= {tail_part.min():.2e}; "
              f"error / estimate <= {np.max(err / res.error_estimate):.3f}, "
              f"error / tail part alone <= {np.max(err / tail_part):.3g}")
        assert res.converged.all() and np.all(err <= res.error_estimate)
        if undercut is not None:  # the allowance is what makes it a bound
            assert np.max(err / tail_part) > undercut
    assert iteration_allowance(1e-12) == iteration_allowance(1e-14) == 0.0


def test_modal_quotient_round_off_is_far_below_the_loose_iteration_tolerance():
    # tuning.LOOSE_DEGREE: from rtol = LOOSE_RTOL on and up to that degree the eigenvalue
    # is the modal quotient; its difference from the pencil quotient (same converged vectors) is
    # K's round-off, largest at small Omega: measured <= 4e-11 at n = 50 and <= 1.1e-10 at n = 64
    from spectral_rod.rod.collocation.eigensolver import lowest_eigenpair
    from spectral_rod.rod.collocation.modal_form import modal_family
    from spectral_rod.rod.collocation.quotient import pencil_rayleigh_quotient
    from spectral_rod.rod.collocation.tuning import LOOSE_DEGREE, LOOSE_RTOL

    rng = np.random.default_rng(5)
    worst = {}
    for n in (50, LOOSE_DEGREE):
        tw, nv = rng.uniform(0.0, 50.0, 120), np.exp(rng.uniform(0.0, np.log(100.0), 120))
        for fam in FAMILIES:
            mf = modal_family(n, fam)
            lam, z, w, ok, _ = lowest_eigenpair(mf, tw, nv, rtol=1e-14)
            pencil = pencil_rayleigh_quotient(mf.op, tw, nv, mf.left_vectors(w),
                                              mf.right_vectors(z))
            assert ok.all()
            worst[n] = max(worst.get(n, 0.0), float(np.max(np.abs(lam / pencil - 1))))
    print("modal vs pencil quotient, max relative difference:", worst)
    assert max(worst.values()) <= 0.02 * LOOSE_RTOL


def test_resolution_grows_with_twist_and_tolerance():
    res = collocation_load(np.array([0.0, 10.0, 100.0]), 1.5, tol=1e-12,
                                    full_output=True)
    assert res.n[0] < res.n[1] < res.n[2]
    coarse = collocation_load(100.0, 1.5, tol=1e-4, full_output=True)
    assert int(coarse.n) < int(res.n[2])


def test_round_off_floor_warns_instead_of_returning_silently():
    # at Omega = 300 the round-off floor eps (32 + 0.3 Omega^2) ~ 6e-12 exceeds tol = 1e-12
    assert roundoff_floor(300.0) > 1e-12
    with pytest.warns(ConvergenceWarning, match="not met"):
        res = collocation_load(300.0, 1.5, tol=1e-12, full_output=True)
    assert not bool(res.converged)
    assert float(res.error_estimate) > 1e-12
    # and a tolerance above the floor is met there without a warning
    with warnings.catch_warnings():
        warnings.simplefilter("error", ConvergenceWarning)
        assert bool(collocation_load(300.0, 1.5, tol=1e-9, full_output=True).converged)


def test_error_estimate_model():
    # linear in the tail for a resolved mode, plus a term quadratic in (n tail) that decides at
    # loose tols, and inf where the mode is not resolved
    from spectral_rod.rod.collocation.resolution import ERR_LINEAR, ERR_QUADRATIC, TAIL_UNRESOLVED

    lin = error_estimate(1e-8, 0.0, 0) - roundoff_floor(0.0, 0)
    assert lin == pytest.approx(ERR_LINEAR * 1e-8)
    assert error_estimate(2e-8, 0.0, 0) - roundoff_floor(0.0) == pytest.approx(2 * lin)
    quad = error_estimate(1e-2, 0.0, 20) - roundoff_floor(0.0, 20)
    assert quad == pytest.approx(ERR_LINEAR * 1e-2 + ERR_QUADRATIC * 0.2**2)
    assert np.isinf(error_estimate(TAIL_UNRESOLVED, 0.0, 20))


@pytest.mark.parametrize("twist, nu, n", [(6.5, 2.5, 16), (17.0, 1.05, 24)])
def test_error_estimate_bounds_the_error_at_a_coarse_degree(twist, nu, n, reference):
    # two cases of the calibration check below (slow), in the default run: the estimate at a
    # fixed, under-resolved degree is >= the error measured against the mpmath reference
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        res = collocation_load(twist, nu, n=n, full_output=True)
    err = abs(float(res.p_star) / reference(twist, nu) - 1)
    assert 1e-13 < err <= float(res.error_estimate) < 1e-2


@pytest.mark.slow
def test_error_estimate_bounds_the_error_at_fixed_degree(reference):
    # the calibration claim of error_estimate, re-measured on points not used to fit it
    worst = 0.0
    for twist, nu in [(1.3, 1.2), (6.5, 2.5), (17.0, 1.05), (42.0, 7.0), (80.0, 30.0)]:
        ref = reference(twist, nu)
        for n in range(8, int(twist / 2) + 60, 2):
            res = collocation_load(twist, nu, n=n, full_output=True)
            err = abs(float(res.p_star) / ref - 1)
            if float(res.error_estimate) < 1e-2:
                worst = max(worst, err / float(res.error_estimate))
    assert worst <= 1.0


@pytest.mark.parametrize("n", [12, 24, 48, 96])
def test_fast_path_picks_the_rule_eigenvalue(n):
    # the shift-and-invert iteration vs the full eig of A^{-1} B with the physical rule
    twist = np.linspace(0.0, 0.8 * n, 33)
    for nu, family in itertools.product((1.0, 1.3, 3.0, 30.0), FAMILIES):
        nv = np.full(twist.size, nu)
        lam, _, _ = solve_family(n, family, twist, nv)
        a, b = family_operator(n, family).pencil(twist, nv)
        theta, _ = physical_eig(np.linalg.solve(a, np.broadcast_to(b, a.shape)))
        rule = 1.0 / theta
        # both are computed in double precision; the full eig loses ~eps Omega^2 at large twist
        assert np.all(np.abs(lam / rule - 1) <= 1e-13 + 1e-15 * twist**2), (nu, family)


def _forced_high_degree_misses(reference, n: int) -> tuple[int, float]:
    """Silent misses and the largest error / estimate of forced collocation at degree n, tol
    1e-14, on 60 random points (Omega(L) log-uniform in [1e-3, 10], nu in [1, 1e4])."""
    rng = np.random.default_rng(512)
    tw, nv = 10.0 ** rng.uniform(-3.0, 1.0, 60), 10.0 ** rng.uniform(0.0, 4.0, 60)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        res = collocation_load(tw, nv, n=n, tol=1e-14, full_output=True)
    ref = np.array([reference(float(a), float(b)) for a, b in zip(tw, nv, strict=True)])
    err = np.abs(res.p_star / ref - 1)
    return int(np.sum((err > 1e-14) & res.converged)), float(np.max(err / res.error_estimate))


def test_forced_degree_512_at_tol_1e_14_does_not_miss_silently(reference, monkeypatch):
    # issue 37 item 5: an explicit n = 512 at tol 1e-14 erred by up to 5.6x tol at 12 of 150
    # random points while reported converged; the degree's part of the round-off floor
    # (resolution.ROUNDOFF_DEGREE; tests/bench/hunt_forced_degree.py hunts 1,000 points) flags
    # them. Without that part the same points miss (the evidence the test can fail on).
    from spectral_rod.rod.collocation import resolution

    silent, ratio = _forced_high_degree_misses(reference, 512)
    assert silent == 0 and ratio <= 1.0, (silent, ratio)
    monkeypatch.setattr(resolution, "ROUNDOFF_DEGREE", np.inf)  # the part removed
    _, ratio_without = _forced_high_degree_misses(reference, 512)
    # the degree's part carries the estimate: without it the error comes >= 10 times closer
    # to the estimate (with numpy 2.x it exceeds it, silently, at several points; with the
    # floors' numpy 1.23 the round-off happens to stay below it)
    assert ratio_without > 10 * ratio, (ratio_without, ratio)
