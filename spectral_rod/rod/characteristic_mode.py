r"""The closed-form solution of Eq. ``inst1``: the paper's 4x4 boundary determinant and the
buckling mode as sums of cos/sin(beta_k s) (section "Stability of a rectilinear rod").

Notation and derivation: :mod:`spectral_rod.rod.characteristic` (body-frame displacements xi, eta;
omega1 = -lambda xi, omega2 = -mu eta) and :mod:`spectral_rod.rod.wavenumbers` (X_k = beta_k^2 L^2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath as mp
import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import check_int, scalar_nu, scalar_twist
from spectral_rod.errors import ConvergenceError
from spectral_rod.rod.characteristic import (
    REFERENCE_MAX_NU,
    REFERENCE_MAX_TWIST,
    CharacteristicRoot,
    bracketed_root_mp,
    determinant,
    entire_cs,
    entire_cs_double,
)
from spectral_rod.rod.wavenumbers import characteristic_roots

__all__ = ["CharacteristicMode", "boundary_determinant_4x4", "characteristic_mode",
           "fields_at_load", "mode_fields"]


#: Points of the fixed grid a mode's scale is taken on, besides the output grid's
#: (:func:`characteristic_mode`, :func:`spectral_rod.buckling_mode`).
SCALE_POINTS = 257

def boundary_determinant_4x4(lam: mp.mpf, om: mp.mpf, nu: mp.mpf) -> mp.mpf:
    """The paper's 4x4 boundary determinant, literally: s in [0, 1], four fundamental solutions.

    Solutions of Eq. ``inst1`` (body-frame displacements) for each root X_k = beta_k^2 of the
    characteristic equation, written with entire functions of X_k:

        u_k: xi = 2 Omega cos(beta_k s),  eta = (lambda - Omega^2 - X_k) sin(beta_k s)/beta_k,
        v_k: eta = 2 Omega cos(beta_k s),  xi = -(mu - Omega^2 - X_k) sin(beta_k s)/beta_k.

    Rows: xi(0), eta(0), xi(1), eta(1) (hinged ends). Its zeros are the loads of both families;
    exactly, det = 16 Omega^2 D_sym D_anti (tested), so it vanishes identically at Omega = 0
    (the removable singularity the 2x2 reduction divides out).
    """
    mu = lam / nu
    xm, xp = characteristic_roots(lam, mu, om, sqrt=mp.sqrt)
    one = mp.mpf(1)
    cols = []
    for x in (xp, xm):
        c1, s1 = entire_cs(x, one)
        cols.append([2 * om, mp.mpf(0), 2 * om * c1, (lam - om**2 - x) * s1])
    for x in (xp, xm):
        c1, s1 = entire_cs(x, one)
        cols.append([mp.mpf(0), 2 * om, -(mu - om**2 - x) * s1, 2 * om * c1])
    return mp.det(mp.matrix([[col[i] for col in cols] for i in range(4)]))


@dataclass(frozen=True)
class CharacteristicMode:
    """The buckling mode in closed form (sums of cos/sin(beta_k t)) at a characteristic root.

    s: grid on [0, 1]; xi, eta: body-frame displacements along (u0, v0); x1, x2: the centreline
    displacement in the fixed frame, x = R(Omega s) (xi, eta); all scaled to max |x| = 1.

    Examples
    --------
    >>> import spectral_rod as sr
    >>> root = sr.characteristic_critical_load(3.0, 1.5)
    >>> mode = sr.characteristic_mode(root, 3.0, 1.5, points=5)
    >>> mode.s.tolist(), bool(abs(mode.x2[[0, -1]]).max() < 1e-12)   # hinged ends
    ([0.0, 0.25, 0.5, 0.75, 1.0], True)
    """

    s: NDArray[np.float64]
    xi: NDArray[np.float64]
    eta: NDArray[np.float64]
    x1: NDArray[np.float64]
    x2: NDArray[np.float64]


def _amplitudes(family: str, lam: mp.mpf, mu: mp.mpf, om: mp.mpf, xs: tuple[mp.mpf, mp.mpf]
                ) -> list[tuple[mp.mpf, mp.mpf]]:
    """(xi, eta) amplitude vectors of each root's solution in the family
    (:mod:`spectral_rod.rod.characteristic`): xi ~ cos, eta ~ sin/beta (symmetric) or the
    reverse."""
    if family == "symmetric":
        return [(2 * om, lam - om**2 - x) for x in xs]
    return [(mu - om**2 - x, -2 * om) for x in xs]


def _null_coefficients(family: str, amp: list[tuple[mp.mpf, mp.mpf]],
                       half: list[tuple[mp.mpf, mp.mpf]]) -> tuple[mp.mpf, mp.mpf]:
    """Null vector of the family's 2x2 boundary system at t = 1/2, from its larger row."""
    cos_first = family == "symmetric"
    rows = [[a[0] * (h[0] if cos_first else h[1]) for a, h in zip(amp, half, strict=True)],
            [a[1] * (h[1] if cos_first else h[0]) for a, h in zip(amp, half, strict=True)]]
    r = max(rows, key=lambda row: abs(row[0]) + abs(row[1]))
    return r[1], -r[0]


