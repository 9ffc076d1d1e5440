r"""Rayleigh–Ritz upper bounds for the straight rod from the bending energy in the lab frame.

Every other straight-rod solver of the package starts from the printed Eq. ``inst1``. This one
starts from the energy: the constitutive law Eq. ``constit`` and the linearised geometry of
Eqs. ``frenini``/``frenet``, minimised over polynomial trial centrelines. Its values are upper
bounds (per mode family) that decrease monotonically with the degree and converge
exponentially -- the certificate that the lowest root was found.

Formulation
-----------
Dimensionless: s/L in [0, 1], Omega = omega30 L, nu = A2/A1 >= 1, A1 = 1, lambda = P L^2/A1 =
pi^2 p*. The deflection of the centreline in the fixed frame is x(s) = (x1, x2)(s), with x = 0
at s = 0, 1 (hinged ends). Linearising Eq. ``frenet`` about the twisted straight state of Eq.
``frenini`` (u0 = (cos Omega s, sin Omega s), v0 = (-sin, cos)), the bending curvatures are the
body-frame components of x'': omega1 = x''.u0, omega2 = x''.v0, i.e. w = R(-Omega s) x''
(these are the paper's expressions for M_v = A1 omega1 and M_u = -A2 omega2). The stored
energy of Eq. ``constit`` (no spontaneous curvature) and the work of the end load are

    U = 1/2 int (A1 omega1^2 + A2 omega2^2) ds,    W = P/2 int |x'|^2 ds,

(the torsion term A3 alpha'^2 decouples and is left out), so U - W is positive definite
exactly for P below the critical load, and

    pi^2 p* = min over admissible x of  lambda[x] = int (omega1^2 + nu omega2^2) / int |x'|^2.

In lab components the integrand is x''^T S(s) x'' with the stiffness rotating with the twist,

    S = R(Omega s) diag(1, nu) R(Omega s)^T
      = (1 + nu)/2 I + (1 - nu)/2 [[cos 2 Omega s, sin 2 Omega s], [sin 2 Omega s, -cos 2 Omega s]]

(check at s = 0: diag(1, nu)). Only x = 0 at the ends is imposed: x'' = 0 there is the natural
boundary condition of the minimisation (the boundary term of the first variation is
(S x'').delta x' at the ends, and S is invertible).

Consistency with Eq. ``inst1`` (a check, not a starting point): the Euler–Lagrange equation is
(S x'')'' + lambda x'' = 0. With x'' = R w, R' = Omega R J (J the rotation by pi/2) and
D = diag(1, nu): (R D w)'' = R (D w'' + 2 Omega J D w' - Omega^2 D w), so
w1'' - 2 nu Omega w2' + (lambda - Omega^2) w1 = 0 and nu w2'' + 2 Omega w1' + (lambda -
nu Omega^2) w2 = 0 -- Eq. ``inst1`` divided by A1. Note the form used here has no Omega^2
terms at all: nothing cancels at large twist (the body-frame form of ``inst1`` balances
Omega^2 against lambda).

Mode families
-------------
The reflection s -> 1 - s maps the problem to itself. In the mid-span section frame
y = R(-Omega/2) x and t = 2 s - 1 in [-1, 1] the stiffness is S(t) = R(Omega t/2) D R(Omega t/2)^T,
with cos(Omega t) even and sin(Omega t) odd in t. The quotient therefore splits into two
invariant parity subspaces, which are the families of :mod:`spectral_rod.rod.characteristic`
(body-frame xi even / eta odd; y = R(Omega t/2)(xi, eta) with an odd rotation angle):

* symmetric (the Euler mode's): y1 even, y2 odd in t;
* antisymmetric: y1 odd, y2 even.

(Cross-check with :func:`spectral_rod.rod.increment.mode_family`: exp(-i Omega/2) times the
sin(pi s) coefficient of x1 + i x2 is real for the symmetric family, i.e. y1 even.) Each
family is discretised separately; its Ritz value is an upper bound of that family's lowest
load, and p* is the smaller of the two. With d/ds = 2 d/dt, lambda = 4 int y_tt^T S y_tt dt /
int |y_t|^2 dt.

Basis (an integration basis)
----------------------------
y_tt = sum_k c_k e(k) Pn_k(t), k = 0..n, Pn_k = sqrt((2k+1)/2) P_k the orthonormal Legendre
polynomials and e(k) the component that has the parity of k in the family (symmetric: even k in
y1, odd k in y2). y is the double integral plus the linear function that makes y(+-1) = 0, so
y_k' = (P_{k+1} - P_{k-1})/(2k+1) for k >= 2, P_1 for k = 0, P_2/3 for k = 1 (times the
normalisation). For each family the space is exactly the polynomials of degree <= n + 2 with
the family's parities that vanish at t = +-1, so the spaces are nested in n. Then

* stiffness K = int y_tt^T S y_tt: I <= K <= nu I (S has eigenvalues 1 and nu and the
  Pn_k are orthonormal) -- O(1)-conditioned, nothing cancels;
* mass M = int y_t^T y_t = G^T G with G the exact Legendre coefficients of the y_k'
  (:func:`mass_root`, closed form): compact, family independent.

Quadrature and why its node count suffices: K = F^T F with F the values of the curvatures
(omega1, sqrt(nu) omega2) of the basis at Gauss–Legendre nodes (weights folded in). The
integrands are Pn_j Pn_k times 1, cos(Omega t) or sin(Omega t). Gauss–Legendre with q nodes
is exact to degree 2q - 1 and has positive weights summing to 2, so its error on f is at most
4 inf_p ||f - p||_inf over polynomials of degree 2q - 1. Truncating the Chebyshev series
cos(Omega t) = J0 + 2 sum (-1)^k J_2k T_2k (and the sine one) after degree d gives
|error| <= 4 (2n + 1) sum_{m > d} |J_m(Omega)| for 2n + d <= 2q - 1 (|Pn_j Pn_k| <= n + 1/2),
and Kapteyn's inequality |J_m(m z)| <= (z exp(sqrt(1 - z^2))/(1 + sqrt(1 - z^2)))^m
(0 < z <= 1; DLMF 10.14.5) bounds the tail rigorously. :func:`chebyshev_degree` takes the
smallest d with nu (n + 1) times that bound <= :data:`QUADRATURE_BUDGET` = 1e-18 (the entry
bound times the matrix size bounds ||delta K||), so the quadrature changes the quotient by a
relative 1e-18 at most (K >= I); q = n + (d + 1)/2 (rounded up, and >= n + 2 so that the mass
is exact). d ~ Omega + 12 Omega^(1/3): q ~ n + Omega/2. The integrands are even, so
only the nodes t >= 0 are used (weights doubled). The nodes and weights come from Newton's
method on the three-term recurrence (:func:`spectral_rod.numerics.quadrature.gauss_legendre`),
because
numpy's ``leggauss`` and scipy's ``roots_legendre`` weights were measured wrong by 1e-11
(q = 120) to 5e-10 (q = 400) relative -- enough to spoil 1e-12 (orthonormality of Pn_k:
3e-13 at q = 120 with ``leggauss``, 7e-15 with these).

Stable eigen-solve: F = Q R (QR, backward stable), C = (G R^{-1})^T (G R^{-1}) = R^{-T} M
R^{-1}, and theta_max = the largest eigenvalue of C (``scipy.linalg.eigh``) is the largest
theta of M c = theta K c; p = 4/(pi^2 theta_max). Forming F^T F instead would lose a factor nu:
the mode's curvature is mostly along u0 while ||K|| ~ nu, so the rounding of K (~ eps nu) is
relative to a Rayleigh quotient ~ 1; measured at nu = 1e4: error 1e-12 with
``eigh(M, F^T F)``, 1e-14 with the QR form (and 2e-10 with the double-angle form of S). The
backward error of the QR is ~ eps sqrt(nu) relative to the mode's energy.

Resolution and error estimate
-----------------------------
The mode is entire, so polynomials of degree n converge faster than any exp(-c n) once n is
past the transition n ~ |Omega| (the lab-frame mode carries the stiffness's frequency
2 Omega in s, i.e. Omega in t). Before the transition the Ritz values sit on a plateau: they
barely change with n although they are far from the answer (measured at Omega = 500: the
change from n = 10 to 12 is 2e-9 times the error, which is 0.04 to 2500 relative), so a nested
difference says nothing there. Past it the error falls fast (measured worst ratio of errors
e(n)/e(n - 4) for n >= |Omega| + 4 over Omega in [0, 500], nu in [1 + 1e-6, 1e4]: 0.26, and
0.4 at Omega = 1000; the ratio shrinks as n grows).

Error estimate at degree n: the Ritz mode's energy-orthogonal projection onto the space of
degree n - Delta (Delta = :func:`estimate_gap`, 4 ... 14 as Omega grows, keeping the gain over
Delta >= 25) has a Rayleigh quotient p_coarse >= p(n - Delta) >= p(n), and

    error_estimate = max((p_coarse - p(n))/p(n), roundoff_floor(nu, Omega)),

(p_coarse is itself the quotient of a trial function, so also an upper bound of the load).
This bounds the true error of p(n) as long as e(n) <= e(n - Delta)/2 (measured). It is used
only once n - Delta >= |Omega| (past the plateau); otherwise the estimate is inf and the
result flagged. The a priori degree (:func:`initial_degree`) is an empirical fit of the
degree where the error reaches tol, plus Delta; if the estimate misses tol the degree is
raised until it meets it or reaches :data:`N_MAX`.

Measured accuracy, cost and range
---------------------------------
Against the mpmath characteristic equation (:mod:`spectral_rod.rod.characteristic`, 40 digits;
the Ritz code never calls it), default tol = 1e-12:

* Omega in [0, 100] (step 1) x nu in {1, 1 + 1e-6, 1.01, 1.1, 1.5, 2, 4, 10, 30, 100}
  (1010 points): worst relative error 3.1e-15, every point converged, error <= estimate;
* Omega in [0, 100] (step 5) x nu in {1e3, 1e4}: worst 1.4e-14 (the eps sqrt(nu) floor);
* Omega in {200, 300, 500, 700, 1000} x nu in {2, 100, 1e4}: worst 8.7e-15; checked once at
  Omega = 2000 too (error < 1e-15 from n = Omega + 76), outside the allowed range for cost.

Degree used: n = 20 (Omega = 0), 36 (10), 82 (50), 138 (100), 350 (300), 1066 (1000).
Time per point (p*, both families; one BLAS thread, as the ``reproduce`` pipeline runs):
0.5 ms at Omega = 0, 1.6 ms at 50, 5 ms at 100, 28 ms at 300, 0.45 s at 1000 (the QR and
the eigen-solve are O(n^3)); with the default multi-threaded BLAS on the busy 2-core machine
anywhere from the same to 10-40x slower (thread contention; the measurements scatter).

Where it stops: |Omega(L)| <= :data:`RITZ_MAX_TWIST` = 1000 by cost (n ~ |Omega| + 66, time
~ |Omega|^3), not by accuracy; a tol below the round-off floor eps (8 + 2 sqrt(nu) +
|Omega|/40) (e.g. 1e-14 for nu > ~340 at small twist) cannot be met and is reported as such
(ConvergenceWarning, no useless raise).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import blas, eigh, qr, solve_triangular

from spectral_rod._validation import (
    broadcast_points,
    check_nu,
    check_resolution,
    check_tol,
    check_twist,
)
from spectral_rod.errors import ConvergenceWarning
from spectral_rod.numerics.quadrature import gauss_legendre
from spectral_rod.rod.families import FAMILIES, FAMILY_DTYPE, check_family

__all__ = [
    "FAMILIES",
    "N_MAX",
    "RITZ_MAX_TWIST",
    "RitzLoad",
    "family_ritz_value",
    "initial_degree",
    "ritz_critical_load",
]

#: Degree range of y_tt (even): n + 1 unknowns per family. A forced n costs ~n^3: measured at
#: one point on a shared 2-core machine, 0.14 s at n = 320, 0.7 s at 640, 5.5 s at 1280.
N_MIN, N_MAX = 4, 1280
#: |Omega(L)| limit, by cost: n ~ |Omega| + 66 at tol 1e-12, ~0.5 s per point at 1000.
RITZ_MAX_TWIST = 1000.0
#: Bound on the relative change of the quotient caused by the quadrature of K.
QUADRATURE_BUDGET = 1.0e-18
EPS = float(np.finfo(float).eps)


# ---------------------------------------------------------------------------------------------
# Quadrature and basis
# ---------------------------------------------------------------------------------------------

def legendre_values(t: NDArray[np.float64], n: int) -> NDArray[np.float64]:
    """Orthonormal Legendre polynomials Pn_0..Pn_n at t, shape (len(t), n + 1).

    Example: ``legendre_values(np.array([1.0]), 1)`` is [[sqrt(1/2), sqrt(3/2)]].
    """
    p = np.empty((t.size, n + 1))
    p[:, 0] = 1.0
    if n >= 1:
        p[:, 1] = t
    for k in range(1, n):
        p[:, k + 1] = ((2 * k + 1) * t * p[:, k] - k * p[:, k - 1]) / (k + 1)
    return p * np.sqrt((2 * np.arange(n + 1) + 1) / 2)


@lru_cache(maxsize=16)
def mass_root(n: int) -> NDArray[np.float64]:
    """G (n + 2, n + 1) with G^T G = M = int y_j' y_k' dt exactly (module docstring).

    Column k holds the orthonormal-Legendre coefficients of y_k' (the slope of the basis
    function whose second derivative is Pn_k and which vanishes at t = +-1).
    Example: y_0 = sqrt(1/2) (t^2 - 1)/2, so y_0' = sqrt(1/2) t = Pn_1/sqrt(3) and column 0 is
    [0, 1/sqrt(3), 0, ...].
    """
    g = np.zeros((n + 2, n + 1))

    def coef(j: int) -> float:  # P_j = sqrt(2/(2j+1)) Pn_j
        return math.sqrt(2.0 / (2 * j + 1))

    for k in range(n + 1):
        nk = math.sqrt((2 * k + 1) / 2)
        if k == 0:
            g[1, 0] = nk * coef(1)
        elif k == 1:
            g[2, 1] = nk / 3 * coef(2)
        else:
            g[k + 1, k] = nk / (2 * k + 1) * coef(k + 1)
            g[k - 1, k] = -nk / (2 * k + 1) * coef(k - 1)
    g.flags.writeable = False
    return g


def chebyshev_degree(twist_angle: float, nu: float, n: int) -> int:
    """Smallest d with nu (n + 1) 4 (2n + 1) sum_{m > d} Kapteyn(m) <= QUADRATURE_BUDGET.

    d is the Chebyshev degree after which cos/sin(Omega t) are truncated in the quadrature
    error bound; Kapteyn's bound on |J_m(Omega)| (module docstring) for m >= |Omega|; d = 0 at
    Omega = 0.
    Example: ``chebyshev_degree(100.0, 10.0, 130)`` is about 170.
    """
    om = abs(float(twist_angle))
    if om == 0.0:
        return 0
    start = max(1, math.ceil(om))
    m = np.arange(start, start + 400 + math.ceil(25 * om ** (1 / 3)))
    z = om / m
    r = np.sqrt((1 - z) * (1 + z))
    # log(Omega) - log(m), not log(z): z underflows to 0 at subnormal twist (divide warning)
    log_bound = m * (math.log(om) - np.log(m) + r - np.log1p(r))
    tail = np.cumsum(np.exp(log_bound)[::-1])[::-1]  # tail[i] = sum_{j >= i} bound_j
    scale = 4.0 * (2 * n + 1) * (n + 1) * nu
    ok = np.flatnonzero(scale * tail <= QUADRATURE_BUDGET)
    if ok.size == 0:  # pragma: no cover - the range above reaches exp(-400) and beyond
        raise RuntimeError(f"Kapteyn tail not below the budget (twist_angle={om}, n={n})")
    return int(m[ok[0]] - 1)


def quadrature_size(twist_angle: float, nu: float, n: int) -> int:
    """Gauss–Legendre nodes q: exact for the mass, within the budget for the stiffness."""
    return max(n + 2, n + (chebyshev_degree(twist_angle, nu, n) + 2) // 2)


def _half_rule(q: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Nodes t >= 0 of the q-point rule and weights for even integrands (doubled)."""
    t, w = gauss_legendre(q)
    h = q // 2
    tp, wp = t[h:], 2.0 * w[h:]
    if q % 2:
        wp = wp.copy()
        wp[0] /= 2  # the node t = 0 is not mirrored
    return tp, wp


