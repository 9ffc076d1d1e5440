"""Every reading of the ring's "uniform radial pressure" (hydrostatic, toward the axis, toward
the centre point, dead load of fixed direction): the untwisted closed forms against the
classical values and against both solvers to 1e-12, and what each load does to the rigid
motions (the supports it needs)."""

from __future__ import annotations

import numpy as np
import pytest

from spectral_rod import RING_LOADS, ring_buckling
from spectral_rod.ring.closed_forms import (
    homogenised_limit,
    in_plane_mode_load,
    in_plane_untwisted,
    out_of_plane_mode_load,
    out_of_plane_supremum,
    out_of_plane_untwisted,
    untwisted_critical_load,
)
from spectral_rod.ring.loads import (
    RIGID_MOTIONS,
    constraint_rank_on_rigid_motions,
    rigid_motion_load_work,
    rigid_motion_stiffness,
    rigid_motion_vectors,
)
from spectral_rod.ring.munder import munder_buckling

#: Classical in-plane loads q_cr R^3/(EI), n = 2 (Simitses & Hodges, rings: 3 for pressure
#: normal to the deformed ring, 4.5 centrally directed, 4 of constant direction); "axis" is the
#: central load projected on the ring's plane, which in plane is the same force.
CLASSICAL_IN_PLANE = {"hydrostatic": 3.0, "axis": 4.5, "centre": 4.5, "dead": 4.0}


def test_every_reading_is_modelled() -> None:
    assert set(RING_LOADS) == {"hydrostatic", "axis", "centre", "dead"}


@pytest.mark.parametrize("load", RING_LOADS)
def test_in_plane_classical_values(load: str) -> None:
    assert in_plane_untwisted(1.0, load) == CLASSICAL_IN_PLANE[load]
    assert in_plane_untwisted(2.0, load) == 2.0 * CLASSICAL_IN_PLANE[load]


@pytest.mark.parametrize(("load", "A", "A3", "expected"), [
    ("hydrostatic", 1.0, 2.0, 2.0), ("axis", 1.0, 2.0, 2.0), ("dead", 1.0, 2.0, 2.0),
    ("centre", 1.0, 2.0, 12.0 / 4.5), ("centre", 1.0, 1e12, 3.0), ("dead", 1.0, 1e12, 2.25)])
def test_out_of_plane_hand_values(load: str, A: float, A3: float, expected: float) -> None:
    assert out_of_plane_untwisted(A, A3, load) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("load", RING_LOADS)
def test_the_critical_wavenumber_is_2(load: str) -> None:
    rng = np.random.default_rng(3)
    for A, A3 in [(1.0, 1e-6), (1.0, 1e12), *rng.uniform(0.01, 100.0, (10, 2))]:
        inp = [in_plane_mode_load(n, A, load) for n in range(2, 300)]
        out = [out_of_plane_mode_load(n, A, A3, load) for n in range(2, 300)]
        assert np.all(np.diff(inp) > 0) and np.all(np.diff(out) > 0)
        assert inp[0] == pytest.approx(in_plane_untwisted(A, load), rel=1e-14)
        assert out[0] == pytest.approx(out_of_plane_untwisted(A, A3, load), rel=1e-14)
        assert out[0] < out_of_plane_supremum(A, load)


#: (nu, e): the circular ring, an anisotropic section with stiff and with soft torsion
SECTIONS = [(1.0, 1.0), (3.0, 0.4), (2.0, 5.0), (40.0, 1.0)]


@pytest.mark.parametrize("load", RING_LOADS)
@pytest.mark.parametrize(("nu", "e"), SECTIONS)
def test_second_variation_reproduces_the_closed_forms(load: str, nu: float, e: float) -> None:
    inp = ring_buckling(0, nu, e_ratio=e, load=load, subspace="in-plane").load
    out = ring_buckling(0, nu, e_ratio=e, load=load, subspace="out-of-plane").load
    full = ring_buckling(0, nu, e_ratio=e, load=load).load
    assert inp == pytest.approx(in_plane_untwisted(1.0, load), rel=1e-12)
    assert out == pytest.approx(out_of_plane_untwisted(nu, e * (1.0 + nu), load), rel=1e-12)
    assert full == pytest.approx(untwisted_critical_load(nu, e, load), rel=1e-12)


@pytest.mark.parametrize("load", ["centre", "dead"])
@pytest.mark.parametrize(("nu", "e"), [(1.0, 1.0), (3.0, 0.4)])
def test_munder_reproduces_the_closed_forms(load: str, nu: float, e: float) -> None:
    # Munder uses the load as a force only (no potential): an independent check of the
    # potentials behind the closed forms
    q = munder_buckling(0, nu, e_ratio=e, load=load).load
    assert q == pytest.approx(untwisted_critical_load(nu, e, load), rel=1e-12)


