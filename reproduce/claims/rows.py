"""The straight-rod rows of the ledger: each claim declared (:class:`ClaimSpec`), measured from
the evidence (``measure_*``) and judged by its named rule (:func:`reproduce.ledger.judge`).

Every verdict threshold is a named constant in the block "thresholds" below, and every rule is
built by :func:`reproduce.ledger.tiered_rule` from :class:`reproduce.ledger.Condition` objects
that use them, so a rule's text and its logic are one definition. Claims of one kind share one
standard: every "at n pi" claim is judged by :data:`NEAR` (and "exactly at" by :data:`EXACT`);
every "for all Omega" claim over the scene's whole twist range. The evidence texts and findings
only report, from templates with named fields (:data:`EVIDENCE`, :data:`FINDINGS`).

Root causes (:data:`ROOT_IMAGINARY_BETA1`, :data:`ROOT_UNIQUENESS`, :data:`ROOT_P_STAR_TYPO`) are
one-line statements of independent errors of the paper, shared by every failing row they explain.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from reproduce.claims.evidence import (
    DETAIL_NU,
    DPS,
    LIMIT_J,
    NUS,
    SECTION,
    SPOT_TWISTS,
    StraightRodEvidence,
    critical_family_switches,
    maxima_agreement,
    rises_until_first_maximum,
    settling_twist,
)
from reproduce.ledger import (
    Claim,
    ClaimSpec,
    Condition,
    CrossCheck,
    Measured,
    Method,
    evaluate,
    tiered_rule,
)
from spectral_rod import (
    FIGURE1_DOT,
    FIGURE1_Y_PER_P,
    beta_difference,
    critical_wavenumbers,
    crossing_twist_asymptotic,
    large_twist_coefficients,
    large_twist_limit,
    large_twist_wavenumbers,
    local_maxima,
    observed_order,
)

SCENE = "claims"

# ---- thresholds: every number a verdict of this scene turns on -----------------------------
#: The one standard of every "at n pi" claim: "holds approximately" if each maximum sits
#: within this relative distance |Omega - n pi| / (n pi) of n pi.
NEAR = 1e-2
#: "Exactly at n pi": the maxima's twists to this relative accuracy (the cross-checks below
#: bound their error by 1e-7 absolute, ~1e-8 relative).
EXACT = 1e-9
#: |D| at a root of the characteristic determinant evaluated with DPS digits: its terms are O(1)
#: and cancel, so 10 digits of cancellation leave 10**(10 - DPS); a non-root gives O(1).
DET_ZERO = 10.0 ** (10 - DPS)
#: A load or a planarity at round-off: |p* - 1| for the Euler load, sigma_min/sigma_max of a
#: planar mode (measured: 0 and 2e-16).
ROUND_OFF = 1e-12
#: |D(p*)| / |D(0.99 p*)| at a root whose load is a double (the load's rounding, 1e-16 relative,
#: times |D'| ~ 1, against |D| ~ 0.01-0.4 one percent below): 1e-12 leaves four digits of room.
ROOT_RATIO = 1e-12
#: A mode counts as physically three-dimensional if its non-planarity sigma_min/sigma_max
#: exceeds this: a planar mode measures at round-off (< ROUND_OFF), and 1e-3 is 0.1 % of the
#: mode's amplitude out of its best plane, ~10 digits above what the solvers resolve.
NON_PLANAR = 1e-3
#: |beta_k L - (n -+ 1) pi| at a crossing by mpmath with DPS digits (measured 6e-30).
RESONANCE_EXACT = 1e-15
#: 2 pi - (beta2 - beta1) at the largest twist checked (Omega ~ 127): the asymptotic gap
#: (pi lambda delta / Omega^3) |sin Omega| is ~1e-5 there; 1e-4 is "tends to 2 pi".
GAP_TO_2PI = 1e-4
#: Observed decay orders: predicted -2 for p_inf - p* (-3 where the ripple dominates) and -5 for
#: the 4-term expansion's error; a wrong p_inf would give 0 and an expansion with a wrong term
#: -4 or slower, so the margins are room for the 3-point fits, not for a wrong result.
LIMIT_ORDER, EXPANSION_ORDER = -1.8, -4.5
#: Predicted -3 for beta_k L - (Omega -+ pi) (the Omega^-2 terms cancel) and -4 after the
#: predicted Omega^-3 terms; each threshold is halfway to what a failed prediction would leave.
RESONANCE_ORDER, RESONANCE_REMAINDER_ORDER = -2.5, -3.5
#: Cross-check limits: collocation vs mpmath at the spot twists and at large twist; closed-form
#: window ends vs both solvers; mode shapes; the three determinations of the maxima (loads,
#: twists: a crossing's twist is the load error divided by the branches' slope difference).
SPOT_LIMIT, LARGE_TWIST_LIMIT, WINDOW_LIMIT, SHAPE_LIMIT = 1e-11, 1e-9, 1e-10, 1e-8
MAXIMA_LOAD_LIMIT, MAXIMA_TWIST_LIMIT = 1e-9, 1e-7
#: Non-planarity of the same mode by mpmath and by collocation (relative): the collocation
#: mode is resolved to ~1e-10 and sigma_min is ill-conditioned only at a family crossing.
PLANARITY_LIMIT = 1e-6

# ---- root causes: independent errors of the paper (one line each, shared by their rows) ----
#: What the straight rod's sympy derivation reports when every step was checked.
DERIVATION_COMPLETE = "all steps checked"

ROOT_IMAGINARY_BETA1 = ("β1 is taken real for every twist, but it is imaginary on a window "
                        "around Ω(L) = π, Ω_a < Ω(L) < Ω_b = 2π√(ν/(3ν+1)), whose upper end is "
                        "the maximum of β2 − β1 near π")
ROOT_UNIQUENESS = ("Sec. 1 says Eqs. Munder with constit 'uniquely determine' F_t, ω1, ω2, ω3; "
                   "buckling, the paper's own criterion, is the loss of that uniqueness")
ROOT_P_STAR_TYPO = ("Typo in the definition of the load: p* = P_cr/P_cr (identically 1) for "
                    "p* = P_cr/P_E, P_E = π²A1/L²")

COLLOCATION = Method("Chebyshev collocation (spectral_rod.rod.collocation)", "inst1")
CHARACTERISTIC = Method("characteristic equation in mpmath (spectral_rod.rod.characteristic)",
                        "inst1")
CLOSED_FORM = Method("closed forms and asymptotics (spectral_rod.rod.closed_form)", "closed form")
RITZ = Method("Rayleigh-Ritz on the lab-frame energy (spectral_rod.rod.ritz)", "energy")
SYMPY_ENERGY = Method("sympy: Euler-Lagrange equations of the energy "
                      "(spectral_rod.derivations.straight_rod)", "energy")
SYMPY_MUNDER = Method("sympy: Eqs. Munder with constit linearised about the compressed rod "
                      "(spectral_rod.derivations.straight_rod)", "Munder")
#: Rayleigh-Ritz (energy) must agree with the mpmath characteristic equation (inst1) to this.
RITZ_LIMIT = 1e-11


#: What each row found, as templates with named fields (the report's headline lists them).
FINDINGS = {
    "rod-first-maximum": "The first maximum of p* is a corner (family crossing) at Ω(L) = "
                         "{first_lo} (ν = {nu_lo}) … {first_hi} (ν = {nu_hi}), only a local "
                         "maximum.",
    "rod-further-maxima": "The maxima of p* are where the symmetric and antisymmetric mode "
                          "families cross, at β1 L = (n−1)π and β2 L = (n+1)π exactly: Ω_n = "
                          "nπ + O(n⁻³) (ν = {nu}: {examples}), and there is none near π.",
    "rod-limit": "At large twist p* → p∞ = 2ν/(1+ν), the harmonic mean of the two bending "
                 "stiffnesses, from below ({examples}); p∞ − p* ≈ π²δ²p∞³/(4Ω²), δ = "
                 "(1 − 1/ν)/2.",
    "rod-beta-real": "β1 is imaginary on a window around Ω(L) = π ({examples}); as ν → ∞ the "
                     "window tends to (0, 2π/√3), as ν → 1 to the point π.",
    "rod-beta-difference": "β2 − β1 reaches exactly 2π at every maximum; the one near π is the "
                           "end of the imaginary-β1 window, Ω_b = 2π√(ν/(3ν+1)), {worst} off π "
                           "(→ 2π/√3, {limit} off, as ν → ∞; within {near} only for ν < "
                           "{nu_max:.3f}).",
    "rod-three-dimensional": "The buckling mode is three-dimensional at every twist, but its "
                             "non-planarity exceeds {threshold:g} only on {ranges}; it falls "
                             "like Ω^{small:.1f} as Ω → 0 and Ω^{large:.1f} as Ω → ∞ (planar in "
                             "both limits).",
    "rod-twist-raises-load": "p* is not monotone in the twist: it falls by up to {drop:.1e} "
                             "after the 2π maximum (ν = {nu}), though p* > 1 for every Ω > 0.",
}


#: The evidence texts of the rows: templates with named fields, filled by the rows'
#: measurements (:func:`_evidence`), so a word can change without reading a computation.
EVIDENCE = {
    "rod-zero-twist": (
        "max |p* − 1| = {dev:.1e} (collocation); max |D_sym(π², 0, ν)| = {det:.1e} (mpmath; p* ≥ "
        "1 by the Rayleigh bound, so π² is the lowest root); Euler mode planarity σ_min/σ_max = "
        "{euler_planarity_coll:.1e}, max |x₁ − sin πs| = {euler_shape_mismatch:.1e}."),
    "rod-isotropic": (
        "{int_iso_points} twists in [0, {iso_twist_max:g}]: max |p* − 1| = {iso_max_dev_coll:.1e}"
        " (collocation); max |D_sym(π², Ω, 1)| = {iso_max_det_mp:.1e} (mpmath, {dps} digits)."),
    "rod-stabilising": (
        "min (p* − 1) = {min_excess:.3e} > 0 on {int_pos_sum} twists; min increase between "
        "consecutive ν = {min_step:.3e}; all {len_ev_spot} mpmath spot values > 1: {spot_ok}, "
        "increasing in ν: {spot_mono}. (p* is not monotone in Ω: see rod-further-maxima.)"),
    "rod-first-maximum": (
        "{table}. The three determinations agree to {agree_p_coll_vs_closed:.1e} in p* and "
        "{agree_twist_coll_vs_closed:.1e} in Ω. It is a corner (p* = min of two smooth branches, "
        "slopes of opposite sign, e.g. ν = {detail_nu}: {m15_slopes_mp_m15_left:+.4f} "
        "({m15_left}) / {m15_slopes_mp_m15_right:+.4f} ({m15_right})), not a smooth maximum; p* "
        "rises monotonically before it: {rises}. Only a local maximum: the next one (at "
        "{fmt_pi_min_seconds_4} … {fmt_pi_max_seconds_4}) is higher and p* → 2ν/(1+ν) > p*(Ω₂) "
        "({later_higher_and_below_limit}). Distance from 2π: {min_rel:.1e} … {max_rel:.1e} "
        "relative, {growth}; as ν → ∞ (closed form) Ω₂ → "
        "{fmt_pi_crossing_limit_nu_inf}, {crossing_limit_nu_infinity_2:.2%} off 2π: within the "
        "{near:.0%} standard for every ν."),
    "rod-further-maxima": (
        "ν = {detail_nu}: maxima at {rows}, … (offset ∝ n^{slope:.2f}; asymptotically "
        "π((ν−1)/(ν+1))²/(8n³): at n = {last_n} {predicted:.4e}π predicted, {last_offset:.4e}π "
        "found; the n⁻³ law is asymptotic: at n = {first_n} found/predicted = {ratio_first:.2f});"
        " {others}. All {len_ev_maxima} are corners where the critical mode switches family "
        "({alternating}): {all_corner}; none is smooth (grid maxima at family switches: "
        "{grid_max_at_switch}); mpmath, collocation and closed form agree to "
        "{agree_p_coll_vs_closed:.1e} in p* and {agree_twist_coll_vs_closed:.1e} in Ω; heights "
        "increase towards the limit: {heights_rise}. Largest relative offset |Ω_n − nπ|/(nπ) = "
        "{rel:.1e}; its supremum over all ν is the ν → ∞ limit at n = 2, "
        "{crossing_limit_nu_infinity_2:.2%} (closed form; n = 3: "
        "{crossing_limit_nu_infinity_3:.2%}). There is no maximum near π: p* rises monotonically "
        "up to the 2π crossing for every ν ({no_max_near_pi}); the end sections are aligned at Ω "
        "= nπ, but the maxima are where β_k L = (n ∓ 1)π."),
    "rod-limit": (
        "p∞ = {limits}. p∞ − p* > 0 decays like Ω^{orders_0_0:.2f} … "
        "Ω^{orders_0_1:.2f} (−2 from the smooth deficit a2 = −π²δ²p∞³/4, δ = (1 − 1/ν)/2; steeper"
        " where the −b3|sin Ω|/Ω³ ripple, b3 = π²δp∞², is still comparable, i.e. for Ω ≲ 4/(δp∞),"
        " ν near 1); the 4-term expansion's error like Ω^{orders_4_1:.2f} (expected −5), "
        "{worst4:.1e} at Ω = {om_max:.0f}. The deficit p∞ − p* stays below 1 % / 0.1 % of the "
        "total rise p∞ − 1 beyond Ω = {settle_txt} (ν as listed; collocation grid). Solvers agree"
        " to {agree:.1e}. Limits of p∞ (closed form): 1 as ν → 1 (rod-isotropic), 2 as ν → ∞."),
    "rod-beta-real": (
        "By the closed forms β1 is imaginary on a window around π for every ν > 1: Ω_a < Ω(L) < "
        "Ω_b with Ω_b = 2π√(ν/(3ν+1)) (p* = 4ν/(3ν+1) there) and Ω_a = 2y/√(ν+3), (ν−1) y cos y +"
        " 4 sin y = 0, y ∈ (π/2, π] (p* = 4νy²/(π²(ν+3))). {tab}. Closed forms match p* of both "
        "solvers at the ends to {dev:.1e}; X− at the window centre < 0 by mpmath: {imag_mp}, by "
        "collocation: {imag_coll}. Outside the window both β are real; the mode there is "
        "cosh/sinh(|β1| s) and cos/sin(β2 s). Limits (closed form): as ν → 1 the window shrinks "
        "to the point π; as ν → ∞, Ω_b → 2π/√3 and Ω_a → 0 (y → π/2), so it tends to (0, 2π/√3)."),
    "rod-beta-difference": (
        "Every crossing Ω_n (n ≥ 2, the p* maxima of rod-further-maxima) is a corner maximum of "
        "β2 − β1 ({corner}) with β1 L = (n−1)π, β2 L = (n+1)π exactly (mpmath: to {exact:.0e}), "
        "so β2 − β1 = 2π at every maximum and < 2π between them; e.g. ν = {detail_nu}: "
        "{fmt_pi_detail_0_twist_mp_6}, {fmt_pi_detail_1_twist_mp_6}. The maximum near π is the "
        "upper end of the imaginary-β1 window, Ω_b = 2π√(ν/(3ν+1)) (a cusp: β1 = 0, β2 = 2π "
        "exactly; β2 − β1 = {min_d_b_values:.12f} … {max_d_b_values:.12f}), off π by {b_min:.1%} "
        "(ν = {min_nus}) … {b_rel:.1%} (ν = {max_nus}): outside the {near:.0%} standard of the "
        "other 'at nπ' rows for every ν checked, and within it only for ν < {nu_max:.4f} (closed "
        "form: 4ν/(3ν+1) < (1 + {near:g})²); as ν → ∞, Ω_b → 2π/√3, {limit_rel:.1%} off π. The "
        "maxima at the crossings are within {crossings_rel:.1e} of nπ. No other grid maxima and "
        "never above 2π: {ok_grid}. At Ω = {om_big:.1f}: 2π − (β2 − β1) ≤ {tail:.1e} "
        "(asymptotically (πλδ/Ω³)|sin Ω|, asymptotics.py). So the maxima are all exactly 2π and "
        "the minima rise to it."),
    "rod-resonance": (
        "max_k |β_k L − (Ω ∓ π)| decays like Ω^{max_fits:.2f} … Ω^{min_fits:.2f} (predicted −3: "
        "the Ω⁻² terms cancel), {worst:.1e} at Ω = {max_x_twist_for_x_in_ev_limi:.1f}; the "
        "remainder after the predicted Ω⁻³ terms decays like Ω^{max_fits_pred:.2f} or faster. At "
        "each maximum Ω_n the resonance is exact with nπ for Ω: β_k L = (n ∓ 1)π (to "
        "{at_max:.0e})."),
    "rod-three-dimensional": (
        "{cases}. The two solvers' centrelines agree to {mismatch:.1e}. Euler (Ω = 0): "
        "σ_min/σ_max = {euler_planarity_coll:.1e}, ω2 ≡ 0. (ν = 1 is the exception: the modes are"
        " degenerate and a planar one exists; the perturbed torsion ω3 − ω30 = α' is zero in "
        "every case since α decouples.) The 3-D part weakens with twist: ν = {detail_nu}, Ω = "
        "{decay_values} (∝ Ω^{decay:.2f}, measured; collocation agrees to "
        "{planarity_gap:.1e} relative): at large twist the mode is nearly a planar sine in the "
        "plane of the mid-span section's principal axis. Over the whole range Ω(L) ∈ "
        "[{float_next_iter_rng_values_t:g}, 20π] ({len_next_iter_rng_values_twi} twists per ν, "
        "collocation) the smallest non-planarity is {min_range:.1e} > 0, but it exceeds "
        "{non_planar:g} only for {spans_txt}. Limits (measured orders): ∝ "
        "Ω^{small_orders} as Ω → 0 and Ω^{large_orders} as Ω → ∞ "
        "(ν as listed): planar in both limits; no closed form is derived for the coefficients."),
    "rod-twist-raises-load": (
        "p* > 1 for all Ω > 0 and rises monotonically up to ≈ 2π, but beyond it falls on "
        "{falling_fractions} of the grid (ν as in rod-stabilising); the drop after the"
        " 2π maximum is {drops}. True as a trend (towards p∞ > p*(Ω) for "
        "all Ω), not as monotonicity."),
    "eq-inst1": (
        "Derivations: {derivation_straight_rod} (energy route: E·u₀ = I₁, E·v₀ = I₂ identically; "
        "Munder route: lines 3, 4 = I₁, −I₂). Rayleigh-Ritz on the energy agrees with the inst1 "
        "reference to {ritz:.1e} at {sum_len_v_for_v_in_ev_ritz_v} points. Misprints against "
        "Figure 1 (largest |p* − digitised|): {misprint_fits} — the printed "
        "equation fits the figure; a factor 1 or a flipped sign would be off by O(1) (and the "
        "flipped sign has complex eigenvalues); exchanging the A's is a similarity transformation"
        " (ω₂ → νω₂) with the same p*, so neither Figure 1 nor p* can tell it apart — only the "
        "derivation does."),
    "rod-decoupling": (
        "{derivation_straight_rod}: line 1 of Munder is f' = 0 (the force perturbation is a "
        "constant, a change of the end load), line 2 is A₃α'' = 0 (α linear in s, constant "
        "without end torque), and lines 3, 4 contain neither; so the perturbed torsion ω₃ − ω₃₀ ="
        " α' vanishes at buckling."),
    "rod-end-alignment": (
        "The geometric statement is true (u₀(L) = ±u₀(0) at Ω(L) = kπ: max ||u₀(L)·u₀(0)| − 1| = "
        "{align:.1e} for k ≤ 20), but the maxima are not where the ends align: they sit at Ω_n = "
        "nπ + ({min_offs:.1e} … {max_offs:.1e})π, and there is none at π: p* rises monotonically "
        "through π for every ν ({none_near_pi}). They are where the two mode families cross, with"
        " β₁L = (n−1)π and β₂L = (n+1)π exactly. The conclusion 'maxima near kπ (k ≥ 2)' holds; "
        "the inference that the alignment locates them is unsupported: true, but it does not "
        "explain."),
    "rod-two-mode-interplay": (
        "All {len_ev_maxima} maxima are corners where the lowest symmetric and antisymmetric "
        "modes cross ({corners}), and the critical mode alternates between the two families from "
        "one maximum to the next ({alternates}). The paper's 'two modes' are argued from the two "
        "wavenumbers β₁, β₂; the two modes that actually interplay are the two parity families, "
        "each made of both wavenumbers. Conclusion right, reason imprecise."),
    "eq-unique": (
        "At the critical load the determinant of the linearised equations vanishes: "
        "{cases}. So the straight rod and the buckled mode (any amplitude, "
        "linearised) both satisfy Munder with constit and the hinged boundary conditions: the "
        "solution is not unique at P = P_cr, which is the paper's own buckling criterion (Sec. "
        "2). Four equations for four unknowns make a closed system, not a unique solution."),
    "rod-even-order": (
        "det = {e_polynomial} (β, λ = π²p*, ω = ω30 L, ν; from inst1 with ω_k = c_k e^(iβs)): "
        "degree {e_degree}, odd powers of β: {e_odd_terms}. So β² = X± and each ω_k is a "
        "combination of sin/cos(β_k s) — of sinh/cosh(|β1| s) where X− < 0 (rod-beta-real)."),
    "typo-p-star": (
        "Figure 1's {int_r_points} points span p* = {r_p_min:.4f} … {r_p_max:.4f}; the printed "
        "definition P_cr/P_cr is 1 at every load (range {float_np_ptp_printed:g}). The intended "
        "p* = P_cr/P_E, P_E = π²A1/L² (Euler's load of the untwisted rod about its weaker axis), "
        "is what the figure and inst1 fit (fig1-curves)."),
}


def _evidence(row_id: str, **fields: object) -> str:
    """The evidence text of `row_id` from :data:`EVIDENCE` with its named fields."""
    return EVIDENCE[row_id].format(**fields)


def _finding(row_id: str, **fields: object) -> str:
    return FINDINGS[row_id].format(**fields)


def _fmt_pi(x: float, digits: int = 7) -> str:
    return f"{x / math.pi:.{digits}f}π"


def at_n_pi_tiers(key: str, phrase: str, shape: tuple[Condition, ...]
                  ) -> list[tuple[str, tuple[Condition, ...]]]:
    """The one standard of every "at n π" claim: "holds" if the maxima's relative offset
    numbers[key] from nπ is below :data:`EXACT`, "holds approximately" if below :data:`NEAR`,
    each with the claim's own `shape` conditions (corners, rises, ...)."""
    return [("holds", (*shape, Condition(key, "<", phrase, EXACT))),
            ("holds approximately", (*shape, Condition(key, "<", phrase, NEAR)))]


