r"""The twist-induced gain p* - 1 to full *relative* accuracy (issue 6, extreme 1).

Why a separate function
-----------------------
As nu -> 1 or Omega(L) -> 0 the gain p* - 1 vanishes like (nu - 1) and like Omega(L)^2 (for
nu -> 1, Omega -> 0 it is (nu - 1) Omega^2 (pi^2 - 6)/(12 pi^2) + ...). A double-precision
eigenvalue near pi^2 carries it with almost no significant digits: at nu - 1 = 1e-8 and
Omega(L) = 1e-6, p* - 1 = 3.27e-22, far below the rounding of p* itself.

Formulation that computes the increment directly
------------------------------------------------
Paper, section "Stability of a rectilinear rod", Eq. ``inst1`` with hinged ends; s/L in [0, 1],
Omega = omega30 L, nu = A2/A1 = I2/I1 >= 1, p* = P_cr/(pi^2 A1/L^2). In the fixed (lab) frame
let z = x1 + i x2 be the centreline deflection; the body-frame curvatures are
omega1 + i omega2 = exp(-i Omega s) z''. The energy of ``inst1`` gives the Rayleigh quotient

    lambda(z) = [ int |z''|^2 + (nu - 1) int omega2^2 ] / int |z'|^2,   z(0) = z(1) = 0,

(z'' = 0 at the ends is natural) and pi^2 p* = min lambda. Subtracting pi^2,

    pi^2 (p* - 1) = min [ W(z) + (nu - 1) int omega2^2 ] / int |z'|^2,
    W(z) = int |z''|^2 - pi^2 int |z'|^2  >= 0  (Wirtinger).

Both terms are non-negative, so nothing cancels. W vanishes identically against
phi = sin(pi s): W(psi, phi) = int psi (phi'''' + pi^2 phi'') = 0 for *every* admissible psi
(integrations by parts use psi = phi'' = 0 at the ends), and int psi' phi' = pi^2 int psi phi
= 0 when psi is L2-orthogonal to phi. We therefore split z = c1 (phi, i phi) + z2 with z2
orthogonal to phi: the pencil is block diagonal except for the (nu - 1) coupling, and the increment
delta = p* - 1 is the smallest root of the 2x2 Schur complement

    T(delta) = (nu-1) G11 - (nu-1)^2 G12 [W22 + (nu-1) G22 - delta M22]^{-1} G21,
    delta = lambda_min(T(delta)),

whose entries are all O(nu - 1) (times O(Omega) / O(Omega^2) for the omega2 moments of phi),
computed without cancellation; lambda_min of the 2x2 matrix is evaluated as det/lambda_max.
T is operator-concave and decreasing in delta, so Newton's method started from
lambda_min(T(0)) >= delta decreases monotonically to the root.

Basis for z2 (each of x1, x2): sin(k pi s), k = 2..N (W and M diagonal), plus the two
boundary tails sum_{k>N} (+-1)^k sin(k pi s)/k^5 (closed form: Bernoulli polynomial B5 minus the
partial sum). The true mode's sine coefficients decay like k^-5 (its odd extension has a
jump in z''''), which alone would limit the error to O(N^-5); the tails absorb that jump and
the error falls to the rounding floor with N ~ 2 |Omega|/pi + 48. Integrals of omega2 moments
use Gauss-Legendre quadrature (all integrands entire, sin(Omega s) evaluated directly).

Where p* - 1 >= 1e-3 the increment is not small and p* - 1 from the characteristic
equation in double precision (:func:`spectral_rod.characteristic.characteristic_double`, measured
within 1-2 ulp of p* for Omega in [1e-3, 1e4], nu in [1.001, 1e4]) has relative accuracy
<= 1e-12; there (and only there) it is used, which also covers the large-twist /
strong-anisotropy corner where the sine basis converges slowly. (Points with nu - 1 <= 1e-3
always take the Galerkin route: p* - 1 <= (nu - 1)/2 there.)

Verified against the mpmath characteristic equation (:mod:`spectral_rod.characteristic`) at
50-60 digits: relative error <= 1e-9 on the grid nu - 1 in [1e-8, 1e4], Omega in [1e-6, 1e3]
(tests/test_increment.py, scene ``extremes``).
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import lru_cache

import numpy as np
from numpy.polynomial import polynomial as P
from numpy.polynomial.legendre import leggauss
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import cho_factor, cho_solve

from spectral_rod._blas_threads import one_blas_thread
from spectral_rod._validation import broadcast_points, check_nu, check_twist
from spectral_rod.characteristic import characteristic_double_batch

__all__ = ["INCREMENT_MAX_TWIST", "critical_load_increment", "galerkin_increment",
           "galerkin_increment_family"]

#: |Omega(L)| limit of :func:`critical_load_increment` (the basis needs N ~ 2|Omega|/pi + 48).
INCREMENT_MAX_TWIST = 1.0e3
#: Above this gain p* - 1 is taken from critical_load (relative error <= ~1e-12 there).
DIRECT_THRESHOLD = 1.0e-3
_MAX_NEWTON = 60
#: Up to this nu - 1 the complement is solved by a fixed-point iteration (see
#: :func:`_newton_fixed_point`; contraction <= 1.3 (nu - 1)), beyond it by Cholesky.
FIXED_POINT_MAX_E = 1.0e-2


@lru_cache(maxsize=2)
def tail_polynomial(shift: int) -> NDArray[np.float64]:
    """Power coefficients (in s) of sum_{k>=1} (+-1)^k sin(k pi s) / k^5 on [0, 1].

    shift = 0: all signs +; shift = 1: (-1)^k. Closed form -(2 pi)^5/240 B5((s + shift)/2)
    (Bernoulli polynomial), expanded exactly in rationals and rounded once.
    """
    b5 = (Fraction(0), Fraction(-1, 6), Fraction(0), Fraction(5, 3), Fraction(-5, 2),
          Fraction(1))
    out = [Fraction(0)] * 6
    for j, b in enumerate(b5):
        for i in range(j + 1):
            out[i] += b * math.comb(j, i) * Fraction(shift) ** (j - i) / Fraction(2) ** j
    factor = -(2 * math.pi) ** 5 / 240
    return np.array([float(c) * factor for c in out])


@lru_cache(maxsize=128)
def gauss_legendre(q: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Gauss-Legendre nodes and weights of order q on s in [0, 1] (numpy's leggauss, which
    solves an eigenproblem: 59-72 % of a point's cost when it was recomputed per point)."""
    x, w = leggauss(q)
    return (x + 1) / 2, w / 2


