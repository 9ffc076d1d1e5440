r"""The twist-induced gain p* - 1 to full *relative* accuracy (Eq. ``inst1``, hinged ends).

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
the error falls to the rounding floor with N ~ 2 |Omega|/pi + 48. The omega2 moments between
sines in the complement block are closed forms (sums of sinc, :func:`_sine_moments`); the
critical mode's moments and the tails' use Gauss-Legendre quadrature
(:func:`spectral_rod.numerics.quadrature.gauss_legendre`; all integrands entire, sin(Omega s)
evaluated
directly); for a few points the whole moment matrix is taken from the quadrature (fewer numpy
calls). Points are
solved in stacks that share N (:func:`bucket`), all at once (:func:`galerkin_increments`): a
point's result is the same whatever else is in its stack, and differs between the few-point
and the stacked route by rounding only (<= 1e-13 relative, tested).

The compliance form (the default)
---------------------------------
In the energy form above the coupling nu - 1 grows to 1e4, and the two O(nu - 1) terms of T
cancel to the O(1) increment: p* - 1 loses ~log10(nu) digits (measured 5e-11 relative at
nu = 9e3, Omega(L) = 2e-3). The hinged rod's moments are statically determined, so Eq.
``inst1`` can be written in compliances instead (:mod:`spectral_rod.rod.closed_form`):
-z'' = lambda C(s) z with C(s) the pointwise compliance diag(1, 1/nu) rotated by Omega s, i.e.
C = I - (1 - 1/nu) P(s), P(s) the projection on the stiff axis. Hence

    1/lambda = max [ int |z|^2 - (1 - 1/nu) int eta^2 ] / int |z'|^2,
    eta = cos(Omega s) x2 - sin(Omega s) x1,

and with W'(z) = int |z'|^2 / pi^2 - int |z|^2 >= 0 (Wirtinger again, vanishing against
sin(pi s) in the same way),

    delta' = 1 - 1/p* = pi^2 min [ W'(z) + (1 - 1/nu) int eta^2 ] / int |z'|^2,
    p* - 1 = delta' / (1 - delta').

This is the energy form with phi''/pi replaced by pi phi in the moments, W/pi^2 by
pi^2 W' (1 - 1/k^2 on the sines) and nu - 1 by 1 - 1/nu < 1: nothing cancels however large nu,
and the same basis, tails, moments and Newton iteration solve it
(:func:`galerkin_increments`, ``compliance=True``). Measured against 30-digit-plus references
on 1,000 random points, nu - 1 log-uniform in [1e-10, 1e4], Omega(L) log-uniform in [1e-6, 1e3]:
<= 3.9e-13 relative (tests/bench/hunt_increment.py).

Where p* - 1 is not small (>= 1, or >= 1e-2 from Omega(L) = 50 on: :data:`GALERKIN_MAX_GAIN`)
:func:`critical_load_increment` takes p* - 1 from the characteristic equation in double
precision (:func:`spectral_rod.rod.characteristic.characteristic_double`), whose p* error (a few
eps from Omega(L) = 50 on, eps (32 + |Omega|) below) is then <= ~1e-13 of p* - 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from typing import SupportsIndex

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view
from numpy.polynomial import polynomial as P
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import cho_factor, cho_solve

from spectral_rod._blas_threads import one_blas_thread
from spectral_rod._validation import broadcast_points, check_nu, check_twist
from spectral_rod.numerics.quadrature import gauss_legendre_unit
from spectral_rod.rod.characteristic import characteristic_double_batch
from spectral_rod.rod.families import FAMILY_DTYPE

__all__ = ["INCREMENT_MAX_TWIST", "critical_load_increment", "galerkin_increments"]

#: |Omega(L)| limit of :func:`critical_load_increment` (the basis needs N ~ 2|Omega|/pi + 48).
INCREMENT_MAX_TWIST = 1.0e3
#: Up to this nu - 1, p* - 1 <= (nu - 1)/2 is small: the Galerkin form without asking the
#: characteristic equation first.
DIRECT_THRESHOLD = 1.0e-3
#: p* - 1 from which :func:`critical_load_increment` takes the double-precision characteristic
#: equation instead of the Galerkin form: 1 below |Omega(L)| = 50 (its p* error <= eps (32 +
#: |Omega|) is <= 3.6e-14 of p* - 1 there), 1e-2 from 50 on (error <= 2 eps measured, the
#: Galerkin form's grows with the twist there). Recomputed by tests/bench/hunt_increment.py.
GALERKIN_MAX_GAIN, GALERKIN_MAX_GAIN_LARGE_TWIST = 1.0, 1.0e-2
#: Below this |Omega(L)| the increment is solved at it and scaled by (Omega / QUADRATIC_TWIST)^2:
#: p* - 1 is even and analytic in Omega, c(nu) Omega^2 (1 + O(nu^2 Omega^2)), so the scaling is
#: exact to ~1e-192, whereas the moments' products underflow from |Omega| ~ 1e-142 on (measured
#: without the scaling, nu - 1 = 1e-14: 8.8e-8 relative at 1e-144, -3.7e-4 at 1e-146, 0.0 at
#: 1e-148; nu = 101 at 1e-160: -1.8e-320, i.e. a negative p* - 1).
QUADRATIC_TWIST = 1.0e-100
_MAX_NEWTON = 60
_EPS = float(np.finfo(float).eps)
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


def basis_size(twist_angle: float) -> int:
    """Sine modes per field a point needs: N = ceil(2 |Omega|/pi) + 48 (validated, see module)."""
    return math.ceil(2 * abs(twist_angle) / math.pi) + 48


def _second_derivatives(s: NDArray[np.float64], n: int
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """phi'' / pi at the nodes for the M-normalised complement basis and the critical mode.

    Returns (critical mode (q,), sines k = 2..n (q, n - 1), sin(k pi s) for k = 1..n (q, n), the
    tails' input); every column has int phi'^2 = 1.
    """
    k = np.arange(1, n + 1, dtype=np.float64)
    kp = np.pi * k
    sin_ks = np.sin(np.outer(s, kp))
    # phi_k = sqrt(2)/(k pi) sin(k pi s): int phi_k'^2 = 1, phi_k''/pi = -sqrt(2) k sin(k pi s)
    sines = -math.sqrt(2.0) * k * sin_ks
    return sines[:, 0], sines[:, 1:], sin_ks


def _tails(s: NDArray[np.float64], w: NDArray[np.float64], sin_ks: NDArray[np.float64],
           n: int, compliance: bool = False) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The two k^-5 boundary tails (M-orthonormal) at the nodes and their W block: values of
    phi''/pi and W/pi^2 (energy form), or of pi phi and pi^2 W' (compliance form, module
    docstring)."""
    k = np.arange(1, n + 1, dtype=float)
    kp = np.pi * k
    cos_ks = np.cos(np.outer(s, kp))
    d2, d1, d0 = [], [], []
    for shift in (0, 1):
        poly = tail_polynomial(shift)
        c = ((-1.0) ** k if shift else np.ones(n)) / k**5
        d2.append(P.polyval(s, P.polyder(poly, 2)) + sin_ks @ (c * kp**2))
        d1.append(P.polyval(s, P.polyder(poly, 1)) - cos_ks @ (c * kp))
        d0.append(P.polyval(s, poly) - sin_ks @ c)
    t2, t1, t0 = np.array(d2).T, np.array(d1).T, np.array(d0).T
    m = (t1 * w[:, None]).T @ t1
    inv_l = np.linalg.inv(np.linalg.cholesky(m))
    if compliance:
        t0 = t0 @ inv_l.T * np.pi
        return t0, np.eye(2) - (t0 * w[:, None]).T @ t0
    t2 = t2 @ inv_l.T / np.pi
    wirtinger = (t2 * w[:, None]).T @ t2 - np.eye(2)
    return t2, wirtinger


def _min_eig2(t: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Smallest eigenvalue (as det / lambda_max: relative accuracy) and unit eigenvector of each
    symmetric 2x2 matrix of the stack t (P, 2, 2)."""
    a, b, c = t[:, 0, 0], t[:, 0, 1], t[:, 1, 1]
    lmax = 0.5 * (a + c + np.hypot(a - c, 2 * b))
    pos = lmax > 0
    lmin = (a * c - b * b) / np.where(pos, lmax, 1.0) * pos
    # of the two candidate eigenvectors (c - lmin, -b) and (-b, a - lmin), the longer one
    first = np.abs(c - lmin) >= np.abs(a - lmin)  # |v1| >= |v2|: they share the |b| entry
    v = np.empty((t.shape[0], 2))
    v[:, 0] = np.where(first, c - lmin, -b)
    v[:, 1] = np.where(first, -b, a - lmin)
    nv = np.hypot(v[:, 0], v[:, 1])
    v /= np.where(nv > 0, nv, 1.0)[:, None]
    v[nv == 0] = (1.0, 0.0)
    return lmin, v


@lru_cache(maxsize=128)
def _galerkin_basis(n: int, compliance: bool = False) -> tuple[NDArray[np.float64], ...]:
    """Everything of the formulation that depends on neither Omega nor nu, per N = n: nodes s
    and weights w of the quadrature (order :func:`quadrature_order`), the complement's W block
    (both fields), phi''/pi of the critical mode and of the complement (sines, then tails) at
    the nodes, and H0 = int a a^T over the complement (:func:`_moments_closed`). In the
    compliance form (module docstring) pi phi replaces phi''/pi and pi^2 W' = I - pi^2 int
    phi phi^T replaces W/pi^2: for the sines pi phi_k = -(phi_k''/pi)/k^2, pi^2 W'_k =
    1 - 1/k^2."""
    s, w = gauss_legendre_unit(quadrature_order(n))
    crit, sines, sin_ks = _second_derivatives(s, n)
    tails, w_tail = _tails(s, w, sin_ks, n, compliance)
    kk = np.arange(2, n + 1, dtype=float) ** 2
    if compliance:
        crit, sines = -crit, sines / -kk
    m1 = sines.shape[1]
    wblock = np.zeros((m1 + 2, m1 + 2))
    wblock[:m1, :m1] = np.diag(1.0 - 1.0 / kk if compliance else kk - 1.0)
    wblock[m1:, m1:] = w_tail
    w22 = np.zeros((2 * (m1 + 2),) * 2)
    w22[:m1 + 2, :m1 + 2] = wblock
    w22[m1 + 2:, m1 + 2:] = wblock
    comp = np.concatenate([sines, tails], axis=1)
    h0 = comp.T @ (w[:, None] * comp)
    # between sines, int a_j a_k = j^2 delta_jk exactly (1/j^2 in the compliance form), as the
    # closed forms of _sine_moments
    h0[:n - 1, :n - 1] = np.diag(1.0 / kk if compliance else kk)
    return s, w, w22, crit, comp, h0


def mode_family(c1: NDArray[np.float64], twist_angle: ArrayLike) -> NDArray[np.str_]:
    """Parity family of each mode from its sin(pi s) coefficients c1 (P, 2) = (x1, x2) in the lab
    frame (one twist per row).

    By the reflection symmetry (see :mod:`spectral_rod.rod.characteristic`), exp(-i Omega/2) c1 is
    real for the symmetric family (mid-span displacement along u0) and imaginary for the
    antisymmetric one.
    """
    ang = np.arctan2(c1[:, 1], c1[:, 0]) - np.asarray(twist_angle) / 2
    return np.where(np.abs(np.cos(ang)) >= np.abs(np.sin(ang)), "symmetric", "antisymmetric")


#: Points are solved together in buckets of this many sine modes: N rounded up to a multiple
#: of it (more modes than :func:`basis_size` asks, never fewer), with the quadrature order of
#: the bucket's largest twist, so that a point's result does not depend on the other points of
#: the call. Measured (1,000 points, Omega(L) in [0, 50), nu - 1 in [1e-8, 1e-3]): the same
#: p* - 1 as per-point sizes to <= 3e-15 relative.
BUCKET = 8
#: Points per stack are limited so that one stack's moments hold <= this many numbers (24 MB).
STACK_ELEMENTS = 3_000_000


def bucket(twist_angle: float) -> int:
    """Sine modes N used for a point of twist |Omega| (see BUCKET)."""
    return BUCKET * math.ceil(basis_size(twist_angle) / BUCKET)


def quadrature_order(n: int) -> int:
    """Gauss-Legendre order for N = n sine modes: 1.6 N + |Omega|/2 + 40 at the largest
    |Omega| whose :func:`basis_size` is <= N, (N - 48) pi/2 (the integrands' frequencies grow
    with N and |Omega|; validated with the module's grid)."""
    return int(1.6 * n + 0.5 * max(0.0, (n - 48) * math.pi / 2) + 40)


def galerkin_increments(twist: NDArray[np.float64], nu: NDArray[np.float64], *,
                        compliance: bool = True
                        ) -> tuple[NDArray[np.float64], NDArray[np.str_], NDArray[np.int_]]:
    """(p* - 1, mode family, sine modes N) at flat arrays of points (any sign of the twist,
    nu >= 1; exact zero at nu = 1 or Omega = 0), the points of a bucket (:func:`bucket`) solved
    together. ``compliance=True`` (default): the compliance form of the module docstring (its
    coupling 1 - 1/nu stays below 1 however large nu; p* - 1 = delta'/(1 - delta')), else the
    energy form (coupling nu - 1; kept as the cross-check of tests/test_increment.py).

    >>> d, fam, n = galerkin_increments(np.array([1.0, 30.0]), np.array([1.0 + 1e-6, 1.001]))
    >>> [f"{x:.6e}" for x in d], fam.tolist(), n.tolist()
    (['3.182881e-08', '4.995668e-04'], ['symmetric', 'symmetric'], [56, 72])
    """
    om, e = np.abs(twist), nu - 1.0
    if compliance:
        e = e / nu  # 1 - 1/nu, with nu - 1 exact
    tiny = (om > 0) & (om < QUADRATIC_TWIST)  # solved at QUADRATIC_TWIST, scaled at the end
    scale = np.where(tiny, (om / QUADRATIC_TWIST) ** 2, 1.0)
    om = np.where(tiny, QUADRATIC_TWIST, om)
    d = np.zeros(om.size)
    fam = np.full(om.size, "symmetric", dtype=FAMILY_DTYPE)
    sizes = BUCKET * np.ceil((np.ceil(2 * om / np.pi) + 48) / BUCKET).astype(int)  # bucket()
    live = (om > 0) & (e > 0)
    for n in np.unique(sizes[live]).tolist():
        sel = np.flatnonzero(live & (sizes == n))
        sel = sel[np.argsort(e[sel], kind="stable")]  # similar contraction: fewer sweeps a stack
        m = 2 * (n + 1)  # complement functions per point, both fields
        per = max(1, STACK_ELEMENTS // (m * m + quadrature_order(n) * m))
        for i in range(0, sel.size, per):
            part = sel[i:i + per]
            d[part], fam[part] = _bucket_increments(om[part], e[part], n, compliance)
    d *= scale
    if compliance:  # d = delta' = 1 - 1/p*: p* - 1 = delta' / (1 - delta'), no subtraction
        d /= 1.0 - d
    return d, fam, sizes


#: Relative error of p* - 1 from :func:`galerkin_increments` (the compliance form): <= 1e-12 over
#: the range of :func:`critical_load_increment` (measured <= 3.9e-13 on 1,000 random points,
#: nu - 1 in [1e-10, 1e4], Omega(L) in [1e-6, 1e3], by tests/bench/hunt_increment.py).
GAIN_ERROR = 1e-12
#: The rounding of p* = 1 + (p* - 1), in eps.
ROUNDING_ERROR = 2.0


def increment_error_estimate(gain: ArrayLike) -> NDArray[np.float64]:
    """Relative error estimate of p* = 1 + gain from :func:`galerkin_increments`:
    ROUNDING_ERROR eps + GAIN_ERROR gain, at any twist (the compliance form's relative error of
    p* - 1 does not grow with it; tests/bench/hunt_routes.py finds no point above this estimate
    at tol 1e-14)."""
    return ROUNDING_ERROR * _EPS + GAIN_ERROR * np.asarray(gain, dtype=float)


def _bucket_increments(om: NDArray[np.float64], e: NDArray[np.float64], n: int,
                       compliance: bool = False) -> tuple[NDArray[np.float64], NDArray[np.str_]]:
    """The increments of points sharing N (ordered by nu - 1): the moments, then Newton on
    delta = lambda_min(T(delta)) with the fixed-point solves, Cholesky where those do not
    apply (nu - 1 > FIXED_POINT_MAX_E: the last points of the stack) or fail."""
    mom = _moments(om, n, compliance)
    w22 = _galerkin_basis(n, compliance)[2]
    d = np.empty(om.size)
    v = np.empty((om.size, 2))
    k = int(np.searchsorted(e, FIXED_POINT_MAX_E, side="right"))  # e ascending
    ok = np.zeros(om.size, dtype=bool)
    if k:
        d[:k], v[:k], ok[:k] = _newton_fixed_point(e[:k], mom.head(k), w22)
    for i in np.flatnonzero(~ok):
        d[i], v[i] = _newton_cholesky(e[i], mom.g11[i], mom.g21[i], mom.g22(i), w22)
    return d, mode_family(v, om)


@dataclass(frozen=True)
class _Moments:
    """The omega2 moments of a stack of points (see :func:`_moments`): g11 (P, 2, 2) of the
    critical mode, g21 (P, 2m, 2) complement x critical mode, and G22 (P, 2m, 2m) held as its
    pieces: 2 G22 = [[H0 - HC, -HS], [-HS, H0 + HC]] on the complement (m functions a field),
    H0 (m, m) shared, HC and HS (P, m, m) -- or, for a few points, G22 itself (``dense``).
    Products with G22 then read HC and HS only (half of G22)."""

    g11: NDArray[np.float64]
    g21: NDArray[np.float64]
    h0: NDArray[np.float64] | None = None
    hc: NDArray[np.float64] | None = None
    hs: NDArray[np.float64] | None = None
    dense: NDArray[np.float64] | None = None  # G22 itself (few points, :func:`_moments_dense`)

    def head(self, k: int) -> _Moments:
        """The first k points (views)."""
        if self.dense is not None:
            return _Moments(self.g11[:k], self.g21[:k], dense=self.dense[:k])
        assert self.h0 is not None and self.hc is not None and self.hs is not None  # pieces
        return _Moments(self.g11[:k], self.g21[:k], self.h0, self.hc[:k], self.hs[:k])

    def g22_times(self, y: NDArray[np.float64]) -> NDArray[np.float64]:
        """G22 y for y (P, 2m, c)."""
        if self.dense is not None:
            return self.dense @ y
        assert self.h0 is not None and self.hc is not None and self.hs is not None  # pieces
        m, c = self.h0.shape[0], y.shape[2]
        both = np.concatenate([y[:, :m], y[:, m:]], axis=2)  # (P, m, 2c): x1 then x2 columns
        # H0 is diag(j^2) on the sines (exactly) plus the two tails' rows and columns
        h0y = np.diagonal(self.h0)[:, None] * both
        h0y[:, :-2] += self.h0[:-2, -2:] @ both[:, -2:]
        h0y[:, -2:] += self.h0[-2:, :-2] @ both[:, :-2] + (self.h0[-2:, -2:] - np.diag(
            np.diagonal(self.h0)[-2:])) @ both[:, -2:]
        hcy, hsy = self.hc @ both, self.hs @ both
        return 0.5 * np.concatenate([h0y[..., :c] - hcy[..., :c] - hsy[..., c:],
                                     h0y[..., c:] + hcy[..., c:] - hsy[..., :c]], axis=1)

    def g22(self, i: SupportsIndex) -> NDArray[np.float64]:
        """G22 of point i as a dense matrix."""
        if self.dense is not None:
            return self.dense[i]
        assert self.h0 is not None and self.hc is not None and self.hs is not None  # pieces
        h0, hc, hs = self.h0, self.hc[i], self.hs[i]
        return 0.5 * np.block([[h0 - hc, -hs], [-hs, h0 + hc]])


#: Up to this many points a stack's moments come from the quadrature in full
#: (:func:`_moments_dense`): fewer numpy calls, which is what a few points cost (measured:
#: critical_load at Omega(L) = 10, nu - 1 = 1e-5, 0.7 ms against 1.1 ms by the closed forms);
#: above it the closed forms.
DENSE_POINTS = 4


def _moments(om: NDArray[np.float64], n: int, compliance: bool = False) -> _Moments:
    """The moments of a stack (:func:`_moments_dense` for at most DENSE_POINTS points, else
    :func:`_moments_closed`; the two agree to <= 1e-13 of the largest entry,
    tests/test_increment.py)."""
    return (_moments_dense if om.size <= DENSE_POINTS else _moments_closed)(om, n, compliance)


def _moments_dense(om: NDArray[np.float64], n: int, compliance: bool = False) -> _Moments:
    """G = int f f^T by the Gauss-Legendre quadrature of the basis, f = (-sin(Omega s) a,
    cos(Omega s) a) over the critical mode and the complement (x1 then x2 of each)."""
    s, w, _, crit, comp, _ = _galerkin_basis(n, compliance)
    r = np.sqrt(w)
    so, co = np.sin(np.outer(om, s)) * r, np.cos(np.outer(om, s)) * r
    f = np.concatenate([-(crit * so)[:, :, None], (crit * co)[:, :, None],
                        -comp * so[:, :, None], comp * co[:, :, None]], axis=2)
    g = np.swapaxes(f, 1, 2) @ f
    return _Moments(g[:, :2, :2], g[:, 2:, :2], dense=g[:, 2:, 2:])


def _moments_closed(om: NDArray[np.float64], n: int, compliance: bool = False) -> _Moments:
    """The moments G = int f f^T of omega2 = cos(Omega s) x2'' - sin(Omega s) x1'', f over the
    critical mode and the complement, per point.

    The critical mode's moments (g11, g21) set the leading order of p* - 1 and are taken from
    the quadrature with sin(Omega s) and cos(Omega s) themselves: written with cos(2 Omega s)
    they would be 1 - cos(2 Omega s) ~ Omega^2, cancelling at small twist (measured: -2e-3
    relative error of p* - 1 at Omega(L) = 1e-6). G22 enters only as (nu - 1) G22 beside
    W22 >= 3, so absolute accuracy is enough there: with a_k = phi_k''/pi and the tails,
    2 G22 = [[H0 - HC, -HS], [-HS, H0 + HC]], HC = int a a^T cos(2 Omega s),
    HS = int a a^T sin(2 Omega s), closed forms between sines (:func:`_sine_moments`) and the
    quadrature in the tails' rows.
    """
    s, w, _, crit, comp, h0 = _galerkin_basis(n, compliance)
    so, co = np.sin(np.outer(om, s)), np.cos(np.outer(om, s))
    fc = np.stack([-(crit * so), crit * co], axis=2)  # (P, q, 2): the critical mode's columns
    wf = w[:, None] * fc
    g11 = np.swapaxes(fc, 1, 2) @ wf
    g21 = np.concatenate([comp.T @ (-so[:, :, None] * wf), comp.T @ (co[:, :, None] * wf)],
                         axis=1)
    m, jc = comp.shape[1], np.arange(2, n + 1)
    hc, hs = np.empty((2, om.size, m, m))
    _sine_moments(om, jc, out=(hc[:, :n - 1, :n - 1], hs[:, :n - 1, :n - 1]),
                  compliance=compliance)
    for h, trig in ((hc, np.cos), (hs, np.sin)):
        wt = (w * trig(np.outer(2 * om, s)))[:, :, None] * comp[None, :, n - 1:]  # (P, q, 2)
        h[:, :, n - 1:] = comp.T @ wt
        h[:, n - 1:, :n - 1] = np.swapaxes(h[:, :n - 1, n - 1:], 1, 2)
    return _Moments(g11, g21, h0, hc, hs)


def _sine_moments(om: NDArray[np.float64], j: NDArray[np.int_],
                  out: tuple[NDArray[np.float64], NDArray[np.float64]] | None = None,
                  compliance: bool = False) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """int a_j a_k cos(2 Omega s) and int a_j a_k sin(2 Omega s) on [0, 1] for j, k in `j`
    (consecutive integers; arrays (P, j, j), written into `out` if given). From
    sin A sin B cos C and sin A sin B sin C as sums of cos and sin of (j -+ k) pi +- 2 Omega:
    (jk/2) [S((j-k)pi - 2W) + S((j-k)pi + 2W) - S((j+k)pi - 2W) - S((j+k)pi + 2W)] with
    S(x) = sin(x)/x, and (jk/2) [T(2W + (j-k)pi) + T(2W - (j-k)pi) - T(2W + (j+k)pi)
    - T(2W - (j+k)pi)] with T(x) = (1 - cos x)/x = (x/2) sinc(x/2pi)^2, W = Omega. Both depend
    on j - k and j + k only, so O(n) sinc values per point fill the matrices. In the compliance
    form a_j = pi phi_j carries 1/j where phi_j''/pi carries j: the factor is 1/(2 jk).

    >>> hc, hs = _sine_moments(np.array([0.0]), np.arange(1, 3))  # Omega = 0: int a_j a_k
    >>> np.round(hc[0], 12).tolist(), float(np.abs(hs[0]).max())
    ([[1.0, 0.0], [0.0, 4.0]], 0.0)
    """
    j0, size = int(j[0]), j.size
    top = 2 * (j0 + size - 1)  # the largest j + k
    mm = np.arange(-top, top + 1)  # every j - k and j + k
    x = (2 * om / np.pi)[:, None]
    jk = 0.5 * (j[:, None] * j[None, :])
    if compliance:
        jk = 0.25 / jk
    if out is None:
        out = (np.empty((om.size, size, size)), np.empty((om.size, size, size)))
    sums = (np.sinc(mm - x) + np.sinc(mm + x),  # S(m pi - 2W) + S(m pi + 2W)
            _t(x + mm) + _t(x - mm))
    for dest, v in zip(out, sums, strict=True):
        # v at j - k (Toeplitz) and at j + k (Hankel) as strided views: no index arrays
        dest[...] = sliding_window_view(v[:, ::-1], size, axis=1)[:, top - size + 1:top + 1][
            :, ::-1]
        dest -= sliding_window_view(v, size, axis=1)[:, top + 2 * j0:top + 2 * j0 + size]
        dest *= jk
    return out


def _t(beta: NDArray[np.float64]) -> NDArray[np.float64]:
    """T(pi beta) = (1 - cos(pi beta)) / (pi beta) without cancellation."""
    return 0.5 * np.pi * beta * np.sinc(0.5 * beta) ** 2


def _newton_cholesky(e: float, g11, g21, g22, w22) -> tuple[float, NDArray[np.float64]]:
    """Newton's method on delta = lambda_min(T(delta)) for one point, a Cholesky factorisation
    per step (for nu - 1 > FIXED_POINT_MAX_E, or where the fixed point does not converge)."""
    a0 = w22 + e * g22
    eye = np.eye(a0.shape[0])

    def schur(d: float):
        cf = cho_factor(a0 - d * eye, check_finite=False)
        y = cho_solve(cf, g21, check_finite=False)
        return e * g11 - e * e * (g21.T @ y), cf

    t0, _ = schur(0.0)
    lmin, v = _min_eig2(t0[None])
    d = float(lmin[0])
    for _ in range(_MAX_NEWTON):
        try:
            t, cf = schur(d)
        except np.linalg.LinAlgError:  # pragma: no cover - d beyond the complement's spectrum
            d *= 0.5
            continue
        lmin, v = _min_eig2(t[None])
        r = cho_solve(cf, g21 @ v[0], check_finite=False)
        d_new = d - (float(lmin[0]) - d) / (-e * e * float(r @ r) - 1.0)
        if abs(d_new - d) <= 4e-16 * abs(d_new):
            return d_new, v[0]
        d = d_new
    return d, v[0]


def _newton_fixed_point(e: NDArray[np.float64], mom: _Moments, w22: NDArray[np.float64]):
    """Newton on delta = lambda_min(T(delta)) for a stack of points, the solves
    (W22 - delta + e G22) y = g21 by the fixed point y <- (W22 - delta)^{-1} (g21 - e G22 y)
    (W22 is diagonal but for the two 2x2 tail blocks), warm-started from the previous step's y.
    Returns (delta, eigenvector of T, converged): points whose fixed point does not converge
    are flagged False (the caller solves them by Cholesky).

    Contraction: G22 <= W22 + M22 as quadratic forms (omega2^2 <= |z''|^2), so the iteration
    contracts by <= (nu - 1)(1 + 1/3) (W22 >= 3 on the sines). Every point of the stack takes
    every step (finished points keep their delta): selecting the active points would copy the
    moments, which costs more than the steps it saves.
    """
    p = e.size
    e1, e2 = e[:, None, None], (e * e)[:, None, None]
    g12 = np.swapaxes(mom.g21, 1, 2)
    y = np.zeros_like(mom.g21)
    d, ok, done = np.zeros(p), np.ones(p, dtype=bool), np.zeros(p, dtype=bool)
    v = np.tile([1.0, 0.0], (p, 1))
    for it in range(_MAX_NEWTON + 1):
        y, conv = _fixed_point(w22, d, e1, mom, y)
        ok &= conv | done
        done |= ~ok  # a failed fixed point goes to Cholesky: stop iterating it
        lmin, v_new = _min_eig2(e1 * mom.g11 - e2 * (g12 @ y))
        v = np.where(done[:, None], v, v_new)  # finished points keep delta and v
        if it == 0:  # T(0) gives the start, as in the Cholesky version
            d = lmin
            continue
        r = (y @ v[:, :, None])[:, :, 0]  # (a0 - d)^{-1} g21 v
        d_new = d - (lmin - d) / (-e * e * np.einsum("pk,pk->p", r, r) - 1.0)
        d_new = np.where(done, d, d_new)
        done |= np.abs(d_new - d) <= 4e-16 * np.abs(d_new)
        d = d_new
        if done.all():
            break
    return d, v, ok & done


def _fixed_point(w22, d, e1, mom: _Moments, y, sweeps: int = 60):
    """y solving (w22 - d + e G22) y = g21 per point by the fixed-point sweeps of
    _newton_fixed_point, from y; and whether the change fell to 4e-16 relative (a few
    rounding errors) within `sweeps`."""
    half = w22.shape[0] // 2
    t0, t1 = [half - 2, 2 * half - 2], [half - 1, 2 * half - 1]  # each field's two tails
    diag_inv = (1.0 / (np.diagonal(w22)[None, :] - d[:, None]))[:, :, None]
    # the tails' 2x2 block [[a, b], [b, c]] of W22 - d, solved in closed form
    wb = w22[half - 2, half - 1]
    ta = (w22[half - 2, half - 2] - d)[:, None, None]
    tc = (w22[half - 1, half - 1] - d)[:, None, None]
    det = ta * tc - wb * wb
    conv = np.zeros(d.size, dtype=bool)
    for _ in range(sweeps):
        b = mom.g21 - e1 * mom.g22_times(y)
        y_new = b * diag_inv
        b0, b1 = b[:, t0], b[:, t1]
        y_new[:, t0], y_new[:, t1] = (tc * b0 - wb * b1) / det, (ta * b1 - wb * b0) / det
        # a converged point keeps its y: its result must not depend on the other points
        small = np.abs(y_new - y).max(axis=(1, 2)) <= 4e-16 * np.abs(y_new).max(axis=(1, 2))
        y = np.where(conv[:, None, None], y, y_new) if conv.any() else y_new
        conv |= small
        if conv.all():
            break
    return y, conv


def critical_load_increment(twist_angle: ArrayLike, nu: ArrayLike):
    """p* - 1 = P_cr/(pi^2 A1/L^2) - 1 to full relative accuracy (1e-12, measured <= 3.9e-13:
    module docstring).

    twist_angle = Omega(L) = omega30 L in radians, |Omega(L)| <= 1000 (p* is even in it);
    nu = I2/I1 in [1, 1e4] (convention A1 <= A2). Scalars give a float, arrays broadcast.
    The compliance form of the module docstring, or where p* - 1 is not small
    (:data:`GALERKIN_MAX_GAIN`) the double-precision characteristic equation.

    Returns
    -------
    float or ndarray of float
        p* - 1 (a float for scalar input, else of the broadcast shape).

    Examples
    --------
    >>> import spectral_rod as sr   # against p* from the collocation solver
    >>> d = critical_load_increment(5.0, 1.5)
    >>> abs(d - (sr.critical_load(5.0, 1.5) - 1)) < 1e-12
    True
    >>> float(critical_load_increment(0.0, 1.5))   # untwisted: the Euler load, p* = 1
    0.0
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
    limit = np.where(tw >= 50.0, GALERKIN_MAX_GAIN_LARGE_TWIST, GALERKIN_MAX_GAIN)
    with one_blas_thread():
        if rest.size:
            out[rest] = characteristic_double_batch(tw[rest], nv[rest])[0] - 1.0
        small = np.flatnonzero(direct | (out < limit))
        out[small] = galerkin_increments(tw[small], nv[small])[0]
    return float(out[0]) if shape == () else out.reshape(shape)