def crossing_limit_nu_infinity(n: int) -> float:
    """The twist Ω_n of the n-th family crossing as ν → ∞: the closed form of
    asymptotics.crossing_closed_form, Ω_n² = π²[N(ν²+6ν+1) + √(N²(ν²−1)² + M(ν+1)²(3ν+1)(ν+3))]
    / ((3ν+1)(ν+3)), N = n²+1, M = (n²−1)², divided through by ν²: π²(N + √(N² + 3M))/3."""
    big_n, m = n * n + 1.0, (n * n - 1.0) ** 2
    return math.pi * math.sqrt((big_n + math.sqrt(big_n**2 + 3.0 * m)) / 3.0)


def window_end_nu_max(near: float = NEAR) -> float:
    """The largest ν for which the upper end of the imaginary-β1 window, Ω_b = 2π√(ν/(3ν+1)),
    lies within `near` relative of π: 4ν/(3ν+1) < (1 + near)²."""
    q = (1.0 + near) ** 2
    return q / (4.0 - 3.0 * q)


def _maxima_cross_checks(ev: StraightRodEvidence) -> tuple[CrossCheck, ...]:
    """The three determinations of the maxima must back the claims' digits: loads to
    MAXIMA_LOAD_LIMIT, twists to MAXIMA_TWIST_LIMIT (a crossing's twist is ill-conditioned, the
    load error divided by the slope difference of the two branches, ~1e-4 at n = 20). The
    solvers' own agreement to 1e-12 is tested separately (tests/test_two_solvers.py)."""
    a = maxima_agreement(ev)
    return (CrossCheck("maxima p*: mpmath vs closed form", a["p_mp_vs_closed"],
                       MAXIMA_LOAD_LIMIT),
            CrossCheck("maxima p*: collocation vs closed form", a["p_coll_vs_closed"],
                       MAXIMA_LOAD_LIMIT),
            CrossCheck("maxima twist: mpmath vs closed form", a["twist_mp_vs_closed"],
                       MAXIMA_TWIST_LIMIT),
            CrossCheck("maxima twist: collocation vs closed form", a["twist_coll_vs_closed"],
                       MAXIMA_TWIST_LIMIT))


