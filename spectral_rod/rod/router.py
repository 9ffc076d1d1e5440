"""The one router: which method answers p* at each point, for every straight-rod entry point.

:func:`spectral_rod.critical_load`, :func:`spectral_rod.buckling_mode` and the scenes all ask
:func:`choose_method`. The automatic choice (``method="auto"``), measured against the mpmath
characteristic equation (tests/test_extremes.py and the ``extremes`` scene):

* an explicit degree ``n``: Chebyshev collocation everywhere (``n`` is its parameter);
* |Omega(L)| >= :data:`TWIST_ROUTE` = 50: the characteristic equation in double precision
  (:func:`spectral_rod.rod.characteristic.characteristic_double`), each family's lowest root
  bracketed by the large-twist expansion and certified the lowest: its cost does not grow with
  the twist and its relative error is a few eps (the phases of size Omega are never rounded;
  measured <= 2 eps against 40-digit references), whereas collocation needs
  n ~ |Omega|/2 + 4.5 |Omega|^(1/3) + 10 at tol 1e-12 (n capped at 512;
  :func:`spectral_rod.rod.collocation.resolution.initial_degree`) and loses accuracy to
  round-off (1e-12 at Omega(L) = 200);
* nu - 1 <= :data:`NEAR_DEGENERATE` = 1e-3 (and |Omega(L)| < 50): the characteristic
  equation in double precision too, each family's lowest root refined in the bracket of its
  bounds [1, nu], which holds exactly that root
  (:func:`spectral_rod.rod.characteristic.characteristic_double_batch`): p* itself is well
  conditioned there (the nearly double pair of eigenvalues is split between the two parity
  families), measured <= 4.2e-15 relative (0.31 of its error estimate) on 1,000 random points
  (Omega(L) in [0, 50], nu - 1 log-uniform in [1e-14, 1e-3]) against 40-digit references, no
  unflagged miss at tol 1e-14 (tests/bench/hunt_routes.py). Only p* - 1 loses its
  relative accuracy there: :func:`spectral_rod.critical_load_increment` carries it. Where the
  two families' loads differ by less than the error estimate, the family reported is the one
  whose computed root is lower; either family's mode buckles at p* within the estimate (the
  buckling mode is that family's closed form, :mod:`spectral_rod.rod.mode`);
* otherwise Chebyshev collocation (:mod:`spectral_rod.rod.collocation`, <= ~5e-14 relative).

A method can also be forced (``method=`` one of :data:`ROD_METHODS`), e.g. to cross-check:
``"ritz"`` is the Rayleigh-Ritz discretisation of the lab-frame *energy*
(:mod:`spectral_rod.rod.ritz`): it does not start from Eq. ``inst1``, and each family's value is an
upper bound.

>>> choose_method([10.0, 100.0, 10.0], [1.5, 1.5, 1.0001]).tolist()
['collocation', 'characteristic', 'characteristic']
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import broadcast_points, check_nu, check_resolution, check_twist
from spectral_rod.rod.collocation.arithmetic import ARRAYS, FLOATS, Namespace

__all__ = ["INCREMENT_MAX_TWIST", "METHOD_DTYPE", "NEAR_DEGENERATE", "ROD_METHODS", "TWIST_ROUTE",
           "characteristic_route", "check_method", "check_route", "choose_method", "route",
           "route_point"]

#: The methods that compute p* (``method=`` of :func:`spectral_rod.critical_load`).
ROD_METHODS = ("collocation", "characteristic", "increment", "ritz")
#: The numpy string dtype of arrays of method names (:func:`route`'s).
METHOD_DTYPE = f"<U{max(map(len, ROD_METHODS))}"
#: |Omega(L)| (radians) from which the characteristic equation (double precision) is used.
TWIST_ROUTE = 50.0
#: nu - 1 up to which p* comes from the characteristic equation in the family bounds'
#: brackets (|Omega(L)| < TWIST_ROUTE), and up to which method="increment" is accepted.
NEAR_DEGENERATE = 1.0e-3
#: |Omega(L)| limit of the increment (its sine basis needs N ~ 2|Omega|/pi + 48 modes).
INCREMENT_MAX_TWIST = 1.0e3
#: |Omega(L)| limit of Rayleigh-Ritz (degree ~ |Omega| + 66, cost ~ |Omega|^3).
RITZ_MAX_TWIST = 1.0e3


def check_method(method: object) -> str:
    """`method` if it is "auto" or one of :data:`ROD_METHODS`."""
    if not isinstance(method, str):
        raise TypeError(f"method must be 'auto' or one of {ROD_METHODS}, "
                        f"got {type(method).__name__}")
    if method != "auto" and method not in ROD_METHODS:
        raise ValueError(f"method must be 'auto' or one of {ROD_METHODS}, got {method!r}")
    return method


def check_route(n: object, method: object) -> tuple[int | None, str]:
    """(n, method) checked once for every entry point: `method` as :func:`check_method`; a
    degree n (even, N_MIN..N_MAX of the collocation solver) only with collocation."""
    from spectral_rod.rod.collocation.resolution import N_MAX, N_MIN

    method = check_method(method)
    if n is not None:
        n = check_resolution(n, minimum=N_MIN, maximum=N_MAX)
        if method not in ("auto", "collocation"):
            raise ValueError(f"n (the Chebyshev degree) applies to collocation only, "
                             f"not to method={method!r}")
    return n, method


def route(twist: NDArray[np.float64], nu: NDArray[np.float64], n: int | None = None,
          method: str = "auto") -> NDArray[np.str_]:
    """The method per point for flat, validated arrays (module docstring); raises ValueError
    where a forced method is outside its range."""
    if method == "increment":
        bad = (nu - 1.0 > NEAR_DEGENERATE) | (np.abs(twist) > INCREMENT_MAX_TWIST)
        if bad.any():
            raise ValueError(f"method='increment' needs nu - 1 <= {NEAR_DEGENERATE:g} and "
                             f"|twist_angle| <= {INCREMENT_MAX_TWIST:g} (use "
                             f"critical_load_increment for p* - 1 elsewhere)")
    if method == "ritz" and np.any(np.abs(twist) > RITZ_MAX_TWIST):
        raise ValueError(f"method='ritz' needs |twist_angle| <= {RITZ_MAX_TWIST:g} (its cost grows "
                         "like |Omega|^3)")
    if method != "auto":
        return np.full(twist.shape, method, dtype=METHOD_DTYPE)
    if n is not None:
        return np.full(twist.shape, "collocation", dtype=METHOD_DTYPE)
    out = np.full(twist.shape, "collocation", dtype=METHOD_DTYPE)
    out[characteristic_route(twist, nu)] = "characteristic"
    return out


def characteristic_route(twist: Any, nu: Any, xp: Namespace = ARRAYS) -> Any:
    """The automatic route's rule: the characteristic equation answers where |Omega| >=
    TWIST_ROUTE or nu - 1 <= NEAR_DEGENERATE, collocation elsewhere (module docstring); arrays,
    or one point in Python floats with ``xp`` =
    :data:`spectral_rod.rod.collocation.arithmetic.FLOATS`.

    >>> characteristic_route(100.0, 1.5, FLOATS), characteristic_route(5.0, 1.5, FLOATS)
    (True, False)
    """
    return (xp.abs(twist) >= TWIST_ROUTE) | (nu - 1.0 <= NEAR_DEGENERATE)


def route_point(twist: float, nu: float, n: int | None = None, method: str = "auto") -> str:
    """:func:`route` for one validated point in Python floats (the scalar path's; the same
    rule, :func:`characteristic_route`); a forced increment outside its range is left to
    :func:`route` to reject."""
    if method != "auto":
        return method
    if n is not None:
        return "collocation"
    return "characteristic" if characteristic_route(twist, nu, FLOATS) else "collocation"


def choose_method(twist_angle: ArrayLike, nu: ArrayLike, *, n: int | None = None,
                  method: str = "auto"):
    """The method :func:`spectral_rod.critical_load` uses at each point (a str for scalars, an
    array of str otherwise); arguments as there.

    Returns
    -------
    str or ndarray of str
        One of :data:`spectral_rod.ROD_METHODS` per point (the broadcast shape of the inputs).

    Examples
    --------
    >>> choose_method(5.0, 1.5)
    'collocation'
    >>> choose_method([10.0, 100.0], 1.5).tolist()
    ['collocation', 'characteristic']
    """
    twist, nu_arr = check_twist(twist_angle), check_nu(nu)
    n, method = check_route(n, method)
    shape = broadcast_points(twist_angle=twist, nu=nu_arr)
    out = route(np.broadcast_to(twist, shape).ravel(), np.broadcast_to(nu_arr, shape).ravel(),
                n, method).reshape(shape)
    return str(out) if shape == () else out
