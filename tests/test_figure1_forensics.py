"""Figure 1 point by point (spectral_rod.figure1.forensics, issue 12).

The model's claims are recomputed here from its stated rule (not read from its output); the
cluster finder is run on synthetic data with known patches; a cluster may only be explained
by the imaginary-beta_1 window where the window contains it.
"""

from __future__ import annotations

import dataclasses
import math
import re
from importlib import resources
from pathlib import Path

import mpmath as mp
import numpy as np
import pandas as pd
import pytest

from reproduce import figure1
from reproduce.ledger import VERDICTS, Claim
from spectral_rod.errors import ReferenceDataError
from spectral_rod.figure1.data import (
    check_picture_matches,
    figure1_path,
    figure1_picture,
    load_figure1,
    picture_points,
)
from spectral_rod.figure1.forensics import (
    MERGE_GAP,
    analyse_figure1,
    determinant_product,
    explain_cluster,
    family_loads,
    find_runs,
    fit_quantisation,
    fit_switch,
    missing_grid_points,
    off_grid_runs,
    picture_environment,
    picture_lines,
    printed,
    quantise,
    scan_sign_change,
    site_physics,
    straight_line,
)
from spectral_rod.figure1.forensics.scan import REPORT_RULES
from spectral_rod.rod.characteristic import determinants, family_critical_load
from spectral_rod.rod.characteristic_mode import boundary_determinant_4x4
from spectral_rod.rod.closed_form import crossing_closed_form, imaginary_beta1_window
from spectral_rod.rod.critical import critical_load
from spectral_rod.rod.wavenumbers import characteristic_roots

ROOT = Path(__file__).resolve().parent.parent


def _x_minus_mp(p: float, om: float, nu: float) -> float:
    """beta_1^2 L^2 at load p, in mpmath (30 digits)."""
    with mp.workdps(30):
        lam = mp.pi**2 * mp.mpf(p)
        return float(characteristic_roots(lam, lam / mp.mpf(nu), mp.mpf(om), sqrt=mp.sqrt)[0])
CSV = figure1_path()
PICTURE = Path(str(resources.files("spectral_rod") / "data" / "figure1_picture.tex"))
#: the paper next to the project (main checkout) or next to the worktrees' directory
PAPER = next((d / "shared" / "paper" / "drozdov-rabin-buckling.tex" for d in
              (ROOT.parent, ROOT.parent.parent)
              if (d / "shared" / "paper" / "drozdov-rabin-buckling.tex").exists()),
             ROOT.parent / "shared" / "paper" / "drozdov-rabin-buckling.tex")
PI2 = math.pi**2


@pytest.fixture(scope="module")
def points() -> pd.DataFrame:
    return load_figure1(CSV)


@pytest.fixture(scope="module")
def truth(points) -> np.ndarray:
    return critical_load(points["twist_angle"].to_numpy(), points["nu"].to_numpy(), tol=1e-12)


@pytest.fixture(scope="module")
def fx(points, truth):
    lines = picture_lines(PICTURE.read_text(encoding="utf-8"))
    return analyse_figure1(points, lines, p_true=truth)


def _hundredths(y):
    """Two-decimal printing, written out again here (round half up) for independence."""
    return np.floor(np.asarray(y, dtype=float) * 100 + 0.5 + 1e-9).astype(int)


# ------------------------------------------------------------------------------------------
# the model reproduces what it claims (recomputed from the rule)
# ------------------------------------------------------------------------------------------

