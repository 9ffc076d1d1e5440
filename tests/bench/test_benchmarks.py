"""Timings of every call pattern (pytest-benchmark). Not in the default run:

    python -m pytest -m bench

Each pattern is timed twice in the same run, in the same benchmark group: its yardstick first,
then ``critical_load``. The yardstick of every row is the obvious implementation
(``spectral_rod.rod.baseline``: Trefethen ``cheb``, n = 24, dense operator and ``eigvals`` per
point). At large twist and near-degenerate points the baseline does not answer correctly (n = 24
does not resolve Omega(L) >= 50, and it carries no digit of p* - 1 at nu - 1 = 1e-8): there it
is the cost a user would otherwise pay, and the per-point routes the package used before its
batched routes (``yardsticks.py``) are timed as an extra column, their answers checked against
the mpmath reference. The map's collocation part has a second yardstick, the baseline at the
degree ``critical_load`` chose for each point, as n = 24 does not resolve most of it. Where the
yardstick is slow it runs on a sample of the points and the ratio is per point (named in
``extra_info``). The ratio is yardstick/new from the minimum over rounds of
wall-clock time (on a shared machine the minimum is the round least disturbed by other jobs);
the table's "interleaved" column checks it with as many rounds of each, alternating, so that
both see the same load (:func:`_interleaved_ratio`). A test fails if both are below the floor.

Each new-code test records the resolution and the achieved accuracy (against the mpmath
characteristic equation on a sample) in ``extra_info`` and asserts it, so that a fast wrong answer
cannot pass, and fails if both its same-run ratios are below the floor stated with it (FLOORS).
The 10^6-point row also records the call's peak memory (tracemalloc) and asserts <= 500 MB. The
terminal summary prints the table of ratios. Import time and the first (cold) call are timed in
fresh interpreters.
"""

from __future__ import annotations

import json
import subprocess
import sys
import time

import numpy as np
import pytest
from scipy.optimize import brentq
from yardsticks import pre_change_characteristic, pre_change_increment

from spectral_rod import baseline_critical_load, baseline_sweep, critical_load, load_figure1

pytestmark = pytest.mark.bench

#: Same-run ratio floors (yardstick / new): about half the lowest ratio measured on a quiet
#: shared 2-core machine (tests/bench/HISTORY.md), the margin for the 1.5-2x swings of outside
#: load, or the target of the pattern where half the measured ratio exceeds it. The collocation
#: patterns' are those of the C kernel; without the kernel built (the numpy engine) they fail,
#: which is the point: the benchmarks time the package as installed.
FLOORS = {
    "figure1 batch": 30.0, "figure1 per curve": 22.0, "batches of 100": 12.0,
    "batches of 10": 4.0, "scalar loop": 4.5, "one-point arrays": 4.5, "brentq search": 4.5,
    "map collocation part": 10.0, "map colloc., equal n": 30.0, "map all points": 5.0,
    # against the baseline: the targets of these patterns (met: tests/bench/HISTORY.md)
    "large twist": 20.0, "near-degenerate": 20.0, "10^6 random points": 20.0,
    "large twist, scalar": 5.0, "near-degenerate, scalar": 5.0,
    # arrays of a few points: the scalar calls' target (they take the scalar path)
    "batches of 4": 4.5, "large twist, arrays of 4": 5.0, "near-degenerate, arrays of 4": 5.0,
    "scalar loop, twist 20-50": 1.7,
}
TOL = 1e-12


@pytest.fixture(scope="module")
def fig1():
    d = load_figure1()
    return d["twist_angle"].to_numpy(), d["nu"].to_numpy()


@pytest.fixture(scope="module")
def grid_map():
    om, nu = np.meshgrid(np.linspace(0.0, 100.0, 200), np.linspace(1.0, 100.0, 200))
    return om.ravel(), nu.ravel()


def _sample(size, sample=40):
    """`sample` evenly spaced indices of `size` points (those the accuracy is judged on)."""
    return np.unique(np.linspace(0, size - 1, sample).astype(int))


def _errors(p, twist, nu, reference, sample=40):
    """Relative errors against the mpmath reference at the points :func:`_sample` picks, and
    their indices."""
    idx = _sample(twist.size, sample)
    ref = np.array([reference(float(twist[i]), float(nu[i])) for i in idx])
    return np.abs(np.asarray(p)[idx] / ref - 1), idx


def _max_error(p, twist, nu, reference, sample=40) -> float:
    return float(_errors(p, twist, nu, reference, sample)[0].max())


def _yardstick(benchmark, registry, pattern, fn, points, rounds=5):
    """Time a yardstick; store its per-point minimum for the pattern's ratio."""
    benchmark.pedantic(fn, rounds=rounds, iterations=1, warmup_rounds=0)
    st = benchmark.stats.stats
    registry.setdefault(pattern, {}).update(yardstick=(st.min / points, st.median / points),
                                            yardstick_call=(fn, points, rounds))
    benchmark.extra_info.update(points=points, role="yardstick")


def _page_faults(fn) -> float | None:
    """Minor page faults of one call of `fn` (None where the ``resource`` module is missing):
    the allocator state the timings were taken in (see :func:`test_tol_trade`)."""
    try:
        import resource
    except ImportError:  # not on Windows
        return None
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    fn()
    return float(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before)


def _interleaved_min(fns, rounds=7, repeats=5):
    """Minimum wall time of each function, its rounds interleaved with the others' (so that a
    change of machine load hits all of them alike)."""
    best = [np.inf] * len(fns)
    for _ in range(rounds):
        for i, fn in enumerate(fns):
            for _ in range(repeats):
                t = time.perf_counter()
                fn()
                best[i] = min(best[i], time.perf_counter() - t)
    return best


