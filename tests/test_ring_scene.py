"""The `ring` scene: every ledger verdict recomputed from the evidence with independent logic,
verdicts that flip when the evidence changes, and the files the scene writes."""

from __future__ import annotations

import copy
import dataclasses
import json
import math
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import reproduce.ring as scene
from reproduce.ledger import VERDICTS, Measured, judge, with_shared
from reproduce.ring import rows
from spectral_rod import RING_LOADS, ring_critical_load


@pytest.fixture(scope="module")
def evidence() -> scene.RingEvidence:
    return scene.compute_evidence()


@pytest.fixture(scope="module")
def claims(evidence: scene.RingEvidence) -> dict[str, object]:
    return {c.id: c for c in scene.evaluate_claims(evidence)}


def _hand_crit2(N: np.ndarray, nu: np.ndarray, e: np.ndarray) -> np.ndarray:
    """Eq. crit2 in units of E1 I1/R^3, typed independently of spectral_rod.ring."""
    I1 = 1.0
    I2 = nu * I1
    E2 = e
    return E2 * (I1 + I2) / 2 * (3 - (I2 - I1) / (I2 + I1) * (N**2 + 1))


def test_table_is_complete_and_converged(evidence: scene.RingEvidence) -> None:
    t = evidence.table
    assert len(t) == len(scene.TWISTS) * len(scene.NUS) * len(scene.E_RATIOS)
    assert np.allclose(t["crit2"], _hand_crit2(t["N"].to_numpy(float), t["nu"].to_numpy(),
                                               t["e_ratio"].to_numpy()), rtol=1e-13, atol=1e-13)
    for load in RING_LOADS:
        assert (t[f"rel_change_{load}"] <= 1e-12).all()
        assert (t[f"q_{load}"] > 0).all()


def test_all_verdicts_valid_and_ids_prefixed(claims: dict) -> None:
    assert set(claims) == {"ring-crit2", "ring-circular-limit",
                           "ring-circular-twist-independent", "ring-in-out-coincide",
                           "ring-monotone-decrease", "ring-rate-grows-with-nu",
                           "ring-spontaneous-instability", "ring-destabilises",
                           "ring-three-dimensional", "intro-three-dimensional",
                           "ring-gt97-comparison", "ring-two-formulations",
                           "caveat-torsional-stiffness", "caveat-load-model", "eq-munder",
                           "ring-hoop-force", "ring-crit2-galerkin", "ring-crit2-torsion-scaling",
                           "ring-fixed-n-ansatz", "ring-analytic-only-circular",
                           "ring-adjacent-equilibrium", "caveat-ring-supports",
                           "caveat-admissible-twists", "ring-spontaneous-torsions",
                           "ring-three-coupled-equations"}
    for c in claims.values():
        assert c.verdict in VERDICTS and c.scene == "ring" and c.evidence and c.numbers
        assert c.id.split("-")[0] in ("ring", "intro", "caveat", "eq")


def test_gt97_and_two_formulations_recomputed(evidence: scene.RingEvidence,
                                             claims: dict) -> None:
    t, w = evidence.table, evidence.wide
    no_zero_load_solution = bool(
        (t[[f"min_inverse_load_{ld}" for ld in RING_LOADS]] > -1e-12).all().all()
        and (w["min_inverse_load"] > -1e-12).all() and (w["q"] > 0).all()
        and (t[[f"q_{ld}" for ld in RING_LOADS]] > 0).all().all())
    assert no_zero_load_solution
    assert claims["ring-gt97-comparison"].verdict == "fails"
    f = evidence.formulations
    assert len(f) >= 12 and set(f["N"]) >= set(range(9))
    agree = bool((abs(f["q_munder"] - f["q_galerkin"]) / f["q_galerkin"] <= 1e-6).all())
    assert claims["ring-two-formulations"].verdict == ("holds" if agree else "fails")
    # the load caveat states which verdicts depend on the reading; it never "fails" the paper
    n = claims["caveat-load-model"].numbers
    assert claims["caveat-load-model"].verdict == ("holds" if not n["undecided_claims"]
                                                   else "inconclusive")
    assert "ring-destabilises" in n["load_dependent_claims"]


def test_crit2_verdict(evidence: scene.RingEvidence, claims: dict) -> None:
    t = evidence.table
    devs = [np.max(np.abs(t["crit2"] - t[f"q_{ld}"]) / t[f"q_{ld}"]) for ld in RING_LOADS]
    best = min(devs)
    expected = ("holds" if best <= 1e-9 else "holds approximately" if best <= 0.05 else "fails")
    assert claims["ring-crit2"].verdict == expected == "fails"
    # numbers behind the evidence string
    assert claims["ring-crit2"].numbers["hydrostatic"]["max_rel_dev"] == pytest.approx(devs[0])


