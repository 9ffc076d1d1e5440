r"""Where the two mode families cross: the maxima of p*(Omega(L)) (paper, section "Stability of a
rectilinear rod", Eq. ``inst1``; "additional maxima at integer multiples of pi").

p* is the smaller of the two families' lowest loads, so where they cross p* has a corner. Two
independent finders:

* :func:`family_crossing` -- D_sym(pi^2 p, Omega) = D_anti(pi^2 p, Omega) = 0 by 2-D Newton in
  mpmath (the characteristic equation, :mod:`spectral_rod.rod.characteristic`), verified lowest in
  each family by the sign scans; with :func:`family_slope`, dp/dOmega along each family;
* :func:`collocation_crossing` -- Brent's method on the difference of the two families' lowest
  collocation eigenvalues (:mod:`spectral_rod.rod.collocation`), slopes by central differences.

The closed form of the crossings (beta_1 L = (n - 1) pi, beta_2 L = (n + 1) pi exactly) is
:func:`spectral_rod.rod.closed_form.crossing_closed_form`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath as mp

from spectral_rod._validation import TOL_RANGE, check_int, check_real, scalar_nu
from spectral_rod.errors import RootNotFoundError
from spectral_rod.rod.characteristic import (
    DPS_RANGE,
    characteristic_critical_load,
    determinant,
    family_critical_load,
)
from spectral_rod.rod.families import FAMILIES
from spectral_rod.rod.wavenumbers import characteristic_roots

__all__ = ["CollocationCrossing", "CrossingWavenumbers", "FamilyCrossing", "collocation_crossing",
           "crossing_wavenumbers", "family_crossing", "family_slope"]


def family_slope(family: str, p: mp.mpf, twist_angle: mp.mpf, nu: mp.mpf) -> mp.mpf:
    """dp/dOmega(L) along the family's root curve D(pi^2 p, Omega) = 0 (implicit function rule)."""
    d_om = mp.diff(lambda w: determinant(family, mp.pi**2 * p, w, nu), twist_angle)
    d_p = mp.diff(lambda q: determinant(family, mp.pi**2 * q, twist_angle, nu), p)
    return -d_om / d_p


@dataclass(frozen=True)
class FamilyCrossing:
    """A twist at which the lowest symmetric and antisymmetric roots coincide.

    twist: Omega(L) at the crossing; p_star: the common (and lowest) root there; slopes:
    dp/dOmega of each family's root curve; left/right: the family that is critical just below /
    above the crossing; kind: 'corner maximum' when p* rises into the crossing and falls out of it
    (p* = min of two smooth branches has a concave corner there, not a smooth maximum), else
    'corner' (a kink on a monotone stretch); nu: the nu it was computed at.

    Examples
    --------
    >>> import math, spectral_rod as sr
    >>> c = sr.family_crossing(2 * math.pi, 1.5)
    >>> c.left, c.right   # symmetric below, antisymmetric above the crossing
    ('symmetric', 'antisymmetric')
    """

    twist: mp.mpf
    p_star: mp.mpf
    slopes: dict[str, mp.mpf]
    left: str
    right: str
    kind: str
    nu: float | None = None


def _check_on_lowest_branches(p_c: mp.mpf, om_c: mp.mpf, nu: float, dps: int,
                              twist_guess: float) -> None:
    """Both families' sign scans must return p_c as their *lowest* root (else RuntimeError)."""
    tol = mp.mpf(10) ** (-(dps - 8))
    for fam in FAMILIES:
        low = family_critical_load(fam, float(om_c), nu, dps=dps).p_star
        # the scan works at the float-rounded twist: allow for that rounding
        slope_scale = 1 + abs(family_slope(fam, p_c, om_c, mp.mpf(nu)))
        if abs(low - p_c) > tol + slope_scale * abs(om_c) * mp.mpf(2) ** -52:
            raise RootNotFoundError(f"crossing near Omega={twist_guess} (nu={nu}) is not on the "
                               f"lowest {fam} branch: {low} vs {p_c}")


