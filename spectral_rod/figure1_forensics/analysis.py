"""The whole Figure 1 analysis (:func:`analyse_figure1`) and its result (:class:`Forensics`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from spectral_rod._validation import real_array
from spectral_rod.asymptotics import crossing_closed_form, imaginary_beta1_window
from spectral_rod.figure1_forensics.explain import (
    _default_p_star,
    _flanks,
    _twists,
    explain_cluster,
    explain_missing,
    site_physics,
)
from spectral_rod.figure1_forensics.hypotheses import (
    SCAN_VARIABLES,
    best_two_runs,
    quantisation_hypotheses,
    scan_hypotheses,
    variant_hypotheses,
)
from spectral_rod.figure1_forensics.physics import twist_ranges
from spectral_rod.figure1_forensics.picture import (
    PUT_FORMAT,
    X_PER_TWIST,
    missing_grid_points,
    off_grid_runs,
)
from spectral_rod.figure1_forensics.quantisation import Hypothesis
from spectral_rod.figure1_forensics.runs import find_runs
from spectral_rod.figure1_forensics.scan import scan_model, scan_sign_change
from spectral_rod.figure_data import FIGURE1_NU


def _attach_lines(points: pd.DataFrame, lines: pd.DataFrame | None) -> pd.DataFrame:
    """Join the LaTeX line facts to the points (same source order; checked)."""
    if lines is None:
        return points
    if len(lines) != len(points) or not (
            np.allclose(lines["picture_x"], points["picture_x"])
            and np.allclose(lines["picture_y"], points["picture_y"])
            and (lines["curve"].to_numpy() == points["curve"].to_numpy()).all()):
        raise ValueError("lines: the LaTeX picture lines do not match the digitised points "
                         "(different file or order)")
    out = points.copy()
    out["line"] = lines["line"].to_numpy()
    out["edited"] = ~lines["trailing_blank"].to_numpy(dtype=bool)
    out["after_blank_line"] = lines["after_blank_line"].to_numpy(dtype=bool)
    out["fixed_format"] = lines["fixed_format"].to_numpy(dtype=bool)
    return out


def _sites(points: pd.DataFrame, p_star_fn: Callable) -> pd.DataFrame:
    """Data points plus the missing points of each curve's regular grid (in_data False)."""
    pts = points.assign(in_data=True, off_grid=False)
    extra = []
    for c, nu in zip(range(1, len(FIGURE1_NU) + 1), FIGURE1_NU, strict=True):
        sel = (pts["curve"] == c).to_numpy()
        missing, off, _ = missing_grid_points(pts.loc[sel, "picture_x"].to_numpy())
        pts.loc[sel, "off_grid"] = pts.loc[sel, "picture_x"].isin(off).to_numpy()
        for x in missing:
            extra.append({"curve": c, "nu": nu, "picture_x": x, "picture_y": np.nan,
                          "twist_angle": x / X_PER_TWIST, "in_data": False, "off_grid": False})
    if extra:
        miss = pd.DataFrame(extra)
        miss["p_true"] = p_star_fn(miss["twist_angle"].to_numpy(), miss["nu"].to_numpy())
        pts = pd.concat([pts, miss], ignore_index=True)
    return pts


def _run_scans(sites: pd.DataFrame, runs: dict[str, Hypothesis]) -> pd.DataFrame:
    """Each run's real-wavenumber scan at every site: found (bool) and its printed y."""
    t, nu = sites["twist_angle"].to_numpy(), sites["nu"].to_numpy()
    starts = dict(SCAN_VARIABLES)
    out = sites.copy()
    for r, h in runs.items():
        sc = scan_sign_change(t, nu, h.variable, h.step, start_at_zero=starts.get(h.variable,
                                                                                    False))
        out[f"{r}_scan_found"] = np.isfinite(sc.upper)
        out[f"{r}_scan_y"] = scan_model(sc, "upper", t, nu)
        out[f"{r}_undefined"] = sc.undefined
    return out


