"""The public entry point for the straight rod's critical load: which method serves which regime.

Routing (issue 6, measured against the mpmath characteristic equation; tests/test_extremes.py
and the ``extremes`` scene):

* nu - 1 <= :data:`NEAR_DEGENERATE` = 1e-3 and |Omega(L)| < 50 (no explicit ``n``): the
  lowest eigenvalue is nearly double and collocation's non-normal matrices make it
  ill-conditioned; p* = 1 + (p* - 1) with the increment from the lab-frame Schur-complement
  formulation (:func:`spectral_rod.increment.galerkin_increment_family`, relative accuracy
  ~1e-14 of the *increment*, so p* is good to ~1e-16). Reported with ``n = 0`` and
  ``error_estimate = max(eps, 1e-12 (p* - 1))`` (a bound on the increment's measured error).
* other |Omega(L)| < :data:`TWIST_ROUTE` = 50, or an explicit degree ``n``: Chebyshev collocation
  (:func:`spectral_rod.straight_rod.collocation_critical_load`); relative error <= ~3e-14
  there at n <= ~60 (nu in [1, 1e4], including nu - 1 down to 1e-12).
* |Omega(L)| >= 50: the paper's characteristic equation in double precision with a bracketing
  root finder (:func:`spectral_rod.large_twist.characteristic_double`); its cost does not grow
  with the twist (~2 ms a point) and its relative error is ~eps |Omega| (measured <= 2.5e-14
  at Omega(L) = 1000, <= 7e-13 at 1e4), whereas collocation needs n ~ 2.7 |Omega|^0.8 (n
  capped at 512, Omega(L) = 1000 out of reach) and loses accuracy to round-off (1e-12 at 200).
  These points are reported with ``n = 0`` in the full output (no collocation degree) and
  ``error_estimate = eps (8 + |Omega|/2)``, a bound on the measured error.

The asymptote p_inf [1 - pi^2 (nu-1)^2/(4 (nu+1)^2 Omega^2)] (:mod:`spectral_rod.large_twist`)
is *not* used for values: its O(Omega^-3) error exceeds 1e-10 for |Omega(L)| <= 1000.
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike

from spectral_rod._validation import check_nu, check_resolution, check_tol, check_twist
from spectral_rod.increment import galerkin_increment_family
from spectral_rod.large_twist import characteristic_double
from spectral_rod.straight_rod import (
    N_MAX,
    N_MIN,
    ConvergenceWarning,
    CriticalLoad,
    collocation_critical_load,
)

__all__ = ["NEAR_DEGENERATE", "TWIST_ROUTE", "critical_load"]

#: |Omega(L)| from which the characteristic equation (double precision) is used.
TWIST_ROUTE = 50.0
#: nu - 1 up to which p* = 1 + increment (for |Omega(L)| < TWIST_ROUTE).
NEAR_DEGENERATE = 1.0e-3
_EPS = float(np.finfo(float).eps)


def characteristic_error_estimate(twist_angle: np.ndarray) -> np.ndarray:
    """Relative error bound eps (8 + |Omega|/2) of the double-precision characteristic route."""
    return _EPS * (8.0 + np.abs(twist_angle) / 2.0)


def critical_load(twist_angle: ArrayLike, nu: ArrayLike, *, n: int | None = None,
                  tol: float = 1e-12, full_output: bool = False):
    """Critical load p* = P_cr / (pi^2 A1 / L^2) of the hinged, spontaneously twisted rod.

    Eq. ``inst1`` with hinged ends; twist_angle = Omega(L) = omega30 L in radians,
    |Omega(L)| <= 1e4 (p* is even in it: p*(-Omega) = p*(Omega), mirror image of the mode);
    nu = I2/I1 in [1, 1e4] (the paper's convention A1 <= A2; for I2 < I1 swap the axes and pass
    1/nu). ``n`` (even, 8..512) forces collocation at that degree; ``tol`` (1e-14..1e-2) is the
    requested relative accuracy; ``full_output`` returns a :class:`CriticalLoad` (degree used,
    0 for the characteristic-equation route; error estimate; mode family; converged flag).
    Scalars give a float, arrays broadcast and give an ndarray. If ``tol`` is not met a
    :class:`ConvergenceWarning` is issued (never silently). Routing: module docstring.
    """
    twist = check_twist(twist_angle)
    nu_arr = check_nu(nu)
    tol = check_tol(tol)
    if n is not None:
        check_resolution(n, minimum=N_MIN, maximum=N_MAX)
    if not isinstance(full_output, (bool, np.bool_)):
        raise TypeError(f"full_output must be True or False, got {type(full_output).__name__}")
    shape = np.broadcast_shapes(twist.shape, nu_arr.shape)
    tw = np.abs(np.broadcast_to(twist, shape).ravel())
    nv = np.broadcast_to(nu_arr, shape).ravel()
    # an explicit degree n means: collocation everywhere
    routed = (tw >= TWIST_ROUTE) & (n is None)
    degenerate = (nv - 1.0 <= NEAR_DEGENERATE) & ~routed & (n is None)
    if not (routed.any() or degenerate.any()):
        return collocation_critical_load(twist_angle, nu, n=n, tol=tol,
                                         full_output=full_output)
    p = np.empty(tw.size)
    deg = np.zeros(tw.size, dtype=int)
    err = np.empty(tw.size)
    fam = np.empty(tw.size, dtype="<U13")
    colloc = np.flatnonzero(~routed & ~degenerate)
    if colloc.size:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", ConvergenceWarning)
            res = collocation_critical_load(tw[colloc], nv[colloc], n=n, tol=tol,
                                            full_output=True)
        for w in caught:  # re-issue from here (the caller's stack level)
            warnings.warn(str(w.message), w.category, stacklevel=2)
        p[colloc], deg[colloc], err[colloc], fam[colloc] = (
            res.p_star, res.n, res.error_estimate, res.family)
    for i in np.flatnonzero(routed):
        p[i], fam[i] = characteristic_double(tw[i], nv[i])
    err[routed] = characteristic_error_estimate(tw[routed])
    for i in np.flatnonzero(degenerate):
        d, fam[i] = galerkin_increment_family(tw[i], nv[i])
        p[i] = 1.0 + d
        err[i] = max(_EPS, 1e-12 * d)
    converged = err <= tol
    bad = np.flatnonzero(routed & ~converged)
    if bad.size:
        warnings.warn(
            f"critical_load: tol={tol:g} not met at {bad.size} large-twist point(s): the "
            f"characteristic-equation route is accurate to ~eps (8 + |Omega|/2) = "
            f"{err[bad].max():.1e} (twist_angle={tw[bad[0]]:g}, nu={nv[bad[0]]:g})",
            ConvergenceWarning, stacklevel=2)
    if full_output:
        return CriticalLoad(p_star=p.reshape(shape), n=deg.reshape(shape),
                            error_estimate=err.reshape(shape), family=fam.reshape(shape),
                            converged=converged.reshape(shape), tol=tol)
    return float(p[0]) if shape == () else p.reshape(shape)
