r"""The paper's own method: the characteristic equation of Eq. ``inst1`` in extended precision.

This is the independent reference for every test of the collocation solver; it never calls it.

Derivation (body-frame displacements xi, eta, proportional to omega1, omega2)
------------------------------------------------------------------------------
With t = s/L - 1/2 in [-1/2, 1/2], Omega = omega30 L, lambda = P L^2/A1 = pi^2 p*, mu = lambda/nu,
Eq. ``inst1`` is equivalent to

    xi''  - 2 Omega eta' + (lambda - Omega^2) xi  = 0,
    eta'' + 2 Omega xi'  + (mu     - Omega^2) eta = 0,      xi = eta = 0 at t = +-1/2

(omega1 = -lambda xi, omega2 = -mu eta; hinged ends are omega = 0, see ``straight_rod``).
Trying xi, eta ~ exp(i beta t) gives the characteristic equation for X = beta^2,

    (lambda - Omega^2 - X)(mu - Omega^2 - X) = 4 Omega^2 X,

whose roots X_+ > X_- are always real (discriminant (lambda-mu)^2 + 8 Omega^2 (lambda+mu) > 0);
X_- < 0 (beta_1 imaginary) exactly when mu < Omega^2 < lambda. The wavenumbers of the paper are
beta_k = sqrt(X_-), sqrt(X_+). Reflection t -> -t splits the solutions:

* symmetric family (xi even, eta odd): xi = a cos(beta t), eta = b sin(beta t)/beta, with
  (lambda - Omega^2 - X) a = 2 Omega b, i.e. (a, b) = (2 Omega, lambda - Omega^2 - X);
* antisymmetric family (xi odd, eta even): xi = a sin(beta t)/beta, eta = b cos(beta t), with
  (mu - Omega^2 - X) b = -2 Omega a, i.e. (a, b) = (mu - Omega^2 - X, -2 Omega).

The functions cos(sqrt(X) t) and sin(sqrt(X) t)/sqrt(X) are entire in X (they become cosh and
sinh/kappa when X < 0, and 1 and t at X = 0), and the chosen amplitude vectors vanish only at
Omega = 0, so after dividing the 2x2 boundary determinants at t = 1/2 by the common factor
2 Omega (the removable singularity at zero twist) they are continuous in lambda and vanish
exactly at the eigenvalues of each family:

    D_sym(lambda)  = C_+ S_- (lambda - Omega^2 - X_-) - C_- S_+ (lambda - Omega^2 - X_+),
    D_anti(lambda) = (mu - Omega^2 - X_+) S_+ C_- - (mu - Omega^2 - X_-) S_- C_+,

with C = cos(sqrt(X)/2), S = sin(sqrt(X)/2)/sqrt(X). At Omega = 0 they reduce to
(lambda - mu) cos(sqrt(lambda)/2) S(mu) and (mu - lambda) S(lambda) cos(sqrt(mu)/2): the Euler
modes lambda = pi^2, 4 nu pi^2 and 4 pi^2, nu pi^2. (This 2x2 pair is the paper's 4x4 boundary
determinant block-diagonalised by the reflection symmetry.)

The lowest root
---------------
The Rayleigh quotient gives 1 <= p* <= (1 + nu)/2. We scan both determinants for sign changes
on a grid in p from 1 - 1e-9 upward (step ``scan_step``) and take the first bracket; the root in
it is refined by bisection-safe Anderson iteration in mpmath at ``dps`` digits. A root exactly at
p = 1 (nu = 1 or Omega = 0) is returned in closed form.

Further tools (used by the claims scene)
----------------------------------------
* :func:`family_critical_load` -- the lowest root of one family (bounds 1 <= p <= nu);
* :func:`family_crossing` -- where the two families' lowest roots coincide (2-D Newton on
  D_sym = D_anti = 0, verified lowest by the scans): the maxima of p*(Omega), which are corners;
  at a crossing beta_1 L, beta_2 L are both odd or both even multiples of pi (proof and closed
  form in :mod:`spectral_rod.asymptotics`);
* :func:`family_slope` -- dp/dOmega along one family's root curve;
* :func:`boundary_determinant_4x4` -- the paper's 4x4 boundary determinant on s in [0, 1],
  literally; it equals 16 Omega^2 D_sym D_anti;
* :func:`characteristic_mode` -- the buckling mode and centreline in closed form.
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp

from spectral_rod._validation import check_nu, check_twist

__all__ = [
    "CharacteristicMode",
    "CharacteristicRoot",
    "FamilyCrossing",
    "boundary_determinant_4x4",
    "characteristic_critical_load",
    "characteristic_mode",
    "determinant",
    "family_critical_load",
    "family_crossing",
    "family_slope",
    "wavenumbers",
]


def _entire_cs(x: mp.mpf) -> tuple[mp.mpf, mp.mpf]:
    """C = cos(sqrt(X)/2) and S = sin(sqrt(X)/2)/sqrt(X), real for real X of either sign."""
    if x > 0:
        b = mp.sqrt(x)
        return mp.cos(b / 2), mp.sin(b / 2) / b
    if x < 0:
        k = mp.sqrt(-x)
        return mp.cosh(k / 2), mp.sinh(k / 2) / k
    return mp.mpf(1), mp.mpf(1) / 2


def _roots(lam: mp.mpf, mu: mp.mpf, om: mp.mpf) -> tuple[mp.mpf, mp.mpf]:
    """X_+ >= X_- of X^2 - (lambda + mu + 2 Omega^2) X + (lambda - Omega^2)(mu - Omega^2) = 0."""
    s = lam + mu + 2 * om**2
    disc = mp.sqrt((lam - mu) ** 2 + 8 * om**2 * (lam + mu))
    x_plus = (s + disc) / 2
    prod = (lam - om**2) * (mu - om**2)
    # product/x_plus avoids cancellation in (s - disc)/2
    return x_plus, prod / x_plus


def determinant(family: str, lam: mp.mpf, om: mp.mpf, nu: mp.mpf) -> mp.mpf:
    """D_sym or D_anti of the module docstring (divided by 2 Omega; valid at Omega = 0)."""
    mu = lam / nu
    xp, xm = _roots(lam, mu, om)
    cp, sp = _entire_cs(xp)
    cm, sm = _entire_cs(xm)
    if family == "symmetric":
        return cp * sm * (lam - om**2 - xm) - cm * sp * (lam - om**2 - xp)
    if family == "antisymmetric":
        return (mu - om**2 - xp) * sp * cm - (mu - om**2 - xm) * sm * cp
    raise ValueError(f"family must be 'symmetric' or 'antisymmetric', got {family!r}")


def _scaled_determinant(family: str, om: mp.mpf, nu: mp.mpf):
    """p -> determinant at lambda = pi^2 p (a one-argument function for mp.findroot)."""

    def g(p: mp.mpf) -> mp.mpf:
        return determinant(family, mp.pi**2 * p, om, nu)

    return g


@dataclass(frozen=True)
class CharacteristicRoot:
    """p* from the characteristic equation, the family of the mode, and beta_k^2 L^2 there."""

    p_star: mp.mpf
    family: str
    x_minus: mp.mpf  # beta_1^2 L^2 (negative: beta_1 imaginary)
    x_plus: mp.mpf   # beta_2^2 L^2
    bracket: tuple[mp.mpf, mp.mpf]


def wavenumbers(p_star: float, twist_angle: float, nu: float, dps: int = 30
                ) -> tuple[mp.mpf, mp.mpf]:
    """(beta_1^2 L^2, beta_2^2 L^2) = (X_-, X_+) at load p*: the paper's critical wavenumbers."""
    with mp.workdps(dps):
        lam = mp.pi**2 * mp.mpf(p_star)
        xp, xm = _roots(lam, lam / mp.mpf(nu), mp.mpf(abs(twist_angle)))
        return xm, xp


