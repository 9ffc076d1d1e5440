"""The authors' presumed procedure: a sign-change scan of the boundary determinant of Eq.
``inst1`` (D_sym D_anti, :mod:`spectral_rod.rod.characteristic`) on a lattice of one variable,
with its variants (real wavenumbers, single precision, start at zero).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from spectral_rod.figure1.data import picture_y_from_p_star
from spectral_rod.figure1.forensics.quantisation import VARIABLES, Variable
from spectral_rod.rod.characteristic import SCAN_MARGIN, SCAN_START, determinants
from spectral_rod.rod.families import p_star_bounds


class ReportRule(NamedTuple):
    """A rule by which a scan reports its first sign-change bracket (:meth:`ScanResult.report`).

    name: the rule's key (:attr:`Hypothesis.scan_rule`); words: how it reads in the report;
    band: where the reported value v lies relative to the root v*, in scan steps, when the first
    bracket holds the root: [v* + band[0] step, v* + band[1] step]; value: the reported v of
    each point of a scan.
    """

    name: str
    words: str
    band: tuple[float, float]
    value: Callable[[ScanResult], NDArray[np.float64]]


def _secant(scan: ScanResult) -> NDArray[np.float64]:
    """The root of the line through the bracket's two determinant values (the lower end where
    they give no finite one)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        w = scan.d_lower / (scan.d_lower - scan.d_upper)
    return scan.lower + (scan.upper - scan.lower) * np.where(np.isfinite(w), w, 0.0)


#: The report rules, in the order their hypotheses are fitted (one declaration per rule).
REPORT_RULES = (
    ReportRule("upper", "the bracket's upper end", (0.0, 1.0), lambda scan: scan.upper),
    ReportRule("lower", "the bracket's lower end", (-1.0, 0.0), lambda scan: scan.lower),
    ReportRule("midpoint", "the bracket's midpoint", (-0.5, 0.5),
               lambda scan: 0.5 * (scan.lower + scan.upper)),
    ReportRule("linear", "the secant (linear interpolation) in the bracket", (-1.0, 1.0),
               _secant),
)
#: :data:`REPORT_RULES` by name.
RULES_BY_NAME = {r.name: r for r in REPORT_RULES}


def determinant_product(p: NDArray[np.float64], twist: float, nu: float, *,
                        real_wavenumbers: bool = False, dtype: type = np.float64
                        ) -> NDArray[np.floating]:
    """D_sym D_anti at lambda = pi^2 p: the sign of the paper's 4x4 boundary determinant.

    The 4x4 determinant equals 16 Omega^2 D_sym D_anti
    (:func:`spectral_rod.rod.characteristic_mode.boundary_determinant_4x4`), so at fixed Omega != 0
    it
    changes sign exactly where the product does. The factors are
    :func:`spectral_rod.rod.characteristic.determinants` with its `real_wavenumbers` and `dtype`
    (np.float64 or np.float32, to test single precision). The sign changes across the root
    p* = 1.0024446 at Omega = 0.5, nu = 1.5:

    >>> np.sign(determinant_product(np.array([1.002, 1.003]), 0.5, 1.5)).tolist()
    [-1.0, 1.0]
    """
    # defensive: cosh overflows in single precision only for
    # -X_- > ~3e4, far outside the scans' range, and an infinite value closes no bracket
    with np.errstate(over="ignore"):
        d_sym, d_anti = determinants(p, twist, nu, dtype=dtype,
                                     real_wavenumbers=real_wavenumbers)
    return d_sym * d_anti


@dataclass
class ScanResult:
    """Per point: the first bracket [lower, upper] (in the scan variable) where the determinant
    changes sign, and its values there; NaN where the scan finds no sign change. undefined: how
    many lattice points up to the bracket (or the whole scan) gave an undefined determinant
    (NaN: imaginary beta_1 with real wavenumbers). The remaining fields are the scan's settings
    (:func:`scan_sign_change`)."""

    variable: str
    step: float
    lower: NDArray[np.float64]
    upper: NDArray[np.float64]
    d_lower: NDArray[np.float64]
    d_upper: NDArray[np.float64]
    undefined: NDArray[np.float64]
    start_at_zero: bool = False
    real_wavenumbers: bool = True
    dtype: type = np.float64

    def report(self, rule: str) -> NDArray[np.float64]:
        """The scan variable as reported by `rule`, a name of :data:`REPORT_RULES`: 'upper',
        'lower', 'midpoint' or 'linear' (secant)."""
        if rule not in RULES_BY_NAME:
            names = [repr(r) for r in RULES_BY_NAME]
            raise ValueError(f"rule must be {', '.join(names[:-1])} or {names[-1]}, got {rule!r}")
        return RULES_BY_NAME[rule].value(self)

    def settings(self, **changes: object) -> dict:
        """The keyword arguments of :func:`scan_sign_change` that repeat this scan (`changes`
        applied)."""
        return {"start_at_zero": self.start_at_zero, "real_wavenumbers": self.real_wavenumbers,
                "dtype": self.dtype, **changes}

    def extended(self, twist: NDArray[np.float64], nu: NDArray[np.float64]) -> ScanResult:
        """This scan's points followed by the same scan at the points (twist, nu)."""
        more = scan_sign_change(twist, nu, self.variable, self.step, **self.settings())
        lower, upper, d_lower, d_upper, undefined = (
            np.concatenate([getattr(self, f), getattr(more, f)]) for f in
            ("lower", "upper", "d_lower", "d_upper", "undefined"))
        return ScanResult(self.variable, self.step, lower, upper, d_lower, d_upper, undefined,
                          **self.settings())


