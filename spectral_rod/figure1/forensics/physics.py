"""The physics at each Figure 1 point: the wavenumbers squared X_+- of Eq. ``inst1``'s
characteristic equation, both families' lowest loads, and the imaginary-beta_1 window.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from spectral_rod.rod.characteristic import family_double_batch
from spectral_rod.rod.closed_form import imaginary_beta1_window
from spectral_rod.rod.wavenumbers import characteristic_roots

#: The labels of :func:`twist_ranges`, in twist order.
RANGES = ("below window", "window", "above window")


def wavenumbers_squared(p: NDArray[np.float64], twist: NDArray[np.float64], nu: NDArray[np.float64]
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(X_-, X_+) = (beta_1^2 L^2, beta_2^2 L^2) at load p* = p (vectorised).

    Roots of (lambda - Omega^2 - X)(lambda/nu - Omega^2 - X) = 4 Omega^2 X, lambda = pi^2 p;
    X_- < 0 (beta_1 imaginary) iff lambda/nu < Omega^2 < lambda. At Omega = 0,
    (X_-, X_+) = (lambda/nu, lambda):

    >>> x_minus, x_plus = wavenumbers_squared(np.array([1.0]), np.array([0.0]), np.array([1.5]))
    >>> bool(np.isclose(x_minus[0], np.pi**2 / 1.5)), bool(np.isclose(x_plus[0], np.pi**2))
    (True, True)
    """
    lam = np.pi**2 * np.asarray(p, dtype=float)
    return characteristic_roots(lam, lam / np.asarray(nu, dtype=float),
                                np.asarray(twist, dtype=float))


def family_loads(twist: NDArray[np.float64], nu: NDArray[np.float64]
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Lowest root p of each family, (p_sym, p_anti), at every (twist, nu) (double precision,
    broadcast): :func:`spectral_rod.rod.characteristic.family_double_batch`, all points at once.
    NaN where a family has no root below nu.

    >>> p_sym, p_anti = family_loads([0.5], [1.5])  # the symmetric mode is the critical one
    >>> round(float(p_sym[0]), 7), round(float(p_anti[0]), 4)
    (1.0024446, 1.4928)
    """
    tw, nv = np.broadcast_arrays(np.asarray(twist, float), np.asarray(nu, float))
    p_sym, p_anti = family_double_batch(tw.ravel(), nv.ravel())
    return p_sym.reshape(tw.shape), p_anti.reshape(tw.shape)


def twist_ranges(twist: NDArray[np.float64], nu: NDArray[np.float64]) -> NDArray[np.str_]:
    """Label of each point relative to the imaginary-beta_1 window (Omega_a, Omega_b) of its nu.

    'below window' (Omega <= Omega_a), 'window', 'above window' (Omega >= Omega_b); the window
    from :func:`spectral_rod.imaginary_beta1_window`.

    >>> twist_ranges(np.array([1.0, 3.0, 4.0]), np.full(3, 1.5)).tolist()
    ['below window', 'window', 'above window']
    """
    out = np.empty(np.shape(twist), dtype=object)
    for n in np.unique(nu):
        w = imaginary_beta1_window(float(n))
        sel = np.asarray(nu) == n
        t = np.asarray(twist)[sel]
        out[sel] = np.where(t <= w.omega_a, RANGES[0],
                            np.where(t >= w.omega_b, RANGES[2], RANGES[1]))
    return out.astype(str)
