"""The convergence scene's measurements (issue 5): exponential vs O(h^2), cost table."""

from __future__ import annotations

import numpy as np
import pytest

from reproduce import convergence as scene


@pytest.fixture(scope="module")
def case_runs():
    return scene.study_case(10.0, 1.1)


def test_collocation_converges_exponentially_and_fd_algebraically(case_runs):
    df = case_runs
    col = df[df["method"] == "collocation (fixed n)"]
    fd = df[df["method"] == "finite differences"]
    # collocation: from error 1e-2 down to 1e-12 within ~20 degrees (exponential)
    n_hi = col.loc[col["rel_error"] <= 1e-12, "resolution"].min()
    n_lo = col.loc[col["rel_error"] <= 1e-2, "resolution"].min()
    assert n_hi - n_lo <= 20
    # finite differences: slope -2 on the log-log plot, never reaching 1e-8 on this range
    assert scene._fd_slopes(df)[0] == pytest.approx(2.0, abs=0.1)
    assert fd["rel_error"].min() > 1e-8


def test_cost_table_lists_every_method_and_target(case_runs):
    df = case_runs
    cost = scene.cost_table(df)
    assert set(cost["target"]) == set(scene.TARGETS)
    methods = set(cost["method"])
    assert {"collocation (fixed n)", "finite differences", "characteristic eq. (mpmath)",
            "collocation (auto, tol)"} <= methods
    auto = cost[cost["method"] == "collocation (auto, tol)"]
    assert np.all(auto["rel_error"] <= auto["target"])  # the automatic degree meets tol
    fd12 = cost[(cost["method"] == "finite differences") & (cost["target"] == 1e-12)]
    assert fd12["resolution"].isna().all() or fd12["resolution"].iloc[0] is None


def test_mode_coefficients_have_decayed_at_the_automatic_degree():
    n, family, c1, c2 = scene.mode_coefficients(10.0, 1.1)
    assert family in ("symmetric", "antisymmetric")
    assert max(np.abs(c1).max(), np.abs(c2).max()) == pytest.approx(1.0)
    tail = max(np.abs(c1[-3:]).max(), np.abs(c2[-3:]).max())
    assert tail < 1e-8 and c1.size == n + 1


@pytest.mark.slow
def test_scene_runs_and_writes_its_outputs(tmp_path):
    out = scene.run(tmp_path, lambda msg: None)
    names = {p.name for p in out.files}
    assert {"convergence_resolution.png", "convergence_time.png",
            "convergence_coefficients.png", "convergence.csv", "convergence_cost.csv"} <= names
    assert out.report.startswith("## Convergence")
    assert "| Ω(L), ν | method |" in out.report
    assert out.details["figure1_speed"]["max_rel_diff"] < 1e-10


def test_interleaved_best_times_alternates_and_keeps_each_minimum(monkeypatch):
    # a fake clock: each call of function i advances it by the durations listed for i, so the
    # minima and the order of the calls are known exactly
    clock, calls = [0.0], []
    durations = {0: iter([9.0, 3.0, 5.0]), 1: iter([9.0, 1.0, 0.5])}

    def make(i):
        def fn():
            calls.append(i)
            clock[0] += next(durations[i])
            return f"result {i} after {len(calls)} calls"
        return fn

    monkeypatch.setattr(scene.time, "perf_counter", lambda: clock[0])
    (best0, out0), (best1, out1) = scene.interleaved_best_times([make(0), make(1)],
                                                                 min_total=1.5)
    # one untimed call each, then rounds of both until *each* has run min_total (function 0
    # alone reaches it after one round)
    assert calls == [0, 1, 0, 1, 0, 1]
    assert (best0, best1) == (3.0, 0.5)  # the timed repeats only (not the untimed 9.0)
    assert (out0, out1) == ("result 0 after 5 calls", "result 1 after 6 calls")
