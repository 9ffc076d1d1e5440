"""Scene `figure1`: the paper's Figure 1, p*(Omega(L)) for nu = 1.1, 1.3, 1.5.

Models: the hinged straight rod with spontaneous twist (Eq. ``inst1``), nothing else.
Compares: the Chebyshev collocation p* with every digitised point of the paper's picture.
Writes: figure1.png, figure1.pdf (paper's axes, digitised points over computed curves, residual
panel), figure1_comparison.csv (computed vs digitised p* at each digitised point),
figure1_forensics.json / figure1_forensics.png (every point explained:
:mod:`spectral_rod.figure1.forensics`), the Figure 1 row of the claims ledger (claims.json/.md)
and the report section (per-curve rms/max deviation, resolution, run time, the forensics).
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from reproduce._runner import SceneOutput
from reproduce.io import json_value, write_csv, write_figure, write_text
from reproduce.ledger import (
    Claim,
    ClaimSpec,
    Condition,
    CrossCheck,
    Measured,
    Method,
    Rule,
    judge,
    ledger_check,
    tiered_rule,
    update_ledger,
)
from reproduce.ties import family_tie
from spectral_rod import (
    CAUSE_IMAGINARY_BETA1,
    CLUSTER_DOUBLE_ROOT,
    CLUSTER_WINDOW,
    FIGURE1_DOT,
    FIGURE1_NU,
    FIGURE1_PRINT_QUANTUM,
    FIGURE1_Y_PER_P,
    Forensics,
    analyse_figure1,
    characteristic_critical_load,
    critical_load,
    figure1_picture,
    load_figure1,
    picture_lines,
)

#: The twist ranges of Forensics.range_sizes (its order) in words.
RANGE_WORDS = "below / in / above"
#: The report section's paragraphs (:func:`run`, :func:`forensics_section`): templates with
#: named fields.
SECTION_TEXT = {
    "head": "## Figure 1: critical load versus twist\n\n![Figure 1](figure1.png)\n\n"
            "Collocation (Chebyshev, degree chosen per point by coefficient decay, tol {tol:g}) "
            "at the {points} digitised points of the paper's picture; degree n from {n_min} to "
            "{n_max} (median {n_median}); largest error estimate {estimate:.1e}. Sweep time "
            "{sweep:.2f} s.\n\nDeviation computed − digitised (the digitisation is printed to "
            "{quantum:g} picture units, i.e. {quantum_p:.1e} in p*; the plotted dots are {dot:g} "
            "unit = {dot_p:.1e} wide):\n\n| ν | points | rms | max abs | at Ω(L) | mean | within "
            "rms ≤ {rms:g}, max ≤ {max:g} |\n|---|---|---|---|---|---|---|",
    "deviation_row": "| {nu} | {r[points]} | {r[rms]:.2e} | {r[max_abs]:.2e} | "
                     "{r[twist_at_max]:.3f} | {r[mean]:+.2e} | {passes} |",
    "files": "Files: `figure1.png`, `figure1.pdf`, `figure1_comparison.csv` (columns: curve, "
             "nu, picture_x, picture_y, twist_angle, p_star_digitised, p_star_computed, "
             "deviation, n, error_estimate, mode_family).",
    "forensics_head": "### Every point explained\n\n![Figure 1 forensics]"
                      "(figure1_forensics.png)\n\nAnalysis time {seconds:.1f} s "
                      "(spectral_rod.figure1.forensics; output `figure1_forensics.json`). A point "
                      "is *reproduced* if the model's y, printed to the print quantum, equals "
                      "the picture's ({quantum:g} picture units = {quantum_p:.1e} in p*). Points "
                      "{ranges} the imaginary-β₁ window: {sizes}.",
    "best": "**Best model:** `{name}` -- {description}. It reproduces **{ok} of {n}** points "
            "exactly. Where the scan yields no value it predicts a failure of the authors' "
            "procedure; a quantisation model always yields a value, so it can also match "
            "inserted points by coincidence (compare the two two-run rows).",
    "switch_head": "Where the two runs meet (the switch is fitted per curve):\n\n| ν | low run: "
                   "last reproduced Ω | last point ≤ Ω_a | window (Ω_a, Ω_b) | high run: first "
                   "reproduced Ω | first point ≥ Ω_b |\n|---|---|---|---|---|---|",
    "clusters_head": "**Clusters** (runs of points off the best model):\n\n| # | ν | Ω(L) | "
                     "points | max abs deviation | kind |\n|---|---|---|---|---|---|",
    "cluster_row": "| C{k} | {c[nu]} | {c[twist_from]:.3f}…{c[twist_to]:.3f} | {c[points]} | "
                   "{c[max_abs_deviation]:.2e} | {c[kind]} |",
    "missing_head": "**Missing grid points:**",
    "prediction_head": "Predicted failures of the procedure (grid points where the covering "
                       "run's scan finds no sign change) against irregular grid points "
                       "(missing, or in a cluster):\n\n| ν | predicted | irregular | both | "
                       "predicted only | irregular only |\n|---|---|---|---|---|---|",
    "ledger": "**Ledger row `{id}`: {verdict}.** {rule} Related rows: {links}.",
    "readme": "README sentence: {sentence}",
}
#: The scene's prose: templates with named fields, filled by :func:`readme_sentence` and its
#: helpers (so a word can change without reading a computation).
TEXT = {
    "at_same": "reported at {lo[reported_at]}",
    "at_split": "reported at {lo[reported_at]} at low twist and at {hi[reported_at]} at high "
                "twist",
    "run": "a sign-change scan of the boundary determinant {at}, stepping {lo[variable]} "
           "({lo[description]}) by {lo[step]:g} at low twist and {hi[variable]} "
           "({hi[description]}) by {hi[step]:g} at high twist",
    "off": "up to {g[max_abs_deviation]:.1e} off",
    "window_lines": ", {g[sloped_line]} of them on straight lines between the flanking computed "
                    "points",
    "window_lead": "straight lines ",
    "window_group": "{lead}across the imaginary-β₁ window ({n} points{lines}, {off})",
    "double_flat": ", {g[flat]} of them printed flat",
    "double_lead": "flat values ",
    "double_group": "{lead}at the {ns} crossing where both mode families' roots fall in one "
                    "scan step ({n} points{flat}, {off})",
    "other_group": "{g[kind]} ({n} points, {off})",
    "bound_all": "every one of them",
    "bound_some": "{dev[within_band]} of them",
    "where": "so computed − digitised lies in [{lo:.1e}, {hi:.1e}] there (within one scan step "
             "plus the print rounding at {bound})",
    "where_none": "none of them",
    "readme": "Figure 1 is explained point by point: {n_ok} of {n} plotted points are exactly "
              "(to the {quantum:g} print quantum) what the authors' procedure gives from the "
              "converged p* -- {run} -- {where}.",
    "other": " The other {n_bad}",
    "in_clusters": " lie in clusters of {in_clusters} points, which",
    "all_inserted": " were inserted separately (LaTeX lines without the program's trailing "
                    "blank)",
    "some_inserted": " include {edited} inserted separately (LaTeX lines without the program's "
                     "trailing blank)",
    "not_reproduced": " are not reproduced",
    "fails_all": " where that procedure fails",
    "fails_some": "; that procedure fails at {caused} of them",
    "groups": ": {groups}.",
    "missing_at": "Ω = {m[twist_angle]:.3f} (ν = {m[nu]})",
    "same_reason": "For the same reason",
    "both_roots": "Where both mode families' roots fall in one scan step",
    "missing": " {why} at the {ns} crossing no value was printed at {miss}.",
}

NAME = "figure1"
SUMMARY = ("straight twisted rod, Eq. inst1: collocation p*(Omega) vs the digitised Figure 1, "
           "every point explained -> figure1.png/.pdf, figure1_comparison.csv, "
           "figure1_forensics.json/.png, ledger row fig1-curves")
#: `python -m reproduce check`: per output file and column (or JSON key), how a regenerated
#: value may differ from the committed one (rules in reproduce/compare.py).
CHECK = {
    "figure1_comparison.csv": {
        # 2 tol, one unit of the 12 printed digits, or the solver's own error estimate
        "p_star_computed": {"rel": 2e-11, "floor": "error_estimate"},
        "deviation": {"abs": 2e-11},
        "error_estimate": {"rel": 1e-6, "abs": 1e-12},  # an estimate near round-off
        "mode_family": family_tie(1e-12),  # TOL, defined below
        "*": "exact",  # the digitised inputs, n
    },
    "claims.json": ledger_check({"*.numbers.max_abs_deviation": {"rel": 1e-6, "abs": 1e-12},
                                 "*.numbers.rms_per_curve.*": {"rel": 1e-6, "abs": 1e-12},
                                 "*.numbers.clusters.*.max_abs_deviation": {"rel": 1e-6,
                                                                           "abs": 1e-12},
                                 "*.numbers.*": {"rel": 1e-9, "abs": 1e-12}}),
    "figure1_forensics.json": {"*.max_abs_deviation": {"rel": 1e-6, "abs": 1e-12},
                               "reproduced_deviation.*": {"abs": 2e-11},  # as "deviation"
                               "*.twist_from": 1e-12, "*.twist_to": 1e-12,
                               "*.explanation": "text", "*": "exact"},
    "sections/figure1.json": {"details.sweep_seconds": "ignore",
                              "details.forensics_seconds": "ignore",
                              "details.summary.*": {"rel": 1e-9, "abs": 2e-12}, "*": "exact"},
}
TOL = 1e-12
#: Acceptance thresholds of the reproduction: per-curve rms and max |deviation|.
RMS_LIMIT, MAX_LIMIT = 1.5e-4, 6e-4
COLORS = dict(zip(FIGURE1_NU, ("tab:blue", "tab:orange", "tab:green"), strict=True))
#: Guide lines of the main panel at Omega(L) = k pi (the family crossings lie near k pi, k >= 2).
GUIDES = (1, 2, 3)


def comparison_table(reference: pd.DataFrame, tol: float = TOL) -> pd.DataFrame:
    """Computed p* at every digitised point, with the deviation and the solver's diagnostics."""
    res = critical_load(reference["twist_angle"].to_numpy(), reference["nu"].to_numpy(),
                        tol=tol, full_output=True)
    out = reference.copy()
    out = out.rename(columns={"p_star": "p_star_digitised"})
    out["p_star_computed"] = res.p_star
    out["deviation"] = out["p_star_computed"] - out["p_star_digitised"]
    out["n"] = res.n
    out["error_estimate"] = res.error_estimate
    out["mode_family"] = res.family
    if not res.converged.all():
        raise RuntimeError("figure1: collocation did not converge at some digitised points")
    return out


