"""Machine-checked derivation of the linearised stability problem of the twisted ring.

Run ``python -m spectral_rod.derivations.ring_linearisation`` to print the operator and the
checks; tests call :func:`derive` and compare the numerical operator of
``spectral_rod.ring_stability`` against its output at random parameter values.

Setting (Drozdov & Rabin, section "Stability of a ring"): centreline R0 = R e_r, t0 = e_phi,
u0 = -cos(Omega) e_r + sin(Omega) e_z, v0 = sin(Omega) e_r + cos(Omega) e_z, Omega = N s / R.

Steps, each checked by sympy (an ``AssertionError`` means the algebra is wrong):

1. Eq. ``frenini`` applied to the reference frame gives the spontaneous torsions
   w10 = cos(Omega)/R, w20 = -sin(Omega)/R, w30 = N/R (as in the paper).
2. Eq. ``Munder`` at the stress-free state (all moments zero, w = w0) under q = -q e_r gives the
   hoop force F_t = -q R.
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
   projected enclosed area), "axis" V = q int rho ds (rho = distance from the axis).

Result: second variation 1/2 int (k_density - q g_density) ds with the densities returned by
:func:`derive`, in terms of y_phi(s), y_z(s), alpha(s).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

s = sp.Symbol("s", real=True)
R, A1, A2, A3, q = sp.symbols("R A1 A2 A3 q", positive=True)
N = sp.Symbol("N", integer=True, nonnegative=True)
eps = sp.Symbol("epsilon")
y_phi, y_z, alpha = (sp.Function(n, real=True)(s) for n in ("y_phi", "y_z", "alpha"))


def _vec(*c: sp.Expr) -> sp.Matrix:
    return sp.Matrix(c)


def _skew(v: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def _d(v: sp.Matrix) -> sp.Matrix:
    return v.diff(s)


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


def _z(expr: sp.Expr) -> bool:
    """Exact zero test: trig functions rewritten as exponentials cancel under expansion."""
    e = sp.expand(sp.expand(expr).rewrite(sp.exp))
    return e == 0 or sp.simplify(e) == 0


def check_spontaneous_torsions(F: dict[str, sp.Matrix]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Step 1: Eq. ``frenini`` for the reference frame."""
    t0, u0, v0 = F["t0"], F["u0"], F["v0"]
    w10, w20, w30 = (_d(t0).dot(u0), _d(t0).dot(v0), _d(u0).dot(v0))
    Om = N * s / R
    assert _z(w10 - sp.cos(Om) / R) and _z(w20 + sp.sin(Om) / R) and _z(w30 - N / R)
    # the remaining components of Eq. frenini hold too (the frame is consistent)
    for vec in (_d(t0) - (w10 * u0 + w20 * v0), _d(u0) - (-w10 * t0 + w30 * v0),
                _d(v0) - (-w20 * t0 - w30 * u0)):
        assert all(_z(c) for c in vec)
    return sp.cos(Om) / R, -sp.sin(Om) / R, N / R


def check_hoop_force(F: dict[str, sp.Matrix]) -> sp.Expr:
    """Step 2: Eq. ``Munder`` with M = 0, w = w0, load q = -q e_r -> F_t = -q R."""
    w1, w2, _ = check_spontaneous_torsions(F)
    load = -q * F["e_r"]
    q_u, q_v, q_t = load.dot(F["u0"]), load.dot(F["v0"]), load.dot(F["t0"])
    Ft = sp.Symbol("F_t")
    eq1 = q_t  # dF_t/ds + q_t = 0 with F_t constant
    eq3 = -w1 * Ft - q_u
    eq4 = w2 * Ft + q_v
    assert _z(eq1)
    sol = sp.solve(sp.expand_trig(eq3), Ft)
    assert len(sol) == 1 and _z(sol[0] + q * R)
    assert _z(eq4.subs(Ft, -q * R))
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
    assert QtQ == sp.zeros(3, 3)
    # first-order part of d_i = Q d_i0 is theta x d_i0; linearise w1 = t'.u, w2 = t'.v, w3 = u'.v
    t0, u0, v0 = F["t0"], F["u0"], F["v0"]
    dt, du, dv = theta.cross(t0), theta.cross(u0), theta.cross(v0)

    def lin(a0: sp.Matrix, da: sp.Matrix, b0: sp.Matrix, db: sp.Matrix) -> sp.Expr:
        return _d(da).dot(b0) + _d(a0).dot(db)

    dw = [lin(t0, dt, u0, du), lin(t0, dt, v0, dv), lin(u0, du, v0, dv)]
    dth = _d(theta)
    expected = [dth.dot(F["v0"]), -dth.dot(F["u0"]), dth.dot(F["t0"])]
    for a, b in zip(dw, expected, strict=True):
        assert _z(a - b)
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
    assert _z(out["y_r"] + R * y_phi.diff(s))
    assert _z(out["theta_z"] - (R * y_phi.diff(s, 2) + y_phi / R))
    assert _z(out["theta_r"] - y_z.diff(s))
    return out


