"""The ring rows of the ledger: each claim declared (:class:`ClaimSpec`), measured from the
evidence (``measure_*``) and judged by its named rule (:func:`reproduce.ledger.judge`).

Two formulations stand behind the ring's numbers: the Fourier-Galerkin solution of the sympy
second variation (:mod:`spectral_rod.ring.second_variation`) and the numerical linearisation of the
paper's Eqs. ``Munder`` (:mod:`spectral_rod.ring.munder`). Munder is solved on the comparison
cases, so their agreement is the scene's shared cross-check, carried by every row that uses
second-variation loads (``shared_checks=True``), and on the decisive rings ("witnesses") of the
verdicts that rest on a range it does not cover (the largest rise of ring-monotone-decrease, the
first step of ring-rate-grows-with-nu where the drop does not grow): those verdicts need both
formulations to agree there. Munder is listed among a row's methods only where its numbers
enter the row's measurement.

The words are module-level template tables with named fields: :data:`RULE_TEXTS` (each rule's
text, whose fields are the thresholds its logic is given by :func:`ring_rule`),
:data:`EVIDENCE` (each row's evidence) and :data:`PHRASES` (their parts and the cross-checks'
names). A ``measure_*`` function only computes the fields. :mod:`.galerkin_rows` and
:mod:`.model_rows` keep their own tables of the same kind.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable, Iterable

import numpy as np
import pandas as pd

from reproduce.ledger import Claim, ClaimSpec, CrossCheck, Measured, Method, Rule, evaluate
from reproduce.ring.evidence import (
    AGREEMENT_CASES,
    E_RATIOS,
    EQUILIBRIUM_CASES,
    LARGE_TWIST_CASE,
    NUS,
    ROD_MODE_CASE,
    SECTION,
    TWISTS,
    WIDE_NUS,
    WIDE_TWISTS,
    RingEvidence,
    q_at,
)
from reproduce.ring.galerkin_rows import (
    ANALYTIC_ONLY,
    CRIT2_GALERKIN,
    FIXED_N,
    TORSION_SCALING,
    measure_analytic_only,
    measure_crit2_galerkin,
    measure_fixed_n,
    measure_torsion_scaling,
)
from reproduce.ring.limits import large_anisotropy_limits, large_twist_threshold
from reproduce.ring.model_rows import (
    ADJACENT,
    SUPPORTS,
    THREE_EQUATIONS,
    TORSIONS,
    TWISTS_CAVEAT,
    measure_adjacent,
    measure_supports,
    measure_three_equations,
    measure_torsions,
    measure_twists_caveat,
)
from reproduce.ring.root_causes import CIRCULAR_OUT_OF_PLANE, CRIT2_NOT_GALERKIN
from reproduce.ring.standards import (
    APPROX_TOL,
    CLASSICAL,
    CLOSED_FORM_TOL,
    COUPLED_MOSTLY,
    CRIT2,
    DEVIATION_RULE_TEXT,
    EQUATIONS_TOL,
    EXACT_TOL,
    FORMULATION_TOL,
    MIXED_SHARE,
    MUNDER,
    NON_PLANAR,
    PAPER_CIRCULAR_LOAD,
    PAPER_NU_MAX,
    RESIDUAL_TOL,
    ROD,
    SCENE,
    SECOND_VARIATION,
    ZERO_INVERSE_LOAD_TOL,
    readings,
    rule_from_template,
    verdict_by_deviation,
)
from spectral_rod import (
    RING_LOADS,
    RING_RAISE_TOL,
    crit2,
    homogenised_limit,
    out_of_plane_supremum,
    twist_raises_load,
    untwisted_critical_load,
)


def _range(values) -> str:
    lo, hi = min(values), max(values)
    return f"{lo:g}..{hi:g}" if lo != hi else f"{lo:g}"


#: Where Munder was solved (the comparison cases), for rows whose range it does not cover.
MUNDER_COVERAGE = (f"Eqs. Munder are solved only on the {len(AGREEMENT_CASES)} comparison cases "
                   f"(N = {_range([c[0] for c in AGREEMENT_CASES])}, ν = "
                   f"{_range([c[1] for c in AGREEMENT_CASES])}: the shared cross-check), "
                   "not over this claim's range")


#: The status :func:`spectral_rod.derivation_status` reports for a derivation whose every step
#: checked.
DERIVATION_CHECKED = "all steps checked"

#: The verdict rules' texts: templates whose named fields are the thresholds the rule's logic
#: is given (:func:`ring_rule` formats the text and binds the logic with the same values).
RULE_TEXTS = {
    "ring-crit2": "on the best-matching reading of the load, max |crit2 − q|/q over the table: "
                  + DEVIATION_RULE_TEXT,
    "ring-circular-limit": (
        "holds if both crit2(ν = 1) and the converged load are within {exact:g} of 3E₁I₁/R³, "
        "holds approximately within {approx:.0%}, fails otherwise"),
    "ring-circular-twist-independent": (
        "holds if the relative spread of q_cr over N is ≤ {exact:g}; fails otherwise"),
    "ring-in-out-coincide": (
        "holds if the in-plane and out-of-plane loads agree to {exact:g} in every case; fails "
        "otherwise"),
    "ring-monotone-decrease": (
        "holds if q_cr(N) never rises with N by more than {exact:g} relative in any (ν, e, "
        "reading) series; fails if it rises in some and Eqs. Munder confirm the largest rise "
        "(its two rings re-solved, the witness: a rise > {exact:g}); inconclusive if no series "
        "was solved or the witness shows no rise"),
    "ring-rate-grows-with-nu": (
        "holds if every measure grows with ν over the whole scan in every (e, reading) series; "
        "holds approximately if every one grows at least over the paper's range (ν ≤ "
        "{paper_nu_max:g}, Figure 1) but not beyond; fails if one stops growing within it; "
        "either of the last two only if Eqs. Munder confirm the first ν step where the drop to "
        "N = {last_twist} does not grow (the witness), else inconclusive; inconclusive also if "
        "a series has fewer than two ν"),
    "ring-spontaneous-instability": (
        "holds if some converged q_cr at or beyond the threshold twist is ≤ 0 (unstable without "
        "load); fails if rings at or beyond the threshold were solved, every converged q_cr "
        "(both formulations) is positive and no eigenvalue 1/q is below −{zero_inverse:g} "
        "(round-off); inconclusive otherwise"),
    "ring-destabilises": (
        "holds if q_cr(N) < q_cr(0) (1 − {raise_tol:g}, a round-off margin) in every case under "
        "every reading of the load; holds approximately if so under some of the readings the "
        "paper's wording allows; fails if under none; inconclusive if a reading has no twisted "
        "case solved"),
    "ring-three-dimensional": (
        "holds if ≥ {coupled_mostly:.0%} of the twisted critical modes are mixed (both shares ≥ "
        "{mixed_share:.0%}: coupling makes them three-dimensional); holds approximately if none "
        "is in-plane (every mode leaves the plane: the sentence is true) but fewer are mixed "
        "(they are out-of-plane modes with a trace of in-plane motion: the coupling does not "
        "explain it); fails if some mode is in-plane (out-of-plane share < {mixed_share:.0%}); "
        "inconclusive if no such mode was solved"),
    "intro-three-dimensional": (
        "holds if the rod's mode is non-planar (> {non_planar:g}) and no twisted ring mode is "
        "in-plane (out-of-plane share ≥ {mixed_share:.0%} in every one); fails otherwise; "
        "inconclusive if no twisted ring mode was solved"),
    "ring-gt97-comparison": (
        "fails if every converged q_cr of both formulations is positive and no eigenvalue 1/q is "
        "below −{zero_inverse:g}: the discrepancy the sentence explains does not arise in the "
        "full linearised problem (it is crit2's), so the explanation explains nothing; "
        "inconclusive otherwise (a discrepancy, whose explanation — the difference of the "
        "problems — is not examined here)"),
    "ring-two-formulations": (
        "holds if they agree to {formulation:g} relative in every case; fails otherwise"),
    "caveat-torsional-stiffness": (
        "holds if with the rectangle's A₃ every q_cr stays positive and the lowered/raised "
        "pattern of q_cr(N) vs q_cr(0) is the same as with the paper's A₃; fails otherwise"),
    "caveat-load-model": (
        "holds if every other ring row is decided (not inconclusive) under each reading alone, "
        "so that which verdicts depend on the reading is established (they are listed); "
        "inconclusive if some row is undecided under some reading"),
    "eq-munder": (
        "holds if Munder agrees with Kirchhoff's balances to {equations:g} and the straight-rod "
        "linearisation reproduces inst1; fails otherwise"),
    "ring-hoop-force": (
        "holds if the residual is below {residual:g} and the derivation's checks pass; fails "
        "otherwise"),
}


def ring_rule(row_id: str, decide: Callable[..., str], **thresholds: float) -> Rule:
    """The rule of `row_id`: its text is :data:`RULE_TEXTS` filled with `thresholds`, its logic
    `decide(numbers, **thresholds)` -- one definition of every threshold for both."""
    return rule_from_template(RULE_TEXTS[row_id], decide, **thresholds)


#: The evidence texts of the rows: templates with named fields, filled by the rows'
#: measurements (:func:`_evidence`), so a word can change without reading a computation.
EVIDENCE = {
    "ring-crit2": (
        "|crit2 − q|/q per reading — {per_reading}. Where crit2 > 0, (crit2 − q)/q spans "
        "[{lo:+.2f}, {hi:+.2f}] ({lead}); at N = 0 crit2 = e(ν+2), e.g. {crit2_nu4:g} vs "
        "{q_nu4:.4f} at ν = 4, e = 1 (ring-crit2-galerkin). crit2 ≤ 0 in {n_nonpositive} of {n} "
        "cases while the numerical load is never below {min_numerical:.4f}. As N → ∞ crit2 → −∞ "
        "(like −e(ν − 1)N²/2) while q_cr tends to the homogenised ring's positive load (closed "
        "form; e.g. ν = 4, e = 1: {limit_nu4:.4f}, {lead})."),
    "ring-circular-limit": (
        "crit2(ν=1) = 3e: {crit2_e1:.4f} (e = 1), {crit2_iso:.4f} (isotropic) — E₂ in crit2 vs "
        "E₁ in the text, equal only if E₂ = E₁. Converged q_cr: {q_e1:.6f} (e = 1), "
        "{q_iso:.6f} (isotropic), {kinds} (hydrostatic); per reading at e = 1: {by_reading}. "
        "{text:g} is the in-plane hydrostatic load (in-plane solver: |q/{text:g} − 1| = "
        "{in_plane:.1e}; in plane under the other readings: {other_in_plane}). Max relative gap "
        "to the text: crit2 {crit2_vs_text:.3f}, numerical {num_vs_text:.3f}."),
    "ring-circular-twist-independent": (
        "max relative spread of q_cr over N = {twists} at ν = 1: {spread:.1e}."),
    "ring-in-out-coincide": (
        "in-plane {in_hyd:.6f} (hydrostatic) / {in_axis:.6f} (axis) vs out-of-plane "
        "{out_e1:.6f} (e = 1), {out_iso:.6f} (isotropic), wavenumber n = {waves} in every case; "
        "smallest relative gap {min_gap:.3f}. The out-of-plane load is below its supremum over "
        "all torsional stiffnesses, 9A/4 = {sup_out:.4f}, {reach}. Solver vs closed forms: "
        "{closed:.1e}."),
    "ring-monotone-decrease": (
        "q_cr rises somewhere in {bad} of {groups} (ν, e, load) series; largest rise "
        "{largest:.1%} ({label}, ν = {nu:g}, {load}, N = {k}→{k_next}).{witness} {typical} "
        "{large_twist}"),
    "ring-rate-grows-with-nu": (
        "Every measure grows with ν from ν = {nu_first:g} up to ν = {end_min:g} … {end_max:g} "
        "depending on the series (e=1/hydrostatic, {ends_lead}), {paper_range}{then}Drop "
        "q(0)→q({last_twist}) by ν (e=1/hydrostatic): {drops_lead}. {drop_signs}. Limit ν → ∞ "
        "(closed form, drop from q(0) to q(N → ∞)): {limits} — a rise for {rise_readings}, no "
        "change for {flat_readings}.{witness}"),
    "ring-spontaneous-instability": "{beyond}. {zero_load}.{artefact}{beyond_scan}",
    "ring-destabilises": (
        "{per_reading}. Some twist raises the load above ν* ({boundaries}); {lowering}. N → ∞ "
        "limit (e = 1, hydrostatic): ν = {nu_a:g}: {lim_a:.4f} vs q(0) = {q_a:.4f}; ν = "
        "{nu_b:g}: {lim_b:.4f} vs q(0) = {q_b:.4f}. Beyond N = {last_twist} (N → ∞, closed form) "
        "twist raises the load above ν*_∞ = {far}; as ν → ∞, q(N → ∞)/q(0) → {large_nu}. "
        "{zero}"),
    "ring-three-dimensional": (
        "In-plane share of the load work over the {n_modes} twisted critical modes (ν > 1, "
        "N ≥ 1, {n_readings} reading(s)): min {q0:.1e}, quartiles {q25:.1e} / {q50:.1e} / "
        "{q75:.1e}, 90th percentile {q90:.3f}, max {q100:.3f}; {below_1_percent} below 1 %, "
        "{out_of_plane} out-of-plane (share < {mixed_share:.0%}), {mixed_fraction:.0%} mixed, "
        "{in_plane} in-plane. So buckling leaves the plane, but as an out-of-plane mode with a "
        "trace of in-plane motion; the untwisted rings, with no coupling, buckle out of plane "
        "too in {untwisted_out_of_plane} of {untwisted_modes} cases. {large_twist} The two "
        "formulations classify the comparison cases identically (disagreements: "
        "{disagreements})."),
    "intro-three-dimensional": (
        "Rod (Ω = {omega:g}, ν = {nu:g}): σ_min/σ_max = {rod:.3f} (see rod-three-dimensional "
        "for more cases); ring: {leaving} of {n_modes} twisted critical modes leave the plane "
        "({mixed_fraction:.0%} mixed, the rest out-of-plane). For ν = 1 (circular section) "
        "neither statement applies: planar modes exist."),
    "ring-gt97-comparison": (
        "The conclusion the paper contrasts with GT97 (instability of the unloaded ring beyond "
        "the threshold twist) is crit2's. {zero_load}; {reading}"),
    "caveat-torsional-stiffness": (
        "J/(I₁+I₂) of a rectangle: {ratios}. With A₃ = G J the converged q_cr moves by up to "
        "{max_change:.1%} (isotropic material), stays positive everywhere: {all_positive}, and "
        "the pattern of q_cr(N) < q_cr(0) is unchanged: {same}. So the verdicts on crit2, the "
        "threshold twist and destabilisation {hinge} (crit2 itself scales with A₃ and would "
        "move with it)."),
    "caveat-load-model": (
        "The readings differ by up to {spread:.0%} in q_cr (untwisted circular ring, e = 1, in "
        "plane: {in_plane}; out of plane: {out_of_plane}). Of {n_rows} other ring rows, judged "
        "on each reading's evidence alone, the verdict depends on the reading for: "
        "{dependent}; undecided under some reading: {undecided}. Every other verdict is the "
        "same under all four readings."),
    "ring-two-formulations": (
        "Largest relative difference {max_diff:.1e} over {cases} cases (resolution up to "
        "{max_frequency} Fourier modes per field)."),
    "eq-munder": (
        "Ring: Munder vs Kirchhoff's balances {munder_vs_kirchhoff:.1e}, Munder vs the energy's "
        "second variation {munder_vs_energy:.1e} (relative q_cr). Straight rod: {status} "
        "(Munder lines 3, 4 are inst1). As printed, line 3 is −(F' + q)·u and line 4 "
        "+(F' + q)·v after the elimination — consistent, with mixed signs (ring_munder's "
        "docstring)."),
    "ring-hoop-force": (
        "Largest residual of Munder at the loaded circle {residual:.1e} (every reading, {cases} "
        "cases); sympy: {derivation}."),
}

#: The parts of the evidence texts and the cross-checks' names: list items (joined by the
#: measurement) and the alternatives a number chooses between, each a template with named
#: fields (:func:`_phrase`).
PHRASES = {
    "formulations-check": "q_cr: second variation vs Munder on {cases} cases (N = {twists}, "
                          "ν = {nus})",
    "witness-check": "witness: {what}, second variation vs Munder",
    "crit2-reading": "{load}: max {max_rel_dev:.3g} (N = {at_N}, ν = {at_nu:g}, {at_e}), median "
                     "{median_rel_dev:.2f}, at N = 0 up to {max_rel_dev_N0:.2f}",
    "reading-load": "{load} {q:.4f}",
    "reach-never": "so it never reaches the smallest in-plane load {lowest_in:.4f}",
    "reach-not-below": "which does not keep it below the in-plane {lowest_in:.4f}",
    "monotone-witness-check": "q_cr at the largest rise (N = {n0}, {n1}; {label}, ν = {nu:g}, "
                              "{load})",
    "monotone-witness": " Eqs. Munder at those two rings: a rise of {munder_rise:.1%}.",
    "large-twist-limit": "Limit N → ∞ (homogenised ring, closed form; e = 1, ν = {nu:g}): "
                         "{parts}.",
    "large-twist-limit-reading": "{load} {limit:.4f} vs q(0) = {q0:.4f}",
    "typical-shape": "Typical shape (e = 1, ν = {nu:g}, hydrostatic): {first} …: lowest at "
                     "N = {k}, critical wavenumber n = {wave}{resonance}; {after}.",
    "typical-rising": "then rising monotonically to q({last_twist}) = {q_last:.4f} (the N → ∞ "
                      "limit, harmonic-mean stiffness: {limit:.4f})",
    "typical-not-rising": "not rising monotonically after it",
    "typical-resonance": " (N equals the mode's wavenumber: the resonance n = 2N − n)",
    "rate-over-paper": "so over the paper's range ν ≤ {paper_nu_max:g}",
    "rate-not-over-paper": "not over the whole of the paper's range ν ≤ {paper_nu_max:g}",
    "rate-then-falls": ", and then falls. ",
    "rate-end": ". ",
    "rate-growth-end": "{measure}: to {end:g}",
    "rate-drop": "{nu:g}: {drop:+.3f}",
    "rate-limit": "{load} {drop:+.3f}",
    "rate-drop-rises": "{key}: a rise (q({last_twist}) > q(0)) from ν = {nu:g} on",
    "rate-drop-falls": "{key}: a drop at every ν",
    "rate-witness-check": "q_cr at N = {n0}, {n1} for ν = {nu0:g}, {nu1:g} ({label}, {load})",
    "rate-witness": " Eqs. Munder at ν = {nu0:g} → {nu1:g} ({key}): drop {d0:+.3f} → "
                    "{d1:+.3f}.",
    "no-reading": "no reading",
    "beyond-threshold": "ν = {nu:g}: N ≥ {N_integer}: crit2 ≤ {max_crit2:.3g}, numerical q_cr ≥ "
                        "{min_q:.4f}",
    "zero-load": "Over the {n_solves} second-variation solves (table and wide scan to ν = "
                 "{nu_max:g}) and {n_munder_solves} Munder solves: stiffness positive definite "
                 "(Cholesky), smallest 1/q = {min_inverse_load:.1e} ({inverse}), {loads} "
                 "(smallest {min_q:.4f}; on the wide scan {min_q_wide:.4f})",
    "inverse-round-off": "zero to round-off: no eigenvalue at q ≤ 0",
    "inverse-below": "below round-off: an eigenvalue at q ≤ 0",
    "loads-positive": "every q_cr > 0",
    "loads-non-positive": "some q_cr ≤ 0",
    "crit2-artefact": " The zero of crit2 is an artefact of the one-mode estimate.",
    "beyond-scan": " Beyond the scanned range the same holds for every N and ν: the energy "
                   "½∫ΣA_k(ω_k−ω_k0)² is positive definite off rigid motions whatever N and ν, "
                   "and q_cr(N → ∞) tends to the homogenised ring's positive load (closed form).",
    "lowered-cases": "{load}: q_cr(N) < q_cr(0) in {below} of {total} cases",
    "boundary": "{key}: ν* = {nu:.3f}",
    "no-boundary": "nowhere on the scan",
    "lowered-everywhere": "under the {load} load twist lowers q_cr in every case up to ν = "
                          "{nu_max:g}",
    "raised-somewhere": "under the {load} load, at ν = {nu_max:g} (e = 1), twist raises q_cr "
                        "for N = {up} and lowers it for N = {down}",
    "none": "none",
    "far-boundary": "{key} {nu:.3f}",
    "far-never": "{key} never",
    "large-nu-ratio": "{load} {ratio:.3f}",
    "no-instability": "No twist leads to instability without load (every q_cr > 0).",
    "some-instability": "Some q_cr ≤ 0: see ring-spontaneous-instability.",
    "share-toward-infinity": "Toward N → ∞ (ν = {nu:g}, e = {e:g}, {load}) the share {trend}: "
                             "{shares}{coda}",
    "share-falls": "falls",
    "share-does-not-fall": "does not fall",
    "share": "N = {N}: {share:.1e}",
    "share-fades": " — the homogenised ring is isotropic and its modes decouple, so the "
                   "coupling fades.",
    "full-stop": ".",
    "gt97-none": "so the stress-free twisted ring has no non-trivial solution at zero load "
                 "either: there is no discrepancy with GT97's finding for the problem the paper "
                 "poses, only with crit2. Whether GT97's problem differs is beside the point and "
                 "is not examined here.",
    "gt97-some": "so a twisted ring has a non-trivial solution without load; whether the "
                 "difference of the problems explains it is not examined here.",
    "gt97-unsettled": "so the solves do not settle whether a solution exists at q ≤ 0.",
    "torsion-ratio": "ν = {nu:g}: {ratio:.3f}",
    "torsion-no-hinge": "do not hinge on A₃",
    "torsion-may-depend": "may depend on A₃",
    "reading-verdicts": "{row} ({verdicts})",
    "reading-verdict": "{load} {verdict}",
}


def _evidence(row_id: str, **fields: object) -> str:
    """The evidence text of `row_id` from :data:`EVIDENCE` with its named fields."""
    return EVIDENCE[row_id].format(**fields)


def _phrase(name: str, **fields: object) -> str:
    """The part `name` of an evidence text (:data:`PHRASES`) with its named fields."""
    return PHRASES[name].format(**fields)


def _items(name: str, items: Iterable[dict[str, object]], sep: str = ", ") -> str:
    """The phrase `name` once per item (its fields), joined by `sep`."""
    return sep.join(_phrase(name, **fields) for fields in items)


def _formulations_check(ev: RingEvidence) -> CrossCheck:
    f = ev.formulations
    name = _phrase("formulations-check", cases=len(f), twists=_range(f["N"]),
                   nus=_range(f["nu"]))
    return CrossCheck(name, float(f["rel_diff"].max()), FORMULATION_TOL)


def shared_checks(ev: RingEvidence) -> tuple[CrossCheck, ...]:
    """The cross-checks of every row declared with ``shared_checks=True``."""
    return (_formulations_check(ev),)


def _witness_check(what: str, second_variation: list[float], munder: list[float]
                   ) -> CrossCheck:
    """The decisive rings of a verdict re-solved by Eqs. Munder: the largest relative
    difference of their loads (NaN, a failed check, if they could not be re-solved)."""
    q, m = np.asarray(second_variation), np.asarray(munder)
    diff = float(np.max(np.abs(m - q) / np.abs(q)))  # NaN (a failed check) if one is NaN
    return CrossCheck(_phrase("witness-check", what=what), diff, FORMULATION_TOL)


def crit2_deviation(ev: RingEvidence) -> dict[str, dict[str, float]]:
    """Per load model: max |crit2 - q|/q over the table, where, and the sign-wrong count."""
    out = {}
    for load in readings(ev):
        dev = ev.table[f"rel_dev_{load}"].abs()
        row = ev.table.loc[int(dev.idxmax())]
        n0 = ev.table[ev.table["N"] == 0][f"rel_dev_{load}"].abs()
        pos = ev.table[ev.table["crit2"] > 0][f"rel_dev_{load}"]
        out[load] = {"max_rel_dev": float(dev.max()), "at_N": int(row["N"]),
                     "at_nu": float(row["nu"]), "at_e": str(row["e_label"]),
                     "median_rel_dev": float(dev.median()),
                     "max_rel_dev_N0": float(n0.max()),
                     "positive_formula_rel_dev_range": (float(pos.min()), float(pos.max())),
                     "n_formula_nonpositive": int((ev.table["crit2"] <= 0).sum()),
                     "min_numerical": float(ev.table[f"q_{load}"].min())}
    return out


def _best_reading_deviation(n: dict, *, exact: float, approx: float) -> str:
    return verdict_by_deviation(min(v["max_rel_dev"] for v in n.values()), exact, approx)


CRIT2_ROW = ClaimSpec(
    id="ring-crit2", section=SECTION + ", Eq. crit2",
    claim="Eq. crit2: q_cr = E₂(I₁+I₂)/(2R³)·[3 − (I₂−I₁)/(I₂+I₁)·(N²+1)] is the critical load "
          "of the ring with Ω = Ns/R (one-mode Galerkin estimate).",
    test="crit2 against the converged q_cr (10+ digits) on the table: N = 0..10, ν ∈ "
         f"{{{', '.join(f'{v:g}' for v in NUS)}}}, e = 1 and isotropic e = "
         f"{E_RATIOS['isotropic']:.4f}, every reading of the load.",
    methods=(CRIT2, SECOND_VARIATION), shared_checks=True,
    rule=ring_rule("ring-crit2", _best_reading_deviation, exact=EXACT_TOL, approx=APPROX_TOL),
    figure="ring.png", related=("ring-crit2-galerkin", "ring-spontaneous-instability",
                                "ring-gt97-comparison"),
    root_cause=CRIT2_NOT_GALERKIN)


def measure_crit2(ev: RingEvidence) -> Measured:
    d = crit2_deviation(ev)
    lead = readings(ev)[0]
    first = d[lead]
    lo, hi = first["positive_formula_rel_dev_range"]
    return Measured(
        numbers={ld: d[ld] for ld in readings(ev)},
        evidence=_evidence(
            "ring-crit2", per_reading=_items("crit2-reading", ({"load": ld, **v}
                                                                for ld, v in d.items()), "; "),
            lo=lo, hi=hi, lead=lead, crit2_nu4=crit2(0, 4.0, 1.0), q_nu4=q_at(ev, 4.0, 0),
            n_nonpositive=first["n_formula_nonpositive"], n=len(ev.table),
            min_numerical=min(v["min_numerical"] for v in d.values()),
            limit_nu4=homogenised_limit(4.0, 1.0, lead)))


def _circular_limit_deviation(n: dict, *, exact: float, approx: float) -> str:
    return verdict_by_deviation(max(n["crit2_vs_text"], n["numerical_vs_text"]), exact, approx)


CIRCULAR_LIMIT = ClaimSpec(
    id="ring-circular-limit", section=SECTION + ", para. 'An analytical solution ...'",
    claim="For I₁ = I₂ the ring buckles at q_cr = 3E₁I₁/R³, and Eq. crit2 reduces to it.",
    test="crit2 at ν = 1 (= 3E₂I₁/R³, i.e. 3e) against the text's 3E₁I₁/R³; the converged "
         "critical load of the circular ring (N = 0, any N gives the same) for e = 1 and "
         "isotropic e, every reading of the load; the in-plane-only solver against 3.",
    methods=(SECOND_VARIATION, CLASSICAL, CRIT2), shared_checks=True,
    rule=ring_rule("ring-circular-limit", _circular_limit_deviation, exact=EXACT_TOL,
                   approx=APPROX_TOL),
    root_cause=CIRCULAR_OUT_OF_PLANE)


def measure_circular_limit(ev: RingEvidence) -> Measured:
    c = ev.untwisted_circular
    text = PAPER_CIRCULAR_LOAD
    per = {}
    for label, e in E_RATIOS.items():
        sub = c[c["e_label"] == label]
        per[label] = {"crit2": crit2(0, 1.0, e), "text": text,
                      "numerical": {r["load"]: float(r["critical"]) for _, r in sub.iterrows()},
                      "in_plane": {r["load"]: float(r["in_plane"]) for _, r in sub.iterrows()}}
    crit2_vs_text = max(abs(v["crit2"] - text) / text for v in per.values())
    num_vs_text = max(abs(q - text) / text for v in per.values() for q in v["numerical"].values())
    in_plane = max(abs(v["in_plane"]["hydrostatic"] - text) / text for v in per.values())
    one, iso = per["e=1"], per["isotropic"]
    kinds = "/".join(sorted(set(c["kind"])))
    return Measured(
        numbers={"per_e": per, "crit2_vs_text": crit2_vs_text, "numerical_vs_text": num_vs_text,
                 "in_plane_vs_text": in_plane},
        evidence=_evidence(
            "ring-circular-limit", crit2_e1=one["crit2"], crit2_iso=iso["crit2"],
            q_e1=one["numerical"]["hydrostatic"], q_iso=iso["numerical"]["hydrostatic"],
            kinds=kinds, text=text, in_plane=in_plane, crit2_vs_text=crit2_vs_text,
            num_vs_text=num_vs_text,
            by_reading=_items("reading-load", ({"load": ld, "q": q}
                                               for ld, q in one["numerical"].items())),
            other_in_plane=_items("reading-load", ({"load": ld, "q": q}
                                                   for ld, q in one["in_plane"].items()
                                                   if ld != "hydrostatic"))))


def _spread_rule(n: dict, *, exact: float) -> str:
    return "holds" if n["max_rel_spread"] <= exact else "fails"


TWIST_INDEPENDENT = ClaimSpec(
    id="ring-circular-twist-independent", section=SECTION + ", para. 'As expected ...'",
    claim="For a circular cross-section (I₁ = I₂) the critical force does not depend on the "
          "spontaneous twist.",
    test="Converged q_cr at ν = 1 for N = 0..10, e = 1 and isotropic, every reading (with "
         "A₁ = A₂ the energy A₁(ω₁−ω₁₀)² + A₂(ω₂−ω₂₀)² is invariant under Ω).",
    methods=(SECOND_VARIATION,), shared_checks=True, one_formulation_why=MUNDER_COVERAGE,
    rule=ring_rule("ring-circular-twist-independent", _spread_rule, exact=EXACT_TOL),
    figure="ring.png")


def measure_twist_independent(ev: RingEvidence) -> Measured:
    t = ev.table[ev.table["nu"] == 1.0]
    spread = max(float((g[f"q_{ld}"].max() - g[f"q_{ld}"].min()) / g[f"q_{ld}"].min())
                 for _, g in t.groupby("e_label") for ld in RING_LOADS)
    return Measured({"max_rel_spread": spread},
                    _evidence("ring-circular-twist-independent", twists=_range(t["N"]),
                              spread=spread))


def _gap_rule(n: dict, *, exact: float) -> str:
    return "holds" if n["max_rel_gap"] <= exact else "fails"


IN_OUT = ClaimSpec(
    id="ring-in-out-coincide", section=SECTION + ", para. 'In this case, the onset ...'",
    claim="For a circular rod the onset of in-plane buckling coincides with that of out-of-plane "
          "buckling.",
    test="Untwisted circular ring (N = 0; any N gives the same): solver restricted to the "
         "in-plane field y_φ and to the out-of-plane fields (y_z, α), checked against the closed "
         "forms of each reading (in plane 3, 4.5, 4.5, 4 A₁/R³; out of plane Timoshenko & Gere, "
         "12A/(4 + A/A₃) for the centre load), for e = 1 and isotropic, every reading.",
    methods=(SECOND_VARIATION, CLASSICAL), shared_checks=True,
    rule=ring_rule("ring-in-out-coincide", _gap_rule, exact=EXACT_TOL),
    root_cause=CIRCULAR_OUT_OF_PLANE)


def measure_in_out(ev: RingEvidence) -> Measured:
    c = ev.untwisted_circular
    gaps = ((c["in_plane"] - c["out_of_plane"]) / c["out_of_plane"]).abs()
    closed = float(max(
        ((c["in_plane"] - c["in_plane_closed"]) / c["in_plane_closed"]).abs().max(),
        ((c["out_of_plane"] - c["out_of_plane_closed"]) / c["out_of_plane_closed"]).abs().max()))
    sup_out = out_of_plane_supremum(1.0)
    hyd = c[c["load"] == "hydrostatic"].set_index("e_label")
    axis = c[c["load"] == "axis"].set_index("e_label")
    waves = sorted(set(c["in_plane_n"]) | set(c["out_of_plane_n"]))
    lowest_in = float(c["in_plane"].min())
    reach = _phrase("reach-never" if sup_out < lowest_in else "reach-not-below",
                    lowest_in=lowest_in)
    return Measured(
        numbers={"min_rel_gap": float(gaps.min()), "max_rel_gap": float(gaps.max()),
                 "sup_out_of_plane": sup_out, "solver_vs_closed_forms": closed,
                 "in_plane": {f"{r.e_label}/{r.load}": r.in_plane for r in c.itertuples()},
                 "out_of_plane": {f"{r.e_label}/{r.load}": r.out_of_plane
                                  for r in c.itertuples()}},
        evidence=_evidence(
            "ring-in-out-coincide", in_hyd=hyd.loc["e=1", "in_plane"],
            in_axis=axis.loc["e=1", "in_plane"], out_e1=hyd.loc["e=1", "out_of_plane"],
            out_iso=hyd.loc["isotropic", "out_of_plane"],
            waves=", ".join(str(w) for w in waves), min_gap=gaps.min(), sup_out=sup_out,
            reach=reach, closed=closed),
        cross_checks=(CrossCheck("untwisted ring: solver vs classical closed forms", closed,
                                 CLOSED_FORM_TOL),))


def _series(ev_wide, label: str, load: str):
    g = ev_wide[(ev_wide["e_label"] == label) & (ev_wide["load"] == load)]
    return {float(nu): h.sort_values("N")["q"].to_numpy() for nu, h in g.groupby("nu")}


def _monotone_rule(n: dict, *, exact: float) -> str:
    if n["groups"] == 0:
        return "inconclusive"
    if n["non_monotone_groups"] == 0:
        return "holds"
    return "fails" if (n["munder_rise"] or 0.0) > exact else "inconclusive"


MONOTONE = ClaimSpec(
    id="ring-monotone-decrease", section="Sec. 'Conclusions'; " + SECTION,
    claim="For a circular ring, an increase in the spontaneous twist leads to a monotonic "
          "decrease in the critical force.",
    test=f"Converged q_cr(N), N = {_range(TWISTS)}, for each ν > 1 of the table, e and reading "
         "of the load: any rise q(N+1) > q(N). (crit2 itself is monotone by construction.) "
         "Limit N → ∞ in closed form (homogenised ring).",
    methods=(SECOND_VARIATION, MUNDER), shared_checks=True,
    rule=ring_rule("ring-monotone-decrease", _monotone_rule, exact=EXACT_TOL),
    figure="ring.png", related=("ring-rate-grows-with-nu", "ring-destabilises"),
    root_cause=CRIT2_NOT_GALERKIN)


def measure_monotone(ev: RingEvidence) -> Measured:
    t = ev.table[ev.table["nu"] > 1.0]
    largest, at, bad, groups = 0.0, ("", 0.0, "", 0), 0, 0
    for (label, nu), g in t.groupby(["e_label", "nu"]):
        g = g.sort_values("N")
        for load in readings(ev):
            q = g[f"q_{load}"].to_numpy()
            rel = np.diff(q) / q[:-1]
            groups += 1
            bad += int(np.any(rel > EXACT_TOL))
            k = int(np.argmax(rel))
            if rel[k] > largest:
                largest, at = float(rel[k]), (str(label), float(nu), load, k)
    label, nu, load, k = at
    checks: tuple[CrossCheck, ...] = ()
    munder_rise: float | None = None
    witness = ""
    if bad:
        pair = (TWISTS[k], TWISTS[k + 1])
        sv = [q_at(ev, nu, N, label, load) for N in pair]
        mu = [ev.munder_load(N, nu, label, load) for N in pair]
        munder_rise = (mu[1] - mu[0]) / mu[0]
        checks = (_witness_check(_phrase("monotone-witness-check", n0=pair[0], n1=pair[1],
                                         label=label, nu=nu, load=load), sv, mu),)
        witness = _phrase("monotone-witness", munder_rise=munder_rise)
    return Measured(
        numbers={"largest_rise": largest, "largest_rise_at": at, "non_monotone_groups": bad,
                 "groups": groups, "munder_rise": munder_rise},
        evidence=_evidence("ring-monotone-decrease", bad=bad, groups=groups, largest=largest,
                           label=label, nu=nu, load=load, k=k, k_next=k + 1, witness=witness,
                           typical=_typical_shape(ev, 2.0), large_twist=_large_twist_text(ev)),
        cross_checks=checks)


def _large_twist_text(ev: RingEvidence, nu: float = 2.0) -> str:
    """Beyond the scanned twists: q_cr(N -> infinity) against q_cr(0) in closed form."""
    parts = _items("large-twist-limit-reading",
                   ({"load": ld, "limit": homogenised_limit(nu, 1.0, ld),
                     "q0": untwisted_critical_load(nu, 1.0, ld)} for ld in readings(ev)), "; ")
    return _phrase("large-twist-limit", nu=nu, parts=parts)


def _typical_shape(ev: RingEvidence, nu: float) -> str:
    """The series q_cr(N) at `nu` (e = 1, hydrostatic): where it is lowest, what follows."""
    t = ev.table
    g = t[(t["e_label"] == "e=1") & (t["nu"] == nu)].sort_values("N")
    q, waves = g["q_hydrostatic"].to_numpy(), g["wavenumber_hydrostatic"].to_numpy()
    k = int(np.argmin(q))
    lim = homogenised_limit(nu, 1.0, "hydrostatic")
    rising = k < q.size - 1 and np.all(np.diff(q[k:]) > 0)
    after = (_phrase("typical-rising", last_twist=TWISTS[-1], q_last=q[-1], limit=lim)
             if rising else _phrase("typical-not-rising"))
    resonance = _phrase("typical-resonance") if k == waves[k] else ""
    return _phrase("typical-shape", nu=nu, first=", ".join(f"{v:.4f}" for v in q[:5]), k=k,
                   wave=waves[k], resonance=resonance, after=after)


#: The measures of "the rate of the decrease" with twist, each a relative drop from q_cr(0) of a
#: (nu, e, reading) series q_cr(N), N = 0..WIDE_TWISTS[-1].
RATE_MEASURES: dict[str, Callable[[np.ndarray], float]] = {
    "drop to N = 1": lambda q: float((q[0] - q[1]) / q[0]),
    f"drop to N = {WIDE_TWISTS[-1]}": lambda q: float((q[0] - q[-1]) / q[0]),
    "largest drop": lambda q: float((q[0] - q.min()) / q[0]),
}


def growth_end(values: dict[float, float]) -> float:
    """The largest nu up to which `values` (by increasing nu) grows at every step from the first
    nu (the first nu itself if it does not grow at the first step)."""
    nus, v = list(values), list(values.values())
    k = 0
    while k + 1 < len(v) and v[k + 1] > v[k]:
        k += 1
    return float(nus[k])


def _rate_rule(n: dict, *, paper_nu_max: float, scan_nu_max: float, last_twist: int) -> str:
    """`last_twist` names the witness's drop in the rule's text; the logic reads it from
    ``munder_witness_grows``."""
    if n["fewest_nus"] < 2:
        return "inconclusive"
    ends = [e for per in n["growth_end"].values() for e in per.values()]
    if min(ends) >= scan_nu_max:
        return "holds"
    if n["munder_witness_grows"] is not False:  # the first non-growth unconfirmed
        return "inconclusive"
    return "holds approximately" if min(ends) >= paper_nu_max else "fails"


RATE = ClaimSpec(
    id="ring-rate-grows-with-nu", section="Sec. 'Conclusions'",
    claim="The rate of the decrease (of the ring's critical force with twist) grows with ν.",
    test="Three measures of the rate — " + ", ".join(RATE_MEASURES) + " — of the converged "
         f"q_cr(N), N = 0..{WIDE_TWISTS[-1]}, for ν ∈ {{{', '.join(f'{v:g}' for v in WIDE_NUS)}}}, "
         "both e and every reading: up to which ν does each grow? Limits: N → ∞ and ν → ∞ in "
         "closed form.",
    methods=(SECOND_VARIATION, MUNDER, CLASSICAL), shared_checks=True,
    rule=ring_rule("ring-rate-grows-with-nu", _rate_rule, paper_nu_max=PAPER_NU_MAX,
                   scan_nu_max=max(WIDE_NUS), last_twist=WIDE_TWISTS[-1]),
    related=("ring-monotone-decrease",), root_cause=CRIT2_NOT_GALERKIN)


def _series_measures(ev: RingEvidence) -> dict[str, dict[str, dict[float, float]]]:
    """Per (e, reading) series and measure of RATE_MEASURES: its value by nu."""
    out = {}
    for label in E_RATIOS:
        for load in readings(ev):
            s = _series(ev.wide, label, load)
            out[f"{label}/{load}"] = {name: {nu: f(q) for nu, q in s.items()}
                                      for name, f in RATE_MEASURES.items()}
    return out


def measure_rate(ev: RingEvidence) -> Measured:
    per = _series_measures(ev)
    last = f"drop to N = {WIDE_TWISTS[-1]}"
    drops = {k: v[last] for k, v in per.items()}
    grows = {k: bool(np.all(np.diff(list(d.values())) > 0)) for k, d in drops.items()}
    ends = {k: {name: growth_end(vals) for name, vals in v.items()} for k, v in per.items()}
    checks, witness_grows, witness = _rate_witness(ev, drops, grows)
    h = drops.get("e=1/hydrostatic", next(iter(drops.values())))
    limits = {ld: large_anisotropy_limits(ld)["relative_drop"] for ld in readings(ev)}
    span = [e for v in ends.values() for e in v.values()]
    return Measured(
        numbers={"relative_drop_0_to_10": drops, "drop_grows_with_nu": grows,
                 "growth_end": ends, "fewest_nus": min((len(v) for v in drops.values()),
                                                       default=0),
                 "munder_witness_grows": witness_grows, "large_nu_relative_drop": limits},
        evidence=_evidence(
            "ring-rate-grows-with-nu", nu_first=WIDE_NUS[0], end_min=min(span),
            end_max=max(span), last_twist=WIDE_TWISTS[-1],
            ends_lead=_items("rate-growth-end", (
                {"measure": k, "end": v}
                for k, v in ends.get("e=1/hydrostatic", next(iter(ends.values()))).items())),
            paper_range=_phrase("rate-over-paper" if min(span) >= PAPER_NU_MAX else
                                "rate-not-over-paper", paper_nu_max=PAPER_NU_MAX),
            then=_phrase("rate-then-falls" if min(span) < max(WIDE_NUS) else "rate-end"),
            drops_lead=_items("rate-drop", ({"nu": nu, "drop": v} for nu, v in h.items())),
            drop_signs=_drop_sign_text(drops),
            limits=_items("rate-limit", ({"load": ld, "drop": v} for ld, v in limits.items())),
            rise_readings=(", ".join(ld for ld, v in limits.items() if v < 0)
                           or _phrase("no-reading")),
            flat_readings=(", ".join(ld for ld, v in limits.items() if v == 0)
                           or _phrase("no-reading")),
            witness=witness),
        cross_checks=checks)


def _rate_witness(ev: RingEvidence, drops: dict[str, dict[float, float]],
                  grows: dict[str, bool]) -> tuple[tuple[CrossCheck, ...], bool | None, str]:
    """The first (e, load) series whose drop does not grow, at its first such ν step,
    re-solved by Eqs. Munder (N = first and last of the scan at both ν): the checks, whether
    Munder's drop grows there (None: no such series), the evidence sentence."""
    key = next((k for k, g in grows.items() if not g), None)
    if key is None:
        return (), None, ""
    label, load = key.split("/")
    nus, d = list(drops[key]), list(drops[key].values())
    i = next(j for j in range(len(d) - 1) if not d[j + 1] > d[j])
    ends = (WIDE_TWISTS[0], WIDE_TWISTS[-1])
    wide = ev.wide[(ev.wide["e_label"] == label) & (ev.wide["load"] == load)]
    sv, mu = [], []
    for nu in nus[i:i + 2]:
        g = wide[wide["nu"] == nu].set_index("N")["q"]
        sv += [float(g.loc[N]) for N in ends]
        mu += [ev.munder_load(N, nu, label, load) for N in ends]
    d_mu = [(mu[0] - mu[1]) / mu[0], (mu[2] - mu[3]) / mu[2]]
    check = _witness_check(_phrase("rate-witness-check", n0=ends[0], n1=ends[1], nu0=nus[i],
                                   nu1=nus[i + 1], label=label, load=load), sv, mu)
    grows_mu = bool(d_mu[1] > d_mu[0]) if np.all(np.isfinite(d_mu)) else None
    return ((check,), grows_mu,
            _phrase("rate-witness", nu0=nus[i], nu1=nus[i + 1], key=key, d0=d_mu[0],
                    d1=d_mu[1]))