def family_crossing(twist_guess: float, nu: float, *, p_guess: float | None = None,
                    dps: int = 30) -> FamilyCrossing:
    """Solve D_sym(pi^2 p, Omega) = D_anti(pi^2 p, Omega) = 0 for (Omega, p) by 2-D Newton.

    The start is (twist_guess, p*(twist_guess)) from :func:`characteristic_critical_load` unless
    ``p_guess`` is given. The result is verified independently: the sign scan of each family
    must return the crossing load as that family's *lowest* root, so the crossing lies on the
    critical curve p*(Omega). Raises RuntimeError otherwise.

    Returns
    -------
    FamilyCrossing
        The crossing twist and load, the slopes of both branches, the families critical on
        either side, its kind and nu.

    Examples
    --------
    >>> import math
    >>> c = family_crossing(2 * math.pi, 1.5)
    >>> c.kind
    'corner maximum'
    >>> import spectral_rod as sr   # the closed form
    >>> abs(float(c.twist) - sr.crossing_closed_form(2, 1.5).twist) < 1e-12
    True
    """
    twist_guess = check_real(twist_guess, "twist_guess", 0.0, 1.0e3, lo_open=True)
    nu, dps = scalar_nu(nu), check_int(dps, "dps", *DPS_RANGE)
    if p_guess is not None:
        p_guess = check_real(p_guess, "p_guess", 1.0, (1.0 + nu) / 2.0)
    with mp.workdps(dps):
        nuv = mp.mpf(nu)
        if p_guess is None:
            p_guess = characteristic_critical_load(twist_guess, nu, dps=dps).p_star

        def system(p: mp.mpf, om: mp.mpf) -> list[mp.mpf]:
            return [determinant(f, mp.pi**2 * p, om, nuv) for f in FAMILIES]

        try:
            p_c, om_c = mp.findroot(system, (mp.mpf(p_guess), mp.mpf(twist_guess)))
        except (ValueError, ZeroDivisionError, TypeError) as exc:
            # mpmath: "Could not find root within given tolerance", a singular Jacobian
            # ("matrix is numerically singular", e.g. at nu = 1, where p* = 1 at every twist),
            # or Newton iterates that left the real axis (the determinant compares a complex
            # X: "no ordering relation is defined for complex numbers", e.g. from pi at
            # nu = 1e4, where there is no crossing)
            raise RootNotFoundError(f"no family crossing found from twist_guess={twist_guess}, "
                                    f"nu={nu} ({exc})") from None
        _check_on_lowest_branches(p_c, om_c, nu, dps, twist_guess)
        slopes = {f: family_slope(f, p_c, om_c, nuv) for f in FAMILIES}
        left = max(slopes, key=lambda f: slopes[f])   # steeper rise => lower just to the left
        right = min(slopes, key=lambda f: slopes[f])
        kind = "corner maximum" if slopes[left] > 0 > slopes[right] else "corner"
        return FamilyCrossing(om_c, p_c, slopes, left, right, kind, nu)


@dataclass(frozen=True)
class CollocationCrossing:
    """A family crossing located by collocation: twist, p* there, slopes per family, degree,
    and the estimated absolute errors of twist and p_star (:func:`collocation_crossing`).

    Examples
    --------
    >>> import math, spectral_rod as sr
    >>> c = sr.collocation_crossing(2 * math.pi, 1.5)
    >>> abs(c.twist - sr.crossing_closed_form(2, 1.5).twist) <= max(c.twist_error, 1e-9)
    True
    """

    twist: float
    p_star: float
    slopes: dict[str, float]
    n: int
    twist_error: float
    p_error: float