def _ritz_check(ev: StraightRodEvidence, key: str) -> CrossCheck:
    """The energy formulation against the inst1 one at the claim's points."""
    return CrossCheck(f"{key} p*: Rayleigh-Ritz (energy) vs mpmath (inst1)",
                      float(max(ev.ritz[key])), RITZ_LIMIT)


def _spot_cross_check(rows: list[dict[str, float]], name: str, limit: float) -> CrossCheck:
    rel = max(abs(r["p_coll"] - r["p_mp"]) / r["p_mp"] for r in rows)
    return CrossCheck(name, rel, limit)


# ------------------------------------------------------------------------------------------

ZERO_TWIST = ClaimSpec(
    id="rod-zero-twist", section=SECTION + ", after Eq. inst1",
    claim="Without spontaneous twist Eq. inst1 is the classical beam problem: p* = 1 (Euler), "
          "planar mode.",
    test="p*(0, ν) by collocation for ν = " + ", ".join(map(str, NUS)) + "; the characteristic "
         "determinant at λ = π² (Ω = 0); planarity of the collocation mode.",
    methods=(COLLOCATION, CHARACTERISTIC),
    rule=tiered_rule([("holds", (
        Condition("max_dev_coll", "<", "max |p*(0, ν) − 1|", ROUND_OFF),
        Condition("max_det_mp", "<", "max |D_sym(π², 0, ν)|", DET_ZERO),
        Condition("euler_planarity", "<", "the Euler mode's non-planarity", ROUND_OFF)))],
        "fails"),
    figure="claims_mode.png")


def measure_zero_twist(ev: StraightRodEvidence) -> Measured:
    dev = max(abs(r["p_coll"] - 1.0) for r in ev.zero_twist)
    det = max(r["det_sym_euler"] for r in ev.zero_twist)
    euler = ev.modes[0]
    return Measured(
        numbers={"headline": f"p*(0, ν) = 1 to {dev:.0e}; planar Euler mode",
                 "max_dev_coll": dev, "max_det_mp": det,
                 "euler_planarity": euler["planarity_coll"]},
        evidence=_evidence(
                     "rod-zero-twist",
                     dev=dev,
                     det=det,
                     euler_planarity_coll=euler['planarity_coll'],
                     euler_shape_mismatch=euler['shape_mismatch']))


ISOTROPIC = ClaimSpec(
    id="rod-isotropic", section=SECTION + ", para. 'For a circularly symmetric ...'",
    claim="For ν = 1 the Euler load holds for every twist: p* = 1 independent of Ω.",
    test="collocation p*(Ω, 1) on a twist grid; the symmetric characteristic determinant at "
         "λ = π² on the same twists (mpmath); in the fixed-frame form (A) of asymptotics.py the "
         "twist term has coefficient δ = (1 − 1/ν)/2 = 0, so Z'' + π² p Z = 0 exactly.",
    methods=(COLLOCATION, CHARACTERISTIC, CLOSED_FORM),
    rule=tiered_rule([("holds", (
        Condition("max_dev_coll", "<", "max |p*(Ω, 1) − 1| on the grid", ROUND_OFF),
        Condition("max_det_mp", "<", "max |D_sym(π², Ω, 1)| on the grid", DET_ZERO)))],
        "fails"))


def measure_isotropic(ev: StraightRodEvidence) -> Measured:
    iso = ev.isotropic
    return Measured(
        numbers={"headline": f"|p* − 1| ≤ {iso['max_dev_coll']:.0e} for Ω ∈ [0, "
                             f"{iso['twist_max']:g}]", **iso},
        evidence=_evidence(
                     "rod-isotropic",
                     int_iso_points=int(iso['points']),
                     iso_twist_max=iso['twist_max'],
                     iso_max_dev_coll=iso['max_dev_coll'],
                     iso_max_det_mp=iso['max_det_mp'],
                     dps=DPS))


STABILISING = ClaimSpec(
    id="rod-stabilising", section="Sec. 'Conclusions'; " + SECTION,
    claim="Spontaneous twist stabilises the rod (p* ≥ 1, > 1 for Ω > 0 when ν > 1) and the "
          "effect grows with ν.",
    test=f"collocation on the twists in (0, 20π] for ν = {', '.join(map(str, NUS))}: min "
         f"(p* − 1) and min over twists of p*(ν_(k+1)) − p*(ν_k); mpmath spot checks at Ω = "
         f"{', '.join(map(str, SPOT_TWISTS))}. Proof: the Rayleigh quotient ∫(A1 ω1² + A2 ω2²)/"
         "(P_E ∫|x'|²) is ≥ 1 (A2 ≥ A1, Wirtinger) and non-decreasing in A2 for every trial "
         "mode.",
    methods=(COLLOCATION, CHARACTERISTIC, RITZ),
    rule=tiered_rule([("holds", (
        Condition("min_excess", ">", "min over the grid twists Ω > 0 of (p* − 1)", 0.0),
        Condition("min_step_in_nu", ">", "the smallest rise of p* between consecutive ν", 0.0),
        Condition("spot_above_one", "true", "every mpmath spot value is > 1"),
        Condition("spot_increasing_in_nu", "true", "the mpmath spot values increase with ν")))],
        "fails"),
    figure="claims_load.png")


