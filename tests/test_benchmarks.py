"""Timings (pytest-benchmark). Not in the default run; run them with

    python -m pytest -m bench

Each benchmark records the resolution and the achieved accuracy in ``extra_info``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from spectral_rod import critical_load
from spectral_rod.figure_data import load_figure1

CSV = Path(__file__).resolve().parent.parent / "reference_data" / "figure1_digitised.csv"

pytestmark = pytest.mark.bench


@pytest.fixture(scope="module")
def sweep_points():
    d = load_figure1(CSV)
    return d["twist_angle"].to_numpy(), d["nu"].to_numpy()


@pytest.mark.benchmark(group="figure1 sweep")
def test_figure1_sweep(benchmark, sweep_points, reference):
    twist, nu = sweep_points
    res = benchmark(critical_load, twist, nu, tol=1e-12, full_output=True)
    idx = np.arange(0, twist.size, 97)
    ref = np.array([reference(float(twist[i]), float(nu[i])) for i in idx])
    err = float(np.max(np.abs(res.p_star[idx] / ref - 1)))
    benchmark.extra_info.update(points=int(twist.size), n_max=int(res.n.max()),
                                n_median=float(np.median(res.n)), max_rel_error_sampled=err)
    assert err <= 1e-12