def test_circular_limit_verdict(evidence: scene.RingEvidence, claims: dict) -> None:
    # crit2 at nu = 1 is 3 e; the text says 3 (E1); isotropic e differs
    e_iso = 1 / 2.6
    assert abs(3 * e_iso - 3.0) > 1.0
    # numerical circular ring = Timoshenko & Gere out-of-plane, n = 2: 9/(4 + 1/(2e))
    t = evidence.table
    for label, e in scene.E_RATIOS.items():
        q = t[(t["nu"] == 1.0) & (t["e_label"] == label)]["q_hydrostatic"]
        assert np.allclose(q, 9 / (4 + 1 / (2 * e)), rtol=1e-12)
    assert claims["ring-circular-limit"].verdict == "fails"
    assert claims["ring-circular-limit"].numbers["in_plane_vs_text"] < 1e-12


def test_twist_independence_verdict(evidence: scene.RingEvidence, claims: dict) -> None:
    t = evidence.table[evidence.table["nu"] == 1.0]
    spread = max(float(np.ptp(g[f"q_{ld}"]) / g[f"q_{ld}"].min())
                 for _, g in t.groupby("e_label") for ld in ("hydrostatic", "axis"))
    assert claims["ring-circular-twist-independent"].verdict == (
        "holds" if spread <= 1e-9 else "fails") == "holds"


def test_in_out_coincide_verdict(claims: dict) -> None:
    # closed forms: in-plane 3 (hydrostatic) and 4.5 (axis) vs out-of-plane <= 9/4
    assert claims["ring-in-out-coincide"].verdict == "fails"
    assert claims["ring-in-out-coincide"].numbers["sup_out_of_plane"] == pytest.approx(2.25)
    assert claims["ring-in-out-coincide"].numbers["min_rel_gap"] == pytest.approx(0.5)


def test_monotone_verdict(evidence: scene.RingEvidence, claims: dict) -> None:
    t = evidence.table[evidence.table["nu"] > 1.0]
    rising = 0
    for _, g in t.groupby(["e_label", "nu"]):
        g = g.sort_values("N")
        for ld in RING_LOADS:
            rising += bool(np.any(np.diff(g[f"q_{ld}"].to_numpy()) > 0))
    assert claims["ring-monotone-decrease"].verdict == ("holds" if rising == 0 else "fails")
    assert rising > 0


def test_spontaneous_instability_verdict(evidence: scene.RingEvidence, claims: dict) -> None:
    t = evidence.table
    assert (t[[f"q_{ld}" for ld in RING_LOADS]] > 0).all().all()
    assert (t[[f"min_inverse_load_{ld}" for ld in RING_LOADS]] > -1e-12).all().all()
    assert claims["ring-spontaneous-instability"].verdict == "fails"


def test_destabilises_verdict(evidence: scene.RingEvidence, claims: dict) -> None:
    # recount from the wide scan, per load model, independently of the scene's helper
    w = evidence.wide[evidence.wide["nu"] > 1.0]
    every = {}
    for ld in RING_LOADS:
        raised = 0
        for _, g in w[w["load"] == ld].groupby(["e_label", "nu"]):
            q = g.set_index("N")["q"]
            raised += int((q.loc[1:] >= q.loc[0]).sum())
        every[ld] = raised == 0
    numbers = claims["ring-destabilises"].numbers
    assert numbers["every_case_lowered"] == every
    expected = ("holds" if all(every.values()) else
                "holds approximately" if any(every.values()) else "fails")
    assert claims["ring-destabilises"].verdict == expected
    # the boundary nu* is where the largest twist gain changes sign (gain typed here)
    def gain(nu: float, e: float, load: str) -> float:
        q = [ring_critical_load(N, nu, e_ratio=e, load=load) for N in range(11)]
        return max(q[1:]) / q[0] - 1

    finite = {k: v for k, v in numbers["nu_boundary"].items() if math.isfinite(v)}
    assert finite
    for key, nu_star in finite.items():
        label, load = key.split("/")
        e = scene.E_RATIOS[label]
        assert gain(nu_star * 0.99, e, load) < 0 < gain(nu_star * 1.01, e, load)


def test_destabilising_rule() -> None:
    def decide(hydrostatic: bool, axis: bool, cases: int = 10) -> str:
        return rows.DESTABILISES.rule.decide(
            {"every_case_lowered": {"hydrostatic": hydrostatic, "axis": axis},
             "fewest_cases": cases})

    assert decide(True, True) == "holds"
    assert decide(False, True) == "holds approximately"
    assert decide(False, False) == "fails"
    assert decide(True, True, cases=0) == "inconclusive"  # all([]) is no evidence


