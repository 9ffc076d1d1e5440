r"""Large twist Omega(L) >> 1: the characteristic equation in double precision, and asymptotics.

Collocation needs a degree n growing like Omega(L) (n ~ 700 at Omega(L) = 1000, beyond the cap
n = 512) and its round-off grows with n; the paper's characteristic equation has a cost that
does not depend on the twist. This module solves the same determinants as
:mod:`spectral_rod.characteristic` (paper, section "Stability of a rectilinear rod", Eq.
``inst1``; derivation there) but in numpy double precision, vectorised over a scan grid, with a
bracketing root finder -- fast enough to be the production route for large twist. Its accuracy
comes from the slow phase sqrt(X_+) - sqrt(X_-) ~ 2 kappa being a difference of two phases of
size ~Omega: the relative error of p* is ~ eps Omega (measured: <= 1e-13 at Omega(L) = 1000,
see tests/test_extremes.py), whatever n collocation would need.

Normalisation: p* = P_cr / (pi^2 A1 / L^2), Omega(L) = omega30 L, nu = I2/I1 >= 1.

Asymptotics (Omega(L) -> infinity)
----------------------------------
In the lab frame the rod's bending axes rotate fast; averaging the lab-frame equation
z'' + a z + b exp(2 i Omega s) conj(z) = 0 (a, b = (lambda +- lambda/nu)/2) over the fast scale
gives a slow mode sin(pi s) with a + b^2/(4 Omega^2) = pi^2 (the characteristic equation with
X = (Omega - kappa)^2 gives the same to this order), i.e.

    p*  = p_inf [1 - pi^2 (nu - 1)^2 / (4 (nu + 1)^2 Omega^2)] + O(Omega^-3),
    p_inf = 2 nu / (1 + nu)   (harmonic mean of the two bending stiffnesses).

The O(Omega^-3) remainder is oscillatory (boundary layers at the hinges); to first order in
nu - 1 it is -(nu - 1) pi^2 |sin Omega| / (2 Omega^3) (from p* - 1 = (nu - 1)(1/2 - |J|),
J = pi^2 sin Omega / (2 Omega (pi^2 - Omega^2))). Measured against the mpmath reference the
relative error of the two-term formula is pi^2 (nu-1)/(nu+1) |sin Omega| / Omega^3 (+O(Omega^-4))
(nu up to 1e4; tests/test_extremes.py): up to 4e-7 at Omega(L) = 300, 1e-8 at 1000, 1e-11 at
1e4 -- never better than the 1e-10 target within |Omega(L)| <= 1000, so it is not used for
values (critical_load uses the characteristic equation there).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from spectral_rod._validation import check_nu, check_twist

__all__ = ["characteristic_double", "determinants", "large_twist_critical_load"]

FAMILIES = ("symmetric", "antisymmetric")
#: Scan step in p for sign changes (the reference uses 1/128; roots of one family are >= O(1)
#: apart for large twist, the two families' lowest roots are bracketed separately).
SCAN_STEP = 1.0 / 256


def _cs(x: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """C = cos(sqrt(X)/2), S = sin(sqrt(X)/2)/sqrt(X), continued to X <= 0 (cosh, sinh)."""
    r = np.sqrt(np.abs(x))
    pos = x > 0
    rp, rn = np.where(pos, r, 0.0), np.where(pos, 0.0, r)  # hyperbolic part only where X <= 0
    c = np.where(pos, np.cos(rp / 2), np.cosh(rn / 2))
    with np.errstate(invalid="ignore", divide="ignore"):
        s = np.where(pos, np.sin(rp / 2), np.sinh(rn / 2)) / r
    return c, np.where(r == 0, 0.5, s)


def determinants(p: ArrayLike, twist_angle: float, nu: float
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(D_sym, D_anti) of :mod:`spectral_rod.characteristic` at lambda = pi^2 p, in double.

    Same formulas (entire in lambda, divided by 2 Omega); p may be an array.
    """
    lam = np.pi**2 * np.asarray(p, dtype=float)
    om2 = float(twist_angle) ** 2
    mu = lam / float(nu)
    ssum = lam + mu + 2 * om2
    xp = 0.5 * (ssum + np.sqrt((lam - mu) ** 2 + 8 * om2 * (lam + mu)))
    xm = (lam - om2) * (mu - om2) / xp
    cp, sp = _cs(xp)
    cm, sm = _cs(xm)
    d_sym = cp * sm * (lam - om2 - xm) - cm * sp * (lam - om2 - xp)
    d_anti = (mu - om2 - xp) * sp * cm - (mu - om2 - xm) * sm * cp
    return d_sym, d_anti


def _first_root(f, grid: NDArray[np.float64], values: NDArray[np.float64]) -> float | None:
    """Lowest root of f bracketed by a sign change of `values` on `grid`, refined by brentq."""
    sign = np.sign(values)
    idx = np.flatnonzero(sign[:-1] * sign[1:] <= 0)
    if not idx.size:
        return None
    i = int(idx[0])
    if values[i] == 0:
        return float(grid[i])
    return float(brentq(f, grid[i], grid[i + 1], xtol=1e-16, rtol=4 * np.finfo(float).eps,
                        maxiter=200))


def characteristic_double(twist_angle: float, nu: float) -> tuple[float, str]:
    """Lowest root p* of the two determinants (double precision) and its family.

    Scans p from 1 - 1e-9 upward in steps of :data:`SCAN_STEP` (chunks of width 1, up to the
    Rayleigh bound (1 + nu)/2) and refines the first sign change of each family with Brent's
    method. Raises RuntimeError if no root is found. Intended for |Omega(L)| >= ~30.
    """
    om, nu = abs(float(twist_angle)), float(nu)
    top = (1.0 + nu) / 2.0 + 1e-6
    lo = 1.0 - 1e-9
    while lo < top:
        hi = min(lo + 1.0, top)
        grid = np.linspace(lo, hi, max(2, math.ceil((hi - lo) / SCAN_STEP) + 1))
        vals = determinants(grid, om, nu)
        roots = []
        for k, fam in enumerate(FAMILIES):
            r = _first_root(lambda p, k=k: float(determinants(p, om, nu)[k]), grid, vals[k])
            if r is not None:
                roots.append((r, fam))
        if roots:
            return min(roots)
        lo = hi
    raise RuntimeError(f"no root of the characteristic equation for p* in [1, {top}] "
                       f"(twist_angle={om}, nu={nu})")


def large_twist_critical_load(twist_angle: ArrayLike, nu: ArrayLike
                              ) -> tuple[NDArray[np.float64], NDArray[np.str_]]:
    """p* and mode family by :func:`characteristic_double` for broadcast arrays (any twist sign)."""
    twist = check_twist(twist_angle)
    nu_arr = check_nu(nu)
    shape = np.broadcast_shapes(twist.shape, nu_arr.shape)
    tw = np.broadcast_to(twist, shape).ravel()
    nv = np.broadcast_to(nu_arr, shape).ravel()
    p = np.empty(tw.size)
    fam = np.empty(tw.size, dtype=object)
    for i, (om, n) in enumerate(zip(tw, nv, strict=True)):
        p[i], fam[i] = characteristic_double(om, n)
    return p.reshape(shape), fam.astype(str).reshape(shape)
