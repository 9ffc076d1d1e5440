"""The evidence of the ring claims: every number they are judged on, computed by calls to the
library (the converged second-variation solver for a table of rings, the second formulation from
Eqs. ``Munder`` on a set of cases, the classical closed forms, a wide-nu scan, the caveats).

One scene run solves each ring once: the table, the wide scan, the formulation cases and the
checks overlap, so every solve goes through the run's :func:`memo_solver` (nothing is kept
across runs).
"""

from __future__ import annotations

import functools
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import pandas as pd

from spectral_rod import (
    RING_AGREEMENT_CASES,
    RING_E_ISOTROPIC,
    RING_ISOTROPIC_POISSON,
    RING_LOADS,
    RingConvergenceError,
    buckling_mode,
    crit2,
    derivation_status,
    destabilisation_threshold,
    in_plane_untwisted,
    munder_base_residual,
    munder_buckling,
    non_planarity,
    out_of_plane_untwisted,
    rectangle_torsion_ratio,
    ring_buckling,
    ring_formula_load,
    ring_formulation_row,
    ring_one_harmonic_load,
    threshold_twist,
)

SECTION = "Sec. 'Stability of a ring'"
TWISTS = tuple(range(11))
NUS = (1.0, 1.1, 1.3, 1.5, 2.0, 4.0)
#: e = E2/E1: the paper's notation read literally (E2 = E1) and an isotropic material, for which
#: A3 = E2 (I1 + I2) is G J of a circular section (spectral_rod.RING_E_ISOTROPIC).
E_RATIOS = {"e=1": 1.0, "isotropic": RING_E_ISOTROPIC}
TITLES = {"e=1": "E₂ = E₁", "isotropic": f"isotropic, E₂ = G (Poisson {RING_ISOTROPIC_POISSON:g})"}
#: The wide scan for the general claims (twist destabilises; the rate grows with nu): nu to 100.
WIDE_NUS = (1.1, 1.5, 2.0, 3.0, 4.0, 6.0, 10.0, 20.0, 50.0, 100.0)
WIDE_TWISTS = tuple(range(11))
#: nu* (above which some twist raises q_cr) is refined to this in nu: three digits suffice to
#: place it among the scan's nu, which are 1e-1 and more apart.
BOUNDARY_XTOL = 1.0e-3
#: The cases on which the two ring formulations are compared (N = 0..8, several nu, e, loads).
AGREEMENT_CASES = RING_AGREEMENT_CASES
#: Cases on which Eqs. Munder are compared with Kirchhoff's vector balances, and on which the
#: loaded circle's residual is evaluated.
EQUILIBRIUM_CASES = ((2, 2.0, 1.0, "axis"), (3, 4.0, 1.0, "hydrostatic"),
                     (1, 1.3, RING_E_ISOTROPIC, "hydrostatic"))
#: The straight rod's mode for the introduction's claim (Omega(L), nu).
ROD_MODE_CASE = (5.0, 1.5)

#: The row of :attr:`RingEvidence.timings` for the witnesses' re-solves by Eqs. Munder (made
#: while the claims are measured, on the evidence and on each load model's alone).
WITNESS_TIMING = "witnesses (Munder re-solves)"

#: The progress messages of :func:`compute_evidence`: templates with named fields.
PROGRESS = {
    "table": "solving {rings} rings for {label} (e = {e:.4f}), every reading",
    "wide": "wide scan nu in [{nu_first:g}, {nu_last:g}] for {label}",
    "checks": "threshold twists, untwisted circular ring, the straight rod's mode",
    "one-harmonic": "the one-harmonic Galerkin (the paper's stated method) on the table",
    "formulations": "second formulation (Munder) on {cases} cases",
    "rectangle": "torsion caveat: rectangular sections",
    "equilibrium": "Eqs. Munder vs Kirchhoff's balances; the loaded circle; the sympy derivation",
}


def _progress(name: str, **fields: object) -> str:
    """The progress message `name` of :data:`PROGRESS` with its named fields."""
    return PROGRESS[name].format(**fields)


#: solve(N, nu, e, load, method="second-variation"|"munder"|"kirchhoff") -> the library result
Solve = Callable[..., Any]


