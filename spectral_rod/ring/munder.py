"""Ring stability, second formulation: the paper's equilibrium equations linearised numerically.

Why this formulation
--------------------
:mod:`spectral_rod.ring.second_variation` rests on one hand (sympy) derivation: the *second
variation*
of energy plus load *potential* in the reduced unknowns y_phi, y_z, alpha.  This module shares
none of it.  It starts from the paper's own *force balances*, Eq. ``Munder`` with Eq.
``constit`` and Eq. ``frenet``, keeps the loads as *forces* (no potential is used anywhere), keeps
every unknown field (no elimination by hand), and lets the computer do the linearisation: the
nonlinear residuals are evaluated in complex arithmetic at x0 + i h e_k (complex step, h =
1e-20), so Im(residual)/h is the exact derivative to round-off.  What the two formulations have
in common is only the model (Kirchhoff rod, the ring, the four readings of the load), which is
the point of the comparison.  A discrete rod (option (B)) would have rebuilt the energy and the load
potentials, i.e. the same *kind* of derivation as the first formulation; the equilibrium route
also tests Eq. ``Munder`` as printed, and the conservative-load potentials of the first
formulation independently.

Unknowns (periodic in s, R = 1, cylindrical components on e_r, e_phi, e_z)
--------------------------------------------------------------------------
* theta(s): rotation vector of the cross-section frame, d_i = exp(theta x) d_i0 (Rodrigues'
  formula, exact rotation for any theta);
* y(s): displacement of the centreline, R = R0 + y;
* f(s): perturbation of the tangential force, F_t = -q R + f (the base hoop force);
* six constants lambda = (lambda_F, lambda_M): amplitudes of the reaction load
  lambda_F + lambda_M x R0(s) that enforces the six rigid-body constraints int y ds = 0,
  int R0 x y ds = 0 (the same constraints as ``ring_stability``; the reaction is the gradient of
  the constraints, i.e. exactly the Lagrange multipliers of the constrained energy problem).

Residuals, each evaluated from the nonlinear expressions
--------------------------------------------------------
* Eq. ``frenet``: w1 = t'.u, w2 = t'.v, w3 = u'.v of the rotated frame (derivatives of the frame
  vectors by spectral differentiation of their sampled Cartesian components), w_k0 from the
  reference frame in the same way;
* Eq. ``constit``: M_u = -A2 (w2 - w20), M_v = A1 (w1 - w10), M_t = A3 (w3 - w30);
* Eq. ``Munder``, all four lines as printed, with q_u, q_v, q_t the components of the external
  force (load + reaction) on the *deformed* frame and m = 0;  lines 3 and 4 (the u and v
  components of the normal balance; as printed they equal -(F' + q).u and +(F' + q).v) are
  recombined into the normal force-balance vector -r3 u + r4 v and projected on e_r and e_z;
* kinematics (inextensible, unshearable): y' - (t - t0) = 0, three components;
* the six constraints.

Load models ("hydrostatic": q e_z x R'(s) per unit length, R' = t0 + y'; "axis": magnitude q,
horizontal, towards the ring's axis at the displaced point R0 + y; "centre": magnitude q,
towards the ring's centre point, -q R/|R|; "dead": -q e_r(s), fixed) are forces only.

With ``equations="kirchhoff"`` the Munder lines are replaced by the vector balances
M' + t x F = 0 and F' + q = 0 with the full force F = -q R t0 + dF (three more unknown fields
instead of f).  This variant does *not* use Eq. ``Munder``; agreement of the two numerically
verifies Munder as printed (the elimination of F_u, F_v).

Discretisation: every field is a real Fourier series with frequencies 0..M; fields are sampled at
P >= 2 M + 8 N + 21 equispaced points (odd: no Nyquist mode), which differentiates (FFT) and
integrates every *linearised* quantity exactly; the residuals are Galerkin-projected on the same
trigonometric functions.  All transforms act on real and imaginary parts separately: a complex
FFT would leak the round-off of the O(1) base state into the O(h) imaginary part (found the hard
way: it produced spurious couplings of size ~0.3).  The load
enters the residual linearly, so the Jacobian is the pencil J0 + q J1 (two complex-step passes,
q = 0 and q = 1).  Its nonzero pattern splits into independent blocks (measured, not assumed:
connected components of the pattern; for N > 0 they turn out to be the frequency families of
the twist); each block is Jacobi-equilibrated and solved as a generalised eigenproblem (QZ);
q_cr is the smallest positive real eigenvalue over all blocks.  The truncation M is raised until
two successive q_cr agree to ``tol``.

All loads are q R^3/(E1 I1): A1 = 1, A2 = nu, A3 = e (1 + nu).

Findings (``tests/test_ring_second_formulation.py``)
----------------------------------------------------
* The loaded circle with F_t = -q R and no moment satisfies all four lines of Eq. ``Munder``
  (residual ~1e-15), for every reading of the load.
* Eq. ``Munder`` as printed needs no correction (its lines 3 and 4 are -(F' + q).u and
  +(F' + q).v; only the way they are recombined before projection matters for the truncated
  system, see :func:`_residual`): it gives the same q_cr as the Kirchhoff vector
  balances (relative ~1e-15), and the same q_cr as the energy formulation on 23 cases
  (N = 0..8, nu = 1..4, e = 1 and 1/2.6, every reading of the load) to a few 1e-15; reversing
  the sign of any one of its 20 printed terms moves q_cr by at least 3.9 % (axis load, N = 2,
  nu = 2), so the agreement is not blind to a misprint.  (With the hydrostatic load q_t = 0
  identically, so that term's sign cannot matter there.)
* The closed forms (in plane 3, 4.5, 4.5, 4 A1/R^3 for the hydrostatic, axis, centre and dead
  readings, out of plane Timoshenko-Gere, twist-independence for nu = 1) are reproduced to
  ~1e-15 (``tests/test_ring_loads.py`` for the centre and dead readings).
* The measured blocks of the Jacobian are the frequency families f = +-n (mod 2N) of the
  twist, each split in two by the ring's reflection symmetry.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import cast

import numpy as np
import scipy.linalg
import scipy.sparse
import scipy.sparse.csgraph
from numpy.typing import NDArray

from spectral_rod._validation import check_bool, check_choice, check_int, check_real
from spectral_rod.errors import ConvergenceWarning, RingConvergenceError
from spectral_rod.ring.formula import check_e_ratio, check_scalar_nu, check_twist_count
from spectral_rod.ring.second_variation import (
    RingBuckling,
    check_load,
    check_reachable,
    refine,
    roundoff_floor,
    stiffnesses,
)

#: Residual systems: the paper's Eq. ``Munder`` or the Kirchhoff vector balances.
EQUATIONS = ("munder", "kirchhoff")
#: Unknown fields (cylindrical components) per system, in order.
FIELDS = {
    "munder": ("theta_r", "theta_phi", "theta_z", "y_r", "y_phi", "y_z", "f_t"),
    "kirchhoff": ("theta_r", "theta_phi", "theta_z", "y_r", "y_phi", "y_z", "F_r", "F_phi",
                  "F_z"),
}
#: Fields that move the ring in its plane (for N = 0 the blocks are purely in- or out-of-plane).
IN_PLANE_FIELDS = frozenset({"theta_z", "y_r", "y_phi", "f_t", "F_r", "F_phi"})
#: Largest twist accepted (cost grows like N).
MAX_TWIST = 30
#: Complex-step size: any h with h^2 below round-off of O(1) quantities gives the exact
#: derivative; no subtraction, so no cancellation.
STEP = 1.0e-20
#: Entries of the equilibrated Jacobian below this are round-off.  Measured on the 17 agreement
#: cases at their final truncation: round-off entries <= 4.6e-12 (growing slowly with M), true
#: couplings >= 4.7e-6; the threshold sits in the gap (a dropped coupling of this size would
#: move q by O(1e-9) at worst).
PATTERN_TOL = 1.0e-9
#: The split is made only if the entries leave a gap around PATTERN_TOL: the smallest entry
#: above it exceeds the largest nonzero entry below it by this factor.  Measured at the edges of
#: the parameter range (nu = 1e4, nu = 1 + 1e-6, e = 1e4, N = 30 at M = 248) the entries run
#: continuously through 1e-9 (no gap); the pencil is then solved as one block (exact, slower).
PATTERN_GAP = 100.0
#: An eigenvalue counts as real if |Im q| <= REAL_TOL |q|.  Measured: with the equations as
#: printed every finite eigenvalue of the 17 agreement cases is real to the last bit (QZ returns
#: 1 x 1 blocks), as it must be for conservative loads; a reversed term of Munder typically
#: produces pairs with |Im q|/|q| ~ 0.1.  A larger imaginary part triggers a ConvergenceWarning.
REAL_TOL = 1.0e-7
#: Columns evaluated per complex-step batch (bounds the memory to a few tens of MB).
BATCH = 256


# ---------------------------------------------------------------- grid, basis, geometry

@dataclass(frozen=True)
class _Grid:
    """Collocation grid for truncation M: frequencies 0..M per field, stored as the real
    coefficients (c_0, a_1, b_1, ..., a_M, b_M) of c_0 + sum a_f cos(f s) + b_f sin(f s)."""

    M: int
    s: NDArray[np.float64]  # P equispaced points on [0, 2 pi), P odd
    freq: NDArray[np.int64]  # frequency of each coefficient

    @property
    def P(self) -> int:
        return self.s.size

    @property
    def n_coef(self) -> int:
        return 2 * self.M + 1

    @property
    def weight(self) -> float:
        return 2.0 * np.pi / self.P


def _fft_size(n: int) -> int:
    """The smallest odd integer >= n with no prime factor above 7.

    Any odd P >= 2 M + 8 N + 21 is exact (:func:`_grid`); pocketfft is much slower on lengths
    with a large prime factor (measured on real FFTs of (181, P, 3) arrays along P, as in the
    Jacobian: 1.35 ms at the prime P = 61, 0.51 ms at P = 63). Not
    ``scipy.fft.next_fast_len``: it may return an even length, and P must be odd.

    >>> _fft_size(37), _fft_size(61), _fft_size(69)
    (45, 63, 75)
    """
    m = n if n % 2 else n + 1
    while True:
        r = m
        for f in (3, 5, 7):
            while r % f == 0:
                r //= f
        if r == 1:
            return m
        m += 2


def _grid(M: int, N: int) -> _Grid:
    """Grid with P >= 2 M + 8 N + 21 (odd) points: exact quadrature and differentiation of all
    linearised quantities, whose bandwidth is at most M + 3 N + 4; P is the next length FFTs
    are fast on (:func:`_fft_size`).

    >>> _grid(4, 1).P, _grid(4, 1).n_coef
    (45, 9)
    """
    P = _fft_size(2 * M + 8 * N + 21)
    s = np.arange(P, dtype=np.float64) * (2.0 * np.pi / P)
    return _Grid(M, s, np.array([0] + [f for f in range(1, M + 1) for _ in (0, 1)]))


# All transforms below act on real arrays; complex (complex-step) data is transformed part by
# part: a complex FFT would mix the O(1) round-off of the real (base) part into the O(h)
# imaginary part and destroy the complex step.  They use pocketfft only (no BLAS: a threaded
# BLAS on these small matrices is ~10x slower on a busy 2-core machine, measured).

def _by_parts(fn: Callable[[NDArray[np.float64]], NDArray[np.float64]], a: NDArray) -> NDArray:
    """fn applied to the real and imaginary parts of a separately."""
    if not np.iscomplexobj(a):
        return fn(a)
    return fn(a.real) + 1j * fn(a.imag)


def _synthesise(coef: NDArray, grid: _Grid) -> NDArray:
    """Values at the grid points (batch x P) of trigonometric coefficients (batch x 2M + 1)."""
    P = grid.P

    def real(c: NDArray[np.float64]) -> NDArray[np.float64]:
        X = np.zeros((c.shape[0], P // 2 + 1), complex)
        X[:, 0] = P * c[:, 0]
        X[:, 1:grid.M + 1] = 0.5 * P * (c[:, 1::2] - 1j * c[:, 2::2])
        return np.fft.irfft(X, n=P, axis=1)

    return _by_parts(real, coef)


def _project(values: NDArray, grid: _Grid) -> NDArray:
    """Galerkin projection int r(s) phi_j(s) ds on 1, cos(f s), sin(f s), f <= M (exact
    trapezoidal rule), of sampled fields (batch x P) -> (batch x 2M + 1)."""

    def real(v: NDArray[np.float64]) -> NDArray[np.float64]:
        R = np.fft.rfft(v, axis=1)[:, :grid.M + 1] * grid.weight
        out = np.empty((v.shape[0], grid.n_coef))
        out[:, 0] = R[:, 0].real
        out[:, 1::2], out[:, 2::2] = R[:, 1:].real, -R[:, 1:].imag
        return out

    return _by_parts(real, values)


def _ds(a: NDArray, grid: _Grid) -> NDArray:
    """Spectral derivative d/ds along axis 1 (the grid axis) of a batch of sampled fields
    (exact for every frequency below P/2; P odd, so no Nyquist mode)."""
    P = grid.P
    ik = 1j * np.arange(P // 2 + 1).reshape((1, P // 2 + 1) + (1,) * (a.ndim - 2))

    def real(x: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.fft.irfft(ik * np.fft.rfft(x, axis=1), n=P, axis=1)

    return _by_parts(real, a)


@dataclass(frozen=True)
class _Geometry:
    """Cylindrical unit vectors and the reference frame (paper, section "Stability of a ring")
    sampled on the grid, Cartesian components, shape (1, P, 3)."""

    e_r: NDArray[np.float64]
    e_phi: NDArray[np.float64]
    e_z: NDArray[np.float64]
    t0: NDArray[np.float64]
    u0: NDArray[np.float64]
    v0: NDArray[np.float64]


def _geometry(grid: _Grid, N: int) -> _Geometry:
    """t0 = e_phi, u0 = -cos(Omega) e_r + sin(Omega) e_z, v0 = sin(Omega) e_r + cos(Omega) e_z
    with Omega = N s (R = 1)."""
    s = grid.s
    om = N * s
    zero, one = np.zeros_like(s), np.ones_like(s)
    e_r = np.stack([np.cos(s), np.sin(s), zero], axis=-1)
    e_phi = np.stack([-np.sin(s), np.cos(s), zero], axis=-1)
    e_z = np.stack([zero, zero, one], axis=-1)
    u0 = -np.cos(om)[:, None] * e_r + np.sin(om)[:, None] * e_z
    v0 = np.sin(om)[:, None] * e_r + np.cos(om)[:, None] * e_z
    return _Geometry(*(a[None] for a in (e_r, e_phi, e_z, e_phi, u0, v0)))


def _dot(a: NDArray, b: NDArray) -> NDArray:
    """Componentwise a.b over the last axis, without conjugation (complex step)."""
    return np.sum(a * b, axis=-1)


def _sinc_terms(a2: NDArray[np.complex128]) -> tuple[NDArray, NDArray]:
    """sin(a)/a and (1 - cos a)/a^2 as analytic functions of a2 = a^2 (series near 0, where the
    complex step evaluates them)."""
    small = np.abs(a2) < 1.0e-8
    a = np.sqrt(np.where(small, 1.0, a2))
    c1 = np.where(small, 1.0 - a2 / 6.0 + a2**2 / 120.0, np.sin(a) / a)
    c2 = np.where(small, 0.5 - a2 / 24.0 + a2**2 / 720.0, (1.0 - np.cos(a)) / a**2)
    return c1, c2


def rotate(theta: NDArray, vec: NDArray) -> NDArray:
    """exp(theta x) vec by Rodrigues' formula (exact finite rotation; analytic in theta).

    >>> np.allclose(rotate(np.array([0, 0, np.pi / 2]), np.array([1.0, 0, 0])), [0, 1, 0])
    True
    """
    c1, c2 = _sinc_terms(_dot(theta, theta))
    tv = np.cross(theta, vec)
    return vec + c1[..., None] * tv + c2[..., None] * np.cross(theta, tv)


def _darboux(t: NDArray, u: NDArray, v: NDArray, grid: _Grid) -> tuple[NDArray, NDArray, NDArray]:
    """Eq. ``frenet``: w1 = t'.u, w2 = t'.v, w3 = u'.v (frame derivatives spectrally)."""
    dt, du = _ds(t, grid), _ds(u, grid)
    return _dot(dt, u), _dot(dt, v), _dot(du, v)


