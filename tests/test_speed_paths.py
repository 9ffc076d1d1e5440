"""Issue 14: the fast paths give the answers of the paths they shortcut, and keep the guarantees.

References are independent where accuracy is checked (the mpmath characteristic equation via
the ``reference`` fixture, closed-form roots); elsewhere two code paths that must agree are
compared with each other (the lean solver against the batched engine, the scalar path against
the array path, the batched sign scan against the one-point scan).
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from threadpoolctl import threadpool_info, threadpool_limits

from spectral_rod import ConvergenceWarning, CriticalLoad, critical_load
from spectral_rod._blas_threads import one_blas_thread
from spectral_rod.numerics.sign_scan import bracketed_roots, lowest_root, lowest_roots
from spectral_rod.rod.characteristic import characteristic_double_batch
from spectral_rod.rod.collocation import modal_kernel
from spectral_rod.rod.collocation.arithmetic import ARRAYS, FLOATS
from spectral_rod.rod.collocation.driver import pick_family
from spectral_rod.rod.collocation.eigensolver import solve_family, solve_point, solve_points
from spectral_rod.rod.collocation.reference import solve_family_eig
from spectral_rod.rod.collocation.tuning import SMALL_CALL
from spectral_rod.rod.families import CLOSE_REL
from spectral_rod.rod.router import NEAR_DEGENERATE, TWIST_ROUTE, route, route_point

TWISTS = (0.0, 1e-3, 0.7, 3.0, 6.3, 9.9, 20.0, 45.0)
NUS = (1.0 + 1e-6, 1.001, 1.1, 1.5, 4.0, 100.0)


def test_route_point_is_the_router_rule():
    tw = np.array([0.0, 10.0, TWIST_ROUTE, TWIST_ROUTE - 1e-9, 200.0, 10.0, 10.0])
    nv = np.array([1.5, 1.0, 1.5, 1.0, 1.0, 1.0 + NEAR_DEGENERATE, 1.0 + 2 * NEAR_DEGENERATE])
    for method in ("auto", "collocation", "characteristic"):
        for n in (None, 16):
            want = route(tw, nv, n, method) if not (n and method == "characteristic") else None
            if want is None:
                continue
            got = [route_point(float(a), float(b), n, method) for a, b in zip(tw, nv,
                                                                             strict=True)]
            assert got == want.tolist()


def test_scalar_path_equals_the_array_path_for_one_point():
    for om in TWISTS:
        for nu in NUS:
            a = critical_load(om, nu, full_output=True)
            b = critical_load(np.array([om]), np.array([nu]), full_output=True)
            assert a.p_star == float(b.p_star[0]) and a.family == b.family[0]
            assert a.method == b.method[0] and a.n == int(b.n[0])


def _same_output(a, b) -> None:
    """The same type, and for arrays the same dtype, shape and values (fields of results)."""
    if isinstance(a, CriticalLoad):
        for f in dataclasses.fields(a):
            _same_output(getattr(a, f.name), getattr(b, f.name))
        return
    assert type(a) is type(b)
    if isinstance(a, np.ndarray):
        assert (a.dtype, a.shape) == (b.dtype, b.shape) and np.array_equal(a, b)
    else:
        assert a == b


@pytest.mark.parametrize(("twist_shape", "nu_shape", "dtype"), [
    ((1,), (1,), np.float64), ((1,), None, np.float64), (None, (1, 1), np.float64),
    ((), (), np.float64), ((1,), (1,), np.float32), ((1,), None, np.int64)])
def test_one_element_arrays_take_the_scalar_path_with_the_general_output(
        monkeypatch, twist_shape, nu_shape, dtype):
    # e.g. scipy.optimize.least_squares passes (1,) vectors: the scalar path answers, and the
    # result has the types, dtypes and shapes of the general path's (which it replaces)
    import spectral_rod.rod.critical as critical

    def arg(value, shape):
        return value if shape is None else np.reshape(np.asarray(value, dtype=dtype), shape)

    for om, nu in ((0.0, 1.5), (3.0, 1.3), (9.0, 100.0), (45.0, 1.1), (-7.0, 4.0),
                   (80.0, 1.5), (-640.0, 30.0), (50.0, 1.0 + 1e-12)):  # the last 3: large twist
        args = arg(om, twist_shape), arg(nu, nu_shape)
        with monkeypatch.context() as m:  # the general path must not run
            m.setattr(critical, "solve_points", None)
            fast = [critical_load(*args, full_output=f) for f in (True, False)]
        with monkeypatch.context() as m:  # and here only the general path runs
            m.setattr(critical, "_few_points", lambda *a: None)
            general = [critical_load(*args, full_output=f) for f in (True, False)]
        for a, b in zip(fast, general, strict=True):
            _same_output(a, b)


def _small_call_points(size: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """`size` points mixing the routes: collocation, large twist, nu - 1 near zero."""
    tw = np.where(rng.random(size) < 0.5, rng.uniform(-49.0, 49.0, size),
                  rng.uniform(50.0, 900.0, size))
    nv = np.where(rng.random(size) < 0.3, 1.0 + 10.0 ** rng.uniform(-9, -3, size),
                  rng.uniform(1.0, 100.0, size))
    return tw, nv


@pytest.mark.parametrize(("twist_shape", "nu_shape", "dtype"), [
    ((3,), (3,), np.float64), ((2, 4), None, np.float64), ((2, 1), (4,), np.float64),
    ((SMALL_CALL,), (SMALL_CALL,), np.float32), ((2,), (2,), np.int64)])
def test_small_arrays_are_their_scalar_calls_with_the_general_output(
        monkeypatch, twist_shape, nu_shape, dtype):
    # an array call of at most SMALL_CALL points: each point as its scalar call answers it,
    # with the general path's types, dtypes and shapes, and p* within the general path's
    # estimates (that path may pool degrees)
    import spectral_rod.rod.critical as critical

    rng = np.random.default_rng(sum(twist_shape) + 7)
    size = math.prod(np.broadcast_shapes(twist_shape, nu_shape or ()))
    tw, nv = _small_call_points(size, rng)
    tw = np.reshape(tw[:math.prod(twist_shape)], twist_shape).astype(dtype)
    nu = float(nv[0]) if nu_shape is None else np.reshape(nv[:math.prod(nu_shape)],
                                                          nu_shape).astype(dtype)
    with monkeypatch.context() as m:  # the general path must not run
        m.setattr(critical, "solve_points", None)
        fast = [critical_load(tw, nu, full_output=f) for f in (True, False)]
    with monkeypatch.context() as m:
        m.setattr(critical, "_few_points", lambda *a: None)
        general = [critical_load(tw, nu, full_output=f) for f in (True, False)]
    for f in dataclasses.fields(CriticalLoad):
        a, b = getattr(fast[0], f.name), getattr(general[0], f.name)
        assert type(a) is type(b)
        if isinstance(a, np.ndarray):
            assert (a.dtype, a.shape) == (b.dtype, b.shape)
    assert np.array_equal(fast[1], fast[0].p_star) and fast[1].shape == general[1].shape
    scalar = [critical_load(float(a), float(b)) for a, b in
              zip(*(np.broadcast_to(v, fast[1].shape).ravel() for v in (tw, nu)), strict=True)]
    assert fast[1].ravel().tolist() == scalar
    assert np.all(np.abs(fast[1] / general[1] - 1)
                  <= np.maximum(fast[0].error_estimate, general[0].error_estimate))


def test_small_array_warns_once_as_the_general_path(monkeypatch):
    # two of three points miss tol at a forced degree: one warning, the general path's text,
    # pointing at the caller
    import spectral_rod.rod.critical as critical

    tw, nv = np.array([45.0, 3.0, -40.0]), np.array([1.5, 1.5, 4.0])
    messages = []
    for few in (critical._few_points, lambda *a: None):
        with monkeypatch.context() as m, warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            m.setattr(critical, "_few_points", few)
            res = critical_load(tw, nv, n=24, full_output=True)
        assert res.converged.tolist() == [False, True, False]
        assert [w.filename for w in caught] == [__file__]
        messages.append(str(caught[0].message))
    assert "not met at 2 point(s)" in messages[0]
    assert messages[0] == messages[1]
    with warnings.catch_warnings(record=True) as caught:  # a scalar call's warning too
        warnings.simplefilter("always")
        critical_load(45.0, 1.5, n=24)
    assert [w.filename for w in caught] == [__file__]
    assert "not met at 1 point(s)" in str(caught[0].message)


@pytest.mark.parametrize("size", [1, 3])
def test_small_masked_arrays_are_refused_as_on_the_general_path(size):
    # a masked entry must not be answered as if it were a number (the general path refuses it)
    twist = np.ma.array(np.linspace(1.0, 3.0, size), mask=[True] + [False] * (size - 1))
    with pytest.raises(TypeError, match="twist_angle: masked arrays"):
        critical_load(twist, 1.5)
    with pytest.raises(TypeError, match="nu: masked arrays"):
        critical_load(2.0, np.ma.array([1.5] * size, mask=[True] * size))


def test_arrays_above_small_call_take_the_general_path(monkeypatch):
    import spectral_rod.rod.critical as critical

    calls = []
    solve = critical.solve_points
    monkeypatch.setattr(critical, "solve_points", lambda *a: calls.append(1) or solve(*a))
    critical_load(np.linspace(0.0, 10.0, SMALL_CALL + 1), 1.5)
    critical_load(np.linspace(0.0, 10.0, SMALL_CALL), 1.5)
    assert calls == [1]


def test_one_element_arrays_outside_the_scalar_path_take_the_general_path():
    # nu - 1 near zero, a bool array: the general path answers (or rejects), as for arrays of
    # any size; a forced degree gives the same answer by either path
    assert critical_load(np.array([3.0]), 1.5, n=30, full_output=True).n.tolist() == [30]
    assert critical_load(np.array([3.0]), np.array([1.0 + 1e-6]), method="increment",
                         full_output=True
                         ).method.tolist() == ["increment"]
    with pytest.raises(TypeError, match="twist_angle"):
        critical_load(np.array([True]), 1.5)
    with pytest.raises(ValueError, match="nu"):
        critical_load(np.array([3.0]), np.array([0.5]))


@pytest.mark.parametrize("kwargs", [{"tol": 1e-14}, {"n": 30}, {"n": 52, "tol": 1e-4}])
def test_scalar_path_answers_below_the_floor_and_at_a_forced_degree(monkeypatch, reference,
                                                                   kwargs):
    # issue 37 item 4: tol under the round-off floor eps (32 + 0.3 Omega^2), or an explicit n,
    # stays on the scalar path (the array path cost 3.5-12x an automatic call there), with the
    # array path's answer, estimate, flag and warning
    import spectral_rod.rod.critical as critical

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        array = critical_load(np.array([45.0]), 1.5, full_output=True, **kwargs)

    def _must_not_run(*args, **kw):
        raise AssertionError("the scalar call went to the array path")

    monkeypatch.setattr(critical, "solve_points", _must_not_run)
    missed = not bool(array.converged[0])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = critical_load(45.0, 1.5, full_output=True, **kwargs)
    assert [issubclass(w.category, ConvergenceWarning) for w in caught] == [True] * missed
    assert res.converged == (not missed) and res.error_estimate == float(array.error_estimate[0])
    assert res.p_star == float(array.p_star[0]) and res.n == int(array.n[0])
    assert abs(res.p_star / reference(45.0, 1.5) - 1) <= res.error_estimate


def test_scalar_and_large_batch_agree_to_the_stated_bound(reference):
    # a batch of more than FEW_POINTS points of one degree takes the batched engine
    tw = np.linspace(4.0, 4.6, 60)
    nv = np.full(tw.size, 1.3)
    res = critical_load(tw, nv, full_output=True)
    batch = res.p_star
    single = np.array([critical_load(float(a), 1.3) for a in tw])
    assert np.all(res.n == critical_load(4.3, 1.3, full_output=True).n)  # one degree: no pooling
    bound = np.finfo(float).eps * (32 + 0.3 * tw**2)  # critical_load's docstring, equal degree
    assert np.all(np.abs(single / batch - 1) <= bound)
    for i in (0, 30, 59):
        assert abs(single[i] / reference(float(tw[i]), 1.3) - 1) <= 1e-13


@pytest.fixture(params=["kernel", "numpy"])
def few_engine(request, monkeypatch):
    """The engine and its reference: the C kernel (one lane for a few points) and the numpy
    reference (the only one where the kernel is not installed)."""
    if request.param == "numpy":
        monkeypatch.setattr(modal_kernel, "_library", lambda: None)
    elif not modal_kernel.available():
        pytest.skip("the C kernel is not built here")
    return request.param


def _check_families(lam, tails, ref_of, bound):
    """Each family's lambda against ref_of(family) where it converged (finite tail); where the
    antisymmetric family was stopped early, that it lies above the symmetric one."""
    for f, fam in enumerate(("symmetric", "antisymmetric")):
        done = np.isfinite(tails[f])
        assert f == 1 or done.all()
        if done.any():
            ref = ref_of(fam)
            assert np.max(np.abs(lam[f][done] / ref[done] - 1)) <= bound
        assert np.all(lam[1][~done] > lam[0][~done] * (1 + CLOSE_REL))


#: How far the iteration's eigenvalue may be from the full ``eig``'s of the same pencil at the
#: degrees below (n <= 40): eig's own round-off (cond(A^{-1} B) ~ n^4) dominates.
EIG_AGREEMENT = 1e-12


def test_few_point_engine_matches_the_eig_reference(few_engine):
    # the engine for a few points (one lane of the kernel, or the numpy reference's dense
    # shifted inverses) against the test reference, the full eig with the rule
    om = np.array([0.3, 2.0, 6.0, 9.0, 15.0])
    nu = np.array([1.1, 1.5, 1.3, 3.0, 10.0])
    for n in (24, 40):
        lam, tails, by_kernel = solve_points(n, om, nu, 1e-14)
        assert by_kernel.all() == (few_engine == "kernel")
        _check_families(lam, tails,
                        lambda fam, n=n: solve_family_eig(n, fam, om, nu)[0], EIG_AGREEMENT)


def test_kernel_and_numpy_reference_agree_on_a_few_points(monkeypatch):
    # the two engines solve one problem: the same eigenvalues to the round-off part of the
    # error model, the same tails to 1e-6 (their own round-off ~1e-16)
    if not modal_kernel.available():
        pytest.skip("the C kernel is not built here")
    om = np.array([0.3, 2.0, 6.0, 9.0, 15.0, 45.0])
    nu = np.array([1.1, 1.5, 1.3, 3.0, 10.0, 1.5])
    bound = np.finfo(float).eps * (32 + 0.3 * om**2)  # critical_load's docstring
    for n in (24, 40):
        kernel = solve_points(n, om, nu, 1e-14)
        monkeypatch.setattr(modal_kernel, "_library", lambda: None)
        numpy = solve_points(n, om, nu, 1e-14)
        monkeypatch.undo()
        assert kernel.by_kernel.all() and not numpy.by_kernel.any()
        assert np.all(np.abs(kernel.lam[0] / numpy.lam[0] - 1) <= bound)
        both = np.isfinite(kernel.tails[1]) & np.isfinite(numpy.tails[1])
        assert np.all(np.abs(kernel.lam[1][both] / numpy.lam[1][both] - 1) <= bound[both])
        assert np.allclose(kernel.tails[0], numpy.tails[0], rtol=1e-6, atol=1e-14)


def test_one_point_solver_matches_the_batch_path(few_engine):
    # solve_point (Python floats) against solve_points on the same points, with and without
    # the extended-precision quotient (|Omega| > LONG_TWIST = 10)
    om = np.array([0.3, 6.0, 15.0, 45.0])
    nu = np.array([1.1, 1.3, 10.0, 1.5])
    for n in (24, 40):
        few = solve_points(n, om, nu, 1e-14)
        for j in range(om.size):
            bound = np.finfo(float).eps * (32 + 0.3 * om[j] ** 2)  # critical_load's docstring
            lam, tails, by_kernel = solve_point(n, float(om[j]), float(nu[j]), 1e-14)
            assert by_kernel == bool(few.by_kernel[j])
            assert np.max(np.abs(np.array(lam) / few.lam[:, j] - 1)) <= bound
            assert np.allclose(tails, few.tails[:, j], rtol=1e-6, atol=1e-14)  # round-off: 1e-16
            _check_families(np.array(lam)[:, None], np.array(tails)[:, None],
                            lambda fam, n=n, j=j: solve_family(
                                n, fam, om[j:j + 1], nu[j:j + 1], rtol=1e-14)[0], bound)


def test_degree_groups_are_pooled_where_the_cost_model_says_it_is_cheaper():
    from spectral_rod.rod.collocation.driver import solve_degrees

    n = np.repeat([16, 18, 20], [50, 50, 300])
    assert solve_degrees(n).tolist() == [20] * n.size  # two small groups join a large one
    n = np.repeat([16, 28], [150, 1])  # one stray point does not lift 150 points by 12
    assert solve_degrees(n).tolist() == n.tolist()
    n = np.array([16, 18, 18, 20])  # the lean solver's groups: one call's cost to save
    assert solve_degrees(n).tolist() == [20] * n.size
    n = np.array([16, 16, 16, 60])  # ... but not 3 points lifted from 16 to 60
    assert solve_degrees(n).tolist() == n.tolist()
    n = np.repeat([60, 64, 66, 70], 50)  # not across nor above LEAN_MAX_DEGREE = 64
    assert solve_degrees(n)[100:].tolist() == n[100:].tolist()


def _plan_cost(n, solved_at):
    from spectral_rod.rod.collocation.driver import solve_cost

    degs, counts = np.unique(solved_at, return_counts=True)
    return sum(solve_cost(int(c), int(d)) for d, c in zip(degs, counts, strict=True))


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(4, 40).map(lambda k: 2 * k), min_size=1, max_size=600))
def test_pooled_degrees_never_lower_and_never_costlier(degrees):
    from spectral_rod.rod.collocation.driver import solve_degrees
    from spectral_rod.rod.collocation.tuning import LEAN_MAX_DEGREE

    n = np.array(degrees)
    out = solve_degrees(n)
    assert np.all(out >= n) and set(out.tolist()) <= set(n.tolist())
    assert np.all(out[n > LEAN_MAX_DEGREE] == n[n > LEAN_MAX_DEGREE])
    assert _plan_cost(n, out) <= _plan_cost(n, n) * (1 + 1e-12)  # by the model it pools on


def test_a_pooled_call_meets_tol_and_agrees_with_scalar_calls(reference):
    # one curve of 300 points spans degrees 16-28: its groups are pooled at higher degrees
    from spectral_rod.rod.collocation.driver import solve_degrees
    from spectral_rod.rod.collocation.resolution import initial_degree

    tw = np.linspace(0.1, 12.0, 300)
    assert np.any(solve_degrees(initial_degree(tw, 1e-12)) > initial_degree(tw, 1e-12))
    res = critical_load(tw, 1.3, full_output=True)
    assert res.converged.all() and np.any(res.n > initial_degree(tw, 1e-12))
    single = [critical_load(float(a), 1.3, full_output=True) for a in tw]
    for r, p, e in zip(single, res.p_star, res.error_estimate, strict=True):
        assert abs(p / r.p_star - 1) <= max(e, r.error_estimate)  # critical_load's docstring
    for i in (0, 150, 299):
        assert abs(res.p_star[i] / reference(float(tw[i]), 1.3) - 1) <= res.error_estimate[i]


def test_a_small_call_over_several_degrees_is_one_engine_call(monkeypatch, reference):
    # 9 points over 5 a priori degrees: one engine call (tuning.CALL_COST), not 5 of a few lanes
    from spectral_rod.rod.collocation import driver
    from spectral_rod.rod.collocation.resolution import initial_degree

    tw, nv = np.linspace(2.0, 18.0, 9), np.linspace(1.2, 30.0, 9)
    assert np.unique(initial_degree(tw, 1e-12)).size >= 4
    calls = []
    solve = driver.solve_points
    monkeypatch.setattr(driver, "solve_points", lambda n, *a: calls.append(n) or solve(n, *a))
    res = critical_load(tw, nv, full_output=True)
    assert len(calls) == 1 and res.converged.all()
    for a, b, p, e in zip(tw, nv, res.p_star, res.error_estimate, strict=True):
        assert abs(p / reference(float(a), float(b)) - 1) <= e


def test_an_unresolved_degree_is_flagged():
    # degree 8 at Omega = 30 resolves nothing: the engine's value, if any, is an eigenvalue the
    # eig reference finds too, with a tail that says so; critical_load flags it in any case
    lam, tails, _ = solve_points(8, np.array([30.0]), np.array([1.5]), 1e-14)
    if math.isfinite(lam[0, 0]):
        ref, _, _ = solve_family_eig(8, "symmetric", np.array([30.0]), np.array([1.5]))
        assert lam[0, 0] > 0 and math.isfinite(ref[0]) and tails[0, 0] > 1e-3
    with pytest.warns(Warning):
        res = critical_load(30.0, 1.5, n=8, full_output=True)
    assert not res.converged


@pytest.mark.parametrize("tol", [1e-2, 1e-4, 1e-8])
def test_loose_tolerances_are_met(tol, reference):
    tw = np.array([0.5, 3.0, 6.2, 9.5])
    for nu in (1.1, 1.5):
        res = critical_load(tw, nu, tol=tol, full_output=True)
        assert res.converged.all()
        for t, p in zip(tw, res.p_star, strict=True):
            assert abs(p / reference(float(t), nu) - 1) <= tol
            assert abs(critical_load(float(t), nu, tol=tol) / reference(float(t), nu) - 1) <= tol


def test_one_blas_thread_restores_the_callers_setting():
    blas = [i for i in threadpool_info() if i["user_api"] == "blas"]
    if not blas:
        pytest.skip("no BLAS library visible to threadpoolctl")
    with threadpool_limits(limits=2, user_api="blas"):
        before = [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]
        with one_blas_thread():
            inside = [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]
        after = [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]
    assert set(inside) == {1} and after == before


def test_batched_scan_is_the_one_point_scan():
    # sin(a x) on [0.1, 10]: lowest root pi/a; cos(b x) as a second component: pi/(2b)
    a, b = np.array([1.0, 2.0, 0.5, 3.0]), np.array([0.3, 0.2, 1.0, 0.25])

    def values(points, grid):
        return np.stack([np.sin(a[points, None] * grid), np.cos(b[points, None] * grid)], 1)

    def refine(points, k, lo, hi):
        rate = np.where(k == 0, a[points], b[points])
        return bracketed_roots(lambda j, x: np.where(k[j] == 0, np.sin(rate[j] * x),
                                                     np.cos(rate[j] * x)), lo, hi)

    roots, comp = lowest_roots(values, refine, np.full(4, 0.1), np.full(4, 10.0),
                               np.full(4, 0.05), chunk=17)
    want = np.minimum(np.pi / a, np.pi / (2 * b))
    assert np.allclose(roots, want, rtol=4e-16, atol=0)
    assert comp.tolist() == np.argmin([np.pi / a, np.pi / (2 * b)], axis=0).tolist()
    for i in range(4):
        one = lowest_root(lambda g, i=i: [[math.sin(a[i] * x) for x in g],
                                          [math.cos(b[i] * x) for x in g]],
                          lambda k, lo, hi, i=i: (math.pi / a[i], math.pi / (2 * b[i]))[k],
                          0.1, 10.0, 0.05)
        assert one == (pytest.approx(want[i], rel=1e-15), int(comp[i]))


def test_no_root_is_reported_as_such():
    roots, comp = lowest_roots(lambda p, g: np.ones((p.size, 1, g.shape[1])),
                               lambda *args: None, np.zeros(2), np.ones(2), np.full(2, 0.1),
                               chunk=4)
    assert comp.tolist() == [-1, -1] and np.isnan(roots).all()


def test_scalar_large_twist_path(monkeypatch, reference):
    """A scalar call on the large-twist route (auto, or the characteristic method forced) takes
    the scalar path, gives the general path's answer bit for bit, meets the reference, and
    hands a tol it cannot meet to the general path, which warns and flags it."""
    import spectral_rod.rod.critical as critical
    from spectral_rod.rod import characteristic

    cases = [(80.0, 1.5, "auto"), (999.0, 1.0 + 1e-9, "auto"), (3.0, 1.5, "characteristic"),
             (-250.0, 1e4, "auto")]
    for om, nu, method in cases:
        with monkeypatch.context() as m:  # the general path must not run
            m.setattr(critical, "solve_points", None)
            fast = critical_load(om, nu, method=method, full_output=True)
        with monkeypatch.context() as m:  # the general path, its brackets on arrays
            m.setattr(critical, "_point", lambda *a, **k: None)
            m.setattr(characteristic, "FEW_BRACKETS", 0)
            general = critical_load(np.array([om]), nu, method=method, full_output=True)
        assert fast.method == "characteristic" and fast.converged
        # the same algorithm in floats (libm's sin/cos) and in numpy: equal to an ulp or so,
        # depending on numpy's build (1 ulp apart at the dependency floors)
        assert (fast.family, fast.error_estimate) == (
            str(general.family[0]), float(general.error_estimate[0]))
        assert abs(fast.p_star - float(general.p_star[0])) <= 4 * np.finfo(float).eps * fast.p_star
        assert abs(fast.p_star / reference(abs(om), nu) - 1) <= max(1e-13, fast.error_estimate)
    with pytest.warns(ConvergenceWarning, match="tol=1e-14 not met"):
        res = critical_load(40.0, 1.5, tol=1e-14, method="characteristic", full_output=True)
    assert not res.converged and res.error_estimate > 1e-14


@pytest.mark.parametrize("near", [False, True])
def test_few_brackets_in_floats_agree_with_the_array_refinement(monkeypatch, reference, near):
    """The certified brackets of a few points found and refined in Python floats
    (characteristic.FEW_BRACKETS, FEW_POINTS) and of many on numpy arrays give the same roots
    to within the route's error estimate, and both meet the reference: at large twist, and
    near nu = 1 (the family bounds)."""
    from spectral_rod.rod import characteristic
    from spectral_rod.rod.characteristic import FEW_POINTS, double_error_estimate

    rng = np.random.default_rng(11)
    tw = rng.uniform(0.0, 50.0, 9) if near else rng.uniform(50.0, 1000.0, 2 * FEW_POINTS + 1)
    nv = (1.0 + 10.0 ** rng.uniform(-9.0, -3.0, tw.size) if near
          else np.exp(rng.uniform(0.0, np.log(1e3), tw.size)))
    with monkeypatch.context() as m:  # every point's brackets on arrays
        m.setattr(characteristic, "FEW_BRACKETS", 0)
        p_many, fam_many = characteristic_double_batch(tw, nv)
    for i in range(tw.size):
        p_one, fam_one = characteristic_double_batch(tw[i:i + 1], nv[i:i + 1])
        assert fam_one[0] == fam_many[i]
        assert abs(p_one[0] / p_many[i] - 1) <= float(double_error_estimate(tw[i]))
        assert abs(p_one[0] / reference(float(tw[i]), float(nv[i])) - 1) <= 1e-13


@settings(max_examples=200, deadline=None)
@given(roots=st.lists(st.floats(-3.0, 3.0), min_size=1, max_size=3),
       lo=st.floats(-4.0, 0.0), width=st.floats(1e-3, 8.0))
def test_scalar_bracketed_root_is_the_array_iteration(roots, lo, width):
    """bracketed_root (Python floats) takes the iterates of bracketed_roots (arrays): on the
    same polynomial, bit for bit."""
    from spectral_rod.numerics.sign_scan import bracketed_root

    def poly(x):
        out = x - roots[0]
        for r in roots[1:]:
            out = out * (x - r)
        return out

    hi = lo + width
    if not poly(lo) * poly(hi) < 0:
        return  # no bracket
    many = bracketed_roots(lambda j, x: poly(x), np.full(3, lo), np.full(3, hi))
    assert bracketed_root(poly, lo, hi) == float(many[0])


@pytest.mark.parametrize("few", [0, 24])
def test_batched_characteristic_route_against_the_reference(monkeypatch, reference, few):
    # the brackets on arrays (FEW_BRACKETS 0) and one point at a time in floats
    from spectral_rod.rod import characteristic

    monkeypatch.setattr(characteristic, "FEW_BRACKETS", few)
    tw = np.array([50.0, 120.0, 640.0, 1000.0, 3.0, 45.0])
    nv = np.array([1.5, 1.0 + 1e-9, 30.0, 4.0, 1.0 + 1e-5, 1.0005])
    p, fam = characteristic_double_batch(tw, nv)
    for t, v, pv in zip(tw, nv, p, strict=True):
        assert abs(pv / reference(float(t), float(v)) - 1) <= 1e-13
    assert set(fam.tolist()) <= {0, 1}


# --- the family rule: one rule in two forms (arrays for batches, floats for the scalar path) --

_near = st.sampled_from([0.0, 1e-16, 5e-15, 2e-14, 5e-7, 1e-6, 2e-6, 1e-3, -1e-16, -5e-15,
                         -2e-14, -5e-7, -2e-6, -1e-3])


@settings(max_examples=300, deadline=None)
@given(l0=st.floats(9.0, 1e4), rel=_near, t0=st.floats(1e-16, 1e-2), t1=st.floats(1e-16, 1e-2))
def test_scalar_family_rule_is_the_array_rule(l0, rel, t0, t1):
    """pick_family in Python floats (the scalar path's namespace) and on arrays choose the same
    family and tail on ties (rel = 0), near-ties around TIE_REL and pairs around CLOSE_REL."""
    l1 = l0 * (1.0 + rel)
    p, fam, tail = pick_family(np.array([[l0], [l1]]), np.array([[t0], [t1]]), ARRAYS)
    p1, best, tail_scalar = pick_family([l0, l1], [t0, t1], FLOATS)
    assert (best, tail_scalar, p1) == (int(fam[0]), float(tail[0]), float(p[0]))
    assert p1 == [l0, l1][best] / np.pi**2


def test_lean_loose_eigenvalue_is_the_discrete_eigenvalue_within_the_iteration_tolerance(
        capsys, few_engine):
    """tuning.LOOSE_RTOL: from rtol = LOOSE_RTOL on (up to LOOSE_DEGREE) lambda is the modal
    quotient instead of the pencil's, in the kernel and the numpy reference alike; where
    accepted it stays far inside rtol of the discrete eigenvalue, taken from the full ``eig``
    of the same pencil (LAPACK's QR algorithm, not the power iteration), on Figure 1's and
    random points at their a priori degree and n = 64."""
    from spectral_rod import load_figure1
    from spectral_rod.rod.collocation.resolution import initial_degree

    d = load_figure1()
    rng = np.random.default_rng(7)
    om = np.concatenate([d["twist_angle"].to_numpy()[::40], rng.uniform(0, 50, 40)])
    nus = np.concatenate([d["nu"].to_numpy()[::40], 1 + 10 ** rng.uniform(-3, 2, 40)])
    worst, accepted, families = 0.0, 0, 0
    for tw, nu in zip(om, nus, strict=True):
        for n in sorted({initial_degree(float(tw), 1e-6, FLOATS), 64}):
            lam, tails, _ = solve_point(n, float(tw), float(nu), 1e-8)
            ref = [solve_family_eig(n, f, np.array([tw]), np.array([nu]))[0][0]
                   for f in ("symmetric", "antisymmetric")]
            families += 2
            if math.isfinite(tails[0]):  # an "above" family is only shown to lie above
                done = [math.isfinite(t) for t in tails]
                accepted += sum(done)
                worst = max(worst, max(abs(a / b - 1) for a, b, c in zip(lam, ref, done,
                                                                          strict=True) if c))
    assert accepted >= 0.5 * families
    assert worst <= 0.05 * 1e-8
    with capsys.disabled():
        print(f"\nloose quotient ({few_engine}): {om.size} points, {accepted} of {families} "
              f"families accepted and converged, max |lambda/eig - 1| {worst:.2g}")


def test_an_explicit_degree_forces_collocation_on_every_path():
    """`n` forces collocation at that degree (critical_load's contract), also where the router
    would send the point to the characteristic equation (|Omega(L)| >= 50): the scalar path, a
    one-element array and a batch answer alike."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)  # n = 8 cannot resolve Omega = 100
        scalar = critical_load(100.0, 10.0, n=8, full_output=True)
        one = critical_load(np.array([100.0]), 10.0, n=8, full_output=True)
        batch = critical_load(np.array([100.0, 5.0]), 10.0, n=8, full_output=True)
    assert scalar.method == one.method[0] == batch.method[0] == "collocation"
    assert scalar.n == one.n[0] == batch.n[0] == 8
    assert not scalar.converged and scalar.p_star == one.p_star[0] == batch.p_star[0]