def test_best_model_count_recomputed_from_its_rule(fx, points, truth):
    lo, hi = fx.runs["low"], fx.runs["high"]
    assert (lo.variable, lo.step, hi.variable, hi.step) == \
        ("lambda - nu Omega^2", 0.001, "lambda", 0.002)
    om, nu, y = (points[c].to_numpy() for c in ("twist_angle", "nu", "picture_y"))
    lam = PI2 * truth
    # the stated rule: lambda - nu Omega^2 = 0.001 ceil(...) up to the window, lambda = 0.002
    # ceil(...) beyond it, no value inside the window (beta_1 imaginary: no real-beta root)
    low = (0.001 * np.ceil((lam - nu * om**2) / 0.001) + nu * om**2) / PI2
    high = 0.002 * np.ceil(lam / 0.002) / PI2
    w = {n: imaginary_beta1_window(n) for n in (1.1, 1.3, 1.5)}
    below = np.array([t <= w[n].omega_a for t, n in zip(om, nu, strict=True)])
    above = np.array([t >= w[n].omega_b for t, n in zip(om, nu, strict=True)])
    model = np.where(below, low, np.where(above, high, np.nan))
    # both family roots in one 0.002 step (near the crossings, closed form): the scan sees no
    # sign change, no value; each family's root from the mpmath characteristic equation
    for i in np.flatnonzero(above):
        if min(abs(om[i] - crossing_closed_form(k, nu[i]).twist) for k in (2, 3)) < 0.2:
            lam_f = [PI2 * float(family_critical_load(f, om[i], nu[i], dps=20,
                                                       p_max=0.5 * (1 + nu[i])).p_star)
                     for f in ("symmetric", "antisymmetric")]
            if math.ceil(lam_f[0] / 0.002) == math.ceil(lam_f[1] / 0.002):
                model[i] = np.nan
    ok = np.isfinite(model) & (_hundredths(400 * (np.nan_to_num(model) - 1)) == _hundredths(y))
    assert ok.sum() == fx.points["ok"].sum() == fx.to_json()["reproduced_by_best"]
    for n in (1.1, 1.3, 1.5):
        sel = nu == n
        assert ok[sel].sum() == fx.points["ok"][sel].sum()
    # the claim: more than 94 % of the points are reproduced exactly
    assert ok.mean() > 0.94
    assert (ok == fx.points["ok"].to_numpy()).all()


def test_best_model_is_the_same_under_exact_binary_rounding(fx, points):
    """quantisation.printed rounds half away from 0 in decimal (a tie like 18.975, stored as
    18.97499..., goes up); rounding the stored double exactly (Decimal, half up) is the other
    convention. The best model must reproduce the same points under both."""
    from decimal import ROUND_HALF_UP, Decimal

    def exact(v: float) -> int:
        return int((Decimal(v) * 100).quantize(Decimal(1), rounding=ROUND_HALF_UP))

    y_model = fx.points["y_model"].to_numpy()
    picture = [int(Decimal(str(v)) * 100) for v in points["picture_y"]]
    ok = np.array([math.isfinite(m) and exact(float(m)) == q
                   for m, q in zip(y_model, picture, strict=True)])
    assert (ok == fx.points["ok"].to_numpy()).all()


def test_every_point_is_accounted_for(fx):
    assert len(fx.unaccounted()) == 0
    assert all(c["explained"] for c in fx.clusters)
    assert all(m["explained"] for m in fx.missing_points)
    j = fx.to_json()
    assert j["reproduced_by_best"] + j["in_clusters"] >= j["points"]
    assert {"name", "variable", "step", "rounding", "reproduced_exactly", "points"} <= \
        set(j["hypotheses"][0])
    assert {"nu", "twist_from", "twist_to", "points", "max_abs_deviation", "explanation"} <= \
        set(j["clusters"][0])
    assert {"nu", "twist_angle", "explanation"} <= set(j["missing_points"][0])
    assert j["best"] in {h["name"] for h in j["hypotheses"]}


def test_print_rounding_alone_does_not_explain_the_data(fx):
    # nearest rounding of y to its print quantum is one of the hypotheses on the grid
    h = next(h for h in fx.hypotheses if h.name == "nearest(y, 0.025)")
    assert h.ok.sum() < 0.2 * h.ok.size
    near = [h for h in fx.hypotheses if h.rounding == "nearest"]
    assert max(h.ok.sum() for h in near) < 0.5 * fx.best.ok.sum()


def test_switch_between_runs_is_the_window(fx):
    for nu, rec in fx.switches.items():
        w = imaginary_beta1_window(nu)
        assert rec["low_run_last_reproduced"] <= w.omega_a
        assert rec["high_run_first_reproduced"] >= w.omega_b
        assert rec["high_run_starts_at_window"]
        assert rec["low_run_met_imaginary_beta1"] == rec["high_run_met_imaginary_beta1"] == 0


# ------------------------------------------------------------------------------------------
# the pieces, against independent formulations
# ------------------------------------------------------------------------------------------

