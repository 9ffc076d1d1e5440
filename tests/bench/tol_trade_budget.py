"""Where the Figure 1 batch's time goes at each tol: the budget behind the tol trade.

    python tests/bench/tol_trade_budget.py [--rounds N]

Issue 37 asks the Figure 1 batch (1,201 points) at tol 1e-4 to cost <= 0.3 of tol 1e-12
(``TOL_TRADE_MAX``; ``python -m pytest -m bench -k tol_trade`` measures the ratio). This
script splits each call into the C kernel's time and the rest, so that the ratio's parts can be
checked:

1. For tol 1e-12, 1e-4 and 1e-2: the call's minimum time over N rounds, the kernel's
   (``modal_kernel.modal_points`` wrapped and timed, its minimum summed over the call's engine
   calls), the rest (numpy and Python: validation, routing, the a priori degree, pooling, the
   family rule, the estimate, the bounds), the engine calls and the degrees they solved.
2. The ratio at tol 1e-4 and 1e-2 against tol 1e-12, and the kernel's own ratio.
3. The time outside the kernel that both calls would have to lose for the ratio at tol 1e-4 to
   reach the target (a cut X common to both: (t4 - X) / (t12 - X) <= TOL_TRADE_MAX).
4. The lowest degrees as a floor: n forced to 12 and 14 for every point (one engine call, no a
   priori degree, pooling or raise), their cost against the automatic tol 1e-12 call and the
   share of points whose estimate meets tol 1e-4.

The kernel must be built (``pip install -e .``). Minima in one process, every setting's calls
interleaved round by round; timings still move with the machine's load and the allocator's
state (see ``test_tol_trade``). A development tool, not a test (pytest does not collect it).
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from spectral_rod import ConvergenceWarning, critical_load, load_figure1
from spectral_rod.rod.collocation import modal_kernel

sys.path.insert(0, str(Path(__file__).parent))
from test_benchmarks import TOL_TRADE_MAX  # the target, defined once


class KernelClock:
    """Wraps ``modal_kernel.modal_points`` (as the engine calls it) to time each of its calls."""

    def __init__(self) -> None:
        self.calls: list[float] = []
        self._original = modal_kernel.modal_points

    def __enter__(self) -> KernelClock:
        def timed(families, coef, **kw):
            t = time.perf_counter()
            out = self._original(families, coef, **kw)
            self.calls.append(time.perf_counter() - t)
            return out

        modal_kernel.modal_points = timed
        return self

    def __exit__(self, *exc) -> None:
        modal_kernel.modal_points = self._original


def interleaved(tw, nv, settings: list[dict], rounds: int) -> list[tuple[float, float, Any]]:
    """Per setting (critical_load's keywords): the minimum time of a call, the minimum kernel
    time per engine call summed over the call's engine calls, and the full result of an untimed
    first call (which also warms the caches); the settings' calls interleaved round by round,
    so that a change of load hits all of them alike."""
    with KernelClock() as clock, warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)  # forced degrees miss tol
        results = [critical_load(tw, nv, full_output=True, **kw) for kw in settings]
        best = [np.inf] * len(settings)
        kernel: list[list[list[float]]] = [[] for _ in settings]
        for _ in range(rounds):
            for i, kw in enumerate(settings):
                clock.calls.clear()
                t = time.perf_counter()
                critical_load(tw, nv, **kw)
                best[i] = min(best[i], time.perf_counter() - t)
                kernel[i].append(list(clock.calls))
    return [(b, float(np.array(k).min(axis=0).sum()), r)
            for b, k, r in zip(best, kernel, results, strict=True)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=60)
    rounds = parser.parse_args().rounds
    if not modal_kernel.available():
        raise SystemExit("the C kernel is not built: pip install -e .")
    d = load_figure1()
    tw, nv = d["twist_angle"].to_numpy(), d["nu"].to_numpy()
    tols = (1e-12, 1e-4, 1e-2)
    settings = [{"tol": tol} for tol in tols] + [{"tol": 1e-4, "n": n} for n in (12, 14)]
    timed = interleaved(tw, nv, settings, rounds)
    print(f"Figure 1 batch, {tw.size} points; minima of {rounds} interleaved rounds (us)")
    print(f"{'tol':>7} {'total':>8} {'kernel':>8} {'rest':>7}  engine calls (degree: points)")
    for tol, (total, kernel, res) in zip(tols, timed[:3], strict=True):
        degrees, counts = np.unique(res.n, return_counts=True)
        calls = ", ".join(f"{n}: {k}" for n, k in zip(degrees.tolist(), counts.tolist(),
                                                       strict=True))
        print(f"{tol:>7g} {total * 1e6:>8.0f} {kernel * 1e6:>8.0f} {(total - kernel) * 1e6:>7.0f}"
              f"  {degrees.size}: {calls}")
    (t12, k12, _), (t4, k4, _), (t2, k2, _) = timed[:3]
    for tol, t, k in ((1e-4, t4, k4), (1e-2, t2, k2)):
        print(f"tol {tol:g} / tol 1e-12: {t / t12:.3f} (kernel alone {k / k12:.3f})")
    cut = max(0.0, (t4 - TOL_TRADE_MAX * t12) / (1.0 - TOL_TRADE_MAX))
    print(f"a cut X common to both calls reaching {TOL_TRADE_MAX}: X >= {cut * 1e6:.0f} us of the "
          f"{(t4 - k4) * 1e6:.0f} (tol 1e-4) and {(t12 - k12) * 1e6:.0f} us (tol 1e-12) "
          f"outside the kernel")
    for n, (total, _, res) in zip((12, 14), timed[3:], strict=True):
        print(f"n = {n} forced: {total / t12:.3f} of the automatic tol 1e-12 call, "
              f"{res.converged.mean():.0%} of the points meet tol 1e-4")

if __name__ == "__main__":
    main()
