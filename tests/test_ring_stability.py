"""The numerical ring solver: operator against the sympy derivation, and every validation of
issue 4 against closed forms (Timoshenko & Gere rings, energy bounds, homogenisation limit).
Loads are q R^3/(E1 I1); A1 = 1, A2 = nu, A3 = e (1 + nu)."""

from __future__ import annotations

import itertools
import math
from types import ModuleType

import numpy as np
import pytest
import sympy as sp

import spectral_rod.derivations.ring_linearisation as ring_linearisation
from spectral_rod.errors import ConvergenceWarning
from spectral_rod.ring.closed_forms import (
    homogenised_limit,
    in_plane_untwisted,
    out_of_plane_untwisted,
)
from spectral_rod.ring.critical import (
    destabilisation_threshold,
    ring_critical_load,
    twist_raises_load,
)
from spectral_rod.ring.formula import ring_formula_load
from spectral_rod.ring.second_variation import (
    RING_LOADS,
    RingConvergenceError,
    assemble,
    frequency_families,
    rigid_body_constraints,
    ring_buckling,
)


@pytest.fixture(scope="module")
def derivation() -> tuple[ModuleType, dict]:
    return ring_linearisation, ring_linearisation.derive()


def isotropic_ring(A: float, A3: float, load: str) -> float:
    """The untwisted ring of bending stiffness A (both planes): the lower closed form."""
    return min(in_plane_untwisted(A, load), out_of_plane_untwisted(A, A3))


# ---------------------------------------------------------------- the operator vs sympy

def _trig_poly(coeffs: dict[tuple[int, str], float]) -> sp.Expr:
    s = sp.Symbol("s", real=True)
    return sum((c * (sp.cos(f * s) if k == "c" else sp.sin(f * s))
                for (f, k), c in coeffs.items()), sp.Integer(0))


@pytest.mark.parametrize(("N", "seed"), [(0, 0), (1, 1), (2, 2), (3, 3)])
def test_operator_matches_sympy_derivation(derivation: tuple, N: int, seed: int) -> None:
    mod, d = derivation
    rng = np.random.default_rng(seed)
    nu, e = rng.uniform(1.0, 4.0), rng.uniform(0.3, 2.0)
    A1, A2, A3 = 1.0, nu, e * (1 + nu)
    fam = frequency_families(N, 9)[min(2, N)] if N else list(range(5))
    for load in RING_LOADS:
        K, G, basis = assemble(N, nu, e, load, fam)
        x = rng.normal(size=basis.size)
        fields = {name: {} for name in ("y_phi", "y_z", "alpha")}
        for (fld, f, kind), c in zip(basis.labels, x, strict=True):
            fields[fld][(f, kind)] = c
        subs = {mod.y_phi: _trig_poly(fields["y_phi"]), mod.y_z: _trig_poly(fields["y_z"]),
                mod.alpha: _trig_poly(fields["alpha"])}
        params = {mod.R: 1, mod.A1: A1, mod.A2: A2, mod.A3: A3, mod.N: N}
        s = sp.Symbol("s", real=True)
        pts = np.arange(256) * (2 * np.pi / 256)
        for dens, mat in ((d["K"], K), (d[f"G_{load}"], G)):
            expr = dens.subs(params).subs(subs).doit()
            f_num = sp.lambdify(s, expr, "numpy")
            integral = float(np.sum(f_num(pts)) * (2 * np.pi / 256))
            assert x @ mat @ x == pytest.approx(integral, rel=1e-11)


def test_derivation_hoop_force_and_torsions(derivation: tuple) -> None:
    mod, d = derivation
    assert sp.simplify(d["F_t"] + mod.q * mod.R) == 0
    assert sp.simplify(d["w30"] - mod.N / mod.R) == 0


# ---------------------------------------------------------------- rigid motions