# ---------------------------------------------------------------- the nonlinear residual

@dataclass(frozen=True)
class _Problem:
    """Everything the residual needs for one (N, nu, e, load, M, equations)."""

    N: int
    stiff: tuple[float, float, float]
    load: str
    equations: str
    grid: _Grid
    geo: _Geometry
    w0: tuple[NDArray, NDArray, NDArray]
    flip: str | None = None  # one of MUNDER_TERMS to reverse (diagnostic), or None

    @property
    def fields(self) -> tuple[str, ...]:
        return FIELDS[self.equations]

    @property
    def n_field(self) -> int:
        return self.grid.n_coef

    @property
    def size(self) -> int:
        return len(self.fields) * self.n_field + 6


def reference_torsions(N: object, M: int = 8) -> tuple[NDArray[np.float64], ...]:
    """(s, w10, w20, w30) of the stress-free twisted ring (R = 1, Omega = N s): Eq. ``frenet``
    applied to the paper's frame t0 = e_phi, u0 = -cos Omega e_r + sin Omega e_z, v0 = sin Omega
    e_r + cos Omega e_z by spectral differentiation on this formulation's grid (truncation M),
    to be compared with the paper's w10 = cos Omega/R, w20 = -sin Omega/R, w30 = N/R.

    Returns
    -------
    tuple of four ndarray of float
        The grid s and the torsions w10, w20, w30 on it.

    Examples
    --------
    >>> import numpy as np
    >>> s, w10, w20, w30 = reference_torsions(2)
    >>> bool(np.allclose(w10, np.cos(2 * s)) and np.allclose(w20, -np.sin(2 * s))
    ...      and np.allclose(w30, 2.0))
    True
    """
    n_turns = check_twist_count(N, maximum=MAX_TWIST)
    grid = _grid(check_int(M, "M", 4, 200), n_turns)
    geo = _geometry(grid, n_turns)
    w0 = _darboux(geo.t0.astype(complex), geo.u0.astype(complex), geo.v0.astype(complex), grid)
    return (grid.s, *(np.real(np.squeeze(w)) for w in w0))