def measure_stabilising(ev: StraightRodEvidence) -> Measured:
    pos = ev.grid > 0
    min_excess = min(float(np.min(ev.p[nu][pos] - 1.0)) for nu in NUS)
    min_step = float(np.min(np.diff(np.array([ev.p[nu][pos] for nu in NUS]), axis=0)))
    spot_ok = all(r["p_mp"] > 1.0 for r in ev.spot)
    spot_mono = all(a["p_mp"] < b["p_mp"] for a in ev.spot for b in ev.spot
                    if a["twist"] == b["twist"] and a["nu"] < b["nu"])
    return Measured(
        numbers={"headline": f"p* − 1 ≥ {min_excess:.1e} for Ω > 0 (grid); p* increasing in ν",
                 "min_excess": min_excess, "min_step_in_nu": min_step,
                 "spot_above_one": spot_ok, "spot_increasing_in_nu": spot_mono},
        evidence=_evidence(
                     "rod-stabilising",
                     min_excess=min_excess,
                     int_pos_sum=int(pos.sum()),
                     min_step=min_step,
                     len_ev_spot=len(ev.spot),
                     spot_ok=spot_ok,
                     spot_mono=spot_mono),
        cross_checks=(_spot_cross_check(ev.spot, "spot p*: collocation vs mpmath", SPOT_LIMIT),
                      _ritz_check(ev, "spot")))


FIRST_MAXIMUM = ClaimSpec(
    id="rod-first-maximum", section=SECTION + ", para. 'For any ν > 1 ...'",
    claim="For ν > 1, p* increases initially with Ω(L) and reaches a maximum at Ω(L) = 2π.",
    test="The maximum is where the lowest symmetric and antisymmetric roots cross, located three "
         "ways: D_sym = D_anti = 0 by 2-D Newton in mpmath (verified lowest in each family by "
         "sign scans); Brent on the difference of the two families' collocation eigenvalues; the "
         "closed form of asymptotics.crossing_closed_form (at a crossing β1 L = (n−1)π, β2 L = "
         "(n+1)π exactly). Slopes dp/dΩ of both branches; p* increasing on the collocation grid "
         "before it.",
    methods=(CHARACTERISTIC, COLLOCATION, CLOSED_FORM, RITZ),
    rule=tiered_rule(at_n_pi_tiers("max_rel_offset", "|Ω₂ − 2π|/(2π)", (
        Condition("rises", "true", "p* rises up to it"),
        Condition("corners", "true", "it is a corner (family crossing)"))), "fails"),
    figure="claims_load.png", related=("rod-further-maxima", "rod-end-alignment"))


def measure_first_maximum(ev: StraightRodEvidence) -> Measured:
    firsts = [ev.maxima_for(nu)[0] for nu in NUS]
    rises = all(rises_until_first_maximum(ev, nu) for nu in NUS)
    corners = all(m.kind == "corner maximum" for m in firsts)
    rel = [abs(m.twist_mp / (2 * math.pi) - 1) for m in firsts]
    agree = maxima_agreement(ev)
    # local, not global: a later maximum is higher, and p* tends to a larger limit
    later_higher = all(ev.maxima_for(nu)[1].p_mp > ev.maxima_for(nu)[0].p_mp for nu in NUS)
    below_limit = all(m.p_mp < large_twist_limit(m.nu) for m in firsts)
    table = "; ".join(f"ν = {m.nu}: Ω₂ = {_fmt_pi(m.twist_mp)} = {m.twist_mp:.9f} "
                      f"(p* = {m.p_mp:.9f})" for m in firsts)
    seconds = [ev.maxima_for(nu)[1].twist_mp for nu in NUS]
    growing = bool(np.all(np.diff(rel) > 0))
    m15 = next(m for m in firsts if m.nu == DETAIL_NU)
    return Measured(
        numbers={"finding": _finding("rod-first-maximum", first_lo=_fmt_pi(firsts[0].twist_mp),
                                     first_hi=_fmt_pi(firsts[-1].twist_mp), nu_lo=firsts[0].nu,
                                     nu_hi=firsts[-1].nu),
                 "headline": f"Ω₂ = {_fmt_pi(firsts[0].twist_mp)} (ν = {firsts[0].nu}) … "
                             f"{_fmt_pi(firsts[-1].twist_mp)} (ν = {firsts[-1].nu}); a corner "
                             "(family crossing), and only a local maximum",
                 "rises": rises, "corners": corners, "max_rel_offset": max(rel),
                 "twist_over_pi": {m.nu: m.twist_mp / math.pi for m in firsts},
                 "p_star": {m.nu: m.p_mp for m in firsts},
                 "twist_over_pi_collocation": {m.nu: m.twist_coll / math.pi for m in firsts},
                 "twist_over_pi_closed_form": {m.nu: m.twist_closed / math.pi for m in firsts},
                 "kind": {m.nu: m.kind for m in firsts}, "agreement": agree,
                 "local_not_global": bool(later_higher and below_limit)},
        evidence=_evidence(
                     "rod-first-maximum",
                     table=table,
                     agree_p_coll_vs_closed=agree['p_coll_vs_closed'],
                     agree_twist_coll_vs_closed=agree['twist_coll_vs_closed'],
                     detail_nu=DETAIL_NU,
                     m15_slopes_mp_m15_left=m15.slopes_mp[m15.left],
                     m15_left=m15.left,
                     m15_slopes_mp_m15_right=m15.slopes_mp[m15.right],
                     m15_right=m15.right,
                     rises=rises,
                     fmt_pi_min_seconds_4=_fmt_pi(min(seconds), 4),
                     fmt_pi_max_seconds_4=_fmt_pi(max(seconds), 4),
                     later_higher_and_below_limit=later_higher and below_limit,
                     min_rel=min(rel),
                     max_rel=max(rel),
                     growth="growing with ν" if growing
                                                   else "not monotone in ν",
                     fmt_pi_crossing_limit_nu_inf=_fmt_pi(crossing_limit_nu_infinity(2), 5),
                     crossing_limit_nu_infinity_2=crossing_limit_nu_infinity(2) / (2 * math.pi) - 1,
                     near=NEAR),
        cross_checks=(*_maxima_cross_checks(ev), _ritz_check(ev, "maxima")))


FURTHER_MAXIMA = ClaimSpec(
    id="rod-further-maxima", section=SECTION + ", para. 'For any ν > 1 ...'",
    claim="Beyond 2π the critical force oscillates, with additional maxima at integer multiples "
          "of π.",
    test="Family crossings near nπ (n = 2…20 for ν = 1.5, n = 2…4 for the other ν) by both "
         "solvers and in closed form (Ω_n² = π²[N(ν²+6ν+1) + √(N²(ν²−1)² + M(ν+1)²(3ν+1)(ν+3))]"
         "/((3ν+1)(ν+3)), N = n²+1, M = (n²−1)², p*_n = 2ν(N − Ω_n²/π²)/(ν+1)); every local "
         "maximum of the dense collocation curve must sit at a family switch; fit of the offset "
         "Ω_n − nπ against n; is there a maximum near π?",
    methods=(CHARACTERISTIC, COLLOCATION, CLOSED_FORM, RITZ),
    rule=tiered_rule(at_n_pi_tiers("max_relative_offset", "max |Ω_n − nπ|/(nπ)", (
        Condition("all_corners", "true", "every maximum is a family-crossing corner"),
        Condition("grid_maxima_at_switches", "true",
                  "every grid maximum sits at a family switch"))), "fails"),
    figure="claims_load.png", related=("rod-first-maximum", "rod-end-alignment",
                                       "rod-two-mode-interplay"))


def measure_further_maxima(ev: StraightRodEvidence) -> Measured:
    detail = ev.maxima_for(DETAIL_NU)
    all_corner = all(m.kind == "corner maximum" for m in ev.maxima)
    rel = max(abs(m.offset) / m.n for m in ev.maxima)
    heights_rise = all(b.p_mp > a.p_mp for nu in NUS
                       for a, b in zip(ev.maxima_for(nu)[:-1], ev.maxima_for(nu)[1:],
                                       strict=True))
    # offset scaling (Omega_n - n pi) ~ C n^-3 for the detailed nu
    ns = np.array([m.n for m in detail], dtype=float)
    offs = np.array([m.offset for m in detail])
    slope = observed_order(ns[-8:], offs[-8:])
    last = detail[-1]
    predicted = (crossing_twist_asymptotic(last.n, DETAIL_NU) - last.n * math.pi) / math.pi
    first = detail[0]
    ratio_first = first.offset / ((crossing_twist_asymptotic(first.n, DETAIL_NU)
                                   - first.n * math.pi) / math.pi)
    no_max_near_pi = all(rises_until_first_maximum(ev, nu) for nu in NUS)
    gaps = []
    for nu in NUS:
        sw = critical_family_switches(ev, nu)
        for om in local_maxima(ev.grid, ev.p[nu]):
            gaps.append(float(np.min(np.abs(sw - om))) if sw.size else math.inf)
    grid_max_at_switch = max(gaps) <= 1.01 * float(ev.grid[1] - ev.grid[0])
    agree = maxima_agreement(ev)
    alternating = ("alternately symmetric/antisymmetric" if _families_alternate(ev)
                   else "not alternating between the families")
    rows = ", ".join(f"{m.n}π{m.offset:+.2e}π" for m in detail[:6])
    others = "; ".join(f"ν = {nu}: " + ", ".join(f"{_fmt_pi(m.twist_mp, 6)}"
                                                for m in ev.maxima_for(nu))
                       for nu in NUS if nu != DETAIL_NU)
    return Measured(
        numbers={"finding": _finding("rod-further-maxima", nu=DETAIL_NU, examples=", ".join(
                     _fmt_pi(m.twist_mp, 6) for m in detail[:3])),
                 "headline": f"corners at Ω_n = nπ + O(n⁻³) (ν = {DETAIL_NU}: "
                             f"{_fmt_pi(detail[1].twist_mp, 6)}, {_fmt_pi(detail[2].twist_mp, 6)})"
                             ", closed form; none near π",
                 "detail_nu": DETAIL_NU, "grid_maxima_at_switches": grid_max_at_switch,
                 "twist_over_pi": {m.n: m.twist_mp / math.pi for m in detail},
                 "offset_exponent": slope, "max_relative_offset": rel,
                 "offset_last_found": last.offset, "offset_last_predicted": predicted,
                 "offset_ratio_first": ratio_first,
                 "maximum_near_pi": not no_max_near_pi, "all_corners": all_corner,
                 "heights_rise": heights_rise, "agreement": agree},
        evidence=_evidence(
                     "rod-further-maxima",
                     detail_nu=DETAIL_NU,
                     rows=rows,
                     slope=slope,
                     last_n=last.n,
                     predicted=predicted,
                     last_offset=last.offset,
                     first_n=first.n,
                     ratio_first=ratio_first,
                     others=others,
                     len_ev_maxima=len(ev.maxima),
                     alternating=alternating,
                     all_corner=all_corner,
                     grid_max_at_switch=grid_max_at_switch,
                     agree_p_coll_vs_closed=agree['p_coll_vs_closed'],
                     agree_twist_coll_vs_closed=agree['twist_coll_vs_closed'],
                     heights_rise=heights_rise,
                     rel=rel,
                     crossing_limit_nu_infinity_2=crossing_limit_nu_infinity(2) / (2 * math.pi) - 1,
                     crossing_limit_nu_infinity_3=crossing_limit_nu_infinity(3) / (3 * math.pi) - 1,
                     no_max_near_pi=no_max_near_pi),
        cross_checks=(*_maxima_cross_checks(ev), _ritz_check(ev, "maxima")))


