r"""Machine-checked derivation of Eq. ``inst1`` (the twisted straight rod) and its variants.

Run ``python -m spectral_rod.derivations.straight_rod`` to print the results and the variant
table; the tests and the claims ledger call :func:`derive` and :func:`variant_table`.

Setting (Drozdov & Rabin, section "Stability of a rectilinear rod"): Eq. ``frenini`` frame
u0 = cos(Omega) e1 + sin(Omega) e2, v0 = -sin(Omega) e1 + cos(Omega) e2, t0 = e3 with
Omega = omega30 s; compressive end load P (F_t = -P); hinged ends. Eq. ``inst1`` is

    I1 = A1 w1'' + (P - A1 omega30^2) w1 - 2 A2 omega30 w2' = 0,
    I2 = A2 w2'' + (P - A2 omega30^2) w2 + 2 A1 omega30 w1' = 0.

Steps, each checked by exact sympy identities (a
:class:`~spectral_rod.derivations._sympy.DerivationError` naming the step means the algebra is
wrong; the checks are not ``assert`` statements, so they also run under ``python -O``; trig
functions are rewritten as exponentials, so cancellation is exact):

1. Reference state. Eq. ``frenini`` gives w10 = w20 = 0, w30 = omega30; with M = 0 and
   F_t = -P every line of Eq. ``Munder`` holds (no loads).
2. Perturbed frame. R = s e3 + eps (x1 e1 + x2 e2), t = R'/|R'|, u = the section axis rotated
   by Omega + eps alpha and Gram-Schmidt-orthonormalised against t, v = t x u (exactly
   orthonormal). Its first-order part is t1 = x', u1 = alpha v0 - (x'.u0) t0,
   v1 = -alpha u0 - (x'.v0) t0, and v agrees with Gram-Schmidt of the rotated v-axis.
3. First-order torsions from Eq. ``frenet`` (w1 = t'.u, w2 = t'.v, w3 = u'.v):
   w1 = eps x''.u0, w2 = eps x''.v0 (for *any* first-order frame perturbation, since t0' = 0),
   w3 = omega30 + eps alpha'. Hence the paper's geometric relations x1'' = w1 cos - w2 sin,
   x2'' = w1 sin + w2 cos, and with Eq. ``constit`` the paper's printed perturbation moments
   M_u = A2 (x1'' sin - x2'' cos), M_v = A1 (x1'' cos + x2'' sin), M_t = A3 alpha'.
4. Equilibrium route. Eq. ``Munder`` (loads zero) to first order, with F_t = -P + eps f:
   line 1 = f', line 2 = A3 alpha'', line 3 = I1, line 4 = -I2. So lines 3-4 are ``inst1``
   exactly and contain neither f nor alpha; f and alpha obey f' = 0 (the axial force
   perturbation is constant: a change of the end load) and A3 alpha'' = 0 (alpha linear in s:
   a rigid rotation plus a uniform twist that needs an end torque; constant for torque-free
   ends), which contain no w: the decoupling the paper asserts.
5. Energy route. End shortening of the inextensible centreline: 1 - t.e3 = eps^2 |x'|^2/2 +
   O(eps^4), so the second-order energy is 1/2 A1 w1^2 + 1/2 A2 w2^2 - P/2 |x'|^2
   (+ 1/2 A3 alpha'^2, whose Euler-Lagrange equation is A3 alpha'' = 0, line 2 again). Its
   Euler-Lagrange vector E[x] (sympy ``euler_equations``) satisfies, identically in x,

       E = G'',  G = A1 w1 u0 + A2 w2 v0 + P x,     E.u0 = I1[w(x)],  E.v0 = I2[w(x)],

   i.e. the fourth-order EL equations *are* ``inst1`` in the body frame. The first variation is
   int E.dx ds + [B]: with x = 0 imposed at the ends the natural condition is
   A1 w1 u0 + A2 w2 v0 = 0, i.e. w1 = w2 = 0 (zero end moments).
6. Equivalence with the boundary conditions. x'' = w1 u0 + w2 v0 (a rotation: x'' = 0 iff
   w = 0). EL + hinged ends => G'' = 0 and G = 0 at both ends => G = 0, i.e. A1 w1 = -P xi,
   A2 w2 = -P eta ((xi, eta) = (x.u0, x.v0)). Conversely, for w solving ``inst1`` with w = 0
   at the ends, x_w = -(A1 w1 u0 + A2 w2 v0)/P has x_w''.u0 - w1 = -I1/P, x_w''.v0 - w2 = -I2/P
   (identities), so x_w is the hinged centreline (x_w = x_w'' = 0 at the ends) with these
   curvatures and G[x_w] = 0. Hinged ends x = x'' = 0 <=> w1 = w2 = 0 at the ends.
7. Variants (the coupling system a1 w1'' + (P - a1 om^2) w1 + c1 om w2' = 0,
   a2 w2'' + (P - a2 om^2) w2 + c2 om w1' = 0, w = 0 at the ends). Scaling w2 -> g w2 maps
   (c1, c2) -> (g c1, c2/g) and keeps the boundary conditions, so the spectrum depends on c1 c2
   only. With weights (1, r), r = -c1/c2, the pencil is formally self-adjoint (the Lagrange
   form is a total derivative iff c1 + r c2 = 0); the weight diag(1, r) is positive definite
   iff r > 0, i.e. c1 c2 < 0, and then the spectrum is real. For r < 0 (the flipped sign) the
   form is indefinite and complex pairs can occur (and do, numerically). At A1 = A2 = A,
   zeta = w1 + i w2 (or w1 + w2 for the flipped sign) reduces every variant to one scalar ODE
   with closed-form eigenvalues: printed P = A (n pi/L)^2 (twist-independent: the factor 2
   completes the square (d/ds + i om)^2), factor 1 adds 3/4 A om^2, flipped sign 2 A om^2.

Variants (numerical, :func:`variant_table`): a dense Chebyshev collocation (Trefethen's
``cheb``) of the coupling system that uses nothing from ``spectral_rod``; validated on the
printed ``inst1`` against the mpmath characteristic equation and on the variants at nu = 1
against the closed forms of step 7.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from functools import lru_cache
from typing import Any, NamedTuple

import numpy as np
import pandas as pd
import sympy as sp
from numpy.typing import NDArray

from spectral_rod import ConvergenceWarning
from spectral_rod.derivations._sympy import DerivationError, eps, s
from spectral_rod.derivations._sympy import check as _check
from spectral_rod.derivations._sympy import d as _d
from spectral_rod.derivations._sympy import vec as _vec
from spectral_rod.derivations._sympy import z as _z
from spectral_rod.derivations._sympy import zv as _zv
from spectral_rod.figure1.data import FIGURE1_NU

A1, A2, A3, P = sp.symbols("A1 A2 A3 P", positive=True)
omega30 = sp.Symbol("omega30", real=True)
x1, x2, alpha, f = (sp.Function(n, real=True)(s) for n in ("x1", "x2", "alpha", "f"))
w1, w2 = (sp.Function(n, real=True)(s) for n in ("w1", "w2"))
Omega = omega30 * s


# ------------------------------------------------------------------------- sympy helpers

def _order(expr: sp.Expr | sp.Matrix, k: int) -> sp.Expr | sp.Matrix:
    """The eps^k coefficient of expr (k = 0 or 1), by differentiation at eps = 0."""
    e = expr.diff(eps, k) if k else expr
    return e.subs(eps, 0).doit()


def frames() -> dict[str, sp.Matrix]:
    """Cartesian components of e1, e2, e3 and of the Eq. ``frenini`` frame u0, v0, t0."""
    e1, e2, e3 = _vec(1, 0, 0), _vec(0, 1, 0), _vec(0, 0, 1)
    return {"e1": e1, "e2": e2, "e3": e3, "t0": e3,
            "u0": sp.cos(Omega) * e1 + sp.sin(Omega) * e2,
            "v0": -sp.sin(Omega) * e1 + sp.cos(Omega) * e2}


def inst1(v1: sp.Expr, v2: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Left-hand sides (I1, I2) of Eq. ``inst1`` as printed, for curvatures v1, v2."""
    return (A1 * _d(v1, 2) + (P - A1 * omega30**2) * v1 - 2 * A2 * omega30 * _d(v2),
            A2 * _d(v2, 2) + (P - A2 * omega30**2) * v2 + 2 * A1 * omega30 * _d(v1))