def deviation_summary(table: pd.DataFrame) -> pd.DataFrame:
    """Per-curve rms, max |deviation| and mean deviation of computed minus digitised p*."""
    g = table.groupby("nu")["deviation"]
    summary = pd.DataFrame({
        "points": g.size(),
        "rms": g.apply(lambda d: float(np.sqrt(np.mean(d**2)))),
        "max_abs": g.apply(lambda d: float(np.max(np.abs(d)))),
        "mean": g.mean(),
    })
    summary["twist_at_max"] = [
        float(table.loc[table["nu"] == nu, "twist_angle"].to_numpy()[
            np.argmax(np.abs(table.loc[table["nu"] == nu, "deviation"].to_numpy()))])
        for nu in summary.index]
    summary["passes"] = (summary["rms"] <= RMS_LIMIT) & (summary["max_abs"] <= MAX_LIMIT)
    return summary


def draw(table: pd.DataFrame, curves: dict[float, tuple[np.ndarray, np.ndarray]]):
    fig, (ax, axr) = plt.subplots(2, 1, figsize=(7.0, 7.5), sharex=True,
                                  gridspec_kw={"height_ratios": [3, 1.2], "hspace": 0.08})
    for k in GUIDES:
        for a in (ax, axr):
            a.axvline(k * np.pi, color="0.75", lw=0.8, zorder=0)
        ax.text(k * np.pi, 1.252, f"{k if k > 1 else ''}π", ha="center", va="bottom")
    for i, nu in enumerate(FIGURE1_NU, 1):
        om, p = curves[nu]
        sub = table[table["nu"] == nu]
        ax.plot(om, p, color=COLORS[nu], lw=1.6, label=f"curve {i}: ν = {nu} (collocation)")
        ax.plot(sub["twist_angle"], sub["p_star_digitised"], "o", ms=2.2, mfc="none",
                color="k", mew=0.5, label="digitised Figure 1" if i == len(FIGURE1_NU) else None)
        ax.text(10.08, p[-1], f"ν = {nu}", va="center", color=COLORS[nu], fontsize=9)
        axr.plot(sub["twist_angle"], sub["deviation"] * 1e4, ".", ms=2.5, color=COLORS[nu],
                 label=f"ν = {nu}")
    ax.set_xlim(0, 10)
    ax.set_ylim(1.0, 1.25)
    ax.set_ylabel("critical load  p* = P_cr / (π² A₁ / L²)")
    ax.set_title("Figure 1 of Drozdov & Rabin: p* versus total twist angle Ω(L)", pad=18)
    ax.legend(loc="upper left", fontsize=8, frameon=False)
    axr.axhline(0, color="k", lw=0.6)
    axr.set_xlabel("total twist angle  Ω(L) = ω₃₀ L  [rad]")
    axr.set_ylabel("computed − digitised\n[10⁻⁴]")
    axr.legend(loc="lower right", fontsize=7, ncol=3, frameon=False)
    fig.subplots_adjust(right=0.88, top=0.92)
    return fig


