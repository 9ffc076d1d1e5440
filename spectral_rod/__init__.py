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
The modules follow the paper's problems: :mod:`.rod` (the straight rod, Eq. ``inst1``; its
collocation solver in :mod:`.rod.collocation`), :mod:`.ring` (the twisted ring, Eq. ``crit2``),
:mod:`.figure1` (the paper's Figure 1), :mod:`.numerics` (the shared sign scan and quadrature),
:mod:`.derivations` (sympy).

==================================  ==========================================================
paper                               implemented / checked by
==================================  ==========================================================
Eq. ``frenini``, ``frenet``          ring frames: :mod:`.derivations.ring_linearisation`;
                                    rod: :mod:`.derivations.straight_rod` (curvatures)
Eq. ``constit``                     :mod:`.ring.second_variation` (energy), :mod:`.derivations`
Eqs. ``Munder``                     :mod:`.derivations.straight_rod` (linearised: ``inst1``,
                                    decoupling of F_t and alpha); ring: :mod:`.ring.munder`
Eq. ``inst1`` (rectilinear rod)     :func:`critical_load` (:mod:`.rod.critical`) via
                                    :func:`choose_method` (:mod:`.rod.router`): collocation
                                    :mod:`.rod.collocation` (one driver,
                                    :mod:`.rod.collocation.driver`; the C kernel and its numpy
                                    reference; tuning in :mod:`.rod.collocation.tuning`), the
                                    characteristic equation :mod:`.rod.characteristic` (mpmath
                                    reference and double precision),
                                    :func:`critical_load_increment` (p* - 1,
                                    :mod:`.rod.increment`); :mod:`.rod.finite_difference`;
                                    :mod:`.rod.baseline`
the energy (no ``inst1``)            Rayleigh-Ritz :mod:`.rod.ritz` (``method="ritz"``): upper
                                    bounds per mode family
hinged ends, geometric relations    :func:`buckling_mode` (:mod:`.rod.mode`; the closed-form
                                    mode at a characteristic root :mod:`.rod.characteristic_mode`)
wavenumbers beta_1, beta_2           :func:`critical_wavenumbers`, :func:`beta_difference`
                                    (:mod:`.rod.wavenumbers`); :func:`imaginary_beta1_window`
maxima near n pi (Figure 1)         :func:`family_crossing`, :func:`collocation_crossing`
                                    (:mod:`.rod.crossings`), :func:`crossing_closed_form`
limit at large twist                :func:`large_twist_limit`, :func:`large_twist_expansion`
                                    (:mod:`.rod.closed_form`: every closed form and asymptotic
                                    expansion of the rod)
"intrinsically three-dimensional"   :func:`non_planarity` (:mod:`.rod.measures`)
Figure 1                            :func:`load_figure1` (:mod:`.figure1.data`, the digitised
                                    points shipped in ``spectral_rod/data``);
                                    :func:`analyse_figure1` (:mod:`.figure1.forensics`: how
                                    every printed point was made)
ring, q_cr = 3 E1 I1/R^3 (I1 = I2)  :mod:`.ring.closed_forms` (untwisted ring, both planes,
                                    every reading of the load: :mod:`.ring.loads`)
Eq. ``crit2``, threshold twist      :func:`ring_formula_load`, :func:`threshold_twist`
                                    (:mod:`.ring.formula`)
ring stability (the truth)          :func:`ring_critical_load` (:mod:`.ring.critical`),
                                    :func:`ring_buckling` (:mod:`.ring.second_variation`, the
                                    second variation) and ``method="munder"``
                                    (:mod:`.ring.munder`: Eqs. ``Munder``, ``constit``,
                                    ``frenet`` linearised numerically)
"twist destabilises the ring"       :func:`twist_raises_load` (q_cr(N) vs q_cr(0), margin
                                    ``RING_RAISE_TOL``), :func:`destabilisation_threshold`
                                    (:mod:`.ring.critical`)
==================================  ==========================================================

Public names are imported lazily (``import spectral_rod`` stays light; scipy and mpmath load
when a function that needs them is first used); type checkers see them through the
``TYPE_CHECKING`` imports below. ``python -m spectral_rod`` (:func:`format_engine_report`) prints
the engine that solves Eq. ``inst1`` on this install, its BLAS and the dependency versions.
Every public function validates its arguments;
the raw kernels they are built on (e.g. :func:`spectral_rod.rod.wavenumbers.characteristic_roots`,
:func:`spectral_rod.rod.characteristic.determinant` on mpmath numbers) live in their modules.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

#: public name -> module that defines it ("module:attribute" where the names differ)
_EXPORTS = {
    "BucklingMode": "rod.results", "CriticalLoad": "rod.results",
    "ConvergenceError": "errors", "ConvergenceWarning": "errors",
    "RingConvergenceError": "errors", "RootNotFoundError": "errors",
    "ReferenceDataError": "errors",
    "SpectralRodError": "errors",
    "FAMILIES": "rod.families", "p_star_bounds": "rod.families",
    "ROD_METHODS": "rod.router", "choose_method": "rod.router",
    "TWIST_ROUTE": "rod.router", "NEAR_DEGENERATE": "rod.router",
    "critical_load": "rod.critical", "buckling_mode": "rod.mode",
    "collocation_mode_coefficients": "rod.collocation",
    "tail_for_tolerance": "rod.collocation.resolution",
    "critical_load_increment": "rod.increment",
    "CharacteristicRoot": "rod.characteristic",
    "characteristic_critical_load": "rod.characteristic",
    "family_critical_load": "rod.characteristic",
    "characteristic_determinant": "rod.characteristic",
    "CharacteristicMode": "rod.characteristic_mode",
    "characteristic_mode": "rod.characteristic_mode",
    "critical_wavenumbers": "rod.wavenumbers",
    "beta_difference": "rod.wavenumbers",
    "FamilyCrossing": "rod.crossings", "CollocationCrossing": "rod.crossings",
    "family_crossing": "rod.crossings", "collocation_crossing": "rod.crossings",
    "CrossingWavenumbers": "rod.crossings",
    "crossing_wavenumbers": "rod.crossings",
    "BetaWindow": "rod.closed_form", "CrossingClosedForm": "rod.closed_form",
    "LargeTwistCoefficients": "rod.closed_form", "crossing_closed_form": "rod.closed_form",
    "crossing_twist_asymptotic": "rod.closed_form", "imaginary_beta1_window": "rod.closed_form",
    "large_twist_coefficients": "rod.closed_form", "large_twist_expansion": "rod.closed_form",
    "large_twist_limit": "rod.closed_form", "large_twist_wavenumbers": "rod.closed_form",
    "fd_critical_load": "rod.finite_difference",
    "derivation_status": "derivations", "inst1_variant_table": "derivations",
    "RitzLoad": "rod.ritz", "ritz_critical_load": "rod.ritz",
    "baseline_critical_load": "rod.baseline", "baseline_sweep": "rod.baseline",
    "FIGURE1_NU": "figure1.data", "load_figure1": "figure1.data",
    "ThresholdTwist": "ring.formula", "crit2": "ring.formula", "ring_formula_load": "ring.formula",
    "threshold_twist": "ring.formula",
    "RingBuckling": "ring.second_variation", "RING_LOADS": "ring.second_variation",
    "RING_METHODS": "ring.critical", "RING_KIND_TOL": "ring.second_variation:KIND_TOL",
    "destabilisation_threshold": "ring.critical", "munder_buckling": "ring.munder",
    "twist_raises_load": "ring.critical", "RING_RAISE_TOL": "ring.critical:RAISE_TOL",
    "RING_E_ISOTROPIC": "ring.munder:E_ISOTROPIC",
    "RING_ISOTROPIC_POISSON": "ring.munder:ISOTROPIC_POISSON",
    "ring_formulation_agreement": "ring.munder",
    "ring_formulation_row": "ring.munder:formulation_row",
    "munder_base_residual": "ring.munder:base_residual",
    "RING_AGREEMENT_CASES": "ring.munder:AGREEMENT_CASES",
    "homogenised_limit": "ring.closed_forms", "in_plane_untwisted": "ring.closed_forms",
    "out_of_plane_supremum": "ring.closed_forms", "out_of_plane_untwisted": "ring.closed_forms",
    "rectangle_torsion_ratio": "ring.cross_section",
    "figure1_picture": "figure1.data",
    "Forensics": "figure1.forensics", "analyse_figure1": "figure1.forensics",
    "picture_lines": "figure1.forensics",
    **{name: "figure1.forensics" for name in (
        "CLUSTER_KINDS", "CLUSTER_WINDOW", "CLUSTER_DOUBLE_ROOT", "CLUSTER_NO_SIGN_CHANGE",
        "CLUSTER_EDITED", "CLUSTER_UNEXPLAINED", "POINT_CAUSES", "CAUSE_IMAGINARY_BETA1",
        "CAUSE_DOUBLE_ROOT", "CAUSE_NO_SIGN_CHANGE", "CAUSE_EDITED")},
    **{name: "figure1.data" for name in (
        "FIGURE1_DOT", "FIGURE1_PRINT_QUANTUM", "FIGURE1_Y_PER_P", "FIGURE1_X_PER_TWIST")},
    **{name: "rod.measures" for name in (
        "non_planarity", "local_maxima", "family_switches", "increasing_up_to", "settling_point",
        "observed_order")},
    "ring_buckling": "ring.second_variation", "ring_critical_load": "ring.critical",
    "ring_roundoff_floor": "ring.second_variation:roundoff_floor",
    "untwisted_critical_load": "ring.closed_forms",
    "rigid_motion_load_work": "ring.loads",
    "rigid_motion_stiffness": "ring.loads",
    "RING_RIGID_MOTIONS": "ring.loads:RIGID_MOTIONS",
    "ring_constraint_rank": "ring.loads:constraint_rank_on_rigid_motions",
    "in_plane_mode_load": "ring.closed_forms",
    "out_of_plane_mode_load": "ring.closed_forms",
    "ring_reference_torsions": "ring.munder:reference_torsions",
    "ring_one_harmonic_load": "ring.second_variation:one_harmonic_load",
    "ring_coupling_strengths": "ring.second_variation:coupling_strengths",
    "engine_report": "_engine_report", "format_engine_report": "_engine_report",
    "PerformanceWarning": "errors",
}

__all__ = sorted(_EXPORTS)


if TYPE_CHECKING:  # what the lazy loader returns, for type checkers (the same names as
    # _EXPORTS, tests/test_structure.py): `x as x` marks a re-export, and a name that differs
    # from its module's is an assignment (an alias import is not re-exported)
    import spectral_rod.ring.critical as _ring_critical
    import spectral_rod.ring.loads as _ring_loads
    import spectral_rod.ring.munder as _ring_munder
    import spectral_rod.ring.second_variation as _ring_second_variation
    from spectral_rod._engine_report import engine_report as engine_report
    from spectral_rod._engine_report import format_engine_report as format_engine_report
    from spectral_rod.derivations import derivation_status as derivation_status
    from spectral_rod.derivations import inst1_variant_table as inst1_variant_table
    from spectral_rod.errors import ConvergenceError as ConvergenceError
    from spectral_rod.errors import ConvergenceWarning as ConvergenceWarning
    from spectral_rod.errors import PerformanceWarning as PerformanceWarning
    from spectral_rod.errors import ReferenceDataError as ReferenceDataError
    from spectral_rod.errors import RingConvergenceError as RingConvergenceError
    from spectral_rod.errors import RootNotFoundError as RootNotFoundError
    from spectral_rod.errors import SpectralRodError as SpectralRodError
    from spectral_rod.figure1.data import FIGURE1_DOT as FIGURE1_DOT
    from spectral_rod.figure1.data import FIGURE1_NU as FIGURE1_NU
    from spectral_rod.figure1.data import FIGURE1_PRINT_QUANTUM as FIGURE1_PRINT_QUANTUM
    from spectral_rod.figure1.data import FIGURE1_X_PER_TWIST as FIGURE1_X_PER_TWIST
    from spectral_rod.figure1.data import FIGURE1_Y_PER_P as FIGURE1_Y_PER_P
    from spectral_rod.figure1.data import figure1_picture as figure1_picture
    from spectral_rod.figure1.data import load_figure1 as load_figure1
    from spectral_rod.figure1.forensics import CAUSE_DOUBLE_ROOT as CAUSE_DOUBLE_ROOT
    from spectral_rod.figure1.forensics import CAUSE_EDITED as CAUSE_EDITED
    from spectral_rod.figure1.forensics import CAUSE_IMAGINARY_BETA1 as CAUSE_IMAGINARY_BETA1
    from spectral_rod.figure1.forensics import CAUSE_NO_SIGN_CHANGE as CAUSE_NO_SIGN_CHANGE
    from spectral_rod.figure1.forensics import CLUSTER_DOUBLE_ROOT as CLUSTER_DOUBLE_ROOT
    from spectral_rod.figure1.forensics import CLUSTER_EDITED as CLUSTER_EDITED
    from spectral_rod.figure1.forensics import CLUSTER_KINDS as CLUSTER_KINDS
    from spectral_rod.figure1.forensics import CLUSTER_NO_SIGN_CHANGE as CLUSTER_NO_SIGN_CHANGE
    from spectral_rod.figure1.forensics import CLUSTER_UNEXPLAINED as CLUSTER_UNEXPLAINED
    from spectral_rod.figure1.forensics import CLUSTER_WINDOW as CLUSTER_WINDOW
    from spectral_rod.figure1.forensics import POINT_CAUSES as POINT_CAUSES
    from spectral_rod.figure1.forensics import Forensics as Forensics
    from spectral_rod.figure1.forensics import analyse_figure1 as analyse_figure1
    from spectral_rod.figure1.forensics import picture_lines as picture_lines
    from spectral_rod.ring.closed_forms import homogenised_limit as homogenised_limit
    from spectral_rod.ring.closed_forms import in_plane_mode_load as in_plane_mode_load
    from spectral_rod.ring.closed_forms import in_plane_untwisted as in_plane_untwisted
    from spectral_rod.ring.closed_forms import out_of_plane_mode_load as out_of_plane_mode_load
    from spectral_rod.ring.closed_forms import out_of_plane_supremum as out_of_plane_supremum
    from spectral_rod.ring.closed_forms import out_of_plane_untwisted as out_of_plane_untwisted
    from spectral_rod.ring.closed_forms import untwisted_critical_load as untwisted_critical_load
    from spectral_rod.ring.critical import RING_METHODS as RING_METHODS
    from spectral_rod.ring.critical import destabilisation_threshold as destabilisation_threshold
    from spectral_rod.ring.critical import ring_critical_load as ring_critical_load
    from spectral_rod.ring.critical import twist_raises_load as twist_raises_load
    from spectral_rod.ring.cross_section import rectangle_torsion_ratio as rectangle_torsion_ratio
    from spectral_rod.ring.formula import ThresholdTwist as ThresholdTwist
    from spectral_rod.ring.formula import crit2 as crit2
    from spectral_rod.ring.formula import ring_formula_load as ring_formula_load
    from spectral_rod.ring.formula import threshold_twist as threshold_twist
    from spectral_rod.ring.loads import rigid_motion_load_work as rigid_motion_load_work
    from spectral_rod.ring.loads import rigid_motion_stiffness as rigid_motion_stiffness
    from spectral_rod.ring.munder import munder_buckling as munder_buckling
    from spectral_rod.ring.munder import ring_formulation_agreement as ring_formulation_agreement
    from spectral_rod.ring.second_variation import RING_LOADS as RING_LOADS
    from spectral_rod.ring.second_variation import RingBuckling as RingBuckling
    from spectral_rod.ring.second_variation import ring_buckling as ring_buckling
    from spectral_rod.rod.baseline import baseline_critical_load as baseline_critical_load
    from spectral_rod.rod.baseline import baseline_sweep as baseline_sweep
    from spectral_rod.rod.characteristic import CharacteristicRoot as CharacteristicRoot
    from spectral_rod.rod.characteristic import (
        characteristic_critical_load as characteristic_critical_load,
    )
    from spectral_rod.rod.characteristic import (
        characteristic_determinant as characteristic_determinant,
    )
    from spectral_rod.rod.characteristic import family_critical_load as family_critical_load
    from spectral_rod.rod.characteristic_mode import CharacteristicMode as CharacteristicMode
    from spectral_rod.rod.characteristic_mode import characteristic_mode as characteristic_mode
    from spectral_rod.rod.closed_form import BetaWindow as BetaWindow
    from spectral_rod.rod.closed_form import CrossingClosedForm as CrossingClosedForm
    from spectral_rod.rod.closed_form import LargeTwistCoefficients as LargeTwistCoefficients
    from spectral_rod.rod.closed_form import crossing_closed_form as crossing_closed_form
    from spectral_rod.rod.closed_form import crossing_twist_asymptotic as crossing_twist_asymptotic
    from spectral_rod.rod.closed_form import imaginary_beta1_window as imaginary_beta1_window
    from spectral_rod.rod.closed_form import large_twist_coefficients as large_twist_coefficients
    from spectral_rod.rod.closed_form import large_twist_expansion as large_twist_expansion
    from spectral_rod.rod.closed_form import large_twist_limit as large_twist_limit
    from spectral_rod.rod.closed_form import large_twist_wavenumbers as large_twist_wavenumbers
    from spectral_rod.rod.collocation import (
        collocation_mode_coefficients as collocation_mode_coefficients,
    )
    from spectral_rod.rod.collocation.resolution import tail_for_tolerance as tail_for_tolerance
    from spectral_rod.rod.critical import critical_load as critical_load
    from spectral_rod.rod.crossings import CollocationCrossing as CollocationCrossing
    from spectral_rod.rod.crossings import CrossingWavenumbers as CrossingWavenumbers
    from spectral_rod.rod.crossings import FamilyCrossing as FamilyCrossing
    from spectral_rod.rod.crossings import collocation_crossing as collocation_crossing
    from spectral_rod.rod.crossings import crossing_wavenumbers as crossing_wavenumbers
    from spectral_rod.rod.crossings import family_crossing as family_crossing
    from spectral_rod.rod.families import FAMILIES as FAMILIES
    from spectral_rod.rod.families import p_star_bounds as p_star_bounds
    from spectral_rod.rod.finite_difference import fd_critical_load as fd_critical_load
    from spectral_rod.rod.increment import critical_load_increment as critical_load_increment
    from spectral_rod.rod.measures import family_switches as family_switches
    from spectral_rod.rod.measures import increasing_up_to as increasing_up_to
    from spectral_rod.rod.measures import local_maxima as local_maxima
    from spectral_rod.rod.measures import non_planarity as non_planarity
    from spectral_rod.rod.measures import observed_order as observed_order
    from spectral_rod.rod.measures import settling_point as settling_point
    from spectral_rod.rod.mode import buckling_mode as buckling_mode
    from spectral_rod.rod.results import BucklingMode as BucklingMode
    from spectral_rod.rod.results import CriticalLoad as CriticalLoad
    from spectral_rod.rod.ritz import RitzLoad as RitzLoad
    from spectral_rod.rod.ritz import ritz_critical_load as ritz_critical_load
    from spectral_rod.rod.router import NEAR_DEGENERATE as NEAR_DEGENERATE
    from spectral_rod.rod.router import ROD_METHODS as ROD_METHODS
    from spectral_rod.rod.router import TWIST_ROUTE as TWIST_ROUTE
    from spectral_rod.rod.router import choose_method as choose_method
    from spectral_rod.rod.wavenumbers import beta_difference as beta_difference
    from spectral_rod.rod.wavenumbers import critical_wavenumbers as critical_wavenumbers
    RING_AGREEMENT_CASES = _ring_munder.AGREEMENT_CASES
    RING_E_ISOTROPIC = _ring_munder.E_ISOTROPIC
    RING_ISOTROPIC_POISSON = _ring_munder.ISOTROPIC_POISSON
    RING_KIND_TOL = _ring_second_variation.KIND_TOL
    RING_RAISE_TOL = _ring_critical.RAISE_TOL
    RING_RIGID_MOTIONS = _ring_loads.RIGID_MOTIONS
    munder_base_residual = _ring_munder.base_residual
    ring_constraint_rank = _ring_loads.constraint_rank_on_rigid_motions
    ring_coupling_strengths = _ring_second_variation.coupling_strengths
    ring_formulation_row = _ring_munder.formulation_row
    ring_one_harmonic_load = _ring_second_variation.one_harmonic_load
    ring_reference_torsions = _ring_munder.reference_torsions
    ring_roundoff_floor = _ring_second_variation.roundoff_floor
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