@dataclass
class RingEvidence:
    """Everything the ring claims are judged on (all computed by :func:`compute_evidence`)."""

    table: pd.DataFrame
    thresholds: pd.DataFrame
    untwisted_circular: pd.DataFrame
    formulations: pd.DataFrame
    wide: pd.DataFrame
    boundaries: pd.DataFrame
    rectangle: pd.DataFrame
    #: The one-harmonic Galerkin loads (:func:`one_harmonic_rows`)
    one_harmonic: pd.DataFrame = field(default_factory=pd.DataFrame)
    #: In-plane share of the critical mode beyond the table's twists (:func:`large_twist_shares`)
    large_twist_shares: dict[int, float] = field(default_factory=dict)
    equilibrium: dict[str, object] = field(default_factory=dict)
    rod_non_planarity: float = math.nan
    solves: dict[str, int] = field(default_factory=dict)
    #: Wall time per stage (s); the witnesses' re-solves add :data:`WITNESS_TIMING` when the
    #: claims are measured (shared by copies of this evidence, like :attr:`witnesses`).
    timings: dict[str, float] = field(default_factory=dict)
    #: The run's solver (:func:`memo_solver`), for rings re-solved on demand by the second
    #: formulation (:meth:`munder_load`); None: no re-solves (their checks then fail).
    solve: Solve | None = field(default=None, repr=False, compare=False)
    #: Set where the evidence of one load model stands under both labels
    #: (``rows.single_load_evidence``): re-solves use that model, whatever the label.
    load_override: str | None = None
    #: The rings :meth:`munder_load` re-solved (shared by copies of this evidence).
    witnesses: set[tuple[int, float, float, str]] = field(default_factory=set, repr=False,
                                                          compare=False)

    def munder_load(self, N: int, nu: float, e_label: str, load: str) -> float:
        """q_cr of one ring by Eqs. Munder (the second formulation), solved once per run: a
        verdict's decisive rings re-checked. NaN if this evidence has no solver or the solve
        does not converge (the witness's check then fails: "inconclusive")."""
        if self.solve is None:
            return math.nan
        ring = (int(N), float(nu), E_RATIOS[e_label], self.load_override or load)
        self.witnesses.add(ring)
        t = time.perf_counter()
        try:
            return float(self.solve(*ring, "munder").load)
        except RingConvergenceError:
            return math.nan
        finally:  # the re-solves run while the claims are measured: their own timings row
            self.timings[WITNESS_TIMING] = (self.timings.get(WITNESS_TIMING, 0.0)
                                            + time.perf_counter() - t)


def memo_solver() -> Solve:
    """A solver for one scene run that solves each (N, nu, e, load, method) ring once."""
    @functools.cache
    def solve(N: int, nu: float, e: float, load: str, method: str = "second-variation") -> Any:
        if method == "second-variation":
            return ring_buckling(N, nu, e_ratio=e, load=load)
        equations = "munder" if method == "munder" else "kirchhoff"
        return munder_buckling(N, nu, e_ratio=e, load=load, equations=equations)

    return solve


# ------------------------------------------------------------------------------------------
# evidence
# ------------------------------------------------------------------------------------------

def _table_row(solve: Solve, label: str, e: float, nu: float, N: int) -> dict[str, object]:
    row: dict[str, object] = {"e_label": label, "e_ratio": e, "nu": nu, "N": N,
                              "crit2": ring_formula_load(N, nu, e_ratio=e)}
    for load in RING_LOADS:
        r = solve(N, nu, e, load)
        row[f"q_{load}"] = r.load
        row[f"kind_{load}"] = r.kind
        row[f"in_plane_fraction_{load}"] = r.in_plane_fraction
        row[f"wavenumber_{load}"] = r.dominant_frequency
        row[f"max_frequency_{load}"] = r.max_frequency
        row[f"rel_change_{load}"] = r.rel_change
        row[f"min_inverse_load_{load}"] = r.min_load_over_q
        row[f"rel_dev_{load}"] = (row["crit2"] - r.load) / r.load
    return row


def table_rows(solve: Solve, nus: tuple[float, ...] = NUS, twists: tuple[int, ...] = TWISTS,
               e_ratios: dict[str, float] = E_RATIOS,
               progress: Callable[[str], None] = lambda _m: None) -> pd.DataFrame:
    """Formula and converged numerical q_cr R^3/(E1 I1) for every (e, nu, N) and load model."""
    rows = []
    for label, e in e_ratios.items():
        progress(_progress("table", rings=len(nus) * len(twists), label=label, e=e))
        rows += [_table_row(solve, label, e, nu, N) for nu in nus for N in twists]
    return pd.DataFrame(rows)