@pytest.mark.parametrize("spec_measure", rows.CLAIMS, ids=[s.id for s, _ in rows.CLAIMS])
def test_a_failed_cross_check_makes_the_verdict_inconclusive(evidence, spec_measure) -> None:
    spec, measure = spec_measure
    measured = with_shared(spec, measure(evidence), rows.shared_checks(evidence))
    assert judge(spec, measured, "ring").verdict != "inconclusive"
    for i, check in enumerate(measured.cross_checks):
        broken = list(measured.cross_checks)
        broken[i] = type(check)(check.name, 10 * check.limit + 1e-3, check.limit)
        got = judge(spec, Measured(measured.numbers, measured.evidence, tuple(broken)), "ring")
        assert got.verdict == "inconclusive" and check.name in got.evidence


def test_every_ring_row_rests_on_two_formulations_or_says_so(claims: dict) -> None:
    for c in claims.values():
        forms = {m["formulation"] for m in c.methods}
        assert len(forms) >= 2 or "one formulation only" in c.evidence, c.id


# ----------------------------------------------------------- verdicts follow the evidence

def _with_table(ev: scene.RingEvidence, table: pd.DataFrame,
                wide: pd.DataFrame | None = None) -> scene.RingEvidence:
    new = copy.copy(ev)
    new.table = table
    if wide is not None:
        new.wide = wide
    return new


def test_verdicts_flip_when_evidence_changes(evidence: scene.RingEvidence) -> None:
    t = evidence.table.copy()
    # 1. if the numerical loads equalled crit2 (where positive), crit2 would hold
    fake = t[t["crit2"] > 0].copy()
    for ld in RING_LOADS:
        fake[f"q_{ld}"] = fake["crit2"]
        fake[f"rel_dev_{ld}"] = 0.0
    assert scene.evaluate_claim("ring-crit2",
                                _with_table(evidence, fake)).verdict == "holds"
    fake[[f"rel_dev_{ld}" for ld in RING_LOADS]] = 0.03
    assert scene.evaluate_claim("ring-crit2",
                                _with_table(evidence, fake)).verdict == "holds approximately"
    # 2. a strictly decreasing table whose drop grows with nu makes the monotone claim hold
    mono = t.copy()
    for ld in RING_LOADS:
        mono[f"q_{ld}"] = 10.0 - mono["N"] * mono["nu"] * 0.1
    assert scene.evaluate_claim("ring-monotone-decrease",
                                _with_table(evidence, mono)).verdict == "holds"
    wide_down = evidence.wide.copy()
    wide_down["q"] = 10.0 - wide_down["N"] * 0.1
    assert scene.evaluate_claim("ring-destabilises",
                                _with_table(evidence, mono, wide_down)).verdict == "holds"
    # 3. a non-positive load beyond the threshold would support spontaneous instability
    neg = t.copy()
    neg.loc[(neg["nu"] == 2.0) & (neg["N"] == 5), "q_hydrostatic"] = -0.1
    assert scene.evaluate_claim("ring-spontaneous-instability",
                                _with_table(evidence, neg)).verdict == "holds"
    # 4. a twist-dependent circular ring breaks independence
    dep = t.copy()
    dep.loc[(dep["nu"] == 1.0) & (dep["N"] == 3), "q_axis"] *= 1.01
    assert scene.evaluate_claim("ring-circular-twist-independent",
                                _with_table(evidence, dep)).verdict == "fails"
    # 5. twist raising every load refutes "destabilises"
    wide_up = evidence.wide.copy()
    wide_up["q"] = 1.0 + wide_up["N"]
    assert scene.evaluate_claim("ring-destabilises",
                                _with_table(evidence, t, wide_up)).verdict == "fails"


# ----------------------------------------------------------- the scene's files

def test_scene_writes_outputs(tmp_path: Path, evidence: scene.RingEvidence,
                              monkeypatch: pytest.MonkeyPatch) -> None:
    # keep another scene's ledger rows
    (tmp_path / "claims.json").write_text(json.dumps([{
        "id": "rod-x", "section": "s", "claim": "c", "test": "t", "evidence": "e",
        "verdict": "holds", "scene": "claims", "figure": None, "numbers": {}}]))
    monkeypatch.setattr(scene, "compute_evidence", lambda progress=None: evidence)
    messages: list[str] = []
    result = scene.run(tmp_path, messages.append)
    names = {p.name for p in result.files}
    assert {"ring_table.csv", "ring_table.md", "ring_threshold.csv", "ring_threshold.md",
            "ring_formulations.csv", "ring_wide.csv", "ring.png", "claims.json",
            "claims.md"} <= names
    assert result.report.startswith("## Ring")
    rows = json.loads((tmp_path / "claims.json").read_text())
    assert {r["id"] for r in rows if r["scene"] == "ring"} == set(result.details["verdicts"])
    assert any(r["id"] == "rod-x" for r in rows)
    assert (tmp_path / "ring.png").stat().st_size > 20_000
    table = pd.read_csv(tmp_path / "ring_table.csv")
    assert len(table) == len(evidence.table)
    th = pd.read_csv(tmp_path / "ring_threshold.csv")
    assert th.loc[th["nu"] == 2.0, "N_integer"].iloc[0] == 3
    assert math.isinf(th.loc[th["nu"] == 1.0, "N_continuous"].iloc[0])
    assert messages


