"""Machine-checked derivation of the linearised stability problem of the twisted ring.

Run ``python -m spectral_rod.derivations.ring_linearisation`` to print the operator and the
checks; tests call :func:`derive` and compare the numerical operator of
``spectral_rod.ring.second_variation`` against its output at random parameter values.

Setting (Drozdov & Rabin, section "Stability of a ring"): centreline R0 = R e_r, t0 = e_phi,
u0 = -cos(Omega) e_r + sin(Omega) e_z, v0 = sin(Omega) e_r + cos(Omega) e_z, Omega = N s / R.

Steps, each checked by sympy (a :class:`~spectral_rod.derivations._sympy.DerivationError`
naming the step means the algebra is wrong; the checks are not ``assert`` statements, so they
also run under ``python -O``):

1. Eq. ``frenini`` applied to the reference frame gives the spontaneous torsions
   w10 = cos(Omega)/R, w20 = -sin(Omega)/R, w30 = N/R (as in the paper).
2. Eq. ``Munder`` (all four lines as printed, :func:`spectral_rod.derivations.straight_rod.munder`)
   at the stress-free state (all moments zero, w = w0) under q = -q e_r gives the hoop force
   F_t = -q R.
3. Perturb the frame by a rotation vector eps*theta(s) (global components), d_i = Q d_i0 with
   Q = I + eps Th + eps^2 Th^2/2 (orthogonal to O(eps^3)).  Eq. ``frenet`` (w1 = t'.u,
   w2 = t'.v, w3 = u'.v) gives to first order dw1 = theta'.v0, dw2 = -theta'.u0, dw3 = theta'.t0.
   Eq. ``constit`` then makes the second-order elastic energy 1/2 sum A_i dw_i^2 (the base
   state is stress-free, so second-order parts of w_i are multiplied by zero moments).
4. Inextensible, unshearable centreline R' = d_3: to first order y' = theta x t0, which in
   cylindrical components gives y_r = -R y_phi', theta_z = R y_phi'' + y_phi/R,
   theta_r = y_z'; theta_phi = alpha is the free extra twist.
5. Second order of R' = d_3 is y2' = theta x (theta x t0)/2 (+ a first-order correction of
   theta that closes the ring and is orthogonal to t0); the work of the hoop force on it is
   -int F_t t0 . y2' ds = (q R / 2) int ((theta.t0)^2 - |theta|^2) ds = -(q R/2) int |theta_perp|^2.
6. Load potentials, second order in eps: "hydrostatic" V = q/2 int (R x R').e_z ds (q times the
   projected enclosed area), "axis" V = q int rho ds (rho = distance from the axis), "centre"
   V = q int |R| ds (distance from the centre point), "dead" V = q int e_r(s).R ds (a force
   -q e_r(s) fixed at the material point: linear in y, no second-order part).

Result: second variation 1/2 int (k_density - q g_density) ds with the densities returned by
:func:`derive`, in terms of y_phi(s), y_z(s), alpha(s).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from spectral_rod.derivations._sympy import check as _check
from spectral_rod.derivations._sympy import d as _d
from spectral_rod.derivations._sympy import eps, s
from spectral_rod.derivations._sympy import vec as _vec
from spectral_rod.derivations._sympy import z as _z
from spectral_rod.derivations.straight_rod import munder

R, A1, A2, A3, q = sp.symbols("R A1 A2 A3 q", positive=True)
N = sp.Symbol("N", integer=True, nonnegative=True)
y_phi, y_z, alpha = (sp.Function(n, real=True)(s) for n in ("y_phi", "y_z", "alpha"))


def _skew(v: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def frames() -> dict[str, sp.Matrix]:
    """Cartesian components of e_r, e_phi, e_z and of the reference frame t0, u0, v0."""
    phi = s / R
    Om = N * s / R
    e_r = _vec(sp.cos(phi), sp.sin(phi), 0)
    e_phi = _vec(-sp.sin(phi), sp.cos(phi), 0)
    e_z = _vec(0, 0, 1)
    return {"e_r": e_r, "e_phi": e_phi, "e_z": e_z, "t0": e_phi,
            "u0": -sp.cos(Om) * e_r + sp.sin(Om) * e_z,
            "v0": sp.sin(Om) * e_r + sp.cos(Om) * e_z}


def check_spontaneous_torsions(F: dict[str, sp.Matrix]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Step 1: Eq. ``frenini`` for the reference frame."""
    t0, u0, v0 = F["t0"], F["u0"], F["v0"]
    w10, w20, w30 = (_d(t0).dot(u0), _d(t0).dot(v0), _d(u0).dot(v0))
    Om = N * s / R
    _check(_z(w10 - sp.cos(Om) / R) and _z(w20 + sp.sin(Om) / R) and _z(w30 - N / R),
           "1: frenini torsions w10 = cos(Omega)/R, w20 = -sin(Omega)/R, w30 = N/R")
    # the remaining components of Eq. frenini hold too (the frame is consistent)
    for v in (_d(t0) - (w10 * u0 + w20 * v0), _d(u0) - (-w10 * t0 + w30 * v0),
              _d(v0) - (-w20 * t0 - w30 * u0)):
        _check(all(_z(c) for c in v), "1: the reference frame satisfies Eq. frenini")
    return sp.cos(Om) / R, -sp.sin(Om) / R, N / R