def characteristic_critical_load(twist_angle: float, nu: float, *, dps: int = 40,
                                 scan_step: float = 1.0 / 128,
                                 p_max: float | None = None) -> CharacteristicRoot:
    """Lowest root p* of the characteristic determinants (extended precision, ``dps`` digits).

    twist_angle: Omega(L) in radians (p* is even in it); nu = I2/I1 >= 1. The scan runs from
    p = 1 - 1e-9 to p_max (default (1 + nu)/2, the Rayleigh upper bound, plus a margin) and the
    lowest sign change of either family is refined. Raises RuntimeError if none is found.
    """
    om_f = float(check_twist(twist_angle, max_abs=1e6))
    nu_f = float(check_nu(nu, max_value=1e8))
    with mp.workdps(dps):
        om, nuv = mp.mpf(abs(om_f)), mp.mpf(nu_f)
        pi2 = mp.pi**2
        if nu_f == 1.0 or om_f == 0.0:
            # closed form: the Euler load is exact (isotropic section, or no twist)
            lam = pi2
            xp, xm = _roots(lam, lam / nuv, om)
            fam = "symmetric"
            return CharacteristicRoot(mp.mpf(1), fam, xm, xp, (mp.mpf(1), mp.mpf(1)))
        top = (1 + nu_f) / 2 + 1e-6 if p_max is None else p_max
        funcs = {f: _scaled_determinant(f, om, nuv) for f in ("symmetric", "antisymmetric")}
        p_lo = mp.mpf(1) - mp.mpf("1e-9")
        prev = {f: g(p_lo) for f, g in funcs.items()}
        p = p_lo
        while p < top:
            p_next = min(p + mp.mpf(scan_step), mp.mpf(top))
            hits = []
            for f, g in funcs.items():
                val = g(p_next)
                if val == 0 or mp.sign(val) != mp.sign(prev[f]):
                    hits.append((f, val))
                prev[f] = val
            if hits:
                roots = []
                for f, _ in hits:
                    r = mp.findroot(funcs[f], (p, p_next), solver="anderson")
                    if not (p <= r <= p_next):  # pragma: no cover - anderson keeps the bracket
                        r = mp.findroot(funcs[f], (p, p_next), solver="bisect")
                    roots.append((r, f))
                r, fam = min(roots)
                lam = pi2 * r
                xp, xm = _roots(lam, lam / nuv, om)
                return CharacteristicRoot(r, fam, xm, xp, (p, p_next))
            p = p_next
    raise RuntimeError(f"no root of the characteristic equation for p* in [1, {top}] "
                       f"(twist_angle={om_f}, nu={nu_f})")


