"""Scene `extremes`: accuracy of p* and of p* - 1 at the edges of the (Omega(L), nu) plane.

Models: the hinged straight rod with spontaneous twist (paper, Eq. ``inst1``); p* = P_cr /
(pi^2 A1/L^2), Omega(L) = omega30 L, nu = I2/I1.
Compares: the public ``critical_load`` (collocation for |Omega| < 50, double-precision
characteristic equation above) and ``critical_load_increment`` with the mpmath characteristic
equation at 50 digits (the independent reference), at critical_load's default tol, over a
grid reaching nu - 1 = 1e-12, nu = 1e4, Omega(L) = 1e-6 and 1000; and collocation at fixed
degree n = 8..512 (round-off growth).
Writes: extremes.png, extremes_grid.csv, extremes_increment.csv, extremes_resolution.csv,
extremes_routing.csv (collocation vs characteristic equation at large twist: error, n, time) and
the report section. Nothing is cached across runs.
"""

from __future__ import annotations

import inspect
import time
import warnings
from collections.abc import Callable
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from reproduce._runner import SceneOutput
from reproduce.io import write_csv, write_figure
from reproduce.ties import family_tie
from spectral_rod import (
    NEAR_DEGENERATE,
    TWIST_ROUTE,
    ConvergenceWarning,
    characteristic_critical_load,
    critical_load,
    critical_load_increment,
)

NAME = "extremes"
SUMMARY = ("straight rod at the extremes: p* and p*-1 errors over the (Omega, nu) plane vs the "
           "mpmath characteristic equation, round-off vs n -> extremes.png, extremes_*.csv")
#: The tol of every critical_load call here: the library's default (the accuracy it promises).
TOL = inspect.signature(critical_load).parameters["tol"].default
#: Acceptance limits of the scene: relative error of p* (all routes) and of p* - 1
#: (critical_load_increment's stated target).
P_LIMIT, INC_LIMIT = 1e-10, 1e-9
#: `python -m reproduce check`: per output file and column (or JSON key), how a regenerated
#: value may differ from the committed one (rules in reproduce/compare.py). A measured error's
#: round-off digits depend on the engine and the BLAS: beyond 1e-6 relative it must still meet
#: the tol or the stated target (``within``); the family at a tie of the two families is a tie.
_ERROR = {"rel": 1e-6, "abs": 1e-12}  # a measured error: round-off below 1e-12 is noise
_P_ERROR = {**_ERROR, "within": TOL}
_INC_ERROR = {**_ERROR, "within": INC_LIMIT}
CHECK = {
    "extremes_grid.csv": {"p_star": {"rel": 2e-12, "floor": "rel_error"},
                          "p_ref": 1e-14, "rel_error": _P_ERROR,
                          "family": family_tie(TOL), "*": "exact"},
    "extremes_increment.csv": {"increment": {"rel": 2e-12, "floor": "rel_error"},
                               "increment_ref": 1e-14, "rel_error": _INC_ERROR, "*": "exact"},
    "extremes_resolution.csv": {"p_star": {"rel": 2e-12, "floor": "rel_error"},
                                "rel_error": _ERROR, "*": "exact"},
    "extremes_routing.csv": {"*_seconds": "ignore", "*_rel_error": _ERROR, "*": "exact"},
    "sections/extremes.json": {"details.worst_p_star": _P_ERROR,
                               "details.worst_increment": _INC_ERROR, "*": "exact"},
}
DPS = 50
P_TWISTS = (1e-6, 1e-3, 1.0, 5.0, 30.0, 100.0, 300.0, 1000.0)
P_NUS = (1 + 1e-12, 1 + 1e-8, 1 + 1e-4, 1.5, 10.0, 1e4)
INC_TWISTS = (1e-6, 1e-3, 1.0, 5.0, 30.0, 100.0)
INC_NUS = (1 + 1e-8, 1 + 1e-4, 1.5, 10.0, 1e4)
RES_POINTS = ((1.0, 1.5), (30.0, 1.5), (100.0, 10.0), (30.0, 1 + 1e-9))
RES_DEGREES = (8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512)
ROUTE_TWISTS = (10.0, 30.0, 50.0, 100.0, 200.0, 300.0, 1000.0)
ROUTE_NUS = (1.5, 1e4)