def munder(Ft: sp.Expr, w: Sequence[sp.Expr], M: Sequence[sp.Expr],
           m: Sequence[sp.Expr] = (0, 0, 0), q: Sequence[sp.Expr] = (0, 0, 0)) -> list[sp.Expr]:
    """The four lines of Eq. ``Munder`` as printed; w = (w1, w2, w3), M = (M_u, M_v, M_t),
    m = (m_u, m_v, m_t), q = (q_u, q_v, q_t)."""
    o1, o2, o3 = w
    Mu, Mv, Mt = M
    mu, mv, mt = m
    qu, qv, qt = q
    bv = _d(Mv) + o3 * Mu + o2 * Mt + mv
    bu = _d(Mu) - o3 * Mv + o1 * Mt + mu
    return [_d(Ft) + o1 * _d(Mv) - o2 * _d(Mu) + o3 * (o1 * Mu + o2 * Mv) + o1 * mv - o2 * mu + qt,
            _d(Mt) - o1 * Mu - o2 * Mv + mt,
            _d(bv) + o3 * bu - o1 * Ft - qu,
            _d(bu) - o3 * bv + o2 * Ft + qv]


def constit(w: Sequence[sp.Expr], w0: Sequence[sp.Expr]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Eq. ``constit``: (M_u, M_v, M_t) = (-A2 (w2 - w20), A1 (w1 - w10), A3 (w3 - w30))."""
    return (-A2 * (w[1] - w0[1]), A1 * (w[0] - w0[0]), A3 * (w[2] - w0[2]))


# ------------------------------------------------------------------------- steps 1-4

def check_reference_state(F: dict[str, sp.Matrix]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Step 1: Eq. ``frenini`` torsions of the twisted frame; the compressed state solves
    Eq. ``Munder`` with M = 0, F_t = -P. Returns (w10, w20, w30)."""
    t0, u0, v0 = F["t0"], F["u0"], F["v0"]
    w0 = (_d(t0).dot(u0), _d(t0).dot(v0), _d(u0).dot(v0))
    _check(_z(w0[0]) and _z(w0[1]) and _z(w0[2] - omega30),
           "1: frenini torsions of the twisted frame are (0, 0, omega30)")
    for vec in (_d(t0) - (w0[0] * u0 + w0[1] * v0), _d(u0) - (-w0[0] * t0 + w0[2] * v0),
                _d(v0) - (-w0[1] * t0 - w0[2] * u0)):
        _check(_zv(vec), "1: the twisted frame satisfies Eq. frenini")
    _check(all(_z(line) for line in munder(-P, (0, 0, omega30), (0, 0, 0))),
           "1: the compressed rod (F_t = -P, M = 0) solves all four lines of Eq. Munder")
    return sp.Integer(0), sp.Integer(0), omega30


def perturbed_frame(F: dict[str, sp.Matrix]) -> dict[str, sp.Matrix]:
    """Step 2: the exact orthonormal frame (t, u, v) of the perturbed rod (functions of eps).

    t = R'/|R'| for R = s e3 + eps x; u = Gram-Schmidt of the axis rotated by Omega + eps alpha;
    v = t x u. Checks the first-order parts t1 = x', u1 = alpha v0 - (x'.u0) t0,
    v1 = -alpha u0 - (x'.v0) t0 and that v is also Gram-Schmidt of the rotated v-axis.
    """
    xv = x1 * F["e1"] + x2 * F["e2"]
    Rp = F["e3"] + eps * _d(xv)
    t = Rp / sp.sqrt(Rp.dot(Rp))
    ang = Omega + eps * alpha
    ut = sp.cos(ang) * F["e1"] + sp.sin(ang) * F["e2"]
    vt = -sp.sin(ang) * F["e1"] + sp.cos(ang) * F["e2"]
    uh = ut - ut.dot(t) * t
    u = uh / sp.sqrt(uh.dot(uh))
    v = t.cross(u)
    t0, u0, v0, xp = F["t0"], F["u0"], F["v0"], _d(xv)
    _check(_zv(_order(t, 0) - t0) and _zv(_order(u, 0) - u0) and _zv(_order(v, 0) - v0),
           "2: the perturbed frame reduces to (t0, u0, v0) at eps = 0")
    _check(_zv(_order(t, 1) - xp), "2: t1 = x'")
    _check(_zv(_order(u, 1) - (alpha * v0 - xp.dot(u0) * t0)), "2: u1 = alpha v0 - (x'.u0) t0")
    _check(_zv(_order(v, 1) - (-alpha * u0 - xp.dot(v0) * t0)),
           "2: v1 = -alpha u0 - (x'.v0) t0")
    vh = vt - vt.dot(t) * t - vt.dot(u) * u
    _check(_zv(_order(vh / sp.sqrt(vh.dot(vh)) - v, 1)),
           "2: v = t x u agrees with Gram-Schmidt of the rotated v-axis")
    return {"t": t, "u": u, "v": v, "x": xv}


def first_order_torsions(F: dict[str, sp.Matrix], fr: dict[str, sp.Matrix]
                         ) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Step 3: eps^1 parts of w1 = t'.u, w2 = t'.v, w3 = u'.v (Eq. ``frenet``).

    Returns (x''.u0, x''.v0, alpha'); also checks the generic-frame argument, the paper's
    geometric relations and its printed perturbation moments (Eq. ``constit``).
    """
    t, u, v, xv = fr["t"], fr["u"], fr["v"], fr["x"]
    u0, v0 = F["u0"], F["v0"]
    xpp = _d(xv, 2)
    w_1 = (xpp.dot(u0), xpp.dot(v0), _d(alpha))
    exact = (_d(t).dot(u), _d(t).dot(v), _d(u).dot(v))
    for k in range(3):
        _check(_z(_order(exact[k], 0) - (0, 0, omega30)[k]), f"3: w{k + 1} at order eps^0")
        _check(_z(_order(exact[k], 1) - w_1[k]), f"3: w{k + 1} at order eps^1 (Eq. frenet)")
    # any first-order perturbation a(s) of u gives the same w1: t0' = 0 kills (t0)'.a
    a = sp.Matrix([sp.Function(f"a{i}", real=True)(s) for i in range(3)])
    t_lin = F["t0"] + eps * _d(xv)
    _check(_z(_order(_d(t_lin).dot(u0 + eps * a), 1) - w_1[0]),
           "3: w1 is the same for any first-order perturbation of u")
    # the paper's geometric relations: x'' = w1 u0 + w2 v0
    _check(_z(_d(x1, 2) - (w_1[0] * sp.cos(Omega) - w_1[1] * sp.sin(Omega))),
           "3: x1'' = w1 cos(Omega) - w2 sin(Omega)")
    _check(_z(_d(x2, 2) - (w_1[0] * sp.sin(Omega) + w_1[1] * sp.cos(Omega))),
           "3: x2'' = w1 sin(Omega) + w2 cos(Omega)")
    Mu, Mv, Mt = constit(w_1, (0, 0, 0))
    _check(_z(Mu - A2 * (_d(x1, 2) * sp.sin(Omega) - _d(x2, 2) * sp.cos(Omega))),
           "3: printed M_u = A2 (x1'' sin - x2'' cos)")
    _check(_z(Mv - A1 * (_d(x1, 2) * sp.cos(Omega) + _d(x2, 2) * sp.sin(Omega))),
           "3: printed M_v = A1 (x1'' cos + x2'' sin)")
    _check(_z(Mt - A3 * _d(alpha)), "3: printed M_t = A3 alpha'")
    return w_1


def linearised_munder(w_1: tuple[sp.Expr, sp.Expr, sp.Expr]) -> list[sp.Expr]:
    """Step 4: first order of Eq. ``Munder`` about (F_t = -P, M = 0, w = (0, 0, omega30)).

    Checked for abstract curvature perturbations (w1, w2) and again with w from step 3:
    lines = [f', A3 alpha'', I1, -I2]. Returns the four first-order lines in w1, w2, alpha, f.
    """
    w = (eps * w1, eps * w2, omega30 + eps * _d(alpha))
    lines = munder(-P + eps * f, w, constit(w, (0, 0, omega30)))
    lin = [sp.expand(_order(line, 1)) for line in lines]
    _check(all(_z(_order(line, 0)) for line in lines), "4: Eq. Munder holds at order eps^0")
    I1, I2 = inst1(w1, w2)
    names = ("f'", "A3 alpha''", "I1 of inst1", "-I2 of inst1")
    for k, (got, want) in enumerate(zip(lin, (_d(f), A3 * _d(alpha, 2), I1, -I2), strict=True)):
        _check(_z(got - want), f"4: line {k + 1} of Eq. Munder at order eps^1 is {names[k]}")
    # lines 3-4 are free of f and alpha; lines 1-2 are free of w: the decoupling
    _check(not ({f, alpha} & (lin[2].atoms(sp.Function) | lin[3].atoms(sp.Function))),
           "4: lines 3-4 of Eq. Munder contain neither f nor alpha")
    _check(not ({w1, w2} & (lin[0].atoms(sp.Function) | lin[1].atoms(sp.Function))),
           "4: lines 1-2 of Eq. Munder contain no w")
    subs = {w1: w_1[0], w2: w_1[1]}
    I1x, I2x = inst1(w_1[0], w_1[1])
    _check(_z(lin[2].subs(subs).doit() - I1x) and _z(lin[3].subs(subs).doit() + I2x),
           "4: lines 3-4 with w from step 3 are inst1 in x")
    return lin


# ------------------------------------------------------------------------- steps 5-6

def end_shortening() -> sp.Expr:
    """Step 5a: 1 - t.e3 for the unit tangent t = (x1', x2', sqrt(1 - |x'|^2)) of an
    inextensible centreline: eps^2 |x'|^2/2 + O(eps^4). Returns the eps^2 coefficient."""
    a, b = sp.symbols("a b", real=True)  # stand-ins for x1', x2'
    short = 1 - sp.sqrt(1 - eps**2 * (a**2 + b**2))
    ser = sp.series(short, eps, 0, 4).removeO()
    _check(sp.expand(ser - eps**2 * (a**2 + b**2) / 2) == 0,
           "5a: end shortening 1 - t.e3 = eps^2 |x'|^2/2 + O(eps^4)")
    return (_d(x1) ** 2 + _d(x2) ** 2) / 2


def energy_route(F: dict[str, sp.Matrix]) -> dict[str, sp.Expr]:
    """Step 5: Euler-Lagrange equations of 1/2 A1 w1^2 + 1/2 A2 w2^2 - P/2 |x'|^2 with
    w1 = x''.u0, w2 = x''.v0, their relation to Eq. ``inst1`` and the natural end conditions.

    Returns the Lagrangian ``L``, the EL vector ``E`` (Cartesian), ``G`` and the body-frame
    components ``E_u``, ``E_v`` (identically I1, I2 of w(x)).
    """
    from sympy.calculus.euler import euler_equations

    u0, v0 = F["u0"], F["v0"]
    xv = x1 * F["e1"] + x2 * F["e2"]
    k1, k2 = _d(xv, 2).dot(u0), _d(xv, 2).dot(v0)
    L = A1 * k1**2 / 2 + A2 * k2**2 / 2 - P * end_shortening()
    el = [eq.lhs - eq.rhs for eq in euler_equations(L, [x1, x2], s)]
    # by hand: E = (dL/dx'')'' - (dL/dx')' with dL/dx'' = A1 w1 u0 + A2 w2 v0, dL/dx' = -P x'
    moment = A1 * k1 * u0 + A2 * k2 * v0
    E = _d(moment, 2) + P * _d(xv, 2)
    _check(_z(el[0] - E[0]) and _z(el[1] - E[1]) and _z(E[2]),
           "5: sympy's Euler-Lagrange equations equal the hand form E")
    G = moment + P * xv
    _check(_zv(E - _d(G, 2)), "5: E = G''")
    I1, I2 = inst1(k1, k2)
    E_u, E_v = E.dot(u0), E.dot(v0)
    _check(_z(E_u - I1) and _z(E_v - I2), "5: E.u0 = I1, E.v0 = I2 (inst1 in the body frame)")
    # first variation: dL = E.h + B' with B = (dL/dx' - (dL/dx'')').h + (dL/dx'').h'
    h = tuple(sp.Function(n, real=True)(s) for n in ("h1", "h2"))
    hv = h[0] * F["e1"] + h[1] * F["e2"]
    dL = _order(L.subs({x1: x1 + eps * h[0], x2: x2 + eps * h[1]}).doit(), 1)
    B = (-P * _d(xv) - _d(moment)).dot(hv) + moment.dot(_d(hv))
    _check(_z(dL - E.dot(hv) - _d(B)), "5: first variation = E.h + B' (natural end conditions)")
    # torsion energy 1/2 A3 alpha'^2: its EL expression is -A3 alpha'' (line 2 of Munder)
    el_t = euler_equations(A3 * _d(alpha) ** 2 / 2, [alpha], s)[0]
    _check(_z(el_t.lhs - el_t.rhs + A3 * _d(alpha, 2)),
           "5: the torsion energy gives A3 alpha'' = 0 (line 2 of Eq. Munder)")
    return {"L": L, "E": E, "G": G, "E_u": E_u, "E_v": E_v, "natural_bc": moment}


def hinged_equivalence(F: dict[str, sp.Matrix]) -> sp.Matrix:
    """Step 6: hinged ends x = x'' = 0 <=> w = 0 at the ends, and inst1 => EL.

    Returns x_w = -(A1 w1 u0 + A2 w2 v0)/P, the hinged centreline of curvatures (w1, w2).
    """
    u0, v0 = F["u0"], F["v0"]
    rot = sp.Matrix.hstack(u0[:2, 0], v0[:2, 0])  # (x1'', x2'') = rot (w1, w2)
    _check(_z(rot.det() - 1), "6: x'' = w1 u0 + w2 v0 is a rotation")
    xw = -(A1 * w1 * u0 + A2 * w2 * v0) / P
    I1, I2 = inst1(w1, w2)
    _check(_z(_d(xw, 2).dot(u0) - w1 + I1 / P) and _z(_d(xw, 2).dot(v0) - w2 + I2 / P),
           "6: x_w''.u0 - w1 = -I1/P, x_w''.v0 - w2 = -I2/P")
    _check(_z(xw[2]), "6: x_w has no axial component")
    # G[x_w] = A1 k1 u0 + A2 k2 v0 + P x_w vanishes when (k1, k2) = (w1, w2), i.e. on inst1
    k1 = _d(xw, 2).dot(u0)
    k2 = _d(xw, 2).dot(v0)
    G = A1 * k1 * u0 + A2 * k2 * v0 + P * xw
    _check(_zv(G - (A1 * (k1 - w1) * u0 + A2 * (k2 - w2) * v0)),
           "6: G[x_w] vanishes on the curvatures of inst1")
    return xw


# ------------------------------------------------------------------------- step 7

def coupling_operator(c1: sp.Expr, c2: sp.Expr, a1: sp.Expr = A1, a2: sp.Expr = A2,
                      v1: sp.Expr = w1, v2: sp.Expr = w2) -> tuple[sp.Expr, sp.Expr]:
    """The variant family a1 v1'' + (P - a1 om^2) v1 + c1 om v2', a2 v2'' + ... + c2 om v1'.

    Eq. ``inst1`` is (c1, c2) = (-2 A2, 2 A1).
    """
    return (a1 * _d(v1, 2) + (P - a1 * omega30**2) * v1 + c1 * omega30 * _d(v2),
            a2 * _d(v2, 2) + (P - a2 * omega30**2) * v2 + c2 * omega30 * _d(v1))


#: Coupling coefficients (c1, c2) of the printed equation and of the three variants.
SYMBOLIC_VARIANTS: dict[str, tuple[sp.Expr, sp.Expr]] = {
    "printed": (-2 * A2, 2 * A1),
    "factor_one": (-A2, A1),
    "sign_flipped": (2 * A2, 2 * A1),
    "A_exchanged": (-2 * A1, 2 * A2),
}


def check_variant_structure() -> dict[str, dict[str, sp.Expr]]:
    """Step 7: similarity (spectrum depends on c1 c2), self-adjointness, closed forms at A1 = A2.

    Returns per variant: ``product`` c1 c2, ``weight`` r = -c1/c2 making the pencil formally
    self-adjoint, and ``nu1_shift``: the twist term of the eigenvalues P = A (n pi/L)^2 + shift
    at A1 = A2 = A.
    """
    from sympy.calculus.euler import euler_equations

    c1, c2, g, r = sp.symbols("c1 c2 gamma r", nonzero=True)
    _check(tuple(inst1(w1, w2)) == coupling_operator(*SYMBOLIC_VARIANTS["printed"]),
           "7: inst1 is the coupling system with (c1, c2) = (-2 A2, 2 A1)")
    # scaling w2 -> g w2: operator(c1, c2)(w1, g w2) = diag(1, g) operator(g c1, c2/g)(w1, w2)
    lhs = coupling_operator(c1, c2, v2=g * w2)
    rhs = coupling_operator(g * c1, c2 / g)
    _check(_z(lhs[0] - rhs[0]) and _z(lhs[1] - g * rhs[1]),
           "7: scaling w2 -> g w2 maps (c1, c2) to (g c1, c2/g)")
    # Lagrange form with weights (1, r) is a total derivative iff c1 + r c2 = 0
    z1, z2 = (sp.Function(n, real=True)(s) for n in ("z1", "z2"))
    Lw, Lz = coupling_operator(c1, c2), coupling_operator(c1, c2, v1=z1, v2=z2)
    form = z1 * Lw[0] + r * z2 * Lw[1] - w1 * Lz[0] - r * w2 * Lz[1]
    el = [e.lhs for e in euler_equations(form, [w1, w2, z1, z2], s)]
    _check(all(_z(e.subs(r, -c1 / c2)) for e in el),
           "7: the Lagrange form with weight r = -c1/c2 is a total derivative")
    _check(_z(el[2] - (c1 + r * c2) * omega30 * _d(w2)),
           "7: the Lagrange form is a total derivative only if c1 + r c2 = 0")
    out = {}
    A = sp.Symbol("A", positive=True)
    phi = sp.Function("phi")(s)
    for name, (k1, k2) in SYMBOLIC_VARIANTS.items():
        e1, e2 = k1.subs({A1: A, A2: A}), k2.subs({A1: A, A2: A})
        out[name] = {"product": sp.factor(k1 * k2), "weight": sp.simplify(-k1 / k2),
                     "nu1_shift": _isotropic_shift(e1, e2, A, phi)}
    return out


def _isotropic_shift(k1: sp.Expr, k2: sp.Expr, A: sp.Symbol, phi: sp.Function) -> sp.Expr:
    """At A1 = A2 = A: the combination L1 + c L2 (c = i or 1) that is an ODE in
    zeta = w1 + c w2 (it is when c^2 k2 = k1), and the gauge zeta = exp(b s) phi that removes
    zeta', leaving A phi'' + (P - shift) phi = 0. Returns shift (both steps checked)."""
    zeta = sp.Function("zeta")(s)
    lw = coupling_operator(k1, k2, A, A)
    for c in (sp.I, 1):
        comb = sp.expand(lw[0] + c * lw[1])
        beta = k1 / c  # coefficient of om zeta'
        cand = A * _d(zeta, 2) + beta * omega30 * _d(zeta) + (P - A * omega30**2) * zeta
        if not _z(comb - cand.subs(zeta, w1 + c * w2).doit()):
            continue
        b = -beta * omega30 / (2 * A)
        gauged = sp.expand(cand.subs(zeta, sp.exp(b * s) * phi).doit() / sp.exp(b * s))
        shift = sp.simplify(P - (gauged - A * _d(phi, 2)).coeff(phi))
        _check(_z(gauged - (A * _d(phi, 2) + (P - shift) * phi)),
               "7: the gauge exp(b s) removes zeta' at A1 = A2")
        return shift
    raise DerivationError("7: no combination w1 + c w2 closes (c = i, 1)")


@lru_cache(maxsize=1)
def derive() -> dict[str, Any]:
    """All steps, checked; returns the results.

    Keys: ``w0`` (w10, w20, w30), ``w_first`` (first-order w1, w2, w3 in x1, x2, alpha),
    ``munder_first`` (first-order lines of Eq. ``Munder`` in w1, w2, alpha, f), ``inst1``
    (I1, I2 in w1, w2), ``energy`` (dict of step 5), ``x_hinged`` (step 6), ``variants``
    (step 7).
    """
    F = frames()
    w0 = check_reference_state(F)
    fr = perturbed_frame(F)
    w_first = first_order_torsions(F, fr)
    lin = linearised_munder(w_first)
    return {"w0": w0, "w_first": w_first, "munder_first": lin, "inst1": inst1(w1, w2),
            "energy": energy_route(F), "x_hinged": hinged_equivalence(F),
            "variants": check_variant_structure()}


# ------------------------------------------------------------------------- variants: numerics

VARIANTS = tuple(SYMBOLIC_VARIANTS)
#: An eigenvalue with |Im| above this fraction of |lambda| counts as complex.
IMAG_REL = 1.0e-8
#: Default collocation degree and the increment of the resolution check. Every p* on
#: Figure 1's range is converged to ~1e-12 already at n = 24 (measured, all variants,
#: Omega <= 10); n + 12 = 44 keeps the matrices (2 n - 2 = 86 rows) below the size at which the
#: threaded LAPACK slows down tenfold on a loaded machine (measured: 1 ms at 86, 6-50 ms at 94+).
N_DEFAULT, N_CHECK = 32, 12
#: The band of Figure 1's digitisation (``reference_data/figure1_digitised.md``): a change of
#: p* below this cannot be seen in the figure.
FIGURE_RESOLUTION = 5.0e-4


def variant_coefficients(name: str, nu: float) -> tuple[float, float, float, float]:
    """(a1, a2, c1, c2) of a variant in the units A1 = 1, A2 = nu (see :func:`coupling_operator`).

    >>> variant_coefficients("printed", 1.5)
    (1.0, 1.5, -3.0, 2.0)
    """
    if name not in SYMBOLIC_VARIANTS:
        raise ValueError(f"name must be one of {VARIANTS}, got {name!r}")
    if isinstance(nu, bool) or not isinstance(nu, (int, float)) or not (
            math.isfinite(nu) and nu > 0):
        raise ValueError(f"nu must be a finite positive number, got {nu!r}")
    c1, c2 = (float(c.subs({A1: 1, A2: nu})) for c in SYMBOLIC_VARIANTS[name])
    return 1.0, float(nu), c1, c2


def cheb(n: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Trefethen's ``cheb`` (Spectral Methods in MATLAB, 2000): differentiation matrix D
    (n+1 x n+1) on the points x_j = cos(j pi/n), j = 0..n.

    >>> D, x = cheb(2); round(float(D[0, 0]), 12)
    1.5
    """
    x = np.cos(np.pi * np.arange(n + 1) / n)
    c = np.r_[2.0, np.ones(n - 1), 2.0] * (-1.0) ** np.arange(n + 1)
    dx = x[:, None] - x[None, :]
    D = np.outer(c, 1.0 / c) / (dx + np.eye(n + 1))
    return D - np.diag(D.sum(axis=1)), x


def coupling_matrix(coeffs: tuple[float, float, float, float], twist_angle: float,
                    n: int = N_DEFAULT) -> NDArray[np.float64]:
    """K of K w = lambda w: the coupling system collocated on s in [0, 1], w = 0 at the ends.

    The system a1 w1'' + (lambda - a1 Om^2) w1 + c1 Om w2' = 0 (and the same with 1 <-> 2) is
    written on the n - 1 interior Chebyshev points s_j = (1 + cos(j pi/n))/2 of each field
    (Dirichlet rows and columns removed); w = (w1 values, w2 values), size 2 n - 2.
    """
    a1, a2, c1, c2 = coeffs
    D, _ = cheb(n)
    D = 2.0 * D  # d/ds = 2 d/dx for s = (x + 1)/2
    D2, D1, eye = (D @ D)[1:-1, 1:-1], D[1:-1, 1:-1], np.eye(n - 1)
    om = float(twist_angle)
    return np.block([[-a1 * D2 + a1 * om**2 * eye, -c1 * om * D1],
                     [-c2 * om * D1, -a2 * D2 + a2 * om**2 * eye]])


def coupled_spectrum(coeffs: tuple[float, float, float, float], twist_angle: float,
                     n: int = N_DEFAULT) -> NDArray[np.inexact]:
    """All eigenvalues lambda = P L^2/A1 of :func:`coupling_matrix`.

    Example: coupled_spectrum((1, 1, 0, 0), 0.0) contains pi^2 twice (the Euler load).
    """
    return np.linalg.eigvals(coupling_matrix(coeffs, twist_angle, n))


def coupled_mode(coeffs: tuple[float, float, float, float], twist_angle: float,
                 n: int = N_DEFAULT) -> tuple[float, NDArray[np.float64], NDArray[np.float64]]:
    """Lowest positive real eigenpair (p*, w1, w2) of :func:`coupling_matrix`, w on the
    interior points, normalised so that the entry of largest modulus is +1."""
    ev, vec = np.linalg.eig(coupling_matrix(coeffs, twist_angle, n))
    real = np.nonzero((np.abs(ev.imag) <= IMAG_REL * np.abs(ev)) & (ev.real > 0))[0]
    k = real[np.argmin(ev[real].real)]
    v = vec[:, k].real
    v = v / v[np.argmax(np.abs(v))]
    return float(ev[k].real / math.pi**2), v[: n - 1], v[n - 1:]


class VariantRoot(NamedTuple):
    """Lowest positive real eigenvalue p* = lambda/pi^2 of a coupling system, with diagnostics.

    ``error`` = |p*(n) - p*(n + N_CHECK)|; ``lowest_complex`` = the resolved complex eigenvalue
    (lambda/pi^2, present at both resolutions to 1e-6) of smallest real part, or None.
    """

    p_star: float
    error: float
    lowest_complex: complex | None


def _split(ev: NDArray[np.inexact]) -> tuple[NDArray[np.float64], NDArray[np.complex128]]:
    """(sorted positive real eigenvalues, complex eigenvalues), both divided by pi^2."""
    ev = ev / math.pi**2
    is_real = np.abs(ev.imag) <= IMAG_REL * np.abs(ev)
    real = np.sort(ev[is_real].real)
    return real[real > 0], ev[~is_real]


def _resolved_lowest_complex(coarse: NDArray[np.complex128], fine: NDArray[np.complex128]
                             ) -> complex | None:
    """Collocation of a non-normal operator gives spurious complex eigenvalues far up the
    spectrum; a physical one is present, to 1e-6 relative, at both resolutions."""
    keep = [z for z in coarse if fine.size and np.min(np.abs(fine - z)) <= 1e-6 * abs(z)]
    return complex(min(keep, key=lambda z: z.real)) if keep else None


def variant_critical_load(coeffs: tuple[float, float, float, float], twist_angle: float,
                          n: int = N_DEFAULT, tol: float = 1e-8) -> VariantRoot:
    """p* of a coupling system (its lowest positive real eigenvalue / pi^2), at n and n + 12.

    A static buckling load is a real lambda with a nontrivial solution, so complex eigenvalues
    (possible when the system is not self-adjoint) are reported, not taken. Warns with
    ``spectral_rod.ConvergenceWarning`` if the two resolutions differ by more than tol.
    Example: variant_critical_load(variant_coefficients("printed", 1.5), 2 * math.pi).p_star
    is 1.195993680888... (the mpmath reference).
    """
    if isinstance(n, bool) or not isinstance(n, int) or not 8 <= n <= 128:
        raise ValueError(f"n must be an integer in [8, 128], got {n!r}")
    if not (isinstance(twist_angle, (int, float, np.floating)) and math.isfinite(twist_angle)):
        raise ValueError(f"twist_angle must be a finite real number, got {twist_angle!r}")
    real, cplx = _split(coupled_spectrum(coeffs, twist_angle, n))
    real_f, cplx_f = _split(coupled_spectrum(coeffs, twist_angle, n + N_CHECK))
    if real.size == 0 or real_f.size == 0:
        raise RuntimeError(f"no positive real eigenvalue at twist_angle={twist_angle}")
    err = abs(real[0] - real_f[0])
    if err > tol:
        warnings.warn(f"variant p* not converged at twist_angle={twist_angle}: "
                      f"|p*(n) - p*(n+{N_CHECK})| = {err:.2e}", ConvergenceWarning, stacklevel=2)
    return VariantRoot(float(real_f[0]), float(err), _resolved_lowest_complex(cplx, cplx_f))


def variant_curve(name: str, nu: float, twist_angles: Sequence[float], n: int = N_DEFAULT
                  ) -> list[VariantRoot]:
    """p* of one variant along a list of twist angles."""
    coeffs = variant_coefficients(name, nu)
    return [variant_critical_load(coeffs, float(om), n) for om in twist_angles]


def onset_twist(name: str, nu: float, upper: float, threshold: float = FIGURE_RESOLUTION
                ) -> float:
    """Smallest Omega in (0, upper] at which |p*_variant - p*_printed| reaches threshold
    (bisection to 1e-4; assumes one crossing, as for the variants, whose change grows
    like Omega^2 from 0)."""
    def change(om: float) -> float:
        a, b = (variant_curve(v, nu, [om])[0].p_star for v in (name, "printed"))
        return abs(a - b) - threshold

    lo, hi = 0.0, float(upper)
    if change(hi) < 0:
        raise ValueError(f"no change of {threshold} up to twist_angle={upper}")
    while hi - lo > 1e-4:
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if change(mid) >= 0 else (mid, hi)
    return hi


def figure1_deviation(name: str, nu: float, digitised: pd.DataFrame | None = None,
                      every: int = 3) -> dict[str, float] | None:
    """Deviation of a variant's p* from the digitised Figure 1 curve of this nu: max |dp|, rms
    and the twist angle of the max, over every ``every``-th digitised point (None if Figure 1
    has no curve for nu). ``digitised`` defaults to the packaged digitised Figure 1."""
    if digitised is None:
        digitised = _digitised()
    g = digitised[np.isclose(digitised["nu"], nu, rtol=0, atol=1e-12)].iloc[::every]
    if g.empty:
        return None
    p = np.array([r.p_star for r in variant_curve(name, nu, g["twist_angle"])])
    dev = p - g["p_star"].to_numpy()
    k = int(np.argmax(np.abs(dev)))
    return {"max": float(np.abs(dev[k])), "rms": float(np.sqrt(np.mean(dev**2))),
            "at_twist_angle": float(g["twist_angle"].iloc[k])}


@lru_cache(maxsize=1)
def _digitised() -> pd.DataFrame:
    from spectral_rod import load_figure1

    return load_figure1()


def variant_table(twist_angles: Sequence[float] | None = None,
                  nus: Sequence[float] = FIGURE1_NU, digitised: pd.DataFrame | None = None,
                  every: int = 3) -> list[dict[str, object]]:
    """One row per (variant, nu): what the variant does to p* on Figure 1's range.

    Grid default: Omega = 0, 0.25, ..., 10. Row keys: ``variant``, ``nu``, ``c1``, ``c2``
    (A1 = 1), ``coupling_product`` c1 c2 (the spectrum depends on it only), ``self_adjoint_weight``
    -c1/c2 (> 0: self-adjoint with a positive weight, real spectrum), ``max_change`` =
    max |p*_variant - p*_reference| on the grid (mpmath ``characteristic_critical_load``),
    ``at_twist_angle``, ``onset_twist`` (Omega where the change first reaches 5e-4, None if
    never), ``p_star_at_2pi``, ``complex_eigenvalues`` (resolved ones anywhere on the grid),
    ``figure_max`` / ``figure_rms`` (vs the digitised curve, every ``every``-th point),
    ``max_solver_error``. Cost: about 4 s.
    """
    from spectral_rod.rod.characteristic import characteristic_critical_load

    grid = np.linspace(0.0, 10.0, 41) if twist_angles is None else np.asarray(twist_angles)
    rows = []
    for nu in nus:
        ref = np.array([float(characteristic_critical_load(float(om), nu).p_star) for om in grid])
        for name in VARIANTS:
            roots = variant_curve(name, nu, [*grid, 2 * math.pi])
            change = np.abs(np.array([r.p_star for r in roots[:-1]]) - ref)
            above = np.nonzero(change > FIGURE_RESOLUTION)[0]
            fig = figure1_deviation(name, float(nu), digitised, every)
            _, _, c1, c2 = variant_coefficients(name, nu)
            rows.append({
                "variant": name, "nu": float(nu), "c1": c1, "c2": c2,
                "coupling_product": c1 * c2, "self_adjoint_weight": -c1 / c2,
                "max_change": float(change.max()),
                "at_twist_angle": float(grid[int(np.argmax(change))]),
                "onset_twist": onset_twist(name, nu, grid[above[0]]) if above.size else None,
                "p_star_at_2pi": roots[-1].p_star,
                "complex_eigenvalues": any(r.lowest_complex is not None for r in roots),
                "figure_max": fig["max"] if fig else None,
                "figure_rms": fig["rms"] if fig else None,
                "max_solver_error": max(r.error for r in roots)})
    return rows


def main() -> None:
    d = derive()
    print("Checked: frenini torsions and reference state of Munder; perturbed frame; frenet "
          "first-order torsions; printed moments; Munder first order; energy route; hinged "
          "equivalence; variant structure.")
    print("first-order (w1, w2, w3):", *d["w_first"], sep="\n  ")
    print("Munder to first order [= f', A3 alpha'', I1, -I2]:")
    for line in d["munder_first"]:
        print("  ", sp.collect(line, [P, A1, A2, A3]), "= 0")
    print("inst1:", *d["inst1"], sep="\n  ")
    print("\nvariant structure (A1 = A2 = A: eigenvalues A (n pi/L)^2 + shift):")
    for name, info in d["variants"].items():
        print(f"  {name:13s} c1 c2 = {info['product']},  weight -c1/c2 = {info['weight']},  "
              f"shift = {info['nu1_shift']}")
    print("\nvariant table (Omega in [0, 10], step 0.25):")
    for row in variant_table():
        print("  " + ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}"
                               for k, v in row.items()))


if __name__ == "__main__":
    main()