def _interleaved_ratio(yardstick, yardstick_points, pairs, new, points) -> float:
    """yardstick/new per point from the minima over `pairs` alternating rounds of each: a check
    of the ratio above, whose two timings run one after the other (minutes apart, 3-5 rounds
    against 15), so that a change of load between them moves it (measured 2026-12-03: the
    scalar loop's yardstick took 804 us a point in one run, 475-554 in three others)."""
    t_yardstick, t_new = _interleaved_min([yardstick, new], rounds=pairs, repeats=1)
    return (t_yardstick / yardstick_points) / (t_new / points)


def _new(benchmark, registry, pattern, fn, points, info, yardstick_name):
    """Time the new code, store its per-point minimum, record and check the ratio."""
    benchmark.pedantic(fn, rounds=15, iterations=1, warmup_rounds=2)
    st = benchmark.stats.stats
    registry.setdefault(pattern, {})["new"] = (st.min / points, st.median / points)
    entry = _record_ratio(registry, pattern, fn, points, yardstick_name)
    benchmark.extra_info.update(points=points, ratio_min=entry["ratio"], floor=FLOORS[pattern],
                                ratio_interleaved=entry["interleaved"],
                                yardstick=yardstick_name, **info)
    _check_floor(pattern, entry)


def _record_ratio(registry, pattern, fn, points, yardstick_name) -> dict:
    """The pattern's ratio from its stored timings, and the interleaved check of it."""
    entry = registry[pattern]
    entry.update(floor=FLOORS[pattern], yardstick_name=yardstick_name)
    ratio = entry["yardstick"][0] / entry["new"][0]
    entry["ratio"] = ratio
    entry["interleaved"] = _interleaved_ratio(*entry["yardstick_call"], fn, points)
    return entry


def _check_floor(pattern, entry) -> None:
    # a regression lowers both ratios; a change of load between the two timed tests moves only
    # the first (measured 2026-12-03: the scalar loop at 2.6 against 4.3 interleaved)
    ratio = entry["ratio"]
    assert max(ratio, entry["interleaved"]) >= FLOORS[pattern], \
        f"{pattern}: ratio {ratio:.1f} (interleaved {entry['interleaved']:.1f}) below floor"


# --- Figure 1 sweep: one call, one call per curve, batches of 100 and 10 -------------------

@pytest.mark.benchmark(group="figure1 batch")
def test_figure1_baseline(benchmark, fig1, bench_registry):
    _yardstick(benchmark, bench_registry, "figure1 batch", lambda: baseline_sweep(*fig1),
               fig1[0].size)


@pytest.mark.benchmark(group="figure1 batch")
def test_figure1_batch(benchmark, fig1, reference, bench_registry):
    tw, nv = fig1
    res = critical_load(tw, nv, tol=TOL, full_output=True)
    err = _max_error(res.p_star, tw, nv, reference)
    assert res.converged.all() and err <= 1e-13
    _new(benchmark, bench_registry, "figure1 batch", lambda: critical_load(tw, nv, tol=TOL),
         tw.size, {"n_min": int(res.n.min()), "n_max": int(res.n.max()),
                   "max_rel_error_sampled": err}, "baseline")
    # the allocator state of these timings (test_tol_trade)
    benchmark.extra_info["page_faults_a_call"] = _page_faults(lambda: critical_load(tw, nv,
                                                                                    tol=TOL))


def _per_curve(tw, nv):
    return [critical_load(tw[nv == v], v, tol=TOL) for v in np.unique(nv)]


@pytest.mark.benchmark(group="figure1 per curve")
def test_per_curve_baseline(benchmark, fig1, bench_registry):
    tw, nv = fig1
    _yardstick(benchmark, bench_registry, "figure1 per curve",
               lambda: [baseline_sweep(tw[nv == v], nv[nv == v]) for v in np.unique(nv)],
               tw.size, rounds=3)


@pytest.mark.benchmark(group="figure1 per curve")
def test_per_curve(benchmark, fig1, reference, bench_registry):
    tw, nv = fig1
    p = np.empty(tw.size)
    for v, pv in zip(np.unique(nv), _per_curve(tw, nv), strict=True):
        p[nv == v] = pv
    err = _max_error(p, tw, nv, reference)
    assert err <= 1e-13
    _new(benchmark, bench_registry, "figure1 per curve", lambda: _per_curve(tw, nv), tw.size,
         {"calls": 3, "max_rel_error_sampled": err}, "baseline")


def _batches(tw, nv, size):
    return np.concatenate([critical_load(tw[i:i + size], nv[i:i + size], tol=TOL)
                           for i in range(0, tw.size, size)])


@pytest.mark.parametrize("size", [100, 10, 4])
def test_batches_baseline(benchmark, fig1, bench_registry, size):
    benchmark.group = f"batches of {size}"
    tw, nv = fig1
    _yardstick(benchmark, bench_registry, f"batches of {size}",
               lambda: [baseline_sweep(tw[i:i + size], nv[i:i + size])
                        for i in range(0, 600, size)], 600, rounds=3)


@pytest.mark.parametrize("size", [100, 10, 4])
def test_batches(benchmark, fig1, reference, bench_registry, size):
    benchmark.group = f"batches of {size}"
    tw, nv = fig1
    err = _max_error(_batches(tw, nv, size), tw, nv, reference)
    assert err <= 1e-13
    _new(benchmark, bench_registry, f"batches of {size}", lambda: _batches(tw, nv, size),
         tw.size, {"batch": size, "max_rel_error_sampled": err}, "baseline")