@dataclass
class Forensics:
    """Everything :func:`analyse_figure1` found; :meth:`to_json` is figure1_forensics.json.

    sites: one row per data point (in_data) and per missing grid point, with the truth, the
    physics (:func:`site_physics`), the covering run, the best model's y and ok, and cluster
    (index into clusters, -1 if none).
    """

    sites: pd.DataFrame
    hypotheses: list[Hypothesis]
    best: Hypothesis
    runs: dict[str, Hypothesis]
    switches: dict[float, dict]
    clusters: list[dict]
    missing_points: list[dict]
    prediction: dict[float, dict]
    windows: dict[float, dict] = field(default_factory=dict)
    crossings: dict[float, list[dict]] = field(default_factory=dict)

    @property
    def points(self) -> pd.DataFrame:
        """The data points only (source order)."""
        return self.sites[self.sites["in_data"]].reset_index(drop=True)

    def unaccounted(self) -> pd.DataFrame:
        """Data points neither reproduced nor in a cluster (should be empty)."""
        p = self.points
        return p[~p["ok"] & (p["cluster"] < 0)]

    def latex_summary(self) -> dict | None:
        """How many lines were inserted separately, and where those not in a cluster are."""
        p = self.points
        if "edited" not in p:
            return None
        hand = p["edited"].to_numpy(dtype=bool)
        rest = p[hand & (p["cluster"] < 0)]
        return {"lines": len(p), "with_trailing_blank": int((~hand).sum()),
                "format": PUT_FORMAT, "fixed_format": int(p["fixed_format"].sum()),
                "edited": int(hand.sum()),
                "edited_in_clusters": int((hand & (p["cluster"] >= 0)).sum()),
                "edited_reproduced": [{"nu": float(r["nu"]),
                                           "twist_angle": float(r["twist_angle"]),
                                           "reproduced": bool(r["ok"])}
                                          for _, r in rest.iterrows()]}

    def to_json(self) -> dict:
        p = self.points
        nu, ranges = p["nu"].to_numpy(), p["range"].to_numpy()
        hand = p["edited"].to_numpy(dtype=bool) if "edited" in p else None
        return {"hypotheses": [h.summary(nu, ranges, hand) for h in self.hypotheses],
                "best": self.best.name, "best_description": self.best.description,
                "runs": {r: h.name for r, h in self.runs.items()},
                "switches": {str(k): v for k, v in self.switches.items()},
                "clusters": self.clusters, "missing_points": self.missing_points,
                "prediction_vs_data": {str(k): v for k, v in self.prediction.items()},
                "windows": {str(k): v for k, v in self.windows.items()},
                "crossings": {str(k): v for k, v in self.crossings.items()},
                "latex": self.latex_summary(), "points": len(p),
                "reproduced_by_best": int(p["ok"].sum()),
                "in_clusters": int((p["cluster"] >= 0).sum()),
                "unaccounted": len(self.unaccounted())}


def _switch_record(curve_rows: pd.DataFrame, lo: Hypothesis, hi: Hypothesis, s_first: int,
                   s_last: int, nu: float) -> dict:
    """Where the two runs meet on one curve, next to the imaginary-beta_1 window.

    low_last: the last point before the latest optimal split that the low run reproduces;
    high_first: the first point from the earliest optimal split that the high run reproduces.
    """
    t = curve_rows["twist_angle"].to_numpy()
    idx = curve_rows.index.to_numpy()
    low_ok = np.flatnonzero(lo.ok[idx][:s_last])
    high_ok = np.flatnonzero(hi.ok[idx][s_first:]) + s_first
    w = imaginary_beta1_window(nu)
    below, above = t[t <= w.omega_a], t[t >= w.omega_b]
    rec = {"low_run_last_reproduced": float(t[low_ok[-1]]) if low_ok.size else None,
           "high_run_first_reproduced": float(t[high_ok[0]]) if high_ok.size else None,
           "window": [w.omega_a, w.omega_b],
           "last_point_below_window": float(below.max()) if below.size else None,
           "first_point_above_window": float(above.min()) if above.size else None}
    rec["low_run_reaches_window"] = rec["low_run_last_reproduced"] == rec[
        "last_point_below_window"]
    rec["high_run_starts_at_window"] = rec["high_run_first_reproduced"] == rec[
        "first_point_above_window"]
    return rec


