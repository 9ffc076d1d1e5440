"""spectral_rod: a verification package for Drozdov & Rabin, *Buckling of rods with
spontaneous twist and curvature*.

Straight rod (paper's Eq. ``inst1``, hinged ends), dimensionless: s/L in [0, 1], total twist
angle Omega(L) = omega30 L, nu = I2/I1 >= 1, p* = P_cr / (pi^2 A1 / L^2).

* :func:`critical_load` -- Chebyshev collocation with automatic resolution; very large twist is
  routed to the characteristic equation, near-degenerate points to the increment.
* :func:`critical_load_increment` -- p* - 1 to full relative accuracy as nu -> 1 or twist -> 0.
* :func:`buckling_mode` -- the critical mode (omega1, omega2, centreline) and wavenumbers.
* :func:`characteristic_critical_load` -- the paper's characteristic equation in extended
  precision (the independent reference); :func:`family_critical_load` per mode family and
  :func:`family_crossing`, where the families cross (the maxima of p*).
* :func:`large_twist_limit` (2 nu/(1 + nu)), :func:`large_twist_expansion`,
  :func:`imaginary_beta1_window`, :func:`crossing_closed_form` -- closed forms.

Ring (paper's section "Stability of a ring"), q_cr R^3 / (E1 I1), e = E2/E1:

* :func:`ring_formula_load`, :func:`threshold_twist` -- the paper's Eq. ``crit2`` and the twist at
  which it predicts instability without load.
* :func:`ring_critical_load`, :func:`ring_buckling` -- the linearised ring problem solved
  numerically (Fourier spectral), the converged answer against which ``crit2`` is judged.
"""

from spectral_rod.asymptotics import (
    crossing_closed_form,
    imaginary_beta1_window,
    large_twist_expansion,
    large_twist_limit,
)
from spectral_rod.characteristic import (
    characteristic_critical_load,
    family_critical_load,
    family_crossing,
)
from spectral_rod.critical import critical_load
from spectral_rod.increment import critical_load_increment
from spectral_rod.ring import ThresholdTwist, ring_formula_load, threshold_twist
from spectral_rod.ring_stability import (
    RingBuckling,
    RingConvergenceError,
    ring_buckling,
    ring_critical_load,
)
from spectral_rod.straight_rod import (
    BucklingMode,
    ConvergenceWarning,
    CriticalLoad,
    buckling_mode,
    critical_wavenumbers,
)

__version__ = "0.1.0"

__all__ = [
    "BucklingMode",
    "ConvergenceWarning",
    "CriticalLoad",
    "RingBuckling",
    "RingConvergenceError",
    "ThresholdTwist",
    "buckling_mode",
    "characteristic_critical_load",
    "critical_load",
    "critical_load_increment",
    "critical_wavenumbers",
    "crossing_closed_form",
    "family_critical_load",
    "family_crossing",
    "imaginary_beta1_window",
    "large_twist_expansion",
    "large_twist_limit",
    "ring_buckling",
    "ring_critical_load",
    "ring_formula_load",
    "threshold_twist",
]
