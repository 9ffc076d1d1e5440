r"""The buckling mode of the hinged twisted rod (Eq. ``inst1`` and the paper's geometric
relations x'' = R(Omega s) omega), computed by the method that computed p*.

:func:`buckling_mode` asks the router (:mod:`spectral_rod.rod.router`) like
:func:`spectral_rod.critical_load` does:

* ``collocation``: the exact eigenvector of the discrete pencil at the degree that resolved p*
  (its Chebyshev coefficients); the centreline by Chebyshev double integration of
  x'' = R(Omega s) omega with x = 0 at both ends;
* ``characteristic``: the closed form of :mod:`spectral_rod.rod.characteristic_mode` at that p*
  (sums of cos/sin(beta_k s)); omega1 = -lambda xi, omega2 = -mu eta and x = R(Omega s)(xi, eta);
* ``ritz`` (forced only): the closed form at the Ritz p* (the Ritz basis carries the mode too,
  but the closed form is exact, so nothing is gained from a second representation);
* ``increment``: the increment method yields p* - 1 only (its 2x2 Schur complement carries the
  sin(pi s) part of the mode, not the mode), so the mode is the closed form at its p*. The
  families are separated by parity, so this is well conditioned even where the two families'
  loads nearly coincide (nu -> 1). At nu = 1 or Omega = 0 the mode is Euler's planar
  sin(pi s), in the plane of u0 at mid-span.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.polynomial.chebyshev as C
from numpy.typing import NDArray

from spectral_rod._validation import (
    check_nu,
    check_tol,
    check_twist,
    scalar_value,
)
from spectral_rod.errors import ConvergenceError
from spectral_rod.rod.characteristic_mode import SCALE_POINTS, fields_at_load
from spectral_rod.rod.collocation import collocation_mode_coefficients
from spectral_rod.rod.collocation.chebyshev import interpolation_coefficients
from spectral_rod.rod.critical import apply_bounds, solve_points, warn_unconverged
from spectral_rod.rod.results import BucklingMode
from spectral_rod.rod.router import check_route, route
from spectral_rod.rod.wavenumbers import critical_wavenumbers

__all__ = ["MAX_POINTS", "buckling_mode"]

#: Largest output grid of :func:`buckling_mode`.
MAX_POINTS = 100_000


def _check_points(points: object) -> int:
    if isinstance(points, bool) or not isinstance(points, (int, np.integer)):
        raise TypeError(f"points must be an integer in [2, {MAX_POINTS}], "
                        f"got {type(points).__name__}")
    if not 2 <= int(points) <= MAX_POINTS:
        raise ValueError(f"points must be an integer in [2, {MAX_POINTS}], got {points!r}")
    return int(points)


def _centreline(c1: NDArray[np.float64], c2: NDArray[np.float64], twist: float, n: int
                ) -> tuple[C.Chebyshev, C.Chebyshev]:
    """x1, x2 (Chebyshev series in x = 2s - 1) from x'' = R(Omega s) omega, x(0) = x(1) = 0."""
    m = 2 * (n + int(abs(twist)) + 16)
    xs = C.chebpts2(m)
    s = (xs + 1) / 2
    w1, w2 = C.chebval(xs, c1), C.chebval(xs, c2)
    rot = ((w1 * np.cos(twist * s) - w2 * np.sin(twist * s)),
           (w1 * np.sin(twist * s) + w2 * np.cos(twist * s)))
    out = []
    for f in rot:
        g = C.Chebyshev(C.chebint(interpolation_coefficients(f / 4.0), 2))  # d2/ds2 = 4 d2/dx2
        left, right = g(-1.0), g(1.0)
        out.append(g - C.Chebyshev([(left + right) / 2, (right - left) / 2]))
    return out[0], out[1]


def _collocation_fields(twist: float, nu: float, n: int, family: str, s: NDArray[np.float64]
                        ) -> tuple[NDArray[np.floating], ...]:
    """(omega1, omega2, x1, x2) at s, unscaled, from the collocation eigenvector."""
    c1, c2 = collocation_mode_coefficients(abs(twist), nu, n, family)
    if twist < 0:  # p* is even in Omega; the mode of -Omega is the mirror image (omega2 -> -)
        c2 = -c2
    x1, x2 = _centreline(c1, c2, twist, n)
    xs = 2 * s - 1
    return C.chebval(xs, c1), C.chebval(xs, c2), x1(xs), x2(xs)


def _closed_form_fields(twist: float, nu: float, p_star: float, family: str,
                        s: NDArray[np.float64]) -> tuple[NDArray[np.float64], ...]:
    """(omega1, omega2, x1, x2) at s, unscaled, from the closed form (or Euler's mode)."""
    if twist == 0.0 or nu == 1.0:
        xi = np.sin(np.pi * s) * np.cos(twist * (s - 0.5))  # x = sin(pi s) along u0(1/2)
        eta = -np.sin(np.pi * s) * np.sin(twist * (s - 0.5))
    else:
        dps = 30 + int(max(0.0, -math.log10(nu - 1.0)))  # p* - 1 ~ nu - 1 must be resolved
        xi, eta = fields_at_load(family, p_star, abs(twist), nu, s, dps)
        eta = -eta if twist < 0 else eta
    lam = np.pi**2 * p_star
    rot_c, rot_s = np.cos(twist * s), np.sin(twist * s)
    return (-lam * xi, -(lam / nu) * eta, xi * rot_c - eta * rot_s, xi * rot_s + eta * rot_c)


def buckling_mode(twist_angle: float, nu: float, *, n: int | None = None, tol: float = 1e-12,
                  method: str = "auto", points: int = 201) -> BucklingMode:
    """The buckling mode at p* (Eq. ``inst1``): curvatures, centreline and wavenumbers.

    Arguments as in :func:`spectral_rod.critical_load` (scalars only); ``points`` (2..100000) is
    the size of the uniform output grid in s/L. The mode comes from the method that computed p*
    (module docstring); ``converged`` and ``error_estimate`` are those of p*, and a missed
    ``tol`` warns (:class:`spectral_rod.ConvergenceWarning`); a mode that comes out non-finite or
    zero raises :class:`spectral_rod.ConvergenceError` (no such case is known).

    Returns
    -------
    BucklingMode
        The grid ``s``, the curvatures ``omega1``, ``omega2`` (max |omega| = 1 on a fixed fine
        grid), the centreline ``x1``, ``x2`` (zero at both hinges), p*, the method, resolution,
        error estimate and converged flag of p*, the wavenumbers ``beta1``, ``beta2`` and the
        mode family.

    Examples
    --------
    >>> m = buckling_mode(5.0, 1.5)
    >>> m.method, m.family, round(m.p_star, 6)
    ('collocation', 'symmetric', 1.164465)
    """
    twist = scalar_value(check_twist(twist_angle), "twist_angle")
    nu_f = scalar_value(check_nu(nu), "nu")
    tol, npts = check_tol(tol), _check_points(points)
    n, method = check_route(n, method)
    tw, nv = np.array([abs(twist)]), np.array([nu_f])
    res = solve_points(tw, nv, route(tw, nv, n, method), n, tol)
    apply_bounds(res, nv)
    converged = res.error_estimate <= tol
    warn_unconverged("buckling_mode", converged, res, tw, nv, tol)
    p, fam, how, deg = float(res.p_star[0]), str(res.family[0]), str(res.method[0]), int(res.n[0])
    s = np.linspace(0.0, 1.0, npts)
    # the scale and sign come from a fixed fine grid only, so that every output grid (even
    # just the two hinges, where omega = 0) is normalised alike; on its half s <= 1/2, where an
    # antisymmetric mode's +-max |omega| do not tie (on the union with the output grid the
    # mid-span x1 changed sign between points = 5 and 20001 at Omega(L) = -20.76, nu = 915.9,
    # and omega2 moved 0.5 % at 53.37, 273.4; tests/test_safety.py)
    fine = np.linspace(0.0, 1.0, SCALE_POINTS)
    both_s = np.concatenate([s, fine[fine <= 0.5]])
    if how == "collocation":
        fields = _collocation_fields(twist, nu_f, deg, fam, both_s)
    else:
        fields = _closed_form_fields(twist, nu_f, p, fam, both_s)
    w1, w2, x1, x2 = (f[:npts] for f in fields)
    both = np.concatenate([fields[0][npts:], fields[1][npts:]])
    scale = both[np.argmax(np.abs(both))]  # max |omega| = 1 on the fine grid, there positive
    if scale == 0.0 or not all(np.isfinite(f).all() for f in fields):
        # never a nan mode flagged converged (e.g. a closed form that underflows at twist 5e-324)
        raise ConvergenceError(f"buckling_mode: no finite nonzero mode at twist_angle={twist!r}, "
                               f"nu={nu_f!r} (method {how}, p*={p!r})")
    beta1, beta2 = critical_wavenumbers(p, twist, nu_f)
    return BucklingMode(s=s, omega1=w1 / scale, omega2=w2 / scale, x1=x1 / scale, x2=x2 / scale,
                        p_star=p, twist_angle=twist, nu=nu_f, family=fam, method=how, n=deg,
                        error_estimate=float(res.error_estimate[0]),
                        converged=bool(converged[0]), beta1=beta1, beta2=beta2)