def reference(twist: float, nu: float) -> float:
    """p* from the characteristic equation at DPS digits (never from the code under test)."""
    return characteristic_critical_load(twist, nu, dps=DPS).p_star


def p_star_grid() -> pd.DataFrame:
    """Relative error of critical_load over P_TWISTS x P_NUS, with the route used."""
    rows = []
    for om in P_TWISTS:
        res = critical_load(np.full(len(P_NUS), om), np.asarray(P_NUS), full_output=True)
        for j, nu in enumerate(P_NUS):
            ref = reference(om, nu)
            p = float(res.p_star[j])
            rows.append({"twist_angle": om, "nu": nu, "p_star": p, "p_ref": float(ref),
                         "rel_error": float(abs((p - ref) / ref)),
                         "method": str(res.method[j]),
                         "n": int(res.n[j]), "family": str(res.family[j])})
    return pd.DataFrame(rows)


def routing_study() -> pd.DataFrame:
    """Both large-twist candidates measured: collocation (automatic n) and the double-precision
    characteristic equation -- relative error against the reference and wall time."""
    rows = []
    for nu in ROUTE_NUS:
        for om in ROUTE_TWISTS:
            ref = reference(om, nu)
            t0 = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ConvergenceWarning)
                # beyond Omega ~ 300 the automatic degree would exceed the cap: measure n = 512
                res = critical_load(om, nu, n=512 if om > 300 else None,
                                    method="collocation", full_output=True)
            t1 = time.perf_counter()
            pc = critical_load(om, nu, method="characteristic")
            t2 = time.perf_counter()
            rows.append({"twist_angle": om, "nu": nu,
                         "colloc_rel_error": float(abs((float(res.p_star) - ref) / ref)),
                         "colloc_n": int(res.n), "colloc_converged": bool(res.converged),
                         "colloc_seconds": t1 - t0,
                         "char_rel_error": float(abs((pc - ref) / ref)),
                         "char_seconds": t2 - t1})
    return pd.DataFrame(rows)


def increment_grid() -> pd.DataFrame:
    """Relative error of critical_load_increment over INC_TWISTS x INC_NUS."""
    rows = []
    for om in INC_TWISTS:
        for nu in INC_NUS:
            ref = reference(om, nu) - 1
            d = critical_load_increment(om, nu)
            rows.append({"twist_angle": om, "nu": nu, "increment": d,
                         "increment_ref": float(ref), "rel_error": float(abs((d - ref) / ref))})
    return pd.DataFrame(rows)


def resolution_study() -> pd.DataFrame:
    """Collocation at fixed n (forced, no routing): relative error against the reference."""
    rows = []
    for om, nu in RES_POINTS:
        ref = reference(om, nu)
        for n in RES_DEGREES:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ConvergenceWarning)
                p = critical_load(om, nu, n=n)
            rows.append({"twist_angle": om, "nu": nu, "n": n, "p_star": p,
                         "finite": bool(np.isfinite(p)),
                         "rel_error": float(abs((p - ref) / ref))})
    return pd.DataFrame(rows)


def _heatmap(ax, table: pd.DataFrame, xs, ys, title: str, accuracy: str):
    """log10 of the relative errors of `table` over `xs` x `ys`, titled `title` and the
    `accuracy` asked of the solver and demanded by the scene."""
    err = np.log10(np.maximum(table.pivot(index="nu", columns="twist_angle",
                                          values="rel_error").loc[list(ys), list(xs)]
                              .to_numpy(), 1e-17))
    im = ax.imshow(err, origin="lower", cmap="viridis", vmin=-17, vmax=-8, aspect="auto")
    for i in range(len(ys)):
        for j in range(len(xs)):
            ax.text(j, i, f"{err[i, j]:.0f}", ha="center", va="center", fontsize=7,
                    color="w" if err[i, j] < -12 else "k")
    ax.set_xticks(range(len(xs)), [f"{x:g}" for x in xs], rotation=45, fontsize=7)
    ax.set_yticks(range(len(ys)), [_nu_label(y) for y in ys], fontsize=7)
    ax.set_xlabel("Ω(L)")
    ax.set_ylabel("ν")
    ax.set_title(f"{title}\n({accuracy})", fontsize=9)
    return im


