"""The physics at each Figure 1 point: the wavenumbers squared X_+- of Eq. ``inst1``'s
characteristic equation, both families' lowest loads, and the imaginary-beta_1 window.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from spectral_rod.asymptotics import imaginary_beta1_window
from spectral_rod.characteristic import determinants
from spectral_rod.sign_scan import lowest_root
from spectral_rod.wavenumbers import characteristic_roots


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