def _drop_sign_text(drops: dict[str, dict[float, float]]) -> str:
    """Per (e, load) series, from which nu of the scan on the drop q(0) -> q(10) is a rise."""
    parts = []
    for key, d in drops.items():
        rising = [nu for nu, v in d.items() if v < 0]
        parts.append(_phrase("rate-drop-rises", key=key, last_twist=WIDE_TWISTS[-1],
                             nu=min(rising)) if rising else _phrase("rate-drop-falls", key=key))
    return "; ".join(parts)


def _spontaneous_rule(n: dict, *, zero_inverse: float) -> str:
    if n["non_positive_beyond_threshold"]:
        return "holds"
    if n["beyond_threshold"] and n["all_positive"] and n["min_inverse_load"] >= -zero_inverse:
        return "fails"
    return "inconclusive"


SPONTANEOUS = ClaimSpec(
    id="ring-spontaneous-instability", section=SECTION + ", after Eq. crit2; Conclusions",
    claim="For N² ≥ 3(I₁+I₂)/(I₂−I₁) − 1 the ring becomes unstable even in the absence of "
          "external forces.",
    test="(i) Energy: the stress-free twisted ring (ω_k = ω_k0) is the minimiser of "
         "½∫ΣA_k(ω_k−ω_k0)² ≥ 0, zero only for rigid motions, so at q = 0 it cannot be "
         "unstable; numerically the constrained stiffness matrix must be positive definite "
         "(Cholesky in every solve) and no eigenvalue may lie at q ≤ 0. (ii) The converged q_cr "
         "at every tabulated N at or beyond the integer threshold twist of each ν, and on the "
         f"wide scan to ν = {max(WIDE_NUS):g}.",
    methods=(SECOND_VARIATION, MUNDER, CRIT2), shared_checks=True,
    rule=ring_rule("ring-spontaneous-instability", _spontaneous_rule,
                   zero_inverse=ZERO_INVERSE_LOAD_TOL),
    figure="ring.png", related=("ring-crit2", "ring-gt97-comparison"),
    root_cause=CRIT2_NOT_GALERKIN)