def collocation_crossing(twist_guess: float, nu: float, half_width: float = 0.15
                         ) -> CollocationCrossing:
    """Twist where the two families' lowest collocation eigenvalues meet (Brent's method) in
    [twist_guess - half_width, twist_guess + half_width]; slopes dp/dOmega by central
    differences (h = 1e-5).

    The twist is ill-conditioned where the two branches cross at nearly the same slope (nu -> 1):
    an error e p in each family's load moves it by 2 e p / |slope difference|. ``twist_error``
    is that, with e the collocation round-off floor at the crossing
    (:func:`spectral_rod.rod.collocation.resolution.roundoff_floor`; the degree resolves the modes
    to the tightest tol) and the slope difference bounded below by :func:`_slope_gap` (inf
    where that is not resolved); ``p_error`` is e p plus the symmetric slope times
    ``twist_error``. Measured
    against the closed form (:func:`spectral_rod.crossing_closed_form`) on 400 random crossings
    (n pi, n = 2..59, nu = 1 + 1e-6 .. 1e3): twist_error inf for 76, all with
    nu - 1 < 7e-4 (their twist errors up to 3.0e-7 relative); elsewhere every error below its
    estimate (at most 0.18 of twist_error and 0.25 of p_error; median ~1e-4 and 0.05: the
    round-off floor is a worst case).

    Returns
    -------
    CollocationCrossing
        The crossing twist, p* there, each family's slope, the degree and the estimated
        absolute errors ``twist_error`` and ``p_error``.

    Examples
    --------
    >>> c = collocation_crossing(2 * math.pi, 1.5)
    >>> abs(c.twist - 6.285782609677) < max(c.twist_error, 1e-12)
    True
    """
    from scipy.optimize import brentq

    from spectral_rod.rod.collocation import collocation_family_load
    from spectral_rod.rod.collocation.arithmetic import FLOATS
    from spectral_rod.rod.collocation.resolution import initial_degree, roundoff_floor

    half_width = check_real(half_width, "half_width", 0.0, 1.0, lo_open=True)
    twist_guess = check_real(twist_guess, "twist_guess", half_width, 200.0, lo_open=True)
    nu = scalar_nu(nu)
    # one fixed degree for the whole root search (a smooth difference for Brent): the a priori
    # degree of the collocation solver at its tightest tolerance, at the bracket's far end
    n = initial_degree(twist_guess + half_width, TOL_RANGE[0], FLOATS)

    def diff(om: float) -> float:
        return (collocation_family_load(om, nu, FAMILIES[0], n)
                - collocation_family_load(om, nu, FAMILIES[1], n))

    a, b = twist_guess - half_width, twist_guess + half_width
    if diff(a) * diff(b) > 0:
        raise RootNotFoundError(f"the two families do not cross in [{a:g}, {b:g}] (nu={nu})")
    om_c = brentq(diff, a, b, xtol=1e-14, rtol=1e-15)
    h = 1e-5
    slopes = {f: (collocation_family_load(om_c + h, nu, f, n)
                  - collocation_family_load(om_c - h, nu, f, n)) / (2 * h) for f in FAMILIES}
    p_c = collocation_family_load(om_c, nu, FAMILIES[0], n)
    load_error = float(roundoff_floor(om_c)) * p_c
    gap = _slope_gap(diff, om_c, load_error)
    twist_error = 2 * load_error / gap if gap > 0 else math.inf
    # inf, not 0 * inf = nan, where the twist is not resolved and a slope rounds to 0
    p_error = (load_error + abs(slopes[FAMILIES[0]]) * twist_error if math.isfinite(twist_error)
               else math.inf)
    return CollocationCrossing(float(om_c), p_c, {k: float(v) for k, v in slopes.items()}, n,
                               twist_error, p_error)


#: Steps of the slope-difference estimate behind ``twist_error`` (:func:`_slope_gap`), and how
#: far the two may disagree: empirical (the difference of the two branches is smooth, and the
#: round-off of a difference quotient falls as 1/h).
GAP_STEPS, GAP_AGREEMENT = (1e-2, 5e-2), 0.25


