r"""Critical load of a hinged, spontaneously twisted straight rod by Chebyshev collocation.

The physics (paper, section "Stability of a rectilinear rod", Eq. ``inst1``)
-----------------------------------------------------------------------------
With s/L in [0, 1], the total twist angle Omega = omega30 L, nu = A2/A1 = I2/I1 >= 1 and the
load lambda = P L^2 / A1 = pi^2 p*, Eq. ``inst1`` for the curvatures omega1, omega2 reads

    -omega1'' + Omega^2 omega1 + 2 nu Omega omega2'          = lambda omega1
    -nu omega2'' + nu Omega^2 omega2 - 2 Omega omega1'       = lambda omega2

Hinged ends: x1 = x2 = 0 and x1'' = x2'' = 0 at s = 0, L. Since x'' is omega rotated by the
twist angle (the paper's geometric relations), x'' = 0 <=> omega1 = omega2 = 0. The conditions
x = 0 are then implied: moment balance of the rod between an end and s, with the end moments
zero, gives A1 omega1 = -P xi and A2 omega2 = -P eta, where (xi, eta) are the displacement
components along (u0, v0); omega = 0 at an end is therefore x = 0 there, and conversely any
solution of ``inst1`` with omega = 0 at both ends gives a centreline with x = x'' = 0 at both ends
(see :func:`buckling_mode`, which integrates x'' = R(Omega s) omega and checks this). So:

    hinged ends  <=>  omega1 = omega2 = 0 at s = 0 and s = L.

Multiplied by A1 and A2 the equations form a self-adjoint, positive definite pencil, so all
eigenvalues are real and positive; the Rayleigh quotient of the energy gives the rigorous
bounds 1 <= p* <= (1 + nu)/2 (Wirtinger's inequality below, planar trial modes above).

Discretisation
--------------
Reflection s -> 1 - s maps solutions to solutions with (omega1, omega2)(s) -> (omega1, -omega2)
(1 - s), so every mode is *symmetric* (omega1 even, omega2 odd about s = 1/2; the Euler mode's
family) or *antisymmetric* (omega1 odd, omega2 even). Each family is discretised separately
in the parity integration bases of :mod:`spectral_rod.chebyshev` (degree n; n/2 and n/2 - 1
unknowns per field), which gives a generalised eigenproblem A c = lambda B c with square B
(the collocation values of the basis). We solve the equivalent standard problem
A^{-1} B theta = theta (theta = 1/lambda): all its matrices are O(1), so round-off does not
grow like n^4 as it does with differentiation matrices.

Choosing the physical eigenvalue (the rule)
-------------------------------------------
The continuous spectrum is real and >= pi^2. Collocation adds spurious eigenvalues that are
complex or very large (theta near 0). From each family we keep theta with |Im theta| <= 1e-8
|theta| and Re theta > 0 and take the largest (the smallest lambda); p* is the smaller of the
two families. The
choice is accepted only if the mode's Chebyshev coefficients have decayed to the tolerance
(a spurious mode is unresolved by construction) and p* >= 1 - tol (the proven lower bound);
otherwise the resolution is increased or the result is flagged as not converged.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import numpy.polynomial.chebyshev as C
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import check_nu, check_resolution, check_tol, check_twist
from spectral_rod.chebyshev import ParityBasis, parity_basis, tail

FAMILIES = ("symmetric", "antisymmetric")
N_MIN, N_MAX = 8, 512
#: Eigenvalues with |Im| above this fraction of |lambda| are complex, i.e. not physical.
IMAG_REL = 1.0e-8
#: The coefficient tail must be this much below tol (eigenvalue errors are ~ tail; see tests).
TAIL_SAFETY = 1.0


class ConvergenceWarning(RuntimeWarning):
    """The requested tolerance was not met (resolution cap or round-off)."""


@dataclass(frozen=True)
class FamilyOperator:
    """The collocation pencil A(Omega, nu) c = lambda B c of one parity family at degree n.

    c are the Chebyshev coefficients of (omega1'', omega2'') in the integration bases of
    :mod:`spectral_rod.chebyshev` (omega1 block first); with d/ds = 2 d/dx,

        A = [[-4 D2_1 + Omega^2 V_1,   4 nu Omega D1_2   ],
             [-4 Omega D1_1,           nu (-4 D2_2 + Omega^2 V_2)]],   B = diag(V_1, V_2),

    where V, D1, D2 are values and x-derivatives of the bases at the equations' points.
    """

    n: int
    family: str
    basis1: ParityBasis  # omega1's basis at equation-1 points
    basis2: ParityBasis  # omega2's basis at equation-2 points
    coupling12: NDArray[np.float64]  # d/dx of omega2's basis at equation-1 points
    coupling21: NDArray[np.float64]  # d/dx of omega1's basis at equation-2 points

    @property
    def sizes(self) -> tuple[int, int]:
        return self.basis1.value.shape[1], self.basis2.value.shape[1]

    def pencil(self, twist_angle: ArrayLike, nu: ArrayLike
               ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """A for broadcast arrays `twist_angle`, `nu` (shape (..., m, m)), and B (m, m)."""
        om = np.asarray(twist_angle, dtype=float)[..., None, None]
        nu = np.asarray(nu, dtype=float)[..., None, None]
        k1, k2 = self.sizes
        b1, b2 = self.basis1, self.basis2
        shape = (*np.broadcast_shapes(om.shape, nu.shape)[:-2], k1 + k2, k1 + k2)
        a = np.empty(shape)
        a[..., :k1, :k1] = -4.0 * b1.d2 + om**2 * b1.value
        a[..., :k1, k1:] = 4.0 * nu * om * self.coupling12
        a[..., k1:, :k1] = -4.0 * om * self.coupling21
        a[..., k1:, k1:] = nu * (-4.0 * b2.d2 + om**2 * b2.value)
        b = np.zeros((k1 + k2, k1 + k2))
        b[:k1, :k1] = b1.value
        b[k1:, k1:] = b2.value
        return a, b

    def split(self, c: NDArray[np.generic]) -> tuple[NDArray[np.generic], NDArray[np.generic]]:
        """Chebyshev coefficients (in x) of (omega1, omega2) from an eigenvector."""
        k1 = self.sizes[0]
        return (self.basis1.chebyshev_coefficients(c[:k1]),
                self.basis2.chebyshev_coefficients(c[k1:]))


@lru_cache(maxsize=128)
def family_operator(n: int, family: str) -> FamilyOperator:
    """Assemble the (n, family) pieces once (they do not depend on Omega or nu)."""
    if family == "symmetric":  # omega1 even: equation 1 at all half points; omega2 odd
        p1, pts1, p2, pts2 = 0, "all", 1, "positive"
    elif family == "antisymmetric":  # omega1 odd, omega2 even
        p1, pts1, p2, pts2 = 1, "positive", 0, "all"
    else:
        raise ValueError(f"family must be one of {FAMILIES}, got {family!r}")
    return FamilyOperator(
        n=n, family=family,
        basis1=parity_basis(n, p1, pts1), basis2=parity_basis(n, p2, pts2),
        coupling12=parity_basis(n, p2, pts1).d1, coupling21=parity_basis(n, p1, pts2).d1)


@dataclass(frozen=True)
class CriticalLoad:
    """Result of :func:`critical_load` with ``full_output=True`` (arrays broadcast like input).

    p_star: P_cr / (pi^2 A1 / L^2); n: Chebyshev degree used; error_estimate: estimated relative
    error of p_star (coefficient tail of the buckling mode); family: 'symmetric' (omega1 even
    about the mid-point) or 'antisymmetric'; converged: error_estimate <= tol.
    """

    p_star: NDArray[np.float64]
    n: NDArray[np.int_]
    error_estimate: NDArray[np.float64]
    family: NDArray[np.str_]
    converged: NDArray[np.bool_]
    tol: float


def initial_degree(twist_angle: NDArray[np.float64], nu: NDArray[np.float64],
                   tol: float) -> NDArray[np.int_]:
    """A priori Chebyshev degree from the mode's largest wavenumber.

    The critical mode is a sum of cos/sin(beta_k s) with beta_k^2 the roots of the
    characteristic equation; at the load (at most (1 + nu)/2 pi^2) the larger root is below
    beta_max^2 = lambda (1 + 1/nu) + 2 Omega^2 ... we use beta_max = sqrt(2) (|Omega| + pi).
    On x in [-1, 1] this is frequency k = beta_max / 2, and the Chebyshev coefficients of
    cos(k x) fall like J_j(k) ~ (e k / 2 j)^j; we take the smallest even j with (e k/2j)^j below
    tol/100. The a-posteriori coefficient check then confirms or raises the degree.
    """
    k = (np.abs(twist_angle) + np.pi) / 2.0 * np.where(nu > 1.0, 1.0, 1.0)
    j = np.arange(4, N_MAX + 1, 2)
    # log10 of the bound for each candidate degree, vectorised over points
    with np.errstate(divide="ignore"):
        logb = j * np.log10(np.e * k[..., None] / (2.0 * j))
    ok = logb <= math.log10(tol) - 2.0
    first = np.where(ok.any(axis=-1), ok.argmax(axis=-1), j.size - 1)
    return np.maximum(j[first], N_MIN)


def _lowest_physical(theta: NDArray[np.complex128]) -> NDArray[np.int_]:
    """Index of the largest real positive theta = 1/lambda in each row (the rule above)."""
    ok = (np.abs(theta.imag) <= IMAG_REL * np.abs(theta)) & (theta.real > 0)
    return np.argmax(np.where(ok, theta.real, -np.inf), axis=-1)


def _mode_tail(op: FamilyOperator, c: NDArray[np.generic]) -> float:
    """Coefficient tail of the mode (omega1, omega2), relative to the larger field.

    A field that vanishes (omega2 at zero twist) has no meaningful tail of its own.
    """
    c1, c2 = op.split(c)
    scale = max(np.abs(c1).max(), np.abs(c2).max())
    if scale == 0.0:
        return math.inf
    return max(tail(c1, op.basis1.parity) * np.abs(c1).max() / scale,
               tail(c2, op.basis2.parity) * np.abs(c2).max() / scale)


def solve_family(n: int, family: str, twist: NDArray[np.float64], nu: NDArray[np.float64]
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Lowest physical lambda = pi^2 p, its mode's coefficient tail, and the eigenvectors.

    Solves the inverse pencil A^{-1} B (eigenvalues theta = 1/lambda): its matrices are O(1) and
    spurious modes land near theta = 0, far from the physical theta = 1/lambda_min.
    Returns lambda = inf where no eigenvalue passes the rule.
    """
    op = family_operator(n, family)
    a, b = op.pencil(twist, nu)
    theta, vec = np.linalg.eig(np.linalg.solve(a, b))
    idx = _lowest_physical(theta)
    rows = np.arange(theta.shape[0])
    th = theta[rows, idx]
    valid = (np.abs(th.imag) <= IMAG_REL * np.abs(th)) & (th.real > 0)
    v = vec[rows, :, idx].real
    tails = np.array([_mode_tail(op, vi) for vi in v])
    lam = np.where(valid, 1.0 / np.where(valid, th.real, 1.0), np.inf)
    return lam, np.where(valid, tails, np.inf), v