def _rigid_motion(basis_labels: list, trans: np.ndarray, rot: np.ndarray) -> np.ndarray:
    """Coefficients of y = a + w x R0 (R = 1) with alpha = w . e_phi, in cylindrical fields:
    y_phi = -a_x sin + a_y cos + w_z, y_z = a_z + w_x sin - w_y cos,
    alpha = -w_x sin + w_y cos (hand computation)."""
    ax, ay, az = trans
    wx, wy, wz = rot
    target = {("y_phi", 1, "s"): -ax, ("y_phi", 1, "c"): ay, ("y_phi", 0, "c"): wz,
              ("y_z", 0, "c"): az, ("y_z", 1, "s"): wx, ("y_z", 1, "c"): -wy,
              ("alpha", 1, "s"): -wx, ("alpha", 1, "c"): wy}
    return np.array([target.get(lab, 0.0) for lab in basis_labels])


def test_rigid_motions_cost_no_energy_and_are_constrained() -> None:
    rng = np.random.default_rng(5)
    for N in (0, 1, 3):
        fams = frequency_families(N, 8)
        fam = sorted({f for fm in fams for f in fm if f in (0, 1)} | {2, 3}) if N else [0, 1, 2]
        K, G, basis = assemble(N, 2.5, 0.7, "hydrostatic", fam)
        C = rigid_body_constraints(basis)
        assert np.linalg.matrix_rank(C) == 6
        for _ in range(3):
            x = _rigid_motion(basis.labels, rng.normal(size=3), rng.normal(size=3))
            assert abs(x @ K @ x) < 1e-12 * (x @ x)
            assert np.linalg.norm(C @ x) > 1e-3 * np.linalg.norm(x)
        # only frequencies 0 and 1 are constrained, whatever else the family holds
        _, _, wide = assemble(N, 2.5, 0.7, "hydrostatic", [0, 1, 2, 15, 17, 31, 33])
        Cw = rigid_body_constraints(wide)
        high = np.array([f >= 2 for _, f, _ in wide.labels])
        assert np.all(Cw[:, high] == 0.0) and np.linalg.matrix_rank(Cw) == 6
        # a rigid tilt lowers the potential of the load (x.G x > 0 means -q x.G x < 0)
        tilt = _rigid_motion(basis.labels, np.zeros(3), np.array([1.0, 0.0, 0.0]))
        assert tilt @ G @ tilt > 0.1


# ---------------------------------------------------------------- validations of issue 4

@pytest.mark.parametrize(("load", "expected"), [("hydrostatic", 3.0), ("axis", 4.5)])
def test_untwisted_in_plane(load: str, expected: float) -> None:
    r = ring_buckling(0, 1.0, load=load, subspace="in-plane")
    assert r.load == pytest.approx(expected, rel=1e-12)
    assert r.kind == "in-plane" and r.dominant_frequency == 2
    assert r.load == pytest.approx(in_plane_untwisted(1.0, load), rel=1e-12)


@pytest.mark.parametrize("e", [1.0, 1 / 2.6, 10.0, 1e3])
@pytest.mark.parametrize("load", ["hydrostatic", "axis"])
def test_untwisted_out_of_plane_timoshenko(e: float, load: str) -> None:
    A3 = 2 * e
    from spectral_rod.ring.second_variation import roundoff_floor

    tol = max(1e-12, 2 * roundoff_floor(e))  # 3.6e-12 at e = 1e3
    r = ring_buckling(0, 1.0, e_ratio=e, load=load, subspace="out-of-plane", tol=tol)
    assert r.load == pytest.approx(out_of_plane_untwisted(1.0, A3), rel=1e-12)
    assert r.kind == "out-of-plane"
    # the full solver returns the lower of in-plane and out-of-plane and names it
    full = ring_buckling(0, 1.0, e_ratio=e, load=load, tol=tol)
    assert full.load == pytest.approx(isotropic_ring(1.0, A3, load), rel=1e-12)
    assert full.kind == "out-of-plane"


@pytest.mark.parametrize(("nu", "e", "kind"), [(4.0, 1.0, "in-plane"), (1.5, 1.0, "out-of-plane"),
                                               (2.0, 0.1, "out-of-plane")])
