"""The ring scene's words come from templates: every row's evidence and rule text is a template
with named fields (reproduce/ring/rows.py, galerkin_rows.py, model_rows.py), each rule's text is
made from the same named thresholds as its logic, and the report's prose is a template table
(reproduce/ring/__init__.py). Fast: no ring is solved here (the filled evidence texts of every
row are checked on the real evidence in tests/test_ring_scene.py)."""

from __future__ import annotations

import re
import string

import pytest

import reproduce.ring as scene
from reproduce.ring import galerkin_rows, model_rows, rows
from reproduce.ring.standards import EXACT_TOL, rule_from_template

MODULES = (rows, galerkin_rows, model_rows)


def _fields(template: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(template) if name}


def _literals(template: str) -> list[str]:
    return [text for text, _, _, _ in string.Formatter().parse(template) if text]


def _module_of(row_id: str):
    return next(m for m in MODULES if row_id in m.RULE_TEXTS)


def test_every_row_has_its_templates() -> None:
    ids = [spec.id for spec, _ in rows.CLAIMS]
    for row_id in ids:
        owners = [m for m in MODULES if row_id in m.RULE_TEXTS]
        assert len(owners) == 1, row_id
        assert row_id in owners[0].EVIDENCE, row_id
    # no template without its row (the parts of texts are in PHRASES, or named apart from rows)
    rule_ids = {k for m in MODULES for k in m.RULE_TEXTS}
    assert rule_ids == set(ids)


@pytest.mark.parametrize("spec", [s for s, _ in rows.CLAIMS], ids=lambda s: s.id)
def test_rule_text_is_its_template_filled(spec) -> None:
    template = _module_of(spec.id).RULE_TEXTS[spec.id]
    assert "{" not in spec.rule.text and "}" not in spec.rule.text
    pattern = "(.*)".join(re.escape(t) for t in _literals(template))
    assert re.fullmatch(("(.*)" if template.startswith("{") else "") + pattern
                        + ("(.*)" if template.endswith("}") else ""), spec.rule.text,
                        flags=re.DOTALL), spec.id


def test_a_changed_threshold_changes_the_rule_text_and_the_verdict() -> None:
    numbers = {"max_rel_spread": 1e-10}
    row = "ring-circular-twist-independent"
    as_declared = rows.ring_rule(row, rows._spread_rule, exact=EXACT_TOL)
    assert as_declared.text == rows.TWIST_INDEPENDENT.rule.text
    assert as_declared.decide(numbers) == rows.TWIST_INDEPENDENT.rule.decide(numbers) == "holds"
    stricter = rows.ring_rule(row, rows._spread_rule, exact=1e-11)
    assert "1e-11" in stricter.text and f"{EXACT_TOL:g}" not in stricter.text
    assert stricter.decide(numbers) == "fails"
    # a tiered rule of another module: the paper's range moves the "holds approximately" line
    excess = {"max_rel_excess_by_nu": {1.1: 0.01, 1.5: 0.04, 2.0: 0.2}}
    spec = galerkin_rows.FIXED_N
    assert spec.rule.decide(excess) == "holds approximately"
    narrower = galerkin_rows._rule("ring-fixed-n-ansatz", galerkin_rows._estimate_rule,
                                   approx=0.02, paper_nu_max=1.5)
    assert "2%" in narrower.text and "2%" not in spec.rule.text
    assert narrower.decide(excess) == "fails"


def test_rule_from_template_names_every_threshold() -> None:
    with pytest.raises(KeyError):
        rule_from_template("holds if x ≤ {limit:g}", lambda n, **_: "holds", other=1.0)


def test_evidence_templates_name_their_fields() -> None:
    """Every template has named fields only (no positional {}), so a word can change without
    reading a computation, and each field is a name a measurement passes."""
    for m in MODULES:
        for name, template in m.EVIDENCE.items():
            assert all(f and not f.isdigit() for f in _fields(template)), (m.__name__, name)
    for name, template in rows.PHRASES.items():
        assert all(f and not f.isdigit() for f in _fields(template)), name
    for name, template in scene.REPORT.items():
        assert all(f and not f.isdigit() for f in _fields(template)), name
