"""Issue 15: every public function fuzzed over every argument (valid, boundary, invalid values).

The property, for each generated call: either a ValueError/TypeError whose message names one of
the arguments that were given an invalid value, or -- when every argument is valid -- a finite
result inside the physical bounds, within a time limit per call. A documented domain fault (a
:class:`spectral_rod.SpectralRodError`, e.g. no family crossing near a guess) is allowed where
the spec says so. Anything else is a mishandled case.

The default run draws a few examples per function; ``python -m pytest -m slow`` runs the larger
profile.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import spectral_rod as sr

#: Wall-time limit of one call in the large profile (a hang detector, not a benchmark:
#: generous for 2 busy cores).
CALL_LIMIT = 60.0
NAN, INF = math.nan, math.inf
#: Values no real scalar argument accepts (with the exception they must raise).
NOT_REAL = [("1.0", TypeError), (None, TypeError), (1 + 2j, TypeError), (True, TypeError),
            (object(), TypeError), (NAN, ValueError), (INF, ValueError), (-INF, ValueError)]
NOT_INT = [(2.5, TypeError), ("3", TypeError), (True, TypeError), (None, TypeError)]
NOT_STR = [(1, TypeError), (None, TypeError), ("no such thing", ValueError)]


@dataclass(frozen=True)
class Arg:
    """One argument: how valid values are drawn, and the invalid values to try."""

    valid: st.SearchStrategy
    invalid: list[tuple[Any, type]] = field(default_factory=list)


def real(lo: float, hi: float, *extra_invalid: float) -> Arg:
    """A real scalar in [lo, hi] (numpy scalars among the valid draws)."""
    base = st.floats(lo, hi, allow_nan=False, allow_infinity=False)
    valid = st.one_of(base, base.map(np.float64), st.sampled_from([lo, hi]))
    return Arg(valid, NOT_REAL + [(v, ValueError) for v in extra_invalid])


def integer(lo: int, hi: int, *extra_invalid: int, even: bool = False) -> Arg:
    base = st.integers(lo, hi)
    if even:
        base = base.map(lambda k: k - k % 2 if k - k % 2 >= lo else k + k % 2)
    valid = st.one_of(base, base.map(np.int64))
    return Arg(valid, NOT_INT + [(v, ValueError) for v in extra_invalid])


def choice(*values: Any, invalid: list[tuple[Any, type]] | None = None) -> Arg:
    return Arg(st.sampled_from(values), NOT_STR if invalid is None else invalid)


def boolean() -> Arg:
    return Arg(st.booleans(), [(1, TypeError), ("no", TypeError), (None, TypeError)])


def optional(arg: Arg, extra: list[tuple[Any, type]] | None = None) -> Arg:
    return Arg(st.one_of(st.none(), arg.valid),
               [(v, e) for v, e in arg.invalid if v is not None] + (extra or []))


def finite(x: Any) -> bool:
    return bool(np.all(np.isfinite(np.asarray(x, dtype=float))))


def p_in_bounds(p: Any, nu: Any, slack: float = 1e-13) -> bool:
    p, nu = np.asarray(p, float), np.asarray(nu, float)
    return bool(np.all((p >= 1 - slack) & (p <= (1 + nu) / 2 * (1 + slack))))


@dataclass(frozen=True)
class Spec:
    """A public function, its arguments, the check of a valid call's result, and which domain
    faults (SpectralRodError subclasses) a valid call may raise."""

    call: Callable[..., Any]
    args: dict[str, Arg]
    check: Callable[[Any, dict[str, Any]], bool] = lambda r, a: True
    faults: tuple[type, ...] = ()
    positional: tuple[str, ...] = ()
    #: arguments computed from the others where their values must match (same length)
    derived: dict[str, Callable[[dict[str, Any]], Any]] = field(default_factory=dict)


TWIST = real(-1e4, 1e4, 1.5e4, -2e4)
NU = real(1.0, 1e4, 0.5, 0.0, 2e4)
SMALL_TWIST = real(-60.0, 60.0, 2e4)
E_RATIO = real(1e-6, 1e6, 0.0, -1.0)
RING_N = integer(0, 8, -1, 1001)
LOAD = choice("hydrostatic", "axis")


def _ring_q(r: Any, a: dict[str, Any]) -> bool:
    return bool(np.isfinite(r) and r > 0)


def _load_ok(r: Any, a: dict[str, Any]) -> bool:
    p = getattr(r, "p_star", r)
    return finite(p) and p_in_bounds(p, a["nu"])


def _mode_ok(r: Any, a: dict[str, Any]) -> bool:
    return (p_in_bounds(r.p_star, a["nu"]) and finite(r.omega1) and finite(r.x1)
            and r.method in sr.ROD_METHODS)


#: twist and nu for the solvers: anywhere in the documented ranges, with the boundaries drawn
SOLVER_TWIST = Arg(st.one_of(st.floats(-1e4, 1e4), st.floats(-60, 60), st.sampled_from(
    [0.0, 49.999, 50.0, -1e4, 1e4])), [*NOT_REAL, (15000.0, ValueError)])
SOLVER_NU = Arg(st.one_of(st.floats(1.0, 1e4), st.sampled_from([1.0, 1.0 + 1e-12, 1.001, 1e4]),
                          st.floats(1.0, 1.01)),
                [*NOT_REAL, (0.5, ValueError), (20000.0, ValueError)])
TOL = real(1e-14, 1e-2, 0.0, 0.5)
METHOD_AUTO = choice("auto", invalid=NOT_STR)
ARRAYS = Arg(st.lists(st.floats(0.0, 60.0), min_size=1, max_size=5).map(np.array),
             [([1.0, NAN], ValueError), (["a"], TypeError)])
#: Grids of the measures: strictly increasing (an unsorted one is refused since 2026-12-04).
GRIDS = Arg(st.lists(st.floats(0.0, 60.0), min_size=1, max_size=5, unique=True)
            .map(lambda v: np.array(sorted(v))),
            [([1.0, NAN], ValueError), (["a"], TypeError), ([2.0, 1.0], ValueError)])

SPECS: dict[str, Spec] = {
    "critical_load": Spec(
        sr.critical_load,
        {"twist_angle": SOLVER_TWIST, "nu": SOLVER_NU, "tol": TOL, "method": METHOD_AUTO,
         "n": optional(integer(8, 512, 7, 1024, even=True)), "full_output": boolean()},
        _load_ok, positional=("twist_angle", "nu")),
    "critical_load_arrays": Spec(
        sr.critical_load, {"twist_angle": ARRAYS, "nu": real(1.0, 100.0, 0.5), "tol": TOL},
        _load_ok, positional=("twist_angle", "nu")),
    "critical_load_forced": Spec(
        sr.critical_load,
        {"twist_angle": real(-100.0, 100.0), "nu": real(1.0, 100.0, 0.5), "tol": TOL,
         "method": choice("collocation", "characteristic", "ritz")},
        _load_ok, positional=("twist_angle", "nu")),
    "buckling_mode": Spec(
        sr.buckling_mode,
        {"twist_angle": SOLVER_TWIST, "nu": SOLVER_NU, "tol": TOL,
         "points": integer(2, 2001, 1, 10**8)},
        _mode_ok, positional=("twist_angle", "nu")),
    "choose_method": Spec(sr.choose_method, {"twist_angle": SOLVER_TWIST, "nu": SOLVER_NU},
                          lambda r, a: r in sr.ROD_METHODS, positional=("twist_angle", "nu")),
    "critical_load_increment": Spec(
        sr.critical_load_increment,
        {"twist_angle": real(-100.0, 100.0, 2e3), "nu": Arg(
            st.floats(1.0, 1.001), [*NOT_REAL, (0.9, ValueError)])},
        lambda r, a: math.isfinite(r) and 0 <= r <= (a["nu"] - 1) / 2 * (1 + 1e-12),
        positional=("twist_angle", "nu")),
    "ritz_critical_load": Spec(
        sr.ritz_critical_load,
        {"twist_angle": real(-100.0, 100.0, 2e3), "nu": real(1.0, 100.0, 0.5), "tol": TOL,
         "family": optional(choice("symmetric", "antisymmetric"))},
        lambda r, a: finite(r) and r >= 1 - 1e-13, positional=("twist_angle", "nu")),
    "characteristic_critical_load": Spec(
        sr.characteristic_critical_load,
        {"twist_angle": real(-1e3, 1e3, 2e6), "nu": real(1.0, 1e3, 0.5),
         "dps": integer(15, 40, 0, 10**9), "scan_step": real(1e-3, 1.0 / 64, 0.0, 1e300)},
        lambda r, a: p_in_bounds(float(r.p_star), a["nu"]), positional=("twist_angle", "nu")),
    "family_critical_load": Spec(
        sr.family_critical_load,
        {"family": choice("symmetric", "antisymmetric"), "twist_angle": real(-50.0, 50.0),
         "nu": real(1.0, 20.0, 0.5), "dps": integer(15, 30, 14)},
        lambda r, a: 1 - 1e-12 <= float(r.p_star) <= a["nu"] + 1e-9,
        positional=("family", "twist_angle", "nu")),
    "characteristic_determinant": Spec(
        sr.characteristic_determinant,
        {"family": choice("symmetric", "antisymmetric"), "p_star": real(0.5, 10.0, 0.0),
         "twist_angle": real(-100.0, 100.0), "nu": real(1.0, 100.0, 0.5)},
        lambda r, a: math.isfinite(r), positional=("family", "p_star", "twist_angle", "nu")),
    "critical_wavenumbers": Spec(
        sr.critical_wavenumbers,
        {"p_star": real(1.0, 2.0, 0.0, -1.0), "twist_angle": real(-100.0, 100.0),
         "nu": real(1.0, 100.0, 0.5)},
        lambda r, a: np.isfinite(abs(r[0])) and np.isfinite(r[1]),
        positional=("p_star", "twist_angle", "nu")),
    "beta_difference": Spec(
        sr.beta_difference,
        {"p_star": real(1.0, 2.0, 0.0), "twist_angle": real(-100.0, 100.0),
         "nu": real(1.0, 100.0, 0.5)},
        lambda r, a: np.isfinite(r), positional=("p_star", "twist_angle", "nu")),
    "collocation_mode_coefficients": Spec(
        sr.collocation_mode_coefficients,
        {"twist_angle": real(-40.0, 40.0, 2e4), "nu": real(1.0, 100.0, 0.5),
         "n": integer(8, 64, 7, 1025, even=True),
         "family": choice("symmetric", "antisymmetric")},
        lambda r, a: finite(r[0]) and finite(r[1]),
        positional=("twist_angle", "nu", "n", "family")),
    "tail_for_tolerance": Spec(sr.tail_for_tolerance, {"tol": TOL}, lambda r, a: r > 0,
                               positional=("tol",)),
    "family_crossing": Spec(
        sr.family_crossing,
        {"twist_guess": real(6.0, 30.0, 0.0, -1.0, 2e3), "nu": real(1.05, 5.0, 0.5)},
        lambda r, a: math.isfinite(float(r.twist)), faults=(sr.RootNotFoundError,),
        positional=("twist_guess", "nu")),
    "collocation_crossing": Spec(
        sr.collocation_crossing,
        {"twist_guess": real(6.0, 30.0, 0.0, 500.0), "nu": real(1.05, 5.0, 0.5),
         "half_width": real(0.05, 0.3, 0.0, 5.0)},
        lambda r, a: math.isfinite(r.twist) and r.twist_error >= 0 and r.p_error >= 0,
        faults=(sr.RootNotFoundError,),
        positional=("twist_guess", "nu")),
    "large_twist_limit": Spec(sr.large_twist_limit, {"nu": NU},
                              lambda r, a: 1 <= r < 2, positional=("nu",)),
    "large_twist_coefficients": Spec(sr.large_twist_coefficients, {"nu": NU},
                                     lambda r, a: finite([r.p_inf, r.a2, r.b3, r.a4]),
                                     positional=("nu",)),
    "large_twist_expansion": Spec(
        sr.large_twist_expansion,
        {"twist_angle": Arg(st.floats(2 * math.pi, 1e4) | st.floats(-1e4, -2 * math.pi),
                            [*NOT_REAL, (0.0, ValueError), (1e-80, ValueError), (6.0, ValueError),
                             (20000.0, ValueError)]),
         "nu": NU, "order": choice(0, 2, 3, 4, invalid=[(1, ValueError), (True, ValueError)]),
         "family": optional(choice("symmetric", "antisymmetric"), [("even", ValueError)])},
        lambda r, a: math.isfinite(r) and 1 - 1e-12 <= r < 2, positional=("twist_angle", "nu")),
    "large_twist_wavenumbers": Spec(
        sr.large_twist_wavenumbers,
        {"twist_angle": Arg(st.floats(2 * math.pi, 1e4), [*NOT_REAL, (0.5, ValueError)]),
         "nu": NU},
        lambda r, a: finite(r), positional=("twist_angle", "nu")),
    "imaginary_beta1_window": Spec(sr.imaginary_beta1_window, {"nu": NU},
                                   lambda r, a: 0 < r.omega_a <= r.omega_b < 2 * math.pi,
                                   positional=("nu",)),
    "crossing_closed_form": Spec(sr.crossing_closed_form,
                                 {"n": integer(2, 10_000, 1, 10**8), "nu": NU},
                                 lambda r, a: finite([r.twist, r.p_star])
                                 and p_in_bounds(r.p_star, a["nu"]), positional=("n", "nu")),
    "crossing_twist_asymptotic": Spec(sr.crossing_twist_asymptotic,
                                      {"n": integer(2, 10_000, 1), "nu": NU},
                                      lambda r, a: math.isfinite(r), positional=("n", "nu")),
    "p_star_bounds": Spec(sr.p_star_bounds, {"nu": NU}, lambda r, a: r[0] <= r[1],
                          positional=("nu",)),
    "rectangle_torsion_ratio": Spec(sr.rectangle_torsion_ratio, {"nu": NU},
                                    lambda r, a: 0 < r < 1, positional=("nu",)),
    "crit2": Spec(sr.crit2, {"N": real(0.0, 1e3, -1.0), "nu": NU, "e_ratio": E_RATIO},
                  lambda r, a: math.isfinite(r), positional=("N", "nu")),
    "ring_formula_load": Spec(sr.ring_formula_load,
                              {"N": integer(0, 1000, -1, 1001), "nu": NU, "e_ratio": E_RATIO},
                              lambda r, a: math.isfinite(r), positional=("N", "nu")),
    "threshold_twist": Spec(sr.threshold_twist, {"nu": NU},
                            lambda r, a: r.continuous > 0, positional=("nu",)),
    "in_plane_untwisted": Spec(sr.in_plane_untwisted, {"A": real(1e-6, 1e6, 0.0), "load": LOAD},
                               lambda r, a: r > 0, positional=("A", "load")),
    "out_of_plane_untwisted": Spec(sr.out_of_plane_untwisted,
                                   {"A": real(1e-6, 1e6, 0.0), "A3": real(1e-6, 1e6, -1.0)},
                                   lambda r, a: r > 0, positional=("A", "A3")),
    "homogenised_limit": Spec(sr.homogenised_limit, {"nu": NU, "e_ratio": E_RATIO, "load": LOAD},
                              lambda r, a: r > 0, positional=("nu", "e_ratio", "load")),
    "untwisted_critical_load": Spec(sr.untwisted_critical_load,
                                    {"nu": NU, "e_ratio": E_RATIO, "load": LOAD},
                                    lambda r, a: r > 0, positional=("nu", "e_ratio", "load")),
    "in_plane_mode_load": Spec(sr.in_plane_mode_load, {"n": integer(2, 1000, 1, 10**6 + 1),
                                                       "A": real(1e-6, 1e6, 0.0), "load": LOAD},
                               lambda r, a: r > 0, positional=("n", "A")),
    "out_of_plane_mode_load": Spec(sr.out_of_plane_mode_load,
                                   {"n": integer(2, 1000, 1, 10**6 + 1),
                                    "A": real(1e-6, 1e6, 0.0), "A3": real(1e-6, 1e6, -1.0),
                                    "load": LOAD},
                                   lambda r, a: r > 0, positional=("n", "A", "A3")),
    "rigid_motion_load_work": Spec(sr.rigid_motion_load_work, {"load": LOAD},
                                   lambda r, a: len(r) == 6, positional=("load",)),
    "ring_coupling_strengths": Spec(sr.ring_coupling_strengths,
                                    {"N": RING_N, "nu": real(1.0, 10.0, 0.9),
                                     "e_ratio": real(0.1, 10.0, 0.0)},
                                    lambda r, a: all(0 <= v <= 1 for v in r.values()),
                                    positional=("N", "nu")),
    "ring_one_harmonic_load": Spec(sr.ring_one_harmonic_load,
                                   {"N": RING_N, "nu": real(1.0, 10.0, 0.9),
                                    "e_ratio": real(0.1, 10.0, 0.0), "load": LOAD},
                                   lambda r, a: r[0] > 0 and r[1] >= 2, positional=("N", "nu")),
    "ring_reference_torsions": Spec(sr.ring_reference_torsions, {"N": RING_N},
                                    lambda r, a: finite(r), positional=("N",)),
    "ring_critical_load": Spec(
        sr.ring_critical_load,
        {"N": RING_N, "nu": real(1.0, 10.0, 0.9), "e_ratio": real(0.1, 10.0, 0.0), "load": LOAD,
         "tol": real(1e-12, 1e-4, 1.0, 0.0),
         "method": choice("second-variation", "munder", invalid=NOT_STR)},
        _ring_q, faults=(sr.RingConvergenceError,), positional=("N", "nu")),
    "ring_buckling": Spec(
        sr.ring_buckling,
        {"N": RING_N, "nu": real(1.0, 10.0, 0.5), "e_ratio": real(0.1, 10.0, 0.0),
         "load": LOAD, "tol": real(1e-12, 1e-4, 0.5), "max_frequency": optional(
             integer(20, 60, 3, 5000)), "subspace": choice("all", "in-plane", "out-of-plane"),
         "raise_on_failure": boolean()},
        lambda r, a: math.isfinite(r.load) and r.load > 0, faults=(sr.RingConvergenceError,),
        positional=("N", "nu")),
    "destabilisation_threshold": Spec(
        sr.destabilisation_threshold,
        {"e_ratio": real(0.1, 10.0, 0.0), "load": LOAD,
         "nus": Arg(st.lists(st.floats(1.0, 6.0), min_size=2, max_size=3, unique=True)
                    .map(sorted), [([3.0, 2.0], ValueError), ([0.5, 2.0], ValueError),
                                   ("ab", TypeError)]),
         "twists": Arg(st.sampled_from([(0, 1), (0, 2), (0, 1, 2)]),
                       [((1, 2), ValueError), (3, TypeError), ((0, -1), ValueError)]),
         "xtol": real(1e-6, 0.5, 0.0),
         "method": choice("second-variation", invalid=NOT_STR)},
        lambda r, a: math.isnan(r) or min(a["nus"]) <= r <= max(a["nus"]),
        faults=(sr.RingConvergenceError,), positional=("e_ratio", "load", "nus")),
    "twist_raises_load": Spec(
        sr.twist_raises_load,
        {"q_twisted": real(-1e6, 1e6), "q_untwisted": real(1e-6, 1e6, 0.0, -1.0)},
        # the order it must respect, not its formula: at or above q(0) raised, clearly below
        # (twice the margin) not; the margin itself is pinned in tests/test_ring_stability.py
        lambda r, a: isinstance(r, bool)
        and (r if a["q_twisted"] >= a["q_untwisted"] else
             not r if a["q_twisted"] <= a["q_untwisted"] * (1 - 2 * sr.RING_RAISE_TOL) else True),
        positional=("q_twisted", "q_untwisted")),
    "twist_raises_load_arrays": Spec(
        sr.twist_raises_load, {"q_twisted": ARRAYS, "q_untwisted": real(1e-6, 1e6, 0.0)},
        lambda r, a: r.shape == np.shape(a["q_twisted"]) and r.dtype == bool,
        positional=("q_twisted", "q_untwisted")),
    "fd_critical_load": Spec(sr.fd_critical_load,
                             {"twist_angle": SMALL_TWIST, "nu": real(1.0, 100.0, 0.5),
                              "intervals": integer(8, 2000, 3, 1 << 22)},
                             lambda r, a: math.isfinite(r) and r > 0.9,
                             positional=("twist_angle", "nu", "intervals")),
    "baseline_critical_load": Spec(sr.baseline_critical_load,
                                   {"twist_angle": SMALL_TWIST, "nu": real(1.0, 100.0, 0.5),
                                    "n": integer(8, 64, 3, 1000)},
                                   lambda r, a: math.isfinite(r) and r > 0,
                                   positional=("twist_angle", "nu", "n")),
    "non_planarity": Spec(sr.non_planarity,
                          {"x1": Arg(st.lists(st.floats(-1, 1), min_size=3, max_size=20),
                                     [([1.0, NAN, 2.0], ValueError), ("abc", TypeError)])},
                          lambda r, a: 0 <= r <= 1, positional=("x1", "x2"),
                          derived={"x2": lambda a: [0.5 * v for v in a["x1"]]
                                   if isinstance(a["x1"], list) else [1.0, 2.0, 3.0]}),
    "local_maxima": Spec(sr.local_maxima, {"grid": GRIDS}, lambda r, a: finite(r),
                         positional=("grid", "values"),
                         derived={"values": lambda a: np.sin(np.asarray(a["grid"], float))}),
    "family_switches": Spec(sr.family_switches, {"grid": GRIDS}, lambda r, a: finite(r),
                            positional=("grid", "family"), derived={"family": lambda a: np.where(
                                np.asarray(a["grid"], float) > 30, "symmetric", "anti")}),
    "increasing_up_to": Spec(sr.increasing_up_to, {"grid": GRIDS, "end": real(0.0, 60.0)},
                             lambda r, a: isinstance(r, bool),
                             positional=("grid", "values", "end"),
                             derived={"values": lambda a: np.cos(np.asarray(a["grid"], float))}),
    "settling_point": Spec(sr.settling_point, {"grid": GRIDS,
                                               "level": real(1e-6, 10.0, 0.0, -1.0)},
                           lambda r, a: r is None or math.isfinite(r),
                           positional=("grid", "gap", "level"),
                           derived={"gap": lambda a: np.exp(-np.asarray(a["grid"], float))}),
    "observed_order": Spec(sr.observed_order,
                           {"x": Arg(st.lists(st.floats(0.1, 60.0), min_size=2, max_size=6,
                                              unique=True).filter(lambda v: max(v) > 1.001 * min(v))
                                     .map(np.array),
                                     [([1.0, NAN], ValueError), (["a"], TypeError),
                                      ([-1.0, 2.0], ValueError), ([2.0, 2.0], ValueError)])},
                           lambda r, a: math.isfinite(r), positional=("x", "err"),
                           derived={"err": lambda a: 1.0 + np.asarray(a["x"], float) ** -2}),
    "ring_roundoff_floor": Spec(sr.ring_roundoff_floor, {"e_ratio": E_RATIO},
                                lambda r, a: 0 < r < 1e-8, positional=("e_ratio",)),
    "out_of_plane_supremum": Spec(sr.out_of_plane_supremum, {"A": real(1e-6, 1e6, 0.0)},
                                  lambda r, a: r > 0, positional=("A",)),
    "baseline_sweep": Spec(sr.baseline_sweep, {"twist": ARRAYS, "nu": real(1.0, 100.0, 0.5)},
                           lambda r, a: finite(r), positional=("twist", "nu")),
    "load_figure1": Spec(sr.load_figure1, {"path": Arg(st.none(), [(5, TypeError),
                                                                   (1.5, TypeError)])},
                         lambda r, a: len(r) == 1201, positional=("path",)),
    "picture_lines": Spec(sr.picture_lines, {"tex": Arg(st.builds(sr.figure1_picture),
                                                         [(5, TypeError), ("no", ValueError)])},
                          lambda r, a: len(r) == 1201, positional=("tex",)),
    "munder_base_residual": Spec(
        sr.munder_base_residual, {"N": RING_N, "nu": real(1.0, 10.0, 0.5), "load": LOAD,
                                  "M": integer(8, 16, 3, 1000)},
        lambda r, a: 0 <= r < 1e-12, positional=("N", "nu")),
    "munder_buckling": Spec(
        sr.munder_buckling, {"N": integer(0, 3, -1, 31), "nu": real(1.0, 4.0, 0.5),
                             "load": LOAD, "raise_on_failure": boolean(),
                             "equations": choice("munder", "kirchhoff")},
        lambda r, a: math.isfinite(r.load) and r.load > 0, faults=(sr.RingConvergenceError,),
        positional=("N", "nu")),
    "ring_formulation_agreement": Spec(
        sr.ring_formulation_agreement,
        {"cases": Arg(st.sampled_from([[(1, 1.3)], [{"N": 0, "nu": 2.0, "load": "axis"}]]),
                      [([(1,)], TypeError), ([{"N": 1}], ValueError), ([(1, 0.5)], ValueError)])},
        lambda r, a: all(row["rel_diff"] < 1e-9 for row in r), positional=("cases",)),
    "derivation_status": Spec(sr.derivation_status, {"name": Arg(
        st.sampled_from(["ring_linearisation"]), NOT_STR)},
        lambda r, a: r == "all steps checked", positional=("name",)),
}


def _call(spec: Spec, kwargs: dict[str, Any]) -> Any:
    pos = [kwargs.pop(k) for k in spec.positional if k in kwargs]
    return spec.call(*pos, **kwargs)


def _draw_call(spec: Spec, data: st.DataObject) -> tuple[dict[str, Any], dict[str, type]]:
    """Valid values for every argument, then invalid values for a random few."""
    kwargs = {k: data.draw(a.valid, label=k) for k, a in spec.args.items()}
    for k, make in spec.derived.items():
        kwargs[k] = make(kwargs)
    bad: dict[str, type] = {}
    for k, a in spec.args.items():
        if a.invalid and data.draw(st.integers(0, 3), label=f"break {k}?") == 0:
            value, exc = data.draw(st.sampled_from(a.invalid), label=f"invalid {k}")
            kwargs[k], bad[k] = value, exc
    return kwargs, bad


def check_one(spec: Spec, kwargs: dict[str, Any], bad: dict[str, type],
              call_limit: float | None = None) -> None:
    """The property of the module docstring, for one call (and, in the large profile only, a
    wall-time limit as a hang detector: the default run has no timed asserts)."""
    t0 = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # unconverged results warn; flags are checked below
            result = _call(spec, dict(kwargs))
    except (ValueError, TypeError) as exc:
        assert bad, f"valid input rejected: {kwargs}: {exc!r}"
        assert any(k in str(exc) for k in bad), f"{exc!r} names none of {sorted(bad)}"
        return
    except sr.SpectralRodError as exc:
        assert not bad, f"invalid {sorted(bad)} not rejected: {exc!r}"
        assert isinstance(exc, spec.faults), f"undocumented fault {exc!r} for {kwargs}"
        return
    assert not bad, f"invalid {sorted(bad)} accepted: {kwargs} -> {result!r}"
    if call_limit is not None:
        assert time.perf_counter() - t0 < call_limit, f"{kwargs} took too long"
    assert spec.check(result, kwargs), f"result {result!r} out of bounds for {kwargs}"


def _fuzz(name: str, data: st.DataObject, call_limit: float | None = None) -> None:
    spec = SPECS[name]
    kwargs, bad = _draw_call(spec, data)
    check_one(spec, kwargs, bad, call_limit)


FAST = settings(max_examples=8, deadline=None, derandomize=True,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
LARGE = settings(max_examples=120, deadline=None,
                 suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@pytest.mark.parametrize("name", sorted(SPECS))
@FAST
@given(data=st.data())
def test_fuzz_public_function(name, data):
    _fuzz(name, data)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SPECS))
@LARGE
@given(data=st.data())
def test_fuzz_public_function_large(name, data):
    _fuzz(name, data, CALL_LIMIT)


#: Public callables without a fuzz spec, and why (each is exercised by its own tests).
EXEMPT = {
    "analyse_figure1": "takes the digitised table; ~2 s a call; argument types tested in "
                       "test_figure1_forensics",
    "characteristic_mode": "takes a CharacteristicRoot; covered by test_exempt_calls",
    "crossing_wavenumbers": "takes a FamilyCrossing; covered by test_exempt_calls",
    "engine_report": "no arguments",
    "format_engine_report": "no arguments",
    "figure1_picture": "no arguments",
    "inst1_variant_table": "no arguments (~4 s); tested in test_derivation_straight_rod",
    "ring_formulation_row": "takes two solver results; covered by test_exempt_calls",
    "rigid_motion_stiffness": "no arguments; tested in test_ring_loads",
    "ring_constraint_rank": "no arguments; tested in test_ring_loads",
}


def test_every_public_function_is_fuzzed_or_exempt():
    covered = {s.call for s in SPECS.values()}
    missing = [n for n in sr.__all__ if callable(getattr(sr, n))
               and not isinstance(getattr(sr, n), type) and getattr(sr, n) not in covered
               and n not in EXEMPT]
    assert not missing, missing


def test_exempt_calls():
    root = sr.characteristic_critical_load(5.0, 1.5, dps=20)
    for bad, exc in ((1.5, TypeError), ("x", TypeError)):
        with pytest.raises(exc, match="root"):
            sr.characteristic_mode(bad, 5.0, 1.5)
    with pytest.raises(ValueError, match="points"):
        sr.characteristic_mode(root, 5.0, 1.5, points=1)
    for twist, nu in ((6.0, 1.5), (5.0, 3.0)):  # a root of another point: accepted before
        with pytest.raises(ValueError, match="not a root at"):
            sr.characteristic_mode(root, twist, nu)
    assert finite(sr.characteristic_mode(root, -5.0, 1.5, points=11).x1)  # p* is even in it
    with pytest.raises(TypeError, match="crossing"):
        sr.crossing_wavenumbers(root, 1.5)
    crossing = sr.family_crossing(2 * math.pi, 1.5)  # before 2026-12-04: any nu was accepted
    with pytest.raises(ValueError, match="not the nu of the crossing"):
        sr.crossing_wavenumbers(crossing, 3.0)
    assert abs(sr.crossing_wavenumbers(crossing, 1.5).resonance_gap) < 1e-12
    with pytest.raises(sr.RootNotFoundError, match=r"nu=1\.0"):  # a ZeroDivisionError before
        sr.family_crossing(2 * math.pi, 1.0)
    with pytest.raises(sr.RootNotFoundError, match="complex"):  # a TypeError before
        sr.family_crossing(math.pi, 1e4)
    with pytest.raises(TypeError, match="points"):
        sr.analyse_figure1("table")
    assert finite(sr.characteristic_mode(root, 5.0, 1.5, points=11).x1)
    ring, munder = sr.ring_buckling(1, 1.5), sr.munder_buckling(1, 1.5)
    with pytest.raises(TypeError, match="RingBuckling"):
        sr.ring_formulation_row(munder, ring)
    with pytest.raises(ValueError, match="different rings"):
        sr.ring_formulation_row(sr.ring_buckling(2, 1.5), munder)
    with pytest.raises(ValueError, match="load models"):  # accepted before 2026-12-04
        sr.ring_formulation_row(sr.ring_buckling(1, 1.5, load="axis"), munder)
    assert sr.ring_formulation_row(ring, munder)["rel_diff"] < 1e-9