def test_determinant_product_has_the_sign_of_the_papers_4x4_determinant():
    for om, nu in ((0.7, 1.5), (5.0, 1.1), (9.4, 1.3)):
        for p in (1.01, 1.04, 1.12, 1.2):
            det = boundary_determinant_4x4(mp.pi**2 * mp.mpf(p), mp.mpf(om), mp.mpf(nu))
            prod = float(determinant_product(np.array([p]), om, nu)[0])
            assert np.sign(float(det)) == np.sign(prod)
            d_s, d_a = determinants(p, om, nu)
            assert prod == pytest.approx(float(d_s * d_a), rel=1e-12)


def test_real_wavenumbers_are_undefined_exactly_where_beta1_is_imaginary():
    p = np.linspace(1.0, 1.4, 61)  # X_- < 0 for p < nu Omega^2 / pi^2 = 1.278
    om, nu = 2.9, 1.5
    d = determinant_product(p, om, nu, real_wavenumbers=True)
    xm = np.array([_x_minus_mp(q, om, nu) for q in p])
    assert (np.isnan(d) == (xm < 0)).all() and (xm < 0).any() and (xm > 0).any()


def test_family_loads_give_the_reference_p_star(reference):
    for om, nu in ((0.5, 1.5), (3.0, 1.1), (6.275, 1.3), (9.43, 1.5)):
        p_s, p_a = family_loads(np.array([om]), np.array([nu]))
        assert min(p_s[0], p_a[0]) == pytest.approx(reference(om, nu), abs=1e-12)


def test_scan_upper_end_is_the_ceil_of_the_root_away_from_failures(reference):
    om = np.array([0.5, 4.0, 7.3])
    for nu in (1.1, 1.5):
        sc = scan_sign_change(om, np.full(3, nu), "lambda", 0.002)
        lam = np.array([PI2 * reference(t, nu) for t in om])
        assert np.allclose(sc.upper, 0.002 * np.ceil(lam / 0.002), rtol=0, atol=1e-12)
        assert (sc.lower < lam).all() and (lam <= sc.upper).all()


def test_each_report_rule_reports_within_its_band(reference):
    # a rule's band (report_band) and its reported value are declared together: they must agree
    om, nu, step = np.array([0.5, 4.0, 7.3]), 1.5, 0.002
    sc = scan_sign_change(om, np.full(3, nu), "lambda", step)
    lam = np.array([PI2 * reference(t, nu) for t in om])
    assert [r.name for r in REPORT_RULES] == ["upper", "lower", "midpoint", "linear"]
    for rule in REPORT_RULES:
        off = (sc.report(rule.name) - lam) / step
        assert (off >= rule.band[0] - 1e-9).all() and (off <= rule.band[1] + 1e-9).all(), rule
    with pytest.raises(ValueError, match="rule must be 'upper', 'lower', 'midpoint' or 'linear'"):
        sc.report("nearest")


def test_scan_fails_where_both_family_roots_share_a_step():
    # the 2 pi crossing (closed form): just below it both roots lie within 1e-4 of each other
    c = crossing_closed_form(2, 1.1)
    om = np.array([c.twist - 0.008])
    p_s, p_a = family_loads(om, np.array([1.1]))
    assert np.ceil(PI2 * p_s[0] / 0.002) == np.ceil(PI2 * p_a[0] / 0.002)
    sc = scan_sign_change(om, np.array([1.1]), "lambda", 0.002)
    assert np.isnan(sc.upper[0])
    # one step further from the crossing the roots separate and the scan finds the root
    sc = scan_sign_change(om - 0.1, np.array([1.1]), "lambda", 0.002)
    assert np.isfinite(sc.upper[0])


def test_quantise_and_printed():
    assert quantise(np.array([0.0031]), 0.002, "ceil")[0] == pytest.approx(0.004)
    assert quantise(np.array([0.0031]), 0.002, "floor")[0] == pytest.approx(0.002)
    assert quantise(np.array([-0.0031]), 0.002, "truncate")[0] == pytest.approx(-0.002)
    assert quantise(np.array([0.003]), 0.002, "nearest")[0] == pytest.approx(0.004)
    assert list(printed(np.array([18.975, 0.004, 27.8444]))) == [1898.0, 0.0, 2784.0]
    with pytest.raises(ValueError, match="rounding"):
        quantise(np.array([1.0]), 0.1, "up")


