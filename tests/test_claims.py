"""The claims scene: every verdict of the straight-rod ledger recomputed, with its key numbers
checked against references that do not come from the number under test."""

from __future__ import annotations

import copy
import itertools
import json
import math

import mpmath as mp
import numpy as np
import pytest

from reproduce import claims as sc
from reproduce.claims import rows
from reproduce.claims.evidence import NUS, solver_agreement
from reproduce.ledger import VERDICTS, Claim, Measured, judge, update_ledger
from spectral_rod import characteristic_critical_load, crossing_closed_form, large_twist_limit


@pytest.fixture(scope="module")
def ev():
    return sc.compute_evidence()


def _claim(claim_id, ev):
    return sc.evaluate_claim(claim_id, ev)


def test_every_claim_has_a_verdict_and_the_expected_one(ev):
    got = {c.id: c.verdict for c in sc.evaluate_claims(ev)}
    assert got == {
        "rod-zero-twist": "holds",
        "rod-isotropic": "holds",
        "rod-stabilising": "holds",
        "rod-twist-raises-load": "holds approximately",
        "rod-first-maximum": "holds approximately",
        "rod-further-maxima": "holds approximately",
        "rod-limit": "holds",
        "rod-beta-real": "fails",
        "rod-beta-difference": "fails",
        "rod-resonance": "holds",
        "rod-three-dimensional": "holds approximately",
        "eq-inst1": "holds",
        "rod-decoupling": "holds",
        "rod-end-alignment": "true but does not explain",
        "rod-two-mode-interplay": "holds",
        "eq-unique": "fails",
        "rod-even-order": "holds",
        "typo-p-star": "fails",
    }


def test_two_solvers_agree_on_every_decisive_load(ev):
    assert solver_agreement(ev) < 1e-11


def test_first_maximum_numbers(ev):
    c = _claim("rod-first-maximum", ev)
    for nu, x in c.numbers["twist_over_pi"].items():
        # closed form (crossing theorem) is an independent third determination
        assert x == pytest.approx(crossing_closed_form(2, nu).twist / math.pi, abs=1e-12)
        assert 2.0 < x < 2.0 + 2 * rows.NEAR
        assert c.numbers["kind"][nu] == "corner maximum"
    assert c.numbers["local_not_global"]
    # the maximum is below the large-twist limit, which is itself never exceeded on the grid
    for nu in NUS:
        assert ev.p[nu].max() < large_twist_limit(nu)


def test_first_maximum_verdict_depends_on_the_corner_and_location(ev):
    broken = copy.deepcopy(ev)
    broken.maxima[0].kind = "corner"  # e.g. if the crossing were on a monotone stretch
    assert _claim("rod-first-maximum", broken).verdict == "fails"
    # moving one solver's maxima breaks the three-way cross-check: no verdict
    moved = copy.deepcopy(ev)
    for m in moved.maxima:
        if m.n == 2:
            m.twist_mp += 0.1 * math.pi
    assert _claim("rod-first-maximum", moved).verdict == "inconclusive"
    # the rule alone: a corner 5 % away from 2 pi is not "at 2 pi"
    measured = rows.measure_first_maximum(ev)
    far = Measured({**measured.numbers, "max_rel_offset": 0.05}, measured.evidence,
                   measured.cross_checks)
    assert judge(rows.FIRST_MAXIMUM, far, "claims").verdict == "fails"
    exact = Measured({**measured.numbers, "max_rel_offset": 0.0}, measured.evidence,
                     measured.cross_checks)
    assert judge(rows.FIRST_MAXIMUM, exact, "claims").verdict == "holds"


def test_further_maxima_numbers(ev):
    c = _claim("rod-further-maxima", ev)
    assert c.numbers["offset_exponent"] == pytest.approx(-3.0, abs=0.1)
    assert not c.numbers["maximum_near_pi"]
    assert c.numbers["all_corners"] and c.numbers["heights_rise"]
    # every maximum n >= 2 lies within 1 % of n pi, above it
    for n, x in c.numbers["twist_over_pi"].items():
        assert 0 < x - n < 1e-2 * n


