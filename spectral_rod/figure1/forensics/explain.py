"""Per-site physics and the explanation of each cluster and missing grid point: computed
causes (window, double root in one step, scan failure, edited lines) and value rules
(straight line, flanking value, lattice point).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import cast

import numpy as np
import pandas as pd
from numpy.typing import NDArray
from scipy.optimize import linprog

from spectral_rod.figure1.data import (
    FIGURE1_PRINT_QUANTUM,
    FIGURE1_X_PER_TWIST,
    picture_y_from_p_star,
)
from spectral_rod.figure1.forensics.physics import family_loads, twist_ranges, wavenumbers_squared
from spectral_rod.figure1.forensics.quantisation import (
    VARIABLES,
    Hypothesis,
    printed,
    quantise,
    reproduced,
)
from spectral_rod.figure1.forensics.runs import chord_values
from spectral_rod.rod.closed_form import crossing_closed_form, imaginary_beta1_window

#: Two computations of p* at a site (collocation, the families' lowest roots) must agree to this.
_P_STAR_AGREEMENT = 1e-9
#: A fitted line with |slope| (picture units per picture unit) below this is horizontal.
_FLAT_SLOPE = 1e-9
#: The kinds of cluster (:func:`explain_cluster`'s 'kind'), in report order: a cluster is of
#: the first kind whose computed cause one of its points has, else 'edited lines' if one of its
#: LaTeX lines was inserted separately, else 'unexplained'.
CLUSTER_KINDS = ("imaginary-beta1 window", "double root in one scan step", "no sign change",
                 "edited lines", "unexplained")
#: The entries of CLUSTER_KINDS by name (labels), in the same order.
CLUSTER_WINDOW, CLUSTER_DOUBLE_ROOT, CLUSTER_NO_SIGN_CHANGE, CLUSTER_EDITED, CLUSTER_UNEXPLAINED = (
    CLUSTER_KINDS)
#: The computed causes of a point's failure (:func:`point_causes`' keys, the missing points'
#: 'causes'), in report order. The last, 'edited line', is LaTeX evidence, not a failure of the
#: procedure: a cluster's physics and a missing point's causes leave it out.
POINT_CAUSES = ("imaginary beta_1", "double root in one step", "no sign change", "edited line")
#: The entries of POINT_CAUSES by name (labels), in the same order.
CAUSE_IMAGINARY_BETA1, CAUSE_DOUBLE_ROOT, CAUSE_NO_SIGN_CHANGE, CAUSE_EDITED = POINT_CAUSES


def _same_step(p_a: NDArray, p_b: NDArray, twist: NDArray, nu: NDArray, variable: str,
               step: float) -> NDArray[np.bool_]:
    """Both loads in one lattice step (k step, (k+1) step] of `variable`: a double sign change."""
    var = VARIABLES[variable]
    ka = np.ceil(var.forward(p_a, twist, nu) / step)
    kb = np.ceil(var.forward(p_b, twist, nu) / step)
    return np.isfinite(ka) & (ka == kb)


def site_physics(sites: pd.DataFrame, runs: dict[str, Hypothesis]) -> pd.DataFrame:
    """Add the computed physics of every site (data point or missing grid point).

    Columns added: x_minus (beta_1^2 L^2 at p*), imaginary_beta1 (x_minus < 0), in_window
    (closed-form window), p_sym, p_anti (each family's lowest root), and for each run r in
    `runs` ('low', 'high'): r_double_root (both roots in one step of the run's lattice),
    r_root_below_start (the root lies below v = 0, where a coefficient scan starts).
    """
    t, nu, p = (sites[c].to_numpy() for c in ("twist_angle", "nu", "p_true"))
    out = sites.copy()
    out["x_minus"] = wavenumbers_squared(p, t, nu)[0]
    out["imaginary_beta1"] = out["x_minus"] < 0
    out["in_window"] = twist_ranges(t, nu) == "window"
    out["p_sym"], out["p_anti"] = family_loads(t, nu)
    gap = np.abs(np.fmin(out["p_sym"], out["p_anti"]) - p)
    if not (gap < _P_STAR_AGREEMENT).all():  # two independent routes to p* must agree
        raise ValueError(f"p_true (or p_star_fn's values) must be the converged p* to "
                         f"{_P_STAR_AGREEMENT:g}: it disagrees with the characteristic "
                         f"equation's family loads at {(~(gap < _P_STAR_AGREEMENT)).sum()} "
                         f"sites (max {np.nanmax(gap):.1e})")
    for r, h in runs.items():
        out[f"{r}_double_root"] = _same_step(out["p_sym"].to_numpy(), out["p_anti"].to_numpy(),
                                             t, nu, h.variable, cast(float, h.step))
        out[f"{r}_root_below_start"] = VARIABLES[h.variable].forward(p, t, nu) < 0
    return out


def _lower_end_rule(rows: pd.DataFrame, runs: dict[str, Hypothesis]) -> NDArray[np.bool_]:
    """Printed value = the lattice point just below the step holding both family roots."""
    t, nu, y = (rows[c].to_numpy() for c in ("twist_angle", "nu", "picture_y"))
    lo = np.fmin(rows["p_sym"].to_numpy(), rows["p_anti"].to_numpy())
    out = np.zeros(len(rows), dtype=bool)
    for r, h in runs.items():
        sel = (rows["run"] == r).to_numpy() & rows[f"{r}_double_root"].to_numpy()
        var, step = VARIABLES[h.variable], cast(float, h.step)  # a run: one scan step
        below = quantise(var.forward(lo, t, nu), step, "ceil") - step
        out |= sel & reproduced(picture_y_from_p_star(var.inverse(below, t, nu)), y)
    return out


@dataclass(frozen=True)
class LineFit:
    """A straight line y = a + b x through a cluster and its flanks, to the print quantum.

    on_line: cluster points within half a print quantum of the line (printed values a rounding
    of it); the flanks are always kept; residual: the largest |line - y| over the kept points.
    """

    a: float
    b: float
    residual: float
    on_line: NDArray[np.bool_]


def _minimax_line(x: NDArray, y: NDArray) -> tuple[float, float, float]:
    """(a, b, e): the line minimising max |a + b x - y| (a linear programme)."""
    ones = np.ones_like(x)
    a_ub = np.vstack([np.column_stack([ones, x, -ones]), np.column_stack([-ones, -x, -ones])])
    res = linprog([0.0, 0.0, 1.0], A_ub=a_ub, b_ub=np.concatenate([y, -y]),
                  bounds=[(None, None)] * 3, method="highs")
    if not res.success:  # pragma: no cover - the programme is always feasible
        raise RuntimeError(f"minimax line fit failed: {res.message}")
    return float(res.x[0]), float(res.x[1]), float(res.x[2])


def straight_line(x: NDArray, y: NDArray, flank_x: NDArray, flank_y: NDArray,
                  tol: float = FIGURE1_PRINT_QUANTUM / 2) -> LineFit:
    """Is the cluster a straight line between its flanks, up to rounding?

    The minimax line through the cluster points and the two flanks; while its residual exceeds
    ``tol`` (+1e-9) the cluster point farthest from the chord between the flanks (computed,
    trusted points) is set aside as a slip and the line refitted.

    >>> fit = straight_line([1, 2, 3], [1.0, 2.5, 3.0], np.array([0.0, 4.0]), np.array([0.0, 4.0]))
    >>> fit.on_line.tolist(), round(fit.b, 9), bool(abs(fit.residual) < 1e-9)
    ([True, False, True], 1.0, True)
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    chord = chord_values(x, (flank_x[0], flank_y[0]), (flank_x[-1], flank_y[-1]))
    keep = np.ones(x.size, dtype=bool)
    while True:
        a, b, e = _minimax_line(np.concatenate([x[keep], flank_x]),
                                np.concatenate([y[keep], flank_y]))
        if e <= tol + 1e-9 or keep.sum() == 0:
            return LineFit(a, b, e, keep)
        keep[int(np.argmax(np.where(keep, np.abs(y - chord), -1.0)))] = False


def value_rules(rows: pd.DataFrame, left: pd.Series | None, right: pd.Series | None,
                runs: dict[str, Hypothesis]) -> tuple[dict[str, NDArray[np.bool_]], LineFit | None]:
    """Which printed values of a cluster follow a rule, and the straight-line fit.

    Rules: 'straight line' (:func:`straight_line` between the flanking reproduced points),
    'flank value' (equal to a flanking printed value), 'lower end of the shared step' (the
    lattice point just below the step holding both family roots).
    """
    y = rows["picture_y"].to_numpy()
    rules: dict[str, NDArray[np.bool_]] = {}
    fit = None
    flanks = [f for f in (left, right) if f is not None]
    if len(flanks) == 2:
        fit = straight_line(rows["picture_x"].to_numpy(), y,
                            np.array([f["picture_x"] for f in flanks]),
                            np.array([f["picture_y"] for f in flanks]))
        rules["straight line"] = fit.on_line
    rules["flank value"] = np.isin(printed(y), printed(np.array([f["picture_y"]
                                                                 for f in flanks])))
    rules["lower end of the shared step"] = _lower_end_rule(rows, runs)
    return rules, fit


def point_causes(rows: pd.DataFrame) -> dict[str, NDArray[np.bool_]]:
    """Computed reasons why the covering run's procedure fails at each row (keys
    :data:`POINT_CAUSES`, in that order; 'edited line' only where `rows` has an ``edited``
    column).

    'imaginary beta_1': X_- < 0 at p* *and* inside the closed-form window (both computations
    must agree); 'double root in one step': both family roots in one step of the run's lattice;
    'no sign change': the run's real-wavenumber scan finds none; 'edited line': the LaTeX line
    lacks the program's trailing blank (if the LaTeX lines were given).
    """
    causes = {CAUSE_IMAGINARY_BETA1: (rows["imaginary_beta1"] & rows["in_window"]).to_numpy(),
              CAUSE_DOUBLE_ROOT: rows["double_root"].to_numpy(dtype=bool),
              CAUSE_NO_SIGN_CHANGE: ~rows["scan_found"].to_numpy(dtype=bool)}
    if "edited" in rows:
        causes[CAUSE_EDITED] = rows["edited"].to_numpy(dtype=bool)
    return causes


def twist_list(rows: pd.DataFrame, mask: NDArray[np.bool_]) -> list[float]:
    """The twists of the rows selected by `mask` (rounded to 1e-6, for JSON and text)."""
    return [round(float(v), 6) for v in rows["twist_angle"].to_numpy()[mask]]


def _nearest_crossing(nu: float, t0: float, t1: float) -> dict:
    """The family crossing (corner maximum) nearest the interval [t0, t1], closed form."""
    cands = [crossing_closed_form(n, nu) for n in range(2, 2 + max(2, math.ceil(t1 / math.pi)))]
    c = min(cands, key=lambda c: max(t0 - c.twist, c.twist - t1, 0.0))
    dist = max(t0 - c.twist, c.twist - t1, 0.0)
    return {"n": c.n, "twist": c.twist, "p_star": c.p_star, "distance": dist,
            "inside": bool(dist == 0.0)}


def _cause_sentences(rows: pd.DataFrame, causes: dict[str, NDArray[np.bool_]],
                     runs: dict[str, Hypothesis], nu: float) -> list[str]:
    """The computed causes of a cluster (or missing point) in words, every number from rows."""
    n, out = len(rows), []
    t0, t1 = float(rows["twist_angle"].min()), float(rows["twist_angle"].max())
    im = causes[CAUSE_IMAGINARY_BETA1]
    if im.any():
        w = imaginary_beta1_window(nu)
        out.append(f"β₁ is imaginary (X₋ < 0 at p*) at {im.sum()} of {n}: the closed-form window "
                   f"for ν = {nu} is {w.omega_a:.4f} < Ω(L) < {w.omega_b:.4f} "
                   f"(asymptotics.imaginary_beta1_window)"
                   + (f"; outside it: Ω = {twist_list(rows, ~im)}" if (~im).any() else ""))
        if "low" in runs and rows["low_root_below_start"].any():
            var = VARIABLES[runs["low"].variable]
            out.append(f"the low-twist run scans {var.name} ({var.description}) upward from 0,"
                       f" and the root lies below that start ({var.name} < 0 at p*) at "
                       f"{int(rows['low_root_below_start'].sum())} of {n}")
    dr = causes[CAUSE_DOUBLE_ROOT]
    if dr.any():
        run = rows["run"].to_numpy()[dr][0]
        h = runs[run]
        c = _nearest_crossing(nu, t0, t1)
        where = "inside the cluster" if c["inside"] else f"{c['distance']:.3f} away"
        tw = twist_list(rows, dr)
        out.append(f"both families' lowest roots lie in one step of the {run}-twist lattice "
                   f"({h.variable} = k·{h.step:g}) at {dr.sum()} of {n} (Ω = "
                   f"{tw[0]:.3f}…{tw[-1]:.3f}), so D_sym·D_anti "
                   f"(the 4x4 determinant / 16Ω²) changes sign twice within one step; the family"
                   f" crossing Ω_{c['n']} = {c['twist']:.4f} (p* = {c['p_star']:.6f}, "
                   f"crossing_closed_form) is {where}")
    ns = causes[CAUSE_NO_SIGN_CHANGE]
    if ns.any():
        run = rows["run"].to_numpy()[ns][0]
        out.append(f"the {run}-twist run's simulated scan ({runs[run].variable} = k·"
                   f"{runs[run].step:g}, real wavenumbers) finds no sign change below "
                   f"p = (1 + ν)/2 at {ns.sum()} of {n}")
    return out


def _value_sentences(rows: pd.DataFrame, rules: dict[str, NDArray[np.bool_]],
                     fit: LineFit | None, left: pd.Series | None, right: pd.Series | None
                     ) -> list[str]:
    """What was printed instead of the procedure's value, in words."""
    n, out = len(rows), []
    x, y = rows["picture_x"].to_numpy(), rows["picture_y"].to_numpy()
    on_line = fit is not None and fit.on_line.sum() > n / 2
    if on_line:
        assert fit is not None and left is not None and right is not None  # a fit: two flanks
        shape = ("a horizontal line" if abs(fit.b) < _FLAT_SLOPE else
                 f"a straight line (slope {fit.b * FIGURE1_X_PER_TWIST:.3f} per rad)")
        s = (f"{shape} through the flanking computed points (x, y) = "
             f"({left['picture_x']:.2f}, {left['picture_y']:.2f}) and "
             f"({right['picture_x']:.2f}, {right['picture_y']:.2f}) reproduces "
             f"{fit.on_line.sum()} of {n} to the print quantum (largest residual "
             f"{abs(fit.residual):.4f})")
        for i in np.flatnonzero(~fit.on_line):
            line_y = fit.a + fit.b * x[i]
            s += (f"; x = {x[i]:.2f} is printed {y[i]:.2f} where the line gives {line_y:.3f} "
                  f"({(y[i] - line_y) / FIGURE1_PRINT_QUANTUM:+.1f} quanta: an isolated slip)")
        out.append(s)
    low, flat = rules["lower end of the shared step"], rules["flank value"]
    if low.any():
        out.append(f"{low.sum()} of {n} are the lattice point just below the step holding both "
                   f"roots")
    if flat.any() and not on_line:
        vals = sorted({f"{f['picture_y']:.2f}" for f in (left, right) if f is not None})
        out.append(f"{flat.sum()} of {n} equal a flanking printed value ({', '.join(vals)})")
    rest = np.zeros(n, dtype=bool) if on_line else ~(low | flat)
    if rest.any():
        out.append("matched by no value rule: " + ", ".join(
            f"x = {r['picture_x']:.2f} printed {r['picture_y']:.2f} (p* gives "
            f"{picture_y_from_p_star(r['p_true']):.3f})" for _, r in rows[rest].iterrows()))
    return out


def _latex_sentence(rows: pd.DataFrame, with_blank: int | None,
                    off_runs: list[dict] | None = None) -> str | None:
    """The LaTeX facts of a cluster's lines; with_blank: how many lines of the whole picture
    end in the trailing blank (the program's format); off_runs: :func:`off_grid_runs` of the
    curve."""
    if "edited" not in rows:
        return None
    n, h = len(rows), int(rows["edited"].sum())
    first, last = int(rows["line"].iloc[0]), int(rows["line"].iloc[-1])
    s = (f"LaTeX (picture lines {first}–{last}): {h} of {n} lines lack the trailing blank "
         f"that {with_blank} of the picture's lines end in"
         + (" (inserted separately from the scan program's output)" if h == n else
            f" (those {h} inserted separately from the scan program's output)" if h else ""))
    blank = rows["after_blank_line"].to_numpy(dtype=bool)
    if blank[0]:
        s += "; a blank line precedes the block"
    if blank[1:].any():
        s += "; blank lines inside it before x = " + ", ".join(
            f"{v:.2f}" for v in rows["picture_x"].to_numpy()[1:][blank[1:]])
    off = int(rows["off_grid"].sum())
    x0, x1 = rows["picture_x"].min(), rows["picture_x"].max()
    for r in off_runs or []:
        if off and r["first"] <= x1 and r["last"] >= x0:
            s += (f"; {off} x values are off the regular grid: the picture's {r['count']} "
                  f"off-grid x ({r['first']:.2f}…{r['last']:.2f}) divide {r['left']:.2f}…"
                  f"{r['right']:.2f} into {r['count'] + 1} equal steps of {r['spacing']:.4f} "
                  f"(to {r['max_deviation']:.4f})")
    return s


def _uncaused_sentence(rows: pd.DataFrame, causes: dict[str, NDArray[np.bool_]],
                       runs: dict[str, Hypothesis]) -> str | None:
    """Points where no computed failure applies: what each run's procedure would print."""
    none = ~(causes[CAUSE_IMAGINARY_BETA1] | causes[CAUSE_DOUBLE_ROOT]
             | causes[CAUSE_NO_SIGN_CHANGE])
    if not none.any():
        return None
    items = []
    for _, r in rows[none].iterrows():
        got = ", ".join(f"{k}-twist scan {r[f'{k}_scan_y']:.2f}" for k in runs
                        if np.isfinite(r[f"{k}_scan_y"]))
        items.append(f"Ω = {r['twist_angle']:.3f}: printed {r['picture_y']:.2f}, {got}")
    s = "The procedure does not fail at " + "; ".join(items)
    if "edited" in rows:
        m, h = int(none.sum()), int(rows["edited"].to_numpy(dtype=bool)[none].sum())
        s += (f" -- its line {'lacks' if h else 'ends in'} the program's trailing blank"
              if m == 1 else f" -- {h} of these {m} lines lack the program's trailing blank")
        if h == m and (~none).any():
            s += ": inserted together with the neighbours where the procedure fails"
    return s + "."


def _cluster_kind(causes: dict[str, NDArray[np.bool_]]) -> str:
    """The cluster's kind (:data:`CLUSTER_KINDS`) from its points' causes."""
    if causes[CAUSE_IMAGINARY_BETA1].any():
        return CLUSTER_WINDOW
    if causes[CAUSE_DOUBLE_ROOT].any():
        return CLUSTER_DOUBLE_ROOT
    if causes[CAUSE_NO_SIGN_CHANGE].any():
        return CLUSTER_NO_SIGN_CHANGE
    edited = causes.get(CAUSE_EDITED, np.zeros(1, bool)).any()
    return CLUSTER_EDITED if edited else CLUSTER_UNEXPLAINED


def explain_cluster(rows: pd.DataFrame, left: pd.Series | None, right: pd.Series | None,
                    runs: dict[str, Hypothesis], with_blank: int | None = None,
                    off_runs: list[dict] | None = None) -> dict:
    """The cluster record: where, how big, and why, from the rows' computed columns.

    rows: the cluster's data sites (columns of :func:`site_physics` and :func:`_run_scans`,
    plus run, double_root, scan_found, ok, p_digitised and the LaTeX columns if known);
    left/right: the flanking reproduced points; with_blank: lines of the picture in the
    program's format, off_runs: the curve's :func:`off_grid_runs` (both for the text).
    'explained' is True iff every point has a computed cause or is an edited line;
    'window_points' lists only points inside the window; 'caused_points' counts the points with
    a computed failure of the procedure; 'printed_as' counts the points on a sloped straight
    line ('sloped line') and those printed flat ('flat': on a horizontal line, or a flanking
    value).
    """
    nu = float(rows["nu"].iloc[0])
    causes = point_causes(rows)
    rules, fit = value_rules(rows, left, right, runs)
    covered = np.logical_or.reduce(list(causes.values()))
    dev = np.abs(rows["p_digitised"] - rows["p_true"]).to_numpy()
    physics = [v for k, v in causes.items() if k != CAUSE_EDITED]
    on_line = rules.get("straight line", np.zeros(len(rows), dtype=bool))
    horizontal = fit is not None and abs(fit.b) < _FLAT_SLOPE
    parts = [f"ν = {nu}, Ω(L) = {rows['twist_angle'].min():.3f}…"
             f"{rows['twist_angle'].max():.3f}: {len(rows)} points, "
             f"{int((~rows['ok']).sum())} not reproduced by the best model, "
             f"max |digitised − p*| = {dev.max():.2e}.",
             ("Cause: " + "; ".join(_cause_sentences(rows, causes, runs, nu)) + ".")
             if np.logical_or.reduce(physics).any() else "No computed failure of the procedure."]
    values = _value_sentences(rows, rules, fit, left, right)
    if values:
        parts.append("Printed instead: " + "; ".join(values) + ".")
    for extra in (_uncaused_sentence(rows, causes, runs),
                  _latex_sentence(rows, with_blank, off_runs)):
        if extra:
            parts.append(extra if extra.endswith(".") else extra + ".")
    return {"nu": nu, "twist_from": float(rows["twist_angle"].min()),
            "twist_to": float(rows["twist_angle"].max()), "points": len(rows),
            "not_reproduced": int((~rows["ok"]).sum()),
            "max_abs_deviation": float(dev.max()), "kind": _cluster_kind(causes),
            "explanation": " ".join(parts), "explained": bool(covered.all()),
            "window_points": twist_list(rows, causes[CAUSE_IMAGINARY_BETA1]),
            "double_root_points": twist_list(rows, causes[CAUSE_DOUBLE_ROOT]),
            "no_sign_change_points": twist_list(rows, causes[CAUSE_NO_SIGN_CHANGE]),
            "edited_points": (twist_list(rows, causes[CAUSE_EDITED])
                                  if CAUSE_EDITED in causes else None),
            "crossing": (_nearest_crossing(nu, float(rows["twist_angle"].min()),
                                           float(rows["twist_angle"].max()))
                         if causes[CAUSE_DOUBLE_ROOT].any() else None),
            "caused_points": int(np.logical_or.reduce(physics).sum()),
            "value_rules": {k: int(v.sum()) for k, v in rules.items()},
            "printed_as": {"sloped line": int(0 if horizontal else on_line.sum()),
                           "flat": int(((on_line & horizontal) | rules["flank value"]).sum())},
            "line": (None if fit is None else
                     {"a": fit.a, "b": fit.b, "residual": fit.residual,
                      "off_line": twist_list(rows, ~fit.on_line)}),
            "twists": twist_list(rows, np.ones(len(rows), dtype=bool))}


def explain_missing(row: pd.Series, sites: pd.DataFrame, runs: dict[str, Hypothesis],
                    off_runs: list[dict], grid_step: float | None = None) -> dict:
    """Why a regular grid point is absent: its computed causes, and the same twist elsewhere.

    row: the missing site (columns of :func:`site_physics`); sites: all sites (for the other
    curves at the same twist); off_runs: the curve's :func:`off_grid_runs` (the off-grid
    points written in the gap holding the missing point instead); grid_step: the curve's grid
    step in picture units (recorded, for grouping adjacent missing points).
    """
    nu, t, x = float(row["nu"]), float(row["twist_angle"]), float(row["picture_x"])
    one = row.to_frame().T.reset_index(drop=True)
    for c in ("imaginary_beta1", "in_window", "double_root", "scan_found"):
        one[c] = one[c].astype(bool)
    causes = point_causes(one.assign(edited=False))
    parts = _cause_sentences(one, causes, runs, nu)
    p_s, p_a = float(row["p_sym"]), float(row["p_anti"])
    text = (f"ν = {nu}, Ω(L) = {t:.3f} (x = {x:.2f}) is absent from the picture. "
            f"p* = {row['p_true']:.7f} (p_sym = {p_s:.7f}, p_anti = {p_a:.7f}). ")
    text += ("Cause: " + "; ".join(parts) + ". ") if parts else "No computed cause. "
    same = sites[(np.abs(sites["twist_angle"] - t) < 1e-9) & (sites["nu"] != nu)
                 & sites["in_data"]]
    for _, o in same.iterrows() if causes[CAUSE_DOUBLE_ROOT].any() else ():
        text += (f"At ν = {o['nu']} the same twist is present and "
                 f"{'reproduced' if o['ok'] else 'not reproduced'} by the best model (its roots "
                 f"p_sym = {o['p_sym']:.7f}, p_anti = {o['p_anti']:.7f} lie "
                 f"{'in one step' if o['double_root'] else 'in different steps'}). ")
    gap = next((r for r in off_runs if r["left"] < x < r["right"]), None)
    if gap:
        text += (f"The picture has {gap['count']} off-grid points of this curve in the gap "
                 f"between the grid points x = {gap['left']:.2f} and {gap['right']:.2f} that "
                 f"holds it (x = {gap['first']:.2f}…{gap['last']:.2f}) instead.")
    else:
        text += "No line was written for it (no inserted substitute)."
    return {"nu": nu, "twist_angle": t, "picture_x": x, "grid_step": grid_step,
            "explanation": text.strip(),
            "causes": [k for k, v in causes.items() if v.any() and k != CAUSE_EDITED],
            "crossing": (_nearest_crossing(nu, t, t) if causes[CAUSE_DOUBLE_ROOT].any()
                         else None),
            "explained": bool(any(v.any() for k, v in causes.items() if k != CAUSE_EDITED))}