# ---------------------------------------------------------------------------------------------
# The Ritz pencil of one family
# ---------------------------------------------------------------------------------------------

def stiffness_root(twist_angle: float, nu: float, n: int, family: str) -> NDArray[np.float64]:
    """F with F^T F = K = int y_tt^T S(t) y_tt dt for the family at degree n (module docstring).

    Rows: omega1 and sqrt(nu) omega2 of the basis functions at the nodes t >= 0, times the
    square roots of the doubled weights. In the mid-span frame u0 = (cos phi, sin phi) with
    phi = Omega t/2, so omega1 = cos(phi) y1'' + sin(phi) y2'', omega2 = -sin(phi) y1'' +
    cos(phi) y2''. Example: at Omega = 0 and nu = 1, F^T F is the identity.
    """
    q = quadrature_size(twist_angle, nu, n)
    t, w = _half_rule(q)
    a = legendre_values(t, n) * np.sqrt(w)[:, None]
    first = (np.arange(n + 1) % 2) == (0 if family == "symmetric" else 1)  # column is y1's
    phi = twist_angle * t / 2
    c, s = np.cos(phi)[:, None], np.sin(phi)[:, None]
    f1 = np.where(first, c, s) * a
    f2 = np.where(first, -s, c) * (math.sqrt(nu) * a)
    return np.vstack([f1, f2])