LIMIT = ClaimSpec(
    id="rod-limit", section=SECTION + ", para. 'For any ν > 1 ...'",
    claim="At large twist p* tends to some limiting value which depends on ν.",
    test="Closed form from the averaged compliance (derivation in "
         "spectral_rod/rod/closed_form.py): "
         "p∞ = 2ν/(1+ν); expansion p* = p∞ + a2/Ω² − b3|sin Ω|/Ω³ + a4/Ω⁴ + O(Ω⁻⁵). Compared "
         f"with p* from both solvers at Ω = π/2 + 2πj, j = {LIMIT_J}; observed decay order of "
         "p* − p∞ and of the expansion error.",
    methods=(CHARACTERISTIC, COLLOCATION, CLOSED_FORM, RITZ),
    # predicted orders −2 (−3 where the ripple dominates) and −5; a wrong p∞ would give 0 and an
    # expansion with a wrong term −4 or slower, so the margins 0.2 and 0.5 are room for the
    # 3-point fits (the next term is O(1/Ω) relative at Ω ≥ 33), not for a wrong result
    rule=tiered_rule([("holds", (
        Condition("slowest_order_p_minus_limit", "<",
                  "the slowest observed decay order of p∞ − p* over ν", LIMIT_ORDER),
        Condition("slowest_order_expansion_error", "<",
                  "that of the 4-term expansion's error", EXPANSION_ORDER)))], "fails"),
    figure="claims_load.png")


def measure_limit(ev: StraightRodEvidence) -> Measured:
    rows = ev.limit
    orders = {}
    for k in (0, 4):
        fits = []
        for nu in NUS:
            r = [x for x in rows if x["nu"] == nu]
            om = np.array([x["twist"] for x in r])
            err = np.array([x[f"err{k}"] for x in r])
            fits.append(observed_order(om, err))
        orders[k] = (min(fits), max(fits))
    om_max = max(x["twist"] for x in rows)
    worst4 = max(abs(x["err4"]) for x in rows if x["twist"] == om_max)
    c = {nu: large_twist_coefficients(nu) for nu in NUS}
    settle = {nu: (settling_twist(ev, nu, 1e-2), settling_twist(ev, nu, 1e-3)) for nu in NUS}
    settle_txt = ", ".join(f"{a / math.pi:.1f}π / " + (f"{b / math.pi:.1f}π" if b else "> 20π")
                           for a, b in settle.values())
    agree = max(abs(x["p_coll"] - x["p_mp"]) for x in rows)
    return Measured(
        numbers={"finding": _finding("rod-limit", examples=", ".join(
                     f"{large_twist_limit(nu):.4f} at ν = {nu}" for nu in NUS)),
                 "slowest_order_p_minus_limit": orders[0][1],
                 "slowest_order_expansion_error": orders[4][1],
                 "headline": "p∞ = 2ν/(1+ν) (harmonic mean of A1, A2); p∞ − p* ≈ "
                             "π²δ²p∞³/(4Ω²) + π²δp∞²|sin Ω|/Ω³",
                 "p_inf": {nu: large_twist_limit(nu) for nu in NUS},
                 "a2": {nu: c[nu].a2 for nu in NUS}, "b3": {nu: c[nu].b3 for nu in NUS},
                 "a4": {nu: c[nu].a4 for nu in NUS},
                 "observed_order_p_minus_limit": orders[0],
                 "observed_order_expansion_error": orders[4],
                 "settling_twist_1pct_0p1pct": settle, "max_solver_gap": agree},
        evidence=_evidence(
                     "rod-limit",
                     limits=", ".join(f"{large_twist_limit(nu):.6f} (ν = {nu})" for nu in NUS),
                     orders_0_0=orders[0][0],
                     orders_0_1=orders[0][1],
                     orders_4_1=orders[4][1],
                     worst4=worst4,
                     om_max=om_max,
                     settle_txt=settle_txt,
                     agree=agree),
        cross_checks=(_spot_cross_check(rows, "large-twist p*: collocation vs mpmath",
                                        LARGE_TWIST_LIMIT),
                      _ritz_check(ev, "limit")))


WAVENUMBERS_REAL = ClaimSpec(
    id="rod-beta-real", section=SECTION + ", para. 'In the general case ...'",
    claim="β1 and β2 are the positive roots of a characteristic equation (both real).",
    test="β² = X± are roots of (λ − Ω² − X)(λ/ν − Ω² − X) = 4Ω²X; X− < 0 (β1 imaginary) iff "
         "λ/ν < Ω² < λ. Window ends where X− = 0 along p*(Ω): closed forms (asymptotics.py) "
         "checked against p* from both solvers at the ends, X− at the window centre from both.",
    methods=(CLOSED_FORM, CHARACTERISTIC, COLLOCATION),
    rule=tiered_rule([
        ("fails", (Condition("imaginary_at_centre", "true", "both solvers find β1² = X− < 0 at "
                             "the centre of the closed-form window for every ν"),
                   Condition("symmetric_at_ends", "true", "the symmetric family is critical at "
                             "both ends (the closed form's premise)"))),
        ("holds", (Condition("real_at_centre", "true",
                             "both find X− ≥ 0 there for every ν"),))],
        "inconclusive", note="the ν or the solvers disagree, or the window's premise is not met"),
    figure="claims_wavenumbers.png", related=("rod-beta-difference",),
    root_cause=ROOT_IMAGINARY_BETA1)


def measure_wavenumbers_real(ev: StraightRodEvidence) -> Measured:
    w = ev.windows
    dev = max(max(r["dev_a"], r["dev_b"]) for r in w)
    sym_ends = all(r["family_a"] == r["family_b"] == "symmetric" for r in w)
    imag_mp = all(r["x_minus_mid_mp"] < 0 for r in w)
    imag_coll = all(r["x_minus_mid_coll"] < 0 for r in w)
    real = all(r["x_minus_mid_mp"] >= 0 and r["x_minus_mid_coll"] >= 0 for r in w)
    tab = "; ".join(f"ν = {r['nu']}: ({r['omega_a']:.6f}, {r['omega_b']:.6f}) = "
                    f"({_fmt_pi(r['omega_a'], 4)}, {_fmt_pi(r['omega_b'], 4)})" for r in w)
    return Measured(
        numbers={"finding": _finding("rod-beta-real", examples="; ".join(
                     f"ν = {r['nu']}: {_fmt_pi(r['omega_a'], 4)} … {_fmt_pi(r['omega_b'], 4)}"
                     for r in (w[0], w[-1]))),
                 "headline": "β1 imaginary for 2y/√(ν+3) < Ω < 2π√(ν/(3ν+1)), "
                             "(ν−1) y cos y + 4 sin y = 0 (e.g. ν = 1.5: "
                             f"{_fmt_pi(w[1]['omega_a'], 4)} … {_fmt_pi(w[1]['omega_b'], 4)})",
                 "imaginary_at_centre": imag_mp and imag_coll, "real_at_centre": real,
                 "symmetric_at_ends": sym_ends,
                 "windows": [{k: r[k] for k in ("nu", "omega_a", "omega_b", "p_a", "p_b")}
                             for r in w],
                 "max_closed_form_dev": dev},
        evidence=_evidence(
                     "rod-beta-real",
                     tab=tab,
                     dev=dev,
                     imag_mp=imag_mp,
                     imag_coll=imag_coll),
        cross_checks=(CrossCheck("window ends: closed form vs both solvers", dev, WINDOW_LIMIT),
                      CrossCheck("sign of X− at the window centre: mpmath vs collocation",
                                 float(imag_mp != imag_coll), 0.0)))


BETA_DIFFERENCE = ClaimSpec(
    id="rod-beta-difference", section=SECTION + ", para. 'To understand the origin ...'",
    claim="β2 − β1 oscillates with Ω(L), with maxima at integer multiples of π, and tends to 2π.",
    test="Re(β2 − β1) L along p*(Ω) (β1 imaginary in the window counts as Re β1 = 0); its slopes "
         "along both family branches at each crossing (mpmath); β_k L there against (n ∓ 1)π "
         "(the crossing theorem in asymptotics.py); its local maxima and its largest value on "
         "the dense collocation curve; its value at the largest twist checked.",
    methods=(CHARACTERISTIC, COLLOCATION, CLOSED_FORM),
    rule=tiered_rule(at_n_pi_tiers(
        "max_relative_offset", "max |Ω_max − nπ|/(nπ) over its maxima (n ≥ 1)", (
            Condition("corner_maxima_at_crossings", "true",
                      "every crossing is a corner maximum of β2 − β1"),
            Condition("resonance_gap_at_maxima", "<", "max |β_k L − (n ∓ 1)π| there",
                      RESONANCE_EXACT),
            Condition("grid_maxima_accounted", "true",
                      "no other grid maxima and never above 2π"),
            Condition("gap_to_2pi_at_large_twist", "<",
                      "2π − (β2 − β1) at the largest twist", GAP_TO_2PI))), "fails"),
    figure="claims_wavenumbers.png", related=("rod-further-maxima", "rod-resonance",
                                              "rod-beta-real"),
    root_cause=ROOT_IMAGINARY_BETA1)