def test_witness_re_solves_have_their_own_timings_row(evidence: scene.RingEvidence) -> None:
    """The witnesses' re-solves (also those of verdicts_per_load, on each load model's evidence
    alone) run while the claims are measured; their time is a row of the timings table."""
    from reproduce.ring import report_section
    from reproduce.ring.evidence import WITNESS_TIMING

    calls: list[tuple] = []

    def slow(*ring):  # the run's solver, 20 ms slower per call
        calls.append(ring)
        time.sleep(0.02)
        return evidence.solve(*ring)

    ev = dataclasses.replace(evidence, timings={"table": 1.0}, witnesses=set(), solve=slow)
    claims = scene.evaluate_claims(ev)
    assert len(ev.witnesses) >= 4 and len(calls) >= len(ev.witnesses)
    assert ev.timings[WITNESS_TIMING] >= 0.02 * len(calls)
    assert f"{WITNESS_TIMING} {ev.timings[WITNESS_TIMING]:.1f} s" in report_section(
        claims, ev, 2.0, len(ev.witnesses))


def test_scene_metadata() -> None:
    assert scene.NAME == "ring"
    assert "\n" not in scene.SUMMARY
    assert scene.__doc__ and "Writes" in scene.__doc__ and "Compares" in scene.__doc__


# ----------------------------------------------------------- rules: holds, fails, inconclusive

def _numbers(claim_id: str, ev: scene.RingEvidence) -> dict:
    _, measure = next(c for c in rows.CLAIMS if c[0].id == claim_id)
    return measure(ev).numbers


def test_spontaneous_and_gt97_rules_have_three_outcomes(evidence: scene.RingEvidence) -> None:
    t = evidence.table.copy()
    assert scene.evaluate_claim("ring-spontaneous-instability", evidence).verdict == "fails"
    # a negative 1/q beyond round-off, every load still positive: the evidence contradicts itself
    odd = evidence.wide.copy()
    odd.loc[odd.index[-1], "min_inverse_load"] = -1e-6
    mixed = _with_table(evidence, t, odd)
    assert scene.evaluate_claim("ring-spontaneous-instability", mixed).verdict == "inconclusive"
    assert scene.evaluate_claim("ring-gt97-comparison", mixed).verdict == "inconclusive"
    # a twisted ring with q_cr <= 0: a discrepancy, whose explanation is not examined here
    neg = t.copy()
    neg.loc[(neg["nu"] == 2.0) & (neg["N"] == 5), "q_axis"] = -0.1
    got = scene.evaluate_claim("ring-gt97-comparison", _with_table(evidence, neg))
    assert got.verdict == "inconclusive" and "not examined" in got.evidence
    assert "GT97's result stands" not in scene.evaluate_claim("ring-gt97-comparison",
                                                              evidence).evidence
    # no ring at or beyond the threshold solved: nothing decides the claim
    n = _numbers("ring-spontaneous-instability", evidence)
    assert rows.SPONTANEOUS.rule.decide({**n, "beyond_threshold": []}) == "inconclusive"


def test_load_caveat_rule(evidence: scene.RingEvidence) -> None:
    got = scene.evaluate_claim("caveat-load-model", evidence)
    assert got.verdict == "holds" and got.kind == "caveat"
    assert set(got.numbers["verdicts_per_load"]["ring-crit2"]) == set(RING_LOADS)
    # one reading's evidence undecided for a claim (a 1/q below round-off there only)
    undecided = copy.copy(evidence)
    undecided.table = evidence.table.assign(min_inverse_load_dead=-1e-6)
    got = scene.evaluate_claim("caveat-load-model", undecided)
    assert got.verdict == "inconclusive"
    assert "ring-spontaneous-instability" in got.numbers["undecided_claims"]
    # every other ring claim is compared, not a chosen few
    assert set(got.numbers["verdicts_per_load"]) == {s.id for s, _ in rows.CLAIMS} - {
        "caveat-load-model"}