# --- scalar calls: a Python loop and a root finder ---------------------------------------

def _scalar_points(fig1):
    tw, nv = fig1
    return tw[::6].tolist(), nv[::6].tolist()  # 201 points along the three curves


@pytest.mark.benchmark(group="scalar loop")
def test_scalar_loop_baseline(benchmark, fig1, bench_registry):
    tw, nv = _scalar_points(fig1)
    _yardstick(benchmark, bench_registry, "scalar loop",
               lambda: [baseline_critical_load(a, b) for a, b in zip(tw, nv, strict=True)],
               len(tw), rounds=3)
    bench_registry["one-point arrays"] = dict(bench_registry["scalar loop"])


def _scalar_loop(benchmark, registry, pattern, tw, nv, reference, sample=40):
    """Time a loop of scalar calls at the points (tw, nv), after checking them against the
    reference (sampled) and against one array call."""
    res = [critical_load(a, b, tol=TOL, full_output=True) for a, b in zip(tw, nv, strict=True)]
    p = np.array([r.p_star for r in res])
    err = _max_error(p, np.array(tw), np.array(nv), reference, sample)
    same = np.max(np.abs(p / critical_load(np.array(tw), np.array(nv), tol=TOL) - 1))
    assert err <= 1e-13 and all(r.converged for r in res)
    _new(benchmark, registry, pattern,
         lambda: [critical_load(a, b, tol=TOL) for a, b in zip(tw, nv, strict=True)], len(tw),
         {"n": sorted({r.n for r in res}), "max_rel_error_sampled": err,
          "max_rel_diff_scalar_vs_array": float(same)}, "baseline")


@pytest.mark.benchmark(group="scalar loop")
def test_scalar_loop(benchmark, fig1, reference, bench_registry):
    _scalar_loop(benchmark, bench_registry, "scalar loop", *_scalar_points(fig1), reference)


def _twisted_points():
    """100 random points, Omega(L) in [20, 50), nu in [1.1, 100]: the collocation route's upper
    degrees (n ~ 30-56), where a scalar call sums the pencil's quotient in double-double."""
    rng = np.random.default_rng(2026_12_05)
    return rng.uniform(20.0, 50.0, 100).tolist(), rng.uniform(1.1, 100.0, 100).tolist()


@pytest.mark.benchmark(group="scalar loop, twist 20-50")
def test_scalar_loop_twisted_baseline(benchmark, bench_registry):
    tw, nv = _twisted_points()
    _yardstick(benchmark, bench_registry, "scalar loop, twist 20-50",
               lambda: [baseline_critical_load(a, b) for a, b in zip(tw, nv, strict=True)],
               len(tw), rounds=3)


@pytest.mark.benchmark(group="scalar loop, twist 20-50")
def test_scalar_loop_twisted(benchmark, reference, bench_registry):
    _scalar_loop(benchmark, bench_registry, "scalar loop, twist 20-50", *_twisted_points(),
                 reference, sample=20)


@pytest.mark.benchmark(group="scalar loop")
def test_one_point_arrays(benchmark, fig1, reference, bench_registry):
    # the (1,) vectors that e.g. scipy.optimize.least_squares passes, one call per point
    tw, nv = (np.array(v)[:, None] for v in _scalar_points(fig1))
    p = np.concatenate([critical_load(a, b, tol=TOL) for a, b in zip(tw, nv, strict=True)])
    err = _max_error(p, tw[:, 0], nv[:, 0], reference)
    assert err <= 1e-13
    _new(benchmark, bench_registry, "one-point arrays",
         lambda: [critical_load(a, b, tol=TOL) for a, b in zip(tw, nv, strict=True)], tw.size,
         {"max_rel_error_sampled": err}, "baseline")


BRENTQ_NU, BRENTQ_TARGET, BRENTQ_BRACKET = 1.3, 1.1, (2.0, 6.0)


def _search(p_of):
    calls = []

    def f(om):
        calls.append(om)
        return p_of(om, BRENTQ_NU) - BRENTQ_TARGET

    return brentq(f, *BRENTQ_BRACKET, xtol=1e-12), len(calls)


@pytest.mark.benchmark(group="brentq search")
def test_brentq_baseline(benchmark, bench_registry):
    _, calls = _search(baseline_critical_load)
    _yardstick(benchmark, bench_registry, "brentq search",
               lambda: _search(baseline_critical_load), calls, rounds=5)


@pytest.mark.benchmark(group="brentq search")
def test_brentq(benchmark, reference, bench_registry):
    om, calls = _search(lambda t, v: critical_load(t, v, tol=TOL))
    err = abs(reference(om, BRENTQ_NU) / BRENTQ_TARGET - 1)  # p* at the root found
    assert err <= 1e-12
    _new(benchmark, bench_registry, "brentq search",
         lambda: _search(lambda t, v: critical_load(t, v, tol=TOL)), calls,
         {"root_twist": om, "calls": calls, "rel_error_of_p_at_root": err}, "baseline")


# --- a 200 x 200 map over Omega in [0, 100], nu in [1, 100] -------------------------------

@pytest.mark.benchmark(group="map")
def test_map_baseline(benchmark, grid_map, bench_registry):
    tw, nv = grid_map
    sample = np.arange(0, tw.size, 97)  # the baseline's cost does not depend on the point
    _yardstick(benchmark, bench_registry, "map all points",
               lambda: baseline_sweep(tw[sample], nv[sample]), sample.size, rounds=3)
    bench_registry["map collocation part"] = dict(bench_registry["map all points"])
    benchmark.extra_info.update(sample="every 97th point of the map, per-point time")