def test_no_maximum_near_pi_by_mpmath(ev):
    # independent of the collocation grid: p* from the characteristic equation rises through pi
    for nu in (1.1, 10.0):
        p = [float(characteristic_critical_load(om, nu, dps=20).p_star)
             for om in (0.8 * math.pi, 0.95 * math.pi, math.pi, 1.05 * math.pi, 1.2 * math.pi)]
        assert all(b > a for a, b in itertools.pairwise(p))


def test_limit_claim_numbers(ev):
    c = _claim("rod-limit", ev)
    lo, hi = c.numbers["observed_order_p_minus_limit"]
    # between -3 (the |sin|/Omega^3 ripple dominates while Omega < 4/(delta p_inf), nu near 1)
    # and -2 (the smooth Omega^-2 deficit)
    assert -3.1 < lo <= hi < -1.8
    lo4, hi4 = c.numbers["observed_order_expansion_error"]
    assert -5.4 < lo4 <= hi4 < -4.6
    for nu, p_inf in c.numbers["p_inf"].items():
        assert p_inf == pytest.approx(2 * nu / (1 + nu))
    # every large-twist p* lies below its limit, by the two leading terms (sin = 1 here)
    for r in ev.limit:
        gap = r["limit"] - r["p_mp"]
        lead = (abs(c.numbers["a2"][r["nu"]]) / r["twist"] ** 2
                + c.numbers["b3"][r["nu"]] / r["twist"] ** 3)
        assert gap > 0
        assert gap == pytest.approx(lead, rel=20 / r["twist"] ** 2)


def test_beta_real_fails_in_the_window(ev):
    c = _claim("rod-beta-real", ev)
    assert c.verdict == "fails"
    assert c.numbers["max_closed_form_dev"] < 1e-12
    # independent location of the window's upper end: X_- changes sign along the mpmath curve
    nu = 1.5
    w = next(r for r in c.numbers["windows"] if r["nu"] == nu)

    def xm(om):
        return characteristic_critical_load(float(om), nu, dps=30).x_minus

    with mp.workdps(20):
        end = mp.findroot(xm, (w["omega_b"] - 0.05, w["omega_b"] + 0.05), solver="anderson")
    assert float(end) == pytest.approx(w["omega_b"], abs=1e-10)
    # one solver contradicting the other: no verdict (was "holds" before the ledger had
    # cross-checks); both saying beta_1 is real: the claim would hold
    flipped = copy.deepcopy(ev)
    for r in flipped.windows:
        r["x_minus_mid_mp"] = abs(r["x_minus_mid_mp"])
    assert _claim("rod-beta-real", flipped).verdict == "inconclusive"
    for r in flipped.windows:
        r["x_minus_mid_coll"] = abs(r["x_minus_mid_coll"])
    assert _claim("rod-beta-real", flipped).verdict == "holds"
    # the closed form failing its check against the solvers: no verdict either
    off = copy.deepcopy(ev)
    off.windows[0]["dev_a"] = 1e-3
    assert _claim("rod-beta-real", off).verdict == "inconclusive"


def test_beta_difference_is_exactly_two_pi_at_the_maxima(ev):
    c = _claim("rod-beta-difference", ev)
    assert c.numbers["corner_maxima_at_crossings"]
    assert c.numbers["resonance_gap_at_maxima"] < 1e-20
    assert c.numbers["gap_to_2pi_at_large_twist"] < 2e-5
    for nu, x in c.numbers["omega_b_over_pi"].items():
        assert x == pytest.approx(2 * math.sqrt(nu / (3 * nu + 1)), rel=1e-14)


def test_resonance_orders(ev):
    c = _claim("rod-resonance", ev)
    assert all(-3.2 < f < -2.8 for f in c.numbers["decay_order"])
    assert all(f < -3.7 for f in c.numbers["decay_order_after_prediction"])


