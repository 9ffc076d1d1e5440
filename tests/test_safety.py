"""Issue 15: the cases a reliability reviewer found, one regression test each -- no silent wrong
answer, no hang, clear errors that name the argument, bounded memory."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import spectral_rod as sr
from spectral_rod import ConvergenceWarning


def test_forced_coarse_degree_warns_flags_and_stays_in_bounds():
    # was: 38.008 (true ~1.13, above the bound 1.15), no warning
    with pytest.warns(ConvergenceWarning, match="not met"):
        res = sr.critical_load(30.0, 1.3, n=8, full_output=True)
    assert not res.converged and 1.0 <= res.p_star <= 1.15


def test_forced_coarse_degree_mode_is_flagged():
    # was: p* 851.85 and no flag at all
    with pytest.warns(ConvergenceWarning):
        mode = sr.buckling_mode(100.0, 1.3, n=8)
    assert not mode.converged and 1.0 <= mode.p_star <= 1.15


@pytest.mark.parametrize("twist", [50.0, 60.0, 1000.0, 1e4])
def test_isotropic_rod_never_below_euler(twist):
    # was: 0.9999999999999998 at 50, 0.9999999999999989 at 60
    assert sr.critical_load(twist, 1.0) >= 1.0


@pytest.mark.parametrize("kwargs, exc", [
    ({"scan_step": 1e300}, ValueError), ({"scan_step": math.nan}, ValueError),
    ({"scan_step": 0.0}, ValueError), ({"scan_step": -0.01}, ValueError),
    ({"scan_step": 1e-300}, ValueError), ({"dps": 0}, ValueError), ({"dps": -5}, ValueError),
    ({"dps": True}, TypeError), ({"dps": 10**9}, ValueError), ({"dps": "30"}, TypeError),
    ({"p_max": 0.5}, ValueError),
])
@pytest.mark.parametrize("func", ["characteristic_critical_load", "family_critical_load"])
def test_reference_knobs_are_validated_before_any_work(func, kwargs, exc, monkeypatch):
    # was: a root that is not the lowest (scan_step=1e300), nan, or a hang (12 cases)
    import spectral_rod.rod.characteristic as ch

    f = getattr(sr, func)
    args = ("symmetric", 3.0, 100.0) if func == "family_critical_load" else (3.0, 100.0)
    with monkeypatch.context() as m:  # the root search must not even start
        m.setattr(ch, "_mp_root", _must_not_run("the root search"))
        with pytest.raises(exc, match=next(iter(kwargs))):
            f(*args, **kwargs)


def test_closed_forms_refuse_arguments_outside_their_validity():
    with pytest.raises(ValueError, match=r"\bn\b"):
        sr.crossing_closed_form(10**8, 1.3)  # was: p* = 0.0
    with pytest.raises(ValueError, match="twist_angle"):
        sr.large_twist_expansion(1e-80, 1.3)  # was: -inf


@pytest.mark.parametrize("twist", [1000.0, 3000.0, 1e4])
def test_large_twist_mode_is_the_characteristic_route(twist, monkeypatch):
    # was: 118 s at 1000, > 120 s at 3000, 8 GB exhausted at 1e4 (collocation at n = 512 and a
    # dense fit): the closed-form route answers, and no collocation is ever entered
    import spectral_rod.rod.mode as mode_module

    monkeypatch.setattr(mode_module, "_collocation_fields", _must_not_run("collocation"))
    monkeypatch.setattr(mode_module, "collocation_mode_coefficients",
                        _must_not_run("collocation"))
    mode = sr.buckling_mode(twist, 1.3, tol=1e-10)  # 1e-12 is below the route's eps |Omega|
    assert mode.method == "characteristic" and mode.converged
    assert np.all(np.isfinite(mode.omega1)) and abs(mode.x1[-1]) < 1e-12


def test_output_grid_size_is_checked_before_the_solve(monkeypatch):
    import spectral_rod.rod.mode as mode_module

    with monkeypatch.context() as m:
        m.setattr(mode_module, "solve_points", _must_not_run("the solve"))
        with pytest.raises(ValueError, match="points"):
            sr.buckling_mode(5.0, 1.5, points=10**8)
    assert sr.buckling_mode(5.0, 1.5, points=np.int64(201)).s.size == 201


def test_increment_at_large_twist_is_bounded(monkeypatch):
    # was: 5.5 s a point at (1000, 1.0005), a Cholesky factorisation per Newton step of a
    # ~1400 x 1400 system; the cost is bounded by one basis of bucket(1000) sine modes and the
    # fixed-point solves (nu - 1 <= FIXED_POINT_MAX_E): no factorisation at all
    import spectral_rod.rod.increment as inc

    sizes = []
    real = inc._bucket_increments
    monkeypatch.setattr(inc, "_bucket_increments",
                        lambda om, e, n, *form: sizes.append(n) or real(om, e, n, *form))
    monkeypatch.setattr(inc, "_newton_cholesky", _must_not_run("a Cholesky factorisation"))
    d = sr.critical_load_increment(1000.0, 1.0005)
    assert sizes == [inc.bucket(1000.0)] and sizes[0] <= 2 * 1000 / math.pi + 56
    assert 0 < d < 2.5e-4 * 1.01


@pytest.mark.parametrize("call, name", [
    (lambda: sr.large_twist_limit(np.array([1.5, 2.0])), "nu"),
    (lambda: sr.imaginary_beta1_window([1.5, 2.0]), "nu"),
    (lambda: sr.family_crossing(2 * math.pi, 1.5, dps="30"), "dps"),
    (lambda: sr.family_crossing(2 * math.pi, 1.5, p_guess=True), "p_guess"),
    (lambda: sr.ring_buckling(2, 1.5, raise_on_failure="no"), "raise_on_failure"),
    (lambda: sr.ring_buckling(2, 1.5, max_frequency=np.float64(30.0)), "max_frequency"),
    (lambda: sr.critical_load([1.0, 2.0], [1.1, 1.2, 1.3]), "twist_angle, nu"),
    (lambda: sr.critical_wavenumbers(1.1, [1.0, 2.0], [1.5, 1.6, 1.7]), "p_star"),
    # found by the hunt of 2026-12-04: each gave an internal error, nan/inf or a silent answer
    (lambda: sr.critical_wavenumbers(1e160, 5.0, 1.5), "p_star"),
    (lambda: sr.beta_difference(1e160, 5.0, 1.5), "p_star"),
    (lambda: sr.crit2(1e200, 1.5), "N"),
    (lambda: sr.ring_formula_load(10**400, 2.0), "N"),
    (lambda: sr.ring_critical_load(1, 2.0, tol=10**400), "tol"),
    (lambda: sr.critical_load(5.0, 1.5, tol=10**400), "tol"),
    (lambda: sr.out_of_plane_untwisted(10**400, 1.0), "A"),
    (lambda: sr.critical_load(np.timedelta64(5), 1.5), "twist_angle"),
    (lambda: sr.critical_load(np.ma.masked_array([1.0, 2.0], [False, True]), 1.5),
     "twist_angle"),
    (lambda: sr.load_figure1(""), "path"),
    (lambda: sr.ring_formulation_agreement(None), "cases"),
    (lambda: sr.ring_formulation_agreement([dict(N=1, nu=1.3, e_raito=2.0)]), "e_raito"),
    (lambda: sr.increasing_up_to([2.0, 1.0, 0.0], [1.0, 2.0, 3.0], 1.0), "grid"),
    (lambda: sr.settling_point([0.0, 2.0, 1.0], [1.0, 2.0, 3.0], 1.0), "grid"),
    (lambda: sr.destabilisation_threshold(1.0, "axis", [2.0, 4.0], twists=np.array(2.0)),
     "twists"),
    (lambda: sr.destabilisation_threshold(1.0, "hydrostatic", [2.0, 4.0], twists=(0, 1),
                                          loads=np.array([[-3.0, 2.0], [-3.0, 3.5]])),
     "positive critical loads, got min -3"),
    (lambda: sr.ring_formulation_row(None, None), "ref must be a RingBuckling"),
    (lambda: sr.analyse_figure1(sr.load_figure1(), p_star_fn=lambda t, n: np.full(np.shape(t),
                                                                                  np.nan)),
     "p_star_fn must return finite"),
])
def test_errors_name_the_argument(call, name):
    with pytest.raises((ValueError, TypeError), match=name):
        call()


def test_numpy_scalars_are_accepted():
    # were rejected: points=np.int64(201), tol=np.float32(1e-10)
    q = sr.ring_critical_load(2, 1.5, tol=np.float32(1e-10))
    assert q == pytest.approx(sr.ring_critical_load(2, 1.5), rel=1e-9)
    assert sr.critical_load(np.float32(5.0), np.float64(1.5), tol=np.float32(1e-10)) > 1


def _agreement(tw, nv, tol=1e-12):
    """Scalar calls against one array call: (relative differences, larger of the two error
    estimates, round-off part, equal-degree mask, points pooled at a higher degree)."""
    arr = sr.critical_load(tw, nv, tol=tol, full_output=True)
    one = [sr.critical_load(float(a), float(b), tol=tol, full_output=True)
           for a, b in zip(tw, nv, strict=True)]
    p_one, n_one = np.array([r.p_star for r in one]), np.array([r.n for r in one])
    larger = np.maximum(arr.error_estimate, [r.error_estimate for r in one])
    return (np.abs(arr.p_star - p_one) / p_one, larger,
            np.finfo(float).eps * (32 + 0.3 * tw**2), arr.n == n_one, int((arr.n > n_one).sum()))


def _agreement_points(points):
    if points == "figure1":
        d = sr.load_figure1()
        return d["twist_angle"].to_numpy(), d["nu"].to_numpy()
    rng = np.random.default_rng(3)
    return rng.uniform(0, 50, 3000), rng.uniform(1.001, 100, 3000)


@pytest.mark.parametrize("points", ["figure1", "random"])
def test_scalar_and_array_calls_agree_to_the_stated_bound(points, capsys):
    # critical_load's docstring: within the larger of the two error estimates (an array call may
    # pool a point at a higher degree), within the round-off part at equal degree; the figures
    # it quotes are the ones printed here
    tw, nv = _agreement_points(points)
    diff, larger, roundoff, same, pooled = _agreement(tw, nv)
    assert np.all(diff <= larger) and np.all((diff <= roundoff)[same])
    with capsys.disabled():
        print(f"\n{points}: {pooled} pooled, max diff {diff.max():.2g}, "
              f"{(diff / larger).max():.2f} of the larger estimate, "
              f"{(diff / roundoff)[same].max():.2f} of the round-off part at equal degree")
    assert sr.critical_load(5.0, 1.5) == sr.critical_load(np.array([5.0]), 1.5)[0]


@pytest.mark.parametrize("tol", [1e-8, 1e-4])
@pytest.mark.parametrize("points", ["figure1", "random"])
def test_scalar_and_array_calls_agree_at_a_looser_tol(points, tol, capsys):
    # critical_load's docstring: at a looser tol, within the round-off part plus the iteration
    # tolerance at equal degree (the round-off part alone is exceeded there: printed)
    from spectral_rod.rod.collocation.eigensolver import iteration_rtol

    tw, nv = _agreement_points(points)
    diff, larger, roundoff, same, _ = _agreement(tw, nv, tol)
    bound = roundoff + iteration_rtol(tol)
    assert np.all(diff <= larger) and np.all((diff <= bound)[same])
    with capsys.disabled():
        print(f"\n{points}, tol {tol:g}: max diff {diff.max():.2g}, "
              f"{(diff / larger).max():.3f} of the larger estimate; at equal degree "
              f"{(diff / bound)[same].max():.3f} of round-off + iteration_rtol, "
              f"{(diff / roundoff)[same].max():.3g} of the round-off part alone")


@pytest.mark.slow
def test_a_million_random_points_stay_within_the_memory_bound():
    import tracemalloc

    rng = np.random.default_rng(1)
    tw, nv = rng.uniform(-1e4, 1e4, 10**6), np.minimum(1 + 10 ** rng.uniform(-8, 4, 10**6), 1e4)
    tracemalloc.start()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        p = sr.critical_load(tw, nv)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    print(f"10^6 random points: traced peak {peak / 1e6:.0f} MB")
    assert peak < 500e6, f"peak {peak / 1e6:.0f} MB"
    assert np.all((p >= 1) & (p <= (1 + nv) / 2))


def test_a_two_point_mode_grid_is_normalised():
    # found by the fuzz suite: points=2 gave the two hinges only (omega = 0), scale 0 -> NaN
    m = sr.buckling_mode(0.0, 2.0, points=2)
    assert np.all(np.isfinite(m.omega1)) and np.all(np.isfinite(m.x1))
    fine = sr.buckling_mode(0.0, 2.0)
    assert m.x1 == pytest.approx(fine.x1[[0, -1]], abs=1e-14)


def test_a_two_point_closed_form_mode_is_scaled_like_a_fine_one():
    # found in review: characteristic_mode scaled by the output grid; at the two hinges x = 0
    # and the "mode" was rounding noise scaled to 1
    from spectral_rod.rod.characteristic import characteristic_critical_load
    from spectral_rod.rod.characteristic_mode import characteristic_mode

    root = characteristic_critical_load(3.0, 2.0)
    coarse, fine = (characteristic_mode(root, 3.0, 2.0, points=k) for k in (2, 201))
    assert np.max(np.abs(coarse.x1)) <= 1e-14 and np.max(np.abs(coarse.x2)) <= 1e-14
    assert np.max(np.hypot(fine.x1, fine.x2)) == pytest.approx(1.0, abs=1e-3)


def _must_not_run(what: str):
    """A stand-in that fails the test if `what` is reached."""
    def fail(*args, **kwargs):
        raise AssertionError(f"{what} was reached")
    return fail


@pytest.mark.parametrize(("twist", "nu", "where"), [(0.5, 1.0005, "_closed_form_fields"),
                                                     (5.0, 1.5, "_collocation_fields")])
def test_a_non_finite_mode_raises(twist, nu, where, monkeypatch):
    """The guard behind the fuzz finding of 2026-12-04 (a nan mode returned converged=True):
    fields that come out nan or zero raise instead of being returned."""
    import spectral_rod.rod.mode as mode

    real = getattr(mode, where)
    for broken in (np.nan, 0.0):
        monkeypatch.setattr(mode, where, lambda *a, b=broken, **k: tuple(
            np.full_like(f, b) for f in real(*a, **k)))
        with pytest.raises(sr.ConvergenceError, match="no finite nonzero mode"):
            sr.buckling_mode(twist, nu)
    monkeypatch.setattr(mode, where, real)
    assert np.isfinite(sr.buckling_mode(twist, nu).omega1).all()


def test_a_non_finite_closed_form_mode_raises(monkeypatch):
    import spectral_rod.rod.characteristic_mode as cf

    root = sr.characteristic_critical_load(5.0, 1.5)
    size = 2 + cf.SCALE_POINTS  # the output grid of points=2 and the fixed scale grid
    monkeypatch.setattr(cf, "mode_fields", lambda *a, **k: (np.zeros(size), np.zeros(size)))
    with pytest.raises(sr.ConvergenceError, match="no finite nonzero mode"):
        cf.characteristic_mode(root, 5.0, 1.5, points=2)


def test_a_directory_is_not_the_figure_data(tmp_path):
    with pytest.raises(sr.ReferenceDataError, match="is a directory"):  # IsADirectoryError before
        sr.load_figure1(tmp_path)


def test_characteristic_mode_at_negative_twist_is_the_mirror_image():
    """-Omega: omega2 -> -omega2, x2 -> -x2 (as buckling_mode, by collocation, says); before
    2026-12-04 the +|Omega| mode came back, with x2 1.2 away from collocation's."""
    root = sr.characteristic_critical_load(-5.0, 1.5)
    cm = sr.characteristic_mode(root, -5.0, 1.5, points=401)
    m = sr.buckling_mode(-5.0, 1.5, points=401)
    a, b = np.r_[cm.x1, cm.x2], np.r_[m.x1, m.x2]
    a, b = a / np.abs(a).max(), b / np.abs(b).max()
    assert min(np.abs(a - b).max(), np.abs(a + b).max()) < 1e-10
    plus = sr.characteristic_mode(sr.characteristic_critical_load(5.0, 1.5), 5.0, 1.5, points=401)
    assert np.abs(plus.x1 - cm.x1).max() < 1e-14 and np.abs(plus.x2 + cm.x2).max() < 1e-14