def measure_beta_difference(ev: StraightRodEvidence) -> Measured:
    detail = ev.maxima_for(DETAIL_NU)
    corner = all(m.dbeta_slopes[m.left] > 0 > m.dbeta_slopes[m.right] for m in ev.maxima)
    exact = max(m.resonance_gap_mp for m in ev.maxima)
    w = {r["nu"]: r for r in ev.windows}
    d_b = {nu: beta_difference(w[nu]["p_b_mp"], w[nu]["omega_b"], nu) for nu in NUS}
    ok_grid = True
    step = float(ev.grid[1] - ev.grid[0])
    for nu in NUS:
        d = beta_difference(ev.p[nu], ev.grid, nu)
        marks = np.array([m.twist_mp for m in ev.maxima_for(nu)] + [w[nu]["omega_b"]])
        sw = critical_family_switches(ev, nu)
        for om in local_maxima(ev.grid, d):
            near = min(np.min(np.abs(marks - om)),
                       np.min(np.abs(sw - om)) if sw.size else math.inf)
            ok_grid &= bool(near <= 1.01 * step)
        ok_grid &= bool(np.all(d <= 2 * math.pi + 1e-9))
    om_big = max(y["twist"] for y in ev.limit)
    tail = max(abs(2 * math.pi - beta_difference(x["p_mp"], x["twist"], x["nu"]))
               for x in ev.limit if x["twist"] == om_big)
    b_rel = max(abs(w[nu]["omega_b"] / math.pi - 1) for nu in NUS)
    b_min = min(abs(w[nu]["omega_b"] / math.pi - 1) for nu in NUS)
    crossings_rel = max(abs(m.offset) / m.n for m in ev.maxima)
    rel = max(b_rel, crossings_rel)
    limit_rel = 2.0 / math.sqrt(3.0) - 1.0  # Omega_b / pi -> 2/sqrt(3) as nu -> infinity
    nu_max = window_end_nu_max()
    return Measured(
        numbers={"finding": _finding("rod-beta-difference", worst=f"{b_min:.1%} … {b_rel:.1%}",
                                     limit=f"{limit_rel:.1%}", near=f"{NEAR:.0%}",
                                     nu_max=nu_max),
                 "max_relative_offset": rel, "offset_near_pi": {
                     nu: w[nu]["omega_b"] / math.pi - 1 for nu in NUS},
                 "max_relative_offset_crossings": crossings_rel,
                 "offset_near_pi_limit_nu_infinity": limit_rel,
                 "nu_max_within_near": nu_max,
                 "headline": "maxima exactly 2π, at the p* maxima Ω_n (n ≥ 2) and at Ω_b "
                             f"(up to {b_rel:.0%} above π); 2π − O(Ω⁻³) between",
                 "corner_maxima_at_crossings": corner, "resonance_gap_at_maxima": exact,
                 "grid_maxima_accounted": ok_grid,
                 "omega_b_over_pi": {nu: w[nu]["omega_b"] / math.pi for nu in NUS},
                 "gap_to_2pi_at_large_twist": tail},
        evidence=_evidence(
                     "rod-beta-difference",
                     corner=corner,
                     exact=exact,
                     detail_nu=DETAIL_NU,
                     fmt_pi_detail_0_twist_mp_6=_fmt_pi(detail[0].twist_mp, 6),
                     fmt_pi_detail_1_twist_mp_6=_fmt_pi(detail[1].twist_mp, 6),
                     min_d_b_values=min(d_b.values()),
                     max_d_b_values=max(d_b.values()),
                     b_min=b_min,
                     min_nus=min(NUS),
                     b_rel=b_rel,
                     max_nus=max(NUS),
                     near=NEAR,
                     nu_max=nu_max,
                     limit_rel=limit_rel,
                     crossings_rel=crossings_rel,
                     ok_grid=ok_grid,
                     om_big=om_big,
                     tail=tail),
        cross_checks=_maxima_cross_checks(ev))


RESONANCE = ClaimSpec(
    id="rod-resonance", section=SECTION + ", para. 'To understand the origin ...'",
    claim="At large twist the wavenumbers approach the resonance β_k L → Ω(L) ± π.",
    test=f"β1 L, β2 L at the mpmath p* for Ω = π/2 + 2πj, j = {LIMIT_J}; decay order of max_k "
         "|β_k L − (Ω ∓ π)| and of the deviation from the O(Ω⁻³) prediction of "
         "asymptotics.large_twist_wavenumbers; β_k L at the maxima (crossings).",
    methods=(CHARACTERISTIC, CLOSED_FORM),
    # predicted orders −3 (the Ω⁻² terms cancel) and −4; each threshold is halfway to the order a
    # failed prediction would leave (−2 without the cancellation, −3 with wrong Ω⁻³ terms)
    rule=tiered_rule([("holds", (
        Condition("slowest_decay_order", "<",
                  "the slowest observed decay order of max_k |β_k L − (Ω ∓ π)| over ν",
                  RESONANCE_ORDER),
        Condition("slowest_decay_order_after_prediction", "<",
                  "that of the remainder after the predicted Ω⁻³ terms",
                  RESONANCE_REMAINDER_ORDER)))], "fails"),
    figure="claims_wavenumbers.png", related=("rod-beta-difference",))


def measure_resonance(ev: StraightRodEvidence) -> Measured:
    devs: dict[float, list[tuple[float, float, float]]] = {}
    for x in ev.limit:
        b1, b2 = critical_wavenumbers(x["p_mp"], x["twist"], x["nu"])
        a1, a2 = large_twist_wavenumbers(x["twist"], x["nu"])
        devs.setdefault(x["nu"], []).append(
            (x["twist"], max(abs(b1 - (x["twist"] - math.pi)), abs(b2 - (x["twist"] + math.pi))),
             max(abs(b1 - a1), abs(b2 - a2))))

    def order(k: int) -> list[float]:
        return [observed_order([r[0] for r in rows], [r[k] for r in rows])
                for rows in devs.values()]

    fits, fits_pred = order(1), order(2)
    worst = max(r[1] for rows in devs.values() for r in rows
                if r[0] == max(q[0] for q in rows))
    at_max = max(m.resonance_gap_mp for m in ev.maxima)
    return Measured(
        numbers={"headline": "β_k L − (Ω ∓ π) = O(Ω⁻³); exactly (n ∓ 1)π at the maxima Ω_n",
                 "slowest_decay_order": max(fits),
                 "slowest_decay_order_after_prediction": max(fits_pred),
                 "decay_order": fits, "decay_order_after_prediction": fits_pred,
                 "largest_twist_deviation": worst},
        evidence=_evidence(
                     "rod-resonance",
                     max_fits=max(fits),
                     min_fits=min(fits),
                     worst=worst,
                     max_x_twist_for_x_in_ev_limi=max(x['twist'] for x in ev.limit),
                     max_fits_pred=max(fits_pred),
                     at_max=at_max))


THREE_DIMENSIONAL = ClaimSpec(
    id="rod-three-dimensional", section=SECTION + ", para. 'Note that at the point ...'",
    claim="At the instability all generalised torsions are non-zero: unlike Euler's planar mode, "
          "buckling of a twisted rod is intrinsically three-dimensional.",
    test="Centreline x(s) = R(Ωs)(ξ, η) of the critical mode from the closed-form solution of "
         "the characteristic equation and from collocation (integrating x'' = R ω); "
         "non-planarity σ_min/σ_max of the samples (x1, x2) (0 iff the centreline lies in a "
         "plane through the axis); ratio of the curvature amplitudes. Proof for ν > 1, Ω ≠ 0: a "
         "planar mode Z = c f(s) in Eq. (A) of asymptotics.py would need e^{2iΩs} c̄/c real for "
         "all s.",
    methods=(CHARACTERISTIC, COLLOCATION, CLOSED_FORM),
    # a "for all Ω" claim: judged over the scene's whole twist range, for every ν
    rule=tiered_rule([
        ("holds", (Condition("min_non_planarity_over_range", ">", "the critical mode's "
                             "non-planarity over Ω(L) ∈ [0.01, 20π], every ν,", NON_PLANAR),
                   Condition("euler_non_planarity", "<", "the Euler mode's", ROUND_OFF))),
        ("holds approximately", (
            Condition("min_non_planarity_over_range", ">", "that non-planarity", ROUND_OFF),
            Condition("euler_non_planarity", "<", "the Euler mode's", ROUND_OFF)))],
        "fails", note="three-dimensional at every twist, but physically so only where the "
                      "non-planarity exceeds the threshold"),
    figure="claims_mode.png", related=("intro-three-dimensional",))


def _order_or_nan(x: NDArray[np.float64], values: NDArray[np.float64]) -> float:
    """The observed order of `values` against `x`; NaN if a value is zero (a planar mode has no
    power law, and the verdict then rests on the zero itself)."""
    return observed_order(x, values) if np.all(np.asarray(values) > 0) else math.nan


def three_dimensional_span(twist: NDArray[np.float64], values: NDArray[np.float64]
                           ) -> tuple[float | None, float | None]:
    """The smallest and largest grid twist whose non-planarity exceeds :data:`NON_PLANAR`
    ((None, None) if none does)."""
    above = np.flatnonzero(np.asarray(values) > NON_PLANAR)
    if above.size == 0:
        return None, None
    return float(twist[above[0]]), float(twist[above[-1]])