def check_hoop_force(F: dict[str, sp.Matrix], w0: tuple[sp.Expr, sp.Expr, sp.Expr]
                     ) -> sp.Expr:
    """Step 2: all four lines of Eq. ``Munder`` (as printed, :func:`straight_rod.munder
    <spectral_rod.derivations.straight_rod.munder>`) with M = 0, m = 0, w = w0 (from step 1)
    and the load q = -q e_r: line 3 gives F_t = -q R, and with it every line vanishes."""
    load = -q * F["e_r"]
    q_uvt = (load.dot(F["u0"]), load.dot(F["v0"]), load.dot(F["t0"]))
    Ft = sp.Symbol("F_t")  # a constant: F_t' = 0
    lines = munder(Ft, w0, (0, 0, 0), q=q_uvt)
    sol = sp.solve(sp.expand_trig(lines[2]), Ft)
    _check(len(sol) == 1 and _z(sol[0] + q * R), "2: line 3 of Eq. Munder gives F_t = -q R")
    for k, line in enumerate(lines):
        _check(_z(line.subs(Ft, -q * R)),
               f"2: line {k + 1} of Eq. Munder holds for the loaded circle, F_t = -q R")
    return -q * R


def first_order_torsions(F: dict[str, sp.Matrix]) -> tuple[sp.Matrix, list[sp.Expr]]:
    """Step 3: first-order changes of w1, w2, w3 for a rotation theta (cylindrical comps)."""
    th_r, th_phi, th_z = (sp.Function(n, real=True)(s) for n in ("theta_r", "theta_phi",
                                                                  "theta_z"))
    theta = th_r * F["e_r"] + th_phi * F["e_phi"] + th_z * F["e_z"]
    # Q = I + eps Th + eps^2 Th^2/2 is orthogonal to O(eps^3) (pointwise, generic theta)
    gen = _skew(sp.Matrix(sp.symbols("g1 g2 g3")))
    Qg = sp.eye(3) + eps * gen + eps**2 * gen * gen / 2
    QtQ = (Qg.T * Qg - sp.eye(3)).applyfunc(lambda x: sp.expand(x).coeff(eps, 1)
                                            + sp.expand(x).coeff(eps, 2))
    _check(QtQ == sp.zeros(3, 3), "3: Q = I + eps Th + eps^2 Th^2/2 is orthogonal to O(eps^3)")
    # first-order part of d_i = Q d_i0 is theta x d_i0; linearise w1 = t'.u, w2 = t'.v, w3 = u'.v
    t0, u0, v0 = F["t0"], F["u0"], F["v0"]
    dt, du, dv = theta.cross(t0), theta.cross(u0), theta.cross(v0)

    def lin(a0: sp.Matrix, da: sp.Matrix, b0: sp.Matrix, db: sp.Matrix) -> sp.Expr:
        return _d(da).dot(b0) + _d(a0).dot(db)

    dw = [lin(t0, dt, u0, du), lin(t0, dt, v0, dv), lin(u0, du, v0, dv)]
    dth = _d(theta)
    expected = [dth.dot(F["v0"]), -dth.dot(F["u0"]), dth.dot(F["t0"])]
    for k, (a, b) in enumerate(zip(dw, expected, strict=True)):
        _check(_z(a - b), f"3: first-order dw{k + 1} (Eq. frenet) = "
               f"{('theta.v0', '-theta.u0', 'theta.t0')[k]}")
    return theta, expected


