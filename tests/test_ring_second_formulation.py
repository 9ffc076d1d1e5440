"""The second ring formulation (:mod:`spectral_rod.ring.munder`): Eq. ``Munder`` linearised
numerically, against closed forms independent of both formulations, against the energy
formulation (:func:`spectral_rod.ring_critical_load`), and against itself (Kirchhoff balances,
resolution, blocking, complex step).  Loads q R^3/(E1 I1); A1 = 1, A2 = nu, A3 = e (1 + nu)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import spectral_rod.ring.munder as rm
from spectral_rod import RING_LOADS, RingConvergenceError, ring_buckling
from spectral_rod.ring.closed_forms import in_plane_untwisted, out_of_plane_untwisted
from spectral_rod.ring.munder import (
    AGREEMENT_CASES,
    E_ISOTROPIC,
    MUNDER_TERMS,
    base_residual,
    block_loads,
    munder_buckling,
    munder_critical_load,
    ring_formulation_agreement,
    rotate,
)

# ---------------------------------------------------------------- closed forms


@pytest.mark.parametrize("load", ["hydrostatic", "axis"])
def test_untwisted_in_plane_closed_form(load: str) -> None:
    expected = in_plane_untwisted(1.0, load)
    # nu = 1, N = 0: the in-plane blocks give 3 / 4.5
    bl, _ = block_loads(0, 1.0, 1.0, load, 10)
    assert min(b.load for b in bl if b.kind == "in-plane") == pytest.approx(expected, rel=1e-12)
    # nu = 4: the in-plane mode is the lowest of all
    assert munder_critical_load(0, 4.0, load=load) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("e", [1.0, E_ISOTROPIC, 10.0])
@pytest.mark.parametrize("load", ["hydrostatic", "axis"])
def test_untwisted_out_of_plane_timoshenko_gere(e: float, load: str) -> None:
    A3 = 2.0 * e
    bl, _ = block_loads(0, 1.0, e, load, 10)
    out = min(b.load for b in bl if b.kind == "out-of-plane")
    assert out == pytest.approx(out_of_plane_untwisted(1.0, A3), rel=1e-12)
    assert not any(b.kind == "coupled" for b in bl)  # N = 0: in/out of plane decouple
    full = munder_critical_load(0, 1.0, e_ratio=e, load=load)
    assert full == pytest.approx(min(in_plane_untwisted(1.0, load),
                                     out_of_plane_untwisted(1.0, A3)), rel=1e-12)


@pytest.mark.parametrize(("N", "e", "load"), [(3, 1.0, "hydrostatic"), (5, E_ISOTROPIC, "axis")])
def test_circular_section_independent_of_twist(N: int, e: float, load: str) -> None:
    """nu = 1: the twisted frame is only a relabelling, q is the isotropic ring's."""
    ref = min(in_plane_untwisted(1.0, load), out_of_plane_untwisted(1.0, 2.0 * e))
    assert munder_critical_load(N, 1.0, e_ratio=e, load=load) == pytest.approx(ref, rel=1e-11)


# ---------------------------------------------------------------- agreement with the energy form

FAST_CASES = [(1, 1.3, 1.0, "hydrostatic"), (2, 2.0, 1.0, "axis"),
              (3, 2.0, E_ISOTROPIC, "axis")]


def _check_rows(rows: list[dict]) -> None:
    for r in rows:
        assert r["rel_diff"] <= 1e-9, r
        assert np.isfinite(r["q_munder"]) and r["q_munder"] > 0


def test_agreement_fast_cases() -> None:
    rows = ring_formulation_agreement(FAST_CASES)
    assert [(r["N"], r["load"]) for r in rows] == [(c[0], c[3]) for c in FAST_CASES]
    _check_rows(rows)


@pytest.mark.slow
def test_agreement_all_cases() -> None:
    cases = list(AGREEMENT_CASES)
    assert len(cases) >= 12
    assert {c[0] for c in cases} == set(range(9))
    assert {c[3] for c in cases} == set(RING_LOADS)
    assert {c[2] for c in cases} == {1.0, E_ISOTROPIC}
    _check_rows(ring_formulation_agreement(cases))