def test_three_dimensional_mode(ev):
    c = _claim("rod-three-dimensional", ev)
    assert c.numbers["min_non_planarity"] > 1e-3
    assert c.numbers["solver_shape_mismatch"] < 1e-10
    assert c.numbers["non_planarity_decay_order"] == pytest.approx(-2.0, abs=0.3)
    # the mpmath modes (an independent solver) bound the range where it is above 1e-3: at
    # Omega = 48 (nu = 1.5) it is below, at 12 above, so the span ends between them
    dec = {r["twist"]: r["planarity_mp"] for r in ev.planarity_decay}
    assert dec[48.0] < rows.NON_PLANAR < dec[12.0]
    lo, hi = c.numbers["three_dimensional_span"][1.5]
    assert 12.0 < hi < 48.0 and lo < 1.0


def test_three_dimensional_is_judged_over_the_whole_range(ev):
    """The "for all Omega" standard: the verdict moves with the smallest non-planarity over the
    range across NON_PLANAR (holds / holds approximately) and round-off (fails)."""
    assert _claim("rod-three-dimensional", ev).verdict == "holds approximately"
    lifted = copy.deepcopy(ev)
    for r in lifted.planarity_range.values():
        r["non_planarity"] = np.maximum(r["non_planarity"], 2 * rows.NON_PLANAR)
    assert _claim("rod-three-dimensional", lifted).verdict == "holds"
    just_below = copy.deepcopy(lifted)
    just_below.planarity_range[1.5]["non_planarity"][-1] = 0.5 * rows.NON_PLANAR
    assert _claim("rod-three-dimensional", just_below).verdict == "holds approximately"
    planar = copy.deepcopy(ev)
    planar.planarity_range[1.5]["non_planarity"][-1] = 0.0
    assert _claim("rod-three-dimensional", planar).verdict == "fails"


def test_beta_difference_is_judged_by_the_at_n_pi_standard(ev):
    """The maximum near pi (the window's end) is held to the siblings' NEAR standard."""
    c = _claim("rod-beta-difference", ev)
    assert c.verdict == "fails" and c.root_cause == rows.ROOT_IMAGINARY_BETA1
    # the offset near pi from the closed form 2 sqrt(nu/(3nu+1)) - 1, not from the scene
    worst = max(2 * math.sqrt(nu / (3 * nu + 1)) - 1 for nu in NUS)
    assert c.numbers["max_relative_offset"] == pytest.approx(worst, rel=1e-12)
    measured = rows.measure_beta_difference(ev)
    for offset, verdict in ((0.99 * rows.NEAR, "holds approximately"),
                            (1.01 * rows.NEAR, "fails"), (0.5 * rows.EXACT, "holds")):
        moved = Measured({**measured.numbers, "max_relative_offset": offset},
                         measured.evidence, measured.cross_checks)
        assert judge(rows.BETA_DIFFERENCE, moved, "claims").verdict == verdict
    # the largest nu whose window end is within NEAR of pi, by bisection on the closed form
    lo, hi = 1.0, 2.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if 2 * math.sqrt(mid / (3 * mid + 1)) - 1 < rows.NEAR else (lo, mid)
    assert rows.window_end_nu_max() == pytest.approx(lo, rel=1e-12)


def test_isotropic_and_zero_twist_and_stabilising(ev):
    assert ev.isotropic["max_dev_coll"] < 1e-12
    assert _claim("rod-zero-twist", ev).numbers["max_det_mp"] < 1e-25
    c = _claim("rod-stabilising", ev)
    assert c.numbers["min_excess"] > 0 and c.numbers["min_step_in_nu"] > 0
    lowered = copy.deepcopy(ev)
    lowered.p[10.0] = lowered.p[10.0] * 0 + 1.0  # a curve below its neighbour
    assert _claim("rod-stabilising", lowered).verdict == "fails"


def test_twist_raises_load_is_only_a_trend(ev):
    c = _claim("rod-twist-raises-load", ev)
    assert all(d > 1e-4 for d in c.numbers["drop_after_first_max"].values())
    assert all(0.2 < f < 0.5 for f in c.numbers["fraction_decreasing"].values())