@pytest.fixture(scope="module")
def map_collocation(grid_map):
    """The map's collocation points (Omega, nu) and critical_load's full result for them."""
    tw, nv = grid_map
    col = np.flatnonzero(critical_load(tw, nv, tol=TOL, full_output=True).method
                         == "collocation")
    return tw[col], nv[col], critical_load(tw[col], nv[col], tol=TOL, full_output=True)


@pytest.mark.benchmark(group="map")
def test_map_baseline_at_solver_degree(benchmark, map_collocation, reference, bench_registry):
    # context for the map's line: at its fixed n = 24 the baseline does not resolve the map's
    # Omega(L) >~ 20 (measured 2026-12-03 on 12 points of each range: max relative error
    # 6.6e-13 for Omega in [0, 10), 3.6e-9 in [10, 20), 1.2e-2 in [20, 35), 4.1 in [35, 50)),
    # so it is also timed at the degree critical_load chose for each point (equal resolution)
    tw, nv, res = map_collocation
    deg = res.n.astype(int)

    def at_degree(points, degree=None):
        return np.array([baseline_critical_load(float(tw[i]), float(nv[i]),
                                                n=int(deg[i] if degree is None else degree))
                         for i in points])

    idx = _sample(tw.size)  # the points the collocation part is judged on
    ref = np.array([reference(float(tw[i]), float(nv[i])) for i in idx])
    errs = {f"max_rel_error_sampled_{name}": float(np.max(np.abs(at_degree(idx, d) / ref - 1)))
            for name, d in (("n24", 24), ("solver_n", None))}
    sample = np.arange(0, tw.size, 97)  # its cost grows with the degree: a spread sample
    _yardstick(benchmark, bench_registry, "map colloc., equal n", lambda: at_degree(sample),
               sample.size, rounds=3)
    benchmark.extra_info.update(sample="every 97th collocation point of the map, per-point time",
                                n_max=int(deg.max()), **errs)


@pytest.mark.benchmark(group="map")
def test_map_collocation_part(benchmark, map_collocation, reference, bench_registry):
    tw, nv, res = map_collocation
    errs, _ = _errors(res.p_star, tw, nv, reference)
    err = float(errs.max())
    # 1e-13 as everywhere (before the degree held the tail's part to a tenth of tol, one
    # sampled point, (35.18, 41.30), erred by 1.1e-13, inside its estimate 3.6e-13)
    assert res.converged.all() and err <= 1e-13
    solve = lambda: critical_load(tw, nv, tol=TOL)  # noqa: E731
    _new(benchmark, bench_registry, "map collocation part", solve, tw.size,
         {"n_max": int(res.n.max()), "max_rel_error_sampled": err}, "baseline")
    # the same timing of the new code against the baseline at the solver's degrees
    equal = bench_registry["map colloc., equal n"]
    equal["new"] = bench_registry["map collocation part"]["new"]
    _check_floor("map colloc., equal n", _record_ratio(
        bench_registry, "map colloc., equal n", solve, tw.size, "baseline at the solver's n"))


@pytest.mark.benchmark(group="map")
def test_map_all_points(benchmark, grid_map, reference, bench_registry):
    tw, nv = grid_map
    res = critical_load(tw, nv, tol=TOL, full_output=True)
    errs, _ = _errors(res.p_star, tw, nv, reference, sample=60)
    err = float(errs.max())
    methods = {m: int((res.method == m).sum()) for m in np.unique(res.method)}
    assert res.converged.all() and err <= 1e-13
    _new(benchmark, bench_registry, "map all points", lambda: critical_load(tw, nv, tol=TOL),
         tw.size, {"methods": methods, "max_rel_error_sampled": err}, "baseline")


# --- large twist and near-degenerate points (yardstick: the baseline; the pre-change ------
# --- per-point routes as an extra column) ------------------------------------------------

@pytest.fixture(scope="module")
def large_twist():
    rng = np.random.default_rng(14)
    return rng.uniform(50.0, 1000.0, 1000), np.exp(rng.uniform(0.0, np.log(100.0), 1000))


@pytest.fixture(scope="module")
def near_degenerate():
    rng = np.random.default_rng(15)
    return rng.uniform(0.0, 50.0, 1000), 1.0 + 10.0 ** rng.uniform(-8.0, -3.0, 1000)


def _baseline_on(tw, nv):
    """The baseline's loop over the points (its cost: at Omega(L) >= 50 its n = 24 does not
    resolve the mode, and near nu = 1 it carries no digit of p* - 1; only its time is used)."""
    return lambda: [baseline_critical_load(a, b) for a, b in zip(tw, nv, strict=True)]


def _extra_yardstick(registry, pattern, name, fn, points, rounds=3) -> None:
    """Time an earlier-route yardstick of `pattern` (an extra column of the table, no floor)."""
    best = min(_interleaved_min([fn], rounds=rounds, repeats=1))
    registry.setdefault(pattern, {}).setdefault("extra", {})[name] = best / points