def test_single_load_evidence_replaces_every_number_of_the_other_model(evidence) -> None:
    one = rows.single_load_evidence(evidence, "axis")
    assert (one.table["q_hydrostatic"] == evidence.table["q_axis"]).all()
    assert (one.thresholds["q_hydrostatic_at_N_e=1"].fillna(0)
            == evidence.thresholds["q_axis_at_N_e=1"].fillna(0)).all()
    for name in ("wide", "untwisted_circular", "boundaries", "rectangle"):
        frame = getattr(one, name)
        hyd = frame[frame["load"] == "hydrostatic"].drop(columns="load").reset_index(drop=True)
        axis = frame[frame["load"] == "axis"].drop(columns="load").reset_index(drop=True)
        assert hyd.equals(axis), name


def test_zero_load_numbers_cover_the_table_and_the_wide_scan(evidence) -> None:
    n = _numbers("ring-spontaneous-instability", evidence)
    keys = {(r.e_label, r.nu, r.N, ld) for r in evidence.table.itertuples() for ld in
            RING_LOADS} | {(r.e_label, r.nu, r.N, r.load) for r in evidence.wide.itertuples()}
    assert n["n_solves"] == len(keys) < (len(RING_LOADS) * len(evidence.table)
                                         + len(evidence.wide))
    low = evidence.wide.copy()
    only_wide = low.index[~low["nu"].isin(scene.NUS)][0]  # a ring the table does not solve
    low.loc[only_wide, "min_inverse_load"] = -5e-13  # round-off still
    assert _numbers("ring-spontaneous-instability",
                    _with_table(evidence, evidence.table, low))["min_inverse_load"] == -5e-13


def test_each_ring_is_solved_once_per_run(evidence) -> None:
    from reproduce.ring.evidence import EQUILIBRIUM_CASES, LARGE_TWIST_CASE
    e_of = scene.E_RATIOS
    second = ({(r.N, r.nu, r.e_ratio, ld) for r in evidence.table.itertuples()
               for ld in RING_LOADS}
              | {(r.N, r.nu, e_of[r.e_label], r.load) for r in evidence.wide.itertuples()}
              | {(r.N, r.nu, r.e_ratio, r.load) for r in evidence.rectangle.itertuples()}
              | {(N, LARGE_TWIST_CASE[0], LARGE_TWIST_CASE[1], LARGE_TWIST_CASE[2])
                 for N in evidence.large_twist_shares})
    munder = {(r.N, r.nu, r.e_ratio, r.load) for r in evidence.formulations.itertuples()}
    munder |= set(EQUILIBRIUM_CASES)
    distinct = len(second) + len(munder) + len(EQUILIBRIUM_CASES)  # + Kirchhoff's
    assert evidence.solves["distinct"] == distinct < evidence.solves["requested"]


def test_shared_cross_check_reaches_every_row_using_second_variation_loads(claims) -> None:
    name = next(c["name"] for c in claims["ring-crit2"].cross_checks)
    assert name.startswith("q_cr: second variation vs Munder")
    with_it = {i for i, c in claims.items() if any(x["name"] == name for x in c.cross_checks)}
    assert "caveat-torsional-stiffness" in with_it
    assert {"ring-two-formulations", "ring-hoop-force"}.isdisjoint(with_it)
    # Munder is a method only where its numbers enter the measurement
    for i in ("ring-circular-twist-independent", "caveat-load-model"):
        assert "Munder" not in {m["formulation"] for m in claims[i].methods}
        assert "one formulation only" in claims[i].evidence
        assert "comparison cases" in claims[i].evidence


def test_threshold_paragraph_follows_the_verdict(claims) -> None:
    row = claims["ring-spontaneous-instability"]
    assert "physical?** No." in scene.physical_threshold_text(row)
    for verdict, word in (("holds", "Yes"), ("inconclusive", "Undecided")):
        assert word in scene.physical_threshold_text(dataclasses.replace(row, verdict=verdict))


def test_rules_without_evidence_are_inconclusive(evidence: scene.RingEvidence) -> None:
    """A rule never reads "holds" or "fails" off an empty set of cases (all([]) is True)."""
    cases = {"ring-monotone-decrease": {"groups": 0},
             "ring-rate-grows-with-nu": {"fewest_nus": 1},
             "ring-three-dimensional": {"n_modes": 0},
             "intro-three-dimensional": {"ring_n_modes": 0}}
    for claim_id, empty in cases.items():
        spec = next(s for s, _ in rows.CLAIMS if s.id == claim_id)
        n = _numbers(claim_id, evidence)
        assert spec.rule.decide(n) != "inconclusive", claim_id
        assert spec.rule.decide({**n, **empty}) == "inconclusive", claim_id
    n = _numbers("ring-destabilises", evidence)
    assert n["fewest_cases"] > 0
    assert rows.DESTABILISES.rule.decide({**n, "fewest_cases": 0}) == "inconclusive"
    # a planar rod mode decides the introduction's claim whatever the ring shows
    n = _numbers("intro-three-dimensional", evidence)
    assert rows.INTRO_3D.rule.decide({**n, "rod_non_planarity": 0.0, "ring_n_modes": 0}) == \
        "fails"