def ritz_matrix(twist_angle: float, nu: float, n: int, family: str) -> NDArray[np.float64]:
    """C = R^{-T} M R^{-1} (F = Q R): its eigenvalues are theta = 1/lambda of the family.

    Its leading (j + 1) x (j + 1) block is the same matrix at degree j (R of the leading
    columns is the leading block of R): the nested spaces in one factorisation. Only the
    upper triangle is filled. Every BLAS call here and in :func:`family_ritz_value` goes to
    scipy's BLAS: mixing in numpy's (a separate OpenBLAS thread pool) was measured 3-10x
    slower at n ~ 140 on the busy 2-core machine.
    """
    r = qr(stiffness_root(twist_angle, nu, n, family), mode="r", overwrite_a=True,
           check_finite=False)[0][: n + 1]
    zt = solve_triangular(r, mass_root(n).T, trans="T", check_finite=False)  # (G R^{-1})^T
    return blas.dsyrk(1.0, zt)


def estimate_gap(twist_angle: float) -> int:
    """Delta (even) between the degree and the coarser level of the error estimate.

    4 + 2 floor(|Omega|^(1/3)/2) (the cube root exact at cubes: ``** (1/3)`` gives 9.99... at
    1000): 4 below |Omega| = 8, 8 at 100, 14 at 1000. The measured error ratio over 4 degrees
    past the transition grows from ~1e-3 (Omega = 5) to 0.26 (Omega = 500), 0.4 at 1000; this
    Delta keeps the gain over Delta >= 25.

    >>> [estimate_gap(w) for w in (5.0, 100.0, 1000.0)]
    [4, 8, 14]
    """
    return 4 + 2 * int(float(np.cbrt(abs(twist_angle))) / 2)