@pytest.mark.benchmark(group="large twist")
def test_large_twist_baseline(benchmark, large_twist, reference, bench_registry):
    tw, nv = (v[:50] for v in large_twist)
    # the pre-change route, an extra column: it must answer correctly, or its column misleads
    assert max(abs(pre_change_characteristic(tw[i], nv[i]) / reference(float(tw[i]),
                                                                        float(nv[i])) - 1)
               for i in range(0, tw.size, 10)) <= 1e-12
    pre = lambda: [pre_change_characteristic(a, b) for a, b in zip(tw, nv, strict=True)]  # noqa: E731
    for pattern in ("large twist", "large twist, scalar", "large twist, arrays of 4"):
        _extra_yardstick(bench_registry, pattern, "pre-change route", pre, tw.size)
    _yardstick(benchmark, bench_registry, "large twist", _baseline_on(tw, nv), tw.size)
    for pattern in ("large twist, scalar", "large twist, arrays of 4"):
        bench_registry[pattern].update(
            {k: bench_registry["large twist"][k] for k in ("yardstick", "yardstick_call")})
    benchmark.extra_info.update(sample="first 50 of the 1,000 points, per-point time")


@pytest.mark.benchmark(group="large twist")
def test_large_twist(benchmark, large_twist, reference, bench_registry):
    tw, nv = large_twist
    res = critical_load(tw, nv, tol=TOL, full_output=True)
    err = _max_error(res.p_star, tw, nv, reference, sample=20)
    assert (res.method == "characteristic").all() and err <= 1e-13
    _new(benchmark, bench_registry, "large twist", lambda: critical_load(tw, nv, tol=TOL),
         tw.size, {"max_rel_error_sampled": err}, "baseline")


@pytest.mark.benchmark(group="large twist")
def test_large_twist_scalar_loop(benchmark, large_twist, reference, bench_registry):
    # a loop of scalar calls (e.g. a root finder at large twist) over the yardstick's 50 points
    tw, nv = (v[:50].tolist() for v in large_twist)
    res = [critical_load(a, b, tol=TOL, full_output=True) for a, b in zip(tw, nv, strict=True)]
    p = np.array([r.p_star for r in res])
    err = _max_error(p, np.array(tw), np.array(nv), reference, sample=10)
    assert all(r.method == "characteristic" and r.converged for r in res) and err <= 1e-13
    _new(benchmark, bench_registry, "large twist, scalar",
         lambda: [critical_load(a, b, tol=TOL) for a, b in zip(tw, nv, strict=True)], len(tw),
         {"max_rel_error_sampled": err}, "baseline")


@pytest.mark.benchmark(group="near-degenerate")
def test_near_degenerate_baseline(benchmark, near_degenerate, bench_registry):
    from spectral_rod.rod.characteristic import characteristic_critical_load

    tw, nv = (v[:20] for v in near_degenerate)
    for i in range(0, tw.size, 5):  # the pre-change route must answer correctly too
        ref = float(characteristic_critical_load(tw[i], nv[i], dps=50).p_star - 1)
        assert abs(pre_change_increment(tw[i], nv[i])[0] / ref - 1) <= 1e-9
    pre = lambda: [pre_change_increment(a, b) for a, b in zip(tw, nv, strict=True)]  # noqa: E731
    for pattern in ("near-degenerate", "near-degenerate, scalar",
                    "near-degenerate, arrays of 4"):
        _extra_yardstick(bench_registry, pattern, "pre-change route", pre, tw.size)
    _yardstick(benchmark, bench_registry, "near-degenerate", _baseline_on(tw, nv), tw.size)
    for pattern in ("near-degenerate, scalar", "near-degenerate, arrays of 4"):
        bench_registry[pattern].update(
            {k: bench_registry["near-degenerate"][k] for k in ("yardstick", "yardstick_call")})
    benchmark.extra_info.update(sample="first 20 of the 1,000 points, per-point time")


@pytest.mark.benchmark(group="near-degenerate")
def test_near_degenerate(benchmark, near_degenerate, reference, bench_registry):
    from spectral_rod import critical_load_increment
    from spectral_rod.rod.characteristic import characteristic_critical_load

    tw, nv = near_degenerate
    res = critical_load(tw, nv, tol=TOL, full_output=True)
    idx = np.arange(0, tw.size, 50)
    ref = np.array([float(characteristic_critical_load(tw[i], nv[i], dps=50).p_star - 1)
                    for i in idx])
    gain = critical_load_increment(tw[idx], nv[idx])
    err_gain = float(np.max(np.abs(gain / ref - 1)))
    err = float(np.max(np.abs(res.p_star[idx] / (1 + ref) - 1)))
    assert (res.method == "characteristic").all() and err <= 1e-13 and err_gain <= 1e-12
    _new(benchmark, bench_registry, "near-degenerate", lambda: critical_load(tw, nv, tol=TOL),
         tw.size, {"max_rel_error_sampled": err, "max_rel_error_of_increment": err_gain},
         "baseline")


@pytest.mark.benchmark(group="near-degenerate")
def test_near_degenerate_scalar_loop(benchmark, near_degenerate, bench_registry):
    from spectral_rod.rod.characteristic import characteristic_critical_load

    tw, nv = (v[:20].tolist() for v in near_degenerate)  # the yardstick's 20 points
    res = [critical_load(a, b, tol=TOL, full_output=True) for a, b in zip(tw, nv, strict=True)]
    idx = range(0, len(tw), 5)
    err = max(abs(res[i].p_star / float(characteristic_critical_load(tw[i], nv[i], dps=50).p_star)
                  - 1) for i in idx)
    assert all(r.method == "characteristic" and r.converged for r in res) and err <= 1e-13
    _new(benchmark, bench_registry, "near-degenerate, scalar",
         lambda: [critical_load(a, b, tol=TOL) for a, b in zip(tw, nv, strict=True)], len(tw),
         {"max_rel_error_sampled": err}, "baseline")


