r"""Closed forms for the straight rod: the large-twist limit of p*, its corrections, and the
window in which the wavenumber beta_1 is imaginary.

Normalisation as in the paper (section "Stability of a rectilinear rod", Eq. ``inst1``):
p* = P_cr / (pi^2 A1 / L^2), Omega = Omega(L) = omega30 L, nu = I2/I1 = A2/A1 >= 1, s in
units of L, lambda = pi^2 p* = P L^2 / A1, mu = lambda / nu.

Derivation of the large-twist limit (fixed-frame, complex form of Eq. ``inst1``)
--------------------------------------------------------------------------------
Let Z = x1 + i x2 be the centreline displacement in the fixed frame (e1, e2). For hinged ends
the bending moments are statically determined by the load, A1 omega1 = -P xi, A2 omega2 = -P eta
((xi, eta) = body-frame components of the displacement, see ``straight_rod``), and the paper's
geometric relations x'' = R(Omega s) omega rotate them back. With the compliance
diag(1/A1, 1/A2) = cbar I + delta diag(1, -1), cbar = (1 + 1/nu)/2, delta = (1 - 1/nu)/2 (A1 = 1),
and R diag(1, -1) R^T acting on Z as Z -> e^{2 i Omega s} conj(Z), Eq. ``inst1`` becomes

    Z'' + lambda cbar Z + lambda delta e^{2 i Omega s} conj(Z) = 0,     Z(0) = Z(1) = 0.   (A)

(A) is *exactly* solved by Z = Z0(s) + e^{2 i Omega s} W(s) with

    Z0'' + lambda cbar Z0 + lambda delta conj(W) = 0,
    W'' + 4 i Omega W' - 4 Omega^2 W + lambda cbar W + lambda delta conj(Z0) = 0,

a constant-coefficient system (its characteristic polynomial is the paper's). For Omega >> 1
the second line is solved by expansion in 1/Omega:

    W = (lambda delta / 4 Omega^2) [1 + i D/Omega + (lambda cbar - 3 D^2)/(4 Omega^2) + ...]
        conj(Z0),      D = d/ds,

and the slow field obeys Z0'' + kappa Z0 + O(Omega^-3) Z0' = 0 with
kappa = lambda cbar + e (1 + pi^2/Omega^2), e = (lambda delta)^2 / (4 Omega^2).

*Leading order:* lambda cbar = pi^2, i.e. the rod buckles like an untwisted rod whose bending
*compliance* is the average over the section's orientations, (1/A1 + 1/A2)/2 -- the moment is
fixed by statics, so compliances (not stiffnesses) average. Hence

    p_inf = 1 / cbar = 2 nu / (1 + nu)          (harmonic mean of A1 and A2, over A1).

Note p_inf < (1 + nu)/2 (the arithmetic mean, the Rayleigh upper bound) for nu > 1.

*Boundary correction:* the fast part does not vanish at the ends, so Z0(0) = -W(0) and
Z0(1) = -e^{2 i Omega} W(1), i.e. Z0(0) = -gamma conj(Z0'(0)), Z0(1) = -gamma e^{2 i Omega}
conj(Z0'(1)) with gamma = i lambda delta / (4 Omega^3). With Z0 = e^{i theta} sin(pi s) and
Green's identity against sin(pi s), the eigenvalue shift is real only for the two orientations
theta = Omega/2 (symmetric family: displacement at mid-span along u0) and theta = Omega/2 + pi/2
(antisymmetric), and kappa = pi^2 (1 +- lambda delta sin(Omega) / Omega^3) respectively. Collecting
(error O(Omega^-5)):

    p cbar + pi^2 p^2 delta^2 (1 + pi^2/Omega^2) / (4 Omega^2)
        = 1 -+ pi^2 p delta sin(Omega) / Omega^3

(upper sign antisymmetric), and by iteration, with p_inf = 1/cbar,

    p_family = p_inf + a2/Omega^2 + sigma b3 sin(Omega)/Omega^3 + a4/Omega^4 + O(Omega^-5),
    a2 = -pi^2 delta^2 p_inf^3 / 4,
    b3 = pi^2 delta p_inf^2,    sigma = +1 (symmetric), -1 (antisymmetric),
    a4 = -pi^4 delta^2 p_inf^3 / 4 + pi^4 delta^4 p_inf^5 / 8,

    p* = min over families = p_inf + a2/Omega^2 - b3 |sin Omega|/Omega^3 + a4/Omega^4 + ... .

So p* approaches the limit from below like Omega^-2, with a |sin Omega| ripple of relative size
O(1/Omega) whose corners (family crossings) sit at Omega ~ n pi. The wavenumbers follow from the
roots X = (Omega +- sqrt(a))^2 +- b^2/(4 Omega sqrt(a)) + ... (a = lambda cbar, b = lambda
delta) with sqrt(a) = pi - e/(2 pi) - (pi lambda delta/(2 Omega^3)) |sin Omega|: the Omega^-2
terms cancel and

    beta_{1,2} L = Omega -+ pi +- (pi b/(2 Omega^3)) |sin Omega| - b^2/(8 Omega^3) + O(Omega^-4),
    beta_2 - beta_1 = 2 pi - (pi b / Omega^3) |sin Omega| + O(Omega^-4).

The window with beta_1 imaginary
--------------------------------
beta_1^2 = X_- < 0 exactly when mu < Omega^2 < lambda (product of the roots (lambda -
Omega^2)(mu - Omega^2) < 0). At its ends X_- = 0 and the symmetric determinant (the critical
family for Omega < 2 pi) factorises:

* Omega^2 = lambda: X_+ = 3 lambda + mu and D_sym = (3 lambda + mu) sin(sqrt(X_+)/2)/sqrt(X_+),
  so the lowest root is sqrt(X_+) = 2 pi: p_b = 4 nu / (3 nu + 1), Omega_b = pi sqrt(p_b)
  = 2 pi sqrt(nu / (3 nu + 1));
* Omega^2 = mu: X_+ = lambda + 3 mu = 4 y^2 and D_sym = 0 becomes
  (nu - 1) y cos y + 4 sin y = 0, y in (pi/2, pi]; then Omega_a = 2 y / sqrt(nu + 3) and
  p_a = 4 nu y^2 / (pi^2 (nu + 3)).

For nu = 1 the window shrinks to the point Omega = pi; for nu > 1 it contains pi.

The maxima of p*: family crossings in closed form
------------------------------------------------
With C_k = cos(beta_k/2), S_k = sin(beta_k/2)/beta_k (beta_k = beta_k L), l_k = lambda - Omega^2
- X_k, m_k = mu - Omega^2 - X_k, the two determinants of :mod:`spectral_rod.rod.characteristic` are
D_sym = C_+ S_- l_- - C_- S_+ l_+ and D_anti = m_+ S_+ C_- - m_- S_- C_+. If both vanish, the
product of the two equalities gives C_+ C_- S_+ S_- (l_- m_+ - l_+ m_-) = 0, and
l_- m_+ - l_+ m_- = (X_+ - X_-)(mu - lambda) != 0 for nu > 1. A short case analysis (C_+ = 0
forces C_- = 0 unless l_+ = m_+ = 0, i.e. lambda = mu; likewise for S) leaves exactly

    crossing  <=>  C_+ = C_- = 0  or  S_+ = S_- = 0  <=>  beta_1 L, beta_2 L both odd or both
                                                          even (non-zero) multiples of pi.

So at every crossing beta_2 - beta_1 is a multiple of 2 pi; on the critical curve (checked by
the sign scans in the tests) the crossing near n pi has beta_1 L = (n - 1) pi and
beta_2 L = (n + 1) pi *exactly* -- the paper's "resonance" holds exactly at the maxima, with
Omega_n in place of n pi. Inserting X_-+ = (n -+ 1)^2 pi^2 in the sum and product of the roots,
X_+ + X_- = lambda + mu + 2 Omega^2 and X_+ X_- = (lambda - Omega^2)(mu - Omega^2), gives a
quadratic for w = Omega^2/pi^2 whose larger root is the crossing:

    w_n = [N (nu^2 + 6 nu + 1) + sqrt(N^2 (nu^2 - 1)^2 + M (nu + 1)^2 (3 nu + 1)(nu + 3))]
          / ((3 nu + 1)(nu + 3)),        N = n^2 + 1,  M = (n^2 - 1)^2,
    Omega_n = pi sqrt(w_n),   p*_n = 2 nu (N - w_n) / (nu + 1).

N - w_n -> 1 while both grow like n^2, so p*_n is evaluated without that difference: with
a = 2 N (nu + 1)^2 and R the square root, N - w_n = (a - R) / ((3 nu + 1)(nu + 3)) and
a^2 - R^2 = 4 n^2 (nu + 1)^2 (3 nu + 1)(nu + 3) (as 4 (nu+1)^2 - (nu-1)^2 = (3nu+1)(nu+3) and
N^2 - M = 4 n^2), so

    p*_n = 8 n^2 nu (nu + 1) / (2 N (nu + 1)^2 + R)      (a sum of positive terms).

(n = 1 reproduces Omega_b and p_b above: there beta_1 = 0 and beta_2 = 2 pi, but S_- = 1/2, so it
is not a crossing.) For large n, with sqrt(N^2 b^2 + M c) expanded in 1/n^2 (b^2 + (nu+1)^2
(3nu+1)(nu+3) = 4 (nu+1)^4),

    w_n = n^2 + (nu - 1)^2 / (4 (nu + 1)^2 n^2) + O(n^-4),
    Omega_n = n pi + pi (delta p_inf)^2 / (8 n^3) + O(n^-5),   delta p_inf = (nu-1)/(nu+1),
    p*_n = p_inf (1 - (delta p_inf)^2 / (4 n^2)) + O(n^-4)

(consistent with a2 above at sin(Omega) = 0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from spectral_rod._validation import check_choice, check_int, scalar_nu, scalar_twist

#: Smallest |Omega(L)| the large-twist expansions accept: they are series in 1/Omega, and below
#: 2 pi the ripple term b3/Omega^3 outgrows the leading ones (at Omega = 1 the four-term series
#: gives p < 0 for nu = 2; from 2 pi on it stays in (1, 2) for every nu in [1, 1e4], checked
#: by the fuzz suite).
EXPANSION_MIN_TWIST = 2.0 * math.pi
#: Largest n of the crossing closed forms (the range their tests cover; n^2 must stay far
#: below the float range).
CROSSING_MAX_N = 10_000


def _nu(nu: object) -> float:
    return scalar_nu(nu)


def _large_twist(twist_angle: object) -> float:
    om = abs(scalar_twist(twist_angle))
    if om < EXPANSION_MIN_TWIST:
        raise ValueError(f"twist_angle must satisfy 2 pi <= |twist_angle| <= 1e4 for the "
                         f"large-twist expansion (a series in 1/Omega), got {om!r}")
    return om

__all__ = [
    "BetaWindow",
    "CrossingClosedForm",
    "LargeTwistCoefficients",
    "crossing_closed_form",
    "crossing_twist_asymptotic",
    "family_expansions",
    "imaginary_beta1_window",
    "large_twist_coefficients",
    "large_twist_expansion",
    "large_twist_limit",
    "large_twist_wavenumbers",
]


def large_twist_limit(nu: float) -> float:
    """lim_{Omega -> inf} p* = 2 nu / (1 + nu): the harmonic mean of A1 and A2 over A1.

    Returns
    -------
    float
        2 nu/(1 + nu).

    Examples
    --------
    >>> large_twist_limit(3.0)
    1.5
    >>> import spectral_rod as sr
    >>> abs(sr.critical_load(1000.0, 3.0) - 1.5) < 1e-5   # Omega(L) = 1000: close to the limit
    True
    """
    nu = _nu(nu)
    return 2.0 * nu / (1.0 + nu)


@dataclass(frozen=True)
class LargeTwistCoefficients:
    """p_family = p_inf + a2/Omega^2 + sigma b3 sin(Omega)/Omega^3 + a4/Omega^4 + O(Omega^-5).

    Examples
    --------
    >>> import spectral_rod as sr
    >>> sr.large_twist_coefficients(1.0).p_inf   # nu = 1: p* = 1 at every twist
    1.0
    """

    p_inf: float
    a2: float
    b3: float
    a4: float


def large_twist_coefficients(nu: float) -> LargeTwistCoefficients:
    """The coefficients of the large-twist expansion (module docstring).

    Returns
    -------
    LargeTwistCoefficients
        p_inf, a2, b3 and a4 of the expansion.

    Examples
    --------
    >>> import math
    >>> c = large_twist_coefficients(1.5)
    >>> c.p_inf, math.isclose(c.a2, -c.p_inf * math.pi**2 * 0.5**2 / (4 * 2.5**2))
    (1.2, True)
    """
    return LargeTwistCoefficients(*_coefficients(_nu(nu)))


def _coefficients(nu: Any) -> tuple[Any, Any, Any, Any]:
    """(p_inf, a2, b3, a4) of the module docstring for nu >= 1: Python floats or numpy arrays
    (arithmetic only, no validation)."""
    p_inf = 2.0 * nu / (1.0 + nu)
    delta = 0.5 * (1.0 - 1.0 / nu)
    pi2 = math.pi**2
    a2 = -pi2 * delta**2 * p_inf**3 / 4.0
    b3 = pi2 * delta * p_inf**2
    a4 = -pi2**2 * delta**2 * p_inf**3 / 4.0 + pi2**2 * delta**4 * p_inf**5 / 8.0
    return p_inf, a2, b3, a4


def family_expansions(twist: Any, nu: Any) -> tuple[Any, Any]:
    """(p_sym, p_anti), both families' loads from the expansion to Omega^-4 (module docstring),
    for |Omega| >= :data:`EXPANSION_MIN_TWIST` and nu >= 1 given as Python floats or numpy arrays
    (no validation: the large-twist route's bracket, :mod:`spectral_rod.rod.characteristic`, calls
    it on validated points). Remainder O(Omega^-5): |p_family - expansion| Omega^5 <= 77 on
    4,000 random points (Omega(L) log-uniform in [20, 1e4], nu in [1, 1e4]; below 1e3, where it
    exceeds the scan's rounding), against the sign scan of the double-precision characteristic
    equation (tests/bench/large_twist_bracket.py).

    >>> [round(p, 9) for p in family_expansions(100.0, 1.5)]
    [1.199986946, 1.199989344]
    """
    om = abs(twist) if isinstance(twist, (float, int)) else np.abs(twist)
    p_inf, a2, b3, a4 = _coefficients(nu)
    sin = math.sin if isinstance(om, (float, int)) else np.sin
    even = p_inf + a2 / om**2 + a4 / om**4
    ripple = b3 * sin(om) / om**3
    return even + ripple, even - ripple


def large_twist_expansion(twist_angle: float, nu: float, *, order: int = 4,
                          family: str | None = None) -> float:
    """p* (or one family's lowest load) from the large-twist expansion up to Omega^-order.

    order: 0 (the limit), 2, 3 or 4; family: None for p* (the lower family, -b3 |sin Omega|),
    'symmetric' (+b3 sin Omega) or 'antisymmetric' (-b3 sin Omega). Error O(Omega^-(order+1))
    for order >= 2 (O(Omega^-2) for order 0). Meant for |Omega| >~ 10; refused below
    |Omega| = 2 pi (:data:`EXPANSION_MIN_TWIST`), where the series stops making sense.

    Returns
    -------
    float
        The expansion's p* (or the family's load).

    Examples
    --------
    >>> import spectral_rod as sr   # against the converged p*
    >>> abs(large_twist_expansion(200.0, 1.5) / sr.critical_load(200.0, 1.5) - 1) < 1e-9
    True
    """
    if isinstance(order, bool) or not isinstance(order, (int, np.integer)):
        raise TypeError(f"order must be an integer (0, 2, 3 or 4), got {type(order).__name__}")
    if order not in (0, 2, 3, 4):
        raise ValueError(f"order must be 0, 2, 3 or 4, got {order!r}")
    om = _large_twist(twist_angle)
    c = large_twist_coefficients(nu)
    if family is None:
        ripple = -abs(math.sin(om))
    elif check_choice(family, "family", ("symmetric", "antisymmetric")) == "symmetric":
        ripple = math.sin(om)
    else:
        ripple = -math.sin(om)
    p = c.p_inf
    if order >= 2:
        p += c.a2 / om**2
    if order >= 3:
        p += c.b3 * ripple / om**3
    if order >= 4:
        p += c.a4 / om**4
    return p


@dataclass(frozen=True)
class BetaWindow:
    """beta_1 is imaginary for omega_a < Omega(L) < omega_b; p* at the ends is p_a, p_b.

    Examples
    --------
    >>> w = imaginary_beta1_window(1.0)   # nu = 1: y = pi
    >>> round(w.y, 12) == round(math.pi, 12)
    True
    """

    omega_a: float
    omega_b: float
    p_a: float
    p_b: float
    y: float  # root of (nu - 1) y cos y + 4 sin y = 0 in (pi/2, pi]


def imaginary_beta1_window(nu: float) -> BetaWindow:
    """The twist window with beta_1^2 < 0 in closed form (module docstring).

    Omega_b = 2 pi sqrt(nu/(3 nu + 1)), p_b = 4 nu/(3 nu + 1); Omega_a = 2 y/sqrt(nu + 3),
    p_a = 4 nu y^2/(pi^2 (nu + 3)), y in (pi/2, pi] the root of (nu - 1) y cos y + 4 sin y = 0
    (y = pi at nu = 1). Valid while the symmetric family is critical at both ends (Omega < 2 pi),
    which the claims tests check for nu in [1, 10].

    Returns
    -------
    BetaWindow
        The window's ends omega_a < omega_b, p* there (p_a, p_b) and the root y.

    Examples
    --------
    >>> import math
    >>> w = imaginary_beta1_window(1.5)
    >>> w.omega_a < math.pi < w.omega_b
    True
    >>> import spectral_rod as sr   # beta_1^2 = X_- changes sign at omega_b
    >>> p = sr.critical_load(w.omega_b, 1.5)
    >>> abs(sr.critical_wavenumbers(p, w.omega_b, 1.5)[0]) < 1e-5
    True
    """
    nu = _nu(nu)
    if nu == 1.0:
        y = math.pi
    else:
        # f(y) = (nu - 1) y cos y + 4 sin y: f(pi/2) = 4 > 0, f(pi) = -(nu - 1) pi < 0
        lo, hi = 0.5 * math.pi, math.pi
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if (nu - 1.0) * mid * math.cos(mid) + 4.0 * math.sin(mid) > 0:
                lo = mid
            else:
                hi = mid
            if hi - lo <= 4e-16 * hi:
                break
        y = 0.5 * (lo + hi)
    p_b = 4.0 * nu / (3.0 * nu + 1.0)
    return BetaWindow(omega_a=2.0 * y / math.sqrt(nu + 3.0),
                      omega_b=2.0 * math.pi * math.sqrt(nu / (3.0 * nu + 1.0)),
                      p_a=4.0 * nu * y**2 / (math.pi**2 * (nu + 3.0)), p_b=p_b, y=y)


def large_twist_wavenumbers(twist_angle: float, nu: float) -> tuple[float, float]:
    """(beta_1 L, beta_2 L) on the critical curve to O(Omega^-3) (error O(Omega^-4)).

    Returns
    -------
    tuple of two float
        (beta_1 L, beta_2 L).

    Examples
    --------
    >>> import math
    >>> b1, b2 = large_twist_wavenumbers(1000.0, 1.5)
    >>> abs(b1 - (1000.0 - math.pi)) < 1e-4, abs(b2 - (1000.0 + math.pi)) < 1e-4   # Omega -+ pi
    (True, True)
    """
    om = _large_twist(twist_angle)
    nu = _nu(nu)
    b = math.pi**2 * large_twist_limit(nu) * 0.5 * (1.0 - 1.0 / nu)
    ripple = math.pi * b * abs(math.sin(om)) / (2.0 * om**3)
    common = -b**2 / (8.0 * om**3)
    return om - math.pi + ripple + common, om + math.pi - ripple + common


@dataclass(frozen=True)
class CrossingClosedForm:
    """The family crossing near n pi (a corner maximum of p*): beta_1 L = (n-1) pi and
    beta_2 L = (n+1) pi exactly there.

    Examples
    --------
    >>> import math, spectral_rod as sr
    >>> c = sr.crossing_closed_form(3, 1.5)
    >>> round(c.beta1 / math.pi, 12), round(c.beta2 / math.pi, 12)   # (n -+ 1) pi
    (2.0, 4.0)
    """

    n: int
    twist: float
    p_star: float
    beta1: float
    beta2: float


def crossing_closed_form(n: int, nu: float) -> CrossingClosedForm:
    """Omega_n and p*_n of the crossing near n pi (2 <= n <= 1e4; module docstring for the
    proof and for the form of p*_n without the cancellation in N - w_n).

    Returns
    -------
    CrossingClosedForm
        n, the crossing twist Omega_n, p*_n and the wavenumbers (n - 1) pi, (n + 1) pi.

    Examples
    --------
    >>> c = crossing_closed_form(2, 1.5)
    >>> round(c.twist, 12), round(c.p_star, 12)
    (6.285782609677, 1.196030793888)
    """
    n = check_int(n, "n", 2, CROSSING_MAX_N)
    nu = _nu(nu)
    big_n, big_m = n * n + 1.0, (n * n - 1.0) ** 2
    den = (3.0 * nu + 1.0) * (nu + 3.0)
    root = math.sqrt(big_n**2 * (nu * nu - 1.0) ** 2 + big_m * (nu + 1.0) ** 2 * den)
    w = (big_n * (nu * nu + 6.0 * nu + 1.0) + root) / den
    # 2 nu (N - w) / (nu + 1) lost ~n^2 eps to cancellation (p* above its bound (1 + nu)/2 by
    # 2.3e-13 at n = 33, nu = 1 + eps, found by the fuzz suite)
    p = 8.0 * n * n * nu * (nu + 1.0) / (2.0 * big_n * (nu + 1.0) ** 2 + root)
    return CrossingClosedForm(n=n, twist=math.pi * math.sqrt(w), p_star=p,
                              beta1=(n - 1) * math.pi, beta2=(n + 1) * math.pi)


def crossing_twist_asymptotic(n: int, nu: float) -> float:
    """Omega_n ~ n pi + pi ((nu - 1)/(nu + 1))^2 / (8 n^3), error O(n^-5) (module docstring).

    Returns
    -------
    float
        The asymptotic crossing twist Omega_n (radians).

    Examples
    --------
    >>> import math
    >>> round(crossing_twist_asymptotic(2, 1.5) / math.pi, 9)   # 2 + (0.5/2.5)^2 / 64
    2.000625
    >>> exact = crossing_closed_form(6, 1.5).twist   # the closed form, error O(n^-5)
    >>> abs(crossing_twist_asymptotic(6, 1.5) - exact) < 1e-5
    True
    """
    n = check_int(n, "n", 2, CROSSING_MAX_N)
    nu = _nu(nu)
    q = (nu - 1.0) / (nu + 1.0)
    return n * math.pi + math.pi * q * q / (8.0 * n**3)
