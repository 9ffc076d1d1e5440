"""The whole Figure 1 analysis (:func:`analyse_figure1`) and its result (:class:`Forensics`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from typing import cast

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from spectral_rod._validation import real_array
from spectral_rod.figure1.data import (
    FIGURE1_NU,
    FIGURE1_PRINT_QUANTUM,
    FIGURE1_Y_PER_P,
    twist_from_picture,
)
from spectral_rod.figure1.forensics.explain import (
    CLUSTER_KINDS,
    explain_cluster,
    explain_missing,
    site_physics,
    twist_list,
)
from spectral_rod.figure1.forensics.hypotheses import (
    SCAN_VARIABLES,
    best_two_runs,
    quantisation_hypotheses,
    scan_hypotheses,
    variant_hypotheses,
)
from spectral_rod.figure1.forensics.physics import RANGES, twist_ranges
from spectral_rod.figure1.forensics.picture import (
    PUT_FORMAT,
    missing_grid_points,
    off_grid_runs,
)
from spectral_rod.figure1.forensics.quantisation import VARIABLES, Hypothesis
from spectral_rod.figure1.forensics.runs import find_runs, flank_positions
from spectral_rod.figure1.forensics.scan import RULES_BY_NAME, report_band, scan_model
from spectral_rod.rod.closed_form import crossing_closed_form, imaginary_beta1_window
from spectral_rod.rod.critical import critical_load

#: Tolerance of the default converged p* (:func:`spectral_rod.critical_load`).
P_STAR_TOL = 1e-12


def _default_p_star(twist: NDArray, nu: NDArray) -> NDArray:
    """The converged p* (collocation to :data:`P_STAR_TOL`, the package's production route)."""
    return np.asarray(critical_load(twist, nu, tol=P_STAR_TOL), dtype=float)


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


def _grids(points: pd.DataFrame) -> dict[int, dict]:
    """Per curve, once: the regular x-grid's step, its missing points, the off-grid x and their
    runs (:func:`missing_grid_points`, :func:`off_grid_runs`)."""
    out = {}
    for c in range(1, len(FIGURE1_NU) + 1):
        x = points.loc[points["curve"] == c, "picture_x"].to_numpy()
        missing, off, step = missing_grid_points(x)
        out[c] = {"step": step, "missing": missing, "off": off,
                  "off_runs": [] if step is None else off_grid_runs(x, step)}
    return out


def _sites(points: pd.DataFrame, grids: dict[int, dict], p_star_fn: Callable) -> pd.DataFrame:
    """Data points plus the missing points of each curve's regular grid (in_data False), the
    data points first, in source order."""
    pts = points.assign(in_data=True, off_grid=False)
    extra = []
    for c, nu in zip(range(1, len(FIGURE1_NU) + 1), FIGURE1_NU, strict=True):
        sel = (pts["curve"] == c).to_numpy()
        pts.loc[sel, "off_grid"] = pts.loc[sel, "picture_x"].isin(grids[c]["off"]).to_numpy()
        extra += [{"curve": c, "nu": nu, "picture_x": x, "picture_y": np.nan,
                   "twist_angle": twist_from_picture(x), "in_data": False, "off_grid": False}
                  for x in grids[c]["missing"]]
    if extra:
        miss = pd.DataFrame(extra)
        miss["p_true"] = p_star_fn(miss["twist_angle"].to_numpy(), miss["nu"].to_numpy())
        pts = pd.concat([pts, miss], ignore_index=True)
    return pts


def _run_scans(sites: pd.DataFrame, runs: dict[str, Hypothesis]) -> pd.DataFrame:
    """Each run's own scan at every site: found (bool), its reported y and its count of
    undefined values. The data points reuse the run's scan (:attr:`Hypothesis.scan`, same
    order); only the missing grid points are scanned here."""
    data = sites["in_data"].to_numpy()
    order = np.concatenate([np.flatnonzero(data), np.flatnonzero(~data)])
    t, nu = sites["twist_angle"].to_numpy()[order], sites["nu"].to_numpy()[order]
    out = sites.copy()
    for r, h in runs.items():
        if h.scan is None or len(h.scan.upper) != data.sum():
            raise ValueError(f"runs[{r!r}] must be a scan hypothesis of the data points")
        sc = h.scan.extended(t[data.sum():], nu[data.sum():])
        for col, values in (("scan_found", np.isfinite(sc.upper)),
                            ("scan_y", scan_model(sc, cast(str, h.scan_rule), t, nu)),
                            ("undefined", sc.undefined)):
            full = np.empty(len(sites), dtype=values.dtype)
            full[order] = values
            out[f"{r}_{col}"] = full
    return out


def _own_run(sites: pd.DataFrame, runs: dict[str, Hypothesis], column: str) -> NDArray:
    """Per site, the column `r_<column>` of its covering run r."""
    run = sites["run"].to_numpy()
    out = np.zeros(len(sites), dtype=sites[f"{next(iter(runs))}_{column}"].dtype)
    for r in runs:
        out[run == r] = sites[f"{r}_{column}"].to_numpy()[run == r]
    return out


@dataclass(frozen=True)
class Forensics:
    """Everything :func:`analyse_figure1` found; :meth:`to_json` is figure1_forensics.json.

    sites: one row per data point (in_data) and per missing grid point, with the truth, the
    physics (:func:`site_physics`), the covering run, the best model's y and ok, and cluster
    (index into clusters, -1 if none).

    Examples
    --------
    >>> sorted(Forensics.__dataclass_fields__)[:3]   # :func:`analyse_figure1` returns one
    ['best', 'clusters', 'crossings']
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

    def max_deviation(self, mask: NDArray[np.bool_] | None = None) -> float:
        """max |digitised - converged p*| over the data points (those selected by `mask`; 0 if
        none is)."""
        p = self.points
        d = np.abs(p["p_digitised"] - p["p_true"]).to_numpy()
        d = d[mask] if mask is not None else d
        return float(d.max()) if d.size else 0.0

    def range_sizes(self) -> dict[str, int]:
        """Data points below / in / above the imaginary-beta_1 window (:data:`RANGES` order)."""
        r = self.points["range"].to_numpy()
        return {k: int((r == k).sum()) for k in RANGES}

    def run_summary(self) -> dict[str, dict]:
        """Per run ('low', 'high'): the scan variable, its description, the step and the report
        rule, in words."""
        return {r: {"variable": h.variable, "description": VARIABLES[h.variable].description,
                    "step": h.step, "rule": h.scan_rule,
                    "reported_at": (RULES_BY_NAME[h.scan_rule].words
                                    if h.scan_rule in RULES_BY_NAME else h.rounding)}
                for r, h in self.runs.items()}

    @cached_property
    def model_band(self) -> pd.DataFrame:
        """Per site: the band [band_low, band_high] of p - p* in which its covering run's
        procedure puts the value it reports (one scan step, :func:`report_band`);
        NaN where that scan finds no value. Computed once: :func:`analyse_figure1` has
        finished the sites and runs it depends on before it builds the Forensics (frozen: its
        fields are not reassigned; callers treat its frames, this one included, as read-only)."""
        s = self.sites
        t, nu, p = (s[c].to_numpy() for c in ("twist_angle", "nu", "p_true"))
        run, found = s["run"].to_numpy(), s["scan_found"].to_numpy(dtype=bool)
        low, high = np.full(len(s), np.nan), np.full(len(s), np.nan)
        for r, h in self.runs.items():
            sel = (run == r) & found
            low[sel], high[sel] = report_band(h.variable, cast(float, h.step),
                                              cast(str, h.scan_rule), p[sel], t[sel], nu[sel])
        return pd.DataFrame({"band_low": low, "band_high": high}, index=s.index)

    def reproduced_deviation(self) -> dict:
        """digitised - p* over the reproduced points: its range, and how many lie within the
        run's band widened by the print rounding (half a print quantum in p* either side) --
        all of them if the printed values are the procedure's (the bound is checked, not
        assumed). min and max are None where no point is reproduced."""
        in_data = self.sites["in_data"].to_numpy()
        s, band = self.sites[in_data], self.model_band[in_data]
        ok = s["ok"].to_numpy(dtype=bool)
        dev = (s["p_digitised"] - s["p_true"]).to_numpy()[ok]
        rounding = 0.5 * FIGURE1_PRINT_QUANTUM / FIGURE1_Y_PER_P
        lo, hi = band["band_low"].to_numpy()[ok], band["band_high"].to_numpy()[ok]
        slack = 1e-12  # the rounding of p* itself
        within = (dev >= lo - rounding - slack) & (dev <= hi + rounding + slack)
        return {"points": int(ok.sum()), "min": float(dev.min()) if dev.size else None,
                "max": float(dev.max()) if dev.size else None,
                "within_band": int(within.sum()), "print_rounding": rounding}

    def missing_groups(self) -> list[list[dict]]:
        """The missing points in runs of grid neighbours (one grid step apart on one curve)
        with the same causes."""
        groups: list[list[dict]] = []
        for m in self.missing_points:
            g = groups[-1] if groups else None
            if (g and g[-1]["nu"] == m["nu"] and g[-1]["causes"] == m["causes"]
                    and m["grid_step"] is not None
                    and round(abs(m["picture_x"] - g[-1]["picture_x"]) / m["grid_step"]) == 1):
                g.append(m)
            else:
                groups.append([m])
        return groups

    def cluster_groups(self) -> list[dict]:
        """The clusters by kind (:data:`CLUSTER_KINDS` order): how many points, with a
        computed cause, inserted separately (edited lines), printed on a sloped straight line or
        flat, the largest deviation, and the family crossings (n) they hold."""
        out = []
        for kind in CLUSTER_KINDS:
            cs = [c for c in self.clusters if c["kind"] == kind]
            if not cs:
                continue
            out.append({"kind": kind, "clusters": len(cs),
                        "points": sum(c["points"] for c in cs),
                        "caused": sum(c["caused_points"] for c in cs),
                        "edited": (None if any(c["edited_points"] is None for c in cs) else
                                   sum(len(c["edited_points"]) for c in cs)),
                        "sloped_line": sum(c["printed_as"]["sloped line"] for c in cs),
                        "flat": sum(c["printed_as"]["flat"] for c in cs),
                        "max_abs_deviation": max(c["max_abs_deviation"] for c in cs),
                        "crossings": sorted({c["crossing"]["n"] for c in cs if c["crossing"]})})
        return out

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
                "edited_reproduced": [{"nu": float(n), "twist_angle": float(t),
                                       "reproduced": bool(o)}
                                      for n, t, o in zip(rest["nu"], rest["twist_angle"],
                                                         rest["ok"], strict=True)]}

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
                "reproduced_deviation": self.reproduced_deviation(),
                "in_clusters": int((p["cluster"] >= 0).sum()),
                "unaccounted": len(self.unaccounted())}


def _switch_record(curve_rows: pd.DataFrame, lo: Hypothesis, hi: Hypothesis, s_first: int,
                   s_last: int) -> dict:
    """Where the two runs meet on one curve, next to the imaginary-beta_1 window (the points'
    'range').

    low_last: the last point before the latest optimal split that the low run reproduces;
    high_first: the first point from the earliest optimal split that the high run reproduces.
    """
    t, rng = curve_rows["twist_angle"].to_numpy(), curve_rows["range"].to_numpy()
    idx = curve_rows.index.to_numpy()
    low_ok = np.flatnonzero(lo.ok[idx][:s_last])
    high_ok = np.flatnonzero(hi.ok[idx][s_first:]) + s_first
    below, above = t[rng == RANGES[0]], t[rng == RANGES[2]]
    rec = {"low_run_last_reproduced": float(t[low_ok[-1]]) if low_ok.size else None,
           "high_run_first_reproduced": float(t[high_ok[0]]) if high_ok.size else None,
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
                   "predicted_only": twist_list(g, fail & ~irregular),
                   "irregular_only": twist_list(g, irregular & ~fail)}
    return out


def _cluster_all(sites: pd.DataFrame, runs: dict[str, Hypothesis], grids: dict[int, dict]
                 ) -> list[dict]:
    """Find and explain the clusters of every curve; sets sites['cluster'] in place."""
    clusters: list[dict] = []
    sites["cluster"] = -1
    with_blank = (int((~sites.loc[sites["in_data"], "edited"].astype(bool)).sum())
                  if "edited" in sites else None)
    for c in range(1, len(FIGURE1_NU) + 1):
        idx = np.flatnonzero(sites["in_data"].to_numpy() & (sites["curve"] == c).to_numpy())
        rows = sites.iloc[idx]
        ok = rows["ok"].to_numpy(dtype=bool)
        for first, last in find_runs(~ok):
            left, right = (None if i is None else rows.iloc[i]
                           for i in flank_positions(ok, first, last))
            rec = explain_cluster(rows.iloc[first:last + 1], left, right, runs, with_blank,
                                  grids[c]["off_runs"])
            sites.iloc[idx[first:last + 1], sites.columns.get_loc("cluster")] = len(clusters)
            clusters.append(rec)
    return clusters


def _crossings(nu: float, twist_max: float) -> list[dict]:
    """The family crossings (closed form) at twists up to twist_max, n = 2, 3, ..."""
    out, n = [], 2
    while (c := crossing_closed_form(n, nu)).twist <= twist_max:
        out.append(vars(c))
        n += 1
    return out


def _checked(p_star_fn: Callable[[NDArray, NDArray], NDArray]
             ) -> Callable[[NDArray, NDArray], NDArray]:
    """A caller's p_star_fn whose every answer must be finite, one value per point (else a
    ValueError naming it, not an all-NaN warning and a RuntimeError deep in the analysis)."""
    def fn(twist: NDArray, nu: NDArray) -> NDArray:
        p = np.asarray(p_star_fn(twist, nu), dtype=float)
        if p.shape != np.shape(twist) or not np.all(np.isfinite(p)):
            raise ValueError(f"p_star_fn must return finite p*, one per point (shape "
                             f"{np.shape(twist)}), got shape {p.shape}, "
                             f"{int(np.sum(~np.isfinite(p)))} non-finite")
        return p
    return fn


def analyse_figure1(points: pd.DataFrame, lines: pd.DataFrame | None = None, *,
                    p_true: NDArray[np.float64] | None = None,
                    p_star_fn: Callable[[NDArray, NDArray], NDArray] | None = None) -> Forensics:
    """Explain every digitised point of Figure 1 (module docstring).

    points: :func:`spectral_rod.figure1.data.load_figure1` (source order); lines:
    :func:`picture_lines` of the same picture (LaTeX evidence; optional); p_true: the converged
    p* at the points (default: ``p_star_fn``); p_star_fn(twist, nu): the converged p* anywhere
    (default ``critical_load(..., tol=P_STAR_TOL)``), used at missing grid points and shifted
    twists.

    Raises TypeError if `points` is not such a DataFrame, ValueError naming the column if one
    of its numeric columns holds NaN, inf or a non-number (e.g. a NaN ``p_star``), and
    ValueError if `p_true` is not one finite value per point.

    Returns
    -------
    Forensics
        Every explained point, the fitted plotting hypotheses, the runs, clusters and
        missing grid points (fields of :class:`Forensics`).

    Examples
    --------
    >>> import spectral_rod as sr
    >>> points = sr.load_figure1()
    >>> f = analyse_figure1(points[points["nu"] == 1.5].head(40))   # one curve's first points
    >>> len(f.sites), bool(f.sites["ok"].all())   # each reproduced by the best hypothesis
    (40, True)
    """
    need = {"curve", "nu", "picture_x", "picture_y", "twist_angle", "p_star"}
    if not isinstance(points, pd.DataFrame) or not need <= set(points.columns):
        raise TypeError(f"points must be the DataFrame of load_figure1() (columns {sorted(need)}), "
                        f"got {type(points).__name__}")
    if points.empty:
        raise ValueError("points: no digitised points to analyse (every model is fitted to them)")
    for col in sorted(need - {"curve"}):
        values = pd.to_numeric(points[col], errors="coerce").to_numpy(dtype=float)
        bad = ~np.isfinite(values)
        if bad.any():
            raise ValueError(f"points[{col!r}] must be finite numbers (the digitised points of "
                             f"load_figure1()); row {int(np.argmax(bad))} holds "
                             f"{points[col].iloc[int(np.argmax(bad))]!r}")
    if lines is not None and not isinstance(lines, pd.DataFrame):
        raise TypeError(f"lines must be None or picture_lines(...), got {type(lines).__name__}")
    if p_true is not None:
        p_true = real_array(p_true, "p_true")
        if p_true.shape != (len(points),):
            raise ValueError(f"p_true must have one value per point ({len(points)}), got shape "
                             f"{p_true.shape}")
    if p_star_fn is not None and not callable(p_star_fn):
        raise TypeError(f"p_star_fn must be callable, got {type(p_star_fn).__name__}")
    p_star_fn = _checked(p_star_fn) if p_star_fn is not None else _default_p_star
    pts = points.reset_index(drop=True).rename(columns={"p_star": "p_digitised"})
    t, nu, y = (pts[c].to_numpy() for c in ("twist_angle", "nu", "picture_y"))
    pts["p_true"] = p_star_fn(t, nu) if p_true is None else np.asarray(p_true, dtype=float)
    pts = _attach_lines(pts, lines)
    pts["range"] = twist_ranges(t, nu)
    p = pts["p_true"].to_numpy()
    quant = quantisation_hypotheses(p, t, nu, y)
    # the scans step their variable on the lattice the ceil quantisation of p* fits best
    ceil_steps = {v: next(cast(float, h.step) for h in quant
                          if h.variable == v and h.rounding == "ceil")
                  for v, _ in SCAN_VARIABLES}
    scan_h = scan_hypotheses(t, nu, y, ceil_steps)
    upper = sorted((h for h in scan_h if h.scan_rule == "upper"), key=lambda h: -int(h.ok.sum()))
    best_q = max(quant, key=lambda h: h.ok.sum())
    singles = quant + scan_h + variant_hypotheses(upper[:2], best_q, p, t, nu, y, p_star_fn)
    curve = pts["curve"].to_numpy()
    hand = pts["edited"].to_numpy(dtype=bool) if "edited" in pts else None
    comp_all = best_two_runs(singles, t, curve, " (any hypotheses)")[0]
    # the best model is a *procedure*: it also says where no value can be produced, and is
    # credited where that coincides with a line inserted separately
    procedures = [h for h in singles if h.is_procedure]
    best, lo, hi, splits = best_two_runs(procedures, t, curve, " (sign-change scans)", hand)
    hyps = [*singles, comp_all, best]
    runs = {"low": lo, "high": hi}
    pts["y_model"], pts["ok"] = best.y_model, best.ok
    switch_twist = {}
    for c, (s, _) in splits.items():
        tc = t[curve == c]
        switch_twist[c] = tc[s] if s < len(tc) else math.inf
    grids = _grids(pts)
    sites = _sites(pts, grids, p_star_fn)
    below = sites["twist_angle"].to_numpy() < sites["curve"].map(switch_twist).to_numpy(float)
    sites["run"] = np.where(below, "low", "high")
    sites = _run_scans(site_physics(sites, runs), runs)
    for col in ("double_root", "scan_found"):
        sites[col] = _own_run(sites, runs, col).astype(bool)
    sites["ok"] = sites["ok"].fillna(False).astype(bool)
    clusters = _cluster_all(sites, runs, grids)
    missing = [explain_missing(r, sites, runs, grids[r["curve"]]["off_runs"],
                               grids[r["curve"]]["step"])
               for _, r in sites[~sites["in_data"]].iterrows()]
    curve_of = {n: c for c, n in enumerate(FIGURE1_NU, 1)}
    switches = {nu_: _switch_record(pts[pts["curve"] == curve_of[nu_]], lo, hi,
                                    *splits[curve_of[nu_]])
                for nu_ in FIGURE1_NU if curve_of[nu_] in splits}  # curves with points
    for nu_, rec in switches.items():
        rec.update(_undefined_record(sites[sites["in_data"] & (sites["nu"] == nu_)]))
    windows = {n: vars(imaginary_beta1_window(n)) for n in FIGURE1_NU}
    crossings = {n: _crossings(n, float(sites.loc[sites["nu"] == n, "twist_angle"].max()))
                 for n in FIGURE1_NU}
    return Forensics(sites, hyps, best, runs, switches, clusters, missing, _prediction(sites),
                     windows, crossings)