@pytest.mark.parametrize(("claim_id", "verdict"), [("ring-monotone-decrease", "fails"),
                                                  ("ring-rate-grows-with-nu",
                                                   "holds approximately")])
def test_witnesses_decide_with_the_second_variation(evidence: scene.RingEvidence,
                                                    claim_id: str, verdict: str) -> None:
    """A "fails" resting on the second variation's full range needs Eqs. Munder to agree at
    its decisive rings: the witness re-solved (and agreeing) gives "fails"; no solver (NaN),
    or a Munder that disagrees, gives "inconclusive"."""
    assert scene.evaluate_claim(claim_id, evidence).verdict == verdict
    row = scene.evaluate_claim(claim_id, evidence)
    witness = [c for c in row.cross_checks if c["name"].startswith("witness:")]
    assert len(witness) == 1 and witness[0]["passed"] and witness[0]["disagreement"] < 1e-12
    assert "Munder" in {m["formulation"] for m in row.methods}
    blind = dataclasses.replace(evidence, solve=None)
    assert scene.evaluate_claim(claim_id, blind).verdict == "inconclusive"

    class Flat(scene.RingEvidence):
        def munder_load(self, N, nu, e_label, load):  # a Munder that sees no twist effect
            return 3.0

    flat = Flat(**{f.name: getattr(evidence, f.name) for f in dataclasses.fields(evidence)})
    assert scene.evaluate_claim(claim_id, flat).verdict == "inconclusive"


def test_single_load_evidence_re_solves_its_own_load_model(evidence: scene.RingEvidence
                                                          ) -> None:
    # the axis-only evidence stands under both labels: its witnesses must be axis rings
    one = rows.single_load_evidence(evidence, "axis")
    assert one.load_override == "axis"
    q = one.munder_load(2, 2.0, "e=1", "hydrostatic")
    assert q == pytest.approx(ring_critical_load(2, 2.0, load="axis"), rel=1e-9)


def test_the_raise_margin_decides_no_case_of_the_scans(evidence: scene.RingEvidence) -> None:
    """RING_RAISE_TOL is a round-off margin (its docstring: the smallest genuine change twist
    makes on the scans, nu > 1, is ~8e-4): no twisted load of the wide scan (the one
    ring-destabilises counts) lies within 1000 margins of q_cr(0), so no verdict depends on the
    margin's value."""
    from spectral_rod import RING_RAISE_TOL

    wide, gaps = evidence.wide, []
    for label in wide["e_label"].unique():
        for load in wide["load"].unique():
            for nu, q in rows._series(wide, label, load).items():
                if nu > 1.0:
                    gaps.append(np.abs(q[1:] / q[0] - 1).min())
    assert gaps and min(gaps) > 1000 * RING_RAISE_TOL
    assert min(gaps) > 5e-4  # the docstring's "~8e-4"


# ----------------------------------------------------------- kinds, root causes, new standards

def test_rows_carry_their_kind_and_root_cause(claims: dict) -> None:
    from reproduce.ring.root_causes import ROOT_CAUSES

    kinds = {i: c.kind for i, c in claims.items()}
    assert kinds["ring-two-formulations"] == "package"
    assert {i for i, k in kinds.items() if k == "caveat"} == {
        "caveat-load-model", "caveat-torsional-stiffness", "caveat-ring-supports",
        "caveat-admissible-twists"}
    for c in claims.values():
        assert c.root_cause is None or c.root_cause in ROOT_CAUSES, c.id
        if c.kind == "paper" and c.verdict == "fails":
            assert c.root_cause, c.id  # every fail of the paper traces to a stated error
    causes = {c.root_cause for c in claims.values() if c.verdict == "fails"}
    assert len(causes) <= len(ROOT_CAUSES)


def test_crit2_galerkin_recomputed_at_N0(claims: dict) -> None:
    """At N = 0 the one-harmonic Galerkin is exact: crit2(0) = e(nu + 2) against the untwisted
    closed forms typed here (in plane about e_z, A1 = 1; out of plane about e_r, A2 = nu)."""
    def untwisted(nu: float, e: float, load: str) -> float:
        a3 = e * (1 + nu)
        inp = {"hydrostatic": 3.0, "axis": 4.5, "centre": 4.5, "dead": 4.0}[load]
        out = (12.0 if load == "centre" else 9.0) * nu / (4 + nu / a3)
        return min(inp, out)

    per = {ld: max(abs(e * (nu + 2) - untwisted(nu, e, ld)) / untwisted(nu, e, ld)
                   for e in scene.E_RATIOS.values() for nu in scene.NUS) for ld in RING_LOADS}
    row = claims["ring-crit2-galerkin"]
    assert row.numbers["max_rel_dev_N0_best_reading"] == pytest.approx(min(per.values()))
    assert row.verdict == "fails" and min(per.values()) > 0.05
    assert row.numbers["one_harmonic_is_upper_bound"]
    for dev, verdict in ((0.0, "holds"), (0.03, "holds approximately"), (0.5, "fails")):
        assert rows.CRIT2_GALERKIN.rule.decide(
            {**row.numbers, "max_rel_dev_N0_best_reading": dev}) == verdict