def measure_three_dimensional(ev: StraightRodEvidence) -> Measured:
    twisted = [m for m in ev.modes if m["twist"] != 0.0]
    euler = ev.modes[0]
    min_plan = min(min(m["planarity_coll"], m["planarity_mp"]) for m in twisted)
    min_ratio = min(m["omega2_over_omega1"] for m in twisted)
    mismatch = max(m["shape_mismatch"] for m in twisted)
    dec = ev.planarity_decay
    decay = observed_order([r["twist"] for r in dec], [r["planarity_mp"] for r in dec])
    planarity_gap = max(abs(r["planarity_coll"] / r["planarity_mp"] - 1) for r in dec)
    rng = ev.planarity_range
    min_range = min(float(np.min(r["non_planarity"])) for r in rng.values())
    spans = {nu: three_dimensional_span(r["twist"], r["non_planarity"]) for nu, r in rng.items()}
    small = {nu: _order_or_nan(r["twist"][:3], r["non_planarity"][:3]) for nu, r in rng.items()}
    large = {nu: _order_or_nan(r["twist"][-3:], r["non_planarity"][-3:])
             for nu, r in rng.items()}
    spans_txt = "; ".join(f"ν = {nu}: " + (f"{a:.3g} < Ω(L) < {b:.3g}" if a is not None
                                           else "nowhere") for nu, (a, b) in spans.items())
    cases = "; ".join(f"Ω = {m['twist']:g}, ν = {m['nu']:g}: σ_min/σ_max = "
                      f"{m['planarity_mp']:.3f} (mpmath) / {m['planarity_coll']:.3f} "
                      f"(collocation), max|ω2|/max|ω1| = {m['omega2_over_omega1']:.3f}"
                      for m in twisted)
    return Measured(
        numbers={"finding": _finding("rod-three-dimensional", threshold=NON_PLANAR,
                                     ranges=spans_txt, small=float(np.median(list(
                                         small.values()))), large=float(np.median(list(
                                             large.values())))),
                 "min_non_planarity_over_range": min_range,
                 "three_dimensional_span": {nu: list(v) for nu, v in spans.items()},
                 "small_twist_order": small, "large_twist_order": large,
                 "non_planarity_solver_gap": planarity_gap,
                 "headline": f"non-planar at every twist, > {NON_PLANAR:g} only on a band of "
                             f"twists; ∝ Ω^{decay:.1f} at large twist",
                 "min_non_planarity": min_plan, "min_omega2_over_omega1": min_ratio,
                 "euler_non_planarity": euler["planarity_coll"],
                 "decay_positive": all(r["planarity_mp"] > 0 for r in dec),
                 "solver_shape_mismatch": mismatch, "non_planarity_decay_order": decay,
                 "non_planarity_vs_twist": {r["twist"]: r["planarity_mp"] for r in dec}},
        evidence=_evidence(
                     "rod-three-dimensional",
                     cases=cases,
                     mismatch=mismatch,
                     euler_planarity_coll=euler['planarity_coll'],
                     detail_nu=DETAIL_NU,
                     decay_values=", ".join(f"{r['twist']:g}: {r['planarity_mp']:.2e}"
                                            for r in dec),
                     decay=decay,
                     planarity_gap=planarity_gap,
                     float_next_iter_rng_values_t=float(next(iter(rng.values()))['twist'][0]),
                     len_next_iter_rng_values_twi=len(next(iter(rng.values()))['twist']),
                     min_range=min_range,
                     non_planar=NON_PLANAR,
                     spans_txt=spans_txt,
                     small_orders="/".join(f"{v:.2f}" for v in small.values()),
                     large_orders="/".join(f"{v:.2f}" for v in large.values())),
        cross_checks=(CrossCheck("mode shape: collocation vs closed form", mismatch, SHAPE_LIMIT),
                      CrossCheck("non-planarity: collocation vs mpmath (relative)",
                                 planarity_gap, PLANARITY_LIMIT)))


TWIST_RAISES_LOAD = ClaimSpec(
    id="rod-twist-raises-load", section="Sec. 'Conclusions'",
    claim="An increase in the spontaneous twist angle leads to the growth of the critical force.",
    test="Sign of dp*/dΩ on the dense collocation grid in [0, 20π]; the largest fall of p* after "
         "the first maximum (between the crossings near 2π and 3π).",
    methods=(COLLOCATION, CHARACTERISTIC, RITZ),
    rule=tiered_rule([
        ("holds", (Condition("always_above_one", "true", "p* > 1 for Ω > 0"),
                   Condition("max_drop_after_first_max", "<=", "the largest fall of p*", 0.0))),
        ("holds approximately", (Condition("always_above_one", "true", "p* > 1 for Ω > 0"),))],
        "fails", note="true as a trend, not as monotonicity, if p* falls somewhere"),
    figure="claims_load.png", related=("rod-stabilising", "rod-further-maxima"))


def measure_monotone_growth(ev: StraightRodEvidence) -> Measured:
    drops, fracs = {}, {}
    for nu in NUS:
        m = ev.maxima_for(nu)
        sel = (ev.grid > m[0].twist_mp) & (ev.grid < m[1].twist_mp)
        drops[nu] = m[0].p_mp - float(np.min(ev.p[nu][sel]))
        fracs[nu] = float(np.mean(np.diff(ev.p[nu]) < 0))
    always_above = all(float(np.min(ev.p[nu][1:])) > 1 for nu in NUS)
    return Measured(
        numbers={"finding": _finding("rod-twist-raises-load", drop=max(drops.values()),
                                     nu=max(drops, key=drops.get)),
                 "headline": "p* > 1 but not monotone: falls by up to "
                             f"{max(drops.values()):.1e} after the 2π maximum",
                 "always_above_one": always_above, "max_drop_after_first_max":
                 max(drops.values()), "drop_after_first_max": drops,
                 "fraction_decreasing": fracs},
        evidence=_evidence(
                     "rod-twist-raises-load",
                     falling_fractions=", ".join(f"{100 * fracs[nu]:.0f} %" for nu in NUS),
                     drops=", ".join(f"{drops[nu]:.2e}" for nu in NUS)),
        cross_checks=(_ritz_check(ev, "maxima"),))


INST1 = ClaimSpec(
    id="eq-inst1", section=SECTION + ", Eq. inst1",
    claim="Eq. inst1 governs bending of the hinged, spontaneously twisted, compressed rod (with "
          "the geometric relations x'' = R(Ω) ω and hinged ends x = x'' = 0).",
    test="(a) sympy: the Euler-Lagrange equations of the energy ½A₁ω₁² + ½A₂ω₂² − (P/2)|x'|² "
         "in the twisted frame of Eq. frenini, projected on u₀, v₀, are inst1 identically; "
         "(b) sympy: Eqs. Munder with constit linearised about the straight compressed rod give "
         "inst1 as their lines 3 and 4; (c) numbers: Rayleigh-Ritz on the energy (which never "
         "sees inst1) against the mpmath characteristic equation of inst1; (d) the misprints a "
         "reader might suspect (coupling factor 1, one sign flipped, the A's exchanged) against "
         "Figure 1.",
    methods=(SYMPY_ENERGY, SYMPY_MUNDER, RITZ, CHARACTERISTIC),
    rule=tiered_rule([("holds", (Condition("derivation_complete", "true", "both sympy "
                                           "derivations reproduce inst1 exactly"),))], "fails"),
    related=("rod-decoupling", "eq-munder", "fig1-curves"))


def measure_inst1(ev: StraightRodEvidence) -> Measured:
    var = ev.derivation["variants"]
    by = {}
    for r in var:
        by.setdefault(r["variant"], []).append(r)
    worst = {k: max(r["figure_max"] for r in v) for k, v in by.items()}
    change = {k: max(r["max_change"] for r in v) for k, v in by.items()}
    ritz = max(max(v) for v in ev.ritz.values())
    return Measured(
        numbers={"derivation": ev.derivation["straight_rod"],
                 "derivation_complete": ev.derivation["straight_rod"] == DERIVATION_COMPLETE,
                 "variant_figure_max": worst,
                 "variant_max_change": change, "ritz_vs_inst1": ritz},
        evidence=_evidence(
                     "eq-inst1",
                     derivation_straight_rod=ev.derivation['straight_rod'],
                     ritz=ritz,
                     sum_len_v_for_v_in_ev_ritz_v=sum(len(v) for v in ev.ritz.values()),
                     misprint_fits=", ".join(f"{k} {v:.2g}" for k, v in
                                                           worst.items())),
        cross_checks=(CrossCheck("p*: Rayleigh-Ritz (energy) vs inst1", ritz, RITZ_LIMIT),))


DECOUPLING = ClaimSpec(
    id="rod-decoupling", section=SECTION + ", para. 'Substituting these expressions ...'",
    claim="The equations for the perturbation of the longitudinal force and for the rotation α "
          "decouple from the equations for the curvatures ω₁, ω₂.",
    test="sympy: the first-order lines of Eqs. Munder (with constit) about the compressed "
         "twisted rod, with F_t = −P + f: lines 1 and 2 contain no ω and lines 3 and 4 no f, α; "
         "the energy's torsion term gives the same A₃α'' = 0.",
    methods=(SYMPY_MUNDER, SYMPY_ENERGY),
    rule=tiered_rule([("holds", (Condition("derivation_complete", "true",
                                           "the derivation's decoupling checks pass"),))],
                     "fails"),
    related=("eq-inst1",))


def measure_decoupling(ev: StraightRodEvidence) -> Measured:
    return Measured(
        numbers={"derivation": ev.derivation["straight_rod"],
                 "derivation_complete": ev.derivation["straight_rod"] == DERIVATION_COMPLETE},
        evidence=_evidence(
                     "rod-decoupling",
                     derivation_straight_rod=ev.derivation['straight_rod']))