def _arrays_of_4(tw, nv):
    return np.concatenate([critical_load(tw[i:i + 4], nv[i:i + 4], tol=TOL)
                           for i in range(0, tw.size, 4)])


@pytest.mark.benchmark(group="large twist")
def test_large_twist_arrays_of_4(benchmark, large_twist, reference, bench_registry):
    # arrays of 4 points over the yardstick's 50 points (the last of 2), as a caller that
    # steps a few points at a time passes them
    tw, nv = (v[:50] for v in large_twist)
    err = _max_error(_arrays_of_4(tw, nv), tw, nv, reference, sample=10)
    assert err <= 1e-13
    _new(benchmark, bench_registry, "large twist, arrays of 4", lambda: _arrays_of_4(tw, nv),
         tw.size, {"max_rel_error_sampled": err, "calls": 13}, "baseline")


@pytest.mark.benchmark(group="near-degenerate")
def test_near_degenerate_arrays_of_4(benchmark, near_degenerate, bench_registry):
    from spectral_rod.rod.characteristic import characteristic_critical_load

    tw, nv = (v[:20] for v in near_degenerate)  # the yardstick's 20 points
    p = _arrays_of_4(tw, nv)
    err = max(abs(p[i] / float(characteristic_critical_load(tw[i], nv[i], dps=50).p_star) - 1)
              for i in range(0, tw.size, 5))
    assert err <= 1e-13
    _new(benchmark, bench_registry, "near-degenerate, arrays of 4",
         lambda: _arrays_of_4(tw, nv), tw.size, {"max_rel_error_sampled": err, "calls": 5},
         "baseline")


# --- 10^6 random points in one call (the baseline timed on a sample of them) ---------------

#: Points of the one-call row, and the sample the baseline is timed (and accuracy judged) on.
MILLION, MILLION_SAMPLE = 1_000_000, 200
#: Peak memory allowed for the one-call row.
MILLION_PEAK_MB = 500.0


@pytest.fixture(scope="module")
def million():
    rng = np.random.default_rng(37)
    return rng.uniform(0.0, 100.0, MILLION), rng.uniform(1.0, 100.0, MILLION)


def _peak_mb(fn) -> float:
    """Peak traced memory of one call of `fn` in MB (tracemalloc: numpy reports its buffers
    to it; timed separately, as tracing slows allocation)."""
    import tracemalloc

    tracemalloc.start()
    try:
        fn()
        return tracemalloc.get_traced_memory()[1] / 1e6
    finally:
        tracemalloc.stop()


@pytest.mark.benchmark(group="million points")
def test_million_points_baseline(benchmark, million, bench_registry):
    tw, nv = (v[:MILLION_SAMPLE] for v in million)
    _yardstick(benchmark, bench_registry, "10^6 random points", _baseline_on(tw, nv), tw.size,
               rounds=3)
    benchmark.extra_info.update(sample=f"first {MILLION_SAMPLE} of the {MILLION:,} points")


@pytest.mark.benchmark(group="million points")
def test_million_points(benchmark, million, reference, bench_registry):
    tw, nv = million
    peak = _peak_mb(lambda: critical_load(tw, nv, tol=TOL))
    res = critical_load(tw[:MILLION_SAMPLE], nv[:MILLION_SAMPLE], tol=TOL, full_output=True)
    err = _max_error(res.p_star, tw[:MILLION_SAMPLE], nv[:MILLION_SAMPLE], reference)
    assert res.converged.all() and err <= 1e-13 and peak <= MILLION_PEAK_MB, (err, peak)
    methods = {m: int((res.method == m).sum()) for m in np.unique(res.method)}
    bench_registry.setdefault("10^6 random points", {})["peak_mb"] = peak
    benchmark.pedantic(lambda: critical_load(tw, nv, tol=TOL), rounds=3, iterations=1,
                       warmup_rounds=0)
    st = benchmark.stats.stats
    bench_registry["10^6 random points"]["new"] = (st.min / tw.size, st.median / tw.size)
    entry = _record_ratio(bench_registry, "10^6 random points",
                          lambda: critical_load(tw, nv, tol=TOL), tw.size, "baseline")
    benchmark.extra_info.update(points=tw.size, ratio_min=entry["ratio"],
                                floor=FLOORS["10^6 random points"],
                                ratio_interleaved=entry["interleaved"], peak_mb=peak,
                                seconds_a_call=st.min, max_rel_error_sampled=err,
                                methods_of_the_sample=methods, yardstick="baseline")
    _check_floor("10^6 random points", entry)


# --- import and the first (cold) call, in fresh interpreters ------------------------------

_COLD = """
import sys, time, json
t0 = time.perf_counter()
import spectral_rod
t1 = time.perf_counter()
spectral_rod.critical_load(5.0, 1.3)
t2 = time.perf_counter()
print(json.dumps({"import_s": t1 - t0, "first_call_s": t2 - t1,
                  "scipy": "scipy" in sys.modules, "mpmath": "mpmath" in sys.modules,
                  "modules": len(sys.modules)}))
"""