def _solve_points(twist: NDArray[np.float64], nu: NDArray[np.float64], n: NDArray[np.int_]):
    """p*, family index and tail for flat arrays of points at the given degrees."""
    p = np.empty(twist.size)
    fam = np.empty(twist.size, dtype=int)
    err = np.empty(twist.size)
    for deg in np.unique(n):
        sel = np.flatnonzero(n == deg)
        lam = np.empty((2, sel.size))
        tails = np.empty((2, sel.size))
        for f, family in enumerate(FAMILIES):
            lam[f], tails[f], _ = solve_family(int(deg), family, twist[sel], nu[sel])
        best = np.argmin(lam, axis=0)
        cols = np.arange(sel.size)
        p[sel] = lam[best, cols] / np.pi**2
        fam[sel] = best
        # if the two families are within the tolerance of each other either could be lowest;
        # both must then be resolved
        err[sel] = np.where(np.abs(lam[0] - lam[1]) <= 1e-6 * lam.min(axis=0),
                            tails.max(axis=0), tails[best, cols])
    return p, fam, err


def collocation_critical_load(twist_angle: ArrayLike, nu: ArrayLike, *, n: int | None = None,
                              tol: float = 1e-12, full_output: bool = False):
    """Critical load p* = P_cr / (pi^2 A1 / L^2) of the hinged twisted rod (Eq. ``inst1``)
    by Chebyshev collocation (the public :func:`spectral_rod.critical_load` routes here).

    Parameters
    ----------
    twist_angle : total spontaneous twist Omega(L) = omega30 L in radians (|.| <= 1e4).
        p* is even in it (reflection of the twist sense), so negative angles are allowed.
    nu : I2 / I1 = A2 / A1 >= 1 (the paper's convention A1 <= A2).
    n : Chebyshev degree (even, 8..512). ``None`` chooses it automatically: an a priori degree
        from the mode's wavenumber (:func:`initial_degree`), then the Chebyshev coefficients of
        the computed buckling mode (omega1, omega2) must have decayed below ``tol`` in their
        last two entries; if not, the degree is raised by ~40 % until they do or n = 512.
    tol : requested relative accuracy of p* (1e-14..1e-2).
    full_output : return a :class:`CriticalLoad` with the degree used, the error estimate,
        the mode family and a converged flag, instead of p* alone.

    Returns p* as a float for scalar input, otherwise an ndarray of the broadcast shape.
    If ``tol`` is not met (cap reached), a :class:`ConvergenceWarning` is issued and the result
    is flagged ``converged=False`` in the full output; it is never returned silently.
    """
    twist = check_twist(twist_angle)
    nu_arr = check_nu(nu)
    tol = check_tol(tol)
    shape = np.broadcast_shapes(twist.shape, nu_arr.shape)
    tw = np.abs(np.broadcast_to(twist, shape).ravel())
    nv = np.broadcast_to(nu_arr, shape).ravel()
    if n is not None:
        deg = np.full(tw.size, check_resolution(n, minimum=N_MIN, maximum=N_MAX))
        p, fam, err = _solve_points(tw, nv, deg)
    else:
        deg = initial_degree(tw, nv, tol)
        p, fam, err = _solve_points(tw, nv, deg)
        todo = np.flatnonzero(err > tol * TAIL_SAFETY)
        while todo.size:
            grow = deg[todo] < N_MAX
            todo = todo[grow]
            if not todo.size:
                break
            deg[todo] = np.minimum(N_MAX, 2 * np.ceil(deg[todo] * 0.7).astype(int))
            p[todo], fam[todo], err[todo] = _solve_points(tw[todo], nv[todo], deg[todo])
            todo = todo[err[todo] > tol * TAIL_SAFETY]
    converged = err <= tol * TAIL_SAFETY
    if n is None and not converged.all():
        bad = np.flatnonzero(~converged)
        warnings.warn(
            f"critical_load: tol={tol:g} not met at {bad.size} point(s) (n capped at {N_MAX}; "
            f"worst error estimate {err[bad].max():.2e} at twist_angle={tw[bad[0]]:g}, "
            f"nu={nv[bad[0]]:g})", ConvergenceWarning, stacklevel=2)
    if full_output:
        return CriticalLoad(p_star=p.reshape(shape), n=deg.reshape(shape),
                            error_estimate=err.reshape(shape),
                            family=np.asarray(FAMILIES)[fam].reshape(shape),
                            converged=converged.reshape(shape), tol=tol)
    return float(p[0]) if shape == () else p.reshape(shape)


