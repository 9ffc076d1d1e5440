r"""Figure 1 point by point: how the published values were produced, and why each one differs.

The paper's Figure 1 (p* against Omega(L) for nu = 1.1, 1.3, 1.5; hinged straight rod, Eq.
``inst1``, characteristic equation of :mod:`spectral_rod.characteristic`) is a LaTeX picture of
``\put(x, y){\circle*{1.0}}`` lines, Omega(L) = x/10 and p* = 1 + y/400, printed with two
decimals (:mod:`spectral_rod.figure_data`). Against the converged p* (the truth here) every
printed point is either *reproduced exactly* -- the same two-decimal y -- by a stated model of
the authors' procedure, or it belongs to a cluster or a missing grid point whose cause is
computed. Nothing below is fitted to a single point; every interval and count comes from code.

Models tested
-------------
* **Quantisation** of a variable v(p*) -- p*, p* - 1, lambda = pi^2 p*, the picture y =
  400 (p* - 1), and the two coefficients of Eq. ``inst1``, P - A2 omega30^2 and P - A1 omega30^2
  (lambda - nu Omega^2 and lambda - Omega^2 in units A1/L^2) -- onto the lattice k h (nearest,
  floor, ceil, truncation), h on a fixed grid of candidate steps (m 10^e, m in 1, 2, 2.5, 4, 5),
  then printed with two decimals. The step is fitted per variable and rounding rule.
* **Sign-change scan** (the paper's "standard methods"): step v through the lattice, evaluate
  the sign of the 4x4 boundary determinant (= 16 Omega^2 D_sym D_anti,
  :func:`spectral_rod.characteristic.boundary_determinant_4x4`; here D_sym D_anti in double
  precision from :func:`spectral_rod.characteristic.determinants`), stop at the first sign change
  and report the bracket's upper end, lower end, midpoint or linear interpolation. Variants:
  the determinant written with *real* wavenumbers beta_k = sqrt(X_k) (undefined, NaN, where
  X_- < 0), single precision, and the lattice start v >= 0 for the coefficient variables (the
  scan begins where the coefficient vanishes). Unlike the quantisation models the scan does not
  use the converged p*: it can fail (no sign change, or a wrong root), and where it fails is a
  prediction to compare with where the data are irregular.
* **Two runs**: one model below a switch twist and another above it, the switch fitted per
  curve (every split of the sorted twists is tried), for every ordered pair of hypotheses.

The *best* model is the two-run combination of scan (procedure) hypotheses that accounts for
the most points: reproduced exactly, or -- where the scan yields no value -- the LaTeX line was
inserted separately (:meth:`Hypothesis.credit`). A procedure must say where it fails; a quantisation
model yields a value everywhere and so also matches inserted values by coincidence (its best
two-run combination is reported alongside, with the count of such coincidences visible in the
window column of the table).

Beyond the model
----------------
Contiguous runs of points the best model does not reproduce (merged across at most
:data:`MERGE_GAP` reproduced points) are *clusters*; points of the regular x-grid absent from the
picture are *missing points*. Each gets computed evidence: the imaginary-beta_1 window
(:func:`spectral_rod.imaginary_beta1_window`, and X_- < 0 at the point itself), both families'
lowest roots in one scan step (a double sign change, invisible to a sign scan; family crossings
:func:`spectral_rod.asymptotics.crossing_closed_form`), the scan's own result there, and the
LaTeX lines themselves (lines without the trailing blank of the program's lines, blank-line
block boundaries, off-grid x) and what was printed instead (a straight line between the
flanking computed points to the print precision -- :func:`straight_line`, slips set
aside --, a flanking value, or the lattice point below both roots).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from numpy.typing import NDArray
from scipy.optimize import brentq, linprog

from spectral_rod._validation import real_array
from spectral_rod.asymptotics import crossing_closed_form, imaginary_beta1_window
from spectral_rod.characteristic import combine_determinant, determinants
from spectral_rod.critical import critical_load
from spectral_rod.figure_data import FIGURE1_NU
from spectral_rod.sign_scan import lowest_root
from spectral_rod.wavenumbers import characteristic_roots

__all__ = [
    "DOT",
    "MERGE_GAP",
    "PRINT_QUANTUM",
    "RANGES",
    "ROUNDINGS",
    "VARIABLES",
    "Y_PER_P",
    "Forensics",
    "Hypothesis",
    "LineFit",
    "ScanResult",
    "Variable",
    "analyse_figure1",
    "best_two_runs",
    "determinant_product",
    "explain_cluster",
    "explain_missing",
    "family_loads",
    "find_runs",
    "fit_quantisation",
    "fit_switch",
    "missing_grid_points",
    "off_grid_runs",
    "picture_environment",
    "picture_lines",
    "point_causes",
    "printed",
    "quantisation_hypotheses",
    "quantisation_model",
    "quantise",
    "reproduced",
    "scan_hypotheses",
    "scan_model",
    "scan_sign_change",
    "site_physics",
    "straight_line",
    "twist_ranges",
    "value_rules",
    "variant_hypotheses",
    "wavenumbers_squared",
]

#: Picture y units per unit of p* (p* = 1 + y/400, :mod:`spectral_rod.figure_data`).
Y_PER_P = 400.0
#: Picture x units per radian of Omega(L).
X_PER_TWIST = 10.0
#: The print quantum of the picture coordinates (two decimals).
PRINT_QUANTUM = 0.01
#: Diameter of a plotted dot (\circle*{1.0}) in picture units: what the reader can see.
DOT = 1.0
ROUNDINGS = ("nearest", "floor", "ceil", "truncate")
MANTISSAS = (1.0, 2.0, 2.5, 4.0, 5.0)
#: Non-reproduced runs separated by at most this many reproduced points form one cluster.
#: Why: inside an inserted block a model that always yields a value (a quantisation model)
#: agrees with an inserted value by chance with probability about (print quantum)/(its lattice step
#: in y), 0.01/0.04 ... 0.01/0.08, so a run can be split by one or two coincidences. For the
#: scan model of Figure 1 the clusters are contiguous: the same clusters for gaps 0 to 5
#: (measured when this was written).
MERGE_GAP = 2
_PUT_LINE = re.compile(r"^\\put\(\s*([-+0-9.]+)\s*,\s*([-+0-9.]+)\s*\)\s*\{\\circle\*")
#: The fixed-width format of the picture's point lines (Fortran-like F7.2, F8.2 fields).
PUT_FORMAT = "\\put(%7.2f,%8.2f){\\circle*{1.0}}"


# ------------------------------------------------------------------------------------------
# the LaTeX picture as data
# ------------------------------------------------------------------------------------------

def picture_environment(tex: str) -> str:
    r"""The lines from ``\begin{picture}`` to ``\end{picture}`` (inclusive), verbatim.

    Example: ``picture_environment(open(paper).read()).count(r"\circle*") == 1201``.
    """
    if not isinstance(tex, str):
        raise TypeError(f"tex must be the LaTeX source as a str, got {type(tex).__name__}")
    lines = tex.splitlines(keepends=True)
    begin = next((i for i, ln in enumerate(lines) if r"\begin{picture}" in ln), None)
    end = next((i for i, ln in enumerate(lines) if r"\end{picture}" in ln), None)
    if begin is None or end is None or end < begin:
        raise ValueError("tex: no \\begin{picture} ... \\end{picture} environment found")
    return "".join(lines[begin:end + 1])


def picture_lines(tex: str) -> pd.DataFrame:
    r"""One row per ``\put(x, y){\circle*...}`` line of the picture, in source order.

    Columns: curve (1..3, a new curve where x falls back), line (1-based line number within
    the picture environment), picture_x, picture_y, trailing_blank (the line ends in a blank,
    as most lines do), after_blank_line (the previous line is empty: a block boundary),
    fixed_format (the line, without trailing blanks, is exactly :data:`PUT_FORMAT`), text (the
    line verbatim).
    """
    env = picture_environment(tex).splitlines()
    rows, curve, last_x = [], 0, math.inf
    for k, text in enumerate(env):
        m = _PUT_LINE.match(text)
        if not m:
            continue
        x, y = float(m.group(1)), float(m.group(2))
        if x < last_x:
            curve += 1
        last_x = x
        rows.append((curve, k + 1, x, y, text.endswith(" "), k > 0 and not env[k - 1].strip(),
                     text.rstrip(" ") == PUT_FORMAT % (x, y), text))
    if curve != len(FIGURE1_NU):
        raise ValueError(f"tex: expected {len(FIGURE1_NU)} curves in the picture, found {curve}")
    return pd.DataFrame(rows, columns=["curve", "line", "picture_x", "picture_y",
                                       "trailing_blank", "after_blank_line", "fixed_format",
                                       "text"])


def missing_grid_points(x: NDArray[np.float64], step: float | None = None
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64], float]:
    """(grid points absent from x, x values off the grid, grid step) for one curve.

    The regular grid is step k, k = 1 .. round(max(x)/step), step the most common spacing of
    x (printed to 0.01, so compared to 1e-6). Example: x = [0.25, 0.5, 1.0] -> ([0.75], [], 0.25).
    """
    x = np.asarray(x, dtype=float)
    if step is None:
        gaps, counts = np.unique(np.round(np.diff(np.sort(x)), 6), return_counts=True)
        step = float(gaps[np.argmax(counts)])
    grid = step * np.arange(1, round(x.max() / step) + 1)
    on = np.abs(x / step - np.round(x / step)) < 1e-6
    present = np.round(x[on] / step).astype(int)
    missing = grid[~np.isin(np.arange(1, grid.size + 1), present)]
    return missing, x[~on], step


def off_grid_runs(x: NDArray[np.float64], step: float) -> list[dict]:
    """Runs of consecutive off-grid x (source order) and how they subdivide their gap.

    For each run: its first/last x and count, the on-grid neighbours left/right, the spacing
    (right - left)/(count + 1) of an equal subdivision, and the largest |x - subdivision|.
    Example: x = [0.25, 0.33, 0.42, 0.5], step 0.25 -> one run of 2 with spacing 0.0833.
    """
    x = np.asarray(x, dtype=float)
    off = np.abs(x / step - np.round(x / step)) >= 1e-6
    runs = []
    for first, last in find_runs(off, merge_gap=0):
        if first == 0 or last == x.size - 1:
            continue  # no on-grid neighbour on one side
        left, right, n = x[first - 1], x[last + 1], last - first + 1
        sub = left + (right - left) * np.arange(1, n + 1) / (n + 1)
        runs.append({"first": float(x[first]), "last": float(x[last]), "count": n,
                     "left": float(left), "right": float(right),
                     "spacing": float((right - left) / (n + 1)),
                     "max_deviation": float(np.max(np.abs(x[first:last + 1] - sub)))})
    return runs


# ------------------------------------------------------------------------------------------
# the physics at each point
# ------------------------------------------------------------------------------------------

def wavenumbers_squared(p: NDArray[np.float64], twist: NDArray[np.float64], nu: NDArray[np.float64]
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(X_-, X_+) = (beta_1^2 L^2, beta_2^2 L^2) at load p* = p (vectorised).

    Roots of (lambda - Omega^2 - X)(lambda/nu - Omega^2 - X) = 4 Omega^2 X, lambda = pi^2 p;
    X_- < 0 (beta_1 imaginary) iff lambda/nu < Omega^2 < lambda. Example: at Omega = 0,
    (X_-, X_+) = (lambda/nu, lambda).
    """
    lam = np.pi**2 * np.asarray(p, dtype=float)
    return characteristic_roots(lam, lam / np.asarray(nu, dtype=float),
                                np.asarray(twist, dtype=float))


