"""The ledger's rule builder and the report's headline: tallies by kind, fails by root cause,
findings, all from claims.json."""

from __future__ import annotations

import json

import pytest

from reproduce._runner import headline_verdicts
from reproduce.ledger import VERDICTS, Claim, Condition, tiered_rule, update_ledger

CAUSE_A = "Error A of the paper"
CAUSE_B = "Error B of the paper"


def _row(i: str, verdict: str, kind: str = "paper", cause: str | None = None,
         finding: str | None = None) -> Claim:
    numbers = {"finding": finding} if finding else {}
    return Claim(id=i, section="s", claim=f"claim {i}", test="t", evidence="e",
                 verdict=verdict, scene="claims", kind=kind, root_cause=cause, numbers=numbers)


def _headline(tmp_path, rows):
    update_ledger(tmp_path, "claims", rows)
    return "\n".join(headline_verdicts(tmp_path / "claims.json"))


def test_paper_statements_are_tallied_apart_from_checks_and_caveats(tmp_path):
    text = _headline(tmp_path, [
        _row("a", "holds"), _row("b", "fails", cause=CAUSE_A), _row("c", "fails", cause=CAUSE_A),
        _row("d", "fails", cause=CAUSE_B), _row("e", "fails"),
        _row("p", "holds", kind="package"), _row("q", "fails", kind="caveat")])
    first = text.split("## Verdicts, row by row")[0]
    assert "5 claims of the paper (its own statements) checked — **holds** 1, **fails** 4." \
        in first
    assert "1 check(s) of the package's own methods (**holds** 1)" in first
    assert "1 modelling caveat(s) about what the paper leaves open (**fails** 1)" in first
    # four failing statements, three independent errors: A (two rows), B, and e on its own
    assert "the 4 failing statements trace back to 3 independent error(s)" in first
    assert f"- {CAUSE_A} — `b`, `c`" in first and f"- {CAUSE_B} — `d`" in first
    assert "- `e` (no shared root cause stated): claim e" in first
    # a caveat's fail is not a fail of the paper
    assert "`q`" not in first


def test_moving_a_row_between_kinds_or_causes_changes_the_headline(tmp_path):
    base = [_row("b", "fails", cause=CAUSE_A), _row("c", "fails", cause=CAUSE_A)]
    one = _headline(tmp_path, base)
    assert "trace back to 1 independent error(s)" in one
    two = _headline(tmp_path, [base[0], _row("c", "fails", cause=CAUSE_B)])
    assert "trace back to 2 independent error(s)" in two
    pkg = _headline(tmp_path, [base[0], _row("c", "fails", kind="package")])
    assert "the 1 failing statements" in pkg and "1 check(s) of the package" in pkg


def test_findings_come_from_the_rows_numbers(tmp_path):
    text = _headline(tmp_path, [_row("a", "holds", finding="p* tends to 1.2000 at ν = 1.5.")])
    assert "- p* tends to 1.2000 at ν = 1.5." in text


def test_ring_fallback_finding_reads_the_ring_rows_numbers(tmp_path):
    ring = Claim(id="ring-circular-limit", section="s", claim="c", test="t", evidence="e",
                 verdict="fails", scene="ring", numbers={"per_e": {
                     "e=1": {"numerical": {"hydrostatic": 2.0}, "in_plane": {"hydrostatic": 3.0}},
                     "isotropic": {"numerical": {"hydrostatic": 1.698}}}})
    update_ledger(tmp_path, "ring", [ring])
    text = "\n".join(headline_verdicts(tmp_path / "claims.json"))
    assert "2.000 E₁I₁/R³ out of plane" in text and "1.698" in text
    # numbers of another shape: no finding, no crash
    odd = Claim(id="ring-circular-limit", section="s", claim="c", test="t", evidence="e",
                verdict="fails", scene="ring", numbers={"per_e": [1, 2]})
    update_ledger(tmp_path, "ring", [odd])
    assert "out of plane" not in "\n".join(headline_verdicts(tmp_path / "claims.json"))


def test_tiered_rule_text_and_logic_share_the_thresholds():
    rule = tiered_rule([("holds", (Condition("x", "<", "the error", 1e-9),)),
                        ("holds approximately", (Condition("x", "<", "the error", 1e-2),
                                                 Condition("ok", "true", "it is a corner")))],
                       "fails", note="a note")
    assert rule.text == ("holds if the error < 1e-09; holds approximately if the error < 0.01 "
                         "and it is a corner; fails otherwise (a note)")
    assert rule.decide({"x": 5e-10, "ok": False}) == "holds"
    assert rule.decide({"x": 5e-3, "ok": True}) == "holds approximately"
    assert rule.decide({"x": 5e-3, "ok": False}) == "fails"
    assert rule.decide({"x": float("nan"), "ok": True}) == "fails"  # non-finite: not met
    assert rule.decide({"ok": True}) == "fails"  # missing: not met


def test_bad_rules_are_refused():
    with pytest.raises(ValueError, match="op must be one of"):
        Condition("x", "!=", "x", 1.0)
    with pytest.raises(ValueError, match="threshold"):
        Condition("x", "<", "x")
    with pytest.raises(ValueError, match="not one of"):
        tiered_rule([("maybe", ())], "fails")


def test_the_new_verdict_class_is_a_verdict_and_is_rendered(tmp_path):
    assert "true but does not explain" in VERDICTS
    update_ledger(tmp_path, "claims", [_row("a", "true but does not explain",
                                            cause=None)])
    md = (tmp_path / "claims.md").read_text()
    assert "1 true but does not explain" in md and "coverage.md" in md
    assert json.loads((tmp_path / "claims.json").read_text())[0]["kind"] == "paper"