def critical_wavenumbers(p_star: float, twist_angle: float, nu: float
                         ) -> tuple[complex | float, complex | float]:
    """The paper's wavenumbers (beta_1 L, beta_2 L), beta_1 <= beta_2, at load p*.

    beta_k^2 L^2 = X_-, X_+ are the roots of the characteristic equation of ``inst1``,
    (lambda - Omega^2 - X)(lambda/nu - Omega^2 - X) = 4 Omega^2 X with lambda = pi^2 p*.
    When X_- < 0 (lambda/nu < Omega^2 < lambda) beta_1 is imaginary and returned as a complex
    number i sqrt(-X_-).
    """
    lam = np.pi**2 * float(p_star)
    om = float(twist_angle)
    mu = lam / float(nu)
    s = lam + mu + 2 * om**2
    x_plus = 0.5 * (s + math.sqrt((lam - mu) ** 2 + 8 * om**2 * (lam + mu)))
    x_minus = (lam - om**2) * (mu - om**2) / x_plus
    beta1 = math.sqrt(x_minus) if x_minus >= 0 else complex(0.0, math.sqrt(-x_minus))
    return beta1, math.sqrt(x_plus)


@dataclass(frozen=True)
class BucklingMode:
    """The critical mode of the hinged twisted rod on a uniform grid s/L in [0, 1].

    omega1, omega2: curvatures in the body frame (u0, v0), scaled so that max |omega| = 1;
    x1, x2: the centreline displacement in the fixed frame (e1, e2), obtained by integrating the
    paper's geometric relations x'' = R(Omega s) omega with x = 0 at both ends (units of L when
    omega is in units of 1/L); beta1, beta2: the critical wavenumbers times L (beta1 complex when
    imaginary); family: 'symmetric' or 'antisymmetric' about s = L/2.
    """

    s: NDArray[np.float64]
    omega1: NDArray[np.float64]
    omega2: NDArray[np.float64]
    x1: NDArray[np.float64]
    x2: NDArray[np.float64]
    p_star: float
    twist_angle: float
    nu: float
    family: str
    n: int
    beta1: complex | float
    beta2: float


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
        g = C.Chebyshev(C.chebint(C.chebfit(xs, f / 4.0, m - 1), 2))  # d2/ds2 = 4 d2/dx2
        left, right = g(-1.0), g(1.0)
        out.append(g - C.Chebyshev([(left + right) / 2, (right - left) / 2]))
    return out[0], out[1]