def test_agreement_accepts_dicts_and_short_tuples() -> None:
    rows = ring_formulation_agreement([{"N": 1, "nu": 2.0, "load": "axis"}, (0, 1.0)])
    assert rows[0]["load"] == "axis" and rows[0]["e_ratio"] == 1.0
    assert rows[1]["load"] == "hydrostatic"
    assert set(rows[0]) >= {"q_galerkin", "q_munder", "rel_diff", "max_frequency", "n_unknowns",
                            "t_galerkin", "t_munder"}


# ---------------------------------------------------------------- Eq. Munder itself

@pytest.mark.parametrize(("N", "nu", "e", "load", "M"), [(2, 2.0, 1.0, "axis", 16),
                                                         (3, 4.0, E_ISOTROPIC, "hydrostatic", 20)])
def test_munder_as_printed_equals_kirchhoff_balances(N: int, nu: float, e: float, load: str,
                                                     M: int) -> None:
    """M' + t x F = 0, F' + q = 0 with the full force as unknown (no Munder) give the same
    load: the elimination of F_u, F_v in Eq. ``Munder`` is right as printed."""
    a, wa = block_loads(N, nu, e, load, M)
    b, wb = block_loads(N, nu, e, load, M, "kirchhoff")
    qa, qb = min(x.load for x in a), min(x.load for x in b)
    assert qa == pytest.approx(qb, rel=1e-10)
    assert qa == pytest.approx(munder_critical_load(N, nu, e_ratio=e, load=load), rel=1e-10)
    assert wa < 1e-8 and wb < 1e-8  # conservative: the spectrum is real


@pytest.mark.parametrize("equations", ["munder", "kirchhoff"])
@pytest.mark.parametrize("load", ["hydrostatic", "axis"])
def test_loaded_circle_is_an_equilibrium(equations: str, load: str) -> None:
    """Hoop force F_t = -q R, no moments: the residual vanishes (section "Stability of a ring")."""
    for N, q in ((0, 1.0), (3, 2.5)):
        assert base_residual(N, 2.0, load=load, q=q, equations=equations) < 1e-12


def test_numeric_munder_lines_are_the_printed_equation() -> None:
    """ring_munder's term-by-term Eq. Munder against the sympy transcription of the printed
    equation (:func:`spectral_rod.derivations.straight_rod.munder`), lambdified, on random
    trigonometric fields (the spectral derivatives are exact for them)."""
    import sympy as sp

    from spectral_rod.derivations.straight_rod import munder, s

    prob = rm._problem(2, 2.0, 1.0, "axis", 6, "munder")  # P = 49 points: exact up to f = 24
    rng = np.random.default_rng(17)
    names = ("w1", "w2", "w3", "Mu", "Mv", "Mt", "Ft", "qu", "qv", "qt")
    fields = {n: rng.normal() + sum(rng.normal() * sp.cos(f * s) + rng.normal() * sp.sin(f * s)
                                    for f in (1, 2, 3)) for n in names}
    lines = munder(fields["Ft"], [fields[n] for n in ("w1", "w2", "w3")],
                   [fields[n] for n in ("Mu", "Mv", "Mt")],
                   q=[fields[n] for n in ("qu", "qv", "qt")])
    grid = prob.grid.s
    want = [np.broadcast_to(sp.lambdify(s, line, "numpy")(grid), grid.shape) for line in lines]
    val = {n: sp.lambdify(s, e, "numpy")(grid)[None, :] for n, e in fields.items()}
    got = rm._munder_lines(prob, (val["w1"], val["w2"], val["w3"]),
                           (val["Mu"], val["Mv"], val["Mt"]), val["Ft"],
                           (val["qu"], val["qv"], val["qt"]))
    for k, (g, w) in enumerate(zip(got, want, strict=True)):
        assert np.max(np.abs(g[0] - w)) < 1e-12 * np.max(np.abs(w)), k
    # and a flipped term is seen (the comparison is not blind)
    flipped = rm._munder_lines(rm._problem(2, 2.0, 1.0, "axis", 6, "munder", "3:w1*Ft"),
                               (val["w1"], val["w2"], val["w3"]),
                               (val["Mu"], val["Mv"], val["Mt"]), val["Ft"],
                               (val["qu"], val["qv"], val["qt"]))
    assert np.max(np.abs(flipped[2][0] - want[2])) > 1e-3 * np.max(np.abs(want[2]))