# ------------------------------------------------------------------------------------------
# Figure 1 point by point: verdict rule, ledger row, figure, report section
# ------------------------------------------------------------------------------------------

CLAIM_ID = "fig1-curves"
#: The row's finding (the report's headline), a template with named fields.
FINDING = ("Figure 1 is explained point by point: {ok} of its {n} printed points are the "
           "authors' sign-change scan applied to the converged p*; the other {other} (in "
           "{clusters} clusters, across the imaginary-β₁ window and at a family crossing) were "
           "inserted separately, and {missing} grid points are missing.")
#: Deviation a reader of the printed figure would see: half a plotted dot, in p*.
VISIBLE_DOTS = 0.5
VISIBLE = VISIBLE_DOTS * FIGURE1_DOT / FIGURE1_Y_PER_P
#: Rule F1 (point-by-point accounting), its text and logic from the same conditions.
RULE_F1 = tiered_rule(
    [("inconclusive", (Condition("unaccounted_or_unexplained", ">", "the number of digitised "
                                 "points neither reproduced nor in a cluster, plus clusters and "
                                 "missing points with neither a computed cause nor LaTeX "
                                 "evidence,", 0, fmt="d"),)),
     ("fails", (Condition("max_abs_deviation", ">", "the largest distance of a point from the "
                          "converged p* (half a plotted dot:)", VISIBLE, fmt=".2e"),)),
     ("holds", (Condition("irregular", "<=", "the number of clusters and missing points", 0,
                          fmt="d"),))],
    "holds approximately",
    note="holds: every point is the procedure applied to the correct root")