def test_fit_quantisation_recovers_a_known_step_and_rule():
    om = np.linspace(3.5, 9.0, 120)
    nu = np.full(om.size, 1.3)
    p = critical_load(om, nu, tol=1e-12)
    y = printed(400 * (0.005 * np.ceil(PI2 * p / 0.005) / PI2 - 1)) / 100
    fits = {r: fit_quantisation(p, om, nu, y, "lambda", r) for r in ("nearest", "floor", "ceil")}
    assert fits["ceil"].step == 0.005 and fits["ceil"].ok.all()
    assert max(fits["nearest"].ok.sum(), fits["floor"].ok.sum()) < 0.8 * om.size


# ------------------------------------------------------------------------------------------
# clusters on synthetic data
# ------------------------------------------------------------------------------------------

def _synthetic(patches: list[tuple[int, int]], keep: tuple[int, ...] = ()):
    """A known curve on a known grid, printed by a known rule, with patches replaced."""
    om = 0.025 * np.arange(1, 401)
    p = 1.0 + 0.05 * om**2 / (1.0 + om**2) + 0.002 * np.sin(3 * om)
    model = printed(400 * (0.002 * np.ceil(PI2 * p / 0.002) / PI2 - 1)) / 100
    data = model.copy()
    for first, last in patches:
        data[first:last + 1] = model[first:last + 1] + 0.03 + 0.01 * np.arange(last - first + 1)
    data[list(keep)] = model[list(keep)]  # chance agreements inside a patch
    return om, p, data


def test_cluster_finder_recovers_inserted_patches():
    patches = [(40, 49), (120, 123), (300, 300), (350, 371)]
    om, p, data = _synthetic(patches, keep=(355, 356))
    nu = np.full(om.size, 1.3)
    # the model is fitted from the patched data (step and rule), then the runs found
    fit = max((fit_quantisation(p, om, nu, data, "lambda", r) for r in ("nearest", "ceil")),
              key=lambda h: h.ok.sum())
    assert (fit.step, fit.rounding) == (0.002, "ceil")
    assert find_runs(~fit.ok) == patches
    # a longer gap than MERGE_GAP separates clusters
    gap = [(10, 14), (15 + MERGE_GAP + 1, 25)]
    om, p, data = _synthetic(gap)
    assert find_runs(~fit_quantisation(p, om, nu, data, "lambda", "ceil").ok) == gap
    assert find_runs(np.zeros(5, bool)) == []
    # a grid point removed from the known grid is found missing
    x = 10 * np.delete(om, 200)
    missing, off, step = missing_grid_points(x)
    assert step == 0.25 and np.allclose(missing, [10 * om[200]]) and off.size == 0


def test_straight_line_finds_a_chord_and_its_slip():
    x = np.arange(1.0, 11.0)
    y = np.round(2.0 + 0.3 * x, 2)
    y[4] += 0.05
    fit = straight_line(x, y, np.array([0.0, 11.0]), np.array([2.0, 5.3]))
    assert list(np.flatnonzero(~fit.on_line)) == [4] and fit.residual <= 0.005 + 1e-9


def test_fit_switch_and_missing_grid():
    assert fit_switch(np.arange(4.0), np.array([1, 1, 0, 0]), np.array([0, 0, 1, 1]))[2] == 4
    missing, off, step = missing_grid_points(np.array([0.25, 0.5, 1.0, 1.1, 1.25, 1.5]))
    assert step == 0.25 and list(missing) == [0.75] and list(off) == [1.1]
    with pytest.raises(ValueError, match="sorted"):
        fit_switch(np.array([1.0, 0.0]), np.ones(2), np.ones(2))
    (run,) = off_grid_runs(np.array([0.25, 0.33, 0.42, 0.5]), 0.25)
    assert run["count"] == 2 and run["spacing"] == pytest.approx(0.25 / 3)
    assert run["max_deviation"] < 0.005


# ------------------------------------------------------------------------------------------
# explanations must be true of the points they explain
# ------------------------------------------------------------------------------------------

def test_window_explanations_only_inside_the_window(fx):
    claimed = 0
    for c in fx.clusters + [dict(m, window_points=[m["twist_angle"]]) for m in fx.missing_points
                            if "imaginary beta_1" in m["causes"]]:
        w = imaginary_beta1_window(c["nu"])
        for om in c["window_points"]:
            assert w.omega_a < om < w.omega_b
            p = critical_load(om, c["nu"], tol=1e-12)
            assert _x_minus_mp(p, om, c["nu"]) < 0  # beta_1 imaginary (mpmath)
            claimed += 1
        if c.get("kind") == "imaginary-beta1 window":
            assert len(c["window_points"]) >= 0.9 * c["points"]
    assert claimed > 40


