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
when a function that needs them is first used); type checkers see them through the
``TYPE_CHECKING`` imports below. ``python -m spectral_rod`` (:func:`format_engine_report`) prints
the engine that solves Eq. ``inst1`` on this install, its BLAS and the dependency versions.
Every public function validates its arguments;
the raw kernels they are built on (e.g. :func:`spectral_rod.wavenumbers.characteristic_roots`,
:func:`spectral_rod.characteristic.determinant` on mpmath numbers) live in their modules.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

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
    "engine_report": "_engine_report", "format_engine_report": "_engine_report",
    "PerformanceWarning": "errors",
}

__all__ = sorted(_EXPORTS)


if TYPE_CHECKING:  # what the lazy loader returns, for type checkers (the same names as
    # _EXPORTS, tests/test_structure.py): `x as x` marks a re-export, and a name that differs
    # from its module's is an assignment (an alias import is not re-exported)
    import spectral_rod.ring_loads as _ring_loads
    import spectral_rod.ring_munder as _ring_munder
    import spectral_rod.ring_stability as _ring_stability
    from spectral_rod._engine_report import engine_report as engine_report
    from spectral_rod._engine_report import format_engine_report as format_engine_report
    from spectral_rod.asymptotics import BetaWindow as BetaWindow
    from spectral_rod.asymptotics import CrossingClosedForm as CrossingClosedForm
    from spectral_rod.asymptotics import LargeTwistCoefficients as LargeTwistCoefficients
    from spectral_rod.asymptotics import crossing_closed_form as crossing_closed_form
    from spectral_rod.asymptotics import crossing_twist_asymptotic as crossing_twist_asymptotic
    from spectral_rod.asymptotics import imaginary_beta1_window as imaginary_beta1_window
    from spectral_rod.asymptotics import large_twist_coefficients as large_twist_coefficients
    from spectral_rod.asymptotics import large_twist_expansion as large_twist_expansion
    from spectral_rod.asymptotics import large_twist_limit as large_twist_limit
    from spectral_rod.asymptotics import large_twist_wavenumbers as large_twist_wavenumbers
    from spectral_rod.baseline import baseline_critical_load as baseline_critical_load
    from spectral_rod.baseline import baseline_sweep as baseline_sweep
    from spectral_rod.characteristic import CharacteristicRoot as CharacteristicRoot
    from spectral_rod.characteristic import (
        characteristic_critical_load as characteristic_critical_load,
    )
    from spectral_rod.characteristic import characteristic_determinant as characteristic_determinant
    from spectral_rod.characteristic import family_critical_load as family_critical_load
    from spectral_rod.closed_form import CharacteristicMode as CharacteristicMode
    from spectral_rod.closed_form import characteristic_mode as characteristic_mode
    from spectral_rod.critical import critical_load as critical_load
    from spectral_rod.cross_section import rectangle_torsion_ratio as rectangle_torsion_ratio
    from spectral_rod.crossings import CollocationCrossing as CollocationCrossing
    from spectral_rod.crossings import CrossingWavenumbers as CrossingWavenumbers
    from spectral_rod.crossings import FamilyCrossing as FamilyCrossing
    from spectral_rod.crossings import collocation_crossing as collocation_crossing
    from spectral_rod.crossings import crossing_wavenumbers as crossing_wavenumbers
    from spectral_rod.crossings import family_crossing as family_crossing
    from spectral_rod.derivations import derivation_status as derivation_status
    from spectral_rod.derivations import inst1_variant_table as inst1_variant_table
    from spectral_rod.errors import ConvergenceError as ConvergenceError
    from spectral_rod.errors import ConvergenceWarning as ConvergenceWarning
    from spectral_rod.errors import PerformanceWarning as PerformanceWarning
    from spectral_rod.errors import ReferenceDataError as ReferenceDataError
    from spectral_rod.errors import RingConvergenceError as RingConvergenceError
    from spectral_rod.errors import RootNotFoundError as RootNotFoundError
    from spectral_rod.errors import SpectralRodError as SpectralRodError
    from spectral_rod.families import FAMILIES as FAMILIES
    from spectral_rod.families import p_star_bounds as p_star_bounds
    from spectral_rod.figure1_forensics import CAUSE_DOUBLE_ROOT as CAUSE_DOUBLE_ROOT
    from spectral_rod.figure1_forensics import CAUSE_EDITED as CAUSE_EDITED
    from spectral_rod.figure1_forensics import CAUSE_IMAGINARY_BETA1 as CAUSE_IMAGINARY_BETA1
    from spectral_rod.figure1_forensics import CAUSE_NO_SIGN_CHANGE as CAUSE_NO_SIGN_CHANGE
    from spectral_rod.figure1_forensics import CLUSTER_DOUBLE_ROOT as CLUSTER_DOUBLE_ROOT
    from spectral_rod.figure1_forensics import CLUSTER_EDITED as CLUSTER_EDITED
    from spectral_rod.figure1_forensics import CLUSTER_KINDS as CLUSTER_KINDS
    from spectral_rod.figure1_forensics import CLUSTER_NO_SIGN_CHANGE as CLUSTER_NO_SIGN_CHANGE
    from spectral_rod.figure1_forensics import CLUSTER_UNEXPLAINED as CLUSTER_UNEXPLAINED
    from spectral_rod.figure1_forensics import CLUSTER_WINDOW as CLUSTER_WINDOW
    from spectral_rod.figure1_forensics import POINT_CAUSES as POINT_CAUSES
    from spectral_rod.figure1_forensics import Forensics as Forensics
    from spectral_rod.figure1_forensics import analyse_figure1 as analyse_figure1
    from spectral_rod.figure1_forensics import picture_lines as picture_lines
    from spectral_rod.figure_data import FIGURE1_DOT as FIGURE1_DOT
    from spectral_rod.figure_data import FIGURE1_NU as FIGURE1_NU
    from spectral_rod.figure_data import FIGURE1_PRINT_QUANTUM as FIGURE1_PRINT_QUANTUM
    from spectral_rod.figure_data import FIGURE1_X_PER_TWIST as FIGURE1_X_PER_TWIST
    from spectral_rod.figure_data import FIGURE1_Y_PER_P as FIGURE1_Y_PER_P
    from spectral_rod.figure_data import figure1_picture as figure1_picture
    from spectral_rod.figure_data import load_figure1 as load_figure1
    from spectral_rod.finite_difference import fd_critical_load as fd_critical_load
    from spectral_rod.increment import critical_load_increment as critical_load_increment
    from spectral_rod.measures import family_switches as family_switches
    from spectral_rod.measures import increasing_up_to as increasing_up_to
    from spectral_rod.measures import local_maxima as local_maxima
    from spectral_rod.measures import non_planarity as non_planarity
    from spectral_rod.measures import observed_order as observed_order
    from spectral_rod.measures import settling_point as settling_point
    from spectral_rod.mode import buckling_mode as buckling_mode
    from spectral_rod.results import BucklingMode as BucklingMode
    from spectral_rod.results import CriticalLoad as CriticalLoad
    from spectral_rod.ring_closed_forms import homogenised_limit as homogenised_limit
    from spectral_rod.ring_closed_forms import in_plane_mode_load as in_plane_mode_load
    from spectral_rod.ring_closed_forms import in_plane_untwisted as in_plane_untwisted
    from spectral_rod.ring_closed_forms import out_of_plane_mode_load as out_of_plane_mode_load
    from spectral_rod.ring_closed_forms import out_of_plane_supremum as out_of_plane_supremum
    from spectral_rod.ring_closed_forms import out_of_plane_untwisted as out_of_plane_untwisted
    from spectral_rod.ring_closed_forms import untwisted_critical_load as untwisted_critical_load
    from spectral_rod.ring_formula import ThresholdTwist as ThresholdTwist
    from spectral_rod.ring_formula import crit2 as crit2
    from spectral_rod.ring_formula import ring_formula_load as ring_formula_load
    from spectral_rod.ring_formula import threshold_twist as threshold_twist
    from spectral_rod.ring_loads import rigid_motion_load_work as rigid_motion_load_work
    from spectral_rod.ring_loads import rigid_motion_stiffness as rigid_motion_stiffness
    from spectral_rod.ring_munder import munder_buckling as munder_buckling
    from spectral_rod.ring_munder import ring_formulation_agreement as ring_formulation_agreement
    from spectral_rod.ring_stability import RING_LOADS as RING_LOADS
    from spectral_rod.ring_stability import RING_METHODS as RING_METHODS
    from spectral_rod.ring_stability import RingBuckling as RingBuckling
    from spectral_rod.ring_stability import destabilisation_threshold as destabilisation_threshold
    from spectral_rod.ring_stability import ring_buckling as ring_buckling
    from spectral_rod.ring_stability import ring_critical_load as ring_critical_load
    from spectral_rod.ring_stability import twist_raises_load as twist_raises_load
    from spectral_rod.ritz import RitzLoad as RitzLoad
    from spectral_rod.ritz import ritz_critical_load as ritz_critical_load
    from spectral_rod.router import NEAR_DEGENERATE as NEAR_DEGENERATE
    from spectral_rod.router import ROD_METHODS as ROD_METHODS
    from spectral_rod.router import TWIST_ROUTE as TWIST_ROUTE
    from spectral_rod.router import choose_method as choose_method
    from spectral_rod.straight_rod import (
        collocation_mode_coefficients as collocation_mode_coefficients,
    )
    from spectral_rod.straight_rod.resolution import tail_for_tolerance as tail_for_tolerance
    from spectral_rod.wavenumbers import beta_difference as beta_difference
    from spectral_rod.wavenumbers import critical_wavenumbers as critical_wavenumbers
    RING_AGREEMENT_CASES = _ring_munder.AGREEMENT_CASES
    RING_E_ISOTROPIC = _ring_munder.E_ISOTROPIC
    RING_ISOTROPIC_POISSON = _ring_munder.ISOTROPIC_POISSON
    RING_KIND_TOL = _ring_stability.KIND_TOL
    RING_RAISE_TOL = _ring_stability.RAISE_TOL
    RING_RIGID_MOTIONS = _ring_loads.RIGID_MOTIONS
    munder_base_residual = _ring_munder.base_residual
    ring_constraint_rank = _ring_loads.constraint_rank_on_rigid_motions
    ring_coupling_strengths = _ring_stability.coupling_strengths
    ring_formulation_row = _ring_munder.formulation_row
    ring_one_harmonic_load = _ring_stability.one_harmonic_load
    ring_reference_torsions = _ring_munder.reference_torsions
    ring_roundoff_floor = _ring_stability.roundoff_floor
else:  # hidden from type checkers: a module __getattr__ would make every name Any
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
