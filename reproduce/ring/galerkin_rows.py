"""Ring rows on how Eq. ``crit2`` was obtained: the one-harmonic Galerkin the paper states
("the perturbations ... in the form X_n sin(ns/R0) with a fixed n"), computed, against crit2
and against the converged load; crit2's E2 prefactor; "an analytical solution ... only for
I1 = I2".

At N = 0 the twist couples nothing (frequencies decouple), so the one-harmonic Galerkin is exact
there and equals the classical closed forms of the untwisted ring for every nu: crit2(N = 0) =
e (nu + 2) must reproduce them if it is that method's result.  For N >= 1 the one-harmonic
Galerkin of this conservative problem is a Rayleigh-Ritz estimate, an upper bound of the
converged load; crit2 falls below the converged load.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable

import numpy as np

from reproduce.ledger import ClaimSpec, Measured, Method, Rule
from reproduce.ring.evidence import E_RATIOS, NUS, SECTION, RingEvidence
from reproduce.ring.root_causes import CRIT2_NOT_GALERKIN, UNTWISTED_ANISOTROPIC_SOLVABLE
from reproduce.ring.standards import (
    APPROX_TOL,
    CLASSICAL,
    CLOSED_FORM_TOL,
    CRIT2,
    DEVIATION_RULE_TEXT,
    EXACT_TOL,
    PAPER_NU_MAX,
    SECOND_VARIATION,
    readings,
    rule_from_template,
    verdict_by_deviation,
)
from spectral_rod import (
    crit2,
    in_plane_mode_load,
    out_of_plane_mode_load,
    untwisted_critical_load,
)

ONE_HARMONIC = Method("one-harmonic Galerkin of the second variation (every field cos, sin of "
                      "one ns/R; spectral_rod.ring_one_harmonic_load)", "second variation")
#: Wavenumbers searched for the single-mode load nearest to crit2(N = 0).
WAVENUMBERS = range(2, 41)

#: The verdict rules' texts: templates whose named fields are the thresholds the rule's logic
#: is given (:func:`_rule`).
RULE_TEXTS = {
    "ring-crit2-galerkin": "on the best-matching reading, the largest |crit2(0) − q(0)|/q(0) "
                           "over (ν, e): " + DEVIATION_RULE_TEXT,
    "ring-crit2-torsion-scaling": "largest |(q(e=1)/q(iso)) / (1/e_iso) − 1| over the table: "
                                  + DEVIATION_RULE_TEXT,
    "ring-analytic-only-circular": (
        "fails if a closed form reproduces the converged q_cr of some ring with I₁ ≠ I₂ to "
        "{closed_form:g} (an analytical solution beyond I₁ = I₂); inconclusive otherwise (a "
        "closed form that misses the solver disproves nothing)"),
    "ring-fixed-n-ansatz": (
        "an estimate is reasonable within {approx:.0%}: holds if (q_one-harmonic − q)/q ≤ "
        "{approx:.0%} at every ν of the table; holds approximately if so for every ν within the "
        "paper's range (ν ≤ {paper_nu_max:g}) only; fails otherwise; inconclusive without "
        "twisted rings"),
}

#: The evidence texts of the rows and their parts: templates with named fields, filled by the
#: rows' measurements (:func:`_evidence`, :func:`_items`).
EVIDENCE = {
    "ring-crit2-galerkin": (
        "At N = 0 crit2 = e(ν + 2): {crit2_nu4:g} at ν = 4, e = 1, where the exact "
        "(one-harmonic) load is {exact_nu4}; max |crit2(0) − q(0)|/q(0) per reading: "
        "{per_reading}; for some (ν, e) no single mode's load (n = {n_first}..{n_last}, in or "
        "out of plane, any reading) comes within {nearest:.0%} of crit2(0). For N ≥ 1 the "
        "computed one-harmonic Galerkin is an upper bound of the converged load ({bound_ok}), "
        "while crit2 lies below the converged load in {below} of {twisted} twisted rings; "
        "|crit2 − one-harmonic|/one-harmonic up to {gap:.3g}."),
    "ring-crit2-torsion-scaling": (
        "crit2 scales by {factor:.3f} from the isotropic e to e = 1; the converged load by "
        "{ratio_min:.3f} … {ratio_max:.3f}. {in_plane} of the e = 1 critical modes are in-plane "
        "— bending about e_z only, no torsion — and their load does not depend on E₂ at all "
        "(ratio 1)."),
    "ring-analytic-only-circular": (
        "At N = 0 the closed forms reproduce all {cases} converged loads with I₁ ≠ I₂ to "
        "{dev:.1e}. For N ≥ 1 and I₁ ≠ I₂ the twist couples frequency n to 2N ± n and no closed "
        "form is known (only the N → ∞ limit, by homogenisation): the sentence holds for the "
        "twisted ring, not for the equations as stated."),
    "ring-fixed-n-ansatz": (
        "Largest excess of the one-harmonic load over the converged one by ν: {by_nu} (within "
        "{approx:.0%} up to ν = {good:g}). A reasonable estimate for small anisotropy, a poor "
        "one beyond; it never falls below the converged load, so it has no threshold twist."),
    "exact-load": "{q:g} ({load})",
    "reading-deviation": "{load} {dev:.2f}",
    "excess-by-nu": "ν = {nu:g}: {excess:.1%}",
}


def _rule(row_id: str, decide: Callable[..., str], **thresholds: float) -> Rule:
    """The rule of `row_id`: :data:`RULE_TEXTS` and `decide` with the same `thresholds`."""
    return rule_from_template(RULE_TEXTS[row_id], decide, **thresholds)


def _evidence(name: str, **fields: object) -> str:
    """The text `name` of :data:`EVIDENCE` with its named fields."""
    return EVIDENCE[name].format(**fields)


def _items(name: str, items: Iterable[dict[str, object]]) -> str:
    """The text `name` once per item (its fields), joined by commas."""
    return ", ".join(_evidence(name, **fields) for fields in items)


def _deviation_rule(n: dict, *, key: str, exact: float, approx: float) -> str:
    return verdict_by_deviation(n[key], exact, approx)


def _nearest_mode_load(value: float, nu: float, e: float, loads: tuple[str, ...]) -> float:
    """min over wavenumbers, in-plane and out-of-plane modes and readings of |value - q_n|/q_n:
    how close crit2(N = 0) comes to the load of any single untwisted mode."""
    a3 = e * (1.0 + nu)
    qs = [f(n) for ld in loads for n in WAVENUMBERS
          for f in (lambda n, ld=ld: in_plane_mode_load(n, 1.0, ld),
                    lambda n, ld=ld: out_of_plane_mode_load(n, nu, a3, ld))]
    return float(min(abs(value - q) / q for q in qs))


CRIT2_GALERKIN = ClaimSpec(
    id="ring-crit2-galerkin", section=SECTION + ", para. 'In the general case ...' (Eq. crit2)",
    claim="Eq. crit2 is what the stated Galerkin method gives: y_φ, y_z, α of the form "
          "X_n sin(ns/R₀) with a fixed n, the equations averaged over the ring.",
    test="At N = 0 the harmonics decouple, so the one-harmonic Galerkin is exact and equals the "
         "classical closed forms of the untwisted ring (in plane about e_z with E₁I₁, out of "
         "plane about e_r with E₁I₂, for every reading of the load): crit2(0) = e(ν + 2) "
         f"against them for ν ∈ {{{', '.join(f'{v:g}' for v in NUS)}}}, e = 1 and isotropic; "
         f"the nearest load of any single mode (n = {WAVENUMBERS[0]}..{WAVENUMBERS[-1]}, in or "
         "out of plane, any reading). For N ≥ 1: the one-harmonic Galerkin computed (an upper "
         "bound of the converged load) against crit2.",
    methods=(CRIT2, CLASSICAL, ONE_HARMONIC), shared_checks=True,
    rule=_rule("ring-crit2-galerkin", functools.partial(_deviation_rule,
                                                         key="max_rel_dev_N0_best_reading"),
               exact=EXACT_TOL, approx=APPROX_TOL),
    related=("ring-crit2", "ring-crit2-torsion-scaling", "ring-fixed-n-ansatz"),
    root_cause=CRIT2_NOT_GALERKIN)


def measure_crit2_galerkin(ev: RingEvidence) -> Measured:
    loads = readings(ev)
    per_reading = {}
    nearest = 0.0
    for ld in loads:
        devs = []
        for e in E_RATIOS.values():
            for nu in NUS:
                exact = untwisted_critical_load(nu, e, ld)
                devs.append(abs(crit2(0, nu, e) - exact) / exact)
        per_reading[ld] = float(max(devs))
    for e in E_RATIOS.values():
        for nu in NUS:
            nearest = max(nearest, _nearest_mode_load(crit2(0, nu, e), nu, e, loads))
    best = min(per_reading, key=per_reading.__getitem__)
    o = ev.one_harmonic
    o = o[(o["N"] >= 1) & o["load"].isin(loads)]
    tw = ev.table[ev.table["N"] >= 1]
    below = int((tw["crit2"] < tw[[f"q_{ld}" for ld in loads]].min(axis=1)).sum())
    bound_ok = bool((o["q_one_harmonic"] >= o["q"] * (1 - EXACT_TOL)).all())
    c2 = {(r.e_label, r.nu, r.N): r.crit2 for r in ev.table.itertuples()}
    gap = (np.abs(np.array([c2[(r.e_label, r.nu, r.N)] for r in o.itertuples()])
                  - o["q_one_harmonic"].to_numpy()) / o["q_one_harmonic"].to_numpy())
    return Measured(
        numbers={"max_rel_dev_N0": per_reading, "max_rel_dev_N0_best_reading": per_reading[best],
                 "best_reading": best, "nearest_single_mode_N0": nearest,
                 "crit2_below_converged_N_ge_1": below, "twisted_cases": len(tw),
                 "one_harmonic_is_upper_bound": bound_ok,
                 "max_rel_dev_one_harmonic_N_ge_1": float(gap.max()) if gap.size else np.nan},
        evidence=_evidence(
            "ring-crit2-galerkin", crit2_nu4=crit2(0, 4.0, 1.0),
            exact_nu4=_items("exact-load", ({"q": untwisted_critical_load(4.0, 1.0, ld),
                                             "load": ld} for ld in loads)),
            per_reading=_items("reading-deviation", ({"load": k, "dev": v}
                                                     for k, v in per_reading.items())),
            n_first=WAVENUMBERS[0], n_last=WAVENUMBERS[-1], nearest=nearest, bound_ok=bound_ok,
            below=below, twisted=len(tw), gap=float(gap.max()) if gap.size else float("nan")))


TORSION_SCALING = ClaimSpec(
    id="ring-crit2-torsion-scaling", section=SECTION + ", Eq. crit2",
    claim="Eq. crit2's prefactor E₂(I₁+I₂)/(2R₀³): the critical load is proportional to the "
          "torsional modulus E₂.",
    test="The converged q_cr at e = 1 over q_cr at the isotropic e (same ν, N, reading) against "
         f"crit2's ratio 1/e_iso = {1 / E_RATIOS['isotropic']:.3f}, over the table; in-plane "
         "modes involve no torsion at all.",
    methods=(SECOND_VARIATION, CRIT2), shared_checks=True,
    rule=_rule("ring-crit2-torsion-scaling", functools.partial(_deviation_rule,
                                                                key="max_rel_dev"),
               exact=EXACT_TOL, approx=APPROX_TOL),
    related=("ring-crit2-galerkin", "ring-crit2"), root_cause=CRIT2_NOT_GALERKIN)


def measure_torsion_scaling(ev: RingEvidence) -> Measured:
    t = ev.table
    one, iso = (t[t["e_label"] == lab].set_index(["nu", "N"]) for lab in ("e=1", "isotropic"))
    factor = 1.0 / E_RATIOS["isotropic"]
    devs, ratios, in_plane = [], [], 0
    for ld in readings(ev):
        r = (one[f"q_{ld}"] / iso[f"q_{ld}"]).to_numpy()
        ratios += list(r)
        devs += list(np.abs(r / factor - 1.0))
        in_plane += int((one[f"kind_{ld}"] == "in-plane").sum())
    return Measured(
        numbers={"max_rel_dev": float(max(devs)), "ratio_range": (float(min(ratios)),
                                                                  float(max(ratios))),
                 "crit2_ratio": factor, "in_plane_modes_e1": in_plane},
        evidence=_evidence("ring-crit2-torsion-scaling", factor=factor, ratio_min=min(ratios),
                           ratio_max=max(ratios), in_plane=in_plane))


def _analytic_only_rule(n: dict, *, closed_form: float) -> str:
    return "fails" if n["max_rel_dev_N0_nu_gt_1"] <= closed_form else "inconclusive"


ANALYTIC_ONLY = ClaimSpec(
    id="ring-analytic-only-circular", section=SECTION + ", para. 'We derive three coupled ...'",
    claim="An analytical solution of the ring's perturbation equations can be obtained only in "
          "the special case I₁ = I₂.",
    test="The untwisted ring (N = 0, Ω ≡ 0) with I₁ ≠ I₂: the classical closed forms (in plane "
         "about e_z with E₁I₁, out of plane about e_r with E₁I₂ and A₃; every reading) against "
         f"the converged q_cr for ν ∈ {{{', '.join(f'{v:g}' for v in NUS if v > 1)}}}, e = 1 "
         "and isotropic.",
    methods=(CLASSICAL, SECOND_VARIATION), shared_checks=True,
    rule=_rule("ring-analytic-only-circular", _analytic_only_rule, closed_form=CLOSED_FORM_TOL),
    related=("ring-crit2-galerkin",), root_cause=UNTWISTED_ANISOTROPIC_SOLVABLE)


def measure_analytic_only(ev: RingEvidence) -> Measured:
    t = ev.table[(ev.table["N"] == 0) & (ev.table["nu"] > 1.0)]
    devs = [abs(r[f"q_{ld}"] - untwisted_critical_load(r["nu"], r["e_ratio"], ld))
            / r[f"q_{ld}"] for _, r in t.iterrows() for ld in readings(ev)]
    dev = float(max(devs)) if devs else float("nan")
    return Measured(
        numbers={"max_rel_dev_N0_nu_gt_1": dev, "cases": len(devs)},
        evidence=_evidence("ring-analytic-only-circular", cases=len(devs), dev=dev))


def _estimate_rule(n: dict, *, approx: float, paper_nu_max: float) -> str:
    by_nu = n["max_rel_excess_by_nu"]
    if not by_nu:
        return "inconclusive"
    if max(by_nu.values()) <= approx:
        return "holds"
    paper = [v for nu, v in by_nu.items() if nu <= paper_nu_max]
    return "holds approximately" if paper and max(paper) <= approx else "fails"


FIXED_N = ClaimSpec(
    id="ring-fixed-n-ansatz", section=SECTION + ", para. 'In the general case ...'",
    claim="A one-harmonic perturbation (X_n sin(ns/R₀), fixed n) gives a reasonable estimate of "
          "the twisted ring's critical force.",
    test="The one-harmonic Galerkin load, computed (min over n), against the converged q_cr for "
         f"every twisted ring of the table (N ≥ 1, ν ∈ {{{', '.join(f'{v:g}' for v in NUS)}}}, "
         "e = 1 and isotropic, every reading).",
    methods=(ONE_HARMONIC, SECOND_VARIATION), shared_checks=True,
    rule=_rule("ring-fixed-n-ansatz", _estimate_rule, approx=APPROX_TOL,
               paper_nu_max=PAPER_NU_MAX),
    related=("ring-crit2-galerkin",))


def measure_fixed_n(ev: RingEvidence) -> Measured:
    o = ev.one_harmonic
    o = o[(o["N"] >= 1) & o["load"].isin(readings(ev))]
    excess = (o["q_one_harmonic"] - o["q"]) / o["q"]
    by_nu = {float(nu): float(g.max()) for nu, g in excess.groupby(o["nu"])}
    good = max([k for k, v in by_nu.items() if v <= APPROX_TOL], default=float("nan"))
    return Measured(
        numbers={"max_rel_excess": float(excess.max()), "max_rel_excess_by_nu": by_nu},
        evidence=_evidence("ring-fixed-n-ansatz", approx=APPROX_TOL, good=good,
                           by_nu=_items("excess-by-nu", ({"nu": k, "excess": v}
                                                         for k, v in by_nu.items()))))