RULE = "Rule F1 (point-by-point accounting): " + RULE_F1.text + "."
METHODS = (Method(f"Chebyshev collocation (converged p*, tol {TOL:g})", "inst1"),
           Method("sign-change scan of the boundary determinant D_sym·D_anti (double "
                  "precision), simulating the authors' procedure",
                  "characteristic equation of inst1 (the paper's method)"),
           Method("closed forms: imaginary-β₁ window, family crossings", "closed form"),
           Method("digitised Figure 1 and its LaTeX source lines", "paper's figure"))
#: Collocation's p* at sample points is cross-checked against the mpmath characteristic
#: equation; the accounting assumes that truth to far better than the print quantum.
SAMPLE_EVERY, TRUTH_LIMIT = 60, 1e-11


def accounting(fx: Forensics) -> dict:
    """The numbers the verdict on Figure 1 is taken from."""
    unexplained = (sum(not c["explained"] for c in fx.clusters)
                   + sum(not m["explained"] for m in fx.missing_points))
    return {"unaccounted_points": len(fx.unaccounted()), "unexplained": unexplained,
            "max_abs_deviation": fx.max_deviation(), "visible_deviation": VISIBLE,
            "clusters": len(fx.clusters), "missing_points": len(fx.missing_points),
            "irregular": len(fx.clusters) + len(fx.missing_points),
            "unaccounted_or_unexplained": len(fx.unaccounted()) + unexplained}


def figure1_verdict(numbers: dict) -> str:
    """The verdict on Figure 1 by :data:`RULE_F1`, from the accounting's numbers."""
    return RULE_F1.decide(numbers)


def cross_links(fx: Forensics) -> list[str]:
    """Straight-rod ledger rows the clusters and missing points bear on."""
    links = set()
    for rec in [*fx.clusters, *fx.missing_points]:
        if rec.get("kind") == CLUSTER_WINDOW or CAUSE_IMAGINARY_BETA1 in rec.get("causes", []):
            links.add("rod-beta-real")
        if rec.get("crossing"):
            links.add("rod-first-maximum" if rec["crossing"]["n"] == 2 else "rod-further-maxima")
    return sorted(links)


def _run_phrase(fx: Forensics) -> str:
    lo, hi = (fx.run_summary()[r] for r in ("low", "high"))
    at = (TEXT["at_same"].format(lo=lo) if lo["reported_at"] == hi["reported_at"]
          else TEXT["at_split"].format(lo=lo, hi=hi))
    return TEXT["run"].format(at=at, lo=lo, hi=hi)


def _group_phrase(g: dict) -> str:
    """One kind of cluster in words (every number from :meth:`Forensics.cluster_groups`)."""
    off = TEXT["off"].format(g=g)
    n = g["points"]
    if g["kind"] == CLUSTER_WINDOW:
        lines = "" if g["sloped_line"] == n else TEXT["window_lines"].format(g=g)
        return TEXT["window_group"].format(
            lead=TEXT["window_lead"] if g["sloped_line"] == n else "", n=n, lines=lines, off=off)
    if g["kind"] == CLUSTER_DOUBLE_ROOT:
        ns = "/".join(f"{k}π" for k in g["crossings"])
        flat = "" if g["flat"] == n else TEXT["double_flat"].format(g=g)
        return TEXT["double_group"].format(lead=TEXT["double_lead"] if g["flat"] == n else "",
                                           ns=ns, n=n, flat=flat, off=off)
    return TEXT["other_group"].format(g=g, n=n, off=off)