SENSITIVE_FAST = ["1:qt", "2:w2*Mv", "3:w3*w1*Mt", "4:w3*w2*Mt"]


def _flip_changes(load: str, terms: list[str]) -> dict[str, float]:
    ref = min(b.load for b in block_loads(2, 2.0, 1.0, load, 10)[0])
    return {t: abs(min(b.load for b in block_loads(2, 2.0, 1.0, load, 10, flip=t)[0]) - ref)
            / ref for t in terms}


def test_every_printed_term_matters_fast() -> None:
    """Reversing one term of Munder moves q by > 1 %: the agreement is not insensitive to it."""
    changes = _flip_changes("axis", SENSITIVE_FAST)
    assert all(c > 1e-2 for c in changes.values()), changes


@pytest.mark.slow
def test_every_printed_term_matters_all() -> None:
    changes = _flip_changes("axis", list(MUNDER_TERMS))
    assert all(c > 1e-2 for c in changes.values()), changes
    # the hydrostatic load stays normal to the deformed centreline, so q_t = 0 identically and
    # the sign of its term cannot matter; every other term does
    hyd = _flip_changes("hydrostatic", list(MUNDER_TERMS))
    assert hyd.pop("1:qt") < 1e-12
    assert all(c > 1e-2 for c in hyd.values()), hyd


def test_flip_is_validated() -> None:
    with pytest.raises(ValueError, match="flip"):
        block_loads(1, 2.0, 1.0, "axis", 8, flip="5:nothing")


# ---------------------------------------------------------------- numerics of the formulation

def test_rotation_is_exact() -> None:
    rng = np.random.default_rng(3)
    theta = rng.normal(size=(50, 3)) * 2.0
    a, b = rng.normal(size=(50, 3)), rng.normal(size=(50, 3))
    ra, rb = rotate(theta, a), rotate(theta, b)
    assert np.allclose(np.sum(ra * rb, axis=1), np.sum(a * b, axis=1), atol=1e-12)
    assert np.allclose(np.cross(ra, rb), rotate(theta, np.cross(a, b)), atol=1e-12)
    assert np.allclose(rotate(theta, theta), theta, atol=1e-12)
    # composition about one axis adds the angles
    axis = np.array([0.3, -0.4, 0.5]) / np.linalg.norm([0.3, -0.4, 0.5])
    assert np.allclose(rotate(0.7 * axis, rotate(0.9 * axis, a[0])), rotate(1.6 * axis, a[0]))


def test_complex_step_matches_finite_differences() -> None:
    """The pencil is the derivative of the real nonlinear residual (central differences)."""
    prob = rm._problem(2, 2.0, 0.7, "axis", 6, "munder")
    J0, J1 = rm.pencil(prob)
    rng = np.random.default_rng(5)
    d = rng.normal(size=prob.size)
    q, h = 1.7, 1e-5
    fd = (rm._residual((h * d)[None], prob, q) - rm._residual((-h * d)[None], prob, q)).real
    fd = fd[0] / (2 * h)
    jd = (J0 + q * J1) @ d
    assert np.max(np.abs(fd - jd)) < 1e-6 * np.max(np.abs(jd))


def test_blocks_are_the_twist_families_and_do_not_change_the_answer() -> None:
    """The measured blocks hold frequencies f = +-n (mod 2N) of one n only, and solving the
    unblocked pencil gives the same smallest load."""
    N, M = 3, 12
    bl, _ = block_loads(N, 2.0, 1.0, "hydrostatic", M)
    for b in bl:
        assert len({min(f % (2 * N), -f % (2 * N)) for f in b.frequencies}) <= 1, b
    prob = rm._problem(N, 2.0, 1.0, "hydrostatic", M, "munder")
    qs, _ = rm._block_loads(*rm.pencil(prob))
    assert qs[qs > 0][0] == pytest.approx(min(b.load for b in bl), rel=1e-9)