def family_loads(twist: NDArray[np.float64], nu: NDArray[np.float64], step: float = 1.0 / 1024
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Lowest root p of each family, (p_sym, p_anti), at every (twist, nu) (double precision).

    Sign scan (:func:`spectral_rod.sign_scan.lowest_root`) of D_sym, D_anti
    (:func:`spectral_rod.characteristic.determinants`) from p = 1 - 1e-9
    to the family bound nu in steps ``step``, the first bracket refined by Brent's method. NaN
    where a family has no root below nu. Example: ``family_loads([0.5], [1.5])`` gives
    p_sym ~ 1.0084 (the critical one) and p_anti ~ 1.5 (near the planar mode nu pi^2).
    """
    tw, nv = np.broadcast_arrays(np.asarray(twist, float), np.asarray(nu, float))
    out = np.full((2, tw.size), np.nan)
    for i, (om, n) in enumerate(zip(tw.ravel(), nv.ravel(), strict=True)):
        for k in range(2):
            def values(grid, k=k, om=om, n=n):
                return np.array([determinants(np.array(grid), om, n)[k]])

            def refine(_c, a, b, k=k, om=om, n=n):
                return brentq(lambda p: float(determinants(p, om, n)[k]), a, b, xtol=1e-15,
                              rtol=4 * np.finfo(float).eps)

            found = lowest_root(values, refine, 1.0 - 1e-9, n + 1e-6, step, chunk=257)
            if found is not None:
                out[k, i] = found[0]
    return out[0].reshape(tw.shape), out[1].reshape(tw.shape)


def twist_ranges(twist: NDArray[np.float64], nu: NDArray[np.float64]) -> NDArray[np.str_]:
    """Label of each point relative to the imaginary-beta_1 window (Omega_a, Omega_b) of its nu.

    'below window' (Omega <= Omega_a), 'window', 'above window' (Omega >= Omega_b); the window
    from :func:`spectral_rod.imaginary_beta1_window`. Example: Omega = 1, nu = 1.5 -> 'below
    window'.
    """
    out = np.empty(np.shape(twist), dtype=object)
    for n in np.unique(nu):
        w = imaginary_beta1_window(float(n))
        sel = np.asarray(nu) == n
        t = np.asarray(twist)[sel]
        out[sel] = np.where(t <= w.omega_a, "below window",
                            np.where(t >= w.omega_b, "above window", "window"))
    return out.astype(str)


RANGES = ("below window", "window", "above window")


# ------------------------------------------------------------------------------------------
# quantisation hypotheses
# ------------------------------------------------------------------------------------------

def _steps(lo_exp: int, hi_exp: int) -> tuple[float, ...]:
    """m 10^e for m in MANTISSAS, e = lo_exp .. hi_exp (the fixed candidate grid of steps)."""
    return tuple(float(f"{m}e{e}") for e in range(lo_exp, hi_exp + 1) for m in MANTISSAS)


@dataclass(frozen=True)
class Variable:
    """A quantity the authors may have stepped or rounded: v = forward(p, twist, nu)."""

    name: str
    description: str
    forward: Callable[..., NDArray[np.float64]]
    inverse: Callable[..., NDArray[np.float64]]
    steps: tuple[float, ...]


_PI2 = math.pi**2
VARIABLES: dict[str, Variable] = {v.name: v for v in (
    Variable("p*", "p* itself", lambda p, t, n: p, lambda v, t, n: v, _steps(-6, -3)),
    Variable("p* - 1", "the rise above Euler's load", lambda p, t, n: p - 1.0,
             lambda v, t, n: v + 1.0, _steps(-6, -3)),
    Variable("lambda", "the load lambda = pi^2 p* = P L^2/A1", lambda p, t, n: _PI2 * p,
             lambda v, t, n: v / _PI2, _steps(-5, -2)),
    Variable("y", "the picture coordinate y = 400 (p* - 1)", lambda p, t, n: Y_PER_P * (p - 1.0),
             lambda v, t, n: 1.0 + v / Y_PER_P, _steps(-3, -1)),
    Variable("lambda - nu Omega^2", "the coefficient (P - A2 omega30^2) L^2/A1 of Eq. inst1",
             lambda p, t, n: _PI2 * p - n * t**2, lambda v, t, n: (v + n * t**2) / _PI2,
             _steps(-5, -2)),
    Variable("lambda - Omega^2", "the coefficient (P - A1 omega30^2) L^2/A1 of Eq. inst1",
             lambda p, t, n: _PI2 * p - t**2, lambda v, t, n: (v + t**2) / _PI2,
             _steps(-5, -2)),
)}


def quantise(v: NDArray[np.float64], step: float, rounding: str) -> NDArray[np.float64]:
    """v moved onto the lattice k * step by `rounding` (nearest: half up; truncate: toward 0).

    Example: quantise([0.0031], 0.002, 'ceil') -> [0.004].
    """
    u = np.asarray(v, dtype=float) / step
    rules = {"nearest": lambda a: np.floor(a + 0.5), "floor": np.floor, "ceil": np.ceil,
             "truncate": np.trunc}
    if rounding not in rules:
        raise ValueError(f"rounding must be one of {ROUNDINGS}, got {rounding!r}")
    return rules[rounding](u) * step


def printed(y: NDArray[np.float64]) -> NDArray[np.float64]:
    """y as the picture prints it, in hundredths (Fortran F-format: round half away from 0).

    NaN stays NaN (no value). Example: printed([18.975, 0.004]) -> [1898., 0.].
    """
    y = np.asarray(y, dtype=float)
    return np.sign(y) * np.floor(np.abs(y) * 100.0 + 0.5 + 1e-9)


def _y_of_p(p: NDArray[np.float64]) -> NDArray[np.float64]:
    return Y_PER_P * (np.asarray(p, dtype=float) - 1.0)


def reproduced(y_model: NDArray[np.float64], picture_y: NDArray[np.float64]) -> NDArray[np.bool_]:
    """True where the model's printed y equals the picture's (False where the model has none)."""
    return printed(y_model) == printed(picture_y)


@dataclass
class Hypothesis:
    """A model of the published values, its prediction and which points it reproduces."""

    name: str
    variable: str
    step: float | list[float] | None
    rounding: str
    y_model: NDArray[np.float64]
    ok: NDArray[np.bool_]
    description: str = ""

    def credit(self, edited: NDArray[np.bool_] | None) -> NDArray[np.bool_]:
        """Points the hypothesis accounts for: reproduced, or no value predicted where the
        LaTeX line was inserted separately (the procedure's failure seen in the source)."""
        if edited is None:
            return self.ok
        return self.ok | (np.isnan(self.y_model) & edited)

    def summary(self, nu: NDArray[np.float64], ranges: NDArray[np.str_],
                edited: NDArray[np.bool_] | None = None) -> dict:
        """JSON row: name, variable, step, rounding, reproduced_exactly, points, by_curve,
        by_range (per curve: {range: [reproduced, points]}), no_value (points where the
        procedure yields nothing), no_value_edited (of those, lines inserted separately)."""
        by_curve = {str(n): int(self.ok[nu == n].sum()) for n in FIGURE1_NU}
        by_range = {str(n): {r: [int(self.ok[(nu == n) & (ranges == r)].sum()),
                                 int(((nu == n) & (ranges == r)).sum())] for r in RANGES}
                    for n in FIGURE1_NU}
        return {"name": self.name, "variable": self.variable, "step": self.step,
                "rounding": self.rounding, "reproduced_exactly": int(self.ok.sum()),
                "points": int(self.ok.size), "by_curve": by_curve, "by_range": by_range,
                "no_value": int(np.isnan(self.y_model).sum()),
                "no_value_edited": (None if edited is None else
                                        int((np.isnan(self.y_model) & edited).sum())),
                "description": self.description}


def quantisation_model(p_true: NDArray[np.float64], twist: NDArray[np.float64],
                       nu: NDArray[np.float64], variable: str, step: float, rounding: str
                       ) -> NDArray[np.float64]:
    """Picture y (unprinted) if the authors' value were v(p*) quantised to `step`."""
    var = VARIABLES[variable]
    v = quantise(var.forward(p_true, twist, nu), step, rounding)
    return _y_of_p(var.inverse(v, twist, nu))


def fit_quantisation(p_true: NDArray[np.float64], twist: NDArray[np.float64],
                     nu: NDArray[np.float64], picture_y: NDArray[np.float64], variable: str,
                     rounding: str, steps: tuple[float, ...] | None = None) -> Hypothesis:
    """The step (from the variable's fixed grid) that reproduces the most points exactly.

    Ties go to the coarser step (fewer distinct values: the stronger statement).
    """
    var = VARIABLES[variable]
    best = None
    for h in (steps or var.steps):
        y = quantisation_model(p_true, twist, nu, variable, h, rounding)
        ok = reproduced(y, picture_y)
        if best is None or ok.sum() >= best[2].sum():
            best = (h, y, ok)
    h, y, ok = best
    return Hypothesis(f"{rounding}({variable}, {h:g})", variable, h, rounding, y, ok,
                      f"{var.description} rounded ({rounding}) to multiples of {h:g}")


# ------------------------------------------------------------------------------------------
# the authors' procedure: a sign-change scan of the boundary determinant
# ------------------------------------------------------------------------------------------

def _cs_typed(x: NDArray, real_wavenumbers: bool, zero: NDArray | float = 0.0
              ) -> tuple[NDArray, NDArray]:
    """C = cos(sqrt(X)/2), S = sin(sqrt(X)/2)/sqrt(X) in x's float type.

    real_wavenumbers: sqrt(X) taken in real arithmetic, NaN for X < -zero (as a program written
    in terms of real beta_k would compute it; ``zero`` is the rounding level of X, so an X that
    is zero in exact arithmetic is not counted); otherwise continued to cosh, sinh/kappa.
    """
    one = x.dtype.type(1)
    half = x.dtype.type(0.5)
    r = np.sqrt(np.abs(x))
    pos = x > 0
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        c = np.where(pos, np.cos(r * half), np.cosh(np.where(pos, 0, r) * half))
        s = np.where(pos, np.sin(r * half), np.sinh(np.where(pos, 0, r) * half)) / r
    s = np.where(r == 0, half * one, s)
    if real_wavenumbers:
        c, s = np.where(x < -zero, np.nan, c), np.where(x < -zero, np.nan, s)
    return c.astype(x.dtype), s.astype(x.dtype)


def determinant_product(p: NDArray[np.float64], twist: float, nu: float, *,
                        real_wavenumbers: bool = False, dtype: type = np.float64
                        ) -> NDArray:
    """D_sym D_anti at lambda = pi^2 p: the sign of the paper's 4x4 boundary determinant.

    The 4x4 determinant equals 16 Omega^2 D_sym D_anti
    (:func:`spectral_rod.characteristic.boundary_determinant_4x4`), so at fixed Omega != 0 it
    changes sign exactly where the product does. Same formulas as
    :func:`spectral_rod.characteristic.determinants`, evaluated in `dtype` (np.float64 or
    np.float32, to test single precision); real_wavenumbers: see :func:`_cs_typed`.
    Example: determinant_product([1.0, 1.1], 0.5, 1.5) changes sign (the root p* ~ 1.0084).
    """
    t = np.dtype(dtype).type
    lam = t(np.pi**2) * np.asarray(p, dtype=dtype)
    om2, nu_t = t(twist) ** 2, t(nu)
    mu = lam / nu_t
    xm, xp = characteristic_roots(lam, mu, t(twist))
    # rounding level of X: X_- = 0 exactly where the scan of lambda - nu Omega^2 starts
    zero = 64 * np.finfo(lam.dtype).eps * (lam + om2)
    cs = (_cs_typed(xm, real_wavenumbers, zero), _cs_typed(xp, real_wavenumbers, zero))
    return (combine_determinant("symmetric", lam, mu, om2, (xm, xp), cs)
            * combine_determinant("antisymmetric", lam, mu, om2, (xm, xp), cs))


@dataclass
class ScanResult:
    """Per point: the first bracket [lower, upper] (in the scan variable) where the determinant
    changes sign, and its values there; NaN where the scan finds no sign change. undefined: how
    many lattice points up to the bracket (or the whole scan) gave an undefined determinant
    (NaN: imaginary beta_1 with real wavenumbers)."""

    variable: str
    step: float
    lower: NDArray[np.float64]
    upper: NDArray[np.float64]
    d_lower: NDArray[np.float64]
    d_upper: NDArray[np.float64]
    undefined: NDArray[np.float64]

    def report(self, rule: str) -> NDArray[np.float64]:
        """The scan variable as reported: 'upper', 'lower', 'midpoint' or 'linear' (secant)."""
        if rule == "upper":
            return self.upper
        if rule == "lower":
            return self.lower
        if rule == "midpoint":
            return 0.5 * (self.lower + self.upper)
        if rule == "linear":
            with np.errstate(invalid="ignore", divide="ignore"):
                w = self.d_lower / (self.d_lower - self.d_upper)
            return self.lower + (self.upper - self.lower) * np.where(np.isfinite(w), w, 0.0)
        raise ValueError(f"rule must be 'upper', 'lower', 'midpoint' or 'linear', got {rule!r}")


def _scan_one(twist: float, nu: float, var: Variable, step: float, v_min: float,
              real_wavenumbers: bool, dtype: type) -> tuple[float, ...]:
    """First sign-change bracket of one point's scan and the count of undefined values
    before it (see :func:`scan_sign_change`)."""
    p_lo, p_top = 1.0 - 1e-9, 0.5 * (1.0 + nu) + 1e-6
    k0 = math.floor(float(var.forward(p_lo, twist, nu)) / step)
    if math.isfinite(v_min):
        k0 = max(k0, math.ceil(v_min / step))
    k1 = math.ceil(float(var.forward(p_top, twist, nu)) / step) + 1
    if k1 <= k0:
        return (math.nan,) * 4 + (0.0,)
    v = step * np.arange(k0, k1 + 1, dtype=float)
    d = determinant_product(var.inverse(v, twist, nu), twist, nu,
                            real_wavenumbers=real_wavenumbers, dtype=dtype).astype(float)
    hit = np.flatnonzero(np.isfinite(d[:-1]) & np.isfinite(d[1:]) & (d[:-1] * d[1:] <= 0))
    if not hit.size:
        return (math.nan,) * 4 + (float(np.isnan(d).sum()),)
    j = int(hit[0])
    return (float(v[j]), float(v[j + 1]), float(d[j]), float(d[j + 1]),
            float(np.isnan(d[:j + 2]).sum()))


def scan_sign_change(twist: NDArray[np.float64], nu: NDArray[np.float64], variable: str,
                     step: float, *, start_at_zero: bool = False, real_wavenumbers: bool = True,
                     dtype: type = np.float64) -> ScanResult:
    """Simulate the authors' scan at every point: v = k step upward, first sign change.

    The lattice runs from v(p = 1) (no root of either family lies below Euler's load, so an
    earlier start finds the same first bracket) -- or from v = 0 if `start_at_zero` and that is
    higher (a scan starting where the coefficient variable vanishes) -- up to the Rayleigh
    bound p = (1 + nu)/2. The sign is that of D_sym D_anti (:func:`determinant_product`).
    Example: ``scan_sign_change([0.5], [1.5], 'lambda', 0.002).report('upper')`` is the lattice
    point just above lambda* = pi^2 p*.
    """
    var = VARIABLES[variable]
    v_min = 0.0 if start_at_zero else -math.inf
    tw, nv = np.broadcast_arrays(np.asarray(twist, float), np.asarray(nu, float))
    res = np.array([_scan_one(float(t), float(n), var, step, v_min, real_wavenumbers, dtype)
                    for t, n in zip(tw.ravel(), nv.ravel(), strict=True)]).reshape(-1, 5)
    return ScanResult(variable, step, *(res[:, k].reshape(tw.shape) for k in range(5)))


def scan_model(scan: ScanResult, rule: str, twist: NDArray[np.float64], nu: NDArray[np.float64]
               ) -> NDArray[np.float64]:
    """Picture y (unprinted) the scan reports with `rule`; NaN where it found nothing."""
    var = VARIABLES[scan.variable]
    return _y_of_p(var.inverse(scan.report(rule), twist, nu))


# ------------------------------------------------------------------------------------------
# two runs, clusters
# ------------------------------------------------------------------------------------------

def fit_switch(twist: NDArray[np.float64], ok_low: NDArray[np.bool_], ok_high: NDArray[np.bool_]
               ) -> tuple[int, int, int]:
    """Best split of one curve's points (sorted by twist) between two models.

    Points [0, s) use the low model and [s, n) the high one; returns (s_first, s_last, count)
    with s_first..s_last the splits reaching the largest count of reproduced points. Example:
    ok_low = [1, 1, 0, 0], ok_high = [0, 0, 1, 1] -> (2, 2, 4).
    """
    if np.any(np.diff(twist) < 0):
        raise ValueError("twist must be sorted (one curve in source order)")
    low = np.concatenate([[0], np.cumsum(ok_low)])
    high = np.concatenate([np.cumsum(ok_high[::-1])[::-1], [0]])
    count = low + high
    best = np.flatnonzero(count == count.max())
    return int(best[0]), int(best[-1]), int(count.max())


def find_runs(bad: NDArray[np.bool_], merge_gap: int = MERGE_GAP) -> list[tuple[int, int]]:
    """Index ranges [first, last] of runs of True, merging runs separated by <= merge_gap False.

    Example: find_runs([0, 1, 1, 0, 1, 0, 0, 0, 1], 1) -> [(1, 4), (8, 8)].
    """
    idx = np.flatnonzero(np.asarray(bad, dtype=bool))
    if not idx.size:
        return []
    runs, first, last = [], int(idx[0]), int(idx[0])
    for i in idx[1:]:
        if i - last - 1 <= merge_gap:
            last = int(i)
        else:
            runs.append((first, last))
            first = last = int(i)
    runs.append((first, last))
    return runs


def chord_values(x: NDArray[np.float64], left: tuple[float, float], right: tuple[float, float]
                 ) -> NDArray[np.float64]:
    """y on the straight line through the flanking points `left` = (x0, y0), `right`."""
    (x0, y0), (x1, y1) = left, right
    return y0 + (y1 - y0) * (np.asarray(x, dtype=float) - x0) / (x1 - x0)


# ------------------------------------------------------------------------------------------
# the hypotheses, fitted
# ------------------------------------------------------------------------------------------

#: Scan variables: the load and the two coefficients of Eq. inst1, the coefficients scanned
#: from where they vanish (v >= 0).
SCAN_VARIABLES = (("lambda", False), ("lambda - nu Omega^2", True), ("lambda - Omega^2", True))
SCAN_RULES = ("upper", "lower", "midpoint", "linear")
#: Approximations of pi tried in the normalisation p* = lambda / pi^2.
PI_APPROXIMATIONS = (3.14, 3.1416, 3.14159)
#: Twist offsets (in picture x units) tried for "the x coordinate is not the twist computed".
X_SHIFTS = (-0.125, 0.125)


def quantisation_hypotheses(p_true: NDArray, twist: NDArray, nu: NDArray, picture_y: NDArray
                            ) -> list[Hypothesis]:
    """Every variable x rounding rule of :data:`VARIABLES`, the step fitted on its grid."""
    return [fit_quantisation(p_true, twist, nu, picture_y, v, r)
            for v in VARIABLES for r in ROUNDINGS]


def _scan_hypothesis(scan: ScanResult, rule: str, twist: NDArray, nu: NDArray,
                     picture_y: NDArray, label: str = "", note: str = "") -> Hypothesis:
    y = scan_model(scan, rule, twist, nu)
    return Hypothesis(f"scan{label} {rule}({scan.variable}, {scan.step:g})", scan.variable,
                      scan.step, f"bracket {rule}", y, reproduced(y, picture_y),
                      f"first sign change of D_sym D_anti on {scan.variable} = k {scan.step:g}"
                      f", reported at the bracket's {rule} value{note}")


def scan_hypotheses(twist: NDArray, nu: NDArray, picture_y: NDArray, steps: dict[str, float]
                    ) -> tuple[list[Hypothesis], dict[str, ScanResult]]:
    """Scan simulations (real wavenumbers) on each scan variable's fitted ceil lattice."""
    hyps, scans = [], {}
    for var, start in SCAN_VARIABLES:
        scans[var] = scan_sign_change(twist, nu, var, steps[var], start_at_zero=start)
        hyps += [_scan_hypothesis(scans[var], rule, twist, nu, picture_y) for rule in SCAN_RULES]
    return hyps, scans


def variant_hypotheses(scans: list[ScanResult], best_q: Hypothesis, p_true: NDArray,
                       twist: NDArray, nu: NDArray, picture_y: NDArray,
                       p_star_fn: Callable[[NDArray, NDArray], NDArray]) -> list[Hypothesis]:
    """Single precision, the continued (cosh/sinh) determinant, pi approximations, twist shifts.

    scans: the scans whose upper-end report is varied (single precision, continued
    determinant); best_q: the best quantisation hypothesis, varied in the normalisation (pi
    approximations in p* = lambda/pi^2) and in the twist (x shifted by X_SHIFTS).
    """
    starts = dict(SCAN_VARIABLES)
    out = []
    for base in scans:
        for label, kw, note in (
                (" single", {"dtype": np.float32}, " (single precision)"),
                (" continued", {"real_wavenumbers": False},
                 " (determinant continued to X_- < 0 by cosh/sinh: imaginary beta_1 handled)")):
            sc = scan_sign_change(twist, nu, base.variable, base.step,
                                  start_at_zero=starts[base.variable], **kw)
            out.append(_scan_hypothesis(sc, "upper", twist, nu, picture_y, label, note))
    var = VARIABLES[best_q.variable]
    lam = _PI2 * var.inverse(quantise(var.forward(p_true, twist, nu), best_q.step,
                                      best_q.rounding), twist, nu)
    for pa in PI_APPROXIMATIONS:
        y = Y_PER_P * (lam / pa**2 - 1.0)
        out.append(Hypothesis(f"{best_q.name} with pi = {pa}", best_q.variable, best_q.step,
                              best_q.rounding, y, reproduced(y, picture_y),
                              f"{best_q.description}, converted to p* with pi = {pa}"))
    for dx in X_SHIFTS:
        tw = twist + dx / X_PER_TWIST
        y = quantisation_model(p_star_fn(tw, nu), tw, nu, best_q.variable, best_q.step,
                               best_q.rounding)
        out.append(Hypothesis(f"{best_q.name} at Omega = (x {dx:+g})/10", best_q.variable,
                              best_q.step, best_q.rounding, y, reproduced(y, picture_y),
                              f"{best_q.description}, computed at twist (x {dx:+g})/10"))
    return out


def best_two_runs(hyps: list[Hypothesis], twist: NDArray, curve: NDArray, label: str = "",
                  edited: NDArray[np.bool_] | None = None
                  ) -> tuple[Hypothesis, Hypothesis, Hypothesis, dict[int, tuple[int, int]]]:
    """The pair (low, high) of hypotheses and per-curve switch accounting for the most points.

    Every ordered pair is tried with :func:`fit_switch` on each curve (the earliest optimal
    split is used); a point counts if reproduced or, with `edited` given, if the model
    yields no value where the line was inserted separately (:meth:`Hypothesis.credit`). Returns
    (composite, low, high, {curve: (s_first, s_last)}).
    """
    best = None
    credit = {id(h): h.credit(edited) for h in hyps}
    for lo in hyps:
        for hi in hyps:
            if lo is hi:
                continue
            cl, ch = credit[id(lo)], credit[id(hi)]
            fits = {c: fit_switch(twist[curve == c], cl[curve == c], ch[curve == c])
                    for c in np.unique(curve)}
            total = sum(f[2] for f in fits.values())
            if best is None or total > best[0]:
                best = (total, lo, hi, fits)
    _, lo, hi, fits = best
    y = np.empty_like(lo.y_model)
    for c, (s, _, _) in fits.items():
        idx = np.flatnonzero(curve == c)
        y[idx] = np.concatenate([lo.y_model[idx[:s]], hi.y_model[idx[s:]]])
    ok = np.empty_like(lo.ok)
    for c, (s, _, _) in fits.items():
        idx = np.flatnonzero(curve == c)
        ok[idx] = np.concatenate([lo.ok[idx[:s]], hi.ok[idx[s:]]])
    comp = Hypothesis(f"two runs{label}: {lo.name} below the switch, {hi.name} above",
                      f"{lo.variable} | {hi.variable}", [lo.step, hi.step],
                      f"{lo.rounding} | {hi.rounding}", y, ok,
                      f"low twist: {lo.description}; high twist: {hi.description}; switch "
                      f"fitted per curve")
    return comp, lo, hi, {c: (f[0], f[1]) for c, f in fits.items()}


# ------------------------------------------------------------------------------------------
# the analysis: per-site physics, clusters, missing points
# ------------------------------------------------------------------------------------------

def _default_p_star(twist: NDArray, nu: NDArray) -> NDArray:
    """The converged p* (collocation to 1e-12, the package's production route)."""
    return np.asarray(critical_load(twist, nu, tol=1e-12), dtype=float)


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
    if not (gap < 1e-9).all():  # two independent routes to p* must agree
        raise RuntimeError(f"family loads disagree with p_true at {(~(gap < 1e-9)).sum()} "
                           f"sites (max {np.nanmax(gap):.1e})")
    for r, h in runs.items():
        out[f"{r}_double_root"] = _same_step(out["p_sym"].to_numpy(), out["p_anti"].to_numpy(),
                                             t, nu, h.variable, h.step)
        out[f"{r}_root_below_start"] = VARIABLES[h.variable].forward(p, t, nu) < 0
    return out


def _flanks(curve_rows: pd.DataFrame, first: int, last: int, ok: NDArray[np.bool_]
            ) -> tuple[pd.Series | None, pd.Series | None]:
    """The nearest reproduced points before `first` and after `last` (positions in curve_rows)."""
    before = [i for i in range(first - 1, -1, -1) if ok[i]]
    after = [i for i in range(last + 1, len(curve_rows)) if ok[i]]
    return (curve_rows.iloc[before[0]] if before else None,
            curve_rows.iloc[after[0]] if after else None)


def _lower_end_rule(rows: pd.DataFrame, runs: dict[str, Hypothesis]) -> NDArray[np.bool_]:
    """Printed value = the lattice point just below the step holding both family roots."""
    t, nu, y = (rows[c].to_numpy() for c in ("twist_angle", "nu", "picture_y"))
    lo = np.fmin(rows["p_sym"].to_numpy(), rows["p_anti"].to_numpy())
    out = np.zeros(len(rows), dtype=bool)
    for r, h in runs.items():
        sel = (rows["run"] == r).to_numpy() & rows[f"{r}_double_root"].to_numpy()
        var = VARIABLES[h.variable]
        below = quantise(var.forward(lo, t, nu), h.step, "ceil") - h.step
        out |= sel & reproduced(_y_of_p(var.inverse(below, t, nu)), y)
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
                  tol: float = PRINT_QUANTUM / 2) -> LineFit:
    """Is the cluster a straight line between its flanks, up to rounding?

    The minimax line through the cluster points and the two flanks; while its residual exceeds
    ``tol`` (+1e-9) the cluster point farthest from the chord between the flanks (computed,
    trusted points) is set aside as a slip and the line refitted. Example: x = [1, 2,
    3], y = [1.0, 2.5, 3.0], flanks (0, 0), (4, 4) -> on_line = [True, False, True].
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
    """Computed reasons why the covering run's procedure fails at each row.

    'imaginary beta_1': X_- < 0 at p* *and* inside the closed-form window (both computations
    must agree); 'double root in one step': both family roots in one step of the run's lattice;
    'no sign change': the run's real-wavenumber scan finds none; 'edited line': the LaTeX line
    lacks the program's trailing blank (if the LaTeX lines were given).
    """
    causes = {"imaginary beta_1": (rows["imaginary_beta1"] & rows["in_window"]).to_numpy(),
              "double root in one step": rows["double_root"].to_numpy(dtype=bool),
              "no sign change": ~rows["scan_found"].to_numpy(dtype=bool)}
    if "edited" in rows:
        causes["edited line"] = rows["edited"].to_numpy(dtype=bool)
    return causes


def _twists(rows: pd.DataFrame, mask: NDArray[np.bool_]) -> list[float]:
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
    im = causes["imaginary beta_1"]
    if im.any():
        w = imaginary_beta1_window(nu)
        out.append(f"β₁ is imaginary (X₋ < 0 at p*) at {im.sum()} of {n}: the closed-form window "
                   f"for ν = {nu} is {w.omega_a:.4f} < Ω(L) < {w.omega_b:.4f} "
                   f"(asymptotics.imaginary_beta1_window)"
                   + (f"; outside it: Ω = {_twists(rows, ~im)}" if (~im).any() else ""))
        if "low" in runs and rows["low_root_below_start"].any():
            var = VARIABLES[runs["low"].variable]
            out.append(f"the low-twist run scans {var.name} ({var.description}) upward from 0,"
                       f" and the root lies below that start ({var.name} < 0 at p*) at "
                       f"{int(rows['low_root_below_start'].sum())} of {n}")
    dr = causes["double root in one step"]
    if dr.any():
        run = rows["run"].to_numpy()[dr][0]
        h = runs[run]
        c = _nearest_crossing(nu, t0, t1)
        where = "inside the cluster" if c["inside"] else f"{c['distance']:.3f} away"
        out.append(f"both families' lowest roots lie in one step of the {run}-twist lattice "
                   f"({h.variable} = k·{h.step:g}) at {dr.sum()} of {n} (Ω = "
                   f"{_twists(rows, dr)[0]:.3f}…{_twists(rows, dr)[-1]:.3f}), so D_sym·D_anti "
                   f"(the 4x4 determinant / 16Ω²) changes sign twice within one step; the family"
                   f" crossing Ω_{c['n']} = {c['twist']:.4f} (p* = {c['p_star']:.6f}, "
                   f"crossing_closed_form) is {where}")
    ns = causes["no sign change"]
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
        shape = ("a horizontal line" if abs(fit.b) < 1e-9 else
                 f"a straight line (slope {fit.b * X_PER_TWIST:.3f} per rad)")
        s = (f"{shape} through the flanking computed points (x, y) = "
             f"({left['picture_x']:.2f}, {left['picture_y']:.2f}) and "
             f"({right['picture_x']:.2f}, {right['picture_y']:.2f}) reproduces "
             f"{fit.on_line.sum()} of {n} to the print quantum (largest residual "
             f"{abs(fit.residual):.4f})")
        for i in np.flatnonzero(~fit.on_line):
            line_y = fit.a + fit.b * x[i]
            s += (f"; x = {x[i]:.2f} is printed {y[i]:.2f} where the line gives {line_y:.3f} "
                  f"({(y[i] - line_y) / PRINT_QUANTUM:+.1f} quanta: an isolated slip)")
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
            f"{Y_PER_P * (r['p_true'] - 1):.3f})" for _, r in rows[rest].iterrows()))
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
         f"that {with_blank} of the picture's lines end in (inserted separately from the "
         f"scan program's output)")
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
    none = ~(causes["imaginary beta_1"] | causes["double root in one step"]
             | causes["no sign change"])
    if not none.any():
        return None
    items = []
    for _, r in rows[none].iterrows():
        got = ", ".join(f"{k}-twist scan {r[f'{k}_scan_y']:.2f}" for k in runs
                        if np.isfinite(r[f"{k}_scan_y"]))
        items.append(f"Ω = {r['twist_angle']:.3f}: printed {r['picture_y']:.2f}, {got}")
    return ("The procedure does not fail at " + "; ".join(items)
            + " -- these values were replaced together with their neighbours.")


def _cluster_kind(causes: dict[str, NDArray[np.bool_]]) -> str:
    if causes["imaginary beta_1"].any():
        return "imaginary-beta1 window"
    if causes["double root in one step"].any():
        return "double root in one scan step"
    if causes["no sign change"].any():
        return "no sign change"
    return "edited lines" if causes.get("edited line", np.zeros(1, bool)).any() else "unexplained"


def explain_cluster(rows: pd.DataFrame, left: pd.Series | None, right: pd.Series | None,
                    runs: dict[str, Hypothesis], with_blank: int | None = None,
                    off_runs: list[dict] | None = None) -> dict:
    """The cluster record: where, how big, and why, from the rows' computed columns.

    rows: the cluster's data sites (columns of :func:`site_physics` and :func:`_run_scans`,
    plus run, double_root, scan_found, ok, p_digitised and the LaTeX columns if known);
    left/right: the flanking reproduced points; with_blank: lines of the picture in the
    program's format, off_runs: the curve's :func:`off_grid_runs` (both for the text).
    'explained' is True iff every point has a computed cause or is an edited line;
    'window_points' lists only points inside the window.
    """
    nu = float(rows["nu"].iloc[0])
    causes = point_causes(rows)
    rules, fit = value_rules(rows, left, right, runs)
    covered = np.logical_or.reduce(list(causes.values()))
    dev = np.abs(rows["p_digitised"] - rows["p_true"]).to_numpy()
    physics = [v for k, v in causes.items() if k != "edited line"]
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
            "window_points": _twists(rows, causes["imaginary beta_1"]),
            "double_root_points": _twists(rows, causes["double root in one step"]),
            "no_sign_change_points": _twists(rows, causes["no sign change"]),
            "edited_points": (_twists(rows, causes["edited line"])
                                  if "edited line" in causes else None),
            "crossing": (_nearest_crossing(nu, float(rows["twist_angle"].min()),
                                           float(rows["twist_angle"].max()))
                         if causes["double root in one step"].any() else None),
            "value_rules": {k: int(v.sum()) for k, v in rules.items()},
            "line": (None if fit is None else
                     {"a": fit.a, "b": fit.b, "residual": fit.residual,
                      "off_line": _twists(rows, ~fit.on_line)}),
            "twists": _twists(rows, np.ones(len(rows), dtype=bool))}


def explain_missing(row: pd.Series, sites: pd.DataFrame, runs: dict[str, Hypothesis]) -> dict:
    """Why a regular grid point is absent: its computed causes, and the same twist elsewhere.

    row: the missing site (columns of :func:`site_physics`); sites: all sites (for the other
    curves at the same twist and for off-grid points of the same curve nearby).
    """
    nu, t = float(row["nu"]), float(row["twist_angle"])
    one = row.to_frame().T.reset_index(drop=True)
    for c in ("imaginary_beta1", "in_window", "double_root", "scan_found"):
        one[c] = one[c].astype(bool)
    causes = point_causes(one.assign(edited=False))
    parts = _cause_sentences(one, causes, runs, nu)
    p_s, p_a = float(row["p_sym"]), float(row["p_anti"])
    text = (f"ν = {nu}, Ω(L) = {t:.3f} (x = {row['picture_x']:.2f}) is absent from the picture. "
            f"p* = {row['p_true']:.7f} (p_sym = {p_s:.7f}, p_anti = {p_a:.7f}). ")
    text += ("Cause: " + "; ".join(parts) + ". ") if parts else "No computed cause. "
    same = sites[(np.abs(sites["twist_angle"] - t) < 1e-9) & (sites["nu"] != nu)
                 & sites["in_data"]]
    for _, o in same.iterrows() if causes["double root in one step"].any() else ():
        text += (f"At ν = {o['nu']} the same twist is present and "
                 f"{'reproduced' if o['ok'] else 'not reproduced'} by the best model (its roots "
                 f"p_sym = {o['p_sym']:.7f}, p_anti = {o['p_anti']:.7f} lie "
                 f"{'in one step' if o['double_root'] else 'in different steps'}). ")
    off = sites[(sites["curve"] == row["curve"]) & sites["in_data"] & sites["off_grid"]
                & (np.abs(sites["twist_angle"] - t) < 0.25)]
    if len(off):
        text += (f"The picture has {len(off)} off-grid points of this curve within 0.25 rad "
                 f"(x = {off['picture_x'].min():.2f}…{off['picture_x'].max():.2f}) instead.")
    else:
        text += "No line was written for it (no inserted substitute)."
    return {"nu": nu, "twist_angle": t, "picture_x": float(row["picture_x"]),
            "explanation": text.strip(),
            "causes": [k for k, v in causes.items() if v.any() and k != "edited line"],
            "crossing": (_nearest_crossing(nu, t, t) if causes["double root in one step"].any()
                         else None),
            "explained": bool(any(v.any() for k, v in causes.items() if k != "edited line"))}


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