def test_untwisted_non_circular_picks_lower_mode(nu: float, e: float, kind: str) -> None:
    A3 = e * (1 + nu)
    for load in ("hydrostatic", "axis"):
        r = ring_buckling(0, nu, e_ratio=e, load=load)
        expected = min(in_plane_untwisted(1.0, load), out_of_plane_untwisted(nu, A3))
        assert r.load == pytest.approx(expected, rel=1e-12)
        if load == "hydrostatic":
            assert r.kind == kind


@pytest.mark.parametrize("load", ["hydrostatic", "axis"])
def test_circular_section_independent_of_twist(load: str) -> None:
    for e in (1.0, 1 / 2.6):
        ref = isotropic_ring(1.0, 2 * e, load)
        for N in range(0, 7):
            assert ring_critical_load(N, 1.0, e_ratio=e, load=load) == pytest.approx(ref,
                                                                                     rel=1e-11)


def test_bracketed_by_isotropic_rings() -> None:
    rng = np.random.default_rng(11)
    for _ in range(12):
        nu, e = rng.uniform(1.05, 6.0), rng.uniform(0.2, 3.0)
        N = int(rng.integers(1, 9))
        load = ("hydrostatic", "axis")[int(rng.integers(0, 2))]
        A3 = e * (1 + nu)
        q = ring_critical_load(N, nu, e_ratio=e, load=load)
        assert isotropic_ring(1.0, A3, load) - 1e-12 <= q <= isotropic_ring(nu, A3, load) + 1e-12


@pytest.mark.parametrize("nu", [1.5, 4.0])
def test_rapid_twist_tends_to_harmonic_mean_ring(nu: float) -> None:
    """For N -> infinity the rotating stiffness homogenises (1D: harmonic mean of the rotating
    tensor, isotropic 2 A1 A2/(A1 + A2)); the gap must shrink as N grows."""
    ref = homogenised_limit(nu, 1.0, "hydrostatic")
    gaps = [abs(ring_critical_load(N, nu) - ref) for N in (5, 10, 20)]
    assert gaps[0] > gaps[1] > gaps[2]
    assert gaps[2] < 2e-3 * ref
    assert gaps[1] / gaps[2] > 3.0  # at least ~1/N^2 decay


@pytest.mark.parametrize(("N", "order"), [(1, 2), (2, 1), (3, 2), (5, 2)])
def test_small_asymmetry_perturbation_theory(N: int, order: int) -> None:
    """nu = 1 + d: the twisted stiffness is Abar + Delta (cos 2 Omega ...), Abar = (A1 + A2)/2,
    Delta = d/2.  The Delta term couples frequency n to 2N - n, so for the n = 2 mode it shifts
    q at first order only at the resonance N = 2, otherwise at second order (hand analysis):
    q - q_iso(Abar) = O(d^order)."""
    errs = []
    for d in (0.04, 0.02, 0.01):
        nu = 1 + d
        errs.append(ring_critical_load(N, nu) - isotropic_ring((1 + nu) / 2, 1 + nu,
                                                               "hydrostatic"))
    ratios = [errs[0] / errs[1], errs[1] / errs[2]]
    assert all(abs(r - 2**order) < 0.15 * 2**order for r in ratios)


@pytest.mark.filterwarnings("ignore:ring_buckling at the fixed truncation")
@pytest.mark.parametrize(("N", "nu"), [(1, 4.0), (2, 2.0), (3, 4.0), (6, 1.5)])
def test_spectral_convergence(N: int, nu: float) -> None:
    ref = ring_buckling(N, nu, max_frequency=20 * N + 40).load
    Ms = [2 * N + 2 * k for k in range(1, 12)]
    errs = [ring_buckling(N, nu, max_frequency=M).load - ref for M in Ms]
    # Rayleigh-Ritz: upper bounds, decreasing with the basis
    assert all(err >= -1e-12 * ref for err in errs)
    assert all(b <= a + 1e-12 * ref for a, b in itertools.pairwise(errs))
    # ten digits with a modest number of modes (the tail of the list)
    assert errs[-1] < 1e-10 * ref
    r = ring_buckling(N, nu)
    assert r.converged and r.rel_change <= 1e-12 and r.max_frequency <= 6 * N + 20
    assert r.load == pytest.approx(ref, rel=1e-12)