def _problem(N: int, nu: float, e_ratio: float, load: str, M: int, equations: str,
             flip: str | None = None) -> _Problem:
    if flip is not None and flip not in MUNDER_TERMS:
        raise ValueError(f"flip must be None or one of {MUNDER_TERMS}, got {flip!r}")
    grid = _grid(M, N)
    geo = _geometry(grid, N)
    w0 = _darboux(geo.t0.astype(complex), geo.u0.astype(complex), geo.v0.astype(complex), grid)
    return _Problem(N, stiffnesses(nu, e_ratio), load, equations, grid, geo, w0, flip)


def _sample(X: NDArray, prob: _Problem) -> dict[str, NDArray]:
    """Unknown coefficients (batch x size) -> sampled fields (batch x P) and lambda (batch x 6)."""
    n = prob.n_field
    out = {name: _synthesise(X[:, i * n:(i + 1) * n], prob.grid)
           for i, name in enumerate(prob.fields)}
    out["lambda"] = X[:, len(prob.fields) * n:]
    return out


def _cyl(g: _Geometry, r: NDArray, phi: NDArray, z: NDArray) -> NDArray:
    """Cartesian vector field (batch x P x 3) from cylindrical components (batch x P)."""
    return r[..., None] * g.e_r + phi[..., None] * g.e_phi + z[..., None] * g.e_z


