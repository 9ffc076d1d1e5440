"""`python -m reproduce check`: tolerance rules, the fast variant against the committed outputs,
and a tampered committed number (issue 13, item 3)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pandas as pd
import pytest

from reproduce import cli
from reproduce._runner import SCENE_MODULES, load_scene, run_scenes
from reproduce.check import run_check, scene_specs
from reproduce.compare import compare_json, rule_allows, rule_for

ROOT = Path(__file__).resolve().parent.parent
COMMITTED = ROOT / "paper_figures"


def test_rules():
    assert rule_allows({"rel": 1e-9}, 2.0, 2.0 + 1e-9)
    assert not rule_allows({"rel": 1e-9}, 2.0, 2.0 + 1e-8)
    assert rule_allows({"rel": 1e-12, "floor": "e"}, 1.0, 1.0 + 5e-11, est=(1e-10, 0.0))
    assert not rule_allows({"rel": 1e-12, "floor": "e"}, 1.0, 1.0 + 5e-11, est=(1e-11, 0.0))
    assert rule_allows({"abs": 1e-12}, 1e-16, 9e-13) and not rule_allows({"abs": 1e-12}, 0, 2e-12)
    assert not rule_allows({"rel": 1.0}, float("nan"), 1.0)
    assert not rule_allows({"rel": 1.0}, float("inf"), 1e300)
    assert not rule_allows("exact", "holds", "holds approximately")
    assert rule_allows("text", "p* = 1.196030794, gap 4.2e-16", "p* = 1.196030795, gap 3.1e-16")
    assert not rule_allows("text", "p* = 1.196030794", "p* = 1.196031794")
    assert not rule_allows("text", "rises: True", "rises: False")
    assert rule_for({"a_*": "ignore", "*": "exact"}, "a_seconds") == ("ignore", True)
    assert rule_for({"x": 1e-3}, "y")[1] is False


def _ledger(path: Path, verdict: str, value: float) -> Path:
    rows = [{"id": "c1", "scene": "s", "verdict": verdict, "numbers": {"p": value}},
            {"id": "c2", "scene": "other", "verdict": "fails", "numbers": {"p": 9.0}}]
    path.write_text(json.dumps(rows), encoding="utf-8")
    return path


def test_json_rows_by_owner_and_verdicts(tmp_path):
    spec = {"_owner": "scene", "*.verdict": "exact", "*.numbers.*": 1e-9, "*": "exact"}
    old = _ledger(tmp_path / "old.json", "holds", 1.0)
    same = tmp_path / "same.json"
    same.write_text(json.dumps(json.loads(old.read_text())[:1]), encoding="utf-8")
    assert compare_json("c", old, same, spec, "s").regressions == []  # other scene's row skipped
    flipped = _ledger(tmp_path / "new.json", "holds approximately", 1.0)
    assert [d.where for d in compare_json("c", old, flipped, spec, "s").regressions] == [
        "c1.verdict"]
    moved = _ledger(tmp_path / "moved.json", "holds", 1.0 + 1e-6)
    assert [d.where for d in compare_json("c", old, moved, spec, "s").regressions] == [
        "c1.numbers.p"]


def test_per_row_slack_in_csv_and_json(tmp_path):
    # an achieved error at a loose tol may move by 0.01 tol (the iteration's tolerance), and
    # only by that: the slack comes from the committed row's own tol, in CSV and JSON alike
    from reproduce.compare import compare_csv

    rule = {"rel": 1e-3, "abs": 1e-13, "per_row": ("tol", 0.01)}
    spec = {"err": rule, "*": "exact"}
    old, near, far = (tmp_path / f"{k}.csv" for k in ("old", "near", "far"))
    pd.DataFrame({"tol": [1e-12, 1e-6], "err": [1e-14, 8.1e-11]}).to_csv(old, index=False)
    pd.DataFrame({"tol": [1e-12, 1e-6], "err": [1e-14, 9.0e-9]}).to_csv(near, index=False)
    pd.DataFrame({"tol": [1e-12, 1e-6], "err": [5e-13, 8.1e-11]}).to_csv(far, index=False)
    assert compare_csv("t", old, near, spec).regressions == []
    assert [d.where for d in compare_csv("t", old, far, spec).regressions] == ["row 2, err"]
    rows = {"rows": [{"tol": 1e-12, "err": 1e-14}, {"tol": 1e-6, "err": 8.1e-11}]}
    jspec = {"rows.*.err": rule, "*": "exact"}
    (tmp_path / "old.json").write_text(json.dumps(rows), encoding="utf-8")
    for i, err, bad in ((1, 9.0e-9, []), (1, 2e-8, ["rows.1.err"]), (0, 5e-13, ["rows.0.err"])):
        moved = json.loads(json.dumps(rows))
        moved["rows"][i]["err"] = err
        (tmp_path / "new.json").write_text(json.dumps(moved), encoding="utf-8")
        got = compare_json("j", tmp_path / "old.json", tmp_path / "new.json", jspec, "s")
        assert [d.where for d in got.regressions] == bad


def test_an_achieved_error_must_still_meet_its_tol(tmp_path):
    # the digits of an achieved error at a loose tol depend on the engine (numpy 2.5 against
    # 2.4: 4.49e-9 against 2.40e-10 at tol 1e-4): it may move anywhere below its tol, not above;
    # a fixed-resolution error (no tol) is held to its printed digits
    from reproduce.compare import compare_csv
    from reproduce.convergence import CHECK

    spec = CHECK["convergence.csv"]
    old, new = tmp_path / "old.csv", tmp_path / "new.csv"
    header = "method,tol,resolution,unknowns_per_field,rel_error,seconds\n"
    rows = ["collocation (tol=0.0001),0.0001,70,35,{e1},0.1\n",
            "collocation (fixed n),,16,8,{e2},0.1\n"]
    old.write_text(header + rows[0].format(e1=2.40421e-10) + rows[1].format(e2=3.5e-7))
    for e1, e2, bad in ((4.49208e-09, 3.5e-7, []),
                        (2e-4, 3.5e-7, ["row 2, rel_error"]),
                        (2.40421e-10, 3.5e-7 * (1 + 1e-4), ["row 3, rel_error"])):
        new.write_text(header + rows[0].format(e1=e1) + rows[1].format(e2=e2))
        assert [d.where for d in compare_csv("c", old, new, spec).regressions] == bad


def test_fd_round_off_slack_grows_with_the_unknowns(tmp_path):
    # finite differences at N = 16383 unknowns: round-off moved the error by 1.8e-11 between
    # scipy versions (allowed: 16 eps N = 5.8e-11); the same move at N = 255 is a regression
    from reproduce.compare import compare_csv
    from reproduce.convergence import CHECK

    spec = CHECK["convergence.csv"]
    old, new = tmp_path / "old.csv", tmp_path / "new.csv"
    header = "method,tol,resolution,unknowns_per_field,rel_error,seconds\n"
    old.write_text(header + "finite differences,,16384,16383,3.66818e-09,1\n"
                   "finite differences,,256,255,3.66818e-09,1\n")
    new.write_text(header + "finite differences,,16384,16383,3.68647e-09,1\n"
                   "finite differences,,256,255,3.68647e-09,1\n")
    assert [d.where for d in compare_csv("c", old, new, spec).regressions] == [
        "row 3, rel_error"]


def test_garbled_or_missing_committed_cell_is_reported_once_as_itself(fresh_figure1, tmp_path,
                                                                       capsys):
    csv = _copy_committed_figure1(tmp_path / "committed", fresh_figure1)
    lines = csv.read_text(encoding="utf-8").splitlines(keepends=True)
    head = lines[0].rstrip("\n").split(",")
    col = head.index("p_star_computed")
    for i, text in ((100, "abc"), (200, "")):
        cells = lines[i].rstrip("\n").split(",")
        cells[col] = text
        lines[i] = ",".join(cells) + "\n"
    csv.write_text("".join(lines), encoding="utf-8")
    assert run_check(["figure1"], csv.parent, lambda m: None, fresh=fresh_figure1) == 1
    out = capsys.readouterr().out
    table = [line for line in out.splitlines() if line.startswith("| figure1_comparison.csv")]
    assert len(table) == 2, table
    assert "| row 101, p_star_computed | abc |" in table[0]
    assert "| row 201, p_star_computed | (missing) |" in table[1]
    assert "2 regression(s)" in out


def test_family_label_at_a_tie_compares_as_a_tie(tmp_path):
    # at nu - 1 = 1e-12 the two families' loads agree to 1e-20: which one a solver names is
    # not a result; at (3, 1.5) they differ by far more than the tol, and a flip is a regression
    from reproduce.compare import compare_csv
    from reproduce.extremes import CHECK

    spec = {"family": CHECK["extremes_grid.csv"]["family"], "*": "exact"}
    old, new = tmp_path / "old.csv", tmp_path / "new.csv"
    old.write_text("twist_angle,nu,family\n1000.0,1.000000000001,symmetric\n"
                   "3.0,1.5,symmetric\n")
    new.write_text("twist_angle,nu,family\n1000.0,1.000000000001,antisymmetric\n"
                   "3.0,1.5,antisymmetric\n")
    got = compare_csv("g", old, new, spec)
    assert [d.where for d in got.differences] == ["row 2, family", "row 3, family"]
    assert [d.where for d in got.regressions] == ["row 3, family"]
    assert "tie" in got.differences[0].allowed


def test_a_corrupt_json_is_a_clean_fault(tmp_path):
    from reproduce.io import OutputFileError

    good = _ledger(tmp_path / "good.json", "holds", 1.0)
    bad = tmp_path / "bad.json"
    bad.write_text('[{"id": "c1", ', encoding="utf-8")  # cut short
    with pytest.raises(OutputFileError, match=r"bad\.json is not valid JSON"):
        compare_json("c", good, bad, {"*": "exact"}, "s")


@pytest.fixture(scope="module")
def fresh_figure1(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("fresh")
    run_scenes(["figure1"], out, lambda msg: None)
    return out


def test_fast_check_figure1_against_committed(fresh_figure1, capsys):
    if not (COMMITTED / "figure1_comparison.csv").exists():
        pytest.skip("no committed paper_figures/ in this checkout")
    assert run_check(["figure1"], COMMITTED, lambda m: None, fresh=fresh_figure1) == 0
    assert "0 regression(s)" in capsys.readouterr().out


def _copy_committed_figure1(dst: Path, source: Path) -> Path:
    (dst / "sections").mkdir(parents=True)
    for name in ("figure1_comparison.csv", "sections/figure1.json", "claims.json",
                 "figure1_forensics.json"):
        shutil.copy(source / name, dst / name)
    return dst / "figure1_comparison.csv"


def test_tampered_committed_number_fails(fresh_figure1, tmp_path, capsys):
    csv = _copy_committed_figure1(tmp_path / "committed", fresh_figure1)
    table = pd.read_csv(csv)
    table.loc[100, "p_star_computed"] *= 1 + 1e-6
    table.to_csv(csv, index=False, float_format="%.12g")
    assert run_check(["figure1"], csv.parent, lambda m: None, fresh=fresh_figure1) == 1
    out = capsys.readouterr().out
    assert "row 102, p_star_computed" in out and "FAIL" in out


def test_cli_check_exit_status(tmp_path, capsys, fresh_figure1):
    _copy_committed_figure1(tmp_path / "committed", fresh_figure1)
    assert cli.main(["check", "figure1", "--against", str(tmp_path / "committed"), "-q"]) == 0
    assert cli.main(["check", "figure1", "--against", str(tmp_path / "nowhere"), "-q"]) == 2
    assert "nowhere" in capsys.readouterr().err


def test_every_written_data_file_and_column_is_declared():
    # what each scene wrote last time (sections/NAME.json) must be named in its CHECK, and each
    # CSV column must match a pattern: undeclared outputs would be compared at the default only
    if not (COMMITTED / "sections").is_dir():
        pytest.skip("no committed paper_figures/ in this checkout")
    for name in SCENE_MODULES:
        check = load_scene(name).CHECK
        specs = scene_specs(name, COMMITTED)
        for file, spec in specs.items():
            assert file in check or file.startswith("sections/"), (name, file)
            if file.endswith(".csv") and (COMMITTED / file).exists():
                for col in pd.read_csv(COMMITTED / file, nrows=1).columns:
                    assert rule_for(spec, col)[1], (name, file, col)


def test_every_reading_of_the_ring_load_is_checked_alike():
    # ring_table.csv has one column per reading of the load for each quantity: the four readings
    # are rows of one kind, so each quantity's rule must be the same for all of them (with the
    # reading's own columns named in it), and a critical load is never compared "exact" (it
    # moves in its last bits with the machine's eigensolver).
    from reproduce.ring import CHECK
    from spectral_rod import RING_LOADS

    if not (COMMITTED / "ring_table.csv").exists():
        pytest.skip("no committed paper_figures/ in this checkout")
    spec = CHECK["ring_table.csv"]
    columns = pd.read_csv(COMMITTED / "ring_table.csv", nrows=1).columns
    quantities = {c.removesuffix(f"_{load}") for c in columns for load in RING_LOADS
                  if c.endswith(f"_{load}")}
    assert "q" in quantities
    for quantity in quantities:
        rules = {load: repr(rule_for(spec, f"{quantity}_{load}")[0]).replace(load, "LOAD")
                 for load in RING_LOADS}
        assert len(set(rules.values())) == 1, (quantity, rules)
    assert all(rule_for(spec, f"q_{load}")[0] != "exact" for load in RING_LOADS)
