"""The batched engine's stacked inverse (block recursion without pivoting, checked, LAPACK as
the fallback) against LAPACK's pivoted inverse, on the engine's own Schur complements and on
matrices built to defeat it."""

from __future__ import annotations

import numpy as np
import pytest

from spectral_rod.rod.collocation import modal_form, shifted
from spectral_rod.rod.collocation.stacked_inverse import (
    BLOCK_ENTRIES,
    block_inverse,
    stacked_inverse,
    uses_blocks,
)


def _schur_complements(n: int, family: str, points: int, seed: int) -> np.ndarray:
    """The Schur complements S of K - SHIFT the engine inverts, at random points (twist up to
    50 and down to 1e-12, nu up to 1e4 and down to 1 + 1e-12)."""
    rng = np.random.default_rng(seed)
    om = np.concatenate([rng.uniform(0, 50, points // 2), 10 ** rng.uniform(-12, 1.7,
                                                                             points // 2)])
    nu = np.exp(rng.uniform(0, np.log(1e4), points))
    nu[:10] = 1 + 10 ** rng.uniform(-12, -3, 10)
    mf = modal_form.modal_family(n, family)
    inverse = shifted._ShiftedModal.at(mf, om, nu).schur_inv
    return np.linalg.inv(inverse)  # S itself, to the accuracy of a pivoted LU


@pytest.mark.parametrize("n", [16, 22, 40, 64, 128])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_block_inverse_of_the_engines_schur_complements_is_lapacks(n, family):
    s = _schur_complements(n, family, 60, seed=n)
    ref = np.linalg.inv(s)
    got = block_inverse(s)
    scale = np.abs(ref).max(axis=(1, 2))
    assert np.all(np.abs(got - ref).max(axis=(1, 2)) <= 1e-12 * scale)
    # the checked form takes the block result where it uses blocks (no fallback needed)
    want = got if uses_blocks(s.shape[-1], s.shape[0]) else ref
    assert np.array_equal(stacked_inverse(s), want)


def test_a_zero_or_tiny_leading_pivot_falls_back_to_lapack(monkeypatch):
    from spectral_rod.rod.collocation import stacked_inverse as module

    rng = np.random.default_rng(3)
    k = 12
    # a stack of 174 (a larger random stack holds matrices too ill-conditioned for the
    # identity check below, whichever inverse), the block recursion forced for it
    count = 174
    monkeypatch.setattr(module, "BLOCK_ENTRIES", count * k * k)
    a = rng.standard_normal((count, k, k)) + 4 * np.eye(k)
    # the recursion's leading 3 x 3 block (12 -> 6 -> 3): singular (inf/nan) and nearly
    # singular (finite, but growth ~1e13: a large error); both matrices stay well-conditioned
    a[1, :3, :3] = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [1.0, 1.0, 1.0]]
    a[3, :3, :3] = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0 + 3.1e-13], [1.0, 1.0, 1.0]]
    assert np.linalg.cond(a[1]) < 1e4 and np.linalg.cond(a[3]) < 1e4
    with np.errstate(all="ignore"):
        raw = block_inverse(a)
    assert not np.isfinite(raw[1]).all()
    assert np.abs(raw[3] @ a[3] - np.eye(k)).max() > 1e-6  # the unpivoted result is wrong
    got = stacked_inverse(a)
    assert np.allclose(got @ a, np.eye(k), atol=1e-12)
    for i in (1, 3):  # those two are LAPACK's, the others the block recursion's
        assert np.array_equal(got[i], np.linalg.inv(a[i]))
    others = np.setdiff1d(np.arange(count), [1, 3])
    assert np.array_equal(got[others], raw[others])


def test_a_singular_matrix_raises_as_lapack_does():
    a = np.tile(np.eye(12), (3, 1, 1))
    a[2, 5] = 0.0
    with pytest.raises(np.linalg.LinAlgError):
        stacked_inverse(a)


def test_small_stacks_go_to_lapack_unchanged():
    rng = np.random.default_rng(5)
    for k in (4, 10, 30):
        count = (BLOCK_ENTRIES - 1) // (k * k)
        assert not uses_blocks(k, count) and uses_blocks(k, count + 1)
        a = rng.standard_normal((count, k, k)) + 3 * np.eye(k)
        assert np.array_equal(stacked_inverse(a), np.linalg.inv(a))