# ---------------------------------------------------------------------------------------------
# Per-family roots, family crossings, the paper's 4x4 determinant and the closed-form mode
# ---------------------------------------------------------------------------------------------

def _entire_cs_at(x: mp.mpf, t: mp.mpf) -> tuple[mp.mpf, mp.mpf]:
    """cos(sqrt(X) t) and sin(sqrt(X) t)/sqrt(X): entire in X, real for real X of either sign."""
    if x > 0:
        b = mp.sqrt(x)
        return mp.cos(b * t), mp.sin(b * t) / b
    if x < 0:
        k = mp.sqrt(-x)
        return mp.cosh(k * t), mp.sinh(k * t) / k
    return mp.mpf(1), mp.mpf(t)


def family_critical_load(family: str, twist_angle: float, nu: float, *, dps: int = 40,
                         scan_step: float = 1.0 / 128,
                         p_max: float | None = None) -> CharacteristicRoot:
    """Lowest root p of one family's determinant (``determinant(family, ...)``), by sign scan.

    Bounds (Rayleigh quotient restricted to the family's parity subspace, which the operator of
    Eq. ``inst1`` leaves invariant): 1 <= p_family <= nu, because the planar trial mode
    x = sin(pi s) e(theta) lies in the symmetric family for theta = Omega/2 and in the
    antisymmetric one for theta = Omega/2 + pi/2, and its quotient is at most A2/A1 = nu. The
    scan runs from p = 1 - 1e-9 to p_max (default nu plus a margin) in steps ``scan_step`` and the
    first sign change is refined (Anderson, bisection as fallback). p* is the smaller of the two
    families' roots (:func:`characteristic_critical_load`). At Omega = 0 or nu = 1 the roots are
    the Euler loads, returned in closed form (symmetric 1, antisymmetric min(4, nu) for nu > 1
    at zero twist; both 1 for nu = 1).
    """
    if family not in ("symmetric", "antisymmetric"):
        raise ValueError(f"family must be 'symmetric' or 'antisymmetric', got {family!r}")
    om_f = float(check_twist(twist_angle, max_abs=1e6))
    nu_f = float(check_nu(nu, max_value=1e8))
    with mp.workdps(dps):
        om, nuv = mp.mpf(abs(om_f)), mp.mpf(nu_f)
        if nu_f == 1.0 or om_f == 0.0:
            if family == "symmetric" or nu_f == 1.0:
                r = mp.mpf(1)
            else:
                r = min(mp.mpf(4), nuv)
            lam = mp.pi**2 * r
            xp, xm = _roots(lam, lam / nuv, om)
            return CharacteristicRoot(r, family, xm, xp, (r, r))
        g = _scaled_determinant(family, om, nuv)
        top = mp.mpf(nu_f + 1e-6 if p_max is None else p_max)
        step = mp.mpf(scan_step)
        p = mp.mpf(1) - mp.mpf("1e-9")
        prev = g(p)
        while p < top:
            p_next = min(p + step, top)
            val = g(p_next)
            if val == 0 or mp.sign(val) != mp.sign(prev):
                r = mp.findroot(g, (p, p_next), solver="anderson")
                if not (p <= r <= p_next):  # pragma: no cover - anderson keeps the bracket
                    r = mp.findroot(g, (p, p_next), solver="bisect")
                lam = mp.pi**2 * r
                xp, xm = _roots(lam, lam / nuv, om)
                return CharacteristicRoot(r, family, xm, xp, (p, p_next))
            prev, p = val, p_next
    raise RuntimeError(f"no root of the {family} determinant for p in [1, {float(top)}] "
                       f"(twist_angle={om_f}, nu={nu_f})")