END_ALIGNMENT = ClaimSpec(
    id="rod-end-alignment", section=SECTION + ", para. 'To understand the origin ...'",
    claim="Whenever the total twist is an integer multiple of π the end sections are aligned, "
          "as in the twist-free case (offered alongside the maxima at integer multiples of π).",
    test="Geometry: u₀(L)·u₀(0) = cos Ω(L). As an explanation of the maxima: are the maxima of "
         "p* exactly at kπ, and is there one at every kπ (k ≥ 1)?",
    methods=(CHARACTERISTIC, COLLOCATION, CLOSED_FORM),
    rule=tiered_rule([
        ("holds", (Condition("alignment_error", "<", "max_k ||u₀(L)·u₀(0)| − 1| at Ω(L) = kπ",
                             ROUND_OFF),
                   Condition("max_offset_over_pi", "<", "max |Ω_n/π − n| over the maxima",
                             EXACT),
                   Condition("maximum_near_pi", "true", "there is a maximum at π"))),
        ("true but does not explain", (
            Condition("alignment_error", "<", "max_k ||u₀(L)·u₀(0)| − 1|", ROUND_OFF),))],
        "fails", note="the alignment is the explanation only if it locates the maxima"),
    related=("rod-first-maximum", "rod-further-maxima", "rod-two-mode-interplay"))


def alignment_error(k_max: int = 20) -> float:
    """max over k = 1..k_max of ||u₀(L)·u₀(0)| − 1| at Ω(L) = kπ, with u₀ = cos Ω e₁ + sin Ω e₂
    (the paper's frame): 0 up to round-off iff the end sections are aligned."""
    om = math.pi * np.arange(1, k_max + 1)
    u_l = np.column_stack([np.cos(om), np.sin(om)])
    return float(np.max(np.abs(np.abs(u_l @ np.array([1.0, 0.0])) - 1.0)))


def measure_end_alignment(ev: StraightRodEvidence) -> Measured:
    offs = [abs(m.offset) for m in ev.maxima]
    none_near_pi = all(rises_until_first_maximum(ev, nu) for nu in NUS)
    align = alignment_error()
    return Measured(
        numbers={"max_offset_over_pi": max(offs), "min_offset_over_pi": min(offs),
                 "none_near_pi": none_near_pi, "maximum_near_pi": not none_near_pi,
                 "alignment_error": align},
        evidence=_evidence(
                     "rod-end-alignment",
                     align=align,
                     min_offs=min(offs),
                     max_offs=max(offs),
                     none_near_pi=none_near_pi),
        cross_checks=_maxima_cross_checks(ev))


TWO_MODES = ClaimSpec(
    id="rod-two-mode-interplay", section=SECTION + ", para. 'To understand the origin ...'",
    claim="The oscillatory dependence of the critical force on the twist arises from the "
          "interplay between the two modes.",
    test="Is every maximum of p* a crossing of two modes? The lowest symmetric and "
         "antisymmetric (about mid-span) roots located by both solvers and in closed form; their "
         "slopes at each crossing; the critical family on the dense grid.",
    methods=(CHARACTERISTIC, COLLOCATION, CLOSED_FORM),
    rule=tiered_rule([("holds", (
        Condition("all_corners", "true",
                  "every maximum is a corner where the two mode families cross"),
        Condition("alternates", "true", "the critical family alternates")))], "fails"),
    related=("rod-further-maxima", "rod-beta-difference"))


def _families_alternate(ev: StraightRodEvidence) -> bool:
    """The critical family right of each maximum is the one left of the next (n to n + 1)."""
    return all(a.right == b.left for nu in NUS
               for a, b in zip(ev.maxima_for(nu)[:-1], ev.maxima_for(nu)[1:], strict=True)
               if b.n == a.n + 1)


def measure_two_modes(ev: StraightRodEvidence) -> Measured:
    alternates = _families_alternate(ev)
    corners = all(m.kind == "corner maximum" for m in ev.maxima)
    return Measured(
        numbers={"all_corners": corners, "alternates": alternates},
        evidence=_evidence(
                     "rod-two-mode-interplay",
                     len_ev_maxima=len(ev.maxima),
                     corners=corners,
                     alternates=alternates),
        cross_checks=_maxima_cross_checks(ev))


UNIQUENESS = ClaimSpec(
    id="eq-unique", section="Sec. 'Equilibrium equations', after Eq. Munder",
    claim="Given boundary conditions, Eqs. Munder with constit uniquely determine the four "
          "unknown functions F_t, ω1, ω2, ω3.",
    test="At the critical load the hinged rod's boundary-value problem has the straight "
         "solution and, if the characteristic determinant of inst1 (Munder linearised) vanishes, "
         "a buckled one with the same boundary conditions: |D| at the mpmath p* against |D| at "
         "0.99 p* (Ω = 0 and the modes' twists).",
    methods=(CHARACTERISTIC, SYMPY_MUNDER),
    rule=tiered_rule([("fails", (Condition(
        "det_ratio", "<", "max |D(p*)|/|D(0.99 p*)| (a second solution exists)",
        ROOT_RATIO),))], "holds",
        note="as a count of equations and unknowns the system is closed; as uniqueness it is "
             "what buckling breaks"),
    root_cause=ROOT_UNIQUENESS, related=("eq-munder", "eq-inst1"))


def measure_uniqueness(ev: StraightRodEvidence) -> Measured:
    rows = ev.uniqueness
    ratio = max(r["det_at_critical"] / r["det_below_critical"] for r in rows)
    return Measured(
        numbers={"det_ratio": ratio, "cases": [{k: r[k] for k in ("twist", "nu", "p_star")}
                                               for r in rows]},
        evidence=_evidence(
                     "eq-unique",
                     cases="; ".join(f"Ω = {r['twist']:g}, ν = {r['nu']:g}: |D(p*)| = "
                             f"{r['det_at_critical']:.1e}, |D(0.99 p*)| = "
                             f"{r['det_below_critical']:.1e}" for r in rows)))


EVEN_ORDER = ClaimSpec(
    id="rod-even-order", section=SECTION + ", para. 'In the general case ...'",
    claim="Each of ω1, ω2 obeys a linear fourth-order equation with only even derivatives, so "
          "it is a combination of sin(β_k s) and cos(β_k s).",
    test="sympy: ω_k = c_k e^{iβs} in inst1; the 2 × 2 determinant's polynomial in β "
         "(degree and parity). Whether β_k are real is rod-beta-real's test.",
    methods=(Method("sympy: the characteristic polynomial of inst1 "
                    "(reproduce.claims.evidence.even_order)", "inst1"), CHARACTERISTIC),
    rule=tiered_rule([("holds", (
        Condition("even", "true", "the polynomial in β is even"),
        Condition("degree", ">=", "its degree in β", 4, fmt="d"),
        Condition("degree", "<=", "its degree in β", 4, fmt="d")))], "fails",
        note="the sin/cos form also needs real β_k: see rod-beta-real"),
    one_formulation_why="the statement is about inst1's own structure",
    related=("rod-beta-real", "eq-inst1"))


def measure_even_order(ev: StraightRodEvidence) -> Measured:
    e = ev.even_order
    return Measured(
        numbers={"even": bool(e["even"]), "degree": int(e["degree"]),
                 "odd_terms": int(e["odd_terms"])},
        evidence=_evidence(
                     "rod-even-order",
                     e_polynomial=e['polynomial'],
                     e_degree=e['degree'],
                     e_odd_terms=e['odd_terms']))


P_STAR_TYPO = ClaimSpec(
    id="typo-p-star", section=SECTION + ", para. 'Using standard methods ...'",
    claim="The dimensionless critical force is p* = P_cr/P_cr, P_cr = π²A1/L² the Euler force.",
    test="The printed definition, evaluated at the loads of Figure 1's digitised points, against "
         "the range of p* that Figure 1 shows (the reading p* = P_cr/(π²A1/L²) is what the "
         "figure and inst1 fit: fig1-curves, eq-inst1).",
    methods=(Method("the printed definition evaluated at Figure 1's loads", "paper's figure"),
             COLLOCATION),
    rule=tiered_rule([("fails", (Condition(
        "range_gap", ">", "|range of Figure 1's p* − range of the printed definition|",
        FIGURE1_DOT / FIGURE1_Y_PER_P, fmt=".1e"),))], "holds",
        note="the threshold is one plotted dot of Figure 1"),
    root_cause=ROOT_P_STAR_TYPO, related=("fig1-curves", "rod-zero-twist"))


def measure_p_star_typo(ev: StraightRodEvidence) -> Measured:
    r = ev.figure1_range
    loads = np.array([r["p_min"], r["p_max"]]) * math.pi ** 2  # P_cr in units of A1/L^2
    printed = loads / loads  # the printed definition P_cr / P_cr
    gap = abs((r["p_max"] - r["p_min"]) - float(np.ptp(printed)))
    return Measured(
        numbers={"range_gap": gap, "figure_p_min": r["p_min"], "figure_p_max": r["p_max"]},
        evidence=_evidence(
                     "typo-p-star",
                     int_r_points=int(r['points']),
                     r_p_min=r['p_min'],
                     r_p_max=r['p_max'],
                     float_np_ptp_printed=float(np.ptp(printed))))


#: The straight-rod claims in ledger order: (declaration, measurement).
CLAIMS: tuple[tuple[ClaimSpec, Callable[[StraightRodEvidence], Measured]], ...] = (
    (ZERO_TWIST, measure_zero_twist), (ISOTROPIC, measure_isotropic),
    (STABILISING, measure_stabilising), (TWIST_RAISES_LOAD, measure_monotone_growth),
    (FIRST_MAXIMUM, measure_first_maximum), (FURTHER_MAXIMA, measure_further_maxima),
    (LIMIT, measure_limit), (WAVENUMBERS_REAL, measure_wavenumbers_real),
    (BETA_DIFFERENCE, measure_beta_difference), (RESONANCE, measure_resonance),
    (THREE_DIMENSIONAL, measure_three_dimensional), (INST1, measure_inst1),
    (DECOUPLING, measure_decoupling), (END_ALIGNMENT, measure_end_alignment),
    (TWO_MODES, measure_two_modes), (UNIQUENESS, measure_uniqueness),
    (EVEN_ORDER, measure_even_order), (P_STAR_TYPO, measure_p_star_typo),
)


def evaluate_claims(ev: StraightRodEvidence) -> list[Claim]:
    """Every row of this scene, judged."""
    return evaluate(CLAIMS, ev, SCENE)


def evaluate_claim(claim_id: str, ev: StraightRodEvidence) -> Claim:
    """The one row `claim_id`, judged (e.g. to recompute it after perturbing the evidence)."""
    return evaluate(CLAIMS, ev, SCENE, claim_id)[0]