@pytest.mark.benchmark(group="import and cold call")
def test_import_and_cold_call(benchmark, bench_registry):
    runs = []

    def run():
        out = subprocess.run([sys.executable, "-c", _COLD], capture_output=True, text=True,
                             check=True)
        runs.append(json.loads(out.stdout))

    benchmark.pedantic(run, rounds=5, iterations=1)
    best_import = min(r["import_s"] for r in runs)
    best_call = min(r["first_call_s"] for r in runs)
    bench_registry["import"] = {"import_s": best_import, "first_call_s": best_call}
    benchmark.extra_info.update(import_s=best_import, first_call_s=best_call,
                                first_call_imports_scipy=runs[-1]["scipy"],
                                first_call_imports_mpmath=runs[-1]["mpmath"],
                                modules_after_first_call=runs[-1]["modules"])
    assert best_import < 0.5


# --- the tol knob and the pooling cost model (numbers the docs quote) -----------------------

@pytest.mark.benchmark(group="tol trade")
def test_tol_trade(benchmark, fig1, reference, bench_registry):
    """Issue 37 item 3: the Figure 1 batch at tol 1e-4 costs at most TOL_TRADE_MAX of tol 1e-12,
    its error within ~1e3 of tol (sampled; the issue asks ~100x, which ``hunt_tol.py`` measures
    over random points: 0.18 tol at 1e-4).

    The allocator's state moves this ratio, so the page faults of a call are recorded with it.
    The batched engine's largest temporaries, the (points, k, k) stacks of Schur complements,
    are 366-514 KiB a family at tol 1e-12 and 198-226 KiB at 1e-4 (Figure 1's degree groups),
    above glibc's initial mmap threshold of 128 KiB. Where glibc hands their pages back between
    calls, a call faults hundreds of times, which costs time the arithmetic does not (measured
    2026-12-03): in plain scripts 620-760 faults a call at tol 1e-12 and 0-3 at 1e-4, tol 1e-12
    3-11 % slower, the ratio 0.45-0.49 in most runs; in three runs of this test alone 2 and 0
    faults (0.52, 0.52), then 538 and 284 (0.62). With allocator thresholds that keep the pages
    (``mallopt`` or ``MALLOC_MMAP_THRESHOLD_``; no faults) it was 0.51-0.53 in 10 of 11 runs
    (0.46 in one), and it is 0.525 in instructions (``instruction_counts.py``, re-counted that
    day). Outside load moves it too: a full bench run under heavy load gave 0.45 with no faults.
    Judge the line by the instruction count and by quiet runs without faults.
    """
    tw, nv = fig1
    res = critical_load(tw, nv, tol=1e-4, full_output=True)
    err = _max_error(res.p_star, tw, nv, reference)
    # 1.0e-7 measured: the lower bound, 3e3 below tol and 7e5 above tol 1e-12's errors, says
    # that the degree fell with tol (a bound at the measured value would fail on round-off)
    assert res.converged.all() and 3e-8 <= err <= 1e-4
    t12, t4, t2 = _interleaved_min([lambda: critical_load(tw, nv, tol=1e-12),
                                    lambda: critical_load(tw, nv, tol=1e-4),
                                    lambda: critical_load(tw, nv, tol=1e-2)])
    faults = {tol: _page_faults(lambda tol=tol: critical_load(tw, nv, tol=tol))
              for tol in (1e-12, 1e-4)}
    bench_registry["tol trade"] = {"1e-4": t4 / t12, "1e-2": t2 / t12, "faults": faults}
    benchmark.extra_info.update(cost_ratio_1e4=t4 / t12, cost_ratio_1e2=t2 / t12,
                                max_rel_error_sampled=err, page_faults_1e12=faults[1e-12],
                                page_faults_1e4=faults[1e-4])
    benchmark.pedantic(lambda: critical_load(tw, nv, tol=1e-4), rounds=5, iterations=1)
    # issue 37 item 3: the degree falls with tol as far as the error model certifies
    # (resolution.error_estimate's quadratic term, tuning.truncation_share), and the batch at
    # tol 1e-4 costs at most TOL_TRADE_MAX of tol 1e-12 (n = 12-16 at tol 1e-4 against 20-28:
    # the part of a call that does not depend on the degree, the numpy and Python around the
    # kernel, bounds the ratio; ``python tests/bench/tol_trade_budget.py`` splits it)
    benchmark.extra_info.update(target_1e4=TOL_TRADE_MAX, meets_target=t4 / t12 <= TOL_TRADE_MAX,
                                n_1e4=sorted(set(res.n.tolist())))
    assert t4 / t12 <= TOL_TRADE_MAX, (t4 / t12, t2 / t12)


#: Issue 37: the Figure 1 batch at tol 1e-4 costs at most this share of tol 1e-12, and a scalar
#: call at tol 1e-14 or with an explicit n at most SCALAR_KNOB_MAX times an automatic one.
TOL_TRADE_MAX, SCALAR_KNOB_MAX = 0.3, 2.0