def _nu_label(nu: float) -> str:
    return f"1+{nu - 1:.0e}" if 0 < nu - 1 < 1e-3 else f"{nu:g}"


def draw(grid: pd.DataFrame, inc: pd.DataFrame, res: pd.DataFrame, route: pd.DataFrame):
    fig, axs = plt.subplots(2, 2, figsize=(13, 9.5), layout="constrained")
    axes = axs.ravel()
    im = _heatmap(axes[0], grid, P_TWISTS, P_NUS,
                  "log10 rel. error of p* (critical_load)",
                  f"tol {TOL:.0e}, the default; pass limit {P_LIMIT:.0e}")
    axes[0].axvline(P_TWISTS.index(100.0) - 0.5, color="r", lw=1)
    axes[0].text(P_TWISTS.index(100.0) - 0.45, len(P_NUS) - 0.55, "char. eq. →", color="r",
                 fontsize=7, va="top",
                 bbox={"facecolor": "white", "edgecolor": "none", "pad": 1})
    _heatmap(axes[1], inc, INC_TWISTS, INC_NUS, "log10 rel. error of p*-1 (increment)",
             f"its stated target {INC_LIMIT:.0e}, the pass limit")
    fig.colorbar(im, ax=axes[1], shrink=0.9, label="log10 relative error")
    ax = axes[2]
    for (om, nu), sub in res.groupby(["twist_angle", "nu"], sort=False):
        ax.loglog(sub["n"], np.maximum(sub["rel_error"], 1e-17), "o-", ms=3,
                  label=f"Ω={om:g}, ν={_nu_label(nu)}")
    n = np.asarray(RES_DEGREES, dtype=float)
    ax.loglog(n, 2.2e-16 * n, "k:", lw=1, label="ε n")
    ax.loglog(n, 2.2e-16 * n**4 / 1e4, "k--", lw=1, label="ε n⁴/10⁴ (differentiation)")
    ax.set_ylim(1e-17, 1e2)
    ax.set_xlabel("Chebyshev degree n (fixed)")
    ax.set_ylabel("relative error of p*")
    ax.set_title("collocation at fixed n: truncation, then round-off", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="major", alpha=0.3)
    ax = axes[3]
    for nu, sub in route.groupby("nu"):
        ax.loglog(sub["twist_angle"], np.maximum(sub["colloc_rel_error"], 1e-17), "o-", ms=3,
                  label=f"collocation (auto n), ν={nu:g}")
        ax.loglog(sub["twist_angle"], np.maximum(sub["char_rel_error"], 1e-17), "s--", ms=3,
                  label=f"characteristic eq. (double), ν={nu:g}")
    om = np.asarray(ROUTE_TWISTS)
    # the route's own estimate (eps (8 + |Omega|)), not a copy of its formula
    est = critical_load(om, np.full(om.size, 1.5), method="characteristic",
                        full_output=True).error_estimate
    ax.loglog(om, est, "k:", lw=1, label="characteristic eq.: its error estimate")
    ax.axvline(TWIST_ROUTE, color="r", lw=1)
    ax.text(TWIST_ROUTE * 1.05, 3e-11, "routed to the\ncharacteristic eq. →", color="r",
            fontsize=7, va="top")
    ax.set_ylim(1e-17, 1e-8)
    ax.set_xlabel("Ω(L)")
    ax.set_ylabel("relative error of p*")
    ax.set_title(f"large twist: both methods measured at tol {TOL:.0e} (collocation n capped "
                 "at 512)", fontsize=9)
    ax.legend(fontsize=7, loc="upper left")
    ax.grid(True, which="major", alpha=0.3)
    return fig


def _md(df: pd.DataFrame, cols: list[str]) -> str:
    lines = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for _, r in df[cols].iterrows():
        # nu within 1e-3 of 1 would print as "1" at 3 digits: name its distance from 1
        lines.append("| " + " | ".join(_nu_label(v) if c == "nu" else
                                       f"{v:.3g}" if isinstance(v, float) else str(v)
                                       for c, v in zip(cols, r, strict=True)) + " |")
    return "\n".join(lines)