def family_slope(family: str, p: mp.mpf, twist_angle: mp.mpf, nu: mp.mpf) -> mp.mpf:
    """dp/dOmega(L) along the family's root curve D(pi^2 p, Omega) = 0 (implicit function rule)."""
    f = family
    d_om = mp.diff(lambda w: determinant(f, mp.pi**2 * p, w, nu), twist_angle)
    d_p = mp.diff(lambda q: determinant(f, mp.pi**2 * q, twist_angle, nu), p)
    return -d_om / d_p


@dataclass(frozen=True)
class FamilyCrossing:
    """A twist at which the lowest symmetric and antisymmetric roots coincide.

    twist: Omega(L) at the crossing; p_star: the common (and lowest) root there; slopes:
    dp/dOmega of each family's root curve; left/right: the family that is critical just below /
    above the crossing; kind: 'corner maximum' when p* rises into the crossing and falls out of it
    (p* = min of two smooth branches has a concave corner there, not a smooth maximum), else
    'corner' (a kink on a monotone stretch).
    """

    twist: mp.mpf
    p_star: mp.mpf
    slopes: dict[str, mp.mpf]
    left: str
    right: str
    kind: str


def family_crossing(twist_guess: float, nu: float, *, p_guess: float | None = None,
                    dps: int = 30) -> FamilyCrossing:
    """Solve D_sym(pi^2 p, Omega) = D_anti(pi^2 p, Omega) = 0 for (Omega, p) by 2-D Newton.

    The start is (twist_guess, p*(twist_guess)) from :func:`characteristic_critical_load` unless
    ``p_guess`` is given. The result is verified independently: the sign scan of each family
    (:func:`family_critical_load`) must return the crossing load as that family's *lowest* root,
    so the crossing lies on the critical curve p*(Omega). Raises RuntimeError otherwise.
    """
    with mp.workdps(dps):
        nuv = mp.mpf(nu)
        if p_guess is None:
            p_guess = characteristic_critical_load(twist_guess, nu, dps=dps).p_star

        def system(p: mp.mpf, om: mp.mpf) -> list[mp.mpf]:
            return [determinant("symmetric", mp.pi**2 * p, om, nuv),
                    determinant("antisymmetric", mp.pi**2 * p, om, nuv)]

        sol = mp.findroot(system, (mp.mpf(p_guess), mp.mpf(twist_guess)))
        p_c, om_c = sol[0], sol[1]
        tol = mp.mpf(10) ** (-(dps - 8))
        for fam in ("symmetric", "antisymmetric"):
            low = family_critical_load(fam, float(om_c), nu, dps=dps).p_star
            # the scan works at the float-rounded twist: allow for that rounding
            slope_scale = 1 + abs(family_slope(fam, p_c, om_c, nuv))
            if abs(low - p_c) > tol + slope_scale * abs(om_c) * mp.mpf(2) ** -52:
                raise RuntimeError(f"crossing near Omega={twist_guess} (nu={nu}) is not on the "
                                   f"lowest {fam} branch: {low} vs {p_c}")
        slopes = {f: family_slope(f, p_c, om_c, nuv) for f in ("symmetric", "antisymmetric")}
        left = max(slopes, key=lambda f: slopes[f])   # steeper rise => lower just to the left
        right = min(slopes, key=lambda f: slopes[f])
        kind = "corner maximum" if slopes[left] > 0 > slopes[right] else "corner"
        return FamilyCrossing(om_c, p_c, slopes, left, right, kind)