def _scan_one(twist: float, nu: float, p_top: float, var: Variable, step: float, v_min: float,
              real_wavenumbers: bool, dtype: type) -> tuple[float, ...]:
    """First sign-change bracket of one point's scan (p from SCAN_START to p_top) and the count
    of undefined values before it (see :func:`scan_sign_change`)."""
    p_lo = SCAN_START
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

    The lattice runs from v(p) at p = :data:`~spectral_rod.rod.characteristic.SCAN_START` (just
    below Euler's load p = 1: no root of either family lies lower, so an earlier start finds the
    same first bracket) -- or from v = 0 if `start_at_zero` and that is higher (a scan starting
    where the coefficient variable vanishes) -- up to the Rayleigh bound p = (1 + nu)/2
    (:func:`spectral_rod.rod.families.p_star_bounds`, plus
    :data:`~spectral_rod.rod.characteristic.SCAN_MARGIN`). The sign is that of D_sym D_anti
    (:func:`determinant_product`). The reported upper end is the lattice point just above
    lambda* = pi^2 p* (p* = 1.0024446 at Omega = 0.5, nu = 1.5):

    >>> sc = scan_sign_change([0.5], [1.5], "lambda", 0.002)
    >>> round(float(sc.lower[0]), 3), round(float(sc.upper[0]), 3), round(np.pi**2 * 1.0024446, 4)
    (9.892, 9.894, 9.8937)
    """
    var = VARIABLES[variable]
    v_min = 0.0 if start_at_zero else -math.inf
    tw, nv = np.broadcast_arrays(np.asarray(twist, float), np.asarray(nu, float))
    top = {n: p_star_bounds(n)[1] + SCAN_MARGIN for n in np.unique(nv).tolist()}
    res = np.array([_scan_one(t, n, top[n], var, step, v_min, real_wavenumbers, dtype)
                    for t, n in zip(tw.ravel().tolist(), nv.ravel().tolist(), strict=True)]
                   ).reshape(-1, 5)
    lower, upper, d_lower, d_upper, undefined = (res[:, k].reshape(tw.shape) for k in range(5))
    return ScanResult(variable, step, lower, upper, d_lower, d_upper, undefined,
                      start_at_zero=start_at_zero, real_wavenumbers=real_wavenumbers,
                      dtype=dtype)


def scan_model(scan: ScanResult, rule: str, twist: NDArray[np.float64], nu: NDArray[np.float64]
               ) -> NDArray[np.float64]:
    """Picture y (unprinted) the scan reports with `rule`; NaN where it found nothing."""
    var = VARIABLES[scan.variable]
    return picture_y_from_p_star(var.inverse(scan.report(rule), twist, nu))


def report_band(variable: str, step: float, rule: str, p: NDArray[np.float64],
                twist: NDArray[np.float64], nu: NDArray[np.float64]
                ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(low, high): where a scan of `variable` in steps `step`, reported by `rule`, puts p
    relative to the root p (the rule's :attr:`ReportRule.band`, mapped to p): one scan step.

    >>> lo, hi = report_band("lambda", 0.002, "upper", np.array([1.0]), 0.5, 1.5)
    >>> float(lo[0]), round(float(hi[0]) * np.pi**2, 12)
    (0.0, 0.002)
    """
    var, (a, b) = VARIABLES[variable], RULES_BY_NAME[rule].band
    v = var.forward(np.asarray(p, dtype=float), twist, nu)
    return (var.inverse(v + a * step, twist, nu) - p, var.inverse(v + b * step, twist, nu) - p)