def basis_size(twist_angle: float) -> int:
    """Sine modes per field: N = max(32, ceil(2 |Omega|/pi) + 48) (validated, see module)."""
    return max(32, math.ceil(2 * abs(twist_angle) / math.pi) + 48)


def _second_derivatives(s: NDArray[np.float64], n: int
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """phi'' / pi at the nodes for the M-normalised complement basis and the critical mode.

    Returns (critical (q,), sines k = 2..n (q, n-1), tails (q, 2)) with int phi'^2 = 1 for
    every column (the two tails M-orthonormalised), and the tails' W/pi^2 matrix via the caller.
    """
    k = np.arange(1, n + 1)
    kp = np.pi * k
    sin_ks = np.sin(np.outer(s, kp))
    # phi_k = sqrt(2)/(k pi) sin(k pi s): int phi_k'^2 = 1, phi_k''/pi = -sqrt(2) k sin(k pi s)
    sines = -math.sqrt(2.0) * k * sin_ks
    return sines[:, 0], sines[:, 1:], sin_ks


def _tails(s: NDArray[np.float64], w: NDArray[np.float64], sin_ks: NDArray[np.float64],
           n: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The two k^-5 boundary tails (values of phi''/pi, M-orthonormal) and their W/pi^2."""
    k = np.arange(1, n + 1, dtype=float)
    kp = np.pi * k
    cos_ks = np.cos(np.outer(s, kp))
    d2, d1 = [], []
    for shift in (0, 1):
        poly = tail_polynomial(shift)
        c = ((-1.0) ** k if shift else np.ones(n)) / k**5
        d2.append(P.polyval(s, P.polyder(poly, 2)) + sin_ks @ (c * kp**2))
        d1.append(P.polyval(s, P.polyder(poly, 1)) - cos_ks @ (c * kp))
    t2, t1 = np.array(d2).T, np.array(d1).T
    m = (t1 * w[:, None]).T @ t1
    inv_l = np.linalg.inv(np.linalg.cholesky(m))
    t2 = t2 @ inv_l.T / np.pi
    wirtinger = (t2 * w[:, None]).T @ t2 - np.eye(2)
    return t2, wirtinger


def _min_eig2(t: NDArray[np.float64]) -> tuple[float, NDArray[np.float64]]:
    """Smallest eigenvalue (as det / lambda_max: relative accuracy) and eigenvector of 2x2 t."""
    a, b, c = t[0, 0], t[0, 1], t[1, 1]
    lmax = 0.5 * (a + c + math.hypot(a - c, 2 * b))
    lmin = (a * c - b * b) / lmax if lmax > 0 else 0.0
    v1, v2 = np.array([c - lmin, -b]), np.array([-b, a - lmin])
    v = v1 if np.linalg.norm(v1) >= np.linalg.norm(v2) else v2
    nv = np.linalg.norm(v)
    return lmin, (v / nv if nv > 0 else np.array([1.0, 0.0]))


@lru_cache(maxsize=128)
def _galerkin_basis(n: int, q: int) -> tuple[NDArray[np.float64], ...]:
    """Everything of the formulation that does not depend on Omega or nu, per (n, q): nodes s,
    sqrt(weights), phi''/pi of the critical mode and of the complement (sines, then tails)
    at the nodes, and the complement's W block (both fields). Cached: 30 % of a point's cost."""
    s, w = gauss_legendre(q)
    crit, sines, sin_ks = _second_derivatives(s, n)
    tails, w_tail = _tails(s, w, sin_ks, n)
    m1 = sines.shape[1]
    wblock = np.zeros((m1 + 2, m1 + 2))
    wblock[:m1, :m1] = np.diag(np.arange(2, n + 1, dtype=float) ** 2 - 1.0)
    wblock[m1:, m1:] = w_tail
    w22 = np.zeros((2 * (m1 + 2),) * 2)
    w22[:m1 + 2, :m1 + 2] = wblock
    w22[m1 + 2:, m1 + 2:] = wblock
    return s, np.sqrt(w), crit, np.concatenate([sines, tails], axis=1), w22


def galerkin_increment(twist_angle: float, nu: float, n: int | None = None) -> float:
    """p* - 1 from the lab-frame Schur-complement formulation (module docstring), one point.

    twist_angle = Omega(L) (any sign), nu = I2/I1 >= 1; n sine modes per field (default
    :func:`basis_size`). Exact zero at nu = 1 or Omega = 0.
    """
    return galerkin_increment_family(twist_angle, nu, n)[0]


def mode_family(c1: NDArray[np.float64], twist_angle: float) -> str:
    """Parity family of the mode from its sin(pi s) coefficient c1 = (x1, x2) in the lab frame.

    By the reflection symmetry (see :mod:`spectral_rod.characteristic`), exp(-i Omega/2) c1 is
    real for the symmetric family (mid-span displacement along u0) and imaginary for the
    antisymmetric one.
    """
    ang = math.atan2(c1[1], c1[0]) - twist_angle / 2
    return "symmetric" if abs(math.cos(ang)) >= abs(math.sin(ang)) else "antisymmetric"


def galerkin_increment_family(twist_angle: float, nu: float, n: int | None = None
                              ) -> tuple[float, str]:
    """(p* - 1, mode family) from the Schur-complement formulation; see galerkin_increment."""
    om, e = abs(float(twist_angle)), float(nu) - 1.0
    if om == 0.0 or e == 0.0:
        return 0.0, "symmetric"
    n = basis_size(om) if n is None else int(n)
    s, sqrt_w, crit, comp, w22 = _galerkin_basis(n, int(1.6 * n + 0.5 * om + 40))
    so, co = np.sin(om * s), np.cos(om * s)
    # omega2 = cos(Om s) x2'' - sin(Om s) x1''  (columns: x1 = phi, x2 = phi)
    f = np.concatenate([-(crit * so)[:, None], (crit * co)[:, None],
                        -comp * so[:, None], comp * co[:, None]], axis=1)
    f *= sqrt_w[:, None]
    g = f.T @ f
    g11, g21, g22 = g[:2, :2], g[2:, :2], g[2:, 2:]
    if e <= FIXED_POINT_MAX_E:
        found = _newton_fixed_point(e, g11, g21, g22, w22, om)
        if found is not None:
            return found
    return _newton_cholesky(e, g11, g21, g22, w22, om)


def _newton_cholesky(e, g11, g21, g22, w22, om) -> tuple[float, str]:
    """Newton's method on delta = lambda_min(T(delta)), a Cholesky factorisation per step."""
    a0 = w22 + e * g22
    eye = np.eye(a0.shape[0])

    def schur(d: float):
        cf = cho_factor(a0 - d * eye, check_finite=False)
        y = cho_solve(cf, g21, check_finite=False)
        return e * g11 - e * e * (g21.T @ y), cf

    t0, _ = schur(0.0)
    d, v = _min_eig2(t0)
    for _ in range(_MAX_NEWTON):
        try:
            t, cf = schur(d)
        except np.linalg.LinAlgError:  # pragma: no cover - d beyond the complement's spectrum
            d *= 0.5
            continue
        lmin, v = _min_eig2(t)
        r = cho_solve(cf, g21 @ v, check_finite=False)
        step = (lmin - d) / (-e * e * float(r @ r) - 1.0)
        d_new = d - step
        if abs(d_new - d) <= 4e-16 * abs(d_new):
            return d_new, mode_family(v, om)
        d = d_new
    return d, mode_family(v, om)


def _newton_fixed_point(e, g11, g21, g22, w22, om) -> tuple[float, str] | None:
    """The same Newton iteration with the solves (W22 - delta + e G22) y = g21 by the fixed
    point y <- (W22 - delta)^{-1} (g21 - e G22 y) (W22 is diagonal but for the two 2x2 tail
    blocks), warm-started from the previous step's y; None if it does not converge.

    Contraction: G22 <= W22 + M22 as quadratic forms (omega2^2 <= |z''|^2), so the iteration
    contracts by <= (nu - 1)(1 + 1/3) (W22 >= 3 on the sines). Measured on 200 points,
    Omega(L) in [0, 50), nu - 1 in [1e-8, 1e-3]: 357 us a point against 699 with a Cholesky
    factorisation per Newton step, and the same p* - 1 to the last bit.
    """
    ge = e * g22
    y = np.zeros_like(g21)
    d = 0.0
    v = np.array([1.0, 0.0])
    for it in range(_MAX_NEWTON + 1):
        y = _fixed_point(w22, d, ge, g21, y)
        if y is None:
            return None
        t = e * g11 - e * e * (g21.T @ y)
        lmin, v = _min_eig2(t)
        if it == 0:  # T(0) gives the start, as in the Cholesky version
            d = lmin
            continue
        r = y @ v  # (a0 - d)^{-1} g21 v
        d_new = d - (lmin - d) / (-e * e * float(r @ r) - 1.0)
        if abs(d_new - d) <= 4e-16 * abs(d_new):
            return d_new, mode_family(v, om)
        d = d_new
    return d, mode_family(v, om)


def _fixed_point(w22, d, ge, rhs, y, sweeps: int = 60):
    """y solving (w22 - d + ge) y = rhs by the fixed-point sweeps of _newton_fixed_point, from
    y; None if the change does not fall to 4e-16 relative (a few rounding errors)."""
    half = w22.shape[0] // 2
    tails = np.array([half - 2, half - 1, 2 * half - 2, 2 * half - 1])  # two per field
    diag_inv = 1.0 / (np.diagonal(w22) - d)
    block_inv = np.linalg.inv(w22[half - 2:half, half - 2:half] - d * np.eye(2))
    for _ in range(sweeps):
        b = rhs - ge @ y
        y_new = b * diag_inv[:, None]
        y_new[tails] = (block_inv @ b[tails].reshape(2, 2, -1)).reshape(4, -1)
        if np.max(np.abs(y_new - y)) <= 4e-16 * np.max(np.abs(y_new)):
            return y_new
        y = y_new
    return None


def critical_load_increment(twist_angle: ArrayLike, nu: ArrayLike):
    """p* - 1 = P_cr/(pi^2 A1/L^2) - 1 to full relative accuracy (target 1e-9).

    twist_angle = Omega(L) = omega30 L in radians, |Omega(L)| <= 1000 (p* is even in it);
    nu = I2/I1 in [1, 1e4] (convention A1 <= A2). Scalars give a float, arrays broadcast.
    Where p* - 1 < 1e-3 the lab-frame Schur-complement Galerkin method of the module
    docstring is used; elsewhere p* - 1 from the double-precision characteristic equation.
    """
    twist = check_twist(twist_angle, max_abs=INCREMENT_MAX_TWIST)
    nu_arr = check_nu(nu)
    shape = broadcast_points(twist_angle=twist, nu=nu_arr)
    tw = np.abs(np.broadcast_to(twist, shape).ravel())
    nv = np.broadcast_to(nu_arr, shape).ravel()
    out = np.zeros(tw.size)
    # nu - 1 <= DIRECT_THRESHOLD gives p* - 1 < 1e-3 (p* <= (1 + nu)/2): no need to ask
    direct = nv - 1.0 <= DIRECT_THRESHOLD
    rest = np.flatnonzero(~direct)
    with one_blas_thread():
        if rest.size:
            out[rest] = characteristic_double_batch(tw[rest], nv[rest])[0] - 1.0
        for i in np.flatnonzero(direct | (out < DIRECT_THRESHOLD)):
            out[i] = galerkin_increment(tw[i], nv[i])
    return float(out[0]) if shape == () else out.reshape(shape)