def test_no_eigenvalue_at_nonpositive_load_and_positive_where_crit2_is_negative() -> None:
    for N in range(0, 11):
        for nu in (1.3, 4.0):
            for load in ("hydrostatic", "axis"):
                r = ring_buckling(N, nu, load=load)
                assert r.min_load_over_q >= -1e-12
                assert 0 < r.load < math.inf
    assert ring_formula_load(10, 4.0) < 0 < ring_critical_load(10, 4.0)


def test_mode_kinds_and_shape() -> None:
    r = ring_buckling(2, 2.0)
    assert r.kind == "coupled" and 0 < r.in_plane_fraction < 1
    m = r.mode()
    assert set(m) == {"s", "y_r", "y_phi", "y_z", "alpha"}
    assert np.max(np.abs(m["y_phi"])) > 0 and np.max(np.abs(m["y_z"])) > 0
    # the rigid-body constraints hold for the mode: int y_z ds = 0 and int y_phi ds = 0
    assert abs(np.mean(m["y_z"])) < 1e-12 and abs(np.mean(m["y_phi"])) < 1e-12
    assert ring_buckling(0, 4.0).kind == "in-plane"
    assert ring_buckling(0, 1.0).kind == "out-of-plane"


def test_not_converged_is_flagged(monkeypatch: pytest.MonkeyPatch) -> None:
    import spectral_rod.ring.second_variation as rs

    monkeypatch.setattr(rs, "_truncations", lambda N, M: [2 * N + 2, 2 * N + 4])  # too coarse
    with pytest.raises(RingConvergenceError, match="not converged"):
        rs.ring_buckling(3, 4.0)
    r = rs.ring_buckling(3, 4.0, raise_on_failure=False)
    assert not r.converged and r.rel_change > r.tol


@pytest.mark.parametrize(("kwargs", "exc", "word"), [
    ({"N": -2}, ValueError, "N"),
    ({"N": 1.5}, ValueError, "N"),
    ({"N": None}, TypeError, "N"),
    ({"N": 1000}, ValueError, "N"),
    ({"nu": 0.99}, ValueError, "nu"),
    ({"e_ratio": 0.0}, ValueError, "e_ratio"),
    ({"load": "pressure"}, ValueError, "load"),
    ({"load": 3}, TypeError, "load"),
    ({"subspace": "radial"}, ValueError, "subspace"),
    ({"tol": 0.5}, ValueError, "tol"),
    ({"max_frequency": 2}, ValueError, "max_frequency"),
])
def test_solver_bad_input(kwargs: dict, exc: type[Exception], word: str) -> None:
    args = {"N": 2, "nu": 2.0, **kwargs}
    N, nu = args.pop("N"), args.pop("nu")
    with pytest.raises(exc, match=word):
        ring_buckling(N, nu, **args)
    if set(kwargs) <= {"N", "nu", "e_ratio", "load"}:
        with pytest.raises(exc, match=word):
            ring_critical_load(N, nu, **args)


# ---------------------------------------------------------------- the destabilisation threshold

def _munder_gain(nu: float, twists: tuple[int, ...]) -> float:
    """max over N > 0 of q(N)/q(0) - 1 by the other formulation (Eqs. Munder), typed here."""
    q = {N: ring_critical_load(N, nu, method="munder") for N in twists}
    return max(q[N] for N in twists if N > 0) / q[0] - 1


def test_destabilisation_threshold_is_where_munder_changes_sign():
    twists = (0, 1, 2, 3)
    nu_star = destabilisation_threshold(1.0, "hydrostatic", [2.0, 4.0], twists=twists,
                                        xtol=1e-6)
    assert 2.0 < nu_star < 4.0
    assert _munder_gain(0.99 * nu_star, twists) < 0 < _munder_gain(1.01 * nu_star, twists)


