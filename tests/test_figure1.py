"""Figure 1: digitised data, agreement with the collocation solver, the scene and the CLI."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from reproduce import figure1
from reproduce.__main__ import main
from spectral_rod.figure1.data import figure1_path, load_figure1, parse_figure1

ROOT = Path(__file__).resolve().parent.parent
CSV = figure1_path()
TEX = ROOT.parent / "shared" / "paper" / "drozdov-rabin-buckling.tex"


@pytest.fixture(scope="module")
def digitised():
    return load_figure1(CSV)


def test_csv_is_regenerated_from_the_paper(digitised):
    if not TEX.exists():
        pytest.skip(f"paper source not found at {TEX}")
    parsed = parse_figure1(TEX.read_text(encoding="utf-8"))
    assert len(parsed) == len(digitised) == TEX.read_text().count(r"\circle*")
    assert np.allclose(parsed["p_star"], digitised["p_star"], rtol=0, atol=1e-12)
    assert np.allclose(parsed["twist_angle"], digitised["twist_angle"], rtol=0, atol=1e-12)


def test_digitised_curves_are_the_papers(digitised):
    assert sorted(digitised["nu"].unique()) == [1.1, 1.3, 1.5]
    assert digitised.groupby("curve").size().min() > 390
    end = digitised[digitised["twist_angle"] == 10.0].set_index("nu")["p_star"]
    assert end[1.1] < end[1.3] < end[1.5]


def test_collocation_reproduces_figure1(digitised):
    table = figure1.comparison_table(digitised)
    summary = figure1.deviation_summary(table)
    assert (summary["rms"] <= figure1.RMS_LIMIT).all(), summary
    assert (summary["max_abs"] <= figure1.MAX_LIMIT).all(), summary


def test_missing_or_corrupt_reference_data_is_named(tmp_path, digitised):
    with pytest.raises(FileNotFoundError, match=r"nope\.csv"):
        load_figure1(tmp_path / "nope.csv")
    bad = tmp_path / "bad.csv"
    digitised.drop(columns="p_star").to_csv(bad, index=False)
    with pytest.raises(ValueError, match=r"bad\.csv.*p_star"):
        load_figure1(bad)
    bad2 = tmp_path / "bad2.csv"
    d = digitised.copy()
    d.loc[5, "p_star"] = 2.0
    d.to_csv(bad2, index=False)
    with pytest.raises(ValueError, match=r"bad2\.csv"):
        load_figure1(bad2)


def test_scene_writes_figures_csv_and_report(tmp_path):
    assert main(["figure1", "--out", str(tmp_path)]) == 0
    for name in ("figure1.png", "figure1.pdf", "figure1_comparison.csv", "report.md",
                 "figure1_forensics.png", "figure1_forensics.json", "claims.json"):
        assert (tmp_path / name).stat().st_size > 0, name
    fx = json.loads((tmp_path / "figure1_forensics.json").read_text())
    assert {"hypotheses", "best", "clusters", "missing_points"} <= set(fx)
    rows = json.loads((tmp_path / "claims.json").read_text())
    row = next(r for r in rows if r["id"].startswith("fig1-"))
    assert row["scene"] == "figure1" and row["methods"] and row["verdict"]
    table = pd.read_csv(tmp_path / "figure1_comparison.csv")
    assert len(table) == len(load_figure1(CSV))
    report = (tmp_path / "report.md").read_text()
    assert "rms" in report and "numpy" in report and "commit" in report.lower()
    assert list(tmp_path.glob(".*")) == []  # no temporary files left behind


def test_cli_list_and_bad_usage(capsys):
    assert main(["list"]) == 0
    assert "figure1" in capsys.readouterr().out
    assert main(["nonsense"]) == 2
    assert "usage" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exc:
        main(["figure1", "--bogus"])
    assert exc.value.code == 2


def test_unwritable_output_directory_is_a_clear_error(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    proc = subprocess.run([sys.executable, "-m", "reproduce", "figure1", "--out",
                           str(blocker / "sub")], capture_output=True, text=True, cwd=ROOT)
    assert proc.returncode == 2
    assert "not writable" in proc.stderr
