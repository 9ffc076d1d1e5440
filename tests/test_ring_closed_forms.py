"""The ring's closed forms (:mod:`spectral_rod.ring.closed_forms`) against classical hand values
and against a scan over the wavenumber n (the minimum is at n = 2).  The solvers are tested
against these functions in test_ring_stability.py and test_ring_second_formulation.py."""

from __future__ import annotations

import numpy as np
import pytest

from spectral_rod.ring.closed_forms import (
    homogenised_limit,
    in_plane_untwisted,
    out_of_plane_supremum,
    out_of_plane_untwisted,
)

NS = np.arange(2, 400, dtype=float)


# ---------------------------------------------------------------- classical hand values

@pytest.mark.parametrize(("A", "load", "expected"), [
    (1.0, "hydrostatic", 3.0),    # ring under pressure: q_cr = 3 EI/R^3 (Timoshenko & Gere)
    (1.0, "axis", 4.5),           # force directed to the centre: 4.5 EI/R^3 (Timoshenko & Gere)
    (2.0, "hydrostatic", 6.0),    # linear in EI
    (0.5, "axis", 2.25),
])
def test_in_plane_hand_values(A: float, load: str, expected: float) -> None:
    assert in_plane_untwisted(A, load) == expected


@pytest.mark.parametrize(("A", "A3", "expected"), [
    (1.0, 2.0, 2.0),        # circular rod, E2 = E1: 9/(4 + 1/2) = 2
    (1.0, 1.0, 1.8),        # A3 = A: 9/5
    (2.0, 0.5, 18 / 8),     # A/A3 = 4: 18/8
    (1.0, 1e12, 2.25),      # torsionally rigid: the supremum 9/4
    (1.0, 1e-300, 9e-300),  # torsionally soft: 9 A3 (A/A3 overflowed to 0.0 before 2026-12-04)
    (1e12, 1e-300, 9e-300),
])
def test_out_of_plane_hand_values(A: float, A3: float, expected: float) -> None:
    assert out_of_plane_untwisted(A, A3) == pytest.approx(expected, rel=1e-12)


def test_out_of_plane_supremum_hand_value() -> None:
    assert out_of_plane_supremum(1.0) == 2.25
    assert out_of_plane_supremum(4.0) == 9.0


@pytest.mark.parametrize(("nu", "e", "load", "expected"), [
    (1.0, 1.0, "hydrostatic", 2.0),       # harmonic mean 1: the untwisted circular ring
    (3.0, 1.0, "hydrostatic", 108 / 35),  # A_h = 3/2, A3 = 4: 13.5/(4 + 3/8), below 4.5
    (3.0, 1e-3, "axis", 13.5 / (4 + 375)),  # A3 = 0.004: 1.5 * 9/(4 + 375)
    (3.0, 1e3, "axis", 13.5 / (4 + 1.5 / 4e3)),  # stiff torsion: out of plane, below 6.75
])
def test_homogenised_limit_hand_values(nu: float, e: float, load: str, expected: float) -> None:
    assert homogenised_limit(nu, e, load) == pytest.approx(expected, rel=1e-12)


# ---------------------------------------------------------------- the minimum over n is at n = 2

def test_minimum_over_n_is_n_equals_2() -> None:
    rng = np.random.default_rng(7)
    for A, A3 in [(1.0, 1e-6), (1.0, 1e12), (1e-6, 1e6), *rng.uniform(0.01, 100.0, (20, 2))]:
        m = NS**2
        for load, vals in (("hydrostatic", A * (m - 1)), ("axis", A * (m - 1) ** 2 / (m - 2))):
            assert np.argmin(vals) == 0 and np.all(np.diff(vals) > 0)
            assert in_plane_untwisted(A, load) == pytest.approx(vals.min(), rel=1e-14)
        out = A * (m - 1) ** 2 / (m + A / A3)
        assert np.argmin(out) == 0 and np.all(np.diff(out) > 0)
        assert out_of_plane_untwisted(A, A3) == pytest.approx(out.min(), rel=1e-14)
        sup = A * (m - 1) ** 2 / m
        assert out_of_plane_supremum(A) == pytest.approx(sup.min(), rel=1e-14)
        assert out_of_plane_untwisted(A, A3) < out_of_plane_supremum(A)


@pytest.mark.parametrize(("fn", "args", "exc", "word"), [
    (in_plane_untwisted, (0.0, "axis"), ValueError, "A"),
    (in_plane_untwisted, (1.0, "pressure"), ValueError, "load"),
    (out_of_plane_untwisted, (1.0, -1.0), ValueError, "A3"),
    (homogenised_limit, (0.5, 1.0, "axis"), ValueError, "nu"),
    (homogenised_limit, (2.0, 0.0, "axis"), ValueError, "e_ratio"),
    (homogenised_limit, (2.0, 1.0, 3), TypeError, "load"),
])
def test_bad_input(fn, args: tuple, exc: type[Exception], word: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(exc, match=word):
        fn(*args)