def _beyond_threshold(ev: RingEvidence) -> list[dict[str, object]]:
    """Per nu with a finite threshold: crit2 and the numerical q_cr at N >= the integer one."""
    t, rows = ev.table, []
    for _, th in ev.thresholds.iterrows():
        if math.isinf(th["N_integer"]):
            continue
        sel = t[(t["nu"] == th["nu"]) & (t["N"] >= th["N_integer"])]
        if not sel.empty:
            rows.append({"nu": float(th["nu"]), "N_integer": int(th["N_integer"]),
                         "max_crit2": float(sel["crit2"].max()),
                         "min_q": float(sel[[f"q_{ld}" for ld in RING_LOADS]].min().min())})
    return rows


def _second_variation_solves(ev: RingEvidence) -> pd.DataFrame:
    """Every second-variation solve of the table and the wide scan, once each (long format)."""
    t = ev.table
    table = pd.concat([t[["e_label", "nu", "N"]].assign(
        load=ld, q=t[f"q_{ld}"], min_inverse_load=t[f"min_inverse_load_{ld}"])
        for ld in RING_LOADS])
    wide = ev.wide[["e_label", "nu", "N", "load", "q", "min_inverse_load"]]
    return pd.concat([table, wide]).drop_duplicates(["e_label", "nu", "N", "load"])