def test_a_cluster_moved_out_of_the_window_is_not_explained_by_it(fx):
    k = next(i for i, c in enumerate(fx.clusters) if c["kind"] == "imaginary-beta1 window")
    rows = fx.sites[fx.sites["cluster"] == k].copy()
    moved = rows.assign(twist_angle=rows["twist_angle"] + 1.0)
    moved["p_true"] = critical_load(moved["twist_angle"].to_numpy(), moved["nu"].to_numpy())
    phys = site_physics(moved.drop(columns=["x_minus", "imaginary_beta1", "in_window"]),
                        fx.runs)
    phys["double_root"] = phys["high_double_root"]
    rec = explain_cluster(phys, None, None, fx.runs)
    assert rec["window_points"] == [] and rec["kind"] != "imaginary-beta1 window"
    assert "imaginary" not in rec["explanation"].split("Printed")[0]


def test_double_root_clusters_contain_their_crossing(fx):
    dbl = [c for c in fx.clusters if c["kind"] == "double root in one scan step"]
    assert len(dbl) == 3
    for c in dbl:
        cross = crossing_closed_form(c["crossing"]["n"], c["nu"])
        assert c["twist_from"] <= cross.twist <= c["twist_to"] + 1e-12
        assert len(c["double_root_points"]) >= 0.5 * c["points"]


# ------------------------------------------------------------------------------------------
# the LaTeX source as data
# ------------------------------------------------------------------------------------------

def test_picture_lines_match_the_digitised_points(points):
    lines = picture_lines(PICTURE.read_text(encoding="utf-8"))
    assert np.allclose(lines["picture_x"], points["picture_x"])
    assert np.allclose(lines["picture_y"], points["picture_y"])
    assert (lines["curve"].to_numpy() == points["curve"].to_numpy()).all()


def test_vendored_picture_is_the_papers():
    if not PAPER.exists():
        pytest.skip(f"paper source not found at {PAPER}")
    assert PICTURE.read_text(encoding="utf-8") == picture_environment(
        PAPER.read_text(encoding="utf-8"))


def test_picture_lines_parser_on_a_snippet():
    tex = ("x\n\\begin{picture}(100,100)\n\\put(1,2){\\line(0,1){3}}\n"
           "\\put(  0.25,   0.10){\\circle*{1.0}} \n\n\\put(  0.50,   0.20){\\circle*{1.0}}\n"
           "\\put(  0.25,   5.00){\\circle*{1.0}} \n\\put(  0.50,   5.10){\\circle*{1.0}} \n"
           "\\put(  0.25,   9.00){\\circle*{1.0}} \n\\end{picture}\n")
    df = picture_lines(tex)
    assert list(df["curve"]) == [1, 1, 2, 2, 3]
    assert list(df["trailing_blank"]) == [True, False, True, True, True]
    assert list(df["after_blank_line"]) == [False, True, False, False, False]
    with pytest.raises(ValueError, match="picture"):
        picture_environment("no picture here")


# ------------------------------------------------------------------------------------------
# the verdict rule and the ledger row
# ------------------------------------------------------------------------------------------

def test_verdict_rule_branches(fx):
    assert figure1.figure1_verdict(figure1.accounting(fx)) == "holds approximately"
    bad = [dict(c, explained=False) for c in fx.clusters]
    verdict = figure1.figure1_verdict
    assert verdict(figure1.accounting(dataclasses.replace(fx, clusters=bad))) == "inconclusive"
    sites = fx.sites.copy()
    i = sites.index[sites["in_data"] & sites["ok"]][0]
    sites.loc[i, "p_digitised"] += 2 * figure1.VISIBLE
    assert verdict(figure1.accounting(dataclasses.replace(fx, sites=sites))) == "fails"
    clean = fx.sites.assign(ok=True)
    assert figure1.figure1_verdict(figure1.accounting(dataclasses.replace(
        fx, sites=clean, clusters=[], missing_points=[]))) == "holds"