def test_torsion_scaling_flips_when_the_load_scales_with_E2(evidence) -> None:
    assert scene.evaluate_claim("ring-crit2-torsion-scaling", evidence).verdict == "fails"
    t = evidence.table.copy()
    iso = t["e_label"] == "isotropic"
    for ld in RING_LOADS:  # loads that scale like crit2's E2 factor
        t.loc[iso, f"q_{ld}"] = t.loc[~iso, f"q_{ld}"].to_numpy() * scene.E_RATIOS["isotropic"]
    assert scene.evaluate_claim("ring-crit2-torsion-scaling",
                                _with_table(evidence, t)).verdict == "holds"


def test_fixed_n_ansatz_judged_on_the_papers_range(evidence) -> None:
    o = evidence.one_harmonic
    tw = o[o["N"] >= 1]
    assert (tw["q_one_harmonic"] >= tw["q"] * (1 - 1e-9)).all()  # Rayleigh-Ritz upper bound
    assert scene.evaluate_claim("ring-fixed-n-ansatz", evidence).verdict == "holds approximately"
    exact, worse = copy.copy(evidence), copy.copy(evidence)
    exact.one_harmonic = o.assign(q_one_harmonic=o["q"])
    assert scene.evaluate_claim("ring-fixed-n-ansatz", exact).verdict == "holds"
    worse.one_harmonic = o.assign(q_one_harmonic=o["q"] * 1.1)  # 10 % off at every nu
    assert scene.evaluate_claim("ring-fixed-n-ansatz", worse).verdict == "fails"


def test_analytic_only_row_flips_when_no_closed_form_matches(evidence) -> None:
    assert scene.evaluate_claim("ring-analytic-only-circular", evidence).verdict == "fails"
    t = evidence.table.copy()
    t.loc[t["N"] == 0, [f"q_{ld}" for ld in RING_LOADS]] *= 1.01
    assert scene.evaluate_claim("ring-analytic-only-circular",
                                _with_table(evidence, t)).verdict == "inconclusive"


def test_three_dimensional_reports_how_coupled(evidence, claims: dict) -> None:
    row = claims["ring-three-dimensional"]
    t = evidence.table[(evidence.table["nu"] > 1) & (evidence.table["N"] >= 1)]
    shares = np.concatenate([t[f"in_plane_fraction_{ld}"] for ld in RING_LOADS])
    assert row.numbers["n_modes"] == shares.size
    assert row.numbers["below_1_percent"] == int((shares < 0.01).sum())
    mixed = float(np.mean(np.minimum(shares, 1 - shares) >= 0.05))
    assert row.numbers["mixed_fraction"] == pytest.approx(mixed)
    assert row.verdict == "holds approximately" and mixed < 0.9 and shares.max() < 0.95
    # every twisted mode mixed: holds; one in-plane mode: fails (the evidence, not a number)
    for share, verdict in ((0.4, "holds"), (0.999, "fails")):
        tt = evidence.table.copy()
        twisted = (tt["nu"] > 1) & (tt["N"] >= 1)
        for ld in RING_LOADS:
            tt.loc[twisted, f"in_plane_fraction_{ld}"] = 0.4
        if verdict == "fails":
            tt.loc[twisted.idxmax(), "in_plane_fraction_hydrostatic"] = share
        got = scene.evaluate_claim("ring-three-dimensional", _with_table(evidence, tt))
        assert got.verdict == verdict, share
    assert claims["intro-three-dimensional"].verdict == "holds"


def test_rate_rule_uses_the_papers_range(claims: dict) -> None:
    from reproduce.ring.standards import PAPER_NU_MAX

    n = claims["ring-rate-grows-with-nu"].numbers
    ends = [e for per in n["growth_end"].values() for e in per.values()]
    assert PAPER_NU_MAX == 1.5 and min(ends) >= PAPER_NU_MAX and max(ends) <= 3.0
    assert n["munder_witness_grows"] is False
    decide = rows.RATE.rule.decide
    everywhere = {k: {m: max(scene.WIDE_NUS) for m in v} for k, v in n["growth_end"].items()}
    short = {k: {m: 1.1 for m in v} for k, v in n["growth_end"].items()}
    assert decide({**n, "growth_end": everywhere}) == "holds"
    assert decide(n) == "holds approximately"
    assert decide({**n, "growth_end": short}) == "fails"
    assert decide({**n, "munder_witness_grows": None}) == "inconclusive"
    assert rows.growth_end({1.1: 0.1, 1.5: 0.2, 2.0: 0.15, 3.0: 0.3}) == 1.5