def _slope_gap(diff, om_c: float, load_error: float) -> float:
    """A lower bound of |d(p_sym - p_anti)/dOmega| at the crossing: 1 - GAP_AGREEMENT times the
    central difference at GAP_STEPS[0], if that at GAP_STEPS[1] agrees to GAP_AGREEMENT and it
    is at least 4 times its own round-off (2 load_error / h); else 0 (not resolved)."""
    g = [abs(diff(om_c + h) - diff(om_c - h)) / (2 * h) for h in GAP_STEPS]
    noise = 2 * load_error / GAP_STEPS[0]
    if g[0] < 4 * noise or abs(g[0] - g[1]) > GAP_AGREEMENT * g[0]:
        return 0.0
    return (1 - GAP_AGREEMENT) * g[0]


@dataclass(frozen=True)
class CrossingWavenumbers:
    """The wavenumbers at a family crossing (computed at the crossing's working precision).

    beta1, beta2: beta_k L; difference: Re(beta2 - beta1) L; resonance_gap: max_k |beta_k L -
    (n -+ 1) pi| with n the nearest integer to (beta1 + beta2)/(2 pi) (0 up to the precision
    when the crossing theorem of :mod:`spectral_rod.rod.closed_form` holds); slopes: d(beta2 -
    beta1)/dOmega along each family's root curve.

    Examples
    --------
    >>> import math, spectral_rod as sr
    >>> w = sr.crossing_wavenumbers(sr.family_crossing(2 * math.pi, 1.5), 1.5)
    >>> float(w.resonance_gap) < 1e-12
    True
    """

    beta1: float
    beta2: float
    difference: float
    resonance_gap: float
    slopes: dict[str, float]


def _mp_difference(p: mp.mpf, om: mp.mpf, nu: mp.mpf) -> mp.mpf:
    lam = mp.pi**2 * p
    xm, xp = characteristic_roots(lam, lam / nu, om, sqrt=mp.sqrt)
    return mp.sqrt(xp) - (mp.sqrt(xm) if xm > 0 else 0)


def crossing_wavenumbers(crossing: FamilyCrossing, nu: float, dps: int = 30
                         ) -> CrossingWavenumbers:
    """beta_1 L, beta_2 L and beta_2 - beta_1 at a crossing, with the slopes of beta_2 - beta_1
    along both branches (chain rule with :attr:`FamilyCrossing.slopes`). ``nu`` must be the
    crossing's own (ValueError otherwise).

    Returns
    -------
    CrossingWavenumbers
        beta_1 L, beta_2 L, Re(beta_2 - beta_1) L, the gap to (n -+ 1) pi and the slopes of
        beta_2 - beta_1 along each branch.

    Examples
    --------
    >>> import math
    >>> c = family_crossing(2 * math.pi, 1.5)
    >>> w = crossing_wavenumbers(c, 1.5)
    >>> round(float(w.beta1) / math.pi, 9), round(float(w.beta2) / math.pi, 9)   # (n -+ 1) pi
    (1.0, 3.0)
    """
    if not isinstance(crossing, FamilyCrossing):
        raise TypeError(f"crossing must be a FamilyCrossing, got {type(crossing).__name__}")
    nu, dps = scalar_nu(nu), check_int(dps, "dps", *DPS_RANGE)
    if crossing.nu is not None and nu != crossing.nu:  # else numbers of a point that is none
        raise ValueError(f"nu={nu!r} is not the nu of the crossing ({crossing.nu!r})")
    with mp.workdps(dps):
        nuv, p, om = mp.mpf(nu), crossing.p_star, crossing.twist
        lam = mp.pi**2 * p
        xm, xp = characteristic_roots(lam, lam / nuv, om, sqrt=mp.sqrt)
        b1, b2 = mp.sqrt(xm), mp.sqrt(xp)
        n = int(mp.nint((b1 + b2) / (2 * mp.pi)))
        gap = max(abs(b1 - (n - 1) * mp.pi), abs(b2 - (n + 1) * mp.pi))
        d_om = mp.diff(lambda w: _mp_difference(p, w, nuv), om)
        d_p = mp.diff(lambda q: _mp_difference(q, om, nuv), p)
        slopes = {f: float(d_om + d_p * s) for f, s in crossing.slopes.items()}
        return CrossingWavenumbers(float(b1), float(b2), float(_mp_difference(p, om, nuv)),
                                   float(gap), slopes)
