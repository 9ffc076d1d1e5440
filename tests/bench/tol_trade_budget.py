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
5. The floor of any degree rule (the oracle): each point solved at the lowest of the degrees
   ORACLE_DEGREES whose error against the characteristic equation (``method="characteristic"``,
   an independent formulation, error <= eps (8 + |Omega|)) is <= 1e-4, one engine call per
   degree. Its kernel time, and that plus the automatic tol 1e-4 call's time outside the
   kernel (an under-count: that call has fewer engine calls), against the automatic tol 1e-12
   call: what the tol trade would cost if the solver knew every point's true error.

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


Call = tuple[np.ndarray, np.ndarray, dict]  # critical_load's points and keywords


def interleaved(settings: list[list[Call]], rounds: int) -> list[tuple[float, float, list]]:
    """Per setting (one or more critical_load calls): the minimum time of its calls, the minimum
    kernel time per engine call summed over its engine calls, and the full results of untimed
    first calls (which also warm the caches); the settings interleaved round by round, so that
    a change of load hits all of them alike."""
    with KernelClock() as clock, warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)  # forced degrees miss tol
        results = [[critical_load(tw, nv, full_output=True, **kw) for tw, nv, kw in calls]
                   for calls in settings]
        best = [np.inf] * len(settings)
        kernel: list[list[list[float]]] = [[] for _ in settings]
        for _ in range(rounds):
            for i, calls in enumerate(settings):
                clock.calls.clear()
                t = time.perf_counter()
                for tw, nv, kw in calls:
                    critical_load(tw, nv, **kw)
                best[i] = min(best[i], time.perf_counter() - t)
                kernel[i].append(list(clock.calls))
    return [(b, float(np.array(k).min(axis=0).sum()), r)
            for b, k, r in zip(best, kernel, results, strict=True)]


#: The degrees the oracle (part 5 of the module docstring) chooses from.
ORACLE_DEGREES = (8, 10, 12, 14, 16)


def oracle_calls(tw: np.ndarray, nv: np.ndarray, tol: float) -> list[Call]:
    """Part 5: one call per degree, each point at the lowest of ORACLE_DEGREES whose error
    against the characteristic equation is <= tol (the highest where none is)."""
    reference = critical_load(tw, nv, method="characteristic")
    degree = np.full(tw.size, ORACLE_DEGREES[-1])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        for n in ORACLE_DEGREES[::-1]:
            p = critical_load(tw, nv, tol=tol, n=n)
            degree[np.abs(p / reference - 1.0) <= tol] = n
    return [(tw[degree == n], nv[degree == n], {"tol": tol, "n": n})
            for n in ORACLE_DEGREES if (degree == n).any()]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=60)
    rounds = parser.parse_args().rounds
    if not modal_kernel.available():
        raise SystemExit("the C kernel is not built: pip install -e .")
    d = load_figure1()
    tw, nv = d["twist_angle"].to_numpy(), d["nu"].to_numpy()
    tols = (1e-12, 1e-4, 1e-2)
    settings = ([[(tw, nv, {"tol": tol})] for tol in tols]
                + [[(tw, nv, {"tol": 1e-4, "n": n})] for n in (12, 14)]
                + [oracle_calls(tw, nv, 1e-4)])
    timed = interleaved(settings, rounds)
    print(f"Figure 1 batch, {tw.size} points; minima of {rounds} interleaved rounds (us)")
    print(f"{'tol':>7} {'total':>8} {'kernel':>8} {'rest':>7}  engine calls (degree: points)")
    for tol, (total, kernel, (res,)) in zip(tols, timed[:3], strict=True):
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
    for n, (total, _, (res,)) in zip((12, 14), timed[3:5], strict=True):
        print(f"n = {n} forced: {total / t12:.3f} of the automatic tol 1e-12 call, "
              f"{res.converged.mean():.0%} of the points meet tol 1e-4")
    _, k_oracle, results = timed[5]
    groups = ", ".join(f"{r.n[0]}: {r.n.size}" for r in results)
    rest4 = t4 - k4
    print(f"oracle degrees (true error <= 1e-4; degree: points) {groups}: kernel "
          f"{k_oracle * 1e6:.0f} us ({k_oracle / t12:.3f} of the automatic tol 1e-12 call); with "
          f"the tol 1e-4 call's {rest4 * 1e6:.0f} us outside the kernel "
          f"{(k_oracle + rest4) / t12:.3f}")


if __name__ == "__main__":
    main()