def _to_cyl(g: _Geometry, vec: NDArray) -> list[NDArray]:
    return [_dot(vec, g.e_r), _dot(vec, g.e_phi), _dot(vec, g.e_z)]


def _external_force(prob: _Problem, q: float, R: NDArray, dR: NDArray, lam: NDArray) -> NDArray:
    """Load per unit length of the chosen model plus the rigid-body reaction
    lambda_F + lambda_M x R0, Cartesian (batch x P x 3)."""
    g = prob.geo
    if prob.load == "hydrostatic":
        force = q * np.cross(g.e_z, dR)
    elif prob.load == "axis":  # horizontal, towards the axis of the ring, at the displaced point
        rho = np.sqrt(R[..., 0] ** 2 + R[..., 1] ** 2)
        force = -q * np.stack([R[..., 0] / rho, R[..., 1] / rho, 0.0 * rho], axis=-1)
    elif prob.load == "centre":  # towards the ring's centre point, at the displaced point
        dist = np.sqrt(R[..., 0] ** 2 + R[..., 1] ** 2 + R[..., 2] ** 2)
        force = -q * R / dist[..., None]
    else:  # "dead": fixed direction -e_r(s) at the material point, whatever the displacement
        force = -q * (g.e_r + 0.0 * R)
    R0 = g.e_r  # R = 1
    reaction = lam[:, None, :3] + np.cross(lam[:, None, 3:], R0)
    return force + reaction


#: The signed terms of Eq. ``Munder`` as printed (beyond the leading derivatives), labelled
#: "line:term"; ``flip`` reverses one of them (a diagnostic: every one must matter).
MUNDER_TERMS = (
    "1:w1*Mv'", "1:w2*Mu'", "1:w3*(w1*Mu+w2*Mv)", "1:qt",
    "2:w1*Mu", "2:w2*Mv",
    "3:(w3*Mu)'", "3:(w2*Mt)'", "3:w3*(...)", "3:w3*w3*Mv", "3:w3*w1*Mt", "3:w1*Ft", "3:qu",
    "4:(w3*Mv)'", "4:(w1*Mt)'", "4:w3*(...)", "4:w3*w3*Mu", "4:w3*w2*Mt", "4:w2*Ft", "4:qv",
)


def _munder_lines(prob: _Problem, w: tuple, Mm: tuple, Ft: NDArray, qv: tuple) -> list[NDArray]:
    """Eq. ``Munder`` term by term as printed (m = 0): the four residual lines.

    Each bracket is written out where it occurs (as in the paper), so that a sign error in any
    single occurrence can be simulated with ``prob.flip``.
    """
    g = prob.grid
    w1, w2, w3 = w
    Mu, Mv, Mt = Mm
    qu, qv_, qt = qv
    sg = {k: (-1.0 if k == prob.flip else 1.0) for k in MUNDER_TERMS}
    dMu, dMv, dMt = _ds(Mu, g), _ds(Mv, g), _ds(Mt, g)
    line1 = (_ds(Ft, g) + sg["1:w1*Mv'"] * w1 * dMv - sg["1:w2*Mu'"] * w2 * dMu
             + sg["1:w3*(w1*Mu+w2*Mv)"] * w3 * (w1 * Mu + w2 * Mv) + sg["1:qt"] * qt)
    line2 = dMt - sg["2:w1*Mu"] * w1 * Mu - sg["2:w2*Mv"] * w2 * Mv
    line3 = (_ds(dMv + sg["3:(w3*Mu)'"] * w3 * Mu + sg["3:(w2*Mt)'"] * w2 * Mt, g)
             + sg["3:w3*(...)"] * w3 * (dMu - sg["3:w3*w3*Mv"] * w3 * Mv
                                        + sg["3:w3*w1*Mt"] * w1 * Mt)
             - sg["3:w1*Ft"] * w1 * Ft - sg["3:qu"] * qu)
    line4 = (_ds(dMu - sg["4:(w3*Mv)'"] * w3 * Mv + sg["4:(w1*Mt)'"] * w1 * Mt, g)
             - sg["4:w3*(...)"] * w3 * (dMv + sg["4:w3*w3*Mu"] * w3 * Mu
                                        + sg["4:w3*w2*Mt"] * w2 * Mt)
             + sg["4:w2*Ft"] * w2 * Ft + sg["4:qv"] * qv_)
    return [line1, line2, line3, line4]