def readme_sentence(fx: Forensics) -> str:
    """The one-sentence summary of the forensics for the README (every number computed, the
    words from :data:`TEXT`)."""
    p = fx.points
    dev = fx.reproduced_deviation()
    n_ok = dev["points"]
    bound = (TEXT["bound_all"] if dev["within_band"] == n_ok
             else TEXT["bound_some"].format(dev=dev))
    where = (TEXT["where"].format(lo=-dev["max"], hi=-dev["min"], bound=bound) if n_ok
             else TEXT["where_none"])
    s = TEXT["readme"].format(n_ok=n_ok, n=len(p), quantum=FIGURE1_PRINT_QUANTUM,
                              run=_run_phrase(fx), where=where)
    groups = fx.cluster_groups()
    n_bad = len(p) - n_ok
    if n_bad:
        lat = fx.latex_summary()
        # the counts below are of the clusters' points, which are the points not reproduced
        # unless a cluster bridges reproduced ones (MERGE_GAP) or a point stands alone
        in_clusters = sum(g["points"] for g in groups)
        edited = lat["edited_in_clusters"] if lat else None
        caused = sum(g["caused"] for g in groups)
        s += TEXT["other"].format(n_bad=n_bad)
        if in_clusters != n_bad:
            s += TEXT["in_clusters"].format(in_clusters=in_clusters)
        if edited == in_clusters:
            s += TEXT["all_inserted"]
        elif edited:
            s += TEXT["some_inserted"].format(edited=edited)
        else:
            s += TEXT["not_reproduced"]
        s += (TEXT["fails_all"] if caused == in_clusters
              else TEXT["fails_some"].format(caused=caused))
        s += TEXT["groups"].format(groups=" and ".join(_group_phrase(g) for g in groups))
    crossed = [m for m in fx.missing_points if m.get("crossing")]
    if crossed:
        miss = "; ".join(TEXT["missing_at"].format(m=m) for m in crossed)
        miss_n = "/".join(sorted({f"{m['crossing']['n']}π" for m in crossed}))
        why = (TEXT["same_reason"] if any(g["kind"] == CLUSTER_DOUBLE_ROOT for g in groups)
               else TEXT["both_roots"])
        s += TEXT["missing"].format(why=why, ns=miss_n, miss=miss)
    return s


def truth_check(table: pd.DataFrame) -> CrossCheck:
    """Collocation's p* (the truth of the accounting) against mpmath at every 60th point."""
    rows = table.iloc[::SAMPLE_EVERY]
    ref = np.array([float(characteristic_critical_load(t, nu, dps=30).p_star)
                    for t, nu in zip(rows["twist_angle"], rows["nu"], strict=True)])
    err = float(np.max(np.abs(rows["p_star_computed"].to_numpy() / ref - 1)))
    return CrossCheck(f"p*: collocation vs mpmath at {len(rows)} sample points", err, TRUTH_LIMIT)


FIG1 = ClaimSpec(
    id=CLAIM_ID, section="Figure 1 (Sec. 'Stability of a rectilinear rod')",
    claim=f"Figure 1 shows p*(Ω(L)) for ν = {', '.join(f'{v:g}' for v in FIGURE1_NU)}: the "
          "numerical solution of the characteristic equation of Eq. inst1 (hinged ends).",
    test="Every one of the figure's printed points against the converged p*: fitted models of "
         "how the authors produced and printed each value (quantisation of p*, λ, y, λ − νΩ², "
         "λ − Ω² on fixed step grids; simulated sign-change scans of the boundary "
         "determinant; two runs with a fitted switch), then clusters of points off the best "
         "model and missing grid points, each with computed causes and the LaTeX lines' "
         "formatting (spectral_rod.figure1.forensics).",
    methods=METHODS, rule=Rule(RULE, figure1_verdict), figure="figure1_forensics.png",
    related=("rod-beta-real", "rod-first-maximum", "rod-further-maxima"))