def _spontaneous_numbers(ev: RingEvidence) -> dict[str, object]:
    rows = _beyond_threshold(ev)
    solves = _second_variation_solves(ev)
    f = ev.formulations
    munder = f["q_munder"]
    min_inverse = float(solves["min_inverse_load"].min())
    twisted_non_positive = bool(((solves["N"] > 0) & (solves["q"] <= 0)).any()
                                or ((f["N"] > 0) & (munder <= 0)).any())
    return {"beyond_threshold": rows,
            "all_positive": bool((solves["q"] > 0).all() and (munder > 0).all()),
            "non_positive_beyond_threshold": any(r["min_q"] <= 0 for r in rows),
            "twisted_non_positive": twisted_non_positive,
            "min_inverse_load": min_inverse,
            "no_eigenvalue_at_or_below_zero": min_inverse >= -ZERO_INVERSE_LOAD_TOL,
            "min_q": float(solves["q"].min()), "min_q_wide": float(ev.wide["q"].min()),
            "n_solves": len(solves), "n_munder_solves": len(munder)}


def _zero_load_text(s: dict) -> str:
    """What the solves say about the ring at q = 0."""
    inverse = _phrase("inverse-round-off" if s["no_eigenvalue_at_or_below_zero"] else
                      "inverse-below")
    loads = _phrase("loads-positive" if s["all_positive"] else "loads-non-positive")
    return _phrase("zero-load", nu_max=max(WIDE_NUS), inverse=inverse, loads=loads, **s)


