"""The instruction-count tool of the benchmarks (``tests/bench/instruction_counts.py``): its
statements run against the current API and its reading of callgrind's output is right, checked
without valgrind (the counts themselves need it and are not part of the default run)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

sys.path.insert(0, str(Path(__file__).parent / "bench"))
import instruction_counts as ic


def test_every_pattern_runs_and_counts_its_points() -> None:
    ns: dict[str, object] = {}
    exec(ic.SETUP, ns)  # the tool's own preamble
    expected = {"baseline": 40, "batches of 10": 600, "brentq search": 9, "scalar loop": 201}
    for name, stmt, points in [*((k, *v) for k, v in ic.PATTERNS.items()), ic.TRADE]:
        eval(stmt, ns)  # raises if the API the tool calls has changed
        n = eval(points, ns)
        assert n == expected.get(name, 1201), name


def test_count_divides_the_collected_instructions_by_the_points(monkeypatch) -> None:
    seen = {}

    def fake_run(cmd, **kwargs):
        seen["cmd"] = cmd
        return SimpleNamespace(stdout="POINTS 1201\n",
                               stderr="==7== Events    : Ir\n==7== Collected : 170178998\n")

    monkeypatch.setattr(subprocess, "run", fake_run)
    assert ic.count("figure1 batch") == pytest.approx(170178998 / 1201)
    assert seen["cmd"][:3] == ["valgrind", "--tool=callgrind", "--instr-atstart=no"]
    assert "critical_load(tw, nv)" in seen["cmd"][-1]  # the pattern's statement, counted


def test_unknown_pattern_is_refused(monkeypatch) -> None:
    monkeypatch.setattr(ic.shutil, "which", lambda name: f"/usr/bin/{name}")
    with pytest.raises(SystemExit, match="unknown pattern"):
        ic.main(["figure 1"])


def test_each_pattern_is_counted_once(monkeypatch, capsys) -> None:
    calls = []
    monkeypatch.setattr(ic.shutil, "which", lambda name: f"/usr/bin/{name}")
    monkeypatch.setattr(ic, "count", lambda name: calls.append(name) or 1000.0 * len(calls))
    ic.main(["figure1 batch", ic.TRADE[0]])
    assert calls == ["baseline", "figure1 batch", ic.TRADE[0]]  # the batch serves the trade too
    assert "1.500 of tol 1e-12" in capsys.readouterr().out  # 3000 / 2000


def test_inclusive_count_reads_the_first_matching_function() -> None:
    annotated = """--------
170,278,855 (100.0%)  PROGRAM TOTALS
140,313,660 (82.40%)  ???:ufunc_generic_vectorcall [libnumpy]
 65,604,019 (38.53%)  ???:void inv<double>(char**, long const*, long const*, void*) [umath]
  1,000 ( 0.00%)  ???:void inv<double>'2 [umath]
"""
    assert ic.inclusive_count(annotated, ic.INVERSE_SYMBOL) == 65604019
    assert ic.inclusive_count(annotated, "no such function") == 0


def test_inverse_share_prints_the_ratio_were_the_inverse_free(monkeypatch, capsys) -> None:
    monkeypatch.setattr(ic.shutil, "which", lambda name: f"/usr/bin/{name}")
    monkeypatch.setattr(ic, "count", lambda name: 4000.0)  # the baseline, a point
    monkeypatch.setattr(ic, "profile", lambda name, symbol: (200.0, 0.5))
    ic.main([ic.INVERSE_FLAG])
    out = capsys.readouterr().out
    assert "50.0% of its 200 instructions" in out and "were it free, 40.0x" in out  # 4000/100