def family_ritz_value(twist_angle: float, nu: float, n: int, family: str
                      ) -> tuple[float, float]:
    """(p(n), p_coarse) of one family: the Ritz value and the projected-mode quotient.

    p(n) = 4/(pi^2 theta_max) is an upper bound of the family's lowest load; p_coarse >= p(n -
    Delta) >= p(n) is the Rayleigh quotient of the energy-orthogonal projection of the Ritz mode
    onto degree n - Delta (:func:`estimate_gap`); nan if n - Delta < 0.
    Example: ``family_ritz_value(0.0, 2.0, 12, "symmetric")[0]`` is 1 to ~1e-16 (Euler).
    """
    om = abs(float(twist_angle))
    c = ritz_matrix(om, float(nu), n, family)
    m = n + 1
    theta, vec = eigh(c, lower=False, subset_by_index=[m - 1, m - 1], check_finite=False)
    p = 4.0 / (math.pi**2 * theta[0])
    k = m - estimate_gap(om)
    if k < 1:
        return p, math.nan
    v = vec[:k, 0]
    # in R-coordinates K = I, so truncating v is the energy-orthogonal projection
    cv = blas.dsymv(1.0, c[:k, :k], v, lower=0)
    theta_c = blas.ddot(v, cv) / blas.ddot(v, v)
    return p, 4.0 / (math.pi**2 * theta_c)