def buckling_mode(twist_angle: float, nu: float, *, n: int | None = None, tol: float = 1e-12,
                  points: int = 201) -> BucklingMode:
    """The buckling mode at p* (Eq. ``inst1``): curvatures, centreline and wavenumbers.

    Resolution as in :func:`critical_load`; ``points`` is the size of the output grid.
    """
    res = collocation_critical_load(twist_angle, nu, n=n, tol=tol, full_output=True)
    if isinstance(points, bool) or not isinstance(points, int) or points < 2:
        raise ValueError(f"points must be an integer >= 2, got {points!r}")
    twist = float(twist_angle)
    deg, family = int(res.n), str(res.family)
    op = family_operator(deg, family)
    _, _, vec = solve_family(deg, family, np.array([abs(twist)]), np.array([float(nu)]))
    c1, c2 = op.split(vec[0])
    if twist < 0:  # p* is even in Omega; the mode of -Omega is the mirror image (omega2 -> -)
        c2 = -c2
    s = np.linspace(0.0, 1.0, points)
    xs = 2 * s - 1
    w1, w2 = C.chebval(xs, c1), C.chebval(xs, c2)
    scale = np.max(np.abs(np.concatenate([w1, w2])))
    k = int(np.argmax(np.abs(np.concatenate([w1, w2]))))
    scale *= np.sign(np.concatenate([w1, w2])[k])
    x1, x2 = _centreline(c1 / scale, c2 / scale, twist, deg)
    beta1, beta2 = critical_wavenumbers(float(res.p_star), twist, float(nu))
    return BucklingMode(s=s, omega1=w1 / scale, omega2=w2 / scale, x1=x1(xs), x2=x2(xs),
                        p_star=float(res.p_star), twist_angle=twist, nu=float(nu),
                        family=family, n=deg, beta1=beta1, beta2=beta2)
