"""Benchmarks of issue 5 (pytest-benchmark): the registry the tests fill and the terminal line
with the baseline/new ratio of the Figure 1 sweep.

Run with ``python -m pytest -m bench`` (the marker is excluded from the default run).
"""

from __future__ import annotations

import pytest

RATIO_KEY = pytest.StashKey[dict]()


@pytest.fixture(scope="session")
def bench_registry(request) -> dict:
    """Timing statistics (seconds) by benchmark name, shared across the benchmark tests."""
    return request.config.stash.setdefault(RATIO_KEY, {})


def pytest_terminal_summary(terminalreporter, exitstatus, config) -> None:
    reg = config.stash.get(RATIO_KEY, {})
    if "baseline" in reg and "figure1" in reg:
        base, new = reg["baseline"], reg["figure1"]
        terminalreporter.write_sep("=", "issue 5: Figure 1 sweep, baseline / new")
        terminalreporter.write_line(
            f"baseline (cheb n=24, eigvals per point): min {base['min'] * 1e3:.1f} ms, "
            f"median {base['median'] * 1e3:.1f} ms")
        terminalreporter.write_line(
            f"new (critical_load, tol 1e-12):         min {new['min'] * 1e3:.1f} ms, "
            f"median {new['median'] * 1e3:.1f} ms")
        terminalreporter.write_line(
            f"ratio baseline/new: {base['min'] / new['min']:.1f} (min), "
            f"{base['median'] / new['median']:.1f} (median)")
