"""The obvious implementation of p*(Omega, nu) for Eq. ``inst1`` -- the speed baseline.

What an engineer writes first from Trefethen's *Spectral Methods in MATLAB*: the differentiation
matrix of ``cheb.m`` at degree n = 24, the dense 2-field operator of Eq. ``inst1`` in
(omega1, omega2) built per point (omega = 0 at both ends by deleting the boundary rows and
columns), ``numpy.linalg.eigvals`` on it, and the lowest positive real eigenvalue
lambda = pi^2 p* taken. No parity split, no reuse between points, no resolution control.

It is the yardstick of the benchmarks and of the ``convergence`` scene, not a method we
recommend; it lives in the library so that both (and users) can run it from an installed
package.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from spectral_rod._validation import (
    broadcast_points,
    check_int,
    check_nu,
    check_twist,
    scalar_nu,
    scalar_twist,
)


def cheb(n: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Trefethen's cheb.m: Chebyshev points x_j = cos(j pi / n) and the differentiation matrix."""
    x = np.cos(np.pi * np.arange(n + 1) / n)
    c = np.hstack([2.0, np.ones(n - 1), 2.0]) * (-1.0) ** np.arange(n + 1)
    dx = x[:, None] - x[None, :]
    d = np.outer(c, 1.0 / c) / (dx + np.eye(n + 1))
    return d - np.diag(d.sum(axis=1)), x


def baseline_critical_load(twist_angle: float, nu: float, n: int = 24) -> float:
    """p* at one point: dense operator of Eq. ``inst1`` on s in [0, 1] and ``eigvals``
    (n in [4, 256]; no resolution control: that is the point of a baseline).

    Returns
    -------
    float
        p* = P_cr/(pi^2 A1/L^2) from the dense operator at degree `n` (unchecked resolution).

    Examples
    --------
    >>> round(baseline_critical_load(0.0, 1.5), 10)   # untwisted: the Euler load
    1.0
    >>> import spectral_rod as sr   # against the resolution-controlled solver
    >>> abs(baseline_critical_load(5.0, 1.5) / sr.critical_load(5.0, 1.5) - 1) < 1e-10
    True
    """
    twist_angle, nu = scalar_twist(twist_angle), scalar_nu(nu)
    d, _ = cheb(check_int(n, "n", 4, 256))
    d1 = 2.0 * d  # d/ds with s = (x + 1) / 2
    d2 = (d1 @ d1)[1:-1, 1:-1]
    d1 = d1[1:-1, 1:-1]
    eye = np.eye(n - 1)
    om = twist_angle
    op = np.block([[-d2 + om**2 * eye, 2.0 * nu * om * d1],
                   [-2.0 * om * d1, nu * (-d2 + om**2 * eye)]])
    lam = np.linalg.eigvals(op)
    ok = (np.abs(lam.imag) <= 1e-8 * np.abs(lam)) & (lam.real > 0)
    return float(lam.real[ok].min() / np.pi**2)


def baseline_sweep(twist: NDArray[np.float64], nu: NDArray[np.float64]) -> NDArray[np.float64]:
    """The baseline at every point (broadcast arrays), one after the other.

    Returns
    -------
    ndarray of float
        p* at every point, of the broadcast shape of `twist` and `nu`.

    Examples
    --------
    >>> import numpy as np
    >>> baseline_sweep(np.array([0.0, 0.0]), np.array([1.5, 4.0])).round(10).tolist()
    [1.0, 1.0]
    """
    tw, nv = check_twist(twist, "twist"), check_nu(nu)
    shape = broadcast_points(twist=tw, nu=nv)
    return np.array([baseline_critical_load(float(t), float(v)) for t, v in
                     zip(np.broadcast_to(tw, shape).ravel(), np.broadcast_to(nv, shape).ravel(),
                         strict=True)]).reshape(shape)
