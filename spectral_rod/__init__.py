r"""spectral_rod: a verification package for Drozdov & Rabin, *Buckling of rods with spontaneous
twist and curvature*.

Straight rod (paper's Eq. ``inst1``, hinged ends), dimensionless: s/L in [0, 1], total twist
angle Omega(L) = omega30 L (``twist_angle``), ``nu`` = I2/I1 >= 1, p* = P_cr / (pi^2 A1 / L^2).
Ring: loads q R^3 / (E1 I1), e = E2/E1, N turns of the section (Omega = N s/R).

>>> import spectral_rod as sr
>>> round(sr.critical_load(5.0, 1.5), 9)
1.164464854
>>> sr.choose_method(5.0, 1.5)
'collocation'

From the paper to the code
--------------------------
==================================  ==========================================================
paper                               implemented / checked by
==================================  ==========================================================
Eq. ``frenini``, ``frenet``          ring frames: :mod:`.derivations.ring_linearisation`;
                                    rod: :mod:`.derivations.straight_rod` (curvatures)
Eq. ``constit``                     :mod:`.ring_stability` (energy), :mod:`.derivations`
Eqs. ``Munder``                     :mod:`.derivations.straight_rod` (linearised: ``inst1``,
                                    decoupling of F_t and alpha); ring: :mod:`.ring_munder`
Eq. ``inst1`` (rectilinear rod)     :func:`critical_load` via :func:`choose_method`:
                                    collocation :mod:`.straight_rod`, the characteristic
                                    equation :mod:`.characteristic` (mpmath reference and
                                    double precision), :func:`critical_load_increment`
                                    (p* - 1); :mod:`.finite_difference`; :mod:`.baseline`
the energy (no ``inst1``)            Rayleigh-Ritz :mod:`.ritz` (``method="ritz"``): upper
                                    bounds per mode family
hinged ends, geometric relations    :func:`buckling_mode` (:mod:`.mode`)
wavenumbers beta_1, beta_2           :func:`critical_wavenumbers`, :func:`beta_difference`
                                    (:mod:`.wavenumbers`); :func:`imaginary_beta1_window`
maxima near n pi (Figure 1)         :func:`family_crossing`, :func:`collocation_crossing`
                                    (:mod:`.crossings`), :func:`crossing_closed_form`
limit at large twist                :func:`large_twist_limit`, :func:`large_twist_expansion`
                                    (:mod:`.asymptotics`)
"intrinsically three-dimensional"   :func:`non_planarity` (:mod:`.measures`)
Figure 1                            :func:`load_figure1` (:mod:`.figure_data`, the digitised
                                    points shipped in ``spectral_rod/data``);
                                    :func:`analyse_figure1` (:mod:`.figure1_forensics`: how
                                    every printed point was made)
ring, q_cr = 3 E1 I1/R^3 (I1 = I2)  :mod:`.ring_closed_forms` (untwisted ring, both planes)
Eq. ``crit2``, threshold twist      :func:`ring_formula_load`, :func:`threshold_twist`
                                    (:mod:`.ring_formula`)
ring stability (the truth)          :func:`ring_critical_load`, :func:`ring_buckling`
                                    (:mod:`.ring_stability`, the second variation) and
                                    ``method="munder"`` (:mod:`.ring_munder`: Eqs. ``Munder``,
                                    ``constit``, ``frenet`` linearised numerically)
"twist destabilises the ring"       :func:`twist_raises_load` (q_cr(N) vs q_cr(0), margin
                                    ``RING_RAISE_TOL``), :func:`destabilisation_threshold`
==================================  ==========================================================

Public names are imported lazily (``import spectral_rod`` stays light; scipy and mpmath load
when a function that needs them is first used). Every public function validates its arguments;
the raw kernels they are built on (e.g. :func:`spectral_rod.wavenumbers.characteristic_roots`,
:func:`spectral_rod.characteristic.determinant` on mpmath numbers) live in their modules.
"""

from __future__ import annotations

import importlib
from typing import Any

__version__ = "0.1.0"