def test_supports_adjacent_and_twists_rows(claims: dict) -> None:
    from reproduce.ring import model_rows

    s = claims["caveat-ring-supports"]
    assert s.verdict == "holds" and s.numbers["constraint_rank"] == 6
    assert s.numbers["behaviour"]["dead"]["spin about e_z"] == "destabilised"
    assert "destabilised" not in s.numbers["behaviour"]["centre"].values()
    assert model_rows.SUPPORTS.rule.decide({**s.numbers, "constraint_rank": 5}) == "fails"
    a = claims["ring-adjacent-equilibrium"]
    assert a.verdict == "holds" and set(a.numbers["cases_per_reading"]) == set(RING_LOADS)
    bad = {**a.numbers["max_rel_diff_per_reading"], "dead": 1e-3}
    assert model_rows.ADJACENT.rule.decide({**a.numbers, "max_rel_diff_per_reading": bad}) \
        == "fails"
    none = {**a.numbers["cases_per_reading"], "centre": 0}
    assert model_rows.ADJACENT.rule.decide({**a.numbers, "cases_per_reading": none}) \
        == "inconclusive"
    tw = claims["caveat-admissible-twists"]
    assert tw.verdict == "holds"
    assert model_rows.TWISTS_CAVEAT.rule.decide({**tw.numbers, "half_turn_change": 1.0}) \
        == "fails"


def test_limits_in_closed_form() -> None:
    """N -> infinity: the hydrostatic ring with E2 = E1 is raised by twist of many turns above
    nu = 1 + sqrt(3) (9a/(4 + a/(1 + nu)) = 3 with a = 2nu/(1 + nu): nu^2 - 2nu - 2 = 0, solved
    by hand); nu -> infinity: q(0) -> 3, q(N -> inf) -> 9 * 2/4 = 4.5."""
    from reproduce.ring.limits import large_anisotropy_limits, large_twist_threshold

    assert large_twist_threshold(1.0, "hydrostatic") == pytest.approx(1 + math.sqrt(3),
                                                                      rel=1e-10)
    assert math.isnan(large_twist_threshold(1.0, "axis"))
    lim = large_anisotropy_limits("hydrostatic")
    assert (lim["q_untwisted"], lim["q_large_twist"]) == (3.0, 4.5)
    assert lim["relative_drop"] == pytest.approx(-0.5)


def test_report_shows_the_verdicts_under_every_reading(claims: dict) -> None:
    text = scene.verdicts_by_reading_markdown(list(claims.values()))
    assert all(ld in text for ld in RING_LOADS)
    assert "`ring-destabilises`" in text and "depends on the reading" in text


def test_torsions_and_coupled_equations_rows(claims: dict) -> None:
    from reproduce.ring import model_rows

    t = claims["ring-spontaneous-torsions"]
    assert t.verdict == "holds" and t.numbers["max_abs_dev"] < 1e-12
    assert model_rows.TORSIONS.rule.decide({**t.numbers, "max_abs_dev": 1e-3}) == "fails"
    c = claims["ring-three-coupled-equations"]
    assert c.verdict == "holds"
    assert max(c.numbers["untwisted"].values()) < 1e-12  # N = 0: constant coefficients
    assert max(c.numbers["circular"].values()) < 1e-12  # nu = 1: nothing couples
    # the untwisted ring's (uncoupled) numbers in place of the twisted ones: the claim fails
    assert model_rows.THREE_EQUATIONS.rule.decide(
        {**c.numbers, "twisted": c.numbers["untwisted"]}) == "fails"


def test_every_ring_evidence_is_its_template_filled(evidence: scene.RingEvidence,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    """Each row's evidence text is its module's EVIDENCE template with named fields, every
    field filled (no brace left), and nothing else: the measurement only computes the fields."""
    from reproduce.ring import galerkin_rows, model_rows
    filled: dict[str, list[tuple[dict, str]]] = {}
    for module in (rows, galerkin_rows, model_rows):
        def record(name: str, _fill=module._evidence, _table=module.EVIDENCE,
                   **fields: object) -> str:
            text = _fill(name, **fields)
            assert text == _table[name].format(**fields)
            filled.setdefault(name, []).append((fields, text))
            return text
        monkeypatch.setattr(module, "_evidence", record)
    for spec, measure in rows.CLAIMS:
        got = measure(evidence)
        fields, text = filled[spec.id][-1]
        assert got.evidence == text, spec.id
        assert "{" not in text and "}" not in text, spec.id
        assert fields, spec.id