def test_ledger_keeps_other_scenes_rows_and_has_the_keys(tmp_path, ev):
    ring = Claim(id="ring-x", section="s", claim="c", test="t", evidence="e", verdict="holds",
                 scene="ring")
    update_ledger(tmp_path, "ring", [ring])
    update_ledger(tmp_path, "claims", sc.evaluate_claims(ev))
    rows = json.loads((tmp_path / "claims.json").read_text())
    assert {r["id"] for r in rows} >= {"ring-x", "rod-first-maximum"}
    for r in rows:
        assert {"id", "section", "claim", "test", "evidence", "verdict"} <= r.keys()
        assert r["verdict"] in VERDICTS
        if r["scene"] == "claims":
            assert r["methods"] and all({"name", "formulation"} <= m.keys() for m in r["methods"])


def test_scene_writes_ledger_figures_and_report(tmp_path, ev, monkeypatch):
    monkeypatch.setattr(sc, "compute_evidence", lambda progress=None: ev)
    out = sc.run(tmp_path, lambda _m: None)
    names = {p.name for p in out.files}
    assert {"claims.json", "claims.md", "claims_load.png", "claims_wavenumbers.png",
            "claims_mode.png"} <= names
    assert out.report.startswith("## Claims")
    assert all((tmp_path / n).stat().st_size > 0 for n in names)
    assert out.details["verdicts"]["rod-beta-real"] == "fails"


def test_further_maxima_offset_matches_its_asymptotics(ev):
    c = _claim("rod-further-maxima", ev)
    assert c.numbers["offset_last_found"] == pytest.approx(c.numbers["offset_last_predicted"],
                                                           rel=1e-2)


@pytest.mark.parametrize("spec_measure", rows.CLAIMS, ids=[s.id for s, _ in rows.CLAIMS])
def test_a_failed_cross_check_makes_the_verdict_inconclusive(ev, spec_measure):
    spec, measure = spec_measure
    measured = measure(ev)
    assert judge(spec, measured, "claims").verdict != "inconclusive"
    for i, check in enumerate(measured.cross_checks):
        broken = list(measured.cross_checks)
        broken[i] = type(check)(check.name, 10 * check.limit + 1e-3, check.limit)
        verdict = judge(spec, Measured(measured.numbers, measured.evidence, tuple(broken)),
                        "claims")
        assert verdict.verdict == "inconclusive" and check.name in verdict.evidence


def test_single_formulation_verdicts_say_so(ev):
    for c in sc.evaluate_claims(ev):
        forms = {m["formulation"] for m in c.methods}
        assert ("one formulation only" in c.evidence) == (len(forms) < 2)


def test_fails_and_approximate_verdicts_rest_on_two_formulations(ev):
    for c in sc.evaluate_claims(ev):
        if c.verdict in ("fails", "holds approximately"):
            assert len({m["formulation"] for m in c.methods}) >= 2, c.id


def test_derivation_failure_makes_inst1_fail(ev):
    broken = copy.deepcopy(ev)
    broken.derivation["straight_rod"] = "a step failed: AssertionError()"
    assert _claim("eq-inst1", broken).verdict == "fails"
    assert _claim("rod-decoupling", broken).verdict == "fails"


def test_ritz_disagreement_makes_the_load_claims_inconclusive(ev):
    broken = copy.deepcopy(ev)
    broken.ritz["spot"][0] = 1e-6  # the energy formulation contradicting inst1 at one point
    assert _claim("rod-stabilising", broken).verdict == "inconclusive"


