"""The evidence of the ring claims: every number they are judged on, computed by calls to the
library (the converged second-variation solver for a table of rings, the second formulation from
Eqs. ``Munder`` on a set of cases, the classical closed forms, a wide-nu scan, the caveats).
"""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import pandas as pd
from scipy.optimize import brentq

from spectral_rod import (
    RING_AGREEMENT_CASES,
    RING_LOADS,
    crit2,
    derivation_status,
    homogenised_limit,
    in_plane_untwisted,
    munder_base_residual,
    munder_buckling,
    out_of_plane_untwisted,
    rectangle_torsion_ratio,
    ring_buckling,
    ring_formula_load,
    ring_formulation_agreement,
    threshold_twist,
)

SECTION = "Sec. 'Stability of a ring'"
TWISTS = tuple(range(11))
NUS = (1.0, 1.1, 1.3, 1.5, 2.0, 4.0)
POISSON = 0.3
#: e = E2/E1: the paper's notation read literally (E2 = E1) and an isotropic material, for which
#: A3 = E2 (I1 + I2) is G J of a circular section (E2 = G = E1/(2 (1 + Poisson))).
E_RATIOS = {"e=1": 1.0, "isotropic": 1.0 / (2.0 * (1.0 + POISSON))}
TITLES = {"e=1": "E₂ = E₁", "isotropic": f"isotropic, E₂ = G (Poisson {POISSON})"}
#: Twists used for the rapid-twist (homogenisation) check.
LARGE_TWISTS = (10, 20, 40)
#: The wide scan for the general claims (twist destabilises; the rate grows with nu): nu to 100.
WIDE_NUS = (1.1, 1.5, 2.0, 3.0, 4.0, 6.0, 10.0, 20.0, 50.0, 100.0)
WIDE_TWISTS = tuple(range(11))
#: The cases on which the two ring formulations are compared (N = 0..8, several nu, e, loads).
AGREEMENT_CASES = RING_AGREEMENT_CASES


@dataclass
class RingEvidence:
    """Everything the ring claims are judged on (all computed by :func:`compute_evidence`)."""

    table: pd.DataFrame
    thresholds: pd.DataFrame
    untwisted_circular: pd.DataFrame
    large_twist: pd.DataFrame
    formulations: pd.DataFrame
    wide: pd.DataFrame
    boundaries: pd.DataFrame
    rectangle: pd.DataFrame
    equilibrium: dict[str, object] = field(default_factory=dict)
    timings: dict[str, float] = field(default_factory=dict)


# ------------------------------------------------------------------------------------------
# evidence
# ------------------------------------------------------------------------------------------

def table_rows(nus: tuple[float, ...] = NUS, twists: tuple[int, ...] = TWISTS,
               e_ratios: dict[str, float] = E_RATIOS,
               progress: Callable[[str], None] = lambda _m: None) -> pd.DataFrame:
    """Formula and converged numerical q_cr R^3/(E1 I1) for every (e, nu, N) and load model."""
    rows = []
    for label, e in e_ratios.items():
        progress(f"solving {len(nus) * len(twists)} rings for {label} (e = {e:.4f}), both loads")
        for nu in nus:
            for N in twists:
                row: dict[str, object] = {"e_label": label, "e_ratio": e, "nu": nu, "N": N,
                                          "crit2": ring_formula_load(N, nu, e_ratio=e)}
                for load in RING_LOADS:
                    r = ring_buckling(N, nu, e_ratio=e, load=load)
                    row[f"q_{load}"] = r.load
                    row[f"kind_{load}"] = r.kind
                    row[f"in_plane_fraction_{load}"] = r.in_plane_fraction
                    row[f"wavenumber_{load}"] = r.dominant_frequency
                    row[f"max_frequency_{load}"] = r.max_frequency
                    row[f"rel_change_{load}"] = r.rel_change
                    row[f"min_inverse_load_{load}"] = r.min_load_over_q
                    row[f"rel_dev_{load}"] = (row["crit2"] - r.load) / r.load
                rows.append(row)
    return pd.DataFrame(rows)