def test_blocks_split_only_across_a_gap() -> None:
    """The splitting rule on a pencil whose pattern is known: two O(1) 2 x 2 blocks joined only
    by entries below PATTERN_TOL are two blocks when the smallest entry above it is at least
    PATTERN_GAP times the largest below it, one block (round-off not told from couplings)
    when not."""
    J1 = -np.eye(4)

    def pencil(inner: float, stray: float) -> np.ndarray:
        J0 = np.diag([2.0, 1.5, 1.8, 1.2])
        J0[0, 1] = J0[1, 0] = J0[2, 3] = J0[3, 2] = inner  # couplings inside the blocks
        J0[0, 2] = J0[3, 1] = stray  # between the blocks: below the tolerance
        return J0

    assert sorted(len(r) for r, _ in rm.blocks(pencil(0.5, 1e-14), J1)) == [2, 2]
    assert sorted(len(r) for r, _ in rm.blocks(pencil(0.5, 0.5 * rm.PATTERN_TOL), J1)) == [2, 2]
    no_gap = pencil(0.3 * rm.PATTERN_GAP * rm.PATTERN_TOL, 0.5 * rm.PATTERN_TOL)
    assert len(rm.blocks(no_gap, J1)) == 1
    assert len(rm.blocks(pencil(0.5, 10.0 * rm.PATTERN_TOL), J1)) == 1  # a real coupling


@pytest.mark.parametrize(("N", "nu", "e", "load"), [
    (1, 1.0 + 1e-6, 1.0, "hydrostatic"),   # nearly circular: couplings ~ (nu - 1) near round-off
    (2, 2.0, 1e4, "hydrostatic"),          # torsionally very stiff
    (0, 1e4, 1e4, "axis"),                 # untwisted: in-plane, whether split or not
])
def test_edge_cases_agree_whether_split_or_not(N: int, nu: float, e: float, load: str) -> None:
    """At the edges of the parameter range the equilibrated entries come close to PATTERN_TOL
    (measured: with or without a gap depending on the library versions' round-off); blocks
    follows its rule and the load agrees with the energy formulation either way."""
    from spectral_rod.ring.second_variation import ring_buckling

    M = rm._truncations(N)[1]
    J0, J1 = rm.pencil(rm._problem(N, nu, e, load, M, "munder"))
    if not rm.pattern_has_gap(J0, J1):
        assert len(rm.blocks(J0, J1)) == 1
    tol = max(1e-10, 2 * rm.roundoff_floor(e))  # e = 1e4: a floor of 1.8e-11
    ref = ring_buckling(N, nu, e_ratio=e, load=load, tol=tol)
    got = rm.munder_buckling(N, nu, e_ratio=e, load=load, tol=tol)
    assert got.load == pytest.approx(ref.load, rel=2 * tol)
    assert got.kind == ref.kind  # an unsplit pencil's kind from its mode, not its fields


def test_gap_in_the_pattern_on_the_agreement_cases() -> None:
    """Round-off and couplings are PATTERN_GAP apart on the cases the ledger compares, so
    their pencils are split (a few cases, first truncation)."""
    for N, nu, e, load in AGREEMENT_CASES[::4]:
        prob = rm._problem(N, nu, e, load, rm._truncations(N)[0], "munder")
        assert len(rm.blocks(*rm.pencil(prob))) > 1, (N, nu, e, load)


def test_spectral_convergence_with_resolution() -> None:
    N, nu = 3, 4.0
    ref = min(b.load for b in block_loads(N, nu, 1.0, "hydrostatic", 40)[0])
    errs = [abs(min(b.load for b in block_loads(N, nu, 1.0, "hydrostatic", M)[0]) - ref) / ref
            for M in (6, 8, 10, 14)]
    # a new member of the critical family (f = 2, 4, 8, 10, 14, ...) enters at each step
    assert errs[0] > 1e-3
    assert all(b < a / 100 for a, b in itertools.pairwise(errs))
    assert errs[-1] < 1e-12
    r = munder_buckling(N, nu)
    assert r.converged and r.rel_change <= r.tol
    assert r.load == pytest.approx(ref, rel=1e-11)


