"""Quantisation hypotheses: a variable v(p*) rounded onto a lattice k h, then printed with two
decimals; the step h is fitted per variable and rounding rule.

The candidate steps m 10^e (m in :data:`MANTISSAS`) are an empirical choice: the usual
"round" steps a 1970s program would use.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from spectral_rod.figure1.data import (
    FIGURE1_NU,
    FIGURE1_Y_PER_P,
    p_star_from_picture,
    picture_y_from_p_star,
)
from spectral_rod.figure1.forensics.physics import RANGES

if TYPE_CHECKING:
    from spectral_rod.figure1.forensics.scan import ScanResult

ROUNDINGS = ("nearest", "floor", "ceil", "truncate")
MANTISSAS = (1.0, 2.0, 2.5, 4.0, 5.0)
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
    Variable("lambda", "the load lambda = pi^2 p* = P L^2/A1", lambda p, t, n: _PI2 * p,
             lambda v, t, n: v / _PI2, _steps(-5, -2)),
    Variable("y", f"the picture coordinate y = {FIGURE1_Y_PER_P:g} (p* - 1)",
             lambda p, t, n: picture_y_from_p_star(p), lambda v, t, n: p_star_from_picture(v),
             _steps(-3, -1)),
    Variable("lambda - nu Omega^2", "the coefficient (P - A2 omega30^2) L^2/A1 of Eq. inst1",
             lambda p, t, n: _PI2 * p - n * t**2, lambda v, t, n: (v + n * t**2) / _PI2,
             _steps(-5, -2)),
    Variable("lambda - Omega^2", "the coefficient (P - A1 omega30^2) L^2/A1 of Eq. inst1",
             lambda p, t, n: _PI2 * p - t**2, lambda v, t, n: (v + t**2) / _PI2,
             _steps(-5, -2)),
)}


def quantise(v: NDArray[np.float64], step: float, rounding: str) -> NDArray[np.float64]:
    """v moved onto the lattice k * step by `rounding` (nearest: half up; truncate: toward 0).

    >>> [round(float(quantise([0.0031], 0.002, r)[0]), 6) for r in ROUNDINGS]
    [0.004, 0.002, 0.004, 0.002]
    """
    u = np.asarray(v, dtype=float) / step
    rules: dict[str, Callable[[NDArray[np.float64]], NDArray[np.float64]]] = {
        "nearest": lambda a: np.floor(a + 0.5), "floor": np.floor, "ceil": np.ceil,
        "truncate": np.trunc}
    if rounding not in rules:
        raise ValueError(f"rounding must be one of {ROUNDINGS}, got {rounding!r}")
    return rules[rounding](u) * step


def printed(y: NDArray[np.float64]) -> NDArray[np.float64]:
    """y as the picture prints it, in hundredths: rounded half away from 0 *in decimal*.

    An assumption about the authors' printing (an F-format edit of the value): a y whose decimal
    value is a tie at the third decimal rounds away from 0, so the 1e-9 added before flooring
    lifts the doubles stored just below such a tie (18.975 is 18.97499999...). Rounding the
    binary double exactly would round those down; tests/test_figure1_forensics.py checks that
    the best model reproduces the same points under both conventions. NaN stays NaN (no value).

    >>> printed([18.975, 0.004, -0.005, np.nan]).tolist()
    [1898.0, 0.0, -1.0, nan]
    """
    y = np.asarray(y, dtype=float)
    return np.sign(y) * np.floor(np.abs(y) * 100.0 + 0.5 + 1e-9)


def reproduced(y_model: NDArray[np.float64], picture_y: NDArray[np.float64]) -> NDArray[np.bool_]:
    """True where the model's printed y equals the picture's (False where the model has none).

    >>> reproduced(np.array([8.7249, 8.726, np.nan]), np.array([8.72, 8.72, 8.72])).tolist()
    [True, False, False]
    """
    return printed(y_model) == printed(picture_y)


@dataclass
class Hypothesis:
    """A model of the published values, its prediction and which points it reproduces.

    scan, scan_rule: for a sign-change scan (a procedure), the simulated scan at the points and
    the rule by which its bracket is reported (:meth:`ScanResult.report`); None otherwise.
    """

    name: str
    variable: str
    step: float | list[float] | None
    rounding: str
    y_model: NDArray[np.float64]
    ok: NDArray[np.bool_]
    description: str = ""
    scan: ScanResult | None = None
    scan_rule: str | None = None

    @property
    def is_procedure(self) -> bool:
        """A procedure (a scan) says where it yields no value; a quantisation never fails."""
        return self.scan is not None

    def credit(self, edited: NDArray[np.bool_] | None) -> NDArray[np.bool_]:
        """Points the hypothesis accounts for: reproduced, or no value predicted where the
        LaTeX line was inserted separately (the procedure's failure seen in the source)."""
        if edited is None:
            return self.ok
        return self.ok | (np.isnan(self.y_model) & edited)

    def summary(self, nu: NDArray[np.float64], ranges: NDArray[np.str_],
                edited: NDArray[np.bool_] | None = None) -> dict:
        """JSON row: name, variable, step, rounding, reproduced_exactly, points, by_curve,
        by_range (per curve: {range: [reproduced, points]}), by_range_total (all curves:
        {range: reproduced}, ranges in twist order), no_value (points where the procedure
        yields nothing), no_value_edited (of those, lines inserted separately)."""
        by_curve = {str(n): int(self.ok[nu == n].sum()) for n in FIGURE1_NU}
        by_range = {str(n): {r: [int(self.ok[(nu == n) & (ranges == r)].sum()),
                                 int(((nu == n) & (ranges == r)).sum())] for r in RANGES}
                    for n in FIGURE1_NU}
        total = {r: int(self.ok[ranges == r].sum()) for r in RANGES}
        return {"name": self.name, "variable": self.variable, "step": self.step,
                "rounding": self.rounding, "reproduced_exactly": int(self.ok.sum()),
                "points": int(self.ok.size), "by_curve": by_curve, "by_range": by_range,
                "by_range_total": total,
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
    return picture_y_from_p_star(var.inverse(v, twist, nu))


def fit_quantisation(p_true: NDArray[np.float64], twist: NDArray[np.float64],
                     nu: NDArray[np.float64], picture_y: NDArray[np.float64], variable: str,
                     rounding: str, steps: tuple[float, ...] | None = None) -> Hypothesis:
    """The step (from the variable's fixed grid) that reproduces the most points exactly.

    Ties go to the coarser step (fewer distinct values: the stronger statement).
    """
    var = VARIABLES[variable]
    best: tuple[float, NDArray[np.float64], NDArray[np.bool_]] | None = None
    for h in (steps or var.steps):
        y = quantisation_model(p_true, twist, nu, variable, h, rounding)
        ok = reproduced(y, picture_y)
        if best is None or ok.sum() >= best[2].sum():
            best = (h, y, ok)
    assert best is not None  # the grid of steps is never empty
    h, y, ok = best
    return Hypothesis(f"{rounding}({variable}, {h:g})", variable, h, rounding, y, ok,
                      f"{var.description} rounded ({rounding}) to multiples of {h:g}")


