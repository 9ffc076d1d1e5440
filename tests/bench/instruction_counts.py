"""Load-independent cost of issue 14's collocation call patterns: instructions, not seconds.

    python tests/bench/instruction_counts.py [pattern ...] [--inverse-share]   (needs valgrind)

On the project's shared 2-core machines the same-run wall-clock ratios of ``python -m pytest -m
bench`` swing 1.5-2x with other jobs' load, which hides changes of 5-20 %. An instruction count
does not move with the load: each pattern runs in a fresh interpreter under ``valgrind
--tool=callgrind --instr-atstart=no``; after one uncounted (warm) call, counting is switched on
around one call only (``callgrind_control -i on`` / ``off``), so imports and the per-degree
operator assembly are excluded. Printed: instructions per point of the yardstick (the baseline,
``spectral_rod.rod.baseline``, n = 24: its cost does not depend on the point; 40 Figure 1 points)
and of ``critical_load`` at tol 1e-12 (as the benchmarks), and their ratio; and the Figure 1
batch at tol 1e-4 as a fraction of tol 1e-12; with ``--inverse-share``, the Figure 1 batch's
fraction inside numpy's per-matrix inverse (the Schur complements of the batched engine that
LAPACK inverts: since 2026-12-05 only small stacks and what the block recursion's check
rejects, ``spectral_rod.rod.collocation.stacked_inverse``) and its ratio to the baseline were that
inverse free. It is not a time
ratio: the baseline's dense LAPACK runs more instructions per cycle than numpy's per-call
overhead, so the wall-clock ratios measured so far lie below these (2026-12-02, one machine:
scalar loop 5.7 here, 3.8-7.4 in wall-clock runs; batches of 100 19.1 here, 13.9-22.9).
A development tool, not a test (pytest does not collect it).
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

#: Per pattern: the statement timed (tw, nv: Figure 1's points) and the points it solves.
PATTERNS = {
    "baseline": ("[baseline_critical_load(a, b) for a, b in zip(tw[:40], nv[:40])]", "40"),
    "figure1 batch": ("critical_load(tw, nv)", "tw.size"),
    "figure1 per curve": ("[critical_load(tw[nv == v], v) for v in np.unique(nv)]", "tw.size"),
    "batches of 100": ("[critical_load(tw[i:i + 100], nv[i:i + 100]) "
                       "for i in range(0, tw.size, 100)]", "tw.size"),
    "batches of 10": ("[critical_load(tw[i:i + 10], nv[i:i + 10]) for i in range(0, 600, 10)]",
                      "600"),
    "scalar loop": ("[critical_load(a, b) for a, b in zip(tw[::6].tolist(), nv[::6].tolist())]",
                    "len(tw[::6])"),
    "brentq search": ("brentq(lambda om: critical_load(om, 1.3) - 1.1, 2.0, 6.0, xtol=1e-12)",
                      "9"),
}
#: The tol trade (issue 14: the Figure 1 batch at tol 1e-4 costs at most half of tol 1e-12).
TRADE = ("figure1 batch tol 1e-4", "critical_load(tw, nv, tol=1e-4)", "tw.size")

#: The child's names: what the statements of PATTERNS and TRADE may use.
SETUP = """
import os, numpy as np
from scipy.optimize import brentq
from spectral_rod import baseline_critical_load, critical_load, load_figure1
d = load_figure1()
tw, nv = d["twist_angle"].to_numpy(), d["nu"].to_numpy()
"""
_CHILD = SETUP + """
run = lambda: {stmt}
run()
os.system(f"callgrind_control -i on {{os.getpid()}} > /dev/null")
run()
os.system(f"callgrind_control -i off {{os.getpid()}} > /dev/null")
print("POINTS", {points})
"""


#: callgrind's name for numpy's per-matrix inverse gufunc, the batched engine's largest single
#: cost (``--inverse-share``: what issue 14's Figure 1 batch would reach were it free).
INVERSE_SYMBOL = "inv<double>"
INVERSE_FLAG = "--inverse-share"


def profile(pattern: str, symbol: str | None = None) -> tuple[float, float]:
    """Instructions per point of one call of `pattern` (see the module docstring) and the
    fraction of them spent inside `symbol` (callgrind_annotate's inclusive count; 0 if None)."""
    stmt, points = PATTERNS[pattern] if pattern != TRADE[0] else TRADE[1:]
    with tempfile.TemporaryDirectory() as tmp:
        out_file = Path(tmp) / "callgrind.out"
        out = subprocess.run(
            ["valgrind", "--tool=callgrind", "--instr-atstart=no",
             f"--callgrind-out-file={out_file}", sys.executable, "-c",
             _CHILD.format(stmt=stmt, points=points)],
            capture_output=True, text=True, check=True)
        annotated = "" if symbol is None else subprocess.run(
            ["callgrind_annotate", "--inclusive=yes", str(out_file)],
            capture_output=True, text=True, check=True).stdout
    n = int(re.search(r"POINTS (\d+)", out.stdout).group(1))
    collected = int(re.search(r"Collected : (\d+)", out.stderr).group(1))
    inside = 0 if symbol is None else inclusive_count(annotated, symbol)
    return collected / n, inside / collected


def inclusive_count(annotated: str, symbol: str) -> int:
    """The inclusive instructions of the first function in callgrind_annotate's listing whose
    name contains `symbol` (0 if none)."""
    for line in annotated.splitlines():
        m = re.match(r"\s*([\d,]+) ", line)
        if m and symbol in line:
            return int(m.group(1).replace(",", ""))
    return 0


def count(pattern: str) -> float:
    """Instructions per point of one call of `pattern` (see the module docstring)."""
    return profile(pattern)[0]


def main(args: list[str]) -> None:
    if shutil.which("valgrind") is None or shutil.which("callgrind_control") is None:
        sys.exit("valgrind (with callgrind_control) is needed")
    share = INVERSE_FLAG in args
    names = [a for a in args if a != INVERSE_FLAG]
    known = [p for p in PATTERNS if p != "baseline"] + [TRADE[0]]
    names = names or ([] if share else known)
    unknown = set(names) - set(known)
    if unknown:
        sys.exit(f"unknown pattern(s) {sorted(unknown)}; known: {known}")
    counts: dict[str, float] = {}

    def cached(name: str) -> float:  # the Figure 1 batch serves its row and the trade's
        if name not in counts:
            counts[name] = count(name)
        return counts[name]

    base = cached("baseline")
    print(f"{'pattern':<24}{'instructions/point':>20}{'baseline/new':>14}")
    print(f"{'baseline (n = 24)':<24}{base:>20,.0f}")
    for name in (n for n in names if n != TRADE[0]):
        new = cached(name)
        print(f"{name:<24}{new:>20,.0f}{base / new:>14.1f}", flush=True)
    if TRADE[0] in names:
        loose = cached(TRADE[0])
        print(f"{TRADE[0]:<24}{loose:>20,.0f}   {loose / cached('figure1 batch'):.3f} of tol "
              "1e-12")
    if share:
        per_point, frac = profile("figure1 batch", INVERSE_SYMBOL)
        print(f"figure1 batch: {frac:.1%} of its {per_point:,.0f} instructions a point in "
              f"{INVERSE_SYMBOL}; were it free, {base / (per_point * (1 - frac)):.1f}x below "
              "the baseline")

if __name__ == "__main__":
    main(sys.argv[1:])
