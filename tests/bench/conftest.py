"""Benchmarks (pytest-benchmark): the registry the tests fill and the terminal table of same-run
ratios (yardstick / new) per call pattern, with extra columns for earlier-route yardsticks.

Run with ``python -m pytest -m bench`` (the marker is excluded from the default run); add
``--benchmark-autosave`` to keep the results (with ``extra_info``) under ``.benchmarks/`` and
``--benchmark-compare --benchmark-compare-fail=min:50%`` to compare against the last saved run
on the same machine (README, "More commands").
"""

from __future__ import annotations

import pytest

RATIO_KEY = pytest.StashKey[dict]()


@pytest.fixture(scope="session")
def bench_registry(request) -> dict:
    """Per pattern: per-point (min, median) seconds of the yardstick and the new code, the
    ratio, and the interleaved check of the ratio."""
    return request.config.stash.setdefault(RATIO_KEY, {})


def pytest_terminal_summary(terminalreporter, exitstatus, config) -> None:
    reg = config.stash.get(RATIO_KEY, {})
    rows = [(name, e) for name, e in reg.items() if "ratio" in e]
    if not rows and not {"import", "tol trade", "pooling"} & set(reg):
        return
    tr = terminalreporter
    tr.write_sep("=", "same-run ratios, yardstick / new (minimum over rounds)")
    tr.write_line(f"{'pattern':<30}{'yardstick':<28}{'yardstick/pt':>14}{'new/pt':>12}"
                  f"{'ratio':>8}{'floor':>7}{'interleaved':>13}")
    for name, e in rows:
        tr.write_line(f"{name:<30}{e['yardstick_name']:<28}{_us(e['yardstick'][0]):>14}"
                      f"{_us(e['new'][0]):>12}{e['ratio']:>8.1f}{e['floor']:>7.1f}"
                      f"{e['interleaved']:>13.1f}")
        for extra, seconds in e.get("extra", {}).items():  # earlier-route yardsticks
            tr.write_line(f"{'':<30}{extra:<28}{_us(seconds):>14}{'':>12}"
                          f"{seconds / e['new'][0]:>8.1f}")
        if "peak_mb" in e:
            tr.write_line(f"{'':<30}peak memory of the call: {e['peak_mb']:.0f} MB")
    if "tol trade" in reg:
        tt = reg["tol trade"]
        tr.write_line(f"tol trade, Figure 1 batch (interleaved minima): tol 1e-4 costs "
                      f"{tt['1e-4']:.2f} and tol 1e-2 {tt['1e-2']:.2f} of tol 1e-12 (issue"
                      f" 37 target <= 0.3); minor page faults a call: {tt['faults'][1e-12]}"
                      f" at tol 1e-12, {tt['faults'][1e-4]} at 1e-4")
    if "pooling" in reg:
        pm = reg["pooling"]
        got = ", ".join(f"n={n}: {f * 1e3:.2f} ms + {c * 1e6:.1f} us (n/22)^2"
                        for n, (f, c) in pm["measured"].items())
        tr.write_line(f"pooling cost model {pm['model'][0] * 1e3:.2f} ms + "
                      f"{pm['model'][1] * 1e6:.1f} us (n/22)^2; measured {got}; one more "
                      f"degree group {pm['call'][0] * 1e6:.1f} us (CALL_COST "
                      f"{pm['call'][1] * 1e6:.0f} us)")
    if "import" in reg:
        imp = reg["import"]
        tr.write_line(f"import spectral_rod: {imp['import_s'] * 1e3:.1f} ms; first call "
                      f"critical_load(5.0, 1.3): {imp['first_call_s'] * 1e3:.0f} ms (fresh "
                      f"interpreters, minimum of 5)")


def _us(seconds: float) -> str:
    return f"{seconds * 1e6:.1f} us"