def test_ledger_row(fx):
    from spectral_rod.figure1.data import load_figure1 as _load

    table = figure1.comparison_table(_load(CSV))
    summary = figure1.deviation_summary(table)
    truth = figure1.truth_check(table)
    claim = figure1.forensics_claim(fx, summary, truth)
    assert claim.id.startswith("fig1-") and claim.verdict in VERDICTS
    assert set(claim.related) == set(claim.numbers["cross_links"])
    # the accounting's truth (collocation) contradicted by mpmath: no verdict
    wrong = type(truth)(truth.name, 1e-3, truth.limit)
    assert figure1.forensics_claim(fx, summary, wrong).verdict == "inconclusive"
    assert {m["formulation"] for m in claim.methods} >= {"inst1", "paper's figure"}
    assert set(claim.numbers["cross_links"]) == {"rod-beta-real", "rod-first-maximum",
                                                 "rod-further-maxima"}
    assert "inconclusive" in VERDICTS
    row = Claim(id="x", section="s", claim="c", test="t", evidence="e", verdict="inconclusive",
                scene="figure1")
    assert row.methods == []


def test_partial_inputs_do_not_crash(points):
    with pytest.raises(ValueError, match="no digitised points"):
        analyse_figure1(points.iloc[:0])
    # one curve, its first points only: no clusters, no missing points, one switch record
    part = analyse_figure1(points[points["curve"] == 1].head(40).reset_index(drop=True))
    assert (part.clusters, part.missing_points, list(part.switches)) == ([], [], [1.1])
    assert "point by point: 40 of 40 plotted" in figure1.readme_sentence(part)
    assert missing_grid_points(np.array([0.25]))[2] is None
    assert [a.size for a in family_loads(np.array([]), np.array([]))] == [0, 0]


def test_a_nan_p_star_is_refused_with_the_column_named(points):
    bad = points.copy()
    bad.loc[5, "p_star"] = float("nan")
    with pytest.raises(ValueError, match=r"points\['p_star'\] must be finite"):
        analyse_figure1(bad, p_true=np.ones(len(bad)))
    bad = points.copy()
    bad["twist_angle"] = bad["twist_angle"].astype(object)
    bad.loc[3, "twist_angle"] = "abc"
    with pytest.raises(ValueError, match="twist_angle"):
        analyse_figure1(bad, p_true=np.ones(len(bad)))


@pytest.mark.parametrize("damage", ["truncate", "garble", "binary", "move"])
def test_a_broken_picture_file_is_named(tmp_path, damage):
    tex = figure1_picture()
    path = tmp_path / "figure1_picture.tex"
    if damage == "truncate":
        path.write_text(tex[: len(tex) // 2], encoding="utf-8")
    elif damage == "garble":
        path.write_text(tex.replace("circle*", "circ1e*", 3), encoding="utf-8")
    elif damage == "binary":
        path.write_bytes(b"\xff\xfe\x00" + tex.encode()[:100])
    else:  # every point still parses, one moved: only the comparison with the CSV sees it
        path.write_text(tex.replace("\\put(   0.50,    0.01)", "\\put(   0.50,    0.02)", 1),
                        encoding="utf-8")
    with pytest.raises(ReferenceDataError, match=re.escape(str(path))):
        figure1_picture(path)
    if damage == "move":  # the helper that sees it, on its own
        with pytest.raises(ReferenceDataError, match="not the digitised points"):
            check_picture_matches(picture_points(tex.replace(
                "\\put(   0.50,    0.01)", "\\put(   0.50,    0.02)", 1)), load_figure1())


def test_cli_exits_2_naming_a_broken_picture_file(tmp_path, monkeypatch, capsys):
    from reproduce import cli
    from reproduce import figure1 as scene
    from spectral_rod.figure1 import data as figure_data
    bad = tmp_path / "figure1_picture.tex"
    bad.write_text(figure1_picture()[:5000], encoding="utf-8")
    monkeypatch.setattr(scene, "figure1_picture", lambda: figure_data.figure1_picture(bad))
    assert cli.main(["figure1", "--quiet", "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert str(bad) in err and "Traceback" not in err


def test_rule_f1_text_shows_the_threshold_its_logic_uses():
    assert f"{figure1.VISIBLE:.2e}" in figure1.RULE
    numbers = {"unaccounted_or_unexplained": 0, "irregular": 1,
               "max_abs_deviation": 0.99 * figure1.VISIBLE}
    assert figure1.figure1_verdict(numbers) == "holds approximately"
    assert figure1.figure1_verdict({**numbers, "max_abs_deviation": 1.01 * figure1.VISIBLE}) \
        == "fails"