def test_destabilisation_threshold_from_known_loads_and_without_crossing():
    twists, grid = (0, 1), [2.0, 4.0]
    loads = [[ring_critical_load(N, nu) for N in twists] for nu in grid]
    solved = destabilisation_threshold(1.0, "hydrostatic", grid, twists=twists)
    assert destabilisation_threshold(1.0, "hydrostatic", grid, twists=twists,
                                     loads=loads) == solved
    # under the axis-directed load twist N = 1 lowers q_cr on the whole grid
    assert math.isnan(destabilisation_threshold(1.0, "axis", grid, twists=twists))


def test_twist_raises_load_is_q_cr_n_against_q_cr_0_to_round_off() -> None:
    q0 = 3.0
    assert twist_raises_load(q0, q0) and twist_raises_load(q0 * (1 - 1e-12), q0)  # a tie
    assert not twist_raises_load(q0 * (1 - 1e-6), q0)
    assert twist_raises_load(np.array([2.0, q0, 4.0]), q0).tolist() == [False, True, True]
    # the circular ring: twist cannot change q_cr, and the solves agree to round-off
    assert twist_raises_load(ring_critical_load(3, 1.0), ring_critical_load(0, 1.0))
    with pytest.raises(ValueError, match="q_untwisted"):
        twist_raises_load(1.0, 0.0)
    with pytest.raises(TypeError, match="q_twisted"):
        twist_raises_load("1", 1.0)


def test_destabilisation_threshold_counts_a_round_off_tie_as_raised() -> None:
    """The scan brackets nu* with twist_raises_load (the scene's predicate): a twisted load
    equal to q_cr(0) to round-off is raised, both at the upper end (nu* is that end) and at the
    lower end (no interval from lowered to raised)."""
    twists, grid, tie = (0, 1), [2.0, 4.0], 3.0 * (1 - 1e-12)
    assert destabilisation_threshold(1.0, "hydrostatic", grid, twists=twists,
                                     loads=[[3.0, 2.5], [3.0, tie]]) == 4.0
    assert math.isnan(destabilisation_threshold(1.0, "hydrostatic", grid, twists=twists,
                                                loads=[[3.0, tie], [3.0, 3.5]]))


@pytest.mark.parametrize(("kwargs", "exc", "name"), [
    ({"nus": [4.0, 2.0]}, ValueError, "nus"), ({"nus": [2.0]}, ValueError, "nus"),
    ({"nus": [0.5, 2.0]}, ValueError, "nus"), ({"twists": (1, 2)}, ValueError, "twists"),
    ({"twists": (0, 1.5)}, ValueError, "twists"), ({"twists": 3}, TypeError, "twists"),
    ({"loads": [[1.0, 2.0]]}, ValueError, "loads"), ({"xtol": 0.0}, ValueError, "xtol"),
    ({"method": "energy"}, ValueError, "method"), ({"load": "gravity"}, ValueError, "load"),
])
def test_destabilisation_threshold_validates(kwargs, exc, name):
    args = {"e_ratio": 1.0, "load": "hydrostatic", "nus": [2.0, 4.0], "twists": (0, 1),
            **kwargs}
    with pytest.raises(exc, match=name):
        destabilisation_threshold(args.pop("e_ratio"), args.pop("load"), args.pop("nus"),
                                  **args)


def test_destabilisation_threshold_checks_twists_against_the_chosen_method() -> None:
    from spectral_rod import destabilisation_threshold
    from spectral_rod.ring.munder import MAX_TWIST

    with pytest.raises(ValueError, match=rf"\[0, {MAX_TWIST}\]"):  # before any solve
        destabilisation_threshold(1.0, "hydrostatic", [1.5, 2.0], twists=[0, MAX_TWIST + 1],
                                  method="munder")


