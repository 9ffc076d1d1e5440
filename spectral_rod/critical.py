"""The public entry point for the straight rod's critical load: which method serves which regime.

Today every point goes to the Chebyshev collocation solver
(:func:`spectral_rod.straight_rod.collocation_critical_load`); regimes where collocation is not
the accurate or economical method (very large twist, increments p* - 1 near the degenerate
limits) are routed here to the method that is.
"""

from __future__ import annotations

from numpy.typing import ArrayLike

from spectral_rod.straight_rod import collocation_critical_load


def critical_load(twist_angle: ArrayLike, nu: ArrayLike, *, n: int | None = None,
                  tol: float = 1e-12, full_output: bool = False):
    """Critical load p* = P_cr / (pi^2 A1 / L^2) of the hinged, spontaneously twisted rod.

    Eq. ``inst1`` with hinged ends; twist_angle = Omega(L) = omega30 L in radians (p* is even
    in it), nu = I2/I1 >= 1. See :func:`spectral_rod.straight_rod.collocation_critical_load`
    for ``n``, ``tol`` (relative) and ``full_output`` (a :class:`CriticalLoad` with the degree
    used, the error estimate, the mode family and a converged flag). Scalars give a float,
    arrays broadcast and give an ndarray.
    """
    return collocation_critical_load(twist_angle, nu, n=n, tol=tol, full_output=full_output)
