"""The DNA scene: the twist-to-length conversion and the window, recomputed by hand."""

from __future__ import annotations

import math

import pytest

from reproduce import dna
from reproduce._runner import SCENE_MODULES
from spectral_rod import large_twist_coefficients, large_twist_limit


def test_the_scene_is_registered():
    assert "dna" in SCENE_MODULES


def test_twist_and_length_by_hand():
    h = 10.5 * 0.34  # nm per turn
    assert dna.twist_of_length(20.0, h) == pytest.approx(2 * math.pi * 20.0 / 3.57, rel=1e-12)
    # Figure 1 ends at Omega(L) = 10: 10 / (2 pi) turns of 3.57 nm
    assert dna.length_of_twist(10.0, h) == pytest.approx(10.0 / (2 * math.pi) * 3.57)
    assert dna.length_of_twist(10.0, h) < dna.VALIDITY_DIAMETERS * dna.DIAMETER_NM


def test_window_is_in_the_large_twist_regime():
    data = dna.compute()
    lo, hi = data["twist_window"]
    assert lo > 10 * math.pi and hi < 30 * math.pi
    for s in data["settled"]:
        # the deficit is of the size of the leading asymptotic term at the window's start:
        # |a2| / Omega^2 plus the ripple b3 / Omega^3, relative to the rise p_inf - 1
        c = large_twist_coefficients(s["nu"])
        bound = (abs(c.a2) / lo**2 + c.b3 / lo**3) / (large_twist_limit(s["nu"]) - 1)
        assert 0 < s["max_rel_deficit"] <= 1.2 * bound


def test_section_states_the_figure1_reach():
    text = dna.section(dna.compute())
    assert "No point of Figure 1" in text and "Hagerman 1988" in text


def test_the_scale_caveat_row_and_its_threshold():
    from reproduce.ledger import Measured, judge

    claim = dna.scale_claim(dna.compute())
    assert claim.kind == "caveat" and claim.verdict == "holds"
    # by hand: Figure 1 ends at 10 / (2 pi) turns of at most 3.57 nm; the rod needs 20 nm
    assert claim.numbers["figure1_over_valid_length"] == pytest.approx(
        10 / (2 * math.pi) * 10.5 * 0.34 / 20.0, rel=1e-12)
    assert "No point of Figure 1" in claim.numbers["finding"]
    # a rod model valid from 2 diameters on would reach the end of Figure 1
    reach = Measured({**claim.numbers, "figure1_over_valid_length": 1.01}, claim.evidence)
    assert judge(dna.SCALE, reach, "dna").verdict == "fails"
    short = Measured({**claim.numbers, "figure1_over_valid_length": 0.99}, claim.evidence)
    assert judge(dna.SCALE, short, "dna").verdict == "holds"


def test_the_scene_writes_its_row_into_the_ledger(tmp_path):
    import json

    out = dna.run(tmp_path, lambda _m: None)
    rows = json.loads((tmp_path / "claims.json").read_text())
    assert [r["id"] for r in rows] == ["caveat-dna-scale"] and rows[0]["scene"] == "dna"
    assert out.report.startswith("## DNA")