# ---------------------------------------------------------------------------------------------
# Resolution control
# ---------------------------------------------------------------------------------------------

def roundoff_floor(nu: float, twist_angle: float = 0.0) -> float:
    """Round-off part of the estimate, eps (8 + 2 sqrt(nu) + |Omega|/40) (relative).

    Measured: the largest error of converged values (degree initial_degree(Omega, 1e-14) and
    up to 60 above) against the mpmath reference over Omega in [0, 200] (14 values), both
    families, was 4 eps at nu = 2, 12.5 eps at 100, 31 eps at 1e3, 99 eps at 1e4, i.e.
    ~ eps sqrt(nu) (the QR's backward error relative to the mode's energy); the model has a
    safety factor 2. Example: ``roundoff_floor(1e4)`` is 4.6e-14. The |Omega|/40 term: at large
    twist the round-off grows with it: on 1,589 random values (Omega(L) in [400, 1000], nu - 1
    in [1e-7, 1e-5], either family, against 50-digit family roots; recomputed by
    tests/bench/measure_error_floors.py) the error reached 29 eps, 2.9 times the floor without
    the term; with it the error is <= 0.84 of the estimate and a value below the reference is
    short by <= 0.57 of the floor.
    """
    return EPS * (8.0 + 2.0 * math.sqrt(nu) + abs(twist_angle) / 40.0)