def forensics_claim(fx: Forensics, summary: pd.DataFrame, truth: CrossCheck) -> Claim:
    """The ledger row for Figure 1, its verdict by :data:`RULE`."""
    p = fx.points
    clusters = "; ".join(f"ν = {c['nu']}, Ω = {c['twist_from']:.3f}…{c['twist_to']:.3f} "
                         f"({c['points']} points, {c['kind']}, max {c['max_abs_deviation']:.1e})"
                         for c in fx.clusters)
    missing = ", ".join(f"Ω = {m['twist_angle']:.3f} (ν = {m['nu']})" for m in fx.missing_points)
    links = cross_links(fx)
    measured = Measured(
        evidence=f"Best model: {_run_phrase(fx)}; it reproduces {int(p['ok'].sum())} of {len(p)} "
                 f"points exactly. Clusters: {clusters}. Missing grid points: {missing or 'none'}."
                 f" Every cluster and missing point is explained "
                 f"({sum(c['explained'] for c in fx.clusters)}/{len(fx.clusters)}, "
                 f"{sum(m['explained'] for m in fx.missing_points)}/{len(fx.missing_points)}); "
                 f"largest deviation of any point from p* {fx.max_deviation():.2e} = "
                 f"{fx.max_deviation() * FIGURE1_Y_PER_P:.2f} picture units (a dot is "
                 f"{FIGURE1_DOT:g}). Related rows: {', '.join(links)}.",
        numbers={**accounting(fx), "headline": readme_sentence(fx),
                 "finding": FINDING.format(ok=int(p["ok"].sum()), n=len(p),
                                           other=len(p) - int(p["ok"].sum()),
                                           clusters=len(fx.clusters),
                                           missing=len(fx.missing_points)),
                 "best": fx.best.name,
                 "reproduced": int(p["ok"].sum()), "points": len(p),
                 "clusters": [{k: c[k] for k in ("nu", "twist_from", "twist_to", "points",
                                                 "max_abs_deviation", "kind")}
                              for c in fx.clusters],
                 "missing_points": [{"nu": m["nu"], "twist_angle": m["twist_angle"]}
                                    for m in fx.missing_points],
                 "max_abs_deviation": fx.max_deviation(), "visible_deviation": VISIBLE,
                 "rms_per_curve": {float(k): float(v) for k, v in summary["rms"].items()},
                 "cross_links": links},
        cross_checks=(truth,))
    return judge(FIG1, measured, NAME)


#: Digits as subscripts, for Ω_n in legends.
SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _mark_physics(ax, fx: Forensics, nu: float) -> None:
    """The imaginary-β₁ window and the family crossings of one curve (closed forms)."""
    w = fx.windows[nu]
    ax.axvspan(w["omega_a"], w["omega_b"], color="tab:cyan", alpha=0.18, lw=0,
               label="β₁ imaginary (closed form)")
    crossings = fx.crossings[nu]
    names = ", ".join(f"Ω{str(c['n']).translate(SUBSCRIPT)}" for c in crossings)
    for k, c in enumerate(crossings):
        ax.axvline(c["twist"], color="tab:purple", ls="--", lw=0.8,
                   label=f"family crossings {names}" if k == 0 else None)


def _model_band(ax, fx: Forensics, nu: float) -> None:
    """The band of one scan step in which a reproduced point's deviation lies, per run."""
    s = fx.sites[(fx.sites["nu"] == nu) & ~fx.sites["off_grid"]].sort_values("twist_angle")
    band = fx.model_band.loc[s.index]
    lo, hi = band["band_low"].to_numpy(), band["band_high"].to_numpy()
    for r in fx.runs:
        mine = (s["run"] == r).to_numpy() & np.isfinite(hi)
        if mine.any():
            # the band is of digitised - p*; drawn in the figures' convention, computed - digitised
            ax.fill_between(s["twist_angle"], -hi * 1e4, -lo * 1e4, where=mine, color="0.85",
                            lw=0, step="mid",
                            label="model band: one scan step" if r == "high" else None)


def draw_forensics(fx: Forensics):
    """Residuals computed − digitised (the convention of figure1.png) per curve, coloured by
    class, physical windows marked."""
    fig, axes = plt.subplots(3, 1, figsize=(9.0, 9.5), sharex=True,
                             gridspec_kw={"hspace": 0.12})
    colors = plt.get_cmap("tab10").colors
    for ax, nu in zip(axes, FIGURE1_NU, strict=True):
        s = fx.sites[fx.sites["nu"] == nu]
        d = s[s["in_data"]]
        res = (d["p_true"] - d["p_digitised"]) * 1e4
        _model_band(ax, fx, nu)
        _mark_physics(ax, fx, nu)
        ok = d["ok"].to_numpy()
        ax.plot(d["twist_angle"][ok], res[ok], ".", ms=2.5, color="0.35",
                label=f"reproduced by the best model ({ok.sum()})")
        for k, c in enumerate(fx.clusters):
            if c["nu"] != nu:
                continue
            m = (d["cluster"] == k).to_numpy()
            ax.plot(d["twist_angle"][m], res[m], "o", ms=3.5, mfc="none", mew=1.0,
                    color=colors[(k + 1) % 10],
                    label=f"C{k + 1}: {c['kind']} ({c['points']})")
            ax.annotate(f"C{k + 1}", (d["twist_angle"][m].mean(), res[m].min()),
                        xytext=(0, -12), textcoords="offset points", ha="center", fontsize=8,
                        color=colors[(k + 1) % 10])
        miss = s[~s["in_data"]]
        if len(miss):
            ax.plot(miss["twist_angle"], np.zeros(len(miss)), "x", color="tab:red", ms=6,
                    label=f"missing grid points ({len(miss)})")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_ylabel(f"ν = {nu}\ncomputed − digitised  [10⁻⁴]")
        ax.legend(loc="upper right", fontsize=6.5, ncol=2, frameon=False)
        ax.set_ylim(-7.0, 7.5)  # headroom: the legend above the largest residual (2.8)
    axes[0].set_title("Figure 1 point by point: converged p* − digitised "
                      f"(print quantum {FIGURE1_PRINT_QUANTUM / FIGURE1_Y_PER_P:.1e}, "
                      f"dot {FIGURE1_DOT / FIGURE1_Y_PER_P:.1e})",
                      fontsize=10)
    axes[-1].set_xlabel("total twist angle Ω(L) [rad]")
    axes[-1].set_xlim(0, 10)
    fig.subplots_adjust(left=0.1, right=0.98, top=0.95, bottom=0.06)
    return fig