@pytest.mark.parametrize("load", ["centre", "dead"])
def test_the_formulations_agree_on_twisted_rings(load: str) -> None:
    for N, nu, e in [(2, 2.0, 1.0), (3, 1.5, 0.4)]:
        a = ring_buckling(N, nu, e_ratio=e, load=load).load
        b = munder_buckling(N, nu, e_ratio=e, load=load).load
        assert a == pytest.approx(b, rel=1e-10)


@pytest.mark.parametrize("load", RING_LOADS)
def test_homogenised_limit_uses_the_load(load: str) -> None:
    a_h = 2.0 * 3.0 / 4.0
    assert homogenised_limit(3.0, 1.0, load) == pytest.approx(
        min(in_plane_untwisted(a_h, load), out_of_plane_untwisted(a_h, 4.0, load)), rel=1e-15)


# ---------------------------------------------------------------- supports

def test_rigid_motions_are_rigid_and_restrained() -> None:
    assert rigid_motion_stiffness() < 1e-14
    assert constraint_rank_on_rigid_motions() == 6
    X, _, C, _ = rigid_motion_vectors()
    assert np.linalg.matrix_rank(C[1:] @ X) == 5  # one constraint fewer: a motion drifts


#: Signs of x.G x per rigid motion (+ the load destabilises it, 0 neutral, - restoring), from
#: the finite rigid motions by hand: a tilt by beta shrinks the projected area (hydrostatic) and
#: the distances to the axis by cos beta; a spin psi turns the dead load away from the normal,
#: V = 2 pi q cos psi; the centre load's V = q int |R| grows under every translation.
EXPECTED_SIGNS = {
    "hydrostatic": (0, 0, 0, 0, 1, 1), "axis": (-1, -1, 0, 0, 1, 1),
    "centre": (-1, -1, -1, 0, 0, 0), "dead": (0, 0, 0, 1, 1, 1)}


@pytest.mark.parametrize("load", RING_LOADS)
def test_rigid_motion_load_work_signs(load: str) -> None:
    work = rigid_motion_load_work(load)
    assert list(work) == list(RIGID_MOTIONS)
    signs = tuple(int(np.sign(w)) if abs(w) > 1e-12 else 0 for w in work.values())
    assert signs == EXPECTED_SIGNS[load]


@pytest.mark.parametrize(("fn", "args", "exc", "word"), [
    (in_plane_mode_load, (1, 1.0, "dead"), ValueError, "wavenumber"),
    (out_of_plane_mode_load, (2.0, 1.0, 1.0), TypeError, "wavenumber"),
    (out_of_plane_untwisted, (1.0, 1.0, "pressure"), ValueError, "load"),
    (untwisted_critical_load, (0.5, 1.0, "dead"), ValueError, "nu"),
    (rigid_motion_load_work, ("follower",), ValueError, "load"),
])
def test_bad_input(fn, args: tuple, exc: type[Exception], word: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(exc, match=word):
        fn(*args)


# ---------------------------------------------------------------- the paper's stated method

@pytest.mark.parametrize("load", RING_LOADS)
def test_one_harmonic_galerkin_is_exact_at_N0_and_an_upper_bound(load: str) -> None:
    from spectral_rod import ring_one_harmonic_load

    for nu, e in SECTIONS:
        q, n = ring_one_harmonic_load(0, nu, e, load)
        assert n == 2 and q == pytest.approx(untwisted_critical_load(nu, e, load), rel=1e-12)
    for N, nu in [(1, 2.0), (3, 1.5)]:
        q1, _ = ring_one_harmonic_load(N, nu, 1.0, load)
        assert q1 >= ring_buckling(N, nu, load=load).load * (1 - 1e-12)


def test_coupling_strengths_and_reference_torsions() -> None:
    from spectral_rod import ring_coupling_strengths, ring_reference_torsions

    assert max(ring_coupling_strengths(0, 3.0).values()) == 0.0
    assert max(ring_coupling_strengths(2, 1.0).values()) < 1e-14
    assert min(ring_coupling_strengths(2, 3.0).values()) > 1e-3
    s, w1, w2, w3 = ring_reference_torsions(4)
    assert np.allclose(w1, np.cos(4 * s), atol=1e-12) and np.allclose(w2, -np.sin(4 * s),
                                                                      atol=1e-12)
    assert np.allclose(w3, 4.0, atol=1e-12)
    with pytest.raises(ValueError, match="N"):
        ring_coupling_strengths(-1, 2.0)
    with pytest.raises(ValueError, match="whole turns"):
        ring_reference_torsions(1.5)