def threshold_rows(table: pd.DataFrame, solve: Solve, nus: tuple[float, ...] = NUS
                   ) -> pd.DataFrame:
    """Threshold twist per nu (continuous, integer) and the numerical loads at the integer."""
    rows = []
    for nu in nus:
        th = threshold_twist(nu)
        row: dict[str, object] = {"nu": nu, "N_continuous": th.continuous,
                                  "N_integer": th.integer}
        for label, e in E_RATIOS.items():
            finite = not math.isinf(th.integer)
            row[f"crit2_at_N_{label}"] = crit2(int(th.integer), nu, e) if finite else math.nan
            for load in RING_LOADS:
                row[f"q_{load}_at_N_{label}"] = (solve(int(th.integer), nu, e, load).load
                                                 if finite else math.nan)
        rows.append(row)
    return pd.DataFrame(rows)


def untwisted_circular_rows(solve: Solve) -> pd.DataFrame:
    """N = 0, nu = 1: solver restricted to in-plane / out-of-plane vs the closed forms."""
    rows = []
    for label, e in E_RATIOS.items():
        for load in RING_LOADS:
            full = solve(0, 1.0, e, load)
            inp = ring_buckling(0, 1.0, e_ratio=e, load=load, subspace="in-plane")
            out = ring_buckling(0, 1.0, e_ratio=e, load=load, subspace="out-of-plane")
            rows.append({"e_label": label, "e_ratio": e, "load": load,
                         "in_plane": inp.load, "in_plane_n": inp.dominant_frequency,
                         "in_plane_closed": in_plane_untwisted(1.0, load),
                         "out_of_plane": out.load, "out_of_plane_n": out.dominant_frequency,
                         "out_of_plane_closed": out_of_plane_untwisted(1.0, 2.0 * e, load),
                         "critical": full.load, "kind": full.kind})
    return pd.DataFrame(rows)


def one_harmonic_rows(solve: Solve, table: pd.DataFrame) -> pd.DataFrame:
    """The one-harmonic Galerkin load beside the converged one for every table ring (long
    format: e_label, nu, N, load, q_one_harmonic, n_one_harmonic, q)."""
    rows = []
    for r in table.itertuples():
        for load in RING_LOADS:
            q1, n = ring_one_harmonic_load(int(r.N), float(r.nu), float(r.e_ratio), load)
            rows.append({"e_label": r.e_label, "nu": r.nu, "N": r.N, "load": load,
                         "q_one_harmonic": q1, "n_one_harmonic": n,
                         "q": solve(int(r.N), float(r.nu), float(r.e_ratio), load).load})
    return pd.DataFrame(rows)


#: (nu, e, load) and the twists N beyond the table at which the critical mode's in-plane share
#: is followed toward N -> infinity.
LARGE_TWIST_CASE = (2.0, 1.0, "hydrostatic")
LARGE_TWISTS = (10, 20, 40)


def large_twist_shares(solve: Solve) -> dict[int, float]:
    """In-plane share of the load work of the critical mode at :data:`LARGE_TWISTS`."""
    nu, e, load = LARGE_TWIST_CASE
    return {N: float(solve(N, nu, e, load).in_plane_fraction) for N in LARGE_TWISTS}


def formulation_rows(solve: Solve) -> pd.DataFrame:
    """The two formulations (second variation, Munder) on :data:`AGREEMENT_CASES`: the columns
    of :func:`spectral_rod.ring_formulation_agreement` (without its timings), from this run's
    solves (the second-variation ones are table rings)."""
    return pd.DataFrame([ring_formulation_row(solve(*case), solve(*case, "munder"))
                         for case in AGREEMENT_CASES])


def wide_rows(solve: Solve, progress: Callable[[str], None] = lambda _m: None) -> pd.DataFrame:
    """q_cr(N) and the smallest 1/q for N = 0..10 over :data:`WIDE_NUS`, both e and loads (long
    format)."""
    rows = []
    for label, e in E_RATIOS.items():
        progress(_progress("wide", nu_first=WIDE_NUS[0], nu_last=WIDE_NUS[-1], label=label))
        for nu in WIDE_NUS:
            for load in RING_LOADS:
                for N in WIDE_TWISTS:
                    r = solve(N, nu, e, load)
                    rows.append({"e_label": label, "nu": nu, "load": load, "N": N, "q": r.load,
                                 "min_inverse_load": r.min_load_over_q})
    return pd.DataFrame(rows)