def measure_spontaneous(ev: RingEvidence) -> Measured:
    s = _spontaneous_numbers(ev)
    stable = s["all_positive"] and s["no_eigenvalue_at_or_below_zero"]
    crit2_zero = any(r["max_crit2"] <= 0 for r in s["beyond_threshold"])
    return Measured(
        numbers=s,
        evidence=_evidence("ring-spontaneous-instability",
                           beyond=_items("beyond-threshold", s["beyond_threshold"], "; "),
                           zero_load=_zero_load_text(s),
                           artefact=_phrase("crit2-artefact") if stable and crit2_zero else "",
                           beyond_scan=_phrase("beyond-scan")))


def _destabilised(ev: RingEvidence) -> dict[str, dict[str, object]]:
    """Per load: cases (nu > 1, N >= 1, e) of the wide scan where twist lowers q_cr (q(N) <
    q(0): not :func:`spectral_rod.twist_raises_load`), and where not."""
    out = {}
    for load in readings(ev):
        below, total, raised = 0, 0, []
        for label in E_RATIOS:
            for nu, q in _series(ev.wide, label, load).items():
                lower = ~twist_raises_load(q[1:], q[0])
                below, total = below + int(lower.sum()), total + lower.size
                if not lower.all():
                    raised.append({"e_label": label, "nu": float(nu)})
        out[load] = {"below": below, "total": total, "raised_at": raised}
    return out