def run(out: Path, progress: Callable[[str], None]) -> SceneOutput:
    out = Path(out)
    t0 = time.perf_counter()
    progress("p* over the (Omega, nu) grid vs the mpmath characteristic equation")
    grid = p_star_grid()
    progress("p* - 1 (critical_load_increment) vs the reference")
    inc = increment_grid()
    progress("collocation at fixed n = 8..512")
    res = resolution_study()
    progress("large twist: collocation vs characteristic equation (error, time)")
    route = routing_study()
    files = [write_csv(out / "extremes_grid.csv", grid),
             write_csv(out / "extremes_increment.csv", inc),
             write_csv(out / "extremes_resolution.csv", res),
             write_csv(out / "extremes_routing.csv", route),
             write_figure(out / "extremes.png", draw(grid, inc, res, route))]
    worst_p = grid.loc[grid["rel_error"].idxmax()]
    worst_i = inc.loc[inc["rel_error"].idxmax()]
    by_route = grid.groupby("method")["rel_error"].max()
    res_floor = res[res["n"] >= 128].groupby(["twist_angle", "nu"])["rel_error"].max()
    ok = (grid["rel_error"].max() <= P_LIMIT and inc["rel_error"].max() <= INC_LIMIT
          and res["finite"].all())
    report = "\n".join([
        "## Extremes: accuracy at the edges of the (Ω(L), ν) plane", "",
        "Reference: the paper's characteristic equation in mpmath at "
        f"{DPS} digits. Routing: collocation for |Ω(L)| < {TWIST_ROUTE:g}, double-precision "
        "characteristic equation above (`spectral_rod.rod.critical`).", "",
        f"* p*: worst relative error {worst_p['rel_error']:.1e} at Ω = "
        f"{worst_p['twist_angle']:g}, ν = {worst_p['nu']:.12g} (tol {TOL:.0e}, pass limit "
        f"{P_LIMIT:.0e}); "
        + ", ".join(f"{k}: {v:.1e}" for k, v in by_route.items()) + ".",
        f"* p* − 1: worst relative error {worst_i['rel_error']:.1e} at Ω = "
        f"{worst_i['twist_angle']:g}, ν = {worst_i['nu']:.12g} (stated target and pass limit "
        f"{INC_LIMIT:.0e}), down "
        "to ν − 1 = 1e-8 and Ω(L) = 1e-6 (p* − 1 = "
        f"{inc['increment_ref'].min():.3e} there).",
        "* Fixed n = 8..512: all results finite; round-off floor for n >= 128: "
        + ", ".join(f"(Ω={om:g}, ν={_nu_label(nu)}) {v:.0e}" for (om, nu), v in
                    res_floor.items()) + ".",
        "* Large twist, both methods measured (table below): collocation's n grows with Ω(L) "
        "and its round-off with n; the characteristic equation costs the same at any twist. "
        f"Routing: |Ω(L)| >= {TWIST_ROUTE:g} -> characteristic equation; ν − 1 <= "
        f"{NEAR_DEGENERATE:g} (|Ω| < {TWIST_ROUTE:g}) -> characteristic equation (each family's "
        "root in its bounds [1, ν]); else collocation.",
        "* Asymptote (not used for values): p* = p_inf [1 − π²(ν−1)²/(4(ν+1)²Ω²)] + "
        "O(Ω⁻³) with p_inf = 2ν/(1+ν); the O(Ω⁻³) term is the ripple "
        "−π²(ν−1)/(ν+1) p_inf |sin Ω|/Ω³ (`spectral_rod.rod.closed_form`).",
        f"* Status: {'PASS' if ok else 'FAIL'}; run time {time.perf_counter() - t0:.1f} s.",
        "", "![extremes](extremes.png)", "",
        "### p* − 1 (relative error)", "",
        _md(inc, ["twist_angle", "nu", "increment_ref", "rel_error"]), "",
        "### Large twist: collocation vs characteristic equation", "",
        _md(route, ["twist_angle", "nu", "colloc_rel_error", "colloc_n", "colloc_converged",
                    "colloc_seconds", "char_rel_error", "char_seconds"]), "",
        "### p* (relative error, route)", "",
        _md(grid, ["twist_angle", "nu", "p_ref", "rel_error", "method", "n"]), "",
    ])
    return SceneOutput(files=files, report=report,
                       details={"worst_p_star": float(grid["rel_error"].max()),
                                "worst_increment": float(inc["rel_error"].max()),
                                "pass": bool(ok)})