def boundary_determinant_4x4(lam: mp.mpf, om: mp.mpf, nu: mp.mpf) -> mp.mpf:
    """The paper's 4x4 boundary determinant, literally: s in [0, 1], four fundamental solutions.

    Solutions of Eq. ``inst1`` (body-frame displacements, see the module docstring) for each root
    X_k = beta_k^2 of the characteristic equation, written with entire functions of X_k:

        u_k: xi = 2 Omega cos(beta_k s),  eta = (lambda - Omega^2 - X_k) sin(beta_k s)/beta_k,
        v_k: eta = 2 Omega cos(beta_k s),  xi = -(mu - Omega^2 - X_k) sin(beta_k s)/beta_k.

    Rows: xi(0), eta(0), xi(1), eta(1) (hinged ends). Its zeros are the loads of both families;
    exactly, det = 16 Omega^2 D_sym D_anti (tested), so it vanishes identically at Omega = 0
    (the removable singularity the 2x2 reduction divides out).
    """
    mu = lam / nu
    xp, xm = _roots(lam, mu, om)
    cols = []
    for x in (xp, xm):
        ell = lam - om**2 - x
        c1, s1 = _entire_cs_at(x, mp.mpf(1))
        cols.append([2 * om, mp.mpf(0), 2 * om * c1, ell * s1])
    for x in (xp, xm):
        m = mu - om**2 - x
        c1, s1 = _entire_cs_at(x, mp.mpf(1))
        cols.append([mp.mpf(0), 2 * om, -m * s1, 2 * om * c1])
    mat = mp.matrix(4, 4)
    for j, col in enumerate(cols):
        for i in range(4):
            mat[i, j] = col[i]
    return mp.det(mat)