def _destabilises_rule(n: dict, *, raise_tol: float) -> str:
    """`raise_tol` is the margin of :func:`spectral_rod.twist_raises_load`, which the
    measurement applies (``every_case_lowered``); the rule's text states it."""
    if n["fewest_cases"] == 0:
        return "inconclusive"
    if all(n["every_case_lowered"].values()):
        return "holds"
    return "holds approximately" if any(n["every_case_lowered"].values()) else "fails"


DESTABILISES = ClaimSpec(
    id="ring-destabilises", section="Abstract; Introduction; Conclusions",
    claim="Spontaneous twist destabilises the ring (the opposite of its effect on the straight "
          "rod).",
    test=f"Converged q_cr(N) against q_cr(0) for ν ∈ {{{', '.join(f'{v:g}' for v in WIDE_NUS)}}}, "
         f"N = 1..{WIDE_TWISTS[-1]}, e = 1 and isotropic, for each reading of the load (the "
         "paper says 'radially inward force', 'radial pressure' and 'pressure'); the ν above "
         "which some twist raises q_cr (Brent); the N → ∞ limit (isotropic ring of "
         "harmonic-mean stiffness 2A₁A₂/(A₁+A₂)) and its threshold ν in closed form.",
    methods=(SECOND_VARIATION, CLASSICAL), shared_checks=True,
    rule=ring_rule("ring-destabilises", _destabilises_rule, raise_tol=RING_RAISE_TOL),
    figure="ring.png", related=("caveat-load-model", "ring-rate-grows-with-nu"))


def _raising_twists(ev: RingEvidence, label: str, load: str, nu: float) -> list[int]:
    """The twists N >= 1 of the wide scan that raise q_cr over q_cr(0) at (e, load, nu)."""
    q = _series(ev.wide, label, load)[nu]
    return [N for N in range(1, q.size) if twist_raises_load(q[N], q[0])]


def _lowering_text(ev: RingEvidence, d: dict[str, dict[str, object]]) -> str:
    """Per load: lowered everywhere, or at the largest nu which twists raise q_cr (e = 1)."""
    nu_max, parts = max(WIDE_NUS), []
    for ld in readings(ev):
        if d[ld]["below"] == d[ld]["total"]:
            parts.append(_phrase("lowered-everywhere", load=ld, nu_max=nu_max))
            continue
        up = _raising_twists(ev, "e=1", ld, nu_max)
        down = [N for N in WIDE_TWISTS[1:] if N not in up]
        parts.append(_phrase("raised-somewhere", load=ld, nu_max=nu_max,
                             up=", ".join(map(str, up)) or _phrase("none"),
                             down=", ".join(map(str, down)) or _phrase("none")))
    return "; ".join(parts)


def measure_destabilises(ev: RingEvidence) -> Measured:
    d = _destabilised(ev)
    lim = {nu: homogenised_limit(nu, 1.0, "hydrostatic") for nu in (1.5, 4.0)}
    bounds = {f"{r.e_label}/{r.load}": r.nu_boundary for r in ev.boundaries.itertuples()
              if r.load in readings(ev)}
    every = {ld: d[ld]["below"] == d[ld]["total"] for ld in readings(ev)}
    far = {f"{lab}/{ld}": large_twist_threshold(e, ld) for lab, e in E_RATIOS.items()
           for ld in readings(ev)}
    big = {ld: large_anisotropy_limits(ld) for ld in readings(ev)}
    s = _spontaneous_numbers(ev)
    return Measured(
        numbers={"per_load": d, "every_case_lowered": every,
                 "fewest_cases": min(v["total"] for v in d.values()), "nu_boundary": bounds,
                 "limits_e1": lim, "nu_boundary_large_twist": far,
                 "large_nu_ratio": {ld: v["q_large_twist"] / v["q_untwisted"]
                                    for ld, v in big.items()}},
        evidence=_evidence(
            "ring-destabilises",
            per_reading=_items("lowered-cases", ({"load": ld, **d[ld]} for ld in readings(ev)),
                               "; "),
            boundaries=_items("boundary", ({"key": k, "nu": v} for k, v in bounds.items()
                                           if math.isfinite(v))) or _phrase("no-boundary"),
            lowering=_lowering_text(ev, d), nu_a=1.5, lim_a=lim[1.5], q_a=q_at(ev, 1.5, 0),
            nu_b=4.0, lim_b=lim[4.0], q_b=q_at(ev, 4.0, 0), last_twist=WIDE_TWISTS[-1],
            far=", ".join(_phrase("far-boundary" if math.isfinite(v) else "far-never", key=k,
                                  nu=v) for k, v in far.items()),
            large_nu=_items("large-nu-ratio", ({"load": ld,
                                                "ratio": v["q_large_twist"] / v["q_untwisted"]}
                                               for ld, v in big.items())),
            zero=_phrase("no-instability" if s["all_positive"] else "some-instability")))


def mode_shares(ev: RingEvidence) -> dict[str, object]:
    """The in-plane share of the load work of every twisted critical mode (N >= 1, nu > 1) of
    the table, over the readings `ev` holds: its distribution and how many are mixed (both
    shares >= MIXED_SHARE), out-of-plane (in-plane share < MIXED_SHARE) or in-plane."""
    t = ev.table[(ev.table["nu"] > 1.0) & (ev.table["N"] >= 1)]
    loads = readings(ev)
    shares = np.concatenate([t[f"in_plane_fraction_{ld}"].to_numpy() for ld in loads])
    n = int(shares.size)
    u = ev.table[(ev.table["nu"] > 1.0) & (ev.table["N"] == 0)]
    untwisted_out = int(sum((u[f"in_plane_fraction_{ld}"] < MIXED_SHARE).sum() for ld in loads))
    return {"n_modes": n,
            "mixed_fraction": float(np.mean(np.minimum(shares, 1 - shares) >= MIXED_SHARE))
            if n else math.nan,
            "out_of_plane": int((shares < MIXED_SHARE).sum()),
            "in_plane": int((shares > 1 - MIXED_SHARE).sum()),
            "below_1_percent": int((shares < 0.01).sum()),
            "share_quantiles": {f"{p:g}": float(np.quantile(shares, p / 100)) if n else math.nan
                                for p in (0, 25, 50, 75, 90, 100)},
            "untwisted_out_of_plane": untwisted_out, "untwisted_modes": len(u) * len(loads)}


def _three_d_rule(n: dict, *, coupled_mostly: float, mixed_share: float) -> str:
    """`mixed_share` classifies each mode in the measurement (:func:`mode_shares`, which
    counts ``in_plane`` and ``mixed_fraction`` with it); the rule's text states it."""
    if n["n_modes"] == 0:
        return "inconclusive"
    if n["in_plane"] > 0:
        return "fails"
    return "holds" if n["mixed_fraction"] >= coupled_mostly else "holds approximately"


THREE_D = ClaimSpec(
    id="ring-three-dimensional", section=SECTION + ", after Eq. crit2",
    claim="Because the equations for the perturbations are coupled, the ring's instability has "
          "a three-dimensional character and buckling is not confined to the plane of the ring.",
    test="The critical mode of every twisted ring with ν > 1 in the table, every reading: the "
         "distribution of its in-plane share of the load work (1 in-plane, 0 out-of-plane); "
         f"mixed if both shares are ≥ {MIXED_SHARE:.0%}; the untwisted rings (N = 0) as the "
         "uncoupled reference; the mode kinds by the Munder formulation on the "
         f"{len(AGREEMENT_CASES)} comparison cases.",
    methods=(SECOND_VARIATION, MUNDER), shared_checks=True,
    rule=ring_rule("ring-three-dimensional", _three_d_rule, coupled_mostly=COUPLED_MOSTLY,
                   mixed_share=MIXED_SHARE),
    related=("intro-three-dimensional",))