def _hypothesis_rows(fx: Forensics) -> list[str]:
    rows = ["| hypothesis | reproduced | " + " | ".join(f"ν = {n}" for n in FIGURE1_NU)
            + f" | {RANGE_WORDS} window | no value (edited lines) |",
            "|---|---|" + "---|" * len(FIGURE1_NU) + "---|---|"]
    p = fx.points
    hand = p["edited"].to_numpy(dtype=bool) if "edited" in p else None
    for h in sorted(fx.hypotheses, key=lambda h: -int(h.ok.sum())):
        j = h.summary(p["nu"].to_numpy(), p["range"].to_numpy(), hand)
        rng = " / ".join(str(v) for v in j["by_range_total"].values())
        nv = f"{j['no_value']} ({j['no_value_edited']})" if j["no_value"] else "0"
        rows.append(f"| `{j['name']}` | {j['reproduced_exactly']} | "
                    + " | ".join(str(j["by_curve"][str(n)]) for n in FIGURE1_NU)
                    + f" | {rng} | {nv} |")
    return rows


def _missing_rows(fx: Forensics) -> list[str]:
    """Missing points as bullets; runs of adjacent ones with the same causes share one."""
    rows = []
    for g in fx.missing_groups():
        twists = ", ".join(f"{m['twist_angle']:.3f}" for m in g[1:])
        more = (f" (The same holds at the {len(g) - 1} adjacent grid points Ω = {twists}: "
                f"explanations in the JSON.)" if len(g) > 1 else "")
        rows.append(f"* {g[0]['explanation']}{more}")
    return rows


def _num(v: float | None, fmt: str = ".3f") -> str:
    """A number of a table cell, or — where there is none."""
    return "—" if v is None else format(v, fmt)


def forensics_section(fx: Forensics, claim: Claim, seconds: float) -> list[str]:
    """The report's Markdown on the forensics (every number from fx)."""
    p = fx.points
    sizes = fx.range_sizes()
    lines = [SECTION_TEXT["forensics_head"].format(
                 seconds=seconds, quantum=FIGURE1_PRINT_QUANTUM,
                 quantum_p=FIGURE1_PRINT_QUANTUM / FIGURE1_Y_PER_P, ranges=RANGE_WORDS,
                 sizes=" / ".join(str(v) for v in sizes.values())),
             "", SECTION_TEXT["best"].format(name=fx.best.name, description=fx.best.description,
                                             ok=int(p["ok"].sum()), n=len(p)),
             "", *_hypothesis_rows(fx), "", SECTION_TEXT["switch_head"]]
    for nu, w in fx.switches.items():
        win = fx.windows.get(nu, {})
        lines.append(f"| {nu} | {_num(w['low_run_last_reproduced'])} | "
                     f"{_num(w['last_point_below_window'])} | ({_num(win.get('omega_a'), '.4f')}, "
                     f"{_num(win.get('omega_b'), '.4f')}) | "
                     f"{_num(w['high_run_first_reproduced'])} | "
                     f"{_num(w['first_point_above_window'])} |")
    met = sum(w["low_run_met_imaginary_beta1"] + w["high_run_met_imaginary_beta1"]
              for w in fx.switches.values())
    lines += ["", "Where each run reproduces the printed value, its scan "
              + ("never evaluated" if not met else f"evaluated, at {met} points,")
              + " an undefined (imaginary-β₁) determinant (points met / reproduced): "
              + "; ".join(f"ν = {nu}: low run {w['low_run_met_imaginary_beta1']} of "
                          f"{w['low_run_reproduced']}, high run "
                          f"{w['high_run_met_imaginary_beta1']} of {w['high_run_reproduced']}"
                          for nu, w in fx.switches.items()) + ".",
              "", SECTION_TEXT["clusters_head"]]
    for k, c in enumerate(fx.clusters, 1):
        lines.append(SECTION_TEXT["cluster_row"].format(k=k, c=c))
    lines += [""] + [f"* **C{k}.** {c['explanation']}" for k, c in enumerate(fx.clusters, 1)]
    lat = fx.latex_summary()
    if lat:
        retyped = ", ".join(f"{r['twist_angle']:.3f} (ν = {r['nu']})"
                            for r in lat["edited_reproduced"])
        lines += ["", f"LaTeX lines inserted separately (no trailing blank; "
                  f"{lat['with_trailing_blank']} of {lat['lines']} lines have one; "
                  f"{lat['fixed_format']} of {lat['lines']} share the fixed-width format "
                  f"`{lat['format']}`): {lat['edited']}, of which "
                  f"{lat['edited_in_clusters']} form the clusters; of the other "
                  f"{len(lat['edited_reproduced'])}, "
                  f"{sum(r['reproduced'] for r in lat['edited_reproduced'])} carry exactly "
                  f"the model's value (rewritten): Ω = {retyped}."]
    lines += ["", SECTION_TEXT["missing_head"], ""]
    lines += _missing_rows(fx) or ["* none"]
    lines += ["", SECTION_TEXT["prediction_head"]]
    for nu, r in fx.prediction.items():
        lines.append(f"| {nu} | {r['predicted_failures']} | {r['irregular']} | {r['both']} | "
                     f"{r['predicted_only'] or '—'} | {r['irregular_only'] or '—'} |")
    lines += ["", SECTION_TEXT["ledger"].format(id=claim.id, verdict=claim.verdict, rule=RULE,
                                                links=", ".join(claim.numbers["cross_links"])),
              "", SECTION_TEXT["readme"].format(sentence=readme_sentence(fx))]
    return lines