@dataclass(frozen=True)
class CharacteristicMode:
    """The buckling mode in closed form (sums of cos/sin(beta_k t)) at a characteristic root.

    s: grid on [0, 1]; xi, eta: body-frame displacements along (u0, v0); x1, x2: the centreline
    displacement in the fixed frame, x = R(Omega s) (xi, eta); all scaled to max |x| = 1.
    """

    s: list[float]
    xi: list[float]
    eta: list[float]
    x1: list[float]
    x2: list[float]


def characteristic_mode(root: CharacteristicRoot, twist_angle: float, nu: float,
                        points: int = 201, dps: int = 30) -> CharacteristicMode:
    """The mode of ``root`` from the null vector of its family's 2x2 boundary system.

    Symmetric family: xi = sum_k c_k 2 Omega cos(beta_k t), eta = sum_k c_k (lambda - Omega^2 -
    X_k) sin(beta_k t)/beta_k; antisymmetric: xi = sum_k c_k (mu - Omega^2 - X_k) sin(beta_k
    t)/beta_k, eta = -sum_k c_k 2 Omega cos(beta_k t) (t = s - 1/2). Needs Omega != 0 (at zero
    twist the mode is Euler's planar sin(pi s)).
    """
    if float(twist_angle) == 0.0:
        raise ValueError("characteristic_mode needs a non-zero twist (Euler's mode otherwise)")
    with mp.workdps(dps):
        om, nuv = mp.mpf(twist_angle), mp.mpf(nu)
        lam = mp.pi**2 * root.p_star
        mu = lam / nuv
        xs = (root.x_plus, root.x_minus)
        half = [_entire_cs_at(x, mp.mpf(1) / 2) for x in xs]
        if root.family == "symmetric":
            amp = [(2 * om, lam - om**2 - x) for x in xs]   # (xi ~ cos, eta ~ sin/beta)
            rows = [[a[0] * h[0] for a, h in zip(amp, half, strict=True)],
                    [a[1] * h[1] for a, h in zip(amp, half, strict=True)]]
        else:
            amp = [(mu - om**2 - x, -2 * om) for x in xs]   # (xi ~ sin/beta, eta ~ cos)
            rows = [[a[0] * h[1] for a, h in zip(amp, half, strict=True)],
                    [a[1] * h[0] for a, h in zip(amp, half, strict=True)]]
        # null vector of the 2x2 system from whichever row is larger
        r = max(rows, key=lambda row: abs(row[0]) + abs(row[1]))
        c = (r[1], -r[0])
        s_grid, xi, eta, x1, x2 = [], [], [], [], []
        for j in range(points):
            s = mp.mpf(j) / (points - 1)
            t = s - mp.mpf(1) / 2
            cs = [_entire_cs_at(x, t) for x in xs]
            if root.family == "symmetric":
                a = sum(ck * ak[0] * ct[0] for ck, ak, ct in zip(c, amp, cs, strict=True))
                b = sum(ck * ak[1] * ct[1] for ck, ak, ct in zip(c, amp, cs, strict=True))
            else:
                a = sum(ck * ak[0] * ct[1] for ck, ak, ct in zip(c, amp, cs, strict=True))
                b = sum(ck * ak[1] * ct[0] for ck, ak, ct in zip(c, amp, cs, strict=True))
            s_grid.append(s)
            xi.append(a)
            eta.append(b)
            x1.append(a * mp.cos(om * s) - b * mp.sin(om * s))
            x2.append(a * mp.sin(om * s) + b * mp.cos(om * s))
        scale = max(mp.sqrt(u**2 + v**2) for u, v in zip(x1, x2, strict=True))
        return CharacteristicMode(s=[float(v) for v in s_grid],
                                  xi=[float(v / scale) for v in xi],
                                  eta=[float(v / scale) for v in eta],
                                  x1=[float(v / scale) for v in x1],
                                  x2=[float(v / scale) for v in x2])