def measure_three_d(ev: RingEvidence) -> Measured:
    m = mode_shares(ev)
    f = ev.formulations
    same = float((f["kind_galerkin"] != f["kind_munder"]).sum())
    qs = m["share_quantiles"]
    return Measured(
        numbers={**m, "kind_disagreements": same},
        evidence=_evidence("ring-three-dimensional", n_readings=len(readings(ev)),
                           q0=qs["0"], q25=qs["25"], q50=qs["50"], q75=qs["75"], q90=qs["90"],
                           q100=qs["100"], mixed_share=MIXED_SHARE,
                           large_twist=_large_twist_share_text(ev), disagreements=int(same),
                           **m),
        cross_checks=(CrossCheck("mode kind: second variation vs Munder", same, 0.0),))


def _large_twist_share_text(ev: RingEvidence) -> str:
    """Beyond the table's twists: the in-plane share as N grows (toward the homogenised,
    isotropic ring, whose in-plane and out-of-plane modes decouple)."""
    sh = ev.large_twist_shares
    if not sh:
        return ""
    nu, e, load = LARGE_TWIST_CASE
    falls = bool(np.all(np.diff(list(sh.values())) < 0))
    return _phrase("share-toward-infinity", nu=nu, e=e, load=load,
                   trend=_phrase("share-falls" if falls else "share-does-not-fall"),
                   shares=_items("share", ({"N": N, "share": v} for N, v in sh.items())),
                   coda=_phrase("share-fades" if falls else "full-stop"))


def _intro_3d_rule(n: dict, *, non_planar: float, mixed_share: float) -> str:
    """`mixed_share` classifies the ring's modes in the measurement (:func:`mode_shares`)."""
    if not n["rod_non_planarity"] > non_planar:
        return "fails"
    if n["ring_n_modes"] == 0:
        return "inconclusive"
    return "holds" if n["ring_in_plane_modes"] == 0 else "fails"


INTRO_3D = ClaimSpec(
    id="intro-three-dimensional", section="Introduction",
    claim="In both cases (straight rod and ring) buckling takes place through a three-dimensional "
          "instability.",
    test="Straight rod: non-planarity σ_min/σ_max of the critical centreline at Ω = "
         f"{ROD_MODE_CASE[0]:g}, ν = {ROD_MODE_CASE[1]:g} (buckling_mode); ring: whether the "
         "twisted critical modes leave the plane (ring-three-dimensional's distribution).",
    methods=(ROD, SECOND_VARIATION), shared_checks=True,
    rule=ring_rule("intro-three-dimensional", _intro_3d_rule, non_planar=NON_PLANAR,
                   mixed_share=MIXED_SHARE),
    related=("rod-three-dimensional", "ring-three-dimensional"))


def measure_intro_3d(ev: RingEvidence) -> Measured:
    rod = ev.rod_non_planarity
    m = mode_shares(ev)
    return Measured(
        numbers={"rod_non_planarity": rod, "ring_in_plane_modes": m["in_plane"],
                 "ring_mixed_fraction": m["mixed_fraction"], "ring_n_modes": m["n_modes"]},
        evidence=_evidence("intro-three-dimensional", omega=ROD_MODE_CASE[0],
                           nu=ROD_MODE_CASE[1], rod=rod, leaving=m["n_modes"] - m["in_plane"],
                           n_modes=m["n_modes"], mixed_fraction=m["mixed_fraction"]))


def _gt97_rule(n: dict, *, zero_inverse: float) -> str:
    if n["no_solution_at_zero_load"] and n["min_inverse_load"] >= -zero_inverse:
        return "fails"
    return "inconclusive"


GT97 = ClaimSpec(
    id="ring-gt97-comparison", section=SECTION + ", para. 'It is of interest to compare ...'",
    claim="The apparent discrepancy with Ref. GT97 (no non-trivial solutions for the "
          "stress-free ring) stems from the two problems being different (compression of a "
          "twisted ring here, an end torque on an untwisted one there).",
    test="Is there a discrepancy to explain? The stress-free twisted ring at q = 0: does any "
         "eigenvalue lie at q ≤ 0 (a non-trivial solution without load) in any solve, by either "
         "formulation? (GT97's own problem, an untwisted ring under an end torque, is not solved "
         "here.)",
    methods=(SECOND_VARIATION, MUNDER, CRIT2), shared_checks=True,
    rule=ring_rule("ring-gt97-comparison", _gt97_rule, zero_inverse=ZERO_INVERSE_LOAD_TOL),
    related=("ring-spontaneous-instability",), root_cause=CRIT2_NOT_GALERKIN)


def measure_gt97(ev: RingEvidence) -> Measured:
    s = _spontaneous_numbers(ev)
    none = bool(s["all_positive"] and s["no_eigenvalue_at_or_below_zero"])
    some = bool(s["twisted_non_positive"])
    reading = "gt97-none" if none else "gt97-some" if some else "gt97-unsettled"
    return Measured(
        numbers={"no_solution_at_zero_load": none, "solution_at_zero_load": some,
                 "min_inverse_load": s["min_inverse_load"], "min_q": s["min_q"]},
        evidence=_evidence("ring-gt97-comparison", zero_load=_zero_load_text(s),
                           reading=_phrase(reading)))


def _torsion_caveat_rule(n: dict) -> str:
    return "holds" if n["all_positive"] and n["same_pattern"] else "fails"


TORSION_CAVEAT = ClaimSpec(
    id="caveat-torsional-stiffness", section="Sec. 'Equilibrium equations', Eq. constit",
    claim="(Modelling assumption) The torsional stiffness A₃ = E₂(I₁ + I₂) — the polar moment, "
          "exact for a circular section only; the ring's verdicts do not hinge on it.",
    test="Rectangular sections with the same ν: Saint-Venant J = β h b³ < I₁ + I₂ "
         "(spectral_rod.rectangle_torsion_ratio), isotropic material (A₃ = G J); converged "
         "q_cr(N), N = 0..10, ν of the table, every reading, against the paper's A₃: how far q_cr "
         "moves and whether the verdict-deciding facts move (q_cr > 0 everywhere; q_cr(N) < "
         "q_cr(0); the rise at large N).",
    methods=(SECOND_VARIATION, Method("Saint-Venant torsion of a rectangle (closed form)",
                                      "closed form")), shared_checks=True, kind="caveat",
    rule=ring_rule("caveat-torsional-stiffness", _torsion_caveat_rule))


def measure_torsion_caveat(ev: RingEvidence) -> Measured:
    r = ev.rectangle
    changes, same = [], True
    for (nu, load), g in r.groupby(["nu", "load"]):
        q_rect = g.sort_values("N")["q"].to_numpy()
        q_iso = np.array([q_at(ev, nu, N, "isotropic", load) for N in TWISTS])
        changes.append(float(np.max(np.abs(q_rect / q_iso - 1))))
        if nu > 1.0:  # no lowered/raised pattern without a positive q_cr(0): the rule fails
            same &= bool(q_rect[0] > 0 and q_iso[0] > 0 and np.array_equal(
                twist_raises_load(q_rect[1:], q_rect[0]), twist_raises_load(q_iso[1:], q_iso[0])))
    ratios = r.groupby("nu")["torsion_ratio"].first()
    positive = bool((r["q"] > 0).all())
    return Measured(
        numbers={"torsion_ratio": {float(k): float(v) for k, v in ratios.items()},
                 "max_relative_change": max(changes), "all_positive": bool((r["q"] > 0).all()),
                 "same_pattern": same},
        evidence=_evidence(
            "caveat-torsional-stiffness",
            ratios=_items("torsion-ratio", ({"nu": k, "ratio": v} for k, v in ratios.items())),
            max_change=max(changes), all_positive=positive, same=same,
            hinge=_phrase("torsion-no-hinge" if same and positive else "torsion-may-depend")))


def _load_caveat_rule(n: dict) -> str:
    return "holds" if not n["undecided_claims"] and n["claims_compared"] else "inconclusive"


#: Why the load caveat rests on one formulation (its evidence is other rows' verdicts).
LOAD_CAVEAT_WHY = ("its evidence is the other ring rows' verdicts under each reading alone; "
                   "each of those rows names its own formulations, and every reading's loads "
                   "agree with Eqs. Munder on the comparison cases (ring-adjacent-equilibrium)")


LOAD_CAVEAT = ClaimSpec(
    id="caveat-load-model", section=SECTION + " (load left unspecified)",
    claim="(Modelling caveat) The paper's load — 'a radially inward-directed force per unit "
          "length q = −q e_r', 'uniform radial pressure', 'radially inwards directed pressure' — "
          "fixes it on the circle only. Four standard readings agree there and differ once the "
          "ring moves; every ring verdict is judged under each, and those that depend on the "
          "reading are named.",
    test="Every reading solved throughout: pressure on the ring's projection (hydrostatic, "
         "q e_z × R'), a force toward the ring's axis (axis), toward its centre point (centre), "
         "a dead load of fixed direction −q e_r(s) (dead); the largest spread of q_cr between "
         "readings on the table; every other ring row judged by its rule on each reading's "
         "evidence alone (the other readings' numbers replaced by this one's).",
    methods=(SECOND_VARIATION,), shared_checks=True, one_formulation_why=LOAD_CAVEAT_WHY,
    kind="caveat",
    rule=ring_rule("caveat-load-model", _load_caveat_rule),
    related=("ring-destabilises", "caveat-ring-supports", "ring-adjacent-equilibrium"))


def _relabel_column(col: str, load: str) -> str:
    """The column of `load` that stands where `col` (of any load model) stands."""
    return "_".join(load if part in RING_LOADS else part for part in col.split("_"))


