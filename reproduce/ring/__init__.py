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
:mod:`.outputs` writes tables and the figure. Every sentence is a template with named fields in
a module-level table (``RULE_TEXTS``, ``EVIDENCE``, ``PHRASES`` of the row modules,
:data:`REPORT` here, ``TEXTS`` of :mod:`.outputs`); the computations only fill the fields.
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
        **{f"q_{load}": {"rel": 1e-10, "floor": f"rel_change_{load}"} for load in RING_LOADS},
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


#: The report's prose: templates with named fields, filled by :func:`report_section` and
#: :func:`physical_threshold_text` from the evidence and the judged rows.
REPORT = {
    "title": "## Ring: Eq. crit2 against the converged answer",
    "solved": (
        "{rings} rings (N = {n_first}..{n_last}, ν ∈ {{{nus}}}, e = 1 and isotropic e = "
        "{e_iso:.4f}) solved for every reading of the load ({readings}); every critical load "
        "converged (largest change between the last two truncations {rel_change:.1e} relative, "
        "frequencies ≤ {max_frequency}), and {wide} cases on the wide scan to ν = {nu_max:g}. "
        "Each ring is solved once per run through one memo: {distinct} solves for {requested} "
        "requests (the ν* searches of `destabilisation_threshold` solve their own rings), and "
        "{witnesses} rings re-solved by Eqs. Munder as witnesses (the decisive rings of two "
        "verdicts, on the evidence of all readings and of each alone)."),
    "formulations": (
        "**Two formulations.** The second variation of the energy and the paper's equilibrium "
        "equations Munder (linearised numerically) agree to {max_diff:.1e} (limit "
        "{limit:g}) on {cases} cases:"),
    "crit2": (
        "**How far is crit2?** Max |crit2 − q|/q = {max_rel_dev:.3g} (hydrostatic; axis "
        "{axis_max_rel_dev:.3g}); median {median_rel_dev:.2f}; where crit2 > 0 the relative "
        "error (crit2 − q)/q spans [{lo:+.2f}, {hi:+.2f}]; even at N = 0 up to "
        "{max_rel_dev_N0:.2f}. crit2 is ≤ 0 in {n_formula_nonpositive} of {rings} cases, "
        "whereas the numerical load never falls below {min_numerical:.4f}."),
    "by-reading": ("**Verdicts under each reading of the load** (each row judged on that "
                   "reading's numbers alone):"),
    "depends": "**depends on the reading**",
    "physical": "**Is the threshold twist physical?** {answer} {facts} (see `ring_threshold.md`).",
    "physical-facts": (
        "the numerical stiffness is positive definite in every one of the {n_solves} solves, "
        "the smallest 1/q is {min_inverse_load:.1e} and the smallest critical load {min_q:.4f}"),
    "physical-fails": "No. The stress-free twisted ring minimises a non-negative energy;",
    "physical-holds": "Yes: a converged critical load at or beyond the threshold is ≤ 0;",
    "physical-undecided": "Undecided ({verdict}):",
    "figure": "![ring](ring.png)",
    "tables": ("Tables: `ring_table.md`, `ring_table.csv`, `ring_threshold.csv`, "
               "`ring_formulations.csv`, `ring_wide.csv`. Run time: {timings}; total "
               "{seconds:.1f} s."),
    "timing": "{stage} {seconds:.1f} s",
    "writing": "writing tables, figure and ledger rows",
    "verdicts": "verdicts: {verdicts}",
    "verdict": "{id}={verdict}",
}


def _report(name: str, **fields: object) -> str:
    """The report text `name` of :data:`REPORT` with its named fields."""
    return REPORT[name].format(**fields)


def physical_threshold_text(claim: Claim) -> str:
    """The answer of the ring-spontaneous-instability row to "is the threshold physical?"."""
    answer = {"fails": "physical-fails", "holds": "physical-holds"}.get(claim.verdict,
                                                                        "physical-undecided")
    return _report("physical", answer=_report(answer, verdict=claim.verdict),
                   facts=_report("physical-facts", **claim.numbers))


def verdicts_by_reading_markdown(claims: list[Claim]) -> str:
    """The ring verdicts under each reading of the load alone (from caveat-load-model)."""
    per = next(c for c in claims if c.id == "caveat-load-model").numbers["verdicts_per_load"]
    rows = [[f"`{cid}`", *(v[ld] for ld in RING_LOADS),
             _report("depends") if len(set(v.values())) > 1 else ""]
            for cid, v in per.items()]
    return _report("by-reading") + "\n\n" + markdown_table(["row", *RING_LOADS, ""], rows)


def report_section(claims: list[Claim], ev: RingEvidence, seconds: float,
                   witnesses: int = 0) -> str:
    d = crit2_deviation(ev)
    h = d["hydrostatic"]
    conv = ev.table[[f"max_frequency_{ld}" for ld in RING_LOADS]].max().max()
    rel = ev.table[[f"rel_change_{ld}" for ld in RING_LOADS]].max().max()
    lo, hi = h["positive_formula_rel_dev_range"]
    lines = [_report("title"), "",
             _report("solved", rings=len(ev.table), n_first=TWISTS[0], n_last=TWISTS[-1],
                     nus=", ".join(f"{v:g}" for v in NUS), e_iso=E_RATIOS["isotropic"],
                     readings=", ".join(RING_LOADS), rel_change=rel, max_frequency=int(conv),
                     wide=len(ev.wide), nu_max=max(WIDE_NUS), witnesses=witnesses,
                     **ev.solves), "",
             _report("formulations", max_diff=ev.formulations["rel_diff"].max(),
                     limit=FORMULATION_TOL, cases=len(ev.formulations)), "",
             formulations_markdown(ev), "",
             _report("crit2", axis_max_rel_dev=d["axis"]["max_rel_dev"], lo=lo, hi=hi,
                     rings=len(ev.table),
                     **{**h, "min_numerical": min(d[ld]["min_numerical"] for ld in RING_LOADS)}),
             "", verdicts_by_reading_markdown(claims), "",
             physical_threshold_text(
                 next(c for c in claims if c.id == "ring-spontaneous-instability")), "",
             markdown_table(["id", "claim", "verdict"],
                            [[f"`{c.id}`", c.claim, f"**{c.verdict}**"] for c in claims]),
             "", _report("figure"), "", threshold_markdown(ev).split("\n", 2)[2], "",
             _report("tables", seconds=seconds, timings=", ".join(
                 _report("timing", stage=k, seconds=v) for k, v in ev.timings.items()))]
    return "\n".join(lines) + "\n"


def run(out: Path, progress: Callable[[str], None]) -> SceneOutput:
    t0 = time.perf_counter()
    ev = compute_evidence(progress)
    claims = evaluate_claims(ev)
    witnesses = len(ev.witnesses)
    progress(_report("writing"))
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
    progress(_report("verdicts", verdicts=", ".join(_report("verdict", id=c.id, verdict=c.verdict)
                                                    for c in claims)))
    details = {"verdicts": {c.id: c.verdict for c in claims}, "timings": ev.timings,
               "solves": {**ev.solves, "witnesses": witnesses},
               "crit2_deviation": crit2_deviation(ev)}
    return SceneOutput(files=files, report=report, details=details)