def run(out: Path, progress: Callable[[str], None]) -> SceneOutput:
    t0 = time.perf_counter()
    reference = load_figure1()
    progress(f"loaded {len(reference)} digitised points (spectral_rod/data/figure1_digitised.csv)")
    # the picture is read (and checked against the CSV) first: a broken file stops the scene
    # before any output is written
    pic = picture_lines(figure1_picture())
    table = comparison_table(reference)
    t_sweep = time.perf_counter() - t0
    progress(f"collocation at all digitised points to tol {TOL:g} in {t_sweep:.2f} s")
    grid = np.linspace(0.0, 10.0, 801)
    curves = {nu: (grid, critical_load(grid, nu, tol=TOL)) for nu in FIGURE1_NU}
    summary = deviation_summary(table)
    fig = draw(table, curves)
    files = [write_figure(out / "figure1.png", fig, dpi=160, close=False),
             write_figure(out / "figure1.pdf", fig)]
    files.append(write_csv(out / "figure1_comparison.csv", table, float_format="%.12g"))
    n_used = table["n"]
    lines = [SECTION_TEXT["head"].format(
        tol=TOL, points=len(table), n_min=n_used.min(), n_max=n_used.max(),
        n_median=int(n_used.median()), estimate=table["error_estimate"].max(), sweep=t_sweep,
        quantum=FIGURE1_PRINT_QUANTUM, quantum_p=FIGURE1_PRINT_QUANTUM / FIGURE1_Y_PER_P,
        dot=FIGURE1_DOT, dot_p=FIGURE1_DOT / FIGURE1_Y_PER_P, rms=RMS_LIMIT, max=MAX_LIMIT)]
    for nu, r in summary.iterrows():
        lines.append(SECTION_TEXT["deviation_row"].format(
            nu=nu, r=r, passes="yes" if r["passes"] else "NO"))
    lines += ["", SECTION_TEXT["files"]]
    t1 = time.perf_counter()
    fx = analyse_figure1(reference, pic, p_true=table["p_star_computed"].to_numpy())
    t_fx = time.perf_counter() - t1
    progress(f"forensics: best model reproduces {int(fx.points['ok'].sum())} of "
             f"{len(fx.points)} points, {len(fx.clusters)} clusters, "
             f"{len(fx.missing_points)} missing points ({t_fx:.1f} s)")
    files.append(write_figure(out / "figure1_forensics.png", draw_forensics(fx)))
    files.append(write_text(out / "figure1_forensics.json",
                            json.dumps(fx.to_json(), indent=1, default=json_value) + "\n"))
    claim = forensics_claim(fx, summary, truth_check(table))
    files += update_ledger(out, NAME, [claim])
    lines += ["", *forensics_section(fx, claim, t_fx)]
    report = "\n".join(lines) + "\n"
    files.append(write_text(out / "figure1_report.md", report))
    details = {"sweep_seconds": t_sweep, "forensics_seconds": t_fx,
               "summary": summary.reset_index().to_dict("records"),
               "verdict": claim.verdict}
    return SceneOutput(files=files, report=report, details=details)