def initial_degree(twist_angle: float, tol: float) -> int:
    """A priori degree: |Omega| + 4 + 0.5 L + 0.35 L (1 + |Omega|)^(1/3) + Delta, even.

    L = log10(1/tol). The part before Delta fits the degree at which the error first stays
    below tol, measured on Omega in [0, 500], nu in [1 + 1e-6, 1e4], both families, tol in
    [1e-14, 1e-2] (at most 2 too low in 7 % of 120 cases; the worst case of the nu grid at each
    Omega was fitted). Example: ``initial_degree(100.0, 1e-12)`` is 138.
    """
    om = abs(float(twist_angle))
    big_l = -math.log10(tol)
    x = om + 4 + 0.5 * big_l + 0.35 * big_l * (1 + om) ** (1 / 3)
    n = 2 * math.ceil(x / 2) + estimate_gap(om)
    return min(max(n, N_MIN), N_MAX)


def _raise_degree(n: int) -> int:
    """The next degree tried when the estimate misses tol (~6 % more, at least 4)."""
    return min(N_MAX, n + max(4, 2 * math.ceil(0.03 * n)))


def _estimate(p: float, p_coarse: float, n: int, twist_angle: float, nu: float) -> float:
    """Relative error estimate of p(n): inf on the plateau (n - Delta < |Omega|)."""
    if math.isnan(p_coarse) or n - estimate_gap(twist_angle) < abs(twist_angle):
        return math.inf
    return max((p_coarse - p) / p, roundoff_floor(nu, twist_angle))


def resolve_family(twist_angle: float, nu: float, family: str, tol: float,
                   n: int | None = None) -> tuple[float, int, float]:
    """(p, degree, error estimate) of one family; automatic degree unless ``n`` is given."""
    om, nu = abs(float(twist_angle)), float(nu)
    deg = initial_degree(om, tol) if n is None else n
    while True:
        p, p_coarse = family_ritz_value(om, nu, deg, family)
        est = _estimate(p, p_coarse, deg, om, nu)
        # at the round-off floor a higher degree cannot help
        if n is not None or est <= max(tol, roundoff_floor(nu, om)) or deg >= N_MAX:
            return p, deg, est
        deg = _raise_degree(deg)


# ---------------------------------------------------------------------------------------------
# Public entry point
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class RitzLoad:
    """Result of :func:`ritz_critical_load` with ``full_output=True``.

    p_star: the Ritz upper bound (p* or the requested family's lowest load); n: degree of y_tt
    used (of the critical family); error_estimate: relative, see the module docstring (inf:
    no estimate, n on the plateau); family: the family of p_star; converged: error_estimate <=
    tol; tol. Arrays shaped like the broadcast input; Python scalars for scalar input.

    Examples
    --------
    >>> r = ritz_critical_load([0.0, 5.0], 1.5, full_output=True)
    >>> r.family.tolist(), r.converged.tolist()
    (['symmetric', 'symmetric'], [True, True])
    """

    p_star: NDArray[np.float64] | float
    n: NDArray[np.int_] | int
    error_estimate: NDArray[np.float64] | float
    family: NDArray[np.str_] | str
    converged: NDArray[np.bool_] | bool
    tol: float


def ritz_point(twist_angle: float, nu: float, family: str | None, tol: float,
           n: int | None) -> tuple[float, int, float, str]:
    """(p, n, estimate, family) at one point; p* = the smaller family value."""
    fams = FAMILIES if family is None else (family,)
    res = {f: resolve_family(twist_angle, nu, f, tol, n) for f in fams}
    # ties (nu = 1, or a crossing within rounding) go to the symmetric family
    best = min(fams, key=lambda f: (res[f][0] * (1 - 8 * EPS) if f == "symmetric"
                                    else res[f][0]))
    p, deg, _ = res[best]
    est = max(r[2] for r in res.values())  # p* is within the larger family error
    return p, deg, est, best


