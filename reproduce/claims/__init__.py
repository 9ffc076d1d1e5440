"""Scene `claims`: the paper's statements about the straight twisted rod, checked one by one.

Models: the hinged straight rod with spontaneous twist (Eq. ``inst1``); p* = P_cr / (pi^2 A1 /
L^2), Omega(L) = omega30 L, nu = I2/I1.
Compares: Chebyshev collocation (the dense curves), the paper's characteristic equation in
mpmath (every decisive number: family crossings, slopes, loads at large twist, window ends,
modes) and the closed forms of :mod:`spectral_rod.rod.closed_form`.
Writes: claims.json / claims.md (via :mod:`reproduce.ledger`, keeping the other scenes' rows),
claims_load.png (p* to 20 pi with the limit lines and the approach to the limit),
claims_wavenumbers.png (beta_k L and beta_2 - beta_1 against Omega(L), the imaginary-beta_1
window marked), claims_mode.png (the 3-D centreline of the buckling mode vs Euler's planar
mode), coverage.md (the paper sentence by sentence: :mod:`.coverage`) and the report section
(in ``report.md``).

The package: :mod:`.evidence` computes every number (calls to the library),
:mod:`.rows` declares each claim with its verdict rule and measures it, :mod:`.figures` draws.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

from reproduce._runner import SceneOutput
from reproduce.claims.coverage import coverage_markdown
from reproduce.claims.evidence import DPS, StraightRodEvidence, compute_evidence, solver_agreement
from reproduce.claims.figures import figure_load, figure_mode, figure_wavenumbers
from reproduce.claims.rows import CLAIMS, evaluate_claim, evaluate_claims
from reproduce.io import read_json, write_figure, write_text
from reproduce.ledger import (
    COVERAGE_FILE,
    LEDGER_CHECK,
    Claim,
    update_ledger,
    verdict_counts,
)
from reproduce.tables import markdown_table

NAME = "claims"
SUMMARY = ("straight twisted rod: every claim of the paper's straight-rod section, both solvers "
           "-> claims.json/.md, claims_load.png, claims_wavenumbers.png, claims_mode.png")

#: `python -m reproduce check`: per output file and column (or JSON key), how a regenerated
#: value may differ from the committed one (rules in reproduce/compare.py).
CHECK = {
    "claims.json": LEDGER_CHECK,
    "sections/claims.json": {"details.timings.*": "ignore",
                             "details.solver_agreement": {"rel": 1e-6, "abs": 1e-10},
                             "*": "exact"},
}

__all__ = ["CLAIMS", "NAME", "SUMMARY", "compute_evidence", "evaluate_claim", "evaluate_claims",
           "run"]


def report_section(claims: list[Claim], ev: StraightRodEvidence, seconds: float) -> str:
    counts = ", ".join(f"{n} {v}" for v, n in verdict_counts(c.verdict for c in claims).items()
                       if n)
    lines = ["## Claims: the straight rod, statement by statement", "",
             f"{len(claims)} claims of the paper's straight-rod section checked: {counts}. "
             f"Decisive numbers come from both solvers (collocation and the characteristic "
             f"equation in mpmath, {DPS} digits); they agree to {solver_agreement(ev):.1e} "
             f"(relative) over all {len(ev.spot) + len(ev.limit)} spot loads and "
             f"{len(ev.maxima)} maxima. Full ledger: `claims.md`, `claims.json`; the paper "
             f"sentence by sentence: `{COVERAGE_FILE}`.", "",
             markdown_table(["id", "claim", "verdict", "key numbers"],
                            [[f"`{c.id}`", c.claim, f"**{c.verdict}**",
                              c.numbers.get("headline", "")] for c in claims]),
             "", "![p* to 20π](claims_load.png)", "",
             "![wavenumbers](claims_wavenumbers.png)", "", "![mode](claims_mode.png)", "",
             "Run time: " + ", ".join(f"{k} {v:.1f} s" for k, v in ev.timings.items())
             + f"; total {seconds:.1f} s."]
    return "\n".join(lines) + "\n"


def run(out: Path, progress: Callable[[str], None]) -> SceneOutput:
    t0 = time.perf_counter()
    ev = compute_evidence(progress)
    claims = evaluate_claims(ev)
    files = update_ledger(out, NAME, claims)
    known = {str(r["id"]) for r in read_json(out / "claims.json", list)}
    files.append(write_text(out / COVERAGE_FILE, coverage_markdown(known)))
    for name, maker in (("claims_load.png", figure_load),
                        ("claims_wavenumbers.png", figure_wavenumbers),
                        ("claims_mode.png", figure_mode)):
        files.append(write_figure(out / name, maker(ev)))
    seconds = time.perf_counter() - t0
    report = report_section(claims, ev, seconds)
    progress("verdicts: " + ", ".join(f"{c.id}={c.verdict}" for c in claims))
    details = {"verdicts": {c.id: c.verdict for c in claims}, "timings": ev.timings,
               "solver_agreement": solver_agreement(ev)}
    return SceneOutput(files=files, report=report, details=details)