#: Working digits of the closed-form mode beyond -2 log10 |Omega(L)| (:func:`fields_at_load`).
#: An empirical margin: with it the modes agree with collocation eigenvectors to <= 1e-13 from
#: Omega(L) = 5e-324 to 45 (measured <= 8.5e-15 on 1,100 random modes), and the
#: out-of-plane part x2 / Omega at Omega(L) = 5e-300..1e-12 equals its value at 1e-7 to <= 1e-10
#: (measured <= 1.4e-12; tests/test_two_solvers.py).
MODE_DIGITS = 20
#: The load is refined in the bracket p (1 -+ REFINE_RTOL) around the given one.
REFINE_RTOL = 1e-10


def _refined_load(family: str, p: mp.mpf, om: mp.mpf, nu: mp.mpf) -> mp.mpf:
    """p refined to the working precision on its family's determinant, in the bracket
    p (1 -+ REFINE_RTOL); p itself where the determinant does not change sign there."""
    def f(x: mp.mpf) -> mp.mpf:
        return determinant(family, mp.pi**2 * x, om, nu)

    a, b = p * (1 - REFINE_RTOL), p * (1 + REFINE_RTOL)
    if f(a) * f(b) > 0:
        return p
    return bracketed_root_mp(f, a, b)


def fields_at_load(family: str, p_star: float | mp.mpf, twist_angle: float, nu: float,
                   s: ArrayLike, dps: int = 30) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Body-frame displacements (xi, eta) of `family`'s mode at the load p_star, at the points s
    (unscaled); the work of :func:`mode_fields` (which see), for a load without its root record.
    """
    om_f = abs(float(twist_angle))
    with mp.workdps(max(dps, MODE_DIGITS - 2 * math.floor(math.log10(om_f)))):
        om, nuv = mp.mpf(om_f), mp.mpf(nu)
        lam = mp.pi**2 * _refined_load(family, mp.mpf(p_star), om, nuv)
        xm, xp = characteristic_roots(lam, lam / nuv, om, sqrt=mp.sqrt)
        xs = (xp, xm)
        amp = _amplitudes(family, lam, lam / nuv, om, xs)
        c = _null_coefficients(family, amp, [entire_cs(x) for x in xs])
        raw = [[ck * ak[j] for ck, ak in zip(c, amp, strict=True)] for j in (0, 1)]
        top = max(abs(w) for row in raw for w in row)
        weights = [[float(w / top) for w in row] for row in raw]
    t = np.asarray(s, dtype=float) - 0.5
    cs = [entire_cs_double(float(x), t) for x in xs]
    first, second = (0, 1) if family == "symmetric" else (1, 0)
    xi = sum(w * f[first] for w, f in zip(weights[0], cs, strict=True))
    eta = sum(w * f[second] for w, f in zip(weights[1], cs, strict=True))
    return np.asarray(xi), np.asarray(eta)


def mode_fields(root: CharacteristicRoot, twist_angle: float, nu: float, s: ArrayLike,
                dps: int = 30) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Body-frame displacements (xi, eta) of the mode of ``root`` at the points s (unscaled).

    The amplitudes and the null vector of the family's 2x2 boundary system are computed in
    mpmath (they involve differences such as lambda - Omega^2 - X_k), the sums of cos/sin(beta_k
    t) (t = s - 1/2) in double precision. Symmetric family: xi = sum_k c_k 2 Omega cos(beta_k t),
    eta = sum_k c_k (lambda - Omega^2 - X_k) sin(beta_k t)/beta_k; antisymmetric: xi = sum_k c_k
    (mu - Omega^2 - X_k) sin(beta_k t)/beta_k, eta = -sum_k c_k 2 Omega cos(beta_k t). Needs
    Omega != 0 (at zero twist the mode is Euler's planar sin(pi s)). The weights are divided by
    the largest of them before they leave mpmath: unnormalised they carry a factor ~Omega that
    underflows double precision at tiny twist (unnormalised, at Omega(L) = 1e-322 every field is
    0, so the scaled mode is nan; at 1e-320 it has one significant digit).

    The mode is ill-conditioned at small twist: the part of order Omega is decided by
    lam - Omega^2 - X_+, which is O(Omega^2), so the load and the wavenumbers X_k must agree to
    well below Omega^2 for that part to be right relative to itself. They are therefore
    computed at max(dps, MODE_DIGITS - 2 log10 |Omega(L)|) digits: the load refined on the
    family's determinant from root.p_star, the X_k again from it (root.x_plus/x_minus, at the
    root's precision, are not used). With the root's X_k at 30 digits a 40-digit root's mode is
    wrong (O(1)) for |Omega(L)| <= 1e-40; at MODE_DIGITS - log10 |Omega(L)| digits the mode is
    right, but its out-of-plane part is off by 2e-2 (relative to itself) at 1e-20 and 0.3 at
    1e-200 against an evaluation wholly in mpmath (the committed test is the Omega-scaling of
    MODE_DIGITS, tests/test_two_solvers.py).

    At a split pair (the antisymmetric family near nu = 4, roots ~2.2 Omega apart) the mode is
    that of whichever root root.p_star is nearest, so the root must separate the pair: a
    dps-digit root does so for |Omega(L)| >~ 10^(15 - dps) (measured with 40-digit roots
    against 80-digit ones at nu = 4: the modes agree to 1.5e-13 at 1e-30, 1e-2 at 1e-40).
    """
    if not isinstance(root, CharacteristicRoot):
        raise TypeError(f"root must be a CharacteristicRoot, got {type(root).__name__}")
    # the ranges of characteristic_critical_load, whose roots this accepts
    twist_angle = scalar_twist(twist_angle, max_abs=REFERENCE_MAX_TWIST)
    nu = scalar_nu(nu, max_value=REFERENCE_MAX_NU)
    dps = check_int(dps, "dps", 15, 200)
    if twist_angle == 0.0:
        raise ValueError("twist_angle must be non-zero for the closed-form mode (at zero twist "
                         "the mode is Euler's planar sin(pi s))")
    _check_root_is_of(root, twist_angle, nu)
    xi, eta = fields_at_load(root.family, root.p_star, twist_angle, nu, s, dps)
    # -Omega is the mirror image (omega2 -> -omega2), as in buckling_mode: the +|Omega| mode
    # does not solve inst1 at -Omega (residual ~1e3)
    return xi, (-eta if twist_angle < 0 else eta)