def threshold_rows(table: pd.DataFrame, nus: tuple[float, ...] = NUS) -> pd.DataFrame:
    """Threshold twist per nu (continuous, integer) and the numerical loads at the integer."""
    rows = []
    for nu in nus:
        th = threshold_twist(nu)
        row: dict[str, object] = {"nu": nu, "N_continuous": th.continuous,
                                  "N_integer": th.integer}
        for label, e in E_RATIOS.items():
            if math.isinf(th.integer):
                row[f"crit2_at_N_{label}"] = math.nan
                row[f"q_hydrostatic_at_N_{label}"] = math.nan
                row[f"q_axis_at_N_{label}"] = math.nan
                continue
            N = int(th.integer)
            sel = table[(table["e_label"] == label) & (table["nu"] == nu) & (table["N"] == N)]
            row[f"crit2_at_N_{label}"] = crit2(N, nu, e)
            for load in RING_LOADS:
                row[f"q_{load}_at_N_{label}"] = (float(sel[f"q_{load}"].iloc[0]) if len(sel)
                                                else ring_buckling(N, nu, e_ratio=e,
                                                                   load=load).load)
        rows.append(row)
    return pd.DataFrame(rows)


def untwisted_circular_rows() -> pd.DataFrame:
    """N = 0, nu = 1: solver restricted to in-plane / out-of-plane vs the closed forms."""
    rows = []
    for label, e in E_RATIOS.items():
        for load in RING_LOADS:
            full = ring_buckling(0, 1.0, e_ratio=e, load=load)
            inp = ring_buckling(0, 1.0, e_ratio=e, load=load, subspace="in-plane")
            out = ring_buckling(0, 1.0, e_ratio=e, load=load, subspace="out-of-plane")
            rows.append({"e_label": label, "e_ratio": e, "load": load,
                         "in_plane": inp.load, "in_plane_n": inp.dominant_frequency,
                         "in_plane_closed": in_plane_untwisted(1.0, load),
                         "out_of_plane": out.load, "out_of_plane_n": out.dominant_frequency,
                         "out_of_plane_closed": out_of_plane_untwisted(1.0, 2.0 * e),
                         "critical": full.load, "kind": full.kind})
    return pd.DataFrame(rows)


def large_twist_rows(nus: tuple[float, ...] = (1.5, 4.0)) -> pd.DataFrame:
    """q_cr at N = 10, 20, 40 against the homogenised (harmonic-mean) limit."""
    rows = []
    for nu in nus:
        for label, e in E_RATIOS.items():
            lim = homogenised_limit(nu, e, "hydrostatic")
            for N in LARGE_TWISTS:
                q = ring_buckling(N, nu, e_ratio=e).load
                rows.append({"nu": nu, "e_label": label, "N": N, "q_hydrostatic": q,
                             "limit": lim, "rel_gap": (q - lim) / lim})
    return pd.DataFrame(rows)


def formulation_rows() -> pd.DataFrame:
    """The two formulations (second variation, Munder) on :data:`AGREEMENT_CASES`."""
    return pd.DataFrame(ring_formulation_agreement(AGREEMENT_CASES))


def _lowest_loads(nu: float, e_ratio: float, load: str,
                  twists: tuple[int, ...] = WIDE_TWISTS) -> list[float]:
    return [ring_buckling(N, nu, e_ratio=e_ratio, load=load).load for N in twists]


def wide_rows(progress: Callable[[str], None] = lambda _m: None) -> pd.DataFrame:
    """q_cr(N) for N = 0..10 over :data:`WIDE_NUS`, both e and loads (long format)."""
    rows = []
    for label, e in E_RATIOS.items():
        progress(f"wide scan nu in [{WIDE_NUS[0]:g}, {WIDE_NUS[-1]:g}] for {label}")
        for nu in WIDE_NUS:
            for load in RING_LOADS:
                for N, q in zip(WIDE_TWISTS, _lowest_loads(nu, e, load), strict=True):
                    rows.append({"e_label": label, "nu": nu, "load": load, "N": N, "q": q})
    return pd.DataFrame(rows)


def largest_twist_gain(nu: float, e_ratio: float, load: str) -> float:
    """max over N = 1..10 of q_cr(N)/q_cr(0) - 1: > 0 where some twist raises the load."""
    q = _lowest_loads(nu, e_ratio, load)
    return max(q[1:]) / q[0] - 1.0


def boundary_rows(wide: pd.DataFrame) -> pd.DataFrame:
    """Per e and load: the nu above which some twist N = 1..10 raises q_cr (the first sign
    change of :func:`largest_twist_gain` on the wide grid, refined by Brent to 1e-3 in nu)."""
    rows = []
    for (label, load), g in wide.groupby(["e_label", "load"], sort=False):
        gains = []
        for nu, h in g.groupby("nu"):
            q = h.sort_values("N")["q"].to_numpy()
            gains.append((float(nu), float(q[1:].max() / q[0] - 1.0)))
        e = E_RATIOS[str(label)]
        nu_star = math.nan
        for (a, ga), (b, gb) in itertools.pairwise(gains):
            if ga < 0 <= gb:
                nu_star = brentq(lambda v, e=e, ld=load: largest_twist_gain(v, e, ld), a, b,
                                 xtol=1e-3)
                break
        rows.append({"e_label": label, "load": load, "nu_boundary": nu_star,
                     "raised_at_nus": [nu for nu, gn in gains if gn >= 0]})
    return pd.DataFrame(rows)