def constraint_solution(F: dict[str, sp.Matrix]) -> dict[str, sp.Expr]:
    """Step 4: y' = theta x t0 solved for y_r, theta_r, theta_z in terms of y_phi, y_z."""
    y_r = sp.Function("y_r", real=True)(s)
    th_r, th_z = sp.symbols("theta_r theta_z")
    y = y_r * F["e_r"] + y_phi * F["e_phi"] + y_z * F["e_z"]
    theta = th_r * F["e_r"] + alpha * F["e_phi"] + th_z * F["e_z"]
    res = _d(y) - theta.cross(F["t0"])
    comps = [sp.simplify(res.dot(F[k])) for k in ("e_r", "e_phi", "e_z")]
    yr = sp.solve(comps[1], y_r)[0]
    sol = sp.solve([comps[0].subs(y_r, yr).doit(), comps[2]], [th_r, th_z], dict=True)[0]
    out = {"y_r": sp.simplify(yr), "theta_r": sp.simplify(sol[th_r]),
           "theta_z": sp.simplify(sol[th_z].doit()), "theta_phi": alpha}
    _check(_z(out["y_r"] + R * y_phi.diff(s)), "4: inextensibility y_r = -R y_phi'")
    _check(_z(out["theta_z"] - (R * y_phi.diff(s, 2) + y_phi / R)),
           "4: theta_z = R y_phi'' + y_phi/R")
    _check(_z(out["theta_r"] - y_z.diff(s)), "4: theta_r = y_z'")
    return out


def hoop_work_density(F: dict[str, sp.Matrix], Ft: sp.Expr) -> sp.Expr:
    """Step 5: -F_t t0 . (theta x (theta x t0))/2, the second-order work of the hoop force."""
    th = sp.Matrix(sp.symbols("a b c"))
    t0 = F["t0"]
    dens = -Ft * t0.dot(th.cross(th.cross(t0))) / 2
    perp2 = th.dot(th) - th.dot(t0) ** 2
    _check(_z(dens - (-q * R / 2) * perp2), "5: hoop work density = -(q R/2) |theta_perp|^2")
    return dens


def load_potential_second_order(F: dict[str, sp.Matrix]) -> dict[str, sp.Expr]:
    """Step 6: eps^2 coefficients of the four load potentials (densities per unit s), for a
    general displacement y = y_r e_r + y_phi e_phi + y_z e_z."""
    y_r = sp.Function("y_r", real=True)(s)
    y = y_r * F["e_r"] + y_phi * F["e_phi"] + y_z * F["e_z"]
    Rv = R * F["e_r"] + eps * y
    area = Rv.cross(_d(Rv)).dot(F["e_z"]) * q / 2
    rho = q * sp.sqrt(Rv[0] ** 2 + Rv[1] ** 2)
    dist = q * sp.sqrt(Rv.dot(Rv))
    dead = q * F["e_r"].dot(Rv)

    def second(v: sp.Expr) -> sp.Expr:
        return sp.simplify(sp.diff(v, eps, 2).subs(eps, 0) / 2)

    return {"hydrostatic": second(area), "axis": second(rho), "centre": second(dist),
            "dead": second(dead), "y_r": y_r}


#: The readings of the load whose potentials are derived (those of spectral_rod.RING_LOADS).
LOADS = ("hydrostatic", "axis", "centre", "dead")


