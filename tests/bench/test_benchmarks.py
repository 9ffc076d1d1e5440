"""Timings (pytest-benchmark), issue 5. Not in the default run; run them with

    python -m pytest -m bench

Groups: single point, Figure 1 sweep, large twist, baseline (the obvious implementation of
``spectral_rod.baseline``). Each records the resolution and the achieved accuracy (against
the mpmath characteristic equation) in ``extra_info``; the terminal summary prints the
baseline/new ratio of the Figure 1 sweep (same run, same points), from the minimum over rounds
of the wall-clock time (on a shared machine the minimum is the round least disturbed by other
jobs; the median is printed too). Not CPU time: idle OpenBLAS worker threads spin and would be
charged to whichever code ran last. Speed is reported, never asserted; the accuracy asserts
are there so that a fast wrong answer cannot pass.
"""

from __future__ import annotations

import numpy as np
import pytest

from spectral_rod import baseline_sweep, critical_load, load_figure1

SAMPLE = 61  # every 61st point of the sweep is checked against the mpmath reference

pytestmark = pytest.mark.bench


@pytest.fixture(scope="module")
def sweep_points():
    d = load_figure1()
    return d["twist_angle"].to_numpy(), d["nu"].to_numpy()


def _sampled_error(p, twist, nu, reference) -> float:
    idx = np.arange(0, twist.size, SAMPLE)
    ref = np.array([reference(float(twist[i]), float(nu[i])) for i in idx])
    return float(np.max(np.abs(np.asarray(p)[idx] / ref - 1)))


def _record(registry, name, benchmark) -> None:
    st = benchmark.stats.stats
    registry[name] = {"min": st.min, "median": st.median}


@pytest.mark.benchmark(group="baseline")
def test_baseline_figure1_sweep(benchmark, sweep_points, reference, bench_registry):
    twist, nu = sweep_points
    p = benchmark.pedantic(baseline_sweep, args=(twist, nu), rounds=7, iterations=1,
                           warmup_rounds=0)
    err = _sampled_error(p, twist, nu, reference)
    benchmark.extra_info.update(points=int(twist.size), n=24, max_rel_error_sampled=err)
    _record(bench_registry, "baseline", benchmark)
    assert err < 1e-9  # n = 24 is not enough for 1e-12 at Omega ~ 10, but it is the baseline


@pytest.mark.benchmark(group="figure1 sweep", min_rounds=60, max_time=2.0)
def test_figure1_sweep(benchmark, sweep_points, reference, bench_registry):
    twist, nu = sweep_points
    res = benchmark(critical_load, twist, nu, tol=1e-12, full_output=True)
    err = _sampled_error(res.p_star, twist, nu, reference)
    _record(bench_registry, "figure1", benchmark)
    info = {"points": int(twist.size), "n_min": int(res.n.min()), "n_max": int(res.n.max()),
            "n_median": float(np.median(res.n)), "max_error_estimate":
            float(res.error_estimate.max()), "max_rel_error_sampled": err}
    if "baseline" in bench_registry:
        base = bench_registry["baseline"]
        info["ratio_baseline_over_new_min"] = base["min"] / bench_registry["figure1"]["min"]
        info["ratio_baseline_over_new_median"] = (base["median"]
                                                  / bench_registry["figure1"]["median"])
    benchmark.extra_info.update(info)
    assert res.converged.all() and err <= 1e-12


@pytest.mark.benchmark(group="single point")
def test_single_point(benchmark, reference):
    res = benchmark(critical_load, 5.0, 1.3, tol=1e-12, full_output=True)
    err = abs(float(res.p_star) / reference(5.0, 1.3) - 1)
    benchmark.extra_info.update(n=int(res.n), rel_error=err,
                                error_estimate=float(res.error_estimate))
    assert err <= 1e-12


@pytest.mark.benchmark(group="large twist")
def test_large_twist_collocation(benchmark, reference):
    twist = np.array([50.0, 100.0, 100.0, 100.0])
    nu = np.array([1.5, 1.5, 10.0, 100.0])
    res = benchmark(critical_load, twist, nu, tol=1e-12, method="collocation",
                    full_output=True)
    ref = np.array([reference(float(a), float(b)) for a, b in zip(twist, nu, strict=True)])
    err = float(np.max(np.abs(res.p_star / ref - 1)))
    benchmark.extra_info.update(n=[int(v) for v in res.n], max_rel_error=err,
                                max_error_estimate=float(res.error_estimate.max()))
    assert res.converged.all() and err <= 1e-12