def test_not_converged_is_flagged(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(rm, "_truncations", lambda N: [2 * N + 1, 2 * N + 2])  # too coarse
    with pytest.raises(RingConvergenceError, match="not converged"):
        munder_critical_load(3, 4.0)
    r = munder_buckling(3, 4.0, raise_on_failure=False)
    assert not r.converged and r.rel_change > r.tol


def test_non_real_spectrum_is_flagged(monkeypatch: pytest.MonkeyPatch) -> None:
    real = rm.block_loads
    monkeypatch.setattr(rm, "block_loads", lambda *a, **k: (real(*a, **k)[0], 0.5))
    with pytest.warns(rm.ConvergenceWarning, match="non-real"):
        munder_buckling(1, 2.0)


# ---------------------------------------------------------------- input validation

@pytest.mark.parametrize(("kwargs", "exc", "word"), [
    ({"N": -2}, ValueError, "N"),
    ({"N": 1.5}, ValueError, "N"),
    ({"N": None}, TypeError, "N"),
    ({"N": 31}, ValueError, "N"),
    ({"nu": 0.99}, ValueError, "nu"),
    ({"nu": [1.0, 2.0]}, TypeError, "nu"),
    ({"e_ratio": 0.0}, ValueError, "e_ratio"),
    ({"load": "pressure"}, ValueError, "load"),
    ({"load": 3}, TypeError, "load"),
    ({"tol": 0.5}, ValueError, "tol"),
    ({"tol": True}, TypeError, "tol"),
])
def test_bad_input(kwargs: dict, exc: type[Exception], word: str) -> None:
    args = {"N": 2, "nu": 2.0, **kwargs}
    N, nu = args.pop("N"), args.pop("nu")
    with pytest.raises(exc, match=word):
        munder_critical_load(N, nu, **args)
    with pytest.raises(exc, match=word):
        munder_buckling(N, nu, **args)


def test_bad_equations() -> None:
    with pytest.raises(ValueError, match="equations"):
        munder_buckling(1, 2.0, equations="euler")


@pytest.mark.parametrize(("N", "nu", "e", "load"), [
    (7, 1.0000064203933277, 0.012788199428148982, "axis"),
    (2, 1.0000037306602696, 0.18230871684465033, "axis"),
    (5, 1.0000042531195235, 0.054585947286066805, "axis"),
    (9, 1.0002134028304261, 3.2538941375505686, "hydrostatic"),
])
def test_munder_mode_kind_agrees_near_circular_sections(N, nu, e, load) -> None:
    """Random rings of 2026-12-04 (nu - 1 < 3e-4) that Munder's formulation called coupled and
    the second variation out-of-plane (in-plane share of the load work 5e-16..4e-11): the
    support threshold was applied to the equilibrated unknowns, whose column factors inflate
    the in-plane fields; on the physical amplitudes the two agree."""
    from spectral_rod.ring.second_variation import ring_buckling

    ref = ring_buckling(N, nu, e_ratio=e, load=load)
    got = rm.munder_buckling(N, nu, e_ratio=e, load=load)
    assert ref.kind == "out-of-plane"
    assert got.kind == ref.kind


@pytest.mark.parametrize(("nu", "e", "load"), [(1.0, 1e-5, "axis"), (1.0, 1e4, "hydrostatic"),
                                               (100.0, 1e-4, "hydrostatic"), (1e4, 1e-6, "axis")])
def test_mode_kind_where_the_shifted_pencil_is_exactly_singular(nu: float, e: float,
                                                                load: str) -> None:
    """Untwisted rings whose shifted pencil J0 + q (1 + 1e-13) J1 has an exactly zero pivot
    (the offset is below its round-off): the critical mode is out-of-plane at frequency 2 (the
    Timoshenko-Gere load), as the second variation says. Before 2026-12-04 the inverse
    iteration's inf/nan left no unknown in the mode and the kind came out "in-plane" with no
    frequencies (22 of 96 such grid rings)."""
    tol = 2 * rm.roundoff_floor(e)  # extreme e: the loads' round-off floor (1.8e-9 at 1e-6)
    mb = munder_buckling(0, nu, e_ratio=e, load=load, tol=tol)
    ref = ring_buckling(0, nu, e_ratio=e, load=load, tol=tol)
    assert mb.kind == ref.kind == "out-of-plane" and mb.frequencies == (2,)
    assert abs(mb.load / ref.load - 1) <= 1e-8
