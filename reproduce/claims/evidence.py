"""The evidence of the straight-rod claims: every number the claims are judged on, computed by
calls to the library (dense collocation curves, the characteristic equation in mpmath for every
decisive number, the closed forms of :mod:`spectral_rod.rod.closed_form`).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from spectral_rod import (
    buckling_mode,
    characteristic_critical_load,
    characteristic_determinant,
    characteristic_mode,
    collocation_crossing,
    critical_load,
    critical_wavenumbers,
    crossing_closed_form,
    crossing_wavenumbers,
    derivation_status,
    family_crossing,
    family_switches,
    imaginary_beta1_window,
    increasing_up_to,
    inst1_variant_table,
    large_twist_expansion,
    large_twist_limit,
    load_figure1,
    non_planarity,
    settling_point,
)

SECTION = "Sec. 'Stability of a rectilinear rod'"
#: Asymmetries checked everywhere (Figure 1's 1.1 and 1.5, and beyond it).
NUS = (1.1, 1.5, 2.0, 5.0, 10.0)
TWIST_MAX = 20 * math.pi
GRID_POINTS = 401
#: Maxima located for every nu (n pi), and for the detailed nu the whole run to 20 pi.
MAXIMA_N = (2, 3, 4)
DETAIL_NU = 1.5
DETAIL_N = tuple(range(2, 21))
#: Large-twist checks: Omega = pi/2 + 2 pi j (sin Omega = 1, the ripple's largest value).
LIMIT_J = (5, 10, 20)
#: Spot checks of the dense collocation grid against the characteristic equation.
SPOT_TWISTS = (0.5, 3.0, 5.0, 9.0, 20.0, 40.0, 60.0)
#: Modes shown and measured (Omega(L), nu).
MODE_CASES = ((5.0, 1.5), (12.0, 1.5), (5.0, 10.0))
#: Twists (nu = DETAIL_NU, away from crossings) for the decay of the mode's non-planarity.
PLANARITY_TWISTS = (12.0, 24.0, 48.0)
#: The "for all Omega" claims are judged over the scene's whole twist range (0, TWIST_MAX]:
#: log-spaced from PLANARITY_RANGE_MIN (the small-twist end, where the non-planarity grows
#: like Omega) to TWIST_MAX, for every nu.
PLANARITY_RANGE_MIN = 1e-2
PLANARITY_RANGE_POINTS = 48
CURVE_TOL = 1e-10   # dense curves (figures, shape checks)
TOL = 1e-12         # decisive collocation numbers
DPS = 30


# ------------------------------------------------------------------------------------------
# the evidence
# ------------------------------------------------------------------------------------------

@dataclass
class MaximumRecord:
    """A maximum of p*(Omega) at a family crossing, from both solvers."""

    nu: float
    n: int
    twist_mp: float
    twist_coll: float
    p_mp: float
    p_coll: float
    slopes_mp: dict[str, float]
    slopes_coll: dict[str, float]
    left: str
    right: str
    kind: str
    dbeta_mp: float           # Re(beta2 - beta1) L at the crossing
    dbeta_slopes: dict[str, float]  # its slope along each family's branch
    twist_closed: float       # the closed form of asymptotics.crossing_closed_form
    p_closed: float
    resonance_gap_mp: float   # max_k |beta_k L - (n -+ 1) pi| at the mpmath crossing

    @property
    def offset(self) -> float:
        """(Omega_n - n pi) / pi from the characteristic equation."""
        return self.twist_mp / math.pi - self.n


@dataclass
class StraightRodEvidence:
    grid: NDArray[np.float64]
    p: dict[float, NDArray[np.float64]]
    family: dict[float, NDArray[np.str_]]
    maxima: list[MaximumRecord]
    spot: list[dict[str, float]]
    zero_twist: list[dict[str, float]]
    isotropic: dict[str, float]
    limit: list[dict[str, float]]
    windows: list[dict[str, float]]
    modes: list[dict[str, object]]
    planarity_decay: list[dict[str, float]]
    #: collocation non-planarity of the critical mode over the twist range, per nu
    planarity_range: dict[float, dict[str, NDArray[np.float64]]] = field(default_factory=dict)
    #: the characteristic polynomial of inst1 in beta (sympy) and whether it is even in beta
    even_order: dict[str, object] = field(default_factory=dict)
    #: the characteristic determinant at the critical load and just below it (uniqueness)
    uniqueness: list[dict[str, float]] = field(default_factory=list)
    #: the range of p* over Figure 1's digitised points (the printed definition of p*)
    figure1_range: dict[str, float] = field(default_factory=dict)
    ritz: dict[str, list[float]] = field(default_factory=dict)
    derivation: dict[str, object] = field(default_factory=dict)
    timings: dict[str, float] = field(default_factory=dict)

    def maxima_for(self, nu: float) -> list[MaximumRecord]:
        return sorted((m for m in self.maxima if m.nu == nu), key=lambda m: m.n)


def _maximum(nu: float, n: int) -> MaximumRecord:
    """One maximum three ways. The mpmath Newton starts from the closed form (a starting guess
    only: it solves D_sym = D_anti = 0 itself and the sign scans verify the root is the lowest
    of both families; tests/test_asymptotics.py also starts it from (n pi, p*(n pi)))."""
    closed = crossing_closed_form(n, nu)
    mpc = family_crossing(closed.twist, nu, p_guess=closed.p_star, dps=DPS)
    col = collocation_crossing(n * math.pi, nu)
    wav = crossing_wavenumbers(mpc, nu, dps=DPS)
    return MaximumRecord(
        nu=nu, n=n, twist_mp=float(mpc.twist), twist_coll=col.twist, p_mp=float(mpc.p_star),
        p_coll=col.p_star, slopes_mp={k: float(v) for k, v in mpc.slopes.items()},
        slopes_coll=col.slopes, left=mpc.left, right=mpc.right, kind=mpc.kind,
        dbeta_mp=wav.difference, dbeta_slopes=wav.slopes, twist_closed=closed.twist,
        p_closed=closed.p_star, resonance_gap_mp=wav.resonance_gap)


def _limit_row(nu: float, j: int) -> dict[str, float]:
    om = math.pi / 2 + 2 * math.pi * j
    p_mp = float(characteristic_critical_load(om, nu, dps=DPS).p_star)
    p_coll = float(critical_load(om, nu, tol=TOL))
    return {"nu": nu, "twist": om, "p_mp": p_mp, "p_coll": p_coll,
            "limit": large_twist_limit(nu),
            **{f"err{k}": p_mp - large_twist_expansion(om, nu, order=k) for k in (0, 2, 3, 4)}}


def _window_row(nu: float) -> dict[str, float]:
    w = imaginary_beta1_window(nu)
    row: dict[str, float] = {"nu": nu, "omega_a": w.omega_a, "omega_b": w.omega_b,
                             "p_a": w.p_a, "p_b": w.p_b}
    for end, om, p_closed in (("a", w.omega_a, w.p_a), ("b", w.omega_b, w.p_b)):
        r = characteristic_critical_load(om, nu, dps=DPS)
        row[f"p_{end}_mp"] = float(r.p_star)
        row[f"p_{end}_coll"] = float(critical_load(om, nu, tol=TOL))
        row[f"family_{end}"] = r.family
        row[f"dev_{end}"] = max(abs(float(r.p_star) - p_closed),
                                abs(row[f"p_{end}_coll"] - p_closed))
    mid = 0.5 * (w.omega_a + w.omega_b)
    r = characteristic_critical_load(mid, nu, dps=DPS)
    row["x_minus_mid_mp"] = float(r.x_minus)
    b1, _ = critical_wavenumbers(critical_load(mid, nu, tol=TOL), mid, nu)
    row["x_minus_mid_coll"] = float((b1 * b1).real)
    return row


def _mode_row(twist: float, nu: float) -> dict[str, object]:
    col = buckling_mode(twist, nu, tol=TOL, points=161)
    root = characteristic_critical_load(twist, nu, dps=DPS)
    cm = characteristic_mode(root, twist, nu, points=161, dps=DPS)
    xc = np.column_stack([col.x1, col.x2])
    xm = np.column_stack([cm.x1, cm.x2])
    scale = float(np.sum(xc * xm) / np.sum(xc * xc))
    return {"twist": twist, "nu": nu, "family": root.family, "s": col.s,
            "x1": col.x1 * scale, "x2": col.x2 * scale,
            "x1_mp": np.array(cm.x1), "x2_mp": np.array(cm.x2),
            "planarity_coll": non_planarity(col.x1, col.x2),
            "planarity_mp": non_planarity(cm.x1, cm.x2),
            "omega2_over_omega1": float(np.max(np.abs(col.omega2)) / np.max(np.abs(col.omega1))),
            "shape_mismatch": float(np.max(np.abs(xc * scale - xm)))}


def compute_evidence(progress: Callable[[str], None] = lambda _m: None) -> StraightRodEvidence:
    """Everything the claims need: dense collocation curves and the mpmath decisive numbers."""
    t0 = time.perf_counter()
    timings: dict[str, float] = {}
    grid = np.linspace(0.0, TWIST_MAX, GRID_POINTS)
    p, fam = {}, {}
    for nu in NUS:
        res = critical_load(grid, nu, tol=CURVE_TOL, full_output=True)
        p[nu], fam[nu] = res.p_star, res.family
    timings["collocation curves"] = time.perf_counter() - t0
    progress(f"collocation p* on {GRID_POINTS} twists x {len(NUS)} nu in "
             f"{timings['collocation curves']:.1f} s")

    t1 = time.perf_counter()
    cases = [(nu, n) for nu in NUS for n in MAXIMA_N]
    cases += [(DETAIL_NU, n) for n in DETAIL_N if n not in MAXIMA_N]
    maxima = [_maximum(nu, n) for nu, n in cases]
    timings["family crossings"] = time.perf_counter() - t1
    progress(f"{len(maxima)} family crossings (mpmath 2-D Newton + collocation Brent) in "
             f"{timings['family crossings']:.1f} s")

    t2 = time.perf_counter()
    spot = []
    for nu in NUS:
        for om in SPOT_TWISTS:
            spot.append({"nu": nu, "twist": om,
                         "p_mp": float(characteristic_critical_load(om, nu, dps=DPS).p_star),
                         "p_coll": float(critical_load(om, nu, tol=TOL))})
    zero = [{"nu": nu, "p_coll": float(critical_load(0.0, nu, tol=TOL)),
             "det_sym_euler": abs(characteristic_determinant("symmetric", 1.0, 0.0, nu, DPS))}
            for nu in NUS]
    iso_grid = np.linspace(0.0, 40.0, 81)
    det_iso = max(abs(characteristic_determinant("symmetric", 1.0, float(om), 1.0, DPS))
                  for om in iso_grid)
    isotropic = {"max_dev_coll": float(np.max(np.abs(critical_load(iso_grid, 1.0, tol=TOL)
                                                     - 1.0))),
                 "max_det_mp": float(det_iso), "points": float(iso_grid.size),
                 "twist_max": float(iso_grid[-1])}
    limit = [_limit_row(nu, j) for nu in NUS for j in LIMIT_J]
    windows = [_window_row(nu) for nu in NUS]
    modes = [_mode_row(om, nu) for om, nu in MODE_CASES]
    euler = buckling_mode(0.0, MODE_CASES[0][1], tol=TOL, points=161)
    e_scale = float(euler.x1[np.argmax(np.abs(euler.x1))])
    modes.insert(0, {"twist": 0.0, "nu": MODE_CASES[0][1], "family": euler.family,
                     "s": euler.s, "x1": euler.x1 / e_scale, "x2": euler.x2 / e_scale,
                     "planarity_coll": non_planarity(euler.x1, euler.x2),
                     "omega2_over_omega1": float(np.max(np.abs(euler.omega2))
                                                 / np.max(np.abs(euler.omega1))),
                     "shape_mismatch": float(np.max(np.abs(
                         euler.x1 / e_scale - np.sin(np.pi * euler.s))))})
    planarity_decay = []
    for om in PLANARITY_TWISTS:  # both solvers (the collocation one also spans the range below)
        root = characteristic_critical_load(om, DETAIL_NU, dps=DPS)
        cm = characteristic_mode(root, om, DETAIL_NU, points=121, dps=20)
        col = buckling_mode(om, DETAIL_NU, tol=TOL, points=121)
        planarity_decay.append({"twist": om, "planarity_mp": non_planarity(cm.x1, cm.x2),
                                "planarity_coll": non_planarity(col.x1, col.x2)})
    planarity_range = {nu: planarity_over_range(nu) for nu in NUS}
    uniqueness = [uniqueness_row(om, nu) for om, nu in ((0.0, DETAIL_NU), *MODE_CASES)]
    timings["spot checks, limit, windows, modes"] = time.perf_counter() - t2
    progress(f"spot checks, large-twist loads, windows and modes in "
             f"{timings['spot checks, limit, windows, modes']:.1f} s")
    t3 = time.perf_counter()
    ritz = ritz_values(spot, limit, maxima)
    timings["Rayleigh-Ritz (energy)"] = time.perf_counter() - t3
    t4 = time.perf_counter()
    derivation = run_derivations()
    timings["sympy derivations"] = time.perf_counter() - t4
    progress(f"Rayleigh-Ritz values and the sympy derivations in "
             f"{timings['Rayleigh-Ritz (energy)'] + timings['sympy derivations']:.1f} s")
    return StraightRodEvidence(grid=grid, p=p, family=fam, maxima=maxima, spot=spot,
                               zero_twist=zero, isotropic=isotropic, limit=limit,
                               windows=windows, modes=modes,
                               planarity_decay=planarity_decay,
                               planarity_range=planarity_range, even_order=even_order(),
                               uniqueness=uniqueness, figure1_range=figure1_range(), ritz=ritz,
                               derivation=derivation, timings=timings)


def ritz_values(spot: list[dict[str, float]], limit: list[dict[str, float]],
                maxima: list[MaximumRecord]) -> dict[str, list[float]]:
    """p* by Rayleigh-Ritz on the lab-frame energy (no Eq. inst1) at the spot, large-twist and
    maximum points, each relative to the mpmath characteristic equation."""
    out = {}
    for key, pts in (("spot", [(r["twist"], r["nu"], r["p_mp"]) for r in spot]),
                     ("limit", [(r["twist"], r["nu"], r["p_mp"]) for r in limit]),
                     ("maxima", [(m.twist_mp, m.nu, m.p_mp) for m in maxima])):
        tw, nv, ref = (np.array(v) for v in zip(*pts, strict=True))
        out[key] = list(np.abs(critical_load(tw, nv, tol=TOL, method="ritz") / ref - 1))
    return out


def planarity_over_range(nu: float) -> dict[str, NDArray[np.float64]]:
    """Non-planarity of the collocation buckling mode at PLANARITY_RANGE_POINTS twists
    log-spaced over [PLANARITY_RANGE_MIN, TWIST_MAX]."""
    twists = np.geomspace(PLANARITY_RANGE_MIN, TWIST_MAX, PLANARITY_RANGE_POINTS)
    values = []
    for om in twists:
        m = buckling_mode(float(om), nu, tol=CURVE_TOL, points=121)
        values.append(non_planarity(m.x1, m.x2))
    return {"twist": twists, "non_planarity": np.array(values)}


def uniqueness_row(twist: float, nu: float) -> dict[str, float]:
    """|D| of the critical family's characteristic determinant at the mpmath critical load and
    at 99 % of it: D = 0 means a non-trivial solution beside the trivial one (same boundary
    conditions), i.e. the boundary-value problem has more than one solution."""
    root = characteristic_critical_load(twist, nu, dps=DPS)
    p = float(root.p_star)
    at = abs(characteristic_determinant(root.family, p, twist, nu, DPS))
    below = abs(characteristic_determinant(root.family, 0.99 * p, twist, nu, DPS))
    return {"twist": twist, "nu": nu, "p_star": p, "det_at_critical": float(at),
            "det_below_critical": float(below)}


def even_order() -> dict[str, object]:
    """sympy: substitute omega_k = c_k exp(i beta s) into Eq. inst1 (A2 = nu A1, P = lambda
    A1, omega30 = w) and expand the 2 x 2 determinant; the paper says each omega_k obeys a
    fourth-order equation with even derivatives only, i.e. the polynomial is even in beta."""
    import sympy as sp

    beta, lam, nu, w = sp.symbols("beta lambda nu omega", real=True)
    i = sp.I
    # rows: inst1 line 1 (/A1) and line 2 (/A1); columns: c1, c2
    m = sp.Matrix([[-beta**2 + lam - w**2, -2 * nu * w * i * beta],
                   [2 * w * i * beta, nu * (-beta**2) + lam - nu * w**2]])
    poly = sp.Poly(sp.expand(m.det()), beta)
    degrees = [mon[0] for mon in poly.monoms()]
    return {"polynomial": str(poly.as_expr()), "degree": int(poly.degree()),
            "even": all(d % 2 == 0 for d in degrees),
            "odd_terms": int(sum(d % 2 for d in degrees))}


def figure1_range() -> dict[str, float]:
    """Smallest and largest p* among Figure 1's digitised points (the packaged CSV)."""
    p = load_figure1()["p_star"].to_numpy()
    return {"p_min": float(p.min()), "p_max": float(p.max()), "points": float(p.size)}


