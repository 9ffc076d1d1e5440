"""Linear stability of the spontaneously twisted ring, solved with a Fourier-Galerkin method.

Model (section "Stability of a ring" of Drozdov & Rabin; Eqs. ``frenet``, ``constit``, ``Munder``)
------------------------------------------------------------------------------------------------
Ring of radius R, arc length s, inextensible and unshearable centreline, cross-section axes
u0 = -cos(Omega) e_r + sin(Omega) e_z, v0 = sin(Omega) e_r + cos(Omega) e_z, t0 = e_phi with
Omega(s) = N s / R, so the spontaneous torsions are w10 = cos(Omega)/R, w20 = -sin(Omega)/R,
w30 = N/R.  Constitutive law Eq. ``constit``: M_v = A1 (w1 - w10), M_u = -A2 (w2 - w20),
M_t = A3 (w3 - w30) with A1 = E1 I1, A2 = E1 I2, A3 = E2 (I1 + I2).  The stress-free ring carries
under the load q the hoop force F_t = -q R (Eq. ``Munder``, third and fourth lines) and no moment.

Perturbation: the frame is rotated by a small rotation vector theta(s), d_i = exp(theta x) d_i0,
the centreline displaced by y(s) with R' = d_3 (inextensible, unshearable).  Because the base
state is stress-free, the second variation of the elastic energy only needs the first-order
change of the torsions, which is (derived and checked in
:mod:`spectral_rod.derivations.ring_linearisation`)

    dw1 = theta'.v0,   dw2 = -theta'.u0,   dw3 = theta'.t0.

In cylindrical components with R = 1 (lengths in units of R) and y = y_r e_r + y_phi e_phi +
y_z e_z, the first-order constraint y' = theta x t0 gives y_r = -y_phi' (inextensibility),
theta_z = y_phi'' + y_phi, theta_r = y_z', and theta_phi = alpha is the extra twist.  With

    k_r = theta_r' - theta_phi = y_z'' - alpha,   k_phi = alpha' + y_z',   k_z = y_phi''' + y_phi',

the second variation of energy plus load potential is 1/2 (x.K x - q x.G x) with

    x.K x = int [A1 (k.v0)^2 + A2 (k.u0)^2 + A3 k_phi^2] ds
          = int [Abar (k_r^2 + k_z^2) + Delta (cos 2Omega (k_r^2 - k_z^2) - 2 sin 2Omega k_r k_z)
                 + A3 k_phi^2] ds,    Abar = (A1 + A2)/2, Delta = (A2 - A1)/2,
    x.G x = int (theta_r^2 + theta_z^2) ds - int y_phi theta_z ds      ("hydrostatic"),
    x.G x = int (theta_r^2 + theta_z^2) ds - int y_phi^2 ds            ("axis"),
    x.G x = int (theta_r^2 + theta_z^2) ds - int (y_phi^2 + y_z^2) ds  ("centre"),
    x.G x = int (theta_r^2 + theta_z^2) ds                             ("dead").

The first term of G is the work of the hoop force F_t = -q R on the second-order part of the
tangent, d_3 - t0 = theta x (theta x t0)/2 (|theta x t0|^2 = |y'|^2 = theta_r^2 + theta_z^2); the
second is the second-order load potential:

* ``"hydrostatic"``: force per unit length q e_z x R'(s), i.e. pressure q acting on the ring's
  projection on the plane z = 0, horizontal and normal to the projected centreline.  It is
  conservative with potential V = q * (projected enclosed area) = q/2 int (R x R').e_z ds, whose
  second-order part is q/2 int (y x y').e_z ds = q/2 int y_phi theta_z ds.  This is the classical
  ring load (3 A1/R^3 in plane, n = 2).
* ``"axis"``: the paper's literal q = -q e_r evaluated at the displaced point: magnitude q, always
  horizontal, pointing to the ring's axis.  Potential V = q int rho ds with rho the distance from
  the axis; second-order part q/2 int y_phi^2 ds (4.5 A1/R^3 in plane, n = 2).
* ``"centre"``: magnitude q, pointing to the ring's centre point (a central force), -q R/|R| at
  the displaced point.  Potential V = q int |R| ds; |e_r + y| = 1 + y_r + (y_phi^2 + y_z^2)/2 +
  O(y^3), so the second-order part is q/2 int (y_phi^2 + y_z^2) ds (in plane as "axis", 4.5;
  out of plane 12 A2/(4 + A2/A3), n = 2).
* ``"dead"``: a dead load of fixed direction, -q e_r(s) at the material point s whatever the
  displacement.  Potential V = -int q.(R0 + y) ds is linear in y: only the hoop-force term
  remains (4 A1/R^3 in plane, n = 2).

All four equal -q e_r on the undeformed circle, so the base state (F_t = -q R, no moment) is the
same; they differ only in how the force follows the displacement.  Closed forms of the untwisted
ring for each: :mod:`spectral_rod.ring.closed_forms`; the rigid motions each load destabilises
(what the ring's supports must restrain): :mod:`spectral_rod.ring.loads`.

Rigid-body motions are removed by six explicit linear constraints on the displacement,
int y ds = 0 and int R0 x y ds = 0 (a rigid tilt lowers the potential of the "hydrostatic",
"axis" and "dead" loads, a rigid spin about the axis that of the "dead" load:
:func:`spectral_rod.ring.loads.rigid_motion_load_work`).  On that
subspace K is positive definite (x.K x = 0 only for theta' = 0, i.e. a rigid motion), which is
the energy argument: the stress-free ring cannot be unstable at q = 0.

Discretisation: y_phi, y_z, alpha are real Fourier series in s.  The coefficients of K contain
cos 2Omega, sin 2Omega, so frequency f couples only to f +- 2N: the problem splits into N + 1
independent families {f >= 0 : f = +-n mod 2N}, n = 0..N (N = 0: every frequency on its own).
Each family is assembled by exact trapezoidal quadrature and the generalised eigenproblem
G x = mu K x is solved (K Cholesky-factorised after Jacobi scaling); q = 1/mu.  The truncation is
a Rayleigh-Ritz subspace, so truncated critical loads decrease monotonically to the limit.

All loads are returned as q R^3/(E1 I1); nu = I2/I1, e = E2/E1, so A1 = 1, A2 = nu,
A3 = e (1 + nu) in these units.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import TypeVar

import numpy as np
import scipy.linalg
import scipy.optimize
from numpy.typing import NDArray

from spectral_rod._validation import (
    TOL_RANGE,
    check_bool,
    check_choice,
    check_int,
    check_real,
)
from spectral_rod.errors import ConvergenceWarning, RingConvergenceError
from spectral_rod.ring.formula import check_e_ratio, check_scalar_nu, check_twist_count

#: The readings of the paper's "uniform radial pressure" (module docstring): pressure on the
#: projection (follower), a force toward the ring's axis, toward its centre point, a dead load.
RING_LOADS = ("hydrostatic", "axis", "centre", "dead")
#: Largest twist accepted by the numerical solver (cost grows like N).
MAX_SOLVER_TWIST = 60
#: Fields of the unknown vector, in order.
FIELDS = ("y_phi", "y_z", "alpha")
#: Subspaces the solver can be restricted to: all fields, the in-plane displacement y_phi only,
#: or the out-of-plane fields y_z, alpha only.
SUBSPACES = {"all": FIELDS, "in-plane": ("y_phi",), "out-of-plane": ("y_z", "alpha")}
#: A mode is called in-plane / out-of-plane if its in-plane share of the load work is within
#: this distance of 1 / 0.
KIND_TOL = 1.0e-8
#: LAPACK driver for the generalised symmetric eigenproblem.
EIGH_DRIVER = "gv"


def check_load(load: object, name: str = "load") -> str:
    """One of :data:`RING_LOADS`."""
    return check_choice(load, name, RING_LOADS)


def stiffnesses(nu: float, e_ratio: float) -> tuple[float, float, float]:
    """(A1, A2, A3) in units of E1 I1: (1, nu, e (1 + nu)) (Eq. ``constit``)."""
    return 1.0, nu, e_ratio * (1.0 + nu)


def frequency_families(N: int, max_frequency: int) -> list[list[int]]:
    """Frequencies 0..max_frequency grouped into the families that the twist couples.

    For N > 0 family n (0 <= n <= N) holds the f with f = n or f = -n (mod 2N); for N = 0 there
    is no coupling and every frequency is a family of its own.
    """
    freqs = range(max_frequency + 1)
    if N == 0:
        return [[f] for f in freqs]
    period = 2 * N
    return [[f for f in freqs if f % period in (n, (period - n) % period)] for n in range(N + 1)]


@dataclass(frozen=True)
class _Basis:
    """Real Fourier basis of one family: (field, frequency, 'c'|'s') per column."""

    labels: list[tuple[str, int, str]]

    @property
    def size(self) -> int:
        return len(self.labels)


def _family_basis(freqs: list[int], fields: tuple[str, ...] = FIELDS) -> _Basis:
    labels = []
    for fld in fields:
        for f in freqs:
            labels.append((fld, f, "c"))
            if f > 0:
                labels.append((fld, f, "s"))
    return _Basis(labels)


def _trig_derivatives(freq: NDArray[np.float64], shift: NDArray[np.float64],
                      s: NDArray[np.float64], order: int) -> list[NDArray[np.float64]]:
    """[phi, phi', ..., phi^(order)] (each len(s) x len(freq)) for the basis functions
    phi_j(s) = cos(f_j s - shift_j), shift 0 for cos and pi/2 for sin:
    phi^(k) = f^k cos(f s - shift + k pi/2), i.e. the cycle cos, -sin, -cos, sin."""
    phase = s[:, None] * freq[None, :] - shift[None, :]
    c, sn = np.cos(phase), np.sin(phase)
    cycle = (c, -sn, -c, sn)
    return [freq[None, :] ** k * cycle[k % 4] for k in range(order + 1)]


def _quantities(basis: _Basis, s: NDArray[np.float64]) -> dict[str, NDArray[np.float64]]:
    """Matrices (len(s) x basis.size) mapping coefficients to k_r, k_phi, k_z, theta_r,
    theta_z, y_phi, y_r, y_z, alpha at the points s (R = 1)."""
    freq = np.array([f for _, f, _ in basis.labels], dtype=float)
    shift = np.array([0.0 if kind == "c" else np.pi / 2 for _, _, kind in basis.labels])
    d = _trig_derivatives(freq, shift, s, 3)
    fld = np.array([name for name, _, _ in basis.labels])
    is_p, is_z, is_a = (fld == "y_phi"), (fld == "y_z"), (fld == "alpha")

    def only(mask: NDArray[np.bool_], arr: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.where(mask[None, :], arr, 0.0)

    return {
        "y_phi": only(is_p, d[0]),
        "y_r": only(is_p, -d[1]),
        "theta_z": only(is_p, d[2] + d[0]),
        "k_z": only(is_p, d[3] + d[1]),
        "y_z": only(is_z, d[0]),
        "theta_r": only(is_z, d[1]),
        "k_r": only(is_z, d[2]) - only(is_a, d[0]),
        "k_phi": only(is_z, d[1]) + only(is_a, d[1]),
        "alpha": only(is_a, d[0]),
    }


def _quadrature(max_frequency: int, N: int) -> tuple[NDArray[np.float64], float]:
    """Equispaced points on [0, 2 pi) exact for every product in K and G (frequencies up to
    2 max_frequency + 2N); the trapezoidal weight is 2 pi / P."""
    P = 2 * max_frequency + 2 * N + 8
    return np.arange(P, dtype=np.float64) * (2.0 * np.pi / P), 2.0 * np.pi / P


def _gram(B: NDArray[np.float64], weight: float = 1.0) -> NDArray[np.float64]:
    """weight * B^T B, computed with einsum (single-threaded: these matrices are small and a
    threaded BLAS only adds overhead here)."""
    return weight * np.einsum("pi,pj->ij", B, B)


def assemble(N: int, nu: float, e_ratio: float, load: str, freqs: list[int],
             fields: tuple[str, ...] = FIELDS,
             ) -> tuple[NDArray[np.float64], NDArray[np.float64], _Basis]:
    """Symmetric matrices K (bending/torsion) and G (load work) of one frequency family, such
    that the second variation is 1/2 (x.K x - q x.G x); no constraints applied yet."""
    basis = _family_basis(freqs, fields)
    s, w = _quadrature(max(freqs), N)
    Q = _quantities(basis, s)
    A1, A2, A3 = stiffnesses(nu, e_ratio)
    om = N * s
    sin_om, cos_om = np.sin(om)[:, None], np.cos(om)[:, None]
    b_v = sin_om * Q["k_r"] + cos_om * Q["k_z"]  # k.v0 (v0 = sin Om e_r + cos Om e_z)
    b_u = -cos_om * Q["k_r"] + sin_om * Q["k_z"]  # k.u0 (u0 = -cos Om e_r + sin Om e_z)
    K = w * (_gram(b_v, A1) + _gram(b_u, A2) + _gram(Q["k_phi"], A3))
    G = w * (_gram(Q["theta_r"]) + _gram(Q["theta_z"]))
    if load == "hydrostatic":
        cross = np.einsum("pi,pj->ij", Q["y_phi"], Q["theta_z"])
        G -= w * 0.5 * (cross + cross.T)
    elif load == "axis":
        G -= w * _gram(Q["y_phi"])
    elif load == "centre":
        G -= w * (_gram(Q["y_phi"]) + _gram(Q["y_z"]))
    # "dead": the load potential is linear in y, so only the hoop-force term enters G
    return 0.5 * (K + K.T), 0.5 * (G + G.T), basis


def rigid_body_constraints(basis: _Basis) -> NDArray[np.float64]:
    """6 x basis.size matrix C with C x = (int y ds, int R0 x y ds) in Cartesian components.

    y = -y_phi' e_r + y_phi e_phi + y_z e_z and R0 = e_r (R = 1); exact quadrature.  Only
    frequencies 0 and 1 enter, so C is zero for families without them."""
    if not any(f <= 1 for _, f, _ in basis.labels):
        return np.zeros((6, basis.size))
    # P points integrate frequencies < P exactly; the integrands reach max frequency + 1
    P = 2 * max(f for _, f, _ in basis.labels) + 4
    s = np.arange(P, dtype=np.float64) * (2.0 * np.pi / P)
    w = 2.0 * np.pi / P
    Q = _quantities(basis, s)
    er = np.stack([np.cos(s), np.sin(s), np.zeros_like(s)], axis=1)
    ephi = np.stack([-np.sin(s), np.cos(s), np.zeros_like(s)], axis=1)
    ez = np.tile([0.0, 0.0, 1.0], (s.size, 1))
    rows = []
    for comp in range(3):
        y_c = (Q["y_r"] * er[:, comp, None] + Q["y_phi"] * ephi[:, comp, None]
               + Q["y_z"] * ez[:, comp, None])
        rows.append(w * y_c.sum(axis=0))
    # R0 x y with R0 = e_r: e_r x e_phi = e_z, e_r x e_z = -e_phi, e_r x e_r = 0
    for comp in range(3):
        m_c = Q["y_phi"] * ez[:, comp, None] - Q["y_z"] * ephi[:, comp, None]
        rows.append(w * m_c.sum(axis=0))
    C = np.array(rows)
    C[np.abs(C) < 1e-12] = 0.0
    return C


def _null_space(C: NDArray[np.float64], n: int) -> NDArray[np.float64]:
    """Basis of {x : C x = 0}.  Only the columns that C touches are mixed (the others stay unit
    vectors), so the scaling of high-frequency basis functions is not spoilt."""
    Z = np.eye(n)
    cols = np.flatnonzero(np.any(C != 0.0, axis=0))
    if cols.size == 0:
        return Z
    sub = scipy.linalg.null_space(C[:, cols], rcond=1e-10)
    keep = np.setdiff1d(np.arange(n), cols)
    out = np.zeros((n, keep.size + sub.shape[1]))
    out[keep, np.arange(keep.size)] = 1.0
    out[np.ix_(cols, keep.size + np.arange(sub.shape[1]))] = sub
    return out


@dataclass(frozen=True)
class FamilySolution:
    """Lowest positive buckling load of one frequency family and its mode."""

    load: float
    coefficients: NDArray[np.float64]
    basis_labels: list[tuple[str, int, str]]
    min_mu: float  # smallest 1/q over the family (>= 0 means no load q <= 0 buckles it)
    n_constraints: int
    K: NDArray[np.float64]
    G: NDArray[np.float64]

    def in_plane_fraction(self) -> float:
        """Share of the load work x.G x done by y_phi (G has no y_phi-(y_z, alpha) terms)."""
        x = self.coefficients
        inp = np.array([fld == "y_phi" for fld, _, _ in self.basis_labels])
        total = x @ self.G @ x
        return float(x[inp] @ self.G[np.ix_(inp, inp)] @ x[inp] / total) if total else math.nan

    def dominant_frequency(self) -> int:
        """Frequency carrying the largest part of the mode's bending/torsion energy."""
        x = self.coefficients
        freqs = np.array([f for _, f, _ in self.basis_labels])
        share = {int(f): float(x[freqs == f] @ self.K[np.ix_(freqs == f, freqs == f)]
                               @ x[freqs == f]) for f in np.unique(freqs)}
        return max(share, key=lambda f: share[f])


@dataclass(frozen=True)
class _Prepared:
    """One family reduced to the constraint subspace and Jacobi-scaled."""

    K: NDArray[np.float64]
    G: NDArray[np.float64]
    labels: list[tuple[str, int, str]]
    Z: NDArray[np.float64]
    d: NDArray[np.float64]
    Ks: NDArray[np.float64]
    Gs: NDArray[np.float64]
    rank: int


def _prepare(N: int, nu: float, e_ratio: float, load: str, freqs: list[int],
             fields: tuple[str, ...]) -> _Prepared:
    K, G, basis = assemble(N, nu, e_ratio, load, freqs, fields)
    C = rigid_body_constraints(basis)
    if C.any():
        Z = _null_space(C, basis.size)
        Kz = np.einsum("ia,ib->ab", Z, np.einsum("ij,jb->ib", K, Z))
        Gz = np.einsum("ia,ib->ab", Z, np.einsum("ij,jb->ib", G, Z))
        rank = int(np.linalg.matrix_rank(C))
    else:  # no frequency 0 or 1 in this family: nothing to constrain
        Z, Kz, Gz, rank = np.eye(basis.size), K, G, 0
    d = 1.0 / np.sqrt(np.diag(Kz)) if Z.shape[1] else np.zeros(0)
    return _Prepared(K, G, basis.labels, Z, d, Kz * d[:, None] * d[None, :],
                     Gz * d[:, None] * d[None, :], rank)


def _generalised_eigh(Ks: NDArray[np.float64], Gs: NDArray[np.float64]
                  ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """G y = mu K y for a stack of symmetric pairs with K positive definite (LAPACK sygv via
    scipy, one pair at a time: faster than numpy's batched syevd for these small sizes);
    returns mu ascending and K-orthonormal eigenvectors."""
    mus, vecs = [], []
    for K, G in zip(Ks, Gs, strict=True):
        try:
            mu, vec = scipy.linalg.eigh(G, K, driver=EIGH_DRIVER, check_finite=False)
        except np.linalg.LinAlgError as exc:  # K not positive definite: energy argument
            raise RuntimeError("bending/torsion stiffness is not positive definite on the "
                               "constrained subspace") from exc
        mus.append(mu)
        vecs.append(vec)
    return np.array(mus), np.array(vecs)


def solve_families(N: int, nu: float, e_ratio: float, load: str, families: dict[int, list[int]],
                   fields: tuple[str, ...] = FIELDS) -> dict[int, FamilySolution]:
    """Smallest positive q of G x = (1/q) K x on the constraint subspace of each family
    (families of equal size are stacked together)."""
    return _solve_families(N, nu, e_ratio, load, families, fields)


def _solve_families(N: int, nu: float, e_ratio: float, load: str,
                    families: dict[int, list[int]],
                    fields: tuple[str, ...]) -> dict[int, FamilySolution]:
    prep = {n: _prepare(N, nu, e_ratio, load, fam, fields) for n, fam in families.items()}
    out: dict[int, FamilySolution] = {}
    by_size: dict[int, list[int]] = {}
    for n, p in prep.items():
        if p.Z.shape[1] == 0:  # everything here is a rigid motion: no buckling mode
            out[n] = FamilySolution(math.inf, np.zeros(len(p.labels)), p.labels, math.inf,
                                    p.rank, p.K, p.G)
        else:
            by_size.setdefault(p.Z.shape[1], []).append(n)
    for members in by_size.values():
        mu, Y = _generalised_eigh(np.stack([prep[n].Ks for n in members]),
                                  np.stack([prep[n].Gs for n in members]))
        for i, n in enumerate(members):
            p = prep[n]
            top = int(np.argmax(mu[i]))
            q = 1.0 / mu[i, top] if mu[i, top] > 0 else math.inf
            x = p.Z @ (p.d * Y[i, :, top])
            out[n] = FamilySolution(float(q), x, p.labels, float(mu[i].min()), p.rank, p.K, p.G)
    return out


def solve_family(N: int, nu: float, e_ratio: float, load: str, freqs: list[int],
                 fields: tuple[str, ...] = FIELDS) -> FamilySolution:
    """Smallest positive q of G x = (1/q) K x on the constraint subspace of one family."""
    return solve_families(N, nu, e_ratio, load, {0: freqs}, fields)[0]


#: The one-harmonic Galerkin tries the frequencies n = 2 .. 2N + ONE_HARMONIC_EXTRA (its minimum
#: over n lies at n <= N + 2 on the ring scene's table: the lowest-n modes are the softest).
ONE_HARMONIC_EXTRA = 4


def one_harmonic_load(N: object, nu: object, e_ratio: object = 1.0,
                      load: object = "hydrostatic") -> tuple[float, int]:
    """The paper's stated method for Eq. ``crit2``: every field a single harmonic of one
    frequency n (cos and sin of ns/R: the paper's sin(ns/R) and its quarter-turn shift), the
    second variation restricted to it (Galerkin = Rayleigh-Ritz for this conservative problem,
    so an upper bound of the converged q_cr, exact at N = 0 where frequencies decouple); the
    smallest over n = 2 .. 2N + ONE_HARMONIC_EXTRA, and that n.

    Returns
    -------
    tuple (float, int)
        The smallest one-harmonic load q R^3/(E1 I1) and its frequency n.

    Examples
    --------
    >>> q, n = one_harmonic_load(0, 4.0)   # N = 0: the exact in-plane load 3 at n = 2
    >>> round(q, 12), n
    (3.0, 2)
    """
    n_turns = check_twist_count(N, maximum=MAX_SOLVER_TWIST)
    v, e, ld = check_scalar_nu(nu), check_e_ratio(e_ratio), check_load(load)
    sols = solve_families(n_turns, v, e, ld,
                          {n: [n] for n in range(2, 2 * n_turns + 1 + ONE_HARMONIC_EXTRA)})
    best = min(sols, key=lambda k: sols[k].load)
    return sols[best].load, best


def coupling_strengths(N: object, nu: object, e_ratio: object = 1.0) -> dict[str, float]:
    """How strongly the stiffness K of the second variation couples the perturbation equations
    (frequencies 0..4N+4, relative to K's largest entry): ``fields``, the largest entry linking
    y_phi with (y_z, alpha); ``variable_coefficients``, the largest linking frequency f with
    f + 2N (a coefficient varying like cos 2 Omega).  Both vanish for N = 0 or nu = 1.

    Returns
    -------
    dict of str to float
        ``fields`` and ``variable_coefficients``, each relative to K's largest entry.

    Examples
    --------
    >>> coupling_strengths(0, 2.0)   # untwisted: nothing couples
    {'fields': 0.0, 'variable_coefficients': 0.0}
    >>> min(coupling_strengths(2, 2.0).values()) > 1e-3
    True
    """
    n_turns = check_twist_count(N, maximum=MAX_SOLVER_TWIST)
    v, e = check_scalar_nu(nu), check_e_ratio(e_ratio)
    K, _, basis = assemble(n_turns, v, e, "hydrostatic", list(range(4 * max(n_turns, 1) + 5)))
    scale = float(np.max(np.abs(K)))
    fld = np.array([lab[0] for lab in basis.labels])
    f = np.array([lab[1] for lab in basis.labels])
    inp = fld == "y_phi"
    fields = float(np.max(np.abs(K[np.ix_(inp, ~inp)]))) / scale
    shift = (np.abs(f[:, None] - f[None, :]) == 2 * n_turns) if n_turns else np.zeros(K.shape,
                                                                                       bool)
    variable = float(np.max(np.abs(K[shift]))) / scale if shift.any() else 0.0
    return {"fields": fields, "variable_coefficients": variable}


@dataclass(frozen=True)
class RingBuckling:
    """Full result of :func:`ring_buckling`.

    load               converged q_cr R^3/(E1 I1) (the lowest positive buckling load)
    kind               "in-plane", "out-of-plane" or "coupled" (in-plane share of the load work
                       x.G x within 1e-8 of 1, of 0, or in between)
    in_plane_fraction  share of the load work done by the in-plane displacement y_phi
    family             n: the mode contains the frequencies f = +-n (mod 2N) (N = 0: f = n)
    dominant_frequency the frequency with the largest share of the mode's bending energy
    max_frequency      Fourier truncation (frequencies 0..max_frequency of each field)
    n_modes            real Fourier coefficients per field (2 max_frequency + 1)
    rel_change         |q(max_frequency) - q(previous truncation)| / q, the convergence estimate
    converged          rel_change <= tol and :func:`roundoff_floor` (e_ratio, nu, N) <= tol
    history            [(max_frequency, q)] of the truncations tried
    min_load_over_q    smallest 1/q over every family (>= 0: no eigenvalue at q <= 0)

    Examples
    --------
    >>> import spectral_rod as sr
    >>> b = sr.ring_buckling(0, 4.0)   # untwisted, in plane: 3 A (hydrostatic)
    >>> round(b.load, 12), b.kind
    (3.0, 'in-plane')
    """

    N: int
    nu: float
    e_ratio: float
    load_model: str
    load: float
    kind: str
    in_plane_fraction: float
    family: int
    dominant_frequency: int
    max_frequency: int
    n_modes: int
    rel_change: float
    converged: bool
    tol: float
    history: list[tuple[int, float]]
    min_load_over_q: float
    coefficients: NDArray[np.float64] = field(repr=False)
    basis_labels: list[tuple[str, int, str]] = field(repr=False)

    def mode(self, s: NDArray[np.float64] | None = None) -> dict[str, NDArray[np.float64]]:
        """Mode shape at s (default 256 points on [0, 2 pi R)): y_r, y_phi, y_z, alpha."""
        s = np.linspace(0.0, 2.0 * np.pi, 256, endpoint=False) if s is None else np.asarray(s)
        Q = _quantities(_Basis(self.basis_labels), s)
        return {"s": s, **{k: Q[k] @ self.coefficients for k in ("y_r", "y_phi", "y_z", "alpha")}}


#: Round-off floor of a ring load, relative: ROUNDOFF eps max(e, 1/e) (empirical). An extreme
#: torsional stiffness makes the pencils ill-conditioned in a way successive truncations do not
#: see (their change stays ~1e-15): against the closed forms at nu = 1 (N = 0, 2, 5, both
#: formulations, e = 1e-6..1e6) the error reached 2.0 eps max(e, 1/e) here and 2.5
#: in :mod:`spectral_rod.ring.munder` (2.75e-10 and 5.7e-10 at e = 1e6, 4.3e-11 and 1.1e-10 at
#: 1e-6), up to 7 eps at e = 1; a tol below the floor is not met.
ROUNDOFF = 8.0
#: A twisted ring (N >= 1) whose torsion is much stiffer than its bending also scatters its
#: load between truncations by about eps c, c = A3/(2 A1) = e (1 + nu)/2 (the twist couples
#: the torsion into the bending of every family). Measured as ``rel_change`` of
#: ``ring_buckling(N, nu, e_ratio=e, tol=1e-8, raise_on_failure=False)``: 0.9 eps c at N = 5
#: and 20, nu = 1e4, e = 1e6 (c = 5e9: ~1e-6, so a tol of 1e-8 is out of reach) and at N = 5,
#: nu = 1, e = 1e6; at most 0.15 eps c at N = 5, nu = 1e4, e = 1 (converged at 1e-12). 0.5 lies
#: between: it refuses the first and keeps the last reachable at the default tol
#: (``tests/test_ring_stability.py::test_stiff_torsion_corner_is_refused`` checks both).
COUPLED_ROUNDOFF = 0.5


def roundoff_floor(e_ratio: object, nu: object = 1.0, N: object = 0) -> float:
    """The relative accuracy a ring load can reach (both formulations; a ``tol`` below it is
    reported not converged): ROUNDOFF eps max(e, 1/e), and for a twisted ring (N >= 1) at least
    COUPLED_ROUNDOFF eps e (1 + nu)/2 (stiff torsion coupled by the twist).  The range of
    ``tol`` a ring solve accepts is [roundoff_floor(e, nu, N), TOL_RANGE[1] = 1e-2].

    Returns
    -------
    float
        The smallest relative tol a ring solve can meet.

    Examples
    --------
    >>> f"{roundoff_floor(1e6):.1e}", f"{roundoff_floor(1e6, 1e4, 60):.1e}"
    ('1.8e-09', '5.6e-07')
    """
    e = check_e_ratio(e_ratio)
    eps = float(np.finfo(float).eps)
    floor = ROUNDOFF * eps * max(e, 1.0 / e)
    if check_twist_count(N) >= 1:
        floor = max(floor, COUPLED_ROUNDOFF * eps * e * (1.0 + check_scalar_nu(nu)) / 2.0)
    return floor


def check_reachable(tol: float, e_ratio: float, nu: float = 1.0, N: int = 0) -> None:
    """RingConvergenceError before any solve if ``tol`` is below :func:`roundoff_floor`: the
    refinement would end unconverged anyway, after its most expensive truncations (minutes for
    the Munder form at N = 20, nu = 1e4, e = 1e-6; 27-113 s for N = 60, nu = 1e4, e = 1e6)."""
    floor = roundoff_floor(e_ratio, nu, N)
    if tol < floor:
        raise RingConvergenceError(f"tol {tol:.1e} is below the round-off floor {floor:.1e} of "
                                   f"a ring load at e_ratio={e_ratio!r}, nu={nu!r}, N={N!r} "
                                   f"({ROUNDOFF:g} eps max(e, 1/e), and for N >= 1 at least "
                                   f"{COUPLED_ROUNDOFF:g} eps e (1 + nu)/2); ask for tol in "
                                   f"[{floor:.1e}, {TOL_RANGE[1]:g}]")


def _truncations(N: int, max_frequency: int | None) -> list[int]:
    """Truncations tried: frequencies up to M0, M0 + step, ... (a fixed list if given)."""
    if max_frequency is not None:
        return [max_frequency]
    step = max(4, 2 * N)
    start = 2 * N + 12
    return [start + k * step for k in range(12)]


T = TypeVar("T")


def refine(truncations: Iterable[int], solve: Callable[[int], tuple[T, float]], tol: float
           ) -> tuple[T, list[tuple[int, float]], float]:
    """Solve at each truncation M in turn (``solve(M)`` -> (solution, critical load q)) until
    two successive q agree to ``tol`` relatively, |q - q_prev| <= tol |q|.

    Returns the last solution, the history [(M, q)] and the last relative change (nan after a
    single truncation); the caller decides what a non-converged result means. Shared by
    :func:`ring_buckling` and :func:`spectral_rod.ring.munder.munder_buckling`.
    """
    history: list[tuple[int, float]] = []
    rel, last, solved = math.nan, None, False
    for M in truncations:
        last, q = solve(M)
        solved = True
        if history:
            prev = history[-1][1]
            rel = 0.0 if q == prev else abs(q - prev) / abs(q)
        history.append((M, q))
        if len(history) >= 2 and rel <= tol:
            break
    if not solved:
        raise ValueError("truncations must not be empty")
    return last, history, rel  # type: ignore[return-value]


def ring_buckling(N: object, nu: object, *, e_ratio: object = 1.0, load: object = "hydrostatic",
                  tol: float = 1.0e-12, max_frequency: int | None = None,
                  subspace: str = "all", raise_on_failure: bool = True) -> RingBuckling:
    """Critical load and buckling mode of the twisted ring (see the module docstring).

    Truncations are refined (frequencies 0..M with M = 2N + 12, then in steps of max(4, 2N), so
    every family gains members) until two successive critical loads agree to ``tol``
    relatively.  With ``max_frequency`` given, only that truncation is solved: ``converged`` is
    then False, ``rel_change`` nan, and a :class:`spectral_rod.ConvergenceWarning` says that the
    load is unchecked (an upper bound of the converged one).  ``subspace`` restricts the
    unknowns: "all" (default), "in-plane" (y_phi only) or "out-of-plane" (y_z, alpha only);
    for N = 0 or nu = 1 the
    problem decouples and these give the exact in-plane and out-of-plane loads, otherwise they
    are upper bounds (Rayleigh-Ritz on a subspace).
    Raises :class:`RingConvergenceError` if the refinement did not converge and
    ``raise_on_failure`` (a fixed ``max_frequency`` warns instead: nothing was refined).

    Returns
    -------
    RingBuckling
        The critical load, its mode's kind and family, the mode's coefficients and the
        convergence record.

    Examples
    --------
    >>> b = ring_buckling(0, 1.0)   # untwisted circular ring: 9 A/(4 + A/A3), A3 = 2 A
    >>> round(b.load, 12), b.kind, b.converged
    (2.0, 'out-of-plane', True)
    """
    n_turns = check_twist_count(N, maximum=MAX_SOLVER_TWIST)
    v = check_scalar_nu(nu)
    e = check_e_ratio(e_ratio)
    ld = check_load(load)
    fields = SUBSPACES[check_choice(subspace, "subspace", tuple(SUBSPACES))]
    if max_frequency is not None:
        max_frequency = check_int(max_frequency, "max_frequency", 4, 2000)
    tol = check_real(tol, "tol", *TOL_RANGE)
    raise_on_failure = check_bool(raise_on_failure, "raise_on_failure")
    if raise_on_failure and max_frequency is None:
        check_reachable(tol, e, v, n_turns)

    def solve(M: int) -> tuple[tuple[FamilySolution, int, float], float]:
        sols = solve_families(n_turns, v, e, ld, {
            n: fam for n, fam in enumerate(frequency_families(n_turns, M)) if fam}, fields)
        k = min(sols, key=lambda n: sols[n].load)
        return (sols[k], k, min(sol.min_mu for sol in sols.values())), sols[k].load

    (sol, fam, min_mu), history, rel = refine(_truncations(n_turns, max_frequency), solve, tol)
    floor = roundoff_floor(e, v, n_turns)
    converged = bool(rel <= tol and floor <= tol)
    if not converged and raise_on_failure and max_frequency is None:
        raise RingConvergenceError(
            f"ring critical load not converged for N={n_turns}, nu={v}, e={e}, load={ld}: "
            f"relative change {rel:.2e}, round-off floor {floor:.1e} (tol {tol:.1e}) at "
            f"max_frequency {history[-1][0]}")
    if max_frequency is not None:
        warnings.warn(f"ring_buckling at the fixed truncation max_frequency={max_frequency}: "
                      f"convergence not checked (converged=False; the load is a Rayleigh-Ritz "
                      f"upper bound of the converged one)", ConvergenceWarning, stacklevel=2)
    frac = sol.in_plane_fraction()
    kind = ("in-plane" if frac > 1 - KIND_TOL else "out-of-plane" if frac < KIND_TOL
            else "coupled")
    M = history[-1][0]
    return RingBuckling(n_turns, v, e, ld, sol.load, kind, frac, fam,
                        sol.dominant_frequency(), M, 2 * M + 1, rel,
                        converged, float(tol), history, min_mu, sol.coefficients,
                        sol.basis_labels)
