r"""The paper's own method: the characteristic equation of Eq. ``inst1`` and its lowest root.

Two precisions of one formulation: mpmath at ``dps`` digits (:func:`characteristic_critical_load`,
:func:`family_critical_load`; the independent reference for every test of the collocation solver,
which it never calls) and numpy double precision (:func:`characteristic_double`, the production
route for large twist, whose cost does not grow with the twist).

Derivation (body-frame displacements xi, eta, proportional to omega1, omega2)
------------------------------------------------------------------------------
With t = s/L - 1/2 in [-1/2, 1/2], Omega = omega30 L, lambda = P L^2/A1 = pi^2 p*, mu = lambda/nu,
Eq. ``inst1`` is equivalent to

    xi''  - 2 Omega eta' + (lambda - Omega^2) xi  = 0,
    eta'' + 2 Omega xi'  + (mu     - Omega^2) eta = 0,      xi = eta = 0 at t = +-1/2

(omega1 = -lambda xi, omega2 = -mu eta; hinged ends are omega = 0, see
:mod:`spectral_rod.rod.collocation`). Trying xi, eta ~ exp(i beta t) gives the characteristic
polynomial of :mod:`spectral_rod.rod.wavenumbers` with roots X_- <= X_+. Reflection t -> -t splits
the solutions (:mod:`spectral_rod.rod.families`):

* symmetric family (xi even, eta odd): xi = a cos(beta t), eta = b sin(beta t)/beta, with
  (lambda - Omega^2 - X) a = 2 Omega b, i.e. (a, b) = (2 Omega, lambda - Omega^2 - X);
* antisymmetric family (xi odd, eta even): xi = a sin(beta t)/beta, eta = b cos(beta t), with
  (mu - Omega^2 - X) b = -2 Omega a, i.e. (a, b) = (mu - Omega^2 - X, -2 Omega).

The functions cos(sqrt(X) t) and sin(sqrt(X) t)/sqrt(X) are entire in X (cosh and sinh/kappa when
X < 0, 1 and t at X = 0), and the amplitude vectors vanish only at Omega = 0, so after dividing the
2x2 boundary determinants at t = 1/2 by the common factor 2 Omega (the removable singularity at
zero twist) they are continuous in lambda and vanish exactly at the eigenvalues of each family:

    D_sym(lambda)  = C_+ S_- (lambda - Omega^2 - X_-) - C_- S_+ (lambda - Omega^2 - X_+),
    D_anti(lambda) = (mu - Omega^2 - X_+) S_+ C_- - (mu - Omega^2 - X_-) S_- C_+,

with C = cos(sqrt(X)/2), S = sin(sqrt(X)/2)/sqrt(X). At Omega = 0 they reduce to
(lambda - mu) cos(sqrt(lambda)/2) S(mu) and (mu - lambda) S(lambda) cos(sqrt(mu)/2): the Euler
modes lambda = pi^2, 4 nu pi^2 and 4 pi^2, nu pi^2. (This 2x2 pair is the paper's 4x4 boundary
determinant, :func:`spectral_rod.rod.characteristic_mode.boundary_determinant_4x4`,
block-diagonalised by the reflection symmetry.)

The lowest root
---------------
The Rayleigh quotient gives 1 <= p* <= (1 + nu)/2 (:mod:`spectral_rod.rod.families`), and each
family's lowest load lies in [1, nu]. The lab-frame quotient of Eq. ``inst1``
(:mod:`spectral_rod.rod.increment`) is >= int |z''|^2 / int |z'|^2, whose eigenvalues are k^2 pi^2,
each twice (x1 and x2): by min-max at most two eigenvalues of Eq. ``inst1`` (with multiplicity)
lie below p = 4. Hence a sign change of D_sym and one of D_anti in brackets below p = 4 are
each family's only, and lowest, root there, and p* is the smaller: the *certificate* of the
double-precision routes below.

* mpmath (the reference): both determinants are scanned for sign changes on a grid in p from
  1 - 1e-9 upward (:mod:`spectral_rod.numerics.sign_scan`, step 1/128) and the first bracket is
  refined
  (Anderson iteration, bisection fallback). A root exactly at p = 1 (nu = 1 or Omega = 0) is
  returned in closed form.
* double precision, |Omega(L)| >= :data:`BRACKET_MIN_TWIST` = 50: each family's root is
  bracketed by its large-twist expansion to Omega^-4
  (:func:`spectral_rod.rod.closed_form.family_expansions`, half-width :func:`_half_width`), the two
  brackets are certified as above, and the roots are refined in the *phase form* of the
  determinants (:func:`_phase_terms`), for all points at once; the scalar path runs the same
  algorithm in Python floats (:func:`_bracketed_point`).
* double precision, 1 < nu <= :data:`FAMILY_BOUND_MAX_NU` = 1 + 1e-3: each family's root is
  refined in the bracket of its bounds [1, nu] (:func:`_family_bound_batch`).
* elsewhere, and wherever a bracket shows no sign change: the scan in steps of 1/256, its
  brackets refined together by Anderson-Bjorck regula falsi.

Scan steps (empirical): one family's roots are O(1) apart in p on the ranges tested
(tests/test_extremes.py, test_two_solvers.py).

Double precision: from |Omega(L)| = 50 on, the phase form rounds no phase of size Omega
(sqrt(X)/2 = Omega/2 + r/2, with cos and sin of Omega/2 exact and r = sqrt(X) - Omega without
cancellation): p* to a few eps, measured <= 2 eps on 50 random points (Omega(L) log-uniform in
[50, 1e4], nu in [1, 1e4], 40-digit references) and <= 3.6e-15 by tests/bench/hunt_routes.py
(1,000 random points, Omega(L) log-uniform in [1e-3, 1e4]); :func:`double_error_estimate` is
:data:`PHASE_ERROR` eps there. Below 50 the relative error of :func:`determinants`' roots is
~eps |Omega| (the slow phase sqrt(X_+) - sqrt(X_-) is a difference of two phases of size Omega),
measured <= 0.58 eps |Omega| and <= 7 eps at small twist: the estimate is
eps (:data:`DIRECT_ERROR` + |Omega|).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import (
    check_int,
    check_real,
    scalar_nu,
    scalar_twist,
)
from spectral_rod.errors import RootNotFoundError
from spectral_rod.numerics.sign_scan import (
    bracketed_root,
    bracketed_roots,
    lowest_root,
    lowest_roots,
)
from spectral_rod.rod.families import FAMILIES, check_family, euler_loads
from spectral_rod.rod.wavenumbers import characteristic_roots, root_offsets

if TYPE_CHECKING:  # mpmath is imported where it is used: the double-precision route needs none
    import mpmath as mp

__all__ = [
    "CharacteristicRoot",
    "bracketed_root_mp",
    "characteristic_critical_load",
    "characteristic_determinant",
    "characteristic_double",
    "characteristic_double_batch",
    "combine_determinant",
    "determinant",
    "determinants",
    "double_error_estimate",
    "family_critical_load",
    "family_double_batch",
]

#: Scan steps in p (empirical, see the module docstring) and the scan's start below p = 1.
MP_SCAN_STEP, DOUBLE_SCAN_STEP, SCAN_START = 1.0 / 128, 1.0 / 256, 1.0 - 1e-9
#: How far past its upper bound ((1 + nu)/2 for p*, nu for one family) a scan runs.
SCAN_MARGIN = 1e-6
#: Grid points per scan pass in double precision (all points still scanning at once): smaller
#: passes waste fewer evaluations on low roots but cost more passes. Measured on 1,000 points,
#: Omega(L) in [50, 1000], nu in [1, 100]: 33/65/129/257 -> 36/30/30/34 us a point.
DOUBLE_CHUNK = 129
#: A few points (or brackets): up to this many, a double-precision scan takes passes of
#: ONE_POINT_CHUNK grid points, and its refinement runs one bracket at a time in Python floats
#: (:func:`~spectral_rod.numerics.sign_scan.bracketed_root` on :func:`determinant` with
#: ``lib=math``,
#: 1.1 us an evaluation), where numpy's per-call cost on arrays of one or two entries would be
#: most of the time (measured: 1.2 ms a scalar scan on arrays, 0.21 ms in floats).
FEW_POINTS = 4
#: Up to this many points the certified brackets (the large-twist expansion's, the family
#: bounds') are found and refined one point at a time in Python floats (:func:`_bracketed_point`,
#: :func:`_family_bound_point`: the scalar path's functions) instead of on arrays, whose cost on
#: a few points is numpy's per-call cost (loop / arrays time at 8, 16, 24 and 32 points: 0.23,
#: 0.53, 0.73 and 0.83 for the family bounds, 0.41, 0.70, 1.06 and 1.39 for the large-twist
#: brackets; ``python tests/bench/tuning_crossovers.py``, part 5).
FEW_BRACKETS = 24
#: One pass of this many grid points reaches p = 2, above the large-twist limit 2 nu/(1 + nu)
#: (passes of DOUBLE_CHUNK, 71 us each for one point, take 1.8 a point on average on 30 random
#: large-twist points).
ONE_POINT_CHUNK = 257
_EPS = float(np.finfo(float).eps)
#: The precisions of :func:`determinants` (those of :func:`entire_cs_double`).
_DTYPES = (np.dtype(np.float64), np.dtype(np.float32))


def entire_cs(x: Any, t: Any = None, lib: Any = None) -> tuple[Any, Any]:
    """cos(sqrt(X) t) and sin(sqrt(X) t)/sqrt(X) (t = 1/2 by default), entire in X: mpmath
    numbers, or Python floats with ``lib=math``.

    >>> entire_cs(0.0, lib=math), entire_cs(-4.0, 1.0, lib=math)[0] == math.cosh(2.0)
    ((1.0, 0.5), True)
    """
    if lib is None:
        import mpmath

        lib = mpmath
    if t is None:
        t = 0.5 if lib is math else lib.mpf(1) / 2
    if x > 0:
        b = lib.sqrt(x)
        return lib.cos(b * t), lib.sin(b * t) / b
    if x < 0:
        k = lib.sqrt(-x)
        return lib.cosh(k * t), lib.sinh(k * t) / k
    return (1.0 if lib is math else lib.mpf(1)), t


def entire_cs_double(x: ArrayLike, t: ArrayLike = 0.5
                     ) -> tuple[NDArray[np.floating], NDArray[np.floating]]:
    """:func:`entire_cs` for numpy arrays (broadcast X and t; cosh, sinh where X <= 0).

    Computed in X's precision: float32 X gives float32 results (t converted to it), anything
    else float64.

    >>> c, s = entire_cs_double(np.array([-4.0, 0.0, 4.0], dtype=np.float32))
    >>> c.dtype, [round(float(v), 4) for v in c], [round(float(v), 4) for v in s]
    (dtype('float32'), [1.5431, 1.0, 0.5403], [0.5876, 0.5, 0.4207])
    """
    x = np.asarray(x)
    dtype = np.float32 if x.dtype == np.float32 else np.float64
    x, t = np.broadcast_arrays(x.astype(dtype, copy=False), np.asarray(t, dtype=dtype))
    r = np.sqrt(np.abs(x))
    pos = x > 0
    rp, rn = np.where(pos, r, 0.0), np.where(pos, 0.0, r)  # hyperbolic part only where X <= 0
    c = np.where(pos, np.cos(rp * t), np.cosh(rn * t))
    with np.errstate(invalid="ignore", divide="ignore"):
        s = np.where(pos, np.sin(rp * t), np.sinh(rn * t)) / r
    return c, np.where(r == 0, t, s)


def combine_determinant(family: str, lam: Any, mu: Any, om2: Any, roots: tuple[Any, Any],
             cs: tuple[tuple[Any, Any], ...]) -> Any:
    """D_sym or D_anti from the roots (X_-, X_+) and their (C, S) (module docstring)."""
    (xm, xp), ((cm, sm), (cp, sp)) = roots, cs
    if family == "symmetric":
        return cp * sm * (lam - om2 - xm) - cm * sp * (lam - om2 - xp)
    return (mu - om2 - xp) * sp * cm - (mu - om2 - xm) * sm * cp


def determinant(family: str, lam: Any, om: Any, nu: Any, lib: Any = None) -> Any:
    """D_sym or D_anti at the load lambda = pi^2 p, twist Omega, nu; valid at Omega = 0. In
    mpmath, or in Python floats with ``lib=math`` (one point of the double-precision route:
    numpy's per-call cost would be most of an evaluation).

    >>> abs(determinant("symmetric", math.pi**2, 0.0, 1.5, lib=math)) < 1e-16  # Euler's load
    True
    """
    if lib is None:
        import mpmath

        lib = mpmath
    check_family(family)
    mu = lam / nu
    roots = characteristic_roots(lam, mu, om, sqrt=lib.sqrt)
    cs = (entire_cs(roots[0], lib=lib), entire_cs(roots[1], lib=lib))
    return combine_determinant(family, lam, mu, om * om, roots, cs)


def determinants(p: ArrayLike, twist_angle: ArrayLike, nu: ArrayLike, *,
                 dtype: type = np.float64, real_wavenumbers: bool = False
                 ) -> tuple[NDArray[np.floating], NDArray[np.floating]]:
    """(D_sym, D_anti) at lambda = pi^2 p (p, twist_angle, nu broadcast), in `dtype`.

    dtype: np.float64 (the production route) or np.float32 (single precision, every operation
    in it). real_wavenumbers: sqrt(X) taken in real arithmetic, NaN where X < 0 beyond the
    rounding level of X (as a program written in terms of real beta_k would compute it: an X
    that is zero in exact arithmetic is not counted); otherwise continued to cosh, sinh/kappa.
    D_sym changes sign across the symmetric root p = 1.0024446 at Omega = 0.5, nu = 1.5, in
    either precision; at Omega = 3, nu = 1.5, p = 1 (beta_1 imaginary) only the continuation
    has a value:

    >>> d_sym, _ = determinants([1.002, 1.003], 0.5, 1.5)
    >>> d_sym32, _ = determinants([1.002, 1.003], 0.5, 1.5, dtype=np.float32)
    >>> np.sign(d_sym).tolist(), d_sym32.dtype, np.sign(d_sym32).tolist()
    ([1.0, -1.0], dtype('float32'), [1.0, -1.0])
    >>> [bool(np.isnan(determinants(1.0, 3.0, 1.5, real_wavenumbers=r)[0])) for r in (False, True)]
    [False, True]
    """
    try:
        ok = dtype is not None and np.dtype(dtype) in _DTYPES
    except TypeError:  # not a dtype at all: named below
        ok = False
    if not ok:
        raise ValueError(f"dtype must be np.float64 or np.float32, got {dtype!r}")
    if not isinstance(real_wavenumbers, (bool, np.bool_)):
        raise TypeError(f"real_wavenumbers must be True or False, got "
                        f"{type(real_wavenumbers).__name__}")
    return _determinants(p, twist_angle, nu, np.dtype(dtype).type, real_wavenumbers)


def _determinants(p: ArrayLike, twist_angle: ArrayLike, nu: ArrayLike, dtype: type,
                  real_wavenumbers: bool) -> tuple[NDArray[np.floating], NDArray[np.floating]]:
    """:func:`determinants` without its argument checks (the double-precision root finders call
    it once per refinement step)."""
    lam = dtype(np.pi**2) * np.asarray(p, dtype=dtype)
    om: NDArray[np.floating] = np.asarray(twist_angle, dtype=dtype)
    mu = lam / np.asarray(nu, dtype=dtype)
    om2 = om * om
    roots = characteristic_roots(lam, mu, om)
    cs: tuple[tuple[NDArray[np.floating], NDArray[np.floating]], ...] = (
        entire_cs_double(roots[0]), entire_cs_double(roots[1]))
    if real_wavenumbers:
        # rounding level of X: X_- = 0 exactly where a scan of lambda - nu Omega^2 starts
        zero = 64 * np.finfo(dtype).eps * (lam + om2)
        cs = tuple((np.where(x < -zero, np.nan, c), np.where(x < -zero, np.nan, s))
                   for x, (c, s) in zip(roots, cs, strict=True))
    return tuple(combine_determinant(f, lam, mu, om2, roots, cs)
                 for f in FAMILIES)


@dataclass(frozen=True)
class CharacteristicRoot:
    """p* from the characteristic equation, the family of the mode, and beta_k^2 L^2 there.

    Examples
    --------
    >>> import spectral_rod as sr
    >>> r = sr.characteristic_critical_load(0.0, 1.5)
    >>> float(r.p_star), r.family
    (1.0, 'symmetric')
    """

    p_star: mp.mpf
    family: str
    x_minus: mp.mpf  # beta_1^2 L^2 (negative: beta_1 imaginary)
    x_plus: mp.mpf   # beta_2^2 L^2


def bracketed_root_mp(f: Any, a: mp.mpf, b: mp.mpf) -> mp.mpf:
    """The root of f in [a, b] (f changes sign there) at the working precision, by mpmath's
    Anderson-Bjorck (bisection should it ever leave the bracket)."""
    import mpmath as mp

    r = mp.findroot(f, (a, b), solver="anderson")
    if not a <= r <= b:  # pragma: no cover - anderson keeps the bracket
        r = mp.findroot(f, (a, b), solver="bisect")
    return r


def _mp_root(families: tuple[str, ...], twist_angle: float, nu: float, dps: int,
             scan_step: float, top: float) -> CharacteristicRoot:
    """Lowest root over `families` by the sign scan in mpmath at `dps` digits."""
    import mpmath as mp

    with mp.workdps(dps):
        om, nuv = mp.mpf(abs(twist_angle)), mp.mpf(nu)
        funcs = [lambda p, f=f: determinant(f, mp.pi**2 * p, om, nuv) for f in families]

        found = lowest_root(lambda grid: [[g(p) for p in grid] for g in funcs],
                            lambda k, a, b: bracketed_root_mp(funcs[k], a, b),
                            mp.mpf(SCAN_START), mp.mpf(top), mp.mpf(scan_step))
        if found is None:
            raise RootNotFoundError(f"no root of the {'/'.join(families)} determinant for p in "
                                    f"[1, {top:g}] (twist_angle={twist_angle}, nu={nu})")
        r, k = found
        lam = mp.pi**2 * r
        xm, xp = characteristic_roots(lam, lam / nuv, om, sqrt=mp.sqrt)
        return CharacteristicRoot(r, families[k], xm, xp)


def _closed_form_root(family: str, twist_angle: float, nu: float, dps: int
                      ) -> CharacteristicRoot:
    """nu = 1 or Omega = 0: the Euler loads (symmetric 1; antisymmetric min(4, nu), or 1 at
    nu = 1), exact."""
    import mpmath as mp

    with mp.workdps(dps):
        nuv = mp.mpf(nu)
        r = mp.mpf(1) if family == "symmetric" or nu == 1.0 else min(mp.mpf(4), nuv)
        lam = mp.pi**2 * r
        xm, xp = characteristic_roots(lam, lam / nuv, mp.mpf(abs(twist_angle)), sqrt=mp.sqrt)
        return CharacteristicRoot(r, family, xm, xp)


#: The ranges of |Omega(L)| and nu the mpmath reference accepts (wider than the production
#: routes': the reference checks them at their edges);
#: :func:`~spectral_rod.rod.characteristic_mode.mode_fields`
#: accepts the same.
REFERENCE_MAX_TWIST, REFERENCE_MAX_NU = 1.0e6, 1.0e8
#: Allowed ranges of the reference's knobs: working digits, and the scan step in p (below the
#: default the cost grows, above 1/64 the lowest-root guarantee -- no two roots of one family
#: within a step -- is no longer backed by the tests' grids).
DPS_RANGE, SCAN_STEP_RANGE = (15, 200), (1.0e-4, 1.0 / 64)


def _reference_args(twist_angle: object, nu: object, dps: object, scan_step: object,
                    p_max: object, p_floor: float) -> tuple[float, float, int, float, float | None]:
    """Validated (twist, nu, dps, scan_step, p_max) of the mpmath reference (names in errors)."""
    om = scalar_twist(twist_angle, max_abs=REFERENCE_MAX_TWIST)
    nu = scalar_nu(nu, max_value=REFERENCE_MAX_NU)
    dps = check_int(dps, "dps", *DPS_RANGE)
    scan_step = check_real(scan_step, "scan_step", *SCAN_STEP_RANGE)
    if p_max is not None:
        p_max = check_real(p_max, "p_max", p_floor, 1e8, lo_open=True)
    return om, nu, dps, scan_step, p_max


def characteristic_critical_load(twist_angle: float, nu: float, *, dps: int = 40,
                                 scan_step: float = MP_SCAN_STEP,
                                 p_max: float | None = None) -> CharacteristicRoot:
    """Lowest root p* of the characteristic determinants (extended precision, ``dps`` digits).

    twist_angle: Omega(L) in radians (p* is even in it); nu = I2/I1 >= 1. The scan runs from
    p = 1 - 1e-9 to p_max (default (1 + nu)/2, the Rayleigh upper bound, plus a margin) and the
    lowest sign change of either family is refined. Raises RootNotFoundError if none is found.

    Returns
    -------
    CharacteristicRoot
        p* (an ``mpmath.mpf``), the critical family and beta_k^2 L^2 there.

    Examples
    --------
    >>> float(characteristic_critical_load(0.0, 1.5).p_star)
    1.0
    """
    om_f, nu_f, dps, scan_step, p_max = _reference_args(twist_angle, nu, dps, scan_step, p_max,
                                                        1.0)
    if nu_f == 1.0 or om_f == 0.0:
        return _closed_form_root("symmetric", om_f, nu_f, dps)
    top = (1 + nu_f) / 2 + SCAN_MARGIN if p_max is None else p_max
    return _mp_root(FAMILIES, om_f, nu_f, dps, scan_step, top)


def family_critical_load(family: str, twist_angle: float, nu: float, *, dps: int = 40,
                         scan_step: float = MP_SCAN_STEP,
                         p_max: float | None = None) -> CharacteristicRoot:
    """Lowest root p of one family's determinant (``determinant(family, ...)``), by sign scan.

    Bounds (Rayleigh quotient restricted to the family's parity subspace, which the operator of
    Eq. ``inst1`` leaves invariant): 1 <= p_family <= nu, because the planar trial mode
    x = sin(pi s) e(theta) lies in the symmetric family for theta = Omega/2 and in the
    antisymmetric one for theta = Omega/2 + pi/2, and its quotient is at most A2/A1 = nu. The scan
    runs to p_max (default nu plus a margin). At Omega = 0 or nu = 1 the roots are the Euler
    loads, returned in closed form (symmetric 1, antisymmetric min(4, nu) for nu > 1 at zero
    twist; both 1 for nu = 1). p* is the smaller of the two families' roots.

    Returns
    -------
    CharacteristicRoot
        The family's lowest root p (an ``mpmath.mpf``), the family and beta_k^2 L^2 there.

    Examples
    --------
    >>> import spectral_rod as sr
    >>> r = family_critical_load("symmetric", 5.0, 1.5)   # the critical family at Omega = 5
    >>> abs(float(r.p_star) / sr.critical_load(5.0, 1.5) - 1) < 1e-12
    True
    """
    check_family(family)
    om_f, nu_f, dps, scan_step, p_max = _reference_args(twist_angle, nu, dps, scan_step, p_max,
                                                        1.0)
    if nu_f == 1.0 or om_f == 0.0:
        return _closed_form_root(family, om_f, nu_f, dps)
    top = nu_f + SCAN_MARGIN if p_max is None else p_max
    try:
        root = _mp_root((family,), om_f, nu_f, dps, scan_step, top)
    except RootNotFoundError:
        root = None
    if root is None or root.p_star > nu_f + SCAN_MARGIN:
        # the bound puts a root in [1, nu]: the scan stepped over an even number of roots
        pair = _close_pair_root(family, om_f, nu_f, dps, scan_step, min(top, nu_f + SCAN_MARGIN))
        if pair is not None:
            return pair
    if root is None:
        raise RootNotFoundError(f"no root of the {family} determinant for p in [1, {top:g}] "
                                f"(twist_angle={om_f}, nu={nu_f})")
    return root


def _pair_bracket(f: Any, a: mp.mpf, x: mp.mpf, d0: mp.mpf) -> mp.mpf:
    """The left end of a bracket [lo, x] of the lower root of a pair around the extremum x of
    f (f(x) = d0): twice the quadratic model's half-distance below x, or `a` (a far end, where
    Anderson-Bjorck converged too slowly at Omega = 1e-10) if the model does not bracket."""
    import mpmath as mp

    d2 = mp.diff(f, x, 2)
    if d0 * d2 < 0:
        lo = x - 2 * mp.sqrt(-2 * d0 / d2)
        if a < lo and f(lo) * d0 < 0:
            return lo
    return a


#: Digits beyond dps (and beyond the 2 log10(1/|Omega|) a close pair needs) at which a pair is
#: separated: an empirical margin, like :data:`spectral_rod.rod.characteristic_mode.MODE_DIGITS`.
PAIR_DIGITS = 10


def _close_pair_root(family: str, twist_angle: float, nu: float, dps: int, step: float,
                     top: float) -> CharacteristicRoot | None:
    """The lower of two roots of one family closer than a scan step, or None.

    At small twist the roots lie near the family's Euler loads, and where two of those coincide
    (antisymmetric: 4 = nu) the twist splits them by ~Omega (measured at nu = 4: 4 -+ 1.081
    Omega): the determinant has the same sign on both sides and an extremum of the other sign
    between them. Around each Euler load e below `top`, the extremum x in [e - step, e + step]
    (a root of D') is found; if D(x) has the other sign, the quadratic model of D there brackets
    the lower root. D(x) = O(Omega^2), so the work is done at dps + 2 log10(1/|Omega|) +
    PAIR_DIGITS digits.
    """
    import mpmath as mp

    digits = dps + PAIR_DIGITS + 2 * max(0, math.ceil(-math.log10(twist_angle)))
    with mp.workdps(digits):
        om, nuv = mp.mpf(twist_angle), mp.mpf(nu)

        def f(p):
            return determinant(family, mp.pi**2 * p, om, nuv)

        for e in euler_loads(family, nu, top):
            a, b = mp.mpf(max(e - step, SCAN_START)), mp.mpf(e + step)
            da, db = mp.diff(f, a), mp.diff(f, b)
            if not da * db < 0:
                continue
            x = bracketed_root_mp(lambda p: mp.diff(f, p), a, b)
            d0 = f(x)
            if not d0 * f(a) < 0:
                continue
            r = bracketed_root_mp(f, _pair_bracket(f, a, x, d0), x)
            if r > top:
                continue
            with mp.workdps(dps):
                r = +r
                lam = mp.pi**2 * r
                return CharacteristicRoot(r, family, *characteristic_roots(
                    lam, lam / mp.mpf(nu), mp.mpf(twist_angle), sqrt=mp.sqrt))
    return None


def _float_determinant(family: str, om: float, nu: float, p: float) -> float:
    """D_sym or D_anti at p in Python floats (the refinement of a few brackets)."""
    return determinant(family, math.pi**2 * p, om, nu, lib=math)


def _float_function(family: str, om: float, nu: float) -> Any:
    """p -> D_sym or D_anti in Python floats: the phase form from |Omega| >=
    BRACKET_MIN_TWIST (as the batched refinement), :func:`determinant` below it."""
    if om >= BRACKET_MIN_TWIST:  # roots below p = 4 there: X_- > 0 in their brackets
        hc, hs = math.cos(0.5 * om), math.sin(0.5 * om)
        return lambda p: _phase_determinant(family == "symmetric", p, om, nu, hc, hs, math)
    return partial(_float_determinant, family, om, nu)


def characteristic_double(twist_angle: float, nu: float) -> tuple[float, str]:
    """Lowest root p* of the two determinants in double precision, and its family (one point
    of :func:`characteristic_double_batch`; from |Omega(L)| >= :data:`BRACKET_MIN_TWIST` the
    same certified bracket in Python floats, :func:`_bracketed_point`).

    >>> p, family = characteristic_double(100.0, 1.5)
    >>> round(p, 6), family
    (1.199987, 'symmetric')
    """
    om, nv = abs(float(twist_angle)), float(nu)
    found = None
    if om >= BRACKET_MIN_TWIST and nv > 1.0:
        found = _bracketed_point(om, nv)
    elif 1.0 < nv <= FAMILY_BOUND_MAX_NU:
        found = _family_bound_point(om, nv)
    elif nv == 1.0:
        found = 1.0, FAMILIES[0]
    if found is not None:
        return found
    p, fam = characteristic_double_batch(np.array([om]), np.array([nv]))
    return float(p[0]), FAMILIES[int(fam[0])]


# --- the large-twist bracket ----------------------------------------------------------------
#
# From |Omega(L)| >= BRACKET_MIN_TWIST each family's lowest root is bracketed by its large-twist
# expansion (spectral_rod.rod.closed_form.family_expansions, remainder O(Omega^-5)) instead of being
# found by the sign scan. The certificate that the two roots found are the two lowest
# eigenvalues: the lab-frame Rayleigh quotient of Eq. inst1 (spectral_rod.rod.increment) is
# [int |z''|^2 + (nu - 1) int omega2^2] / int |z'|^2 >= int |z''|^2 / int |z'|^2, whose
# eigenvalues are k^2 pi^2, each twice (x1 and x2); by min-max the third eigenvalue of Eq.
# inst1 is >= 4 pi^2, so at most two eigenvalues (with multiplicity) lie below p = 4. A sign
# change of D_sym and one of D_anti, both in brackets below p = CERTIFICATE_LOAD = 4, are two
# eigenvalues there: each is its family's only one below 4, hence its lowest, and p* is the
# smaller. A point whose brackets do not both change sign is handed to the sign scan.

#: |Omega(L)| from which the lowest root is bracketed by the large-twist expansion.
BRACKET_MIN_TWIST = 50.0
#: The bracket's half-width is BRACKET_REMAINDER / Omega^5 (the expansion's remainder: measured
#: <= 77 Omega^-5 on 4,000 random points, Omega(L) log-uniform in [20, 1e4], nu in [1, 1e4],
#: where it exceeds the scan's rounding, Omega(L) < 1e3; tests/bench/large_twist_bracket.py)
#: plus BRACKET_NOISE eps (8 + |Omega|) (so that the sign at the bracket's ends is decided by
#: the root, not by rounding).
BRACKET_REMAINDER, BRACKET_NOISE = 400.0, 64.0
#: Below this load the lab-frame comparison problem has only two eigenvalues (see above).
CERTIFICATE_LOAD = 4.0


def _half_width(om: Any) -> Any:
    """The bracket's half-width in p at |Omega| = om (floats or arrays)."""
    return BRACKET_REMAINDER / om**5 + BRACKET_NOISE * _EPS * (8.0 + om)


def _phase_terms(p: Any, om: Any, nv: Any, half_cos: Any, half_sin: Any, lib: Any
                 ) -> tuple[Any, ...]:
    """(C_-, S_-, C_+, S_+, lambda, mu, Omega^2, X_-, X_+) at lambda = pi^2 p for X_-, X_+ > 0
    (here: Omega^2 > lambda), the phases sqrt(X)/2 = Omega/2 + r/2 with r = sqrt(X) - Omega
    computed as (X - Omega^2)/(sqrt(X) + Omega) and cos, sin of Omega/2 + r/2 by the addition
    theorem from the exact half_cos = cos(Omega/2), half_sin = sin(Omega/2): a phase of size
    Omega is never rounded, which is the eps |Omega| error of :func:`determinants` there.
    X - Omega^2 from :func:`spectral_rod.rod.wavenumbers.root_offsets`, without cancellation at
    large twist. numpy arrays (lib=np) or Python floats (lib=math)."""
    lam = math.pi**2 * p
    mu = lam / nv
    q = om * om
    u_minus, u_plus = root_offsets(lam, mu, om, sqrt=lib.sqrt)
    out = []
    for u in (u_minus, u_plus):
        beta = lib.sqrt(q + u)
        half_r = 0.5 * u / (beta + om)
        cr, sr = lib.cos(half_r), lib.sin(half_r)
        out += [half_cos * cr - half_sin * sr, (half_sin * cr + half_cos * sr) / beta]
    return (*out, lam, mu, q, q + u_minus, q + u_plus)


def _phase_determinant(sym: Any, p: Any, om: Any, nv: Any, half_cos: Any, half_sin: Any,
                       lib: Any) -> Any:
    """D_sym where `sym`, else D_anti (:func:`combine_determinant`) from :func:`_phase_terms`."""
    cm, sm, cp, sp, lam, mu, q, xm, xp = _phase_terms(p, om, nv, half_cos, half_sin, lib)
    d_sym = cp * sm * (lam - q - xm) - cm * sp * (lam - q - xp)
    d_anti = (mu - q - xp) * sp * cm - (mu - q - xm) * sm * cp
    if lib is math:
        return d_sym if sym else d_anti
    return np.where(sym, d_sym, d_anti)


#: Up to this nu every family's lowest root is bracketed by the family bounds [1, nu]
#: (:func:`_family_bound_batch`) instead of being found by the sign scan.
FAMILY_BOUND_MAX_NU = 1.0 + 1.0e-3


def _family_bound_batch(om: NDArray[np.float64], nv: NDArray[np.float64]
                        ) -> tuple[NDArray[np.float64], NDArray[np.int_], NDArray[np.bool_]]:
    """(p*, family index, certified) at flat arrays of points with 1 < nu <= FAMILY_BOUND_MAX_NU
    (any twist): each family's lowest root lies in [1, nu] (:func:`family_critical_load`: the
    planar trial mode of each family has quotient <= nu) and is its only root below p = 4 (two
    eigenvalues at most lie below 4, see CERTIFICATE_LOAD), so the brackets [SCAN_START,
    nu + SCAN_MARGIN] hold exactly one root each. Both are refined together
    (:func:`~spectral_rod.numerics.sign_scan.bracketed_roots` on :func:`determinants`); certified
    False
    where the computed determinant shows no sign change over a bracket (the caller scans)."""
    n = om.size
    both_om, both_nu = np.concatenate([om, om]), np.concatenate([nv, nv])
    sym = np.repeat([True, False], n)

    def f(j, x):
        d_sym, d_anti = _determinants(x, both_om[j], both_nu[j], np.float64, False)
        return np.where(sym[j], d_sym, d_anti)

    a, b = np.full(2 * n, SCAN_START), both_nu + SCAN_MARGIN
    idx = np.arange(2 * n)
    ok = f(idx, a) * f(idx, b) <= 0
    ok = ok[:n] & ok[n:]
    live = np.flatnonzero(np.concatenate([ok, ok]))
    roots = np.full(2 * n, np.nan)
    roots[live] = _refine_brackets(f, live, a, b)
    fam = (roots[n:] < roots[:n]).astype(int)
    return np.where(fam == 1, roots[n:], roots[:n]), fam, ok


def _family_bound_point(om: float, nv: float) -> tuple[float, str] | None:
    """:func:`_family_bound_batch` for one point in Python floats (the scalar path): (p*,
    family), or None where a bracket shows no sign change."""
    roots = []
    for family in FAMILIES:
        f = _float_function(family, om, nv)
        a, b = SCAN_START, nv + SCAN_MARGIN
        if f(a) * f(b) > 0:
            return None
        roots.append(bracketed_root(f, a, b))
    k = int(roots[1] < roots[0])
    return roots[k], FAMILIES[k]


def _bracketed_batch(om: NDArray[np.float64], nv: NDArray[np.float64]
                     ) -> tuple[NDArray[np.float64], NDArray[np.int_], NDArray[np.bool_]]:
    """(p*, family index, certified) at flat arrays of points with |Omega| >= BRACKET_MIN_TWIST
    and nu > 1: both families' roots in their asymptotic brackets, refined together
    (:func:`~spectral_rod.numerics.sign_scan.bracketed_roots`); certified False where a bracket
    shows no
    sign change (the caller scans those points)."""
    from spectral_rod.rod.closed_form import family_expansions

    n = om.size
    both_om, both_nu = np.concatenate([om, om]), np.concatenate([nv, nv])
    sym = np.repeat([True, False], n)
    half = 0.5 * both_om
    hc, hs = np.cos(half), np.sin(half)
    centre = np.concatenate(family_expansions(om, nv))
    w = _half_width(both_om)
    a, b = centre - w, np.minimum(centre + w, CERTIFICATE_LOAD)

    def f(j, x):
        return _phase_determinant(sym[j], x, both_om[j], both_nu[j], hc[j], hs[j], np)

    fa, fb = f(np.arange(2 * n), a), f(np.arange(2 * n), b)
    ok = fa * fb <= 0
    ok = ok[:n] & ok[n:]
    # each point's lower bracket first; the other family's root only where its bracket reaches
    # below the first root (:func:`_bracketed_point` does the same)
    fam = (a[n:] < a[:n]).astype(int)
    first = np.flatnonzero(ok) + n * fam[ok]
    p = np.full(n, np.nan)
    p[ok] = _refine_brackets(f, first, a, b)
    other = first + np.where(first < n, n, -n)
    need = a[other] < p[ok]
    if need.any():
        second, where = other[need], np.flatnonzero(ok)[need]
        q = _refine_brackets(f, second, a, b)
        lower = q < p[where]
        p[where[lower]], fam[where[lower]] = q[lower], 1 - fam[where[lower]]
    return p, fam, ok


def _refine_brackets(f: Any, idx: NDArray[np.int_], a: NDArray[np.float64],
                     b: NDArray[np.float64]) -> NDArray[np.float64]:
    """The roots of the functions f(idx[j], .) in [a[idx], b[idx]] (all at once)."""
    if not idx.size:
        return np.empty(0)
    return bracketed_roots(lambda j, x: f(idx[j], x), a[idx], b[idx])


def _bracketed_point(om: float, nv: float) -> tuple[float, str] | None:
    """:func:`_bracketed_batch` for one point in Python floats (the scalar path): (p*, family),
    or None where the certificate fails."""
    from spectral_rod.rod.closed_form import family_expansions

    hc, hs = math.cos(0.5 * om), math.sin(0.5 * om)
    w = _half_width(om)
    brackets = []
    for sym, centre in zip((True, False), family_expansions(om, nv), strict=True):
        def f(x: float, sym: bool = sym) -> float:
            return _phase_determinant(sym, x, om, nv, hc, hs, math)

        a, b = centre - w, min(centre + w, CERTIFICATE_LOAD)
        if f(a) * f(b) > 0:
            return None
        brackets.append((a, b, f))
    # the family of the lower bracket first; the other's root is needed only if its bracket
    # reaches below the first root (both are certified by their sign changes above)
    k = int(brackets[1][0] < brackets[0][0])
    a, b, f = brackets[k]
    best = bracketed_root(f, a, b)
    a, b, f = brackets[1 - k]
    if a < best:
        other = bracketed_root(f, a, b)
        if other < best:
            return other, FAMILIES[1 - k]
    return best, FAMILIES[k]


def _double_scan(om: NDArray[np.float64], nv: NDArray[np.float64], top: NDArray[np.float64],
                 family: NDArray[np.int_] | None = None
                 ) -> tuple[NDArray[np.float64], NDArray[np.int_]]:
    """:func:`~spectral_rod.numerics.sign_scan.lowest_roots` of (D_sym, D_anti) at the points (om,
    nv),
    from :data:`SCAN_START` to `top` in steps :data:`DOUBLE_SCAN_STEP`, brackets refined by
    :func:`~spectral_rod.numerics.sign_scan.bracketed_roots`: the lowest root of either family and
    its
    index, or (`family` given) the lowest root of family[j] alone at point j (index 0 where
    found, -1 where not)."""
    def values(points, grid):
        d = np.stack(_determinants(grid, om[points, None], nv[points, None], np.float64, False),
                     axis=1)
        return d if family is None else d[np.arange(points.size), family[points]][:, None]

    def refine(points, k, a, b):
        fam = k if family is None else family[points]

        if points.size <= FEW_POINTS:  # in Python floats, one bracket at a time
            return np.array([bracketed_root(_float_function(FAMILIES[fam[j]], float(om[i]),
                                                            float(nv[i])),
                                            float(a[j]), float(b[j]))
                             for j, i in enumerate(points.tolist())])
        # from BRACKET_MIN_TWIST on in the phase form (its roots lie below p = 2 there, where
        # Omega^2 > lambda as _phase_terms needs): the same eps-level accuracy as the bracket
        om_p, nv_p = om[points], nv[points]
        phase = (om_p >= BRACKET_MIN_TWIST) & (np.pi**2 * b < 0.5 * om_p**2)  # X_- > 0 there
        hc, hs = np.cos(0.5 * om_p), np.sin(0.5 * om_p)

        def f(j, x):
            d = _determinants(x, om_p[j], nv_p[j], np.float64, False)
            direct = np.where(fam[j] == 0, d[0], d[1])
            if not phase[j].any():
                return direct
            with np.errstate(invalid="ignore"):  # X_- < 0 where phase is False
                ph = _phase_determinant(fam[j] == 0, x, om_p[j], nv_p[j], hc[j], hs[j], np)
            return np.where(phase[j], ph, direct)
        return bracketed_roots(f, a, b)

    return lowest_roots(values, refine, np.full(om.size, SCAN_START), top,
                        np.full(om.size, DOUBLE_SCAN_STEP),
                        chunk=DOUBLE_CHUNK if om.size > FEW_POINTS else ONE_POINT_CHUNK)


def _certified(batch: Callable[[NDArray[np.float64], NDArray[np.float64]],
                                tuple[NDArray[np.float64], NDArray[np.int_], NDArray[np.bool_]]],
               point: Callable[[float, float], tuple[float, str] | None],
               om: NDArray[np.float64], nv: NDArray[np.float64]
               ) -> tuple[NDArray[np.float64], NDArray[np.int_], NDArray[np.bool_]]:
    """(p*, family index, certified) at flat arrays of points by a certified bracket: `batch`
    on arrays, or up to :data:`FEW_BRACKETS` points `point` one point at a time in Python floats
    (the same brackets and refinement; where `point` finds none, p* is nan and certified
    False)."""
    if om.size > FEW_BRACKETS:
        return batch(om, nv)
    found = [point(a, b) for a, b in zip(om.tolist(), nv.tolist(), strict=True)]
    p = np.array([math.nan if f is None else f[0] for f in found])
    fam = np.array([-1 if f is None else FAMILIES.index(f[1]) for f in found], dtype=int)
    return p, fam, fam >= 0


def characteristic_double_batch(twist: NDArray[np.float64], nu: NDArray[np.float64]
                                ) -> tuple[NDArray[np.float64], NDArray[np.int_]]:
    """Lowest root p* of the two determinants in double precision, and its family index (0
    symmetric), at flat arrays of points (|Omega|, nu), all points at once.

    The certified brackets of the module docstring where they apply (|Omega(L)| >=
    :data:`BRACKET_MIN_TWIST`: the large-twist expansion; 1 < nu <= :data:`FAMILY_BOUND_MAX_NU`:
    the family bounds), p* = 1 exactly at nu = 1, and elsewhere (or where a bracket shows no
    sign change) one sign scan per point (steps :data:`DOUBLE_SCAN_STEP` from
    :data:`SCAN_START`, up to (1 + nu)/2, :data:`DOUBLE_CHUNK` grid points at a time for every
    point still scanning) brackets the first sign change of either family. The brackets of all
    points are refined together (:func:`spectral_rod.numerics.sign_scan.bracketed_roots`, to 4 eps
    relative like Brent's method). Raises RootNotFoundError if a point has no root.
    """
    om, nv = np.abs(np.asarray(twist, dtype=float)), np.asarray(nu, dtype=float)
    top = (1.0 + nv) / 2.0 + SCAN_MARGIN
    p, fam = np.empty(om.size), np.empty(om.size, dtype=int)
    scan = np.ones(om.size, dtype=bool)
    large = np.flatnonzero((om >= BRACKET_MIN_TWIST) & (nv > 1.0))
    if large.size:
        p[large], fam[large], ok = _certified(_bracketed_batch, _bracketed_point, om[large],
                                              nv[large])
        scan[large[ok]] = False
    isotropic = np.flatnonzero(nv == 1.0)  # the Euler load, exact (as the mpmath reference)
    p[isotropic], fam[isotropic], scan[isotropic] = 1.0, 0, False
    near = np.flatnonzero((om < BRACKET_MIN_TWIST) & (nv > 1.0) & (nv <= FAMILY_BOUND_MAX_NU))
    if near.size:
        p[near], fam[near], ok = _certified(_family_bound_batch, _family_bound_point, om[near],
                                            nv[near])
        scan[near[ok]] = False
    scan = np.flatnonzero(scan)
    if scan.size:
        p[scan], fam[scan] = _double_scan(om[scan], nv[scan], top[scan])
    if (fam < 0).any():
        i = int(np.flatnonzero(fam < 0)[0])
        raise RootNotFoundError(f"no root of the characteristic equation for p* in "
                                f"[1, {top[i]:g}] (twist_angle={om[i]}, nu={nv[i]})")
    return p, fam


def family_double_batch(twist: NDArray[np.float64], nu: NDArray[np.float64]
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Lowest root of each family, (p_sym, p_anti), in double precision at flat arrays of points
    (|Omega|, nu), all points and both families in one scan (:func:`characteristic_double_batch`
    per family; min(p_sym, p_anti) = p*).

    Each family is scanned up to its bound nu (:func:`family_critical_load`); NaN where a family
    has no root below it. Intended for Omega != 0 and nu > 1 (where the Euler loads are not
    repeated roots).

    >>> p_sym, p_anti = family_double_batch(np.array([0.5]), np.array([1.5]))
    >>> round(float(p_sym[0]), 7), round(float(p_anti[0]), 4)
    (1.0024446, 1.4928)
    """
    om, nv = np.abs(np.asarray(twist, dtype=float)), np.asarray(nu, dtype=float)
    n = om.size
    both_om, both_nu = np.concatenate([om, om]), np.concatenate([nv, nv])
    p, found = _double_scan(both_om, both_nu, both_nu + SCAN_MARGIN, np.repeat([0, 1], n))
    p = np.where(found >= 0, p, np.nan)
    return p[:n], p[n:]


#: Relative error estimate of :func:`characteristic_double` from |Omega(L)| >=
#: BRACKET_MIN_TWIST, in units of eps: the phase form's roots measured <= 2 eps against 40-digit
#: references (tests/bench/hunt_routes.py, module docstring).
PHASE_ERROR = 16.0


#: The constant of the estimate eps (DIRECT_ERROR + |Omega|) below BRACKET_MIN_TWIST: errors of
#: up to 7 eps occur at small twist near nu = 1 (Omega(L) < 0.2, nu - 1 <= 1e-3); with it the
#: largest error / estimate of tests/bench/hunt_routes.py is 0.25 (characteristic) and 0.31
#: (near-degenerate) on 1,000 random points each.
DIRECT_ERROR = 32.0


def double_error_estimate(twist_angle: ArrayLike) -> NDArray[np.float64]:
    """Relative error estimate of :func:`characteristic_double` (empirical, module docstring):
    eps (DIRECT_ERROR + |Omega|) below :data:`BRACKET_MIN_TWIST` (the phases of size Omega are
    rounded: measured <= 0.58 eps |Omega|), :data:`PHASE_ERROR` eps from it on (the phase
    form)."""
    om = np.abs(np.asarray(twist_angle, dtype=float))
    return np.where(om >= BRACKET_MIN_TWIST, PHASE_ERROR * _EPS, _EPS * (DIRECT_ERROR + om))


def characteristic_determinant(family: str, p_star: float, twist_angle: float, nu: float,
                               dps: int = 30) -> float:
    """D_sym or D_anti at the load p* (lambda = pi^2 p*), evaluated at ``dps`` digits.

    Returns
    -------
    float
        The determinant's value (its zeros in p* are the family's buckling loads).

    Examples
    --------
    >>> abs(characteristic_determinant("symmetric", 1.0, 0.0, 1.5)) < 1e-25  # Euler's load
    True
    """
    import mpmath as mp

    check_family(family)
    p_star = check_real(p_star, "p_star", 0.0, 1e8, lo_open=True)
    om, nu = abs(scalar_twist(twist_angle, max_abs=1e6)), scalar_nu(nu, max_value=1e8)
    with mp.workdps(check_int(dps, "dps", *DPS_RANGE)):
        return float(determinant(family, mp.pi**2 * mp.mpf(p_star), mp.mpf(om), mp.mpf(nu)))