def rectangle_rows(nus: tuple[float, ...] = NUS) -> pd.DataFrame:
    """The torsion caveat: an isotropic rectangular rod has A3 = G J, J = ratio (I1 + I2)
    (:func:`spectral_rod.rectangle_torsion_ratio`), i.e. e = E_iso * ratio; q_cr(N) with it."""
    rows = []
    for nu in nus:
        ratio = rectangle_torsion_ratio(nu)
        e = E_RATIOS["isotropic"] * ratio
        for load in RING_LOADS:
            for N, q in zip(TWISTS, _lowest_loads(nu, e, load, TWISTS), strict=True):
                rows.append({"nu": nu, "torsion_ratio": ratio, "e_ratio": e, "load": load,
                             "N": N, "q": q})
    return pd.DataFrame(rows)


#: Cases on which Eqs. Munder are compared with Kirchhoff's vector balances, and on which the
#: loaded circle's residual is evaluated.
EQUILIBRIUM_CASES = ((2, 2.0, 1.0, "axis"), (3, 4.0, 1.0, "hydrostatic"),
                     (1, 1.3, E_RATIOS["isotropic"], "hydrostatic"))


def equilibrium_checks() -> dict[str, object]:
    """Eqs. Munder against Kirchhoff's vector balances (M' + t x F = 0, F' + q = 0) on
    :data:`EQUILIBRIUM_CASES`; the loaded circle with F_t = -q R and no moments as a solution of
    Munder (its residual); the sympy ring derivation's own checks (frenini, hoop force)."""
    diffs, residuals = [], []
    for N, nu, e, load in EQUILIBRIUM_CASES:
        m = munder_buckling(N, nu, e_ratio=e, load=load).load
        k = munder_buckling(N, nu, e_ratio=e, load=load, equations="kirchhoff").load
        diffs.append(abs(m - k) / abs(k))
        residuals += [munder_base_residual(N, nu, e_ratio=e, load=ld) for ld in RING_LOADS]
    return {"munder_vs_kirchhoff": max(diffs), "base_residual": max(residuals),
            "ring_derivation": derivation_status("ring_linearisation"),
            "straight_rod_derivation": derivation_status("straight_rod")}


def compute_evidence(progress: Callable[[str], None] = lambda _m: None) -> RingEvidence:
    timings: dict[str, float] = {}
    t = time.perf_counter()
    table = table_rows(progress=progress)
    timings["table"] = time.perf_counter() - t
    t = time.perf_counter()
    progress("threshold twists, untwisted circular ring, rapid-twist limit")
    thresholds = threshold_rows(table)
    circ = untwisted_circular_rows()
    large = large_twist_rows()
    timings["checks"] = time.perf_counter() - t
    t = time.perf_counter()
    progress(f"second formulation (Munder) on {len(AGREEMENT_CASES)} cases")
    forms = formulation_rows()
    timings["second formulation"] = time.perf_counter() - t
    t = time.perf_counter()
    wide = wide_rows(progress)
    boundaries = boundary_rows(wide)
    timings["wide scan"] = time.perf_counter() - t
    t = time.perf_counter()
    progress("torsion caveat: rectangular sections")
    rect = rectangle_rows()
    timings["rectangle caveat"] = time.perf_counter() - t
    t = time.perf_counter()
    progress("Eqs. Munder vs Kirchhoff's balances; the loaded circle; the sympy derivation")
    equilibrium = equilibrium_checks()
    timings["equilibrium checks"] = time.perf_counter() - t
    return RingEvidence(table, thresholds, circ, large, forms, wide, boundaries, rect,
                        equilibrium, timings)


def q_at(ev: RingEvidence, nu: float, N: int, label: str = "e=1",
         load: str = "hydrostatic") -> float:
    """The tabulated converged q_cr at (nu, N, e, load)."""
    t = ev.table
    return float(t[(t["e_label"] == label) & (t["nu"] == nu) & (t["N"] == N)][f"q_{load}"]
                 .iloc[0])