#: public name -> module that defines it ("module:attribute" where the names differ)
_EXPORTS = {
    "BucklingMode": "results", "CriticalLoad": "results",
    "ConvergenceError": "errors", "ConvergenceWarning": "errors",
    "RingConvergenceError": "errors", "RootNotFoundError": "errors",
    "ReferenceDataError": "errors",
    "SpectralRodError": "errors",
    "FAMILIES": "families", "p_star_bounds": "families",
    "ROD_METHODS": "router", "choose_method": "router",
    "TWIST_ROUTE": "router", "NEAR_DEGENERATE": "router",
    "critical_load": "critical", "buckling_mode": "mode",
    "collocation_mode_coefficients": "straight_rod",
    "tail_for_tolerance": "straight_rod.resolution",
    "critical_load_increment": "increment",
    "CharacteristicRoot": "characteristic", "characteristic_critical_load": "characteristic",
    "family_critical_load": "characteristic",
    "characteristic_determinant": "characteristic",
    "CharacteristicMode": "closed_form", "characteristic_mode": "closed_form",
    "critical_wavenumbers": "wavenumbers",
    "beta_difference": "wavenumbers",
    "FamilyCrossing": "crossings", "CollocationCrossing": "crossings",
    "family_crossing": "crossings", "collocation_crossing": "crossings",
    "CrossingWavenumbers": "crossings",
    "crossing_wavenumbers": "crossings",
    "BetaWindow": "asymptotics", "CrossingClosedForm": "asymptotics",
    "LargeTwistCoefficients": "asymptotics", "crossing_closed_form": "asymptotics",
    "crossing_twist_asymptotic": "asymptotics", "imaginary_beta1_window": "asymptotics",
    "large_twist_coefficients": "asymptotics", "large_twist_expansion": "asymptotics",
    "large_twist_limit": "asymptotics", "large_twist_wavenumbers": "asymptotics",
    "fd_critical_load": "finite_difference",
    "derivation_status": "derivations", "inst1_variant_table": "derivations",
    "RitzLoad": "ritz", "ritz_critical_load": "ritz",
    "baseline_critical_load": "baseline", "baseline_sweep": "baseline",
    "FIGURE1_NU": "figure_data", "load_figure1": "figure_data",
    "ThresholdTwist": "ring_formula", "crit2": "ring_formula", "ring_formula_load": "ring_formula",
    "threshold_twist": "ring_formula",
    "RingBuckling": "ring_stability", "RING_LOADS": "ring_stability",
    "RING_METHODS": "ring_stability", "RING_KIND_TOL": "ring_stability:KIND_TOL",
    "destabilisation_threshold": "ring_stability", "munder_buckling": "ring_munder",
    "twist_raises_load": "ring_stability", "RING_RAISE_TOL": "ring_stability:RAISE_TOL",
    "RING_E_ISOTROPIC": "ring_munder:E_ISOTROPIC",
    "RING_ISOTROPIC_POISSON": "ring_munder:ISOTROPIC_POISSON",
    "ring_formulation_agreement": "ring_munder",
    "ring_formulation_row": "ring_munder:formulation_row",
    "munder_base_residual": "ring_munder:base_residual",
    "RING_AGREEMENT_CASES": "ring_munder:AGREEMENT_CASES",
    "homogenised_limit": "ring_closed_forms", "in_plane_untwisted": "ring_closed_forms",
    "out_of_plane_supremum": "ring_closed_forms", "out_of_plane_untwisted": "ring_closed_forms",
    "rectangle_torsion_ratio": "cross_section",
    "figure1_picture": "figure_data",
    "Forensics": "figure1_forensics", "analyse_figure1": "figure1_forensics",
    "picture_lines": "figure1_forensics",
    **{name: "figure1_forensics" for name in (
        "CLUSTER_KINDS", "CLUSTER_WINDOW", "CLUSTER_DOUBLE_ROOT", "CLUSTER_NO_SIGN_CHANGE",
        "CLUSTER_EDITED", "CLUSTER_UNEXPLAINED", "POINT_CAUSES", "CAUSE_IMAGINARY_BETA1",
        "CAUSE_DOUBLE_ROOT", "CAUSE_NO_SIGN_CHANGE", "CAUSE_EDITED")},
    **{name: "figure_data" for name in (
        "FIGURE1_DOT", "FIGURE1_PRINT_QUANTUM", "FIGURE1_Y_PER_P", "FIGURE1_X_PER_TWIST")},
    "non_planarity": "measures", "local_maxima": "measures", "family_switches": "measures",
    "increasing_up_to": "measures", "settling_point": "measures", "observed_order": "measures",
    "ring_buckling": "ring_stability", "ring_critical_load": "ring_stability",
    "ring_roundoff_floor": "ring_stability:roundoff_floor",
    "untwisted_critical_load": "ring_closed_forms",
    "rigid_motion_load_work": "ring_loads",
    "rigid_motion_stiffness": "ring_loads",
    "RING_RIGID_MOTIONS": "ring_loads:RIGID_MOTIONS",
    "ring_constraint_rank": "ring_loads:constraint_rank_on_rigid_motions",
    "in_plane_mode_load": "ring_closed_forms",
    "out_of_plane_mode_load": "ring_closed_forms",
    "ring_reference_torsions": "ring_munder:reference_torsions",
    "ring_one_harmonic_load": "ring_stability:one_harmonic_load",
    "ring_coupling_strengths": "ring_stability:coupling_strengths",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    """Import the defining module of a public name on first use (PEP 562)."""
    target = _EXPORTS.get(name)
    if target is None:
        raise AttributeError(f"module 'spectral_rod' has no attribute {name!r}")
    module, _, attr = target.partition(":")
    value = getattr(importlib.import_module(f"spectral_rod.{module}"), attr or name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))