def ritz_critical_load(twist_angle: ArrayLike, nu: ArrayLike, *, n: int | None = None,
                       tol: float = 1e-12, family: str | None = None,
                       full_output: bool = False):
    """Rayleigh–Ritz upper bound of p* = P_cr/(pi^2 A1/L^2) from the lab-frame energy.

    Each value is an upper bound (up to rounding) that decreases monotonically with n. If the
    error estimate misses ``tol`` a ConvergenceWarning is issued and the point is flagged
    ``converged=False``.

    Parameters
    ----------
    twist_angle : float or array_like
        Omega(L) = omega30 L in radians, |Omega(L)| <= RITZ_MAX_TWIST = 1000 (p* is even in
        it).
    nu : float or array_like
        I2/I1 in [1, 1e4].
    n : int, optional
        Degree of the curvature polynomials (even, 4..1280); None chooses it from ``tol``.
    tol : float
        Requested relative accuracy, 1e-14..1e-2.
    family : str, optional
        None for p* (the smaller of the two families), or "symmetric"/"antisymmetric" for that
        family's lowest load.
    full_output : bool
        Return a :class:`RitzLoad` instead of the load alone.

    Returns
    -------
    float, ndarray or RitzLoad
        p* (or the family's lowest load) as a float for scalar input, an ndarray of the
        broadcast shape for arrays; with ``full_output=True`` a :class:`RitzLoad` (degree,
        error estimate, family, converged flag).

    Examples
    --------
    The untwisted rod buckles at the Euler load, and at a twist the energy's upper bound meets
    the collocation solution of Eq. ``inst1`` (a formulation it shares nothing with):

    >>> round(ritz_critical_load(0.0, 3.0), 12)
    1.0
    >>> import spectral_rod as sr
    >>> r = ritz_critical_load(5.0, 1.5, full_output=True)
    >>> r.family, r.converged, abs(r.p_star / sr.critical_load(5.0, 1.5) - 1) < 1e-13
    ('symmetric', True, True)
    """
    twist = check_twist(twist_angle, max_abs=RITZ_MAX_TWIST)
    nu_arr = check_nu(nu)
    tol = check_tol(tol)
    if n is not None:
        n = check_resolution(n, minimum=N_MIN, maximum=N_MAX)
    if family is not None:
        family = check_family(family)
    if not isinstance(full_output, (bool, np.bool_)):
        raise TypeError(f"full_output must be True or False, got {type(full_output).__name__}")
    shape = broadcast_points(twist_angle=twist, nu=nu_arr)
    tw = np.broadcast_to(twist, shape).ravel()
    nv = np.broadcast_to(nu_arr, shape).ravel()
    rows = [ritz_point(float(a), float(b), family, tol, n) for a, b in zip(tw, nv, strict=True)]
    p = np.array([r[0] for r in rows])
    deg = np.array([r[1] for r in rows], dtype=int)
    err = np.array([r[2] for r in rows])
    fam = np.array([r[3] for r in rows], dtype=FAMILY_DTYPE)
    converged = err <= tol
    if not converged.all():
        bad = np.flatnonzero(~converged)
        i = bad[np.argmax(err[bad])]
        why = ("n - Delta < |Omega|: the degree is on the plateau below the transition"
               if not np.isfinite(err[i]) else f"n capped at {N_MAX} or fixed by the caller")
        warnings.warn(
            f"ritz_critical_load: tol={tol:g} not met at {bad.size} point(s); worst error "
            f"estimate {err[i]:.2e} at twist_angle={tw[i]:g}, nu={nv[i]:g}, n={deg[i]} ({why})",
            ConvergenceWarning, stacklevel=2)
    if full_output:
        if shape == ():
            return RitzLoad(float(p[0]), int(deg[0]), float(err[0]), str(fam[0]),
                            bool(converged[0]), tol)
        return RitzLoad(p.reshape(shape), deg.reshape(shape), err.reshape(shape),
                        fam.reshape(shape), converged.reshape(shape), tol)
    return float(p[0]) if shape == () else p.reshape(shape)