@pytest.mark.parametrize(("twist", "nu"), [(-20.763326807332717, 915.8630331677332),
                                           (53.37, 273.4)])
def test_buckling_mode_normalisation_does_not_depend_on_the_grid(twist, nu):
    """Sign and scale from a fixed grid only: the mid-span value is the same at 5 and 20,001
    points (its sign flipped, or its scale moved 0.5 %, before 2026-12-04)."""
    a = sr.buckling_mode(twist, nu, points=5)
    b = sr.buckling_mode(twist, nu, points=20001)
    assert a.x1[2] == pytest.approx(b.x1[10000], rel=1e-12, abs=1e-15)
    assert a.omega2[2] == pytest.approx(b.omega2[10000], rel=1e-12, abs=1e-15)


def test_wrong_p_true_for_the_forensics_is_a_value_error():
    pts = sr.load_figure1()
    p = sr.critical_load(pts.twist_angle.to_numpy(), pts.nu.to_numpy())
    with pytest.raises(ValueError, match="p_true"):  # a bare RuntimeError before 2026-12-04
        sr.analyse_figure1(pts, p_true=p + 1e-8)


def test_non_planarity_of_huge_samples():
    # 0.0 ("planar") through the SVD's overflow before 2026-12-04
    big = sr.non_planarity([1e308, -1e308, 1e308], [1e308, 1e308, -1e308])
    assert big == pytest.approx(sr.non_planarity([1.0, -1.0, 1.0], [1.0, 1.0, -1.0]), rel=1e-14)
