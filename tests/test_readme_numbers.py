"""The README's findings, and the manual's pages that carry them in full (``docs/findings.md``,
``docs/how_it_works.md``), quote numbers from the generated outputs; each quoted number is
re-derived here from the committed ``paper_figures/`` (what ``python -m reproduce check`` holds
to the code), so text that drifts from the outputs fails.

Speed figures are not here: they are measurements of one machine (``tests/bench/HISTORY.md``).
"""

from __future__ import annotations

import json
import math
import re
from collections import Counter
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
    """The groups of the first occurrence of `pattern`; every later occurrence must quote the
    same numbers (a page that repeats a finding cannot drift from the one the test checks)."""
    found = [m.groups() for m in re.finditer(pattern, text)]
    assert found, f"the pages no longer say {pattern!r}"
    assert all(g == found[0] for g in found), f"{pattern!r} is quoted differently: {found}"
    return found[0]


def _agrees(quoted: str, value: float) -> bool:
    """`quoted` is `value` rounded to its printed digits (half a unit of the last one)."""
    mantissa, _, exponent = quoted.partition("e")
    decimals = len(mantissa.partition(".")[2])
    unit = 10.0 ** (int(exponent or 0) - decimals)
    return abs(float(quoted) - value) <= 0.5 * unit * (1 + 1e-9)


def test_figure1_paragraph(text: str, forensics: dict) -> None:
    got, total = _quoted(text, r"(\d+) of (\d+) plotted points are exactly")
    assert (int(got), int(total)) == (forensics["reproduced_by_best"], forensics["points"])
    # the pages quote computed − digitised (the figures' one sign); the JSON holds digitised − p*
    lo, hi = _quoted(text, r"computed − digitised lies in \[−([\d.e-]+), ([\d.e-]+)\] there")
    dev = forensics["reproduced_deviation"]
    assert _agrees(lo, dev["max"]) and _agrees(hi, -dev["min"])
    (remaining,) = _quoted(text, r"the remaining (\d+) were inserted separately")
    assert int(remaining) == forensics["points"] - forensics["reproduced_by_best"]
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


def test_tally(text: str, claims: dict) -> None:
    """The headline's counts: the paper's statements by verdict, their independent errors (one
    root cause each), and the rows of the other kinds."""
    paper = [r for r in claims.values() if r["kind"] == "paper"]
    verdicts = Counter(r["verdict"] for r in paper)
    causes = {r["root_cause"] for r in paper if r["verdict"] == "fails"}
    assert None not in causes  # every failing statement is traced to a cause
    total, holds, approx, unexplained, fails, errors = _quoted(
        text, r"[Oo]f (\d+) statements of the paper, (\d+) hold, (\d+) hold approximately, "
              r"(\d+) is true but does not explain, and (\d+) fail[,;] (?:tracing|the fails "
              r"trace) back to (\d+) independent errors")
    assert int(total) == len(paper) == sum(verdicts.values())
    assert (int(holds), int(approx), int(unexplained), int(fails)) == (
        verdicts["holds"], verdicts["holds approximately"], verdicts["true but does not explain"],
        verdicts["fails"])
    assert int(errors) == len(causes)
    checks, caveats = _quoted(text, r"(\d+) package checks? and (\d+) modelling caveats")
    kinds = Counter(r["kind"] for r in claims.values())
    assert (int(checks), int(caveats)) == (kinds["package"], kinds["caveat"])


def test_maxima(text: str, claims: dict) -> None:
    (quoted,) = _quoted(text, r"(2\.\d+)π for ν = 1\.5")
    assert _agrees(quoted, claims["rod-first-maximum"]["numbers"]["twist_over_pi"]["1.5"])
    further = claims["rod-further-maxima"]["numbers"]
    assert "falls like n⁻³ for large n only" in text
    assert abs(further["offset_exponent"] + 3) < 0.05  # the n⁻³ law over n = 2..20
    (ratio,) = _quoted(text, r"([\d.]+) times that law at n = 2")
    assert _agrees(ratio, further["offset_ratio_first"])
    assert not further["maximum_near_pi"]
    assert claims["rod-end-alignment"]["verdict"] == "true but does not explain"
    offsets = claims["rod-beta-difference"]["numbers"]["offset_near_pi"]
    lo, hi = _quoted(text, r"([\d.]+)-([\d.]+) % off π")
    assert _agrees(lo, 100 * min(offsets.values())) and _agrees(hi, 100 * max(offsets.values()))
    nus = [float(nu) for nu in offsets]
    assert "for ν = 1.1 to 10" in text and (min(nus), max(nus)) == (1.1, 10.0)