def _undefined_record(rows: pd.DataFrame) -> dict:
    """Does each run's scan, where it produced the printed value, ever evaluate an undefined
    (imaginary-beta_1) determinant? Counts of such points among the points it reproduces."""
    out = {}
    for r in ("low", "high"):
        mine = rows[(rows["run"] == r) & rows["ok"]]
        out[f"{r}_run_reproduced"] = len(mine)
        out[f"{r}_run_met_imaginary_beta1"] = int((mine[f"{r}_undefined"] > 0).sum())
    return out


def _prediction(sites: pd.DataFrame) -> dict[float, dict]:
    """Grid points where the covering run's scan fails vs grid points irregular in the data."""
    out = {}
    grid = sites[~sites["off_grid"]]
    for nu in FIGURE1_NU:
        g = grid[grid["nu"] == nu]
        fail = ~g["scan_found"].to_numpy(dtype=bool)
        irregular = (~g["in_data"] | (g["cluster"] >= 0)).to_numpy()
        out[nu] = {"predicted_failures": int(fail.sum()), "irregular": int(irregular.sum()),
                   "both": int((fail & irregular).sum()),
                   "predicted_only": _twists(g, fail & ~irregular),
                   "irregular_only": _twists(g, irregular & ~fail)}
    return out


def _cluster_all(sites: pd.DataFrame, runs: dict[str, Hypothesis]) -> list[dict]:
    """Find and explain the clusters of every curve; sets sites['cluster'] in place."""
    clusters = []
    sites["cluster"] = -1
    with_blank = (int((~sites.loc[sites["in_data"], "edited"].astype(bool)).sum())
                  if "edited" in sites else None)
    for c in range(1, len(FIGURE1_NU) + 1):
        idx = np.flatnonzero(sites["in_data"].to_numpy() & (sites["curve"] == c).to_numpy())
        rows = sites.iloc[idx]
        ok = rows["ok"].to_numpy(dtype=bool)
        x = rows["picture_x"].to_numpy()
        off_runs = off_grid_runs(x, missing_grid_points(x)[2])
        for first, last in find_runs(~ok):
            left, right = _flanks(rows, first, last, ok)
            rec = explain_cluster(rows.iloc[first:last + 1], left, right, runs, with_blank,
                                  off_runs)
            sites.iloc[idx[first:last + 1], sites.columns.get_loc("cluster")] = len(clusters)
            clusters.append(rec)
    return clusters


