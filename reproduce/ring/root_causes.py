"""The independent errors of the paper's ring section that its failing statements trace back to
(``ClaimSpec.root_cause``: one line each, shared by every row it explains).

Each is a finding of the ring scene's rows, stated once here so that the ledger's headline can
group the fails by cause: the rows that carry a cause name the evidence for it.
"""

from __future__ import annotations

#: Eq. crit2 and everything read off it (the threshold twist, "instability without load", the
#: monotone decrease, the contrast with GT97). Evidence: ring-crit2-galerkin (N = 0),
#: ring-crit2-torsion-scaling, ring-crit2.
CRIT2_NOT_GALERKIN = (
    "Eq. crit2 is not the result of the one-harmonic Galerkin the paper states: at N = 0, where "
    "that Galerkin is exact, it gives e(ν + 2) — scaling with E₂ and growing with ν — instead "
    "of the classical loads of any wavenumber; for N ≥ 1 it falls below the converged load, "
    "which a one-harmonic Rayleigh-Ritz estimate cannot; the threshold twist, the instability "
    "without load, the monotone decrease and the contrast with GT97 are read off it.")

#: The circular ring's load 3E1I1/R^3 and "in-plane and out-of-plane onsets coincide".
CIRCULAR_OUT_OF_PLANE = (
    "For I₁ = I₂ the paper takes the in-plane load 3E₁I₁/R³ as the critical one: the circular "
    "ring buckles out of its plane first, at 9E₁I₁/[(4 + E₁I₁/A₃)R³] (2.000 for E₂ = E₁, 1.698 "
    "for an isotropic rod), so the two onsets do not coincide.")

#: "An analytical solution can be obtained only for I1 = I2".
UNTWISTED_ANISOTROPIC_SOLVABLE = (
    "The untwisted anisotropic ring (N = 0, I₁ ≠ I₂) is solvable in closed form — its harmonics "
    "decouple — so analytical solutions are not confined to I₁ = I₂ (and would have checked "
    "crit2 at N = 0).")

ROOT_CAUSES = (CRIT2_NOT_GALERKIN, CIRCULAR_OUT_OF_PLANE, UNTWISTED_ANISOTROPIC_SOLVABLE)
