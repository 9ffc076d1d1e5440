"""The authors' presumed procedure: a sign-change scan of the boundary determinant of Eq.
``inst1`` (D_sym D_anti, :mod:`spectral_rod.characteristic`) on a lattice of one variable,
with its variants (real wavenumbers, single precision, start at zero).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from spectral_rod.characteristic import combine_determinant
from spectral_rod.figure1_forensics.quantisation import VARIABLES, Variable, _y_of_p
from spectral_rod.wavenumbers import characteristic_roots


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


