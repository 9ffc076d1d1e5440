"""Scene `ring`: the spontaneously twisted ring -- Eq. ``crit2`` against the converged answer.

Models: a circular ring (radius R) whose cross-section turns N times around the centreline,
Omega = N s/R, with bending stiffnesses A1 = E1 I1 <= A2 = E1 I2 and torsion A3 = E2 (I1 + I2),
under a uniform inward load q; loads as q R^3/(E1 I1), nu = I2/I1, e = E2/E1.
Compares: the paper's one-mode Galerkin estimate Eq. ``crit2`` with the converged solution of the
linearised problem in two formulations that share no hand derivation -- the Fourier-Galerkin
second variation (:mod:`spectral_rod.ring.second_variation`) and the numerically linearised Eqs.
``Munder`` (:mod:`spectral_rod.ring.munder`) -- for every reading of the load ("hydrostatic":
pressure on the projection; "axis": toward the ring's axis; "centre": toward its centre point;
"dead": fixed direction), for N = 0..10, nu in {1, 1.1, 1.3, 1.5, 2, 4} (and to nu = 100 for the
general claims), e = 1 and isotropic; the one-harmonic Galerkin the paper states; closed forms of
the untwisted ring and of the rapidly twisted ring, and the limits N, nu -> infinity
(:mod:`.limits`); the rigid motions each reading destabilises (the supports); rectangular
sections (the torsion caveat).
Writes: ring_table.csv / ring_table.md, ring_threshold.csv / ring_threshold.md,
ring_formulations.csv (the two formulations side by side), ring_wide.csv (the wide-nu scan),
ring.png, the ring rows of claims.json / claims.md and the report section.

The package: :mod:`.evidence` computes every number (calls to the library), :mod:`.rows`,
:mod:`.galerkin_rows` and :mod:`.model_rows` declare each claim with its verdict rule and measure
it, with the named thresholds of :mod:`.standards` and the root causes of :mod:`.root_causes`;
:mod:`.outputs` writes tables and the figure.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

from reproduce._runner import SceneOutput
from reproduce.io import write_csv, write_figure, write_text
from reproduce.ledger import LEDGER_CHECK, Claim, update_ledger
from reproduce.ring.evidence import (
    E_RATIOS,
    NUS,
    TWISTS,
    WIDE_NUS,
    RingEvidence,
    compute_evidence,
)
from reproduce.ring.outputs import (
    draw,
    formulations_markdown,
    table_markdown,
    threshold_markdown,
)
from reproduce.ring.rows import (
    CLAIMS,
    FORMULATION_TOL,
    crit2_deviation,
    evaluate_claim,
    evaluate_claims,
)
from reproduce.tables import markdown_table
from spectral_rod import RING_LOADS

NAME = "ring"
SUMMARY = ("twisted ring: Eq. crit2 vs the converged q_cr in two formulations (second variation, "
           "Munder), every reading of the load -> ring_table.*, ring_threshold.*, "
           "ring_formulations.csv, ring_wide.csv, ring.png, ring ledger rows")

#: `python -m reproduce check`: per output file and column (or JSON key), how a regenerated
#: value may differ from the committed one (rules in reproduce/compare.py).
CHECK = {
    "ring_table.csv": {
        "crit2": 1e-12,
        "q_hydrostatic": {"rel": 1e-10, "floor": "rel_change_hydrostatic"},
        "q_axis": {"rel": 1e-10, "floor": "rel_change_axis"},
        "in_plane_fraction_*": {"rel": 1e-6, "abs": 1e-9},
        "rel_change_*": {"rel": 1e-6, "abs": 1e-12}, "min_inverse_load_*": {"abs": 1e-12},
        "rel_dev_*": {"rel": 1e-9, "abs": 1e-12},
        "*": "exact",  # labels, nu, N, kind, wavenumber, max_frequency
    },
    "ring_threshold.csv": {"N_continuous": 1e-12, "crit2_at_*": {"rel": 1e-9, "abs": 1e-12},
                           "q_*": 1e-9, "*": "exact"},
    "ring_formulations.csv": {"q_*": 1e-10, "rel_diff": {"abs": 1e-12},
                              "e_ratio": 1e-14, "nu": 1e-14, "*": "exact"},
    "ring_wide.csv": {"q": 1e-10, "min_inverse_load": {"abs": 1e-12}, "*": "exact"},
    "claims.json": LEDGER_CHECK,
    "sections/ring.json": {"details.timings.*": "ignore",
                           "details.crit2_deviation.*": {"rel": 1e-9, "abs": 1e-12},
                           "*": "exact"},
}

__all__ = ["CLAIMS", "E_RATIOS", "NAME", "NUS", "SUMMARY", "TWISTS", "RingEvidence",
           "compute_evidence", "evaluate_claim", "evaluate_claims", "run"]


def physical_threshold_text(claim: Claim) -> str:
    """The answer of the ring-spontaneous-instability row to "is the threshold physical?"."""
    n = claim.numbers
    facts = (f"the numerical stiffness is positive definite in every one of the {n['n_solves']} "
             f"solves, the smallest 1/q is {n['min_inverse_load']:.1e} and the smallest critical "
             f"load {n['min_q']:.4f}")
    answer = {"fails": "No. The stress-free twisted ring minimises a non-negative energy;",
              "holds": "Yes: a converged critical load at or beyond the threshold is ≤ 0;"
              }.get(claim.verdict, f"Undecided ({claim.verdict}):")
    return f"**Is the threshold twist physical?** {answer} {facts} (see `ring_threshold.md`)."


def verdicts_by_reading_markdown(claims: list[Claim]) -> str:
    """The ring verdicts under each reading of the load alone (from caveat-load-model)."""
    per = next(c for c in claims if c.id == "caveat-load-model").numbers["verdicts_per_load"]
    rows = [[f"`{cid}`", *(v[ld] for ld in RING_LOADS),
             "**depends on the reading**" if len(set(v.values())) > 1 else ""]
            for cid, v in per.items()]
    return ("**Verdicts under each reading of the load** (each row judged on that reading's "
            "numbers alone):\n\n" + markdown_table(["row", *RING_LOADS, ""], rows))


def report_section(claims: list[Claim], ev: RingEvidence, seconds: float,
                   witnesses: int = 0) -> str:
    d = crit2_deviation(ev)
    h = d["hydrostatic"]
    conv = ev.table[[f"max_frequency_{ld}" for ld in RING_LOADS]].max().max()
    rel = ev.table[[f"rel_change_{ld}" for ld in RING_LOADS]].max().max()
    lines = ["## Ring: Eq. crit2 against the converged answer", "",
             f"{len(ev.table)} rings (N = {TWISTS[0]}..{TWISTS[-1]}, ν ∈ "
             f"{{{', '.join(f'{v:g}' for v in NUS)}}}, e = 1 and isotropic e = "
             f"{E_RATIOS['isotropic']:.4f}) solved for every reading of the load ("
             + ", ".join(RING_LOADS) + "); every critical load "
             f"converged (largest change between the last two truncations {rel:.1e} relative, "
             f"frequencies ≤ {int(conv)}), and {len(ev.wide)} cases on the wide scan to ν = "
             f"{max(WIDE_NUS):g}. Each ring is solved once per run through one memo: "
             f"{ev.solves['distinct']} solves for {ev.solves['requested']} requests (the ν* "
             f"searches of `destabilisation_threshold` solve their own rings), and {witnesses} "
             "rings re-solved by Eqs. Munder as witnesses (the decisive rings of two verdicts, "
             "on the evidence of all readings and of each alone).", "",
             f"**Two formulations.** The second variation of the energy and the paper's "
             f"equilibrium equations Munder (linearised numerically) agree to "
             f"{ev.formulations['rel_diff'].max():.1e} (limit {FORMULATION_TOL:g}) on "
             f"{len(ev.formulations)} cases:", "", formulations_markdown(ev), "",
             f"**How far is crit2?** Max |crit2 − q|/q = {h['max_rel_dev']:.3g} (hydrostatic; "
             f"axis {d['axis']['max_rel_dev']:.3g}); median {h['median_rel_dev']:.2f}; where "
             f"crit2 > 0 the relative error (crit2 − q)/q spans "
             f"[{h['positive_formula_rel_dev_range'][0]:+.2f}, "
             f"{h['positive_formula_rel_dev_range'][1]:+.2f}]; even at N = 0 up to "
             f"{h['max_rel_dev_N0']:.2f}. crit2 is ≤ 0 in {h['n_formula_nonpositive']} of "
             f"{len(ev.table)} cases, whereas the numerical load never falls below "
             f"{min(d[ld]['min_numerical'] for ld in RING_LOADS):.4f}.", "",
             verdicts_by_reading_markdown(claims), "",
             physical_threshold_text(
                 next(c for c in claims if c.id == "ring-spontaneous-instability")), "",
             markdown_table(["id", "claim", "verdict"],
                            [[f"`{c.id}`", c.claim, f"**{c.verdict}**"] for c in claims]),
             "", "![ring](ring.png)", "", threshold_markdown(ev).split("\n", 2)[2], "",
             "Tables: `ring_table.md`, `ring_table.csv`, `ring_threshold.csv`, "
             "`ring_formulations.csv`, `ring_wide.csv`. Run time: "
             + ", ".join(f"{k} {v:.1f} s" for k, v in ev.timings.items())
             + f"; total {seconds:.1f} s."]
    return "\n".join(lines) + "\n"


def run(out: Path, progress: Callable[[str], None]) -> SceneOutput:
    t0 = time.perf_counter()
    ev = compute_evidence(progress)
    claims = evaluate_claims(ev)
    witnesses = len(ev.witnesses)
    progress("writing tables, figure and ledger rows")
    files = [write_csv(out / "ring_table.csv", ev.table),
             write_text(out / "ring_table.md", table_markdown(ev)),
             write_csv(out / "ring_threshold.csv", ev.thresholds),
             write_text(out / "ring_threshold.md", threshold_markdown(ev)),
             write_csv(out / "ring_formulations.csv", ev.formulations),
             write_csv(out / "ring_wide.csv", ev.wide),
             write_figure(out / "ring.png", draw(ev))]
    files += update_ledger(out, NAME, claims)
    seconds = time.perf_counter() - t0
    report = report_section(claims, ev, seconds, witnesses)
    progress("verdicts: " + ", ".join(f"{c.id}={c.verdict}" for c in claims))
    details = {"verdicts": {c.id: c.verdict for c in claims}, "timings": ev.timings,
               "solves": {**ev.solves, "witnesses": witnesses},
               "crit2_deviation": crit2_deviation(ev)}
    return SceneOutput(files=files, report=report, details=details)