def test_fixed_truncation_warns_and_is_flagged() -> None:
    """A fixed max_frequency refines nothing: the load comes with converged=False and a
    ConvergenceWarning, and it is an upper bound of the converged load (M = 4 is 1.8 % high at
    N = 3, nu = 1.5)."""
    with pytest.warns(ConvergenceWarning, match="max_frequency=4"):
        r = ring_buckling(3, 1.5, max_frequency=4)
    ref = ring_buckling(3, 1.5)
    assert not r.converged and math.isnan(r.rel_change) and ref.converged
    assert r.load > ref.load * (1 + 1e-3)


@pytest.mark.parametrize("e", [1e-6, 1e-4, 1e4, 1e6])
def test_extreme_torsional_stiffness_meets_only_its_roundoff_floor(e: float) -> None:
    """nu = 1 (any N): q = min(3, 9/(4 + 1/(2 e))) in closed form. At extreme e the error
    (2.75e-10 at e = 1e6, 4.3e-11 at 1e-6) exceeds the default tol while successive
    truncations agree to ~1e-15: before 2026-12-04 this was reported converged. Now the load
    is within roundoff_floor(e) of the closed form, and a tol below that floor is not met."""
    from spectral_rod.ring.second_variation import RingConvergenceError, roundoff_floor

    exact = min(in_plane_untwisted(1.0, "hydrostatic"), out_of_plane_untwisted(1.0, 2.0 * e))
    floor = roundoff_floor(e)
    for N in (0, 2):
        r = ring_buckling(N, 1.0, e_ratio=e, tol=2 * floor)
        assert r.converged and abs(r.load / exact - 1) <= floor
    assert floor > 1e-12
    with pytest.raises(RingConvergenceError, match="round-off floor"):
        ring_buckling(0, 1.0, e_ratio=e)
    unflagged = ring_buckling(0, 1.0, e_ratio=e, raise_on_failure=False)
    assert not unflagged.converged and unflagged.load == pytest.approx(exact, rel=floor)


def test_an_unreachable_tol_is_refused_before_solving() -> None:
    """The Munder form at N = 20, nu = 1e4, e = 1e-6 ran for minutes before ending unconverged
    (found 2026-12-04); its tol 1e-10 is below the floor 1.8e-9, so it is refused at once."""
    from spectral_rod.ring.munder import munder_buckling
    from spectral_rod.ring.second_variation import RingConvergenceError

    with pytest.raises(RingConvergenceError, match="below the round-off floor"):
        munder_buckling(20, 1e4, e_ratio=1e-6)
    with pytest.raises(RingConvergenceError, match="below the round-off floor"):
        ring_buckling(20, 1e4, e_ratio=1e-6)


def test_stiff_torsion_corner_is_refused() -> None:
    """ring_critical_load(60, 1e4, e_ratio=1e6, tol=1e-8): every argument in range, but the
    load scatters by ~1e-6 between truncations (0.9 eps e (1 + nu)/2), so the refinement ran
    27-113 s and failed; now it is refused at once with the reachable range, and a tol in that
    range converges (checked at N = 5, where the same floor applies and the solve is fast)."""
    import time

    from spectral_rod.ring.second_variation import RingConvergenceError, roundoff_floor

    t = time.perf_counter()
    with pytest.raises(RingConvergenceError, match=r"ask for tol in \["):
        ring_critical_load(60, 1e4, e_ratio=1e6, tol=1e-8)
    assert time.perf_counter() - t < 5.0  # refused before any solve (generous on a busy host)
    floor = roundoff_floor(1e6, 1e4, 5)
    assert floor > 1e-8 and roundoff_floor(1e6, 1e4, 0) < 1e-8  # the twist's coupling term
    r = ring_buckling(5, 1e4, e_ratio=1e6, tol=4 * floor)
    assert r.converged
    # the corner's neighbours keep the default tol: e = 1, nu = 1e4, and e = 1e6, nu = 1
    assert roundoff_floor(1.0, 1e4, 5) < 1e-12 and roundoff_floor(1e6, 1.0, 5) < 1e-8