@pytest.mark.benchmark(group="scalar knobs")
def test_scalar_knobs(benchmark, fig1, reference, bench_registry):
    """Scalar calls along Figure 1 at tol 1e-14 and with n forced to the automatic degree,
    against automatic tol 1e-12 calls and the baseline, all interleaved in this run (issue 37
    item 4: no cliff, both <= SCALAR_KNOB_MAX times the automatic call)."""
    import warnings

    from spectral_rod import ConvergenceWarning

    tw, nv = _scalar_points(fig1)
    auto = [critical_load(a, b, tol=TOL, full_output=True) for a, b in zip(tw, nv, strict=True)]
    degrees = [int(r.n) for r in auto]
    forced = [critical_load(a, b, n=d, full_output=True)
              for a, b, d in zip(tw, nv, degrees, strict=True)]
    assert all(r.p_star == f.p_star and f.converged for r, f in zip(auto, forced, strict=True))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)  # tol 1e-14 is below some floors
        tight = np.array([critical_load(a, b, tol=1e-14) for a, b in zip(tw, nv, strict=True)])
        err = _max_error(tight, np.array(tw), np.array(nv), reference)
        t_auto, t_tight, t_n, t_base = _interleaved_min([
            lambda: [critical_load(a, b, tol=TOL) for a, b in zip(tw, nv, strict=True)],
            lambda: [critical_load(a, b, tol=1e-14) for a, b in zip(tw, nv, strict=True)],
            lambda: [critical_load(a, b, n=d) for a, b, d in zip(tw, nv, degrees, strict=True)],
            lambda: [baseline_critical_load(a, b) for a, b in zip(tw, nv, strict=True)]],
            rounds=5, repeats=1)
    entry = {"tol 1e-14 / auto": t_tight / t_auto, "explicit n / auto": t_n / t_auto,
             "baseline / auto": t_base / t_auto, "baseline / tol 1e-14": t_base / t_tight,
             "baseline / explicit n": t_base / t_n, "max_rel_error_sampled_1e14": err}
    bench_registry["scalar knobs"] = entry
    print("scalar knobs (interleaved minima):", {k: f"{v:.3g}" for k, v in entry.items()})
    benchmark.extra_info.update(entry)
    benchmark.pedantic(lambda: [critical_load(a, b, tol=1e-14) for a, b in zip(tw, nv,
                                                                               strict=True)],
                       rounds=3, iterations=1)
    assert err <= 1e-13
    assert t_tight / t_auto <= SCALAR_KNOB_MAX and t_n / t_auto <= SCALAR_KNOB_MAX, entry


@pytest.mark.benchmark(group="pooling cost model")
def test_pooling_cost_model(benchmark, bench_registry):
    # collocation.FIXED_COST and POINT_COST: a batched solve of 30 and of 300 points of one
    # degree gives the fixed cost and the cost a point; the model is used through their ratio
    from spectral_rod._blas_threads import one_blas_thread
    from spectral_rod.rod.collocation.driver import CALL_COST, FIXED_COST, POINT_COST
    from spectral_rod.rod.collocation.eigensolver import solve_points

    rng = np.random.default_rng(2)
    measured = {}
    for n in (16, 22, 36):
        solves = []
        for size in (30, 300):
            tw = rng.uniform(0, max(1.0, 1.8 * (n - 16)), size)
            nv = rng.uniform(1.1, 10.0, size)
            solves.append(lambda n=n, tw=tw, nv=nv: solve_points(n, tw, nv, 1e-14))
        # The fixed cost is a difference of two timings, so both sizes are timed next to each
        # other in each round and the median over rounds is taken: with the minimum of each
        # size over all rounds, a change of load between them once measured 5.02 ms + 9.1 us at
        # n = 22 (a ratio of 551) and 5.96 ms + 16.0 us at n = 36 (372) on 2026-12-03. On one
        # BLAS thread, as inside critical_load, where the model is used.
        per_round = []
        with one_blas_thread():
            for _ in range(12):
                t30, t300 = (_interleaved_min([fn], rounds=1, repeats=3)[0] for fn in solves)
                slope = (t300 - t30) / 270
                per_round.append((t30 - 30 * slope, slope / (n / 22.0) ** 2))
        measured[n] = tuple(float(v) for v in np.median(per_round, axis=0))
    ratios = [fixed / point for fixed, point in measured.values()]
    call = _group_cost()
    bench_registry["pooling"] = {"measured": measured, "model": (FIXED_COST, POINT_COST),
                                 "call": (call, CALL_COST)}
    benchmark.extra_info.update({f"n{n}_fixed_s": f for n, (f, _) in measured.items()})
    benchmark.extra_info.update({f"n{n}_point_s": p for n, (_, p) in measured.items()})
    benchmark.extra_info.update(group_of_one_point_s=call)
    benchmark.pedantic(lambda: None, rounds=1, iterations=1)
    # the decisions depend on FIXED_COST / POINT_COST: within a factor 3 of the measured one
    # (the model's 44; with the kernel's modal_points on 32 lanes, measured 17, 57-59 and
    # 121-125 at n = 16, 22, 36 in three runs of 2026-12-07: a solve of 30 points is one group
    # of 32 lanes, so the measured "fixed" part grows with n)
    assert all(FIXED_COST / POINT_COST / 3 <= r <= 3 * FIXED_COST / POINT_COST for r in ratios)
    # and on CALL_COST / POINT_COST where small groups meet: CALL_COST within a factor 3 of the
    # measured cost of one more group
    assert CALL_COST / 3 <= call <= 3 * CALL_COST, call


def _group_cost() -> float:
    """tuning.CALL_COST: what one more degree group costs the degree loop's engine calls
    (``driver._Arrays.solve``), a group of one point at n = 12 beside one at n = 14 less the
    n = 14 point alone (median of 12 interleaved rounds; ~2.4 us of it the kernel's
    arithmetic)."""
    from spectral_rod.rod.collocation.driver import _Arrays

    tw, nv, rtol = np.array([3.0, 5.0]), np.array([1.5, 2.0]), 1e-14
    two = lambda: _Arrays.solve(tw, nv, np.array([12, 14]), rtol)  # noqa: E731
    one = lambda: _Arrays.solve(tw[1:], nv[1:], np.array([14]), rtol)  # noqa: E731
    diffs = []
    for _ in range(12):
        t_two, t_one = _interleaved_min([two, one], rounds=1, repeats=20)
        diffs.append(t_two - t_one)
    return float(np.median(diffs))