def test_end_alignment_would_hold_if_maxima_sat_at_k_pi(ev):
    measured = rows.measure_end_alignment(ev)
    assert judge(rows.END_ALIGNMENT, measured, "claims").verdict == "true but does not explain"
    at_k_pi = Measured({**measured.numbers, "max_offset_over_pi": 0.0, "maximum_near_pi": True},
                       measured.evidence, measured.cross_checks)
    assert judge(rows.END_ALIGNMENT, at_k_pi, "claims").verdict == "holds"
    # the maxima just outside EXACT of k pi: the alignment no longer locates them
    near = Measured({**at_k_pi.numbers, "max_offset_over_pi": 2 * rows.EXACT},
                    measured.evidence, measured.cross_checks)
    assert judge(rows.END_ALIGNMENT, near, "claims").verdict == "true but does not explain"
    # the geometric statement itself false (ends not aligned at k pi): fails
    skew = Measured({**measured.numbers, "alignment_error": 0.1}, measured.evidence,
                    measured.cross_checks)
    assert judge(rows.END_ALIGNMENT, skew, "claims").verdict == "fails"
    # the geometry, independently: u0(k pi) = (cos k pi, sin k pi) = (+-1, 0)
    assert measured.numbers["alignment_error"] < 1e-15


def test_uniqueness_fails_where_the_determinant_vanishes(ev):
    c = _claim("eq-unique", ev)
    assert c.verdict == "fails" and c.root_cause == rows.ROOT_UNIQUENESS
    # independently: at Omega = 0 Euler's sin(pi s) solves the hinged problem at P_E besides 0
    assert c.numbers["det_ratio"] < 1e-12
    unique = copy.deepcopy(ev)
    for r in unique.uniqueness:
        r["det_at_critical"] = r["det_below_critical"]
    assert _claim("eq-unique", unique).verdict == "holds"


def test_even_order_and_the_p_star_typo(ev):
    assert _claim("rod-even-order", ev).verdict == "holds"
    odd = copy.deepcopy(ev)
    odd.even_order["even"] = False
    assert _claim("rod-even-order", odd).verdict == "fails"
    c = _claim("typo-p-star", ev)
    # Figure 1's own axis runs 1.00 .. 1.25: a non-constant p*
    assert c.verdict == "fails" and c.numbers["figure_p_max"] > 1.1
    flat = copy.deepcopy(ev)
    flat.figure1_range["p_max"] = flat.figure1_range["p_min"]
    assert _claim("typo-p-star", flat).verdict == "holds"


def test_every_rule_text_shows_its_thresholds():
    """One definition: each threshold the straight-rod rules use appears in their text."""
    texts = " ".join(spec.rule.text for spec, _ in rows.CLAIMS)
    for value in (rows.NEAR, rows.EXACT, rows.ROUND_OFF, rows.NON_PLANAR, rows.GAP_TO_2PI,
                  rows.LIMIT_ORDER, rows.EXPANSION_ORDER, rows.RESONANCE_ORDER,
                  rows.RESONANCE_REMAINDER_ORDER, rows.RESONANCE_EXACT, rows.ROOT_RATIO):
        assert f"{value:g}" in texts


def test_crossing_limit_as_nu_grows_matches_the_closed_form():
    # the closed form of the crossing at a large nu approaches the nu -> infinity limit
    for n in (2, 3):
        lim = rows.crossing_limit_nu_infinity(n)
        gaps = [abs(crossing_closed_form(n, nu).twist - lim) for nu in (1e2, 1e3, 1e4)]
        assert gaps[2] < 1e-5 * lim and gaps[2] < gaps[1] / 5 < gaps[0] / 25  # O(1/nu)
    # and that limit is within the at-n-pi standard: "holds approximately" for every nu
    assert rows.crossing_limit_nu_infinity(2) / (2 * math.pi) - 1 < rows.NEAR


def test_the_n_cubed_offset_law_is_asymptotic_only(ev):
    from spectral_rod import crossing_twist_asymptotic

    c = _claim("rod-further-maxima", ev)
    # the closed form of the crossing (not the scene's mpmath root) against the n^-3 law
    exact = crossing_closed_form(2, 1.5).twist / math.pi - 2
    law = crossing_twist_asymptotic(2, 1.5) / math.pi - 2
    assert c.numbers["offset_ratio_first"] == pytest.approx(exact / law, rel=1e-6)
    assert c.numbers["offset_ratio_first"] > 1.2  # far from 1 at n = 2