def analyse_figure1(points: pd.DataFrame, lines: pd.DataFrame | None = None, *,
                    p_true: NDArray[np.float64] | None = None,
                    p_star_fn: Callable[[NDArray, NDArray], NDArray] | None = None) -> Forensics:
    """Explain every digitised point of Figure 1 (module docstring).

    points: :func:`spectral_rod.figure_data.load_figure1` (source order); lines:
    :func:`picture_lines` of the same picture (LaTeX evidence; optional); p_true: the converged
    p* at the points (default: ``p_star_fn``); p_star_fn(twist, nu): the converged p* anywhere
    (default ``critical_load(..., tol=1e-12)``), used at missing grid points and shifted twists.
    """
    need = {"curve", "nu", "picture_x", "picture_y", "twist_angle", "p_star"}
    if not isinstance(points, pd.DataFrame) or not need <= set(points.columns):
        raise TypeError(f"points must be the DataFrame of load_figure1() (columns {sorted(need)}), "
                        f"got {type(points).__name__}")
    if lines is not None and not isinstance(lines, pd.DataFrame):
        raise TypeError(f"lines must be None or picture_lines(...), got {type(lines).__name__}")
    if p_true is not None:
        p_true = real_array(p_true, "p_true")
        if p_true.shape != (len(points),):
            raise ValueError(f"p_true must have one value per point ({len(points)}), got shape "
                             f"{p_true.shape}")
    if p_star_fn is not None and not callable(p_star_fn):
        raise TypeError(f"p_star_fn must be callable, got {type(p_star_fn).__name__}")
    p_star_fn = p_star_fn or _default_p_star
    pts = points.reset_index(drop=True).rename(columns={"p_star": "p_digitised"})
    t, nu, y = (pts[c].to_numpy() for c in ("twist_angle", "nu", "picture_y"))
    pts["p_true"] = p_star_fn(t, nu) if p_true is None else np.asarray(p_true, dtype=float)
    pts = _attach_lines(pts, lines)
    pts["range"] = twist_ranges(t, nu)
    p = pts["p_true"].to_numpy()
    quant = quantisation_hypotheses(p, t, nu, y)
    ceil_steps = {v: next(h.step for h in quant if h.variable == v and h.rounding == "ceil")
                  for v, _ in SCAN_VARIABLES}
    scan_h, scans = scan_hypotheses(t, nu, y, ceil_steps)
    upper = sorted((h for h in scan_h if h.rounding == "bracket upper"),
                   key=lambda h: -int(h.ok.sum()))
    best_q = max(quant, key=lambda h: h.ok.sum())
    singles = quant + scan_h + variant_hypotheses([scans[h.variable] for h in upper[:2]],
                                                  best_q, p, t, nu, y, p_star_fn)
    curve = pts["curve"].to_numpy()
    hand = pts["edited"].to_numpy(dtype=bool) if "edited" in pts else None
    comp_all = best_two_runs(singles, t, curve, " (any hypotheses)")[0]
    # the best model is a *procedure*: it also says where no value can be produced, and is
    # credited where that coincides with a line inserted separately
    procedures = [h for h in singles if h.rounding.startswith("bracket")]
    best, lo, hi, splits = best_two_runs(procedures, t, curve, " (sign-change scans)", hand)
    hyps = [*singles, comp_all, best]
    runs = {"low": lo, "high": hi}
    pts["y_model"], pts["ok"] = best.y_model, best.ok
    switch_twist = {}
    for c, (s, _) in splits.items():
        tc = t[pts["curve"].to_numpy() == c]
        switch_twist[c] = tc[s] if s < len(tc) else math.inf
    sites = _sites(pts, p_star_fn)
    sites["run"] = [("low" if r["twist_angle"] < switch_twist.get(r["curve"], -math.inf)
                     else "high") for _, r in sites.iterrows()]
    sites = _run_scans(site_physics(sites, runs), runs)
    for col in ("double_root", "scan_found"):
        sites[col] = [bool(r[f"{r['run']}_{col}"]) for _, r in sites.iterrows()]
    sites["ok"] = sites["ok"].fillna(False).astype(bool)
    clusters = _cluster_all(sites, runs)
    missing = [explain_missing(r, sites, runs) for _, r in sites[~sites["in_data"]].iterrows()]
    curve_of = {n: c for c, n in enumerate(FIGURE1_NU, 1)}
    switches = {nu_: _switch_record(pts[pts["curve"] == curve_of[nu_]], lo, hi,
                                    *splits[curve_of[nu_]], nu_) for nu_ in FIGURE1_NU}
    for nu_, rec in switches.items():
        rec.update(_undefined_record(sites[sites["in_data"] & (sites["nu"] == nu_)]))
    windows = {n: vars(imaginary_beta1_window(n)) for n in FIGURE1_NU}
    crossings = {n: [vars(crossing_closed_form(k, n)) for k in (2, 3)] for n in FIGURE1_NU}
    return Forensics(sites, hyps, best, runs, switches, clusters, missing, _prediction(sites),
                     windows, crossings)
