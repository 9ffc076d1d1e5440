"""Ring rows on what the paper leaves to the reader: how the ring is held (its supports under
each reading of the load), whether the adjacent-equilibrium criterion applies to the loads, and
which twists close the ring (Sec. 'Stability of a ring')."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable

import numpy as np

from reproduce.ledger import ClaimSpec, Measured, Method, Rule
from reproduce.ring.evidence import SECTION, TWISTS, RingEvidence
from reproduce.ring.standards import (
    EXACT_TOL,
    FORMULATION_TOL,
    MUNDER,
    SECOND_VARIATION,
    readings,
    rule_from_template,
)
from spectral_rod import (
    RING_LOADS,
    derivation_status,
    rigid_motion_load_work,
    rigid_motion_stiffness,
    ring_constraint_rank,
    ring_coupling_strengths,
    ring_reference_torsions,
)

RIGID = Method("rigid motions of the ring in the second variation "
               "(spectral_rod.ring.loads)", "second variation")
#: x.K x of a rigid motion relative to the largest stiffness: zero to round-off.
RIGID_TOL = 1.0e-12
#: |x.G x| below this is a neutral rigid motion (the load work is O(1) otherwise).
NEUTRAL_TOL = 1.0e-12
#: Every rigid motion of a ring in space: three translations, three rotations.
N_RIGID = 6
#: The status :func:`spectral_rod.derivation_status` reports for a derivation whose every step
#: checked.
DERIVATION_CHECKED = "all steps checked"

#: The verdict rules' texts: templates whose named fields are the thresholds the rule's logic
#: is given (:func:`_rule`).
RULE_TEXTS = {
    "caveat-ring-supports": (
        "holds if the rigid motions store no elastic energy (≤ {rigid:g}) and the constraints "
        "restrain all {n_rigid} (rank {n_rigid}: none left to tip, spin or drift); fails "
        "otherwise"),
    "ring-adjacent-equilibrium": (
        "holds if, for every reading, the two agree to {formulation:g} on its cases; fails if "
        "they disagree for some reading; inconclusive if a reading has no case"),
    "caveat-admissible-twists": (
        "holds if the half turn leaves the stiffness unchanged (≤ {neutral:g}) and the quarter "
        "turn does not (half-integer twists close, quarter-integer do not); fails otherwise"),
    "ring-spontaneous-torsions": (
        "holds if the symbolic step passes and the numerical torsions match to {exact:g}; fails "
        "otherwise"),
    "ring-three-coupled-equations": (
        "holds if on the twisted ring both links exceed {coupling:g} of K's largest entry and "
        "the derivation's steps pass; fails otherwise"),
}

#: The evidence texts of the rows and their parts: templates with named fields, filled by the
#: rows' measurements (:func:`_evidence`, :func:`_items`).
EVIDENCE = {
    "caveat-ring-supports": (
        "Rigid motions under q > 0 — {per_reading}. Only the centre-directed load destabilises "
        "none. Elastic energy of the rigid motions {stiffness:.1e}; the six constraints have "
        "rank {rank} on them, so the package's ring is held against every rigid motion (a "
        "frictionless mean restraint: it acts on frequencies 0 and 1 only and leaves every "
        "buckling mode of wavenumber ≥ 2 free)."),
    "ring-adjacent-equilibrium": (
        "Equilibrium (forces) vs energy (potentials), largest relative difference per reading: "
        "{per_reading}. So the loads are conservative and the criterion gives their stability "
        "limit."),
    "caveat-admissible-twists": (
        "Turned by π the stiffness changes by {half:.1e}, by π/2 by {quarter:g}: the ring "
        "closes for N ∈ ½ℤ, the paper and the package use integers only (its solver's families "
        "f = ±n mod 2N need 2N integer, which half-integers satisfy; they are not solved "
        "here)."),
    "ring-spontaneous-torsions": (
        "sympy: {status}; numerically the sampled frame's torsions match the printed ones to "
        "{dev:.1e} (R₀ = 1) for N = {n_first}..{n_last}."),
    "ring-three-coupled-equations": (
        "Relative size of the links in K: twisted (N = {N}, ν = {nu:g}) fields "
        "{twisted_fields:.2f}, f ↔ f ± 2N {twisted_variable:.2f}; untwisted {flat_fields:.1e} / "
        "{flat_variable:.1e}; circular section {circular_fields:.1e} / "
        "{circular_variable:.1e}. So the three equations are coupled with variable coefficients "
        "for N ≥ 1 and I₁ ≠ I₂ only; for N = 0 or I₁ = I₂ they have constant coefficients and "
        "the in-plane one separates."),
    "supports-reading": "{load}: destabilised {destabilised}; neutral {neutral}",
    "adjacent-reading": "{load} {diff:.1e} ({cases} cases)",
    "none": "none",
}


def _rule(row_id: str, decide: Callable[..., str], **thresholds: float) -> Rule:
    """The rule of `row_id`: :data:`RULE_TEXTS` and `decide` with the same `thresholds`."""
    return rule_from_template(RULE_TEXTS[row_id], decide, **thresholds)


def _evidence(name: str, **fields: object) -> str:
    """The text `name` of :data:`EVIDENCE` with its named fields."""
    return EVIDENCE[name].format(**fields)


def _items(name: str, items: Iterable[dict[str, object]], sep: str = ", ") -> str:
    """The text `name` once per item (its fields), joined by `sep`."""
    return sep.join(_evidence(name, **fields) for fields in items)


def _supports_rule(n: dict, *, rigid: float, n_rigid: int) -> str:
    return ("holds" if n["rigid_stiffness"] <= rigid and n["constraint_rank"] == n_rigid
            else "fails")


def _adjacent_rule(n: dict, *, formulation: float) -> str:
    if min(n["cases_per_reading"].values()) == 0:
        return "inconclusive"
    return "holds" if max(n["max_rel_diff_per_reading"].values()) <= formulation else "fails"


def _twists_rule(n: dict, *, neutral: float) -> str:
    return "holds" if n["half_turn_change"] <= neutral < n["quarter_turn_change"] else "fails"


def _torsions_rule(n: dict, *, exact: float) -> str:
    return ("holds" if n["sympy"] == DERIVATION_CHECKED and n["max_abs_dev"] <= exact
            else "fails")


def _three_equations_rule(n: dict, *, coupling: float) -> str:
    return ("holds" if min(n["twisted"].values()) > coupling and n["sympy"] == DERIVATION_CHECKED
            else "fails")


def _behaviour(work: float) -> str:
    return ("destabilised" if work > NEUTRAL_TOL else "restored" if work < -NEUTRAL_TOL
            else "neutral")


SUPPORTS = ClaimSpec(
    id="caveat-ring-supports", section=SECTION + " (supports left unspecified)",
    claim="(Modelling caveat) The paper does not say how the ring is held. Under q > 0 each "
          "reading of the load destabilises some rigid motions (the free ring tips over or "
          "spins); the package restrains all six rigid motions — mean displacement and mean "
          "rotation held at zero, a restraint that does no work on any deformation of "
          "wavenumber ≥ 2.",
    test="The load work x·G·x of the six rigid motions (translations along e_x, e_y, e_z; spin "
         "about e_z; tilts about e_x, e_y) under every reading (> 0: destabilised for every "
         "q > 0, 0: neutral, < 0: restored); their elastic energy x·K·x; the rank of the "
         "solvers' six constraints on them.",
    methods=(RIGID, MUNDER), kind="caveat",
    rule=_rule("caveat-ring-supports", _supports_rule, rigid=RIGID_TOL, n_rigid=N_RIGID),
    related=("caveat-load-model",),
    one_formulation_why="the rigid motions' load work is a property of each load's potential; "
                        "Eqs. Munder carry the same six constraints as reactions")


def measure_supports(ev: RingEvidence) -> Measured:
    work = {ld: rigid_motion_load_work(ld) for ld in RING_LOADS}
    behaviour = {ld: {m: _behaviour(w) for m, w in work[ld].items()} for ld in RING_LOADS}
    parts = [{"load": ld, **{kind: ", ".join(m for m, b in behaviour[ld].items() if b == kind)
                             or _evidence("none") for kind in ("destabilised", "neutral")}}
             for ld in RING_LOADS]
    rank, stiff = ring_constraint_rank(), rigid_motion_stiffness()
    return Measured(
        numbers={"load_work": work, "behaviour": behaviour, "constraint_rank": rank,
                 "rigid_stiffness": stiff},
        evidence=_evidence("caveat-ring-supports", per_reading=_items("supports-reading", parts,
                                                                      "; "),
                           stiffness=stiff, rank=rank))


ADJACENT = ClaimSpec(
    id="ring-adjacent-equilibrium", section=SECTION + ", para. 'We study the stability ...'",
    claim="The critical load is where a small deviation from the loaded circle first satisfies "
          "the linearised equilibrium equations (the adjacent-equilibrium criterion), for the "
          "load used.",
    test="The criterion is the stability limit for conservative loads. Every reading has a "
         "potential (pressure × projected area; q∫ρ ds; q∫|R| ds; a linear potential for the "
         "dead load). Per reading, the equilibrium formulation (Eqs. Munder, the load as a "
         "force, no potential) against the energy's second variation on the comparison cases.",
    methods=(MUNDER, SECOND_VARIATION), shared_checks=True,
    rule=_rule("ring-adjacent-equilibrium", _adjacent_rule, formulation=FORMULATION_TOL),
    related=("ring-two-formulations", "caveat-load-model"))


def measure_adjacent(ev: RingEvidence) -> Measured:
    f = ev.formulations
    cases = {ld: int((f["load"] == ld).sum()) for ld in readings(ev)}
    diff = {ld: float(f.loc[f["load"] == ld, "rel_diff"].max()) if cases[ld] else math.nan
            for ld in readings(ev)}
    return Measured(
        numbers={"cases_per_reading": cases, "max_rel_diff_per_reading": diff},
        evidence=_evidence("ring-adjacent-equilibrium", per_reading=_items(
            "adjacent-reading", ({"load": ld, "diff": diff[ld], "cases": cases[ld]}
                                 for ld in cases))))


def _section_stiffness(nu: float, angle: float) -> np.ndarray:
    """Bending stiffness tensor of a section (A1 = 1, A2 = nu) turned by `angle`."""
    c, s = math.cos(angle), math.sin(angle)
    rot = np.array([[c, -s], [s, c]])
    return rot @ np.diag([1.0, nu]) @ rot.T


#: ν of the admissible-twist check (any ν > 1 does: the check is about the section's symmetry).
TWIST_CHECK_NU = 2.0

TWISTS_CAVEAT = ClaimSpec(
    id="caveat-admissible-twists", section=SECTION + ", para. 'In the general case ...'",
    claim="(Modelling caveat) The paper takes Ω = Ns/R₀ with N a positive integer. A section "
          "with two axes of symmetry maps onto itself after half a turn, so half-integer N also "
          "closes the ring; the package solves N = 0, 1, 2, … (integer N, N = 0 being the "
          "untwisted reference of every comparison).",
    test=f"The bending stiffness tensor of the section (ν = {TWIST_CHECK_NU:g}) turned by π and "
         "by π/2 against the untwisted one: the ring's energy depends on Ω through 2Ω only if "
         "the half turn leaves it unchanged.",
    methods=(Method("rotation of the section's stiffness tensor", "closed form"),), kind="caveat",
    rule=_rule("caveat-admissible-twists", _twists_rule, neutral=NEUTRAL_TOL),
    one_formulation_why="a property of the section's symmetry, not of a solver")


def measure_twists_caveat(ev: RingEvidence) -> Measured:
    base = _section_stiffness(TWIST_CHECK_NU, 0.0)
    half = float(np.max(np.abs(_section_stiffness(TWIST_CHECK_NU, math.pi) - base)))
    quarter = float(np.max(np.abs(_section_stiffness(TWIST_CHECK_NU, math.pi / 2) - base)))
    return Measured(
        numbers={"half_turn_change": half, "quarter_turn_change": quarter},
        evidence=_evidence("caveat-admissible-twists", half=half, quarter=quarter))


SYMPY_FRAMES = Method("sympy: the ring's frame in Eq. frenini "
                      "(spectral_rod.derivations.ring_linearisation, step 1)", "sympy frames")
NUMERIC_FRAMES = Method("Eq. frenet by spectral differentiation of the sampled frame "
                        "(spectral_rod.ring_reference_torsions)", "Munder")

TORSIONS = ClaimSpec(
    id="ring-spontaneous-torsions", section=SECTION + ", para. 'We now turn ...'",
    claim="With t0 = e_φ, u0 = −cos Ω e_r + sin Ω e_z, v0 = sin Ω e_r + cos Ω e_z, Eqs. frenini "
          "give ω₁₀ = cos Ω/R₀, ω₂₀ = −sin Ω/R₀, ω₃₀ = dΩ/ds.",
    test="Symbolically (the ring derivation's step 1) and numerically: the torsions of the "
         f"sampled frame by spectral differentiation for N = {TWISTS[0]}..{TWISTS[-1]} against "
         "the printed formulas.",
    methods=(SYMPY_FRAMES, NUMERIC_FRAMES),
    rule=_rule("ring-spontaneous-torsions", _torsions_rule, exact=EXACT_TOL),
    related=("ring-hoop-force",))


def measure_torsions(ev: RingEvidence) -> Measured:
    dev = 0.0
    for N in TWISTS:
        s, w1, w2, w3 = ring_reference_torsions(N)
        dev = max(dev, float(np.max(np.abs(w1 - np.cos(N * s)))),
                  float(np.max(np.abs(w2 + np.sin(N * s)))), float(np.max(np.abs(w3 - N))))
    status = derivation_status("ring_linearisation")
    return Measured(
        numbers={"max_abs_dev": dev, "sympy": status},
        evidence=_evidence("ring-spontaneous-torsions", status=status, dev=dev,
                           n_first=TWISTS[0], n_last=TWISTS[-1]))


#: The ring on which the coupling of the perturbation equations is measured (N, nu, e).
COUPLING_CASE = (2, 2.0, 1.0)
#: A coupling block counts if its largest entry exceeds this share of K's largest (round-off
#: of the quadrature is ~1e-15 of it).
COUPLING_TOL = 1.0e-12


THREE_EQUATIONS = ClaimSpec(
    id="ring-three-coupled-equations", section=SECTION + ", para. 'We consider a small ...'",
    claim="The perturbations obey three coupled differential equations with variable "
          "coefficients for y_φ(s), y_z(s) and α(s) (y_r eliminated by inextensibility).",
    test=f"The second variation's stiffness K on the twisted ring N = {COUPLING_CASE[0]}, "
         f"ν = {COUPLING_CASE[1]:g}: does it link y_φ with (y_z, α), and frequency f with "
         "f ± 2N (a coefficient varying like cos 2Ω)? The untwisted ring and the circular "
         "section (ν = 1) as references, where both links vanish; the sympy derivation's "
         "inextensibility step (y_r = −R y_φ').",
    methods=(SECOND_VARIATION, SYMPY_FRAMES),
    rule=_rule("ring-three-coupled-equations", _three_equations_rule, coupling=COUPLING_TOL))


def measure_three_equations(ev: RingEvidence) -> Measured:
    N, nu, e = COUPLING_CASE
    twisted = ring_coupling_strengths(N, nu, e)
    flat, circular = ring_coupling_strengths(0, nu, e), ring_coupling_strengths(N, 1.0, e)
    return Measured(
        numbers={"twisted": twisted, "untwisted": flat, "circular": circular,
                 "sympy": derivation_status("ring_linearisation")},
        evidence=_evidence(
            "ring-three-coupled-equations", N=N, nu=nu, twisted_fields=twisted["fields"],
            twisted_variable=twisted["variable_coefficients"], flat_fields=flat["fields"],
            flat_variable=flat["variable_coefficients"], circular_fields=circular["fields"],
            circular_variable=circular["variable_coefficients"]))


__all__ = [
    "ADJACENT",
    "SUPPORTS",
    "THREE_EQUATIONS",
    "TORSIONS",
    "TWISTS_CAVEAT",
    "measure_adjacent",
    "measure_supports",
    "measure_three_equations",
    "measure_torsions",
    "measure_twists_caveat",
]
