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
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp

from spectral_rod._validation import check_nu, check_twist

__all__ = ["CharacteristicRoot", "characteristic_critical_load", "determinant", "wavenumbers"]


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