def hoop_work_density(F: dict[str, sp.Matrix], Ft: sp.Expr) -> sp.Expr:
    """Step 5: -F_t t0 . (theta x (theta x t0))/2, the second-order work of the hoop force."""
    th = sp.Matrix(sp.symbols("a b c"))
    t0 = F["t0"]
    dens = -Ft * t0.dot(th.cross(th.cross(t0))) / 2
    perp2 = th.dot(th) - th.dot(t0) ** 2
    assert _z(dens - (-q * R / 2) * perp2)
    return dens


def load_potential_second_order(F: dict[str, sp.Matrix]) -> dict[str, sp.Expr]:
    """Step 6: eps^2 coefficients of the two load potentials (densities per unit s), for a
    general displacement y = y_r e_r + y_phi e_phi + y_z e_z."""
    y_r = sp.Function("y_r", real=True)(s)
    y = y_r * F["e_r"] + y_phi * F["e_phi"] + y_z * F["e_z"]
    Rv = R * F["e_r"] + eps * y
    area = Rv.cross(_d(Rv)).dot(F["e_z"]) * q / 2
    rho = q * sp.sqrt(Rv[0] ** 2 + Rv[1] ** 2)
    hyd = sp.simplify(sp.diff(area, eps, 2).subs(eps, 0) / 2)
    axis = sp.simplify(sp.diff(rho, eps, 2).subs(eps, 0) / 2)
    return {"hydrostatic": hyd, "axis": axis, "y_r": y_r}


@lru_cache(maxsize=1)
def derive() -> dict[str, sp.Expr]:
    """The second variation 1/2 int (K - q G) ds of the twisted ring, all checks applied.

    Returns sympy densities in y_phi(s), y_z(s), alpha(s) (see the module symbols):
    ``K`` (A1 dw1^2 + A2 dw2^2 + A3 dw3^2), ``G_hydrostatic`` and ``G_axis``, plus
    ``F_t`` (hoop force), ``theta_r``, ``theta_z``, ``y_r`` (constraint solution) and
    ``w10``, ``w20``, ``w30``.
    """
    F = frames()
    w0 = check_spontaneous_torsions(F)
    Ft = check_hoop_force(F)
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
    assert _z(g_hoop - R * (cons["theta_r"] ** 2 + cons["theta_z"] ** 2))
    pots = load_potential_second_order(F)
    out = {"K": K, "F_t": Ft, "w10": w0[0], "w20": w0[1], "w30": w0[2], **cons}
    for name in ("hydrostatic", "axis"):
        v2 = pots[name].subs(pots["y_r"], cons["y_r"]).doit()
        out[f"G_{name}"] = sp.expand(g_hoop - 2 * v2 / q)
    # the simple forms quoted in spectral_rod.ring_stability's docstring (R = 1 there)
    assert _z(out["G_hydrostatic"].subs(R, 1) - (cons["theta_r"] ** 2 + cons["theta_z"] ** 2
                                                - y_phi * cons["theta_z"]).subs(R, 1))
    assert _z(out["G_axis"].subs(R, 1) - (cons["theta_r"] ** 2 + cons["theta_z"] ** 2
                                         - y_phi ** 2).subs(R, 1))
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
    for name in ("hydrostatic", "axis"):
        print(f"\nx.G x density, load '{name}':")
        print(sp.factor(d[f"G_{name}"].subs(R, 1)))
    print("\nEuler-Lagrange equations (hydrostatic, R = 1):")
    for eq in euler_lagrange():
        print(" ", sp.collect(sp.expand(eq.lhs.subs(R, 1)), [q, A1, A2, A3]), "= 0")


if __name__ == "__main__":
    main()