def _residual(X: NDArray, prob: _Problem, q: float) -> NDArray:
    """Galerkin-projected nonlinear residual (batch x size) at unknown coefficients X."""
    g, geo = prob.grid, prob.geo
    fld = _sample(X, prob)
    theta = _cyl(geo, fld["theta_r"], fld["theta_phi"], fld["theta_z"])
    y = _cyl(geo, fld["y_r"], fld["y_phi"], fld["y_z"])
    t, u, v = rotate(theta, geo.t0), rotate(theta, geo.u0), rotate(theta, geo.v0)
    w = _darboux(t, u, v, g)
    A1, A2, A3 = prob.stiff
    Mm = (-A2 * (w[1] - prob.w0[1]), A1 * (w[0] - prob.w0[0]), A3 * (w[2] - prob.w0[2]))
    R0 = geo.e_r
    dy = _ds(y, g)
    force = _external_force(prob, q, R0 + y, geo.t0 + dy, fld["lambda"])
    kin = _to_cyl(geo, dy - (t - geo.t0))
    if prob.equations == "munder":
        Ft = -q + fld["f_t"]
        qv = (_dot(force, u), _dot(force, v), _dot(force, t))
        lines = _munder_lines(prob, w, Mm, Ft, qv)
        # lines 3, 4 are -(F' + q).u and +(F' + q).v (F_u, F_v eliminated): recombined into
        # the normal force balance, a pointwise invertible change of test functions that keeps
        # the truncated system square family by family (with +line3 it is a reflection whose
        # axis turns with Omega and spuriously couples f to f +- 2N even for nu = 1)
        normal = -lines[2][..., None] * u + lines[3][..., None] * v
        fields = [lines[0], lines[1], _dot(normal, geo.e_r), _dot(normal, geo.e_z), *kin]
    else:
        F = -q * geo.t0 + _cyl(geo, fld["F_r"], fld["F_phi"], fld["F_z"])
        M = Mm[0][..., None] * u + Mm[1][..., None] * v + Mm[2][..., None] * t
        moment = _to_cyl(geo, _ds(M, g) + np.cross(t, F))
        forcebal = _to_cyl(geo, _ds(F, g) + force)
        fields = [*moment, *forcebal, *kin]
    proj = [_project(r, g) for r in fields]
    cons = [g.weight * np.sum(y, axis=1), g.weight * np.sum(np.cross(R0, y), axis=1)]
    return np.concatenate([*proj, *cons], axis=1)


def base_residual(N: int, nu: float, *, e_ratio: float = 1.0, load: str = "hydrostatic",
                  q: float = 1.0, M: int = 8, equations: str = "munder",
                  flip: str | None = None) -> float:
    """Largest |residual| at zero perturbation: 0 (to round-off) iff the loaded circle with the
    hoop force F_t = -q R and no moments is an equilibrium of the chosen equations.

    Returns
    -------
    float
        The largest absolute residual of the base state.

    Examples
    --------
    >>> base_residual(2, 3.0) < 1e-12
    True
    """
    prob = _problem(check_twist_count(N, maximum=MAX_TWIST), check_scalar_nu(nu),
                    check_e_ratio(e_ratio), check_load(load), check_int(M, "M", 4, 200),
                    check_choice(equations, "equations", EQUATIONS),
                    None if flip is None else check_choice(flip, "flip", MUNDER_TERMS))
    q = check_real(q, "q", -1e6, 1e6)
    return float(np.max(np.abs(_residual(np.zeros((1, prob.size), complex), prob, q))))


# ---------------------------------------------------------------- Jacobian and eigenproblem

def jacobian(prob: _Problem, q: float) -> NDArray[np.float64]:
    """d(residual)/d(unknowns) at the base state by the complex step (exact to round-off)."""
    n = prob.size
    J = np.empty((n, n))
    for start in range(0, n, BATCH):
        cols = np.arange(start, min(start + BATCH, n))
        X = np.zeros((cols.size, n), complex)
        X[np.arange(cols.size), cols] = 1j * STEP
        J[:, cols] = (_residual(X, prob, q).imag / STEP).T
    return J