def _one_load_frame(frame: pd.DataFrame, load: str) -> pd.DataFrame:
    if "load" in frame.columns:
        mine = frame[frame["load"] == load]
        return pd.concat([mine.assign(load=ld) for ld in RING_LOADS], ignore_index=True)
    return frame.assign(**{c: frame[_relabel_column(c, load)] for c in frame.columns
                           if _relabel_column(c, load) != c})


def single_load_evidence(ev: RingEvidence, load: str) -> RingEvidence:
    """`ev` with every number of the other readings replaced by `load`'s (the formulation
    cases, one reading each, stay as they are; rows that use them filter by the reading)."""
    one = copy.copy(ev)
    # its re-solves (witnesses) are of the model whose numbers it holds (already one model's
    # evidence: that model's, whichever label is picked)
    one.load_override = ev.load_override or load
    for name in ("table", "thresholds", "untwisted_circular", "wide", "boundaries", "rectangle",
                 "one_harmonic"):
        setattr(one, name, _one_load_frame(getattr(ev, name), load))
    return one


def verdicts_per_load(ev: RingEvidence) -> dict[str, dict[str, str]]:
    """Per other ring claim: its rule's verdict on each reading's evidence alone."""
    alone = {ld: single_load_evidence(ev, ld) for ld in RING_LOADS}
    return {spec.id: {ld: spec.rule.decide(measure(alone[ld]).numbers) for ld in RING_LOADS}
            for spec, measure in CLAIMS if spec.id != LOAD_CAVEAT.id}


def measure_load_caveat(ev: RingEvidence) -> Measured:
    t = ev.table
    q = t[[f"q_{ld}" for ld in RING_LOADS]].to_numpy()
    spread = float(np.max((q.max(axis=1) - q.min(axis=1)) / q.min(axis=1)))
    per = verdicts_per_load(ev)
    undecided = [k for k, v in per.items() if "inconclusive" in v.values()]
    dependent = [k for k, v in per.items() if k not in undecided and len(set(v.values())) > 1]
    c = ev.untwisted_circular[ev.untwisted_circular["e_label"] == "e=1"].set_index("load")
    return Measured(
        numbers={"max_relative_spread": spread, "verdicts_per_load": per,
                 "claims_compared": len(per) - len(undecided),
                 "load_dependent_claims": dependent, "undecided_claims": undecided},
        evidence=_evidence(
            "caveat-load-model", spread=spread,
            in_plane=_items("reading-load", ({"load": ld, "q": c.loc[ld, "in_plane"]}
                                             for ld in RING_LOADS)),
            out_of_plane=_items("reading-load", ({"load": ld, "q": c.loc[ld, "out_of_plane"]}
                                                 for ld in RING_LOADS)),
            n_rows=len(per),
            dependent=_items("reading-verdicts", (
                {"row": k, "verdicts": _items("reading-verdict", (
                    {"load": ld, "verdict": v} for ld, v in per[k].items()))}
                for k in dependent), "; ") or _phrase("none"),
            undecided=", ".join(undecided) or _phrase("none")))


def _formulations_rule(n: dict, *, formulation: float) -> str:
    return "holds" if n["max_rel_diff"] <= formulation else "fails"


FORMULATIONS = ClaimSpec(
    id="ring-two-formulations", section=SECTION,
    claim="(Package check) The ring's critical loads do not depend on the formulation: the "
          "second variation of the energy and the paper's equilibrium equations Munder, "
          "linearised about the loaded circle, give the same q_cr.",
    test=f"Both on {len(AGREEMENT_CASES)} cases: N = {_range([c[0] for c in AGREEMENT_CASES])}, "
         f"ν ∈ {{{', '.join(f'{v:g}' for v in sorted({c[1] for c in AGREEMENT_CASES}))}}}, e ∈ "
         f"{{{', '.join(f'{v:.4g}' for v in sorted({c[2] for c in AGREEMENT_CASES}))}}}, loads "
         f"{', '.join(sorted({c[3] for c in AGREEMENT_CASES}))} (table in the ring report).",
    methods=(SECOND_VARIATION, MUNDER), kind="package",
    rule=ring_rule("ring-two-formulations", _formulations_rule, formulation=FORMULATION_TOL),
    related=("eq-munder",))


def measure_formulations(ev: RingEvidence) -> Measured:
    f = ev.formulations
    return Measured(
        numbers={"max_rel_diff": float(f["rel_diff"].max()), "cases": len(f)},
        evidence=_evidence("ring-two-formulations", max_diff=f["rel_diff"].max(), cases=len(f),
                           max_frequency=int(f["max_frequency"].max())))


SYMPY_RING = Method("sympy: frames, hoop force and second variation of the ring "
                    "(spectral_rod.derivations.ring_linearisation)", "second variation")
KIRCHHOFF = Method("Kirchhoff's vector balances M' + t×F + m = 0, F' + q = 0 (ring_munder, "
                   "equations='kirchhoff')", "Kirchhoff balances")
SYMPY_STRAIGHT = Method("sympy: Munder linearised about the straight rod gives inst1, which "
                        "the energy also gives (spectral_rod.derivations.straight_rod)", "Munder")

def _munder_rule(n: dict, *, equations: float) -> str:
    return ("holds" if n["munder_vs_kirchhoff"] <= equations
            and n["straight_rod_derivation"] == DERIVATION_CHECKED else "fails")


MUNDER_ROW = ClaimSpec(
    id="eq-munder", section="Sec. 'Equilibrium equations', Eqs. Munder",
    claim="Eqs. Munder (with constit) are the conditions of mechanical equilibrium: eliminating "
          "the cross-sectional force components from the balance of forces and moments.",
    test="Numerically, on the twisted ring: the critical loads from Eqs. Munder linearised about "
         "the loaded circle against (i) Kirchhoff's vector balances with the full force as "
         "unknown and (ii) the second variation of the energy; symbolically, on the straight "
         "rod: Munder linearised gives inst1, which the energy's Euler-Lagrange equations also "
         "give (eq-inst1).",
    methods=(MUNDER, KIRCHHOFF, SECOND_VARIATION, SYMPY_STRAIGHT), shared_checks=True,
    rule=ring_rule("eq-munder", _munder_rule, equations=EQUATIONS_TOL),
    related=("eq-inst1", "ring-two-formulations", "ring-hoop-force"))


def measure_munder(ev: RingEvidence) -> Measured:
    eq = ev.equilibrium
    status = eq["straight_rod_derivation"]
    return Measured(
        numbers={"munder_vs_kirchhoff": eq["munder_vs_kirchhoff"],
                 "straight_rod_derivation": status,
                 "munder_vs_energy": float(ev.formulations["rel_diff"].max())},
        evidence=_evidence("eq-munder", munder_vs_kirchhoff=eq["munder_vs_kirchhoff"],
                           munder_vs_energy=ev.formulations["rel_diff"].max(), status=status))


def _hoop_rule(n: dict, *, residual: float) -> str:
    return ("holds" if n["base_residual"] <= residual
            and n["ring_derivation"] == DERIVATION_CHECKED else "fails")


HOOP = ClaimSpec(
    id="ring-hoop-force", section=SECTION + ", para. 'We study the stability ...'",
    claim="Below the critical load the inward load is balanced by the tangential internal force "
          "F_t = −qR₀ and no displacement arises.",
    test="The loaded circle with F_t = −qR₀ and no moments in Eqs. Munder: its residual for every "
         "reading of the load (ring_munder); the sympy ring derivation's step 2 (Munder at the "
         "stress-free state gives F_t = −qR₀).",
    methods=(MUNDER, SYMPY_RING),
    rule=ring_rule("ring-hoop-force", _hoop_rule, residual=RESIDUAL_TOL),
    related=("eq-munder",))


def measure_hoop(ev: RingEvidence) -> Measured:
    eq = ev.equilibrium
    return Measured(
        numbers={"base_residual": eq["base_residual"], "ring_derivation": eq["ring_derivation"]},
        evidence=_evidence("ring-hoop-force", residual=eq["base_residual"],
                           cases=len(EQUILIBRIUM_CASES), derivation=eq["ring_derivation"]))


#: The ring claims in ledger order: (declaration, measurement).
CLAIMS: tuple[tuple[ClaimSpec, Callable[[RingEvidence], Measured]], ...] = (
    (CRIT2_ROW, measure_crit2), (CRIT2_GALERKIN, measure_crit2_galerkin),
    (TORSION_SCALING, measure_torsion_scaling), (FIXED_N, measure_fixed_n),
    (ANALYTIC_ONLY, measure_analytic_only), (CIRCULAR_LIMIT, measure_circular_limit),
    (TWIST_INDEPENDENT, measure_twist_independent), (IN_OUT, measure_in_out),
    (MONOTONE, measure_monotone), (RATE, measure_rate), (SPONTANEOUS, measure_spontaneous),
    (DESTABILISES, measure_destabilises), (THREE_D, measure_three_d),
    (INTRO_3D, measure_intro_3d), (GT97, measure_gt97), (FORMULATIONS, measure_formulations),
    (ADJACENT, measure_adjacent), (TORSION_CAVEAT, measure_torsion_caveat),
    (LOAD_CAVEAT, measure_load_caveat), (SUPPORTS, measure_supports),
    (TWISTS_CAVEAT, measure_twists_caveat), (MUNDER_ROW, measure_munder),
    (TORSIONS, measure_torsions), (THREE_EQUATIONS, measure_three_equations),
    (HOOP, measure_hoop),
)


def evaluate_claims(ev: RingEvidence) -> list[Claim]:
    """Every row of this scene, judged (with the shared cross-checks where declared)."""
    return evaluate(CLAIMS, ev, SCENE, shared_checks=shared_checks(ev))


def evaluate_claim(claim_id: str, ev: RingEvidence) -> Claim:
    """The one row `claim_id`, judged (e.g. to recompute it after perturbing the evidence)."""
    return evaluate(CLAIMS, ev, SCENE, claim_id, shared_checks=shared_checks(ev))[0]