def boundary_rows(wide: pd.DataFrame) -> pd.DataFrame:
    """Per e and load: the nu above which some twist N = 1..WIDE_TWISTS[-1] raises q_cr
    (:func:`spectral_rod.destabilisation_threshold` on the wide scan's loads)."""
    rows = []
    for (label, load), g in wide.groupby(["e_label", "load"], sort=False):
        loads = g.pivot(index="nu", columns="N", values="q").loc[:, list(WIDE_TWISTS)]
        nu_star = destabilisation_threshold(E_RATIOS[str(label)], str(load),
                                            loads.index.to_numpy(), twists=WIDE_TWISTS,
                                            loads=loads.to_numpy(), xtol=BOUNDARY_XTOL)
        rows.append({"e_label": label, "load": load, "nu_boundary": nu_star})
    return pd.DataFrame(rows)


def rectangle_rows(solve: Solve, nus: tuple[float, ...] = NUS) -> pd.DataFrame:
    """The torsion caveat: an isotropic rectangular rod has A3 = G J, J = ratio (I1 + I2)
    (:func:`spectral_rod.rectangle_torsion_ratio`), i.e. e = E_iso * ratio; q_cr(N) with it."""
    rows = []
    for nu in nus:
        ratio = rectangle_torsion_ratio(nu)
        e = RING_E_ISOTROPIC * ratio
        for load in RING_LOADS:
            rows += [{"nu": nu, "torsion_ratio": ratio, "e_ratio": e, "load": load, "N": N,
                      "q": solve(N, nu, e, load).load} for N in TWISTS]
    return pd.DataFrame(rows)


def equilibrium_checks(solve: Solve) -> dict[str, object]:
    """Eqs. Munder against Kirchhoff's vector balances (M' + t x F = 0, F' + q = 0) on
    :data:`EQUILIBRIUM_CASES`; the loaded circle with F_t = -q R and no moments as a solution of
    Munder (its residual); the sympy ring derivation's own checks (frenini, hoop force)."""
    diffs, residuals = [], []
    for N, nu, e, load in EQUILIBRIUM_CASES:
        m = solve(N, nu, e, load, "munder").load
        k = solve(N, nu, e, load, "kirchhoff").load
        diffs.append(abs(m - k) / abs(k))
        residuals += [munder_base_residual(N, nu, e_ratio=e, load=ld) for ld in RING_LOADS]
    return {"munder_vs_kirchhoff": max(diffs), "base_residual": max(residuals),
            "ring_derivation": derivation_status("ring_linearisation"),
            "straight_rod_derivation": derivation_status("straight_rod")}


def rod_mode_non_planarity() -> float:
    """sigma_min/sigma_max of the straight rod's critical centreline at :data:`ROD_MODE_CASE`."""
    m = buckling_mode(*ROD_MODE_CASE)
    return non_planarity(m.x1, m.x2)


def compute_evidence(progress: Callable[[str], None] = lambda _m: None) -> RingEvidence:
    solve = memo_solver()
    timings: dict[str, float] = {}

    def timed(name: str, fn: Callable[[], Any]) -> Any:
        t = time.perf_counter()
        value = fn()
        timings[name] = timings.get(name, 0.0) + time.perf_counter() - t
        return value

    table = timed("table", lambda: table_rows(solve, progress=progress))
    progress(_progress("checks"))
    thresholds = timed("checks", lambda: threshold_rows(table, solve))
    shares = timed("checks", lambda: large_twist_shares(solve))
    circ = timed("checks", lambda: untwisted_circular_rows(solve))
    rod = timed("checks", rod_mode_non_planarity)
    progress(_progress("one-harmonic"))
    one = timed("one-harmonic Galerkin", lambda: one_harmonic_rows(solve, table))
    progress(_progress("formulations", cases=len(AGREEMENT_CASES)))
    forms = timed("second formulation", lambda: formulation_rows(solve))
    wide = timed("wide scan", lambda: wide_rows(solve, progress))
    boundaries = timed("wide scan", lambda: boundary_rows(wide))
    progress(_progress("rectangle"))
    rect = timed("rectangle caveat", lambda: rectangle_rows(solve))
    progress(_progress("equilibrium"))
    equilibrium = timed("equilibrium checks", lambda: equilibrium_checks(solve))
    info = solve.cache_info()
    solves = {"distinct": info.misses, "requested": info.hits + info.misses}
    return RingEvidence(table, thresholds, circ, forms, wide, boundaries, rect, one, shares,
                        equilibrium, rod, solves, timings, solve)


def q_at(ev: RingEvidence, nu: float, N: int, label: str = "e=1",
         load: str = "hydrostatic") -> float:
    """The tabulated converged q_cr at (nu, N, e, load)."""
    t = ev.table
    return float(t[(t["e_label"] == label) & (t["nu"] == nu) & (t["N"] == N)][f"q_{load}"]
                 .iloc[0])
