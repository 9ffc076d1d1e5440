"""The README's findings, and the manual's pages that carry them in full (``docs/findings.md``,
``docs/how_it_works.md``), quote numbers from the generated outputs; each quoted number is
re-derived here from the committed ``paper_figures/`` (what ``python -m reproduce check`` holds
to the code), so text that drifts from the outputs fails.

Speed figures are not here: they are measurements of one machine (``tests/bench/HISTORY.md``).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "paper_figures"
README = ROOT / "README.md"
#: the pages whose text the quoted numbers are searched in, read as one
PAGES = (README, ROOT / "docs" / "findings.md", ROOT / "docs" / "how_it_works.md")

pytestmark = pytest.mark.skipif(not (OUT / "claims.json").exists()
                                or not all(p.exists() for p in PAGES),
                                reason="needs a source checkout with paper_figures/ and docs/")


@pytest.fixture(scope="module")
def text() -> str:
    # one line: no wrapping issues
    return " ".join(" ".join(p.read_text(encoding="utf-8").split()) for p in PAGES)


@pytest.fixture(scope="module")
def forensics() -> dict:
    return json.loads((OUT / "figure1_forensics.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def claims() -> dict:
    rows = json.loads((OUT / "claims.json").read_text(encoding="utf-8"))
    return {r["id"]: r for r in rows}


def _quoted(text: str, pattern: str) -> tuple[str, ...]:
    m = re.search(pattern, text)
    assert m, f"README no longer says {pattern!r}"
    return m.groups()


def _agrees(quoted: str, value: float) -> bool:
    """`quoted` is `value` rounded to its printed digits (half a unit of the last one)."""
    mantissa, _, exponent = quoted.partition("e")
    decimals = len(mantissa.partition(".")[2])
    unit = 10.0 ** (int(exponent or 0) - decimals)
    return abs(float(quoted) - value) <= 0.5 * unit * (1 + 1e-9)


def test_figure1_paragraph(text: str, forensics: dict) -> None:
    got, total = _quoted(text, r"(\d+) of (\d+) plotted points are exactly")
    assert (int(got), int(total)) == (forensics["reproduced_by_best"], forensics["points"])
    lo, hi = _quoted(text, r"lies in \[−([\d.e-]+), ([\d.e-]+)\] there")
    dev = forensics["reproduced_deviation"]
    assert _agrees(lo, -dev["min"]) and _agrees(hi, dev["max"])
    others, fails = _quoted(text, r"The other (\d+) were inserted .*?; that procedure fails "
                                  r"at (\d+) of them")
    clusters = forensics["clusters"]
    assert int(others) == forensics["points"] - forensics["reproduced_by_best"]
    assert int(others) == sum(c["points"] for c in clusters)  # every one in a cluster
    assert int(fails) == sum(c["caused_points"] for c in clusters)
    window = (r"imaginary-β₁ window \((\d+) points, (\d+) of them on straight lines .*?, "
              r"up to ([\d.e-]+) off\)")
    flat = r"one scan step \((\d+) points, (\d+) of them printed flat, up to ([\d.e-]+) off\)"
    for kind, pattern, shape in (("imaginary-beta1 window", window, "sloped line"),
                                 ("double root in one scan step", flat, "flat")):
        mine = [c for c in clusters if c["kind"] == kind]
        n, shaped, dmax = _quoted(text, pattern)
        assert int(n) == sum(c["points"] for c in mine)
        assert int(shaped) == sum(c["printed_as"][shape] for c in mine)
        assert _agrees(dmax, max(c["max_abs_deviation"] for c in mine))
    missing = forensics["missing_points"]
    assert "Eight grid points are missing: six in ν = 1.1's window" in text and len(missing) == 8
    w = forensics["windows"]["1.1"]
    in_window = [m for m in missing
                 if m["nu"] == 1.1 and w["omega_a"] < m["twist_angle"] < w["omega_b"]]
    assert len(in_window) == 6
    at_6275 = sorted(m["nu"] for m in missing if abs(m["twist_angle"] - 6.275) < 1e-9)
    assert at_6275 == [1.1, 1.3] and "Ω = 6.275 for ν = 1.1 and 1.3" in text


def test_maximum_and_ring_numbers(text: str, claims: dict) -> None:
    (quoted,) = _quoted(text, r"(2\.\d+)π for ν = 1\.5")
    assert _agrees(quoted, claims["rod-first-maximum"]["numbers"]["twist_over_pi"]["1.5"])
    n = claims["ring-destabilises"]["numbers"]
    cases, e1, iso = _quoted(text, r"in all (\d+) cases up to ν = 100; for pressure, only below "
                                   r"ν\* = ([\d.]+) \(e = 1\) or ([\d.]+) \(isotropic\)")
    assert int(cases) == n["fewest_cases"] and n["every_case_lowered"]["axis"]
    assert _agrees(e1, n["nu_boundary"]["e=1/hydrostatic"])
    assert _agrees(iso, n["nu_boundary"]["isotropic/hydrostatic"])
    table = pd.read_csv(OUT / "ring_table.csv")
    circ = table[(table["nu"] == 1.0) & (table["N"] == 0) & (table["e_label"] == "e=1")]
    (load,) = _quoted(text, r"the true load is out-of-plane, ([\d.]+) E₁I₁/R³ \(e = 1\)")
    assert _agrees(load, float(circ["q_hydrostatic"].iloc[0]))
    assert circ["kind_hydrostatic"].iloc[0] == "out-of-plane"


def test_tol_trade_numbers(text: str) -> None:
    """The achieved errors and the error model's pessimism (tol / achieved) the README quotes
    for the Figure 1 batch; the cost ratios are timings of one machine (not checked)."""
    trade = pd.read_csv(OUT / "convergence_tol_trade.csv").set_index("tol")
    e4, e2 = _quoted(text, r"with achieved errors ([\d.e-]+) and ([\d.e-]+)")
    assert _agrees(e4, trade.loc[1e-4, "batch_max_rel_error"])
    assert _agrees(e2, trade.loc[1e-2, "batch_max_rel_error"])
    p4, p2 = _quoted(text, r"pessimistic by ~([\d.e]+) at 1e-4 and ~([\d.e]+) at 1e-2")
    assert _agrees(p4, 1e-4 / trade.loc[1e-4, "batch_max_rel_error"])
    assert _agrees(p2, 1e-2 / trade.loc[1e-2, "batch_max_rel_error"])