def pencil(prob: _Problem) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(J0, J1) with J(q) = J0 + q J1: the residual is affine in q, so two complex-step passes
    give the pencil exactly."""
    J0 = jacobian(prob, 0.0)
    return J0, jacobian(prob, 1.0) - J0


def _scales(J0: NDArray, J1: NDArray) -> tuple[NDArray, NDArray]:
    """Row and column factors (r, c) of :func:`_equilibrate`."""
    S = np.abs(J0) + np.abs(J1)
    c = 1.0 / np.maximum(S.max(axis=0), 1e-300)
    r = 1.0 / np.maximum((S * c[None, :]).max(axis=1), 1e-300)
    return r, c


def _equilibrate(J0: NDArray, J1: NDArray) -> tuple[NDArray, NDArray]:
    """Row and column scaling (same for both matrices; eigenvalues unchanged) so that every
    row and column of J0 + J1 has largest entry ~1: the QZ algorithm is normwise stable, and
    the Fourier columns span many orders of magnitude (frequency^3)."""
    r, c = _scales(J0, J1)
    return J0 * r[:, None] * c[None, :], J1 * r[:, None] * c[None, :]


def _pattern_magnitudes(J0: NDArray, J1: NDArray) -> NDArray[np.float64]:
    A0, A1 = _equilibrate(J0, J1)
    return np.abs(A0) + np.abs(A1)


def pattern_has_gap(J0: NDArray, J1: NDArray) -> bool:
    """Whether the equilibrated entries leave a gap of PATTERN_GAP around PATTERN_TOL (the
    smallest entry above it is >= PATTERN_GAP times the largest nonzero one below it), so that
    round-off can be told from couplings; True if one side is empty."""
    S = _pattern_magnitudes(J0, J1)
    below, above = S[(S > 0) & (S <= PATTERN_TOL)], S[S > PATTERN_TOL]
    return not (below.size and above.size and above.min() < PATTERN_GAP * below.max())


def blocks(J0: NDArray, J1: NDArray) -> list[tuple[NDArray[np.int64], NDArray[np.int64]]]:
    """Independent square blocks (rows, columns) of the pencil: connected components of the
    bipartite row-column graph of the equilibrated nonzero pattern (entries above
    :data:`PATTERN_TOL`); one block, the whole pencil, if there is no gap
    (:data:`PATTERN_GAP`) between round-off and couplings."""
    n = J0.shape[0]
    S = _pattern_magnitudes(J0, J1)
    if not pattern_has_gap(J0, J1):
        return [(np.arange(n), np.arange(n))]  # round-off not told from couplings
    pattern = scipy.sparse.coo_matrix(S > PATTERN_TOL)
    graph = scipy.sparse.bmat([[None, pattern], [pattern.T, None]])
    n_comp, label = scipy.sparse.csgraph.connected_components(graph, directed=False)
    out = []
    for c in range(n_comp):
        rows = np.flatnonzero(label[:n] == c)
        cols = np.flatnonzero(label[n:] == c)
        if rows.size != cols.size:
            raise RuntimeError(f"pencil block {c} is not square ({rows.size} x {cols.size})")
        if rows.size:
            out.append((rows, cols))
    return out


#: A mode's unknown counts as part of it if its coefficient (in the physical unknowns, not the
#: equilibrated ones) exceeds this fraction of the largest: sqrt of ring_stability's KIND_TOL,
#: whose in-plane share of the load work is quadratic in the physical amplitudes (an in-plane
#: mode's out-of-plane part is round-off).
MODE_SUPPORT_TOL = 1.0e-4


def _mode_support(J0: NDArray, J1: NDArray, q: float) -> NDArray[np.bool_]:
    """The unknowns the null vector of J0 + q J1 involves (two steps of inverse iteration in
    the equilibrated variables from a fixed generic vector, then back to the physical ones):
    fields and frequencies of a block's critical mode (a block's pattern couples fields the
    mode may leave at round-off, and an unsplit pencil shows no structure at all). The
    threshold is applied to the physical amplitudes: in the equilibrated
    ones (column factors spanning frequency^3) the kinds disagreed with the second variation's
    load-work share near nu = 1 (19 of 150 random rings with nu - 1 < 0.016, each
    called coupled here with an in-plane share of 5e-16..5e-9 there). On the physical
    amplitudes 3 of the 150 disagree, the other way round, all with a share of 1.1e-8..4.2e-8:
    within a factor 5 of KIND_TOL, where an amplitude ratio and a share of the load work (two
    different measures) can fall on either side of one threshold."""
    A0, A1 = _equilibrate(J0, J1)
    a = A0 + q * (1.0 + 1e-13) * A1  # beside q
    x = cast(NDArray[np.float64], np.random.default_rng(7).standard_normal(A0.shape[0]))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", scipy.linalg.LinAlgWarning)  # singular: handled below
        lu = scipy.linalg.lu_factor(a, check_finite=False)
        for _ in range(2):
            x = scipy.linalg.lu_solve(lu, x / np.abs(x).max(), check_finite=False)
    if not (np.all(np.isfinite(x)) and np.abs(x).max() > 0):
        # an exactly zero pivot: the offset q 1e-13 is below the round-off of the O(1) entries
        # (at N = 0, nu 1..1e4, e 1e-6..3e4: 22 of 96 grid rings, whose modes were then called
        # in-plane with no frequencies); the smallest right singular vector instead
        x = scipy.linalg.svd(a, check_finite=False)[2][-1]
    x = np.abs(x * _scales(J0, J1)[1])  # the physical unknowns: J0 (c y) = (J0 c) y
    return x > MODE_SUPPORT_TOL * x.max()


def _block_loads(J0: NDArray, J1: NDArray) -> tuple[NDArray[np.float64], float]:
    """Finite real eigenvalues q of (J0 + q J1) x = 0, sorted, and the largest relative
    imaginary part among the finite eigenvalues (a diagnostic: 0 for a conservative problem)."""
    A0, A1 = _equilibrate(J0, J1)
    alpha, beta = scipy.linalg.eig(A0, -A1, right=False, homogeneous_eigvals=True,
                                   check_finite=False)
    finite = np.abs(beta) > 1e-12 * np.abs(alpha)
    qs = alpha[finite] / beta[finite]
    real = np.abs(qs.imag) <= REAL_TOL * np.abs(qs)
    worst = float(np.max(np.abs(qs.imag) / np.maximum(np.abs(qs), 1e-300))) if qs.size else 0.0
    return np.sort(qs[real].real), worst


@dataclass(frozen=True)
class BlockLoad:
    """Lowest positive real load of one independent block of the linearised problem."""

    load: float
    frequencies: tuple[int, ...]
    fields: tuple[str, ...]
    size: int

    @property
    def kind(self) -> str:
        """"in-plane", "out-of-plane" or "coupled", from the fields the block contains."""
        inp = [f in IN_PLANE_FIELDS for f in self.fields]
        return "in-plane" if all(inp) else "out-of-plane" if not any(inp) else "coupled"


def block_loads(N: int, nu: float, e_ratio: float, load: str, M: int,
                equations: str = "munder", flip: str | None = None
                ) -> tuple[list[BlockLoad], float]:
    """Lowest positive load of every block at truncation M, and the largest relative
    imaginary part of any finite eigenvalue (unchecked inputs; see
    :func:`munder_critical_load`).  ``flip`` reverses the sign of one term of Eq. ``Munder``
    (one of :data:`MUNDER_TERMS`; a diagnostic of how sensitive the result is to misprints).

    >>> bl, _ = block_loads(0, 1.0, 1.0, "axis", 6)
    >>> sorted({(b.kind, round(b.load, 9)) for b in bl if b.frequencies == (2,)})
    [('in-plane', 4.5), ('out-of-plane', 2.0)]
    """
    prob = _problem(N, nu, e_ratio, load, M, equations, flip)
    J0, J1 = pencil(prob)
    n = prob.n_field
    names = [*prob.fields]
    out, worst = [], 0.0
    parts = blocks(J0, J1)
    for rows, cols in parts:
        qs, w = _block_loads(J0[np.ix_(rows, cols)], J1[np.ix_(rows, cols)])
        worst = max(worst, w)
        pos = qs[qs > 0]
        if pos.size:  # the mode says what it involves (a block's pattern couples more)
            sub = np.ix_(rows, cols)
            mode = cols[_mode_support(J0[sub], J1[sub], float(pos[0]))]
            if np.any(mode < len(names) * n):  # else (no field unknown) the block's pattern
                cols = mode
        fl = cols[cols < len(names) * n]
        freqs = tuple(sorted({int(prob.grid.freq[c % n]) for c in fl}))
        fields = tuple(sorted({names[c // n] for c in fl}, key=names.index))
        out.append(BlockLoad(float(pos[0]) if pos.size else math.inf, freqs, fields, rows.size))
    return out, worst


# ---------------------------------------------------------------- public solver

@dataclass(frozen=True)
class MunderBuckling:
    """Result of :func:`munder_buckling`.

    load            converged q_cr R^3/(E1 I1)
    kind            "in-plane" / "out-of-plane" / "coupled" (fields of the critical block)
    frequencies     Fourier frequencies of the critical block
    max_frequency   final truncation M (frequencies 0..M per field)
    n_unknowns      size of the full linear system at M
    rel_change      |q(M) - q(previous M)| / q
    converged       rel_change <= tol and ring_stability.roundoff_floor(e_ratio, nu, N) <= tol
    history         [(M, q)] of the truncations tried
    max_imag        largest |Im q|/|q| of any finite eigenvalue at the final M
    """

    N: int
    nu: float
    e_ratio: float
    load_model: str
    equations: str
    load: float
    kind: str
    frequencies: tuple[int, ...]
    max_frequency: int
    n_unknowns: int
    rel_change: float
    converged: bool
    tol: float
    history: list[tuple[int, float]] = field(repr=False)
    max_imag: float = 0.0


def _truncations(N: int) -> list[int]:
    """M = 2N + 8, then steps of max(4, 2N) (each step adds members to every frequency family),
    at most eight truncations."""
    step = max(4, 2 * N)
    return [2 * N + 8 + k * step for k in range(8)]


#: The tol range of this formulation's truncation loop (one decade above the second
#: variation's TOL_RANGE: its loads come from QZ eigenvalues of a larger, equilibrated pencil).
TOL_RANGE = (1e-13, 1e-2)


def _check_tol(tol: object) -> float:
    return check_real(tol, "tol", *TOL_RANGE)


def munder_buckling(N: object, nu: object, *, e_ratio: object = 1.0,
                    load: object = "hydrostatic", tol: float = 1.0e-10,
                    equations: str = "munder", raise_on_failure: bool = True) -> MunderBuckling:
    """Critical load of the twisted ring from the numerically linearised Eq. ``Munder``
    (or the Kirchhoff balances with ``equations="kirchhoff"``); see the module docstring.

    The truncation M is raised (:func:`_truncations`) until two successive critical loads agree
    to ``tol`` relatively; otherwise :class:`spectral_rod.RingConvergenceError` is raised (or,
    with ``raise_on_failure=False``, the result is returned with ``converged=False``).

    Returns
    -------
    MunderBuckling
        The critical load q_cr R^3/(E1 I1), the mode's kind, the final truncation and the
        convergence record (``converged``, ``rel_change``).

    Examples
    --------
    >>> round(munder_buckling(0, 4.0).load, 9)
    3.0
    """
    n_turns = check_twist_count(N, maximum=MAX_TWIST)
    v, e, ld = check_scalar_nu(nu), check_e_ratio(e_ratio), check_load(load)
    tol = _check_tol(tol)
    check_choice(equations, "equations", EQUATIONS)
    raise_on_failure = check_bool(raise_on_failure, "raise_on_failure")
    if raise_on_failure:
        check_reachable(tol, e, v, n_turns)

    def solve(M: int) -> tuple[tuple[BlockLoad, float], float]:
        bl, worst = block_loads(n_turns, v, e, ld, M, equations)
        best = min(bl, key=lambda b: b.load)
        return (best, worst), best.load

    (best, worst), history, rel = refine(_truncations(n_turns), solve, tol)
    M = history[-1][0]
    floor = roundoff_floor(e, v, n_turns)  # truncations do not see it (ring_stability)
    converged = bool(rel <= tol and floor <= tol)
    if not converged and raise_on_failure:
        raise RingConvergenceError(
            f"Munder ring load not converged for N={n_turns}, nu={v}, e={e}, load={ld}: "
            f"relative change {rel:.2e}, round-off floor {floor:.1e} (tol {tol:.1e}) at "
            f"max_frequency {M}")
    if worst > REAL_TOL:
        warnings.warn(f"non-real eigenvalues (|Im q|/|q| up to {worst:.1e}) for N={n_turns}, "
                      f"nu={v}, e={e}, load={ld}: unexpected for conservative loads",
                      ConvergenceWarning, stacklevel=2)
    size = len(FIELDS[equations]) * (2 * M + 1) + 6
    return MunderBuckling(n_turns, v, e, ld, equations, best.load, best.kind, best.frequencies,
                          M, size, rel, converged, tol, history, worst)


def munder_critical_load(N: object, nu: object, *, e_ratio: object = 1.0,
                         load: object = "hydrostatic", tol: float = 1.0e-10) -> float:
    """Converged q_cr R^3/(E1 I1) of the twisted ring (Omega = N s / R) from the paper's
    equilibrium equations ``Munder``/``constit``/``frenet``, linearised numerically.

    Same arguments and units as :func:`spectral_rod.ring_critical_load`; raises
    :class:`spectral_rod.RingConvergenceError` if not converged to ``tol``.

    >>> abs(munder_critical_load(0, 1.0) - 2.0) < 1e-9  # Timoshenko-Gere, n = 2, A3 = 2
    True
    """
    return munder_buckling(N, nu, e_ratio=e_ratio, load=load, tol=tol).load


# ---------------------------------------------------------------- agreement table

#: Poisson's ratio of the isotropic material of the ring cases (a typical metal's).
ISOTROPIC_POISSON = 0.3
#: e = E2/E1 of that material: A3 = E2 (I1 + I2) is G J of a circular section, so
#: E2 = G = E1/(2 (1 + Poisson)).
E_ISOTROPIC = 1.0 / (2.0 * (1.0 + ISOTROPIC_POISSON))
#: The agreement cases (N, nu, e, load): N = 0..8, several nu and e, every reading of the load.
AGREEMENT_CASES: tuple[tuple[int, float, float, str], ...] = (
    (0, 1.0, 1.0, "hydrostatic"),
    (0, 4.0, E_ISOTROPIC, "axis"),
    (1, 1.3, 1.0, "hydrostatic"),
    (1, 4.0, E_ISOTROPIC, "axis"),
    (2, 2.0, 1.0, "axis"),
    (2, 1.3, E_ISOTROPIC, "hydrostatic"),
    (3, 4.0, 1.0, "hydrostatic"),
    (3, 2.0, E_ISOTROPIC, "axis"),
    (4, 1.3, 1.0, "axis"),
    (4, 4.0, E_ISOTROPIC, "hydrostatic"),
    (5, 2.0, 1.0, "hydrostatic"),
    (5, 1.0, E_ISOTROPIC, "axis"),
    (6, 4.0, 1.0, "axis"),
    (6, 1.3, E_ISOTROPIC, "hydrostatic"),
    (7, 2.0, E_ISOTROPIC, "hydrostatic"),
    (8, 4.0, 1.0, "hydrostatic"),
    (8, 1.3, E_ISOTROPIC, "axis"),
    (0, 4.0, 1.0, "centre"),
    (2, 2.0, 1.0, "centre"),
    (3, 1.3, E_ISOTROPIC, "centre"),
    (0, 2.0, E_ISOTROPIC, "dead"),
    (2, 4.0, 1.0, "dead"),
    (3, 1.5, E_ISOTROPIC, "dead"),
)


def _case(c: Mapping[str, object] | tuple) -> tuple[object, object, object, object]:
    if isinstance(c, Mapping):
        if "N" not in c or "nu" not in c:
            raise ValueError(f"cases: a dict case needs keys 'N' and 'nu', got {sorted(c)}")
        unknown = sorted(set(c) - {"N", "nu", "e_ratio", "load"})
        if unknown:  # a misspelt key would silently run the default
            raise ValueError(f"cases: unknown key(s) {unknown}; a dict case has 'N', 'nu' and "
                             f"optionally 'e_ratio', 'load'")
        return c["N"], c["nu"], c.get("e_ratio", 1.0), c.get("load", "hydrostatic")
    if not isinstance(c, (tuple, list)) or not 2 <= len(c) <= 4:
        raise TypeError(f"cases: each case must be (N, nu[, e_ratio[, load]]) or a dict, got "
                        f"{c!r}")
    N, nu, *rest = c
    return N, nu, rest[0] if rest else 1.0, rest[1] if len(rest) > 1 else "hydrostatic"


def ring_formulation_agreement(cases: Iterable[Mapping[str, object] | tuple] = AGREEMENT_CASES,
                               *, tol: float = 1.0e-10) -> list[dict[str, object]]:
    """Both formulations on each case (N, nu[, e_ratio[, load]]) (tuples or dicts).

    Returns
    -------
    list of dict
        One dict per case: N, nu, e_ratio, load, q_galerkin (the energy formulation,
        :func:`spectral_rod.ring_critical_load`), q_munder (this module), rel_diff, the
        critical mode's kind by each (kind_galerkin, kind_munder), max_frequency and
        n_unknowns (this module's final resolution), galerkin_max_frequency, t_galerkin and
        t_munder (wall-clock seconds).

    Examples
    --------
    >>> rows = ring_formulation_agreement([(0, 1.0), (2, 2.0)])
    >>> all(r["rel_diff"] < 1e-10 for r in rows), [r["kind_munder"] for r in rows]
    (True, ['out-of-plane', 'coupled'])
    """
    from spectral_rod.ring.second_variation import ring_buckling

    rows = []
    tol = _check_tol(tol)
    if isinstance(cases, (str, bytes, Mapping)) or not isinstance(cases, Iterable):
        raise TypeError(f"cases must be an iterable of (N, nu[, e_ratio[, load]]) tuples or "
                        f"dicts, got {type(cases).__name__}")
    for i, c in enumerate(cases):
        N, nu, e, ld = _case(c)
        try:  # validate the case before any solve; errors say which case
            check_twist_count(N, maximum=MAX_TWIST), check_scalar_nu(nu)
            check_e_ratio(e), check_load(ld)
        except (ValueError, TypeError) as exc:
            raise type(exc)(f"cases[{i}]: {exc}") from None
        t0 = time.perf_counter()
        ref = ring_buckling(N, nu, e_ratio=e, load=ld)
        t1 = time.perf_counter()
        mb = munder_buckling(N, nu, e_ratio=e, load=ld, tol=tol)
        t2 = time.perf_counter()
        rows.append({**formulation_row(ref, mb), "t_galerkin": t1 - t0, "t_munder": t2 - t1})
    return rows


def formulation_row(ref: RingBuckling, mb: MunderBuckling) -> dict[str, object]:
    """One case of :func:`ring_formulation_agreement` (without its timings) from the two
    formulations' results of one ring.

    Returns
    -------
    dict of str to object
        The case's row, keys as in :func:`ring_formulation_agreement` but the timings.

    Examples
    --------
    >>> import spectral_rod as sr
    >>> row = formulation_row(sr.ring_buckling(0, 1.0), munder_buckling(0, 1.0))
    >>> row["rel_diff"] < 1e-10, row["kind_galerkin"] == row["kind_munder"]
    (True, True)
    """
    if not isinstance(ref, RingBuckling):
        raise TypeError(f"ring_formulation_row: ref must be a RingBuckling (ring_buckling's "
                        f"result), got {type(ref).__name__}")
    if not isinstance(mb, MunderBuckling):
        raise TypeError(f"ring_formulation_row: mb must be a MunderBuckling (munder_buckling's "
                        f"result), got {type(mb).__name__}")
    a = (ref.N, ref.nu, ref.e_ratio, ref.load_model)
    b = (mb.N, mb.nu, mb.e_ratio, mb.load_model)
    if a != b:
        raise ValueError(f"ring_formulation_row: ref and mb are of different rings or load "
                         f"models, (N, nu, e_ratio, load) = {a} and {b}")
    return {"N": mb.N, "nu": mb.nu, "e_ratio": mb.e_ratio, "load": mb.load_model,
            "q_galerkin": ref.load, "q_munder": mb.load,
            "rel_diff": abs(mb.load - ref.load) / abs(ref.load),
            "kind_galerkin": ref.kind, "kind_munder": mb.kind,
            "max_frequency": mb.max_frequency, "n_unknowns": mb.n_unknowns,
            "galerkin_max_frequency": ref.max_frequency}