def test_crit2(text: str, claims: dict) -> None:
    galerkin = claims["ring-crit2-galerkin"]["numbers"]
    (nearest,) = _quoted(text, r"the nearest (?:single mode's load )?is (\d+) % (?:off|away)")
    assert _agrees(nearest, 100 * galerkin["nearest_single_mode_N0"])
    below, twisted = _quoted(text, r"below the converged load in (\d+) of (\d+) twisted rings")
    assert (int(below), int(twisted)) == (galerkin["crit2_below_converged_N_ge_1"],
                                          galerkin["twisted_cases"])
    assert galerkin["one_harmonic_is_upper_bound"]
    # crit2(0) = e(ν + 2), as the pages state it, on every untwisted row of the ring table
    table = pd.read_csv(OUT / "ring_table.csv")
    n0 = table[table["N"] == 0]
    assert "crit2(0) = e(ν + 2)" in text and len(n0) > 0
    assert ((n0["crit2"] - n0["e_ratio"] * (n0["nu"] + 2)).abs() <= 1e-12 * n0["crit2"]).all()
    assert claims["ring-spontaneous-instability"]["numbers"]["all_positive"]
    assert claims["ring-crit2-torsion-scaling"]["verdict"] == "fails"


def test_circular_ring_and_readings(text: str, claims: dict) -> None:
    per_e = claims["ring-circular-limit"]["numbers"]["per_e"]
    e1, iso = _quoted(text, r"out of plane (?:first, )?at .{0,40}?([\d.]+) E₁I₁/R³ for E₂ = E₁ and "
                            r"([\d.]+) for an isotropic rod")
    assert _agrees(e1, per_e["e=1"]["numerical"]["hydrostatic"])
    assert _agrees(iso, per_e["isotropic"]["numerical"]["hydrostatic"])
    # the closed form the findings quote, 9A/(4 + A/A3): A/A3 = 1/2 for E2 = E1
    assert "9E₁I₁/[(4 + E₁I₁/A₃)R³]" in text and _agrees(e1, 9 / (4 + 0.5))
    readings = ("hydrostatic", "axis", "centre", "dead")
    in_plane = _quoted(text, r"in plane at ([\d.]+), ([\d.]+), ([\d.]+) and ([\d.]+) E₁I₁/R³")
    assert all(_agrees(q, per_e["e=1"]["in_plane"][r]) for q, r in zip(in_plane, readings,
                                                                      strict=True))
    out = _quoted(text, r"out of plane at ([\d.]+), ([\d.]+), ([\d.]+) and ([\d.]+) E₁I₁/R³")
    assert all(_agrees(q, per_e["e=1"]["numerical"][r]) for q, r in zip(out, readings,
                                                                       strict=True))
    loads = claims["caveat-load-model"]["numbers"]["verdicts_per_load"]
    assert all(set(v) == set(readings) for v in loads.values())


def test_destabilises(text: str, claims: dict) -> None:
    n = claims["ring-destabilises"]["numbers"]
    wide = pd.read_csv(OUT / "ring_wide.csv")
    cases, nu_max = _quoted(text, r"toward the axis,? q_cr\(N\) < q_cr\(0\) in all (\d+) cases up "
                                  r"to ν = (\d+)")
    axis = n["per_load"]["axis"]
    assert int(cases) == axis["below"] == axis["total"] and n["every_case_lowered"]["axis"]
    assert float(nu_max) == wide["nu"].max()
    e1, iso, n_max = _quoted(text, r"ν\\?\* = ([\d.]+) \(E₂ = E₁\) or ([\d.]+) \(isotropic\) "
                                   r"for N ≤ (\d+)")
    assert _agrees(e1, n["nu_boundary"]["e=1/hydrostatic"])
    assert _agrees(iso, n["nu_boundary"]["isotropic/hydrostatic"])
    assert int(n_max) == wide["N"].max()
    limit_e1, limit_iso = _quoted(text, r"1 \+ √3 = ([\d.]+), or ([\d.]+)")
    large = n["nu_boundary_large_twist"]
    assert abs(large["e=1/hydrostatic"] - (1 + math.sqrt(3))) <= 1e-12  # the closed form
    assert _agrees(limit_e1, 1 + math.sqrt(3))
    assert _agrees(limit_iso, large["isotropic/hydrostatic"])
    # N = 2 lowers the load under pressure at every ν of the scan, above ν* included
    assert re.search(r"N = 2 still lowers (?:the load|it) at every ν of the scan", text)
    pressure = wide[wide["load"] == "hydrostatic"].pivot_table(
        index=["e_label", "nu"], columns="N", values="q")
    assert (pressure[2] < pressure[0]).all()
    assert (pressure.index.get_level_values("nu") > n["nu_boundary"]["e=1/hydrostatic"]).any()


def test_formulations_agree(text: str, claims: dict) -> None:
    assert "the independent formulations agree to ~1e-14" in text
    diffs = (claims["ring-two-formulations"]["numbers"]["max_rel_diff"],
             claims["eq-munder"]["numbers"]["munder_vs_kirchhoff"],
             claims["eq-munder"]["numbers"]["munder_vs_energy"])
    assert max(diffs) < 3e-14 and max(diffs) > 1e-15


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