def _check_root_is_of(root: CharacteristicRoot, twist_angle: float, nu: float) -> None:
    """ValueError unless ``root`` was computed at (twist_angle, nu): its X_+ (stored with it)
    recomputed from root.p_star here (a sum of positive terms: no cancellation) must agree: a
    root of another point gives a mode that is not one (x(1) = 0.017 instead of 0 for the root
    of (5, 1.5) used at (6, 1.5))."""
    lam = math.pi**2 * float(root.p_star)
    x_plus = characteristic_roots(lam, lam / nu, twist_angle, sqrt=math.sqrt)[1]
    if abs(x_plus - float(root.x_plus)) > 1e-9 * x_plus:
        raise ValueError(f"root (p* = {float(root.p_star):.12g}) is not a root at twist_angle="
                         f"{twist_angle!r}, nu={nu!r}: pass the twist and nu it was computed at")


def characteristic_mode(root: CharacteristicRoot, twist_angle: float, nu: float,
                        points: int = 201, dps: int = 30) -> CharacteristicMode:
    """The mode of ``root`` on a uniform grid of `points` in [0, 1] (:func:`mode_fields`), with
    the fixed-frame centreline x = R(Omega s)(xi, eta), scaled to max |x| = 1 (the maximum taken
    on a fixed fine grid too, so that a coarse output grid -- even just the two hinges, where
    x = 0 -- is scaled like any other). A mode that comes out non-finite or zero raises
    :class:`spectral_rod.ConvergenceError` (no such case is known).

    Returns
    -------
    CharacteristicMode
        The grid s, the body-frame displacements (xi, eta) and the fixed-frame centreline
        (x1, x2), scaled to max |x| = 1.

    Examples
    --------
    >>> import spectral_rod as sr
    >>> root = sr.characteristic_critical_load(1000.0, 1.5)
    >>> mode = characteristic_mode(root, 1000.0, 1.5, points=5)
    >>> bool(abs(mode.x1[[0, -1]]).max() < 1e-12)   # hinged ends
    True
    """
    npts = check_int(points, "points", 2, 100_000)
    s = np.concatenate([np.linspace(0.0, 1.0, npts), np.linspace(0.0, 1.0, SCALE_POINTS)])
    xi, eta = mode_fields(root, twist_angle, nu, s, dps)
    om = float(twist_angle)
    x1 = xi * np.cos(om * s) - eta * np.sin(om * s)
    x2 = xi * np.sin(om * s) + eta * np.cos(om * s)
    scale = float(np.max(np.hypot(x1, x2)))
    if not (math.isfinite(scale) and scale > 0.0):
        raise ConvergenceError(f"characteristic_mode: no finite nonzero mode at twist_angle="
                               f"{twist_angle!r}, nu={nu!r}, p*={root.p_star}")
    out = slice(0, npts)
    return CharacteristicMode(s[out], xi[out] / scale, eta[out] / scale, x1[out] / scale,
                              x2[out] / scale)