@lru_cache(maxsize=1)
def derive() -> dict[str, sp.Expr]:
    """The second variation 1/2 int (K - q G) ds of the twisted ring, all checks applied.

    Returns sympy densities in y_phi(s), y_z(s), alpha(s) (see the module symbols):
    ``K`` (A1 dw1^2 + A2 dw2^2 + A3 dw3^2), ``G_hydrostatic``, ``G_axis``, ``G_centre`` and
    ``G_dead`` (one per reading of the load, :data:`spectral_rod.RING_LOADS`), plus
    ``F_t`` (hoop force), ``theta_r``, ``theta_z``, ``y_r`` (constraint solution) and
    ``w10``, ``w20``, ``w30``.
    """
    F = frames()
    w0 = check_spontaneous_torsions(F)
    Ft = check_hoop_force(F, w0)
    theta_fn, dw = first_order_torsions(F)
    cons = constraint_solution(F)
    th_r, th_phi, th_z = (sp.Function(n, real=True)(s) for n in ("theta_r", "theta_phi",
                                                                  "theta_z"))
    subs = {th_r: cons["theta_r"], th_phi: alpha, th_z: cons["theta_z"]}
    dw_sub = [sp.expand(wi.subs(subs).doit()) for wi in dw]
    K = A1 * dw_sub[0] ** 2 + A2 * dw_sub[1] ** 2 + A3 * dw_sub[2] ** 2
    # hoop part of G: 2 * (hoop work density) = -q R |theta_perp|^2, G carries it divided by -q
    a, b, c = sp.symbols("a b c")
    hoop = hoop_work_density(F, Ft)
    theta_cart = [theta_fn.subs(subs).doit()[i] for i in range(3)]
    hoop_y = hoop.subs(dict(zip((a, b, c), theta_cart, strict=True)))
    g_hoop = sp.simplify(-2 * hoop_y / q)
    _check(_z(g_hoop - R * (cons["theta_r"] ** 2 + cons["theta_z"] ** 2)),
           "5: hoop part of G = R (theta_r^2 + theta_z^2)")
    pots = load_potential_second_order(F)
    out = {"K": K, "F_t": Ft, "w10": w0[0], "w20": w0[1], "w30": w0[2], **cons}
    for name in LOADS:
        v2 = pots[name].subs(pots["y_r"], cons["y_r"]).doit()
        out[f"G_{name}"] = sp.expand(g_hoop - 2 * v2 / q)
    # the simple forms quoted in spectral_rod.ring.second_variation's docstring (R = 1 there)
    _check(_z(out["G_hydrostatic"].subs(R, 1) - (cons["theta_r"] ** 2 + cons["theta_z"] ** 2
                                                - y_phi * cons["theta_z"]).subs(R, 1)),
           "6: G_hydrostatic is the form quoted in ring_stability")
    _check(_z(out["G_axis"].subs(R, 1) - (cons["theta_r"] ** 2 + cons["theta_z"] ** 2
                                         - y_phi ** 2).subs(R, 1)),
           "6: G_axis is the form quoted in ring_stability")
    _check(_z(out["G_centre"].subs(R, 1) - (cons["theta_r"] ** 2 + cons["theta_z"] ** 2
                                           - y_phi ** 2 - y_z ** 2).subs(R, 1)),
           "6: G_centre is the form quoted in ring_stability")
    _check(_z(out["G_dead"].subs(R, 1) - (cons["theta_r"] ** 2 + cons["theta_z"] ** 2
                                         ).subs(R, 1)),
           "6: G_dead is the form quoted in ring_stability")
    return out


def euler_lagrange() -> list[sp.Eq]:
    """The three coupled ODEs for y_phi, y_z, alpha (variable coefficients through Omega)."""
    from sympy.calculus.euler import euler_equations

    d = derive()
    return euler_equations((d["K"] - q * d["G_hydrostatic"]) / 2, [y_phi, y_z, alpha], s)


def main() -> None:
    d = derive()
    print("Checked: Eq. frenini torsions, Munder hoop force, frenet/constit first-order "
          "torsions, inextensibility, hoop work, load potentials.")
    print(f"w10 = {d['w10']},  w20 = {d['w20']},  w30 = {d['w30']},  F_t = {d['F_t']}")
    print(f"y_r = {d['y_r']},  theta_r = {d['theta_r']},  theta_z = {d['theta_z']}")
    print("\nx.K x density (A1 dw1^2 + A2 dw2^2 + A3 dw3^2):")
    print(sp.simplify(d["K"].subs(R, 1)))
    for name in LOADS:
        print(f"\nx.G x density, load '{name}':")
        print(sp.factor(d[f"G_{name}"].subs(R, 1)))
    print("\nEuler-Lagrange equations (hydrostatic, R = 1):")
    for eq in euler_lagrange():
        print(" ", sp.collect(sp.expand(eq.lhs.subs(R, 1)), [q, A1, A2, A3]), "= 0")


if __name__ == "__main__":
    main()
