r"""The wavenumbers of Eq. ``inst1``: the roots of its characteristic polynomial.

With t = s/L - 1/2, Omega = omega30 L, lambda = P L^2/A1 = pi^2 p*, mu = lambda/nu, Eq.
``inst1`` in body-frame displacements (omega1 = -lambda xi, omega2 = -mu eta;
:mod:`spectral_rod.rod.characteristic`) has solutions ~ exp(i beta t) exactly when X = beta^2
solves

    (lambda - Omega^2 - X)(mu - Omega^2 - X) = 4 Omega^2 X.

Its roots X_- <= X_+ are always real (discriminant (lambda - mu)^2 + 8 Omega^2 (lambda + mu) >= 0);
X_- < 0 (beta_1 imaginary) exactly when mu < Omega^2 < lambda. The paper's wavenumbers are
beta_1 L = sqrt(X_-), beta_2 L = sqrt(X_+).

:func:`characteristic_roots` is the one place the roots are written; it works on numpy arrays
(default) and on mpmath numbers (``sqrt=mpmath.sqrt``).

>>> x_minus, x_plus = characteristic_roots(9.8696, 9.8696, 0.0)
>>> float(x_minus), float(x_plus)
(9.8696, 9.8696)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from spectral_rod._validation import broadcast_points, check_nu, check_twist, real_array

__all__ = ["P_STAR_MAX", "beta_difference", "characteristic_roots", "critical_wavenumbers",
           "root_offsets"]

#: The largest load accepted (as :func:`spectral_rod.characteristic_determinant`'s): far above
#: any critical load (p* <= nu <= 1e4) and far below where (lambda - mu)^2 overflows (p ~ 1e153).
P_STAR_MAX = 1.0e8


def characteristic_roots(lam: Any, mu: Any, twist_angle: Any,
                         sqrt: Callable[[Any], Any] = np.sqrt) -> tuple[Any, Any]:
    """(X_-, X_+), the roots of (lambda - Omega^2 - X)(mu - Omega^2 - X) = 4 Omega^2 X.

    X_- is computed as the product of the roots over X_+, which avoids the cancellation in
    (s - sqrt(disc))/2. Pass ``sqrt=mpmath.sqrt`` for mpmath numbers.
    """
    om2 = twist_angle * twist_angle
    x_plus = (lam + mu + 2 * om2 + sqrt((lam - mu) ** 2 + 8 * om2 * (lam + mu))) / 2
    return (lam - om2) * (mu - om2) / x_plus, x_plus


def root_offsets(lam: Any, mu: Any, twist_angle: Any,
                 sqrt: Callable[[Any], Any] = np.sqrt) -> tuple[Any, Any]:
    """(X_- - Omega^2, X_+ - Omega^2), the roots of :func:`characteristic_roots` less Omega^2:
    (lambda + mu + R)/2 with R^2 = (lambda - mu)^2 + 8 Omega^2 (lambda + mu), and the product
    of the two, lambda mu - 2 Omega^2 (lambda + mu), over it. Both without cancellation where
    Omega^2 >> lambda (the large-twist phase form of :mod:`spectral_rod.rod.characteristic`), where
    X - Omega^2 is O(Omega) and X itself O(Omega^2). Python floats (``sqrt=math.sqrt``), numpy
    arrays or mpmath numbers.

    >>> [round(v, 12) for v in root_offsets(2.0, 1.0, 0.0, sqrt=lambda x: x**0.5)]
    [1.0, 2.0]
    """
    om2 = twist_angle * twist_angle
    u_plus = (lam + mu + sqrt((lam - mu) ** 2 + 8 * om2 * (lam + mu))) / 2
    return (lam * mu - 2 * om2 * (lam + mu)) / u_plus, u_plus


def _loads(p_star: ArrayLike, twist_angle: ArrayLike, nu: ArrayLike
           ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    p = real_array(p_star, "p_star")
    if np.any(p <= 0) or np.any(p > P_STAR_MAX):
        raise ValueError(f"p_star must be in (0, {P_STAR_MAX:g}], got min {np.min(p):g}, "
                         f"max {np.max(p):g}")
    om, nv = np.abs(check_twist(twist_angle)), check_nu(nu)
    broadcast_points(p_star=p, twist_angle=om, nu=nv)
    lam = np.pi**2 * p
    return lam, lam / nv, om


def critical_wavenumbers(p_star: ArrayLike, twist_angle: ArrayLike, nu: ArrayLike):
    """The paper's wavenumbers (beta_1 L, beta_2 L), beta_1 <= beta_2, at the load p*.

    Scalars give (float or complex, float); arrays broadcast. beta_1 is imaginary where
    X_- < 0 and is then returned as i sqrt(-X_-) (``numpy.emath.sqrt`` convention: a complex
    result wherever one value is imaginary).

    Returns
    -------
    tuple (beta1, beta2)
        beta_1 L (float, or complex where imaginary) and beta_2 L (float); arrays for array input.

    Examples
    --------
    >>> b1, b2 = critical_wavenumbers(1.0, 0.0, 2.0)   # untwisted: beta = pi and pi/sqrt(2)
    >>> round(float(b2 / b1) ** 2, 12)
    2.0
    """
    lam, mu, om = _loads(p_star, twist_angle, nu)
    x_minus, x_plus = characteristic_roots(lam, mu, om)
    b1, b2 = np.emath.sqrt(x_minus), np.sqrt(x_plus)
    if np.ndim(b1) == 0:
        return (complex(b1) if np.iscomplexobj(b1) else float(b1)), float(b2)
    return b1, b2


def beta_difference(p_star: ArrayLike, twist_angle: ArrayLike, nu: ArrayLike):
    """Re(beta_2 - beta_1) L at the load p* (= beta_2 L where beta_1 is imaginary).

    The paper's "difference between the critical wavenumbers" (section "Stability of a
    rectilinear rod"); scalars give a float, arrays an ndarray.

    Returns
    -------
    float or ndarray
        Re(beta_2 - beta_1) L (radians per rod length).

    Examples
    --------
    >>> import math   # untwisted, nu = 2: beta_1 L = pi/sqrt(2), beta_2 L = pi
    >>> math.isclose(float(beta_difference(1.0, 0.0, 2.0)), math.pi * (1 - 1 / math.sqrt(2)))
    True
    """
    lam, mu, om = _loads(p_star, twist_angle, nu)
    x_minus, x_plus = characteristic_roots(lam, mu, om)
    d = np.sqrt(x_plus) - np.sqrt(np.clip(x_minus, 0.0, None))
    return float(d) if np.ndim(d) == 0 else d