def run_derivations() -> dict[str, object]:
    """Run the straight rod's sympy derivation (each step asserts); record what it proved or
    where it stopped, and the misprinted variants of inst1 against Figure 1. (The ring's
    derivation is the ring scene's.)"""
    return {"straight_rod": derivation_status("straight_rod"),
            "variants": inst1_variant_table()}


# ------------------------------------------------------------------------------------------
# derived measurements
# ------------------------------------------------------------------------------------------

def solver_agreement(ev: StraightRodEvidence) -> float:
    """Largest relative difference collocation vs characteristic equation over all checks."""
    rel = [abs(r["p_coll"] - r["p_mp"]) / r["p_mp"] for r in ev.spot + ev.limit]
    rel += [abs(m.p_coll - m.p_mp) / m.p_mp for m in ev.maxima]
    return float(max(rel))


def rises_until_first_maximum(ev: StraightRodEvidence, nu: float) -> bool:
    """p* strictly increasing on the grid from Omega = 0 up to the first crossing."""
    return increasing_up_to(ev.grid, ev.p[nu], ev.maxima_for(nu)[0].twist_mp)


def settling_twist(ev: StraightRodEvidence, nu: float, frac: float) -> float | None:
    """Smallest grid twist beyond which p_inf - p* < frac (p_inf - 1) everywhere on the grid
    (None if that does not happen within the grid)."""
    p_inf = large_twist_limit(nu)
    return settling_point(ev.grid, p_inf - ev.p[nu], frac * (p_inf - 1.0))


def critical_family_switches(ev: StraightRodEvidence, nu: float) -> NDArray[np.float64]:
    """Midpoints of the grid intervals across which the critical family changes."""
    return family_switches(ev.grid, ev.family[nu])


def maxima_agreement(ev: StraightRodEvidence) -> dict[str, float]:
    """Largest twist/load differences between the three determinations of the maxima."""
    return {
        "twist_mp_vs_closed": max(abs(m.twist_mp - m.twist_closed) for m in ev.maxima),
        "twist_coll_vs_closed": max(abs(m.twist_coll - m.twist_closed) for m in ev.maxima),
        "p_mp_vs_closed": max(abs(m.p_mp - m.p_closed) for m in ev.maxima),
        "p_coll_vs_closed": max(abs(m.p_coll - m.p_closed) for m in ev.maxima),
    }
