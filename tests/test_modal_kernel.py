"""The batched engine's C kernel (spectral_rod/rod/collocation/modal_kernel.py) against the numpy
iteration of the same algorithm (eigensolver._iterate), which is its reference and fallback."""

from __future__ import annotations

import numpy as np
import pytest

from spectral_rod import load_figure1
from spectral_rod.rod.collocation import eigensolver as E
from spectral_rod.rod.collocation import modal_form, modal_kernel, quotient, shifted
from spectral_rod.rod.collocation.stacked_inverse import BACKWARD_TOL
from spectral_rod.rod.families import SHIFT

needs_kernel = pytest.mark.skipif(not modal_kernel.available(),
                                  reason="the C kernel is not built here")


def _points(n: int, count: int = 300, seed: int = 5):
    rng = np.random.default_rng(seed + n)
    return rng.uniform(0.0, max(1.0, 1.8 * (n - 16)), count), rng.uniform(1.0, 100.0, count)


def _numpy_pair(mf, twist, nu, rtol, ceiling=None):
    return E._iterate(shifted._ShiftedModal.at(mf, twist, nu),
                      modal_form._start_vector(mf.lam1.size + mf.lam2.size), rtol, ceiling,
                      E.first_check(rtol, ceiling is not None), E.POWER_STEPS)


@needs_kernel
@pytest.mark.parametrize("n", [12, 22, 32, 48, 64, 96])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
@pytest.mark.parametrize("rtol", [E.POWER_RTOL, 1e-6])
def test_kernel_agrees_with_the_numpy_iteration(n, family, rtol):
    mf = modal_form.modal_family(n, family)
    twist, nu = _points(n)
    assert E.uses_kernel(mf.lam2.size if mf.schur == 2 else mf.lam1.size) == (n <= 128)
    lam, z, w, ok, above = E.lowest_eigenpair(mf, twist, nu, rtol=rtol)
    ref_lam, ref_z, ref_w, ref_ok, _ = _numpy_pair(mf, twist, nu, rtol)
    assert not above.any()
    both = ok & ref_ok
    assert both.sum() >= 0.97 * twist.size  # the two stop at the same step but for rounding
    # the modal quotient carries K's round-off, eps n^4 (module docstring): compare to it
    scale = max(rtol, 1e-16 * (n / 4.0) ** 4)
    assert np.max(np.abs(lam[both] / ref_lam[both] - 1)) <= 50 * scale
    # unit vectors (up to sign they are the same eigenvector)
    for got, ref in ((z, ref_z), (w, ref_w)):
        cos = np.abs(np.einsum("ij,ij->i", got[both], ref[both]))
        assert np.allclose(np.linalg.norm(got[both], axis=1), 1.0)
        assert np.min(cos) >= 1 - 1e-8


@pytest.mark.parametrize("n", [12, 22, 40])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_dense_and_schur_forms_of_the_numpy_iteration_agree(n, family):
    # the numpy reference applies (K - SHIFT)^{-1} as dense LAPACK inverses for a few points
    # and through the Schur complement for many: one iteration, the same eigenpairs to rounding
    mf = modal_form.modal_family(n, family)
    twist, nu = _points(n, 4)
    pt = modal_form.modal_parts(mf, twist, nu)
    start = modal_form._start_vector(mf.lam1.size + mf.lam2.size)
    first = E.first_check(E.POWER_RTOL, False)
    dense = E._iterate(shifted._DenseShifted.from_parts(pt), start, E.POWER_RTOL, None, first,
                       E.POWER_STEPS)
    schur = E._iterate(shifted._ShiftedModal.from_parts(mf, pt), start, E.POWER_RTOL, None, first,
                       E.POWER_STEPS)
    assert dense[3].all() and schur[3].all()
    scale = max(E.POWER_RTOL, 1e-16 * (n / 4.0) ** 4)  # K's round-off, as above
    assert np.max(np.abs(dense[0] / schur[0] - 1)) <= 50 * scale
    for got, ref in zip(dense[1:3], schur[1:3], strict=True):
        assert np.min(np.abs(np.einsum("ij,ij->i", got, ref))) >= 1 - 1e-8


@pytest.mark.parametrize("n", [12, 22, 40, 56])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_one_point_iteration_agrees_with_the_batched_numpy_iteration(n, family):
    # the numpy reference's one-point path (one block-diagonal inverse, whole up to
    # POINT_SCHUR_DEGREE and through the Schur complement above; the test from one Gram
    # product) against its batched iteration on the same points: the same eigenpair to rounding
    assert (n <= shifted.POINT_SCHUR_DEGREE) == (n <= 40)
    mf = modal_form.modal_family(n, family)
    pf = shifted._point_family(n, family)
    twist, nu = _points(n, 6)
    first = E.first_check(E.POWER_RTOL, False)
    ref = _numpy_pair(mf, twist, nu, E.POWER_RTOL)
    scale = max(E.POWER_RTOL, 1e-16 * (n / 4.0) ** 4)  # K's round-off, as above
    for j in range(twist.size):
        coef = E.term_coefficients(float(twist[j]), float(nu[j])).tolist()
        lam, unit, status = E._point_iterate(shifted._point_inverse(pf, coef), pf.start,
                                             E.POWER_RTOL, None, first, E.POWER_STEPS)
        assert status == modal_kernel.CONVERGED and ref[3][j]
        assert abs(lam / ref[0][j] - 1) <= 50 * scale
        for got, want in ((pf.right @ unit[0], mf.right_vectors(ref[1][j:j + 1])[0]),
                          (unit[1] @ pf.left, mf.left_vectors(ref[2][j:j + 1])[0])):
            cos = abs(got @ want) / (np.linalg.norm(got) * np.linalg.norm(want))
            assert cos >= 1 - 1e-8


@pytest.mark.parametrize("n", [24, 40, 56])
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_split_products_match_fifty_digit_sums(n, family, monkeypatch):
    # the numpy engine's extended-precision terms for a few points (exact split BLAS products,
    # eigensolver._split_terms) against 50-digit sums of the same forms, where the pencil's
    # quotient cancels to ~lambda/Omega^2, nu up to 90 (omega2 small beside omega1); and a
    # double sum misses it (the test can fail)
    import mpmath as mp

    monkeypatch.setattr(modal_kernel, "_library", lambda: None)  # the numpy engine's sums
    mf = modal_form.modal_family(n, family)
    twist, nu = np.linspace(20.5, 49.5, 5), np.linspace(1.0, 90.0, 5)
    dense = shifted._DenseShifted.from_parts(modal_form.modal_parts(mf, twist, nu))
    _, z, w, ok, _ = E._iterate(dense, modal_form._start_vector(mf.lam1.size + mf.lam2.size),
                                E.POWER_RTOL, None, E.first_check(E.POWER_RTOL, False),
                                E.POWER_STEPS)
    x, y = mf.right_vectors(z[ok]), mf.left_vectors(w[ok])
    hi, lo = quotient._split_terms(n, family, x, y)
    got = quotient._rayleigh_sums(mf.op, twist[ok], nu[ok], y, x, np.longdouble)
    double = quotient._rayleigh_sums(mf.op, twist[ok], nu[ok], y, x, np.float64)
    pieces = mf.op.pieces
    worst_double = 0.0
    with mp.workdps(50):
        for i in range(x.shape[0]):
            xi = [mp.mpf(float(v)) for v in x[i]]
            yi = [mp.mpf(float(v)) for v in y[i]]
            terms = [mp.fsum(yi[r] * mp.mpf(float(p[r, c])) * xi[c]
                             for r in range(p.shape[0]) for c in range(p.shape[1]) if p[r, c])
                     for p in pieces]
            # each term within 4 2^-bits m eps sum |y| |P_i| |x| (_split_terms' docstring: the
            # low part's three sums in double)
            sizes = np.abs(y[i]) @ np.abs(pieces) @ np.abs(x[i])
            bound = 4 * 2.0 ** -quotient._split_bits(n - 1) * (n - 1) * np.finfo(float).eps * sizes
            for t, h, low, b in zip(terms, hi[i], lo[i], bound, strict=True):
                assert abs(mp.mpf(float(h)) + mp.mpf(float(low)) - t) <= b
            om, nv_i = mp.mpf(float(twist[ok][i])), mp.mpf(float(nu[ok][i]))
            coef = [t.coefficient(om, nv_i) for t in E.INST1]
            exact = (mp.fsum(c * t for c, t in zip(coef, terms, strict=True))
                     / mp.fsum(terms[j] for j in quotient._MASS_TERMS))
            # the coefficients in longdouble carry ~1e-19 Omega^2: the result rounds to double
            assert abs(float(got[i] / exact) - 1) <= 4 * np.finfo(float).eps
            worst_double = max(worst_double, abs(float(double[i] / exact) - 1))
    assert worst_double > 4 * np.finfo(float).eps


@needs_kernel
def test_kernel_ceiling_marks_the_same_points_above():
    d = load_figure1()
    twist, nu = d["twist_angle"].to_numpy(), d["nu"].to_numpy()
    sym = modal_form.modal_family(22, "symmetric")
    anti = modal_form.modal_family(22, "antisymmetric")
    ceiling = E.lowest_eigenpair(sym, twist, nu)[0] * (1 + 1e-6)
    lam, _, _, ok, above = E.lowest_eigenpair(anti, twist, nu, ceiling=ceiling)
    ref_lam, _, _, ref_ok, ref_above = _numpy_pair(anti, twist, nu, E.POWER_RTOL, ceiling)
    assert above.sum() > 100 and ok.sum() > 100  # both outcomes occur on Figure 1's points
    assert np.array_equal(above, ref_above) and np.array_equal(ok, ref_ok)
    assert np.max(np.abs(lam[ok] / ref_lam[ok] - 1)) <= 1e-13


@needs_kernel
def test_kernel_rejects_factors_it_cannot_trust():
    # diagonal Schur complements (r_e = 0): one singular, one with a NaN, the rest fine
    k_e, k_s, points = 5, 4, 40
    d_s = np.tile(np.arange(1.0, k_s + 1.0), (points, 1)) * 10.0
    d_s[3, 0], d_s[17, 2] = 0.0, np.nan
    rng = np.random.default_rng(0)
    res = modal_kernel.modal_lowest(
        np.zeros((points, k_e)), np.ones(points), np.ones(points), d_s,
        rng.standard_normal((k_e, k_s)), rng.standard_normal((k_s, k_e)), np.full(k_e, 0.3),
        np.full(k_s, 0.3), None, shift=SHIFT, rtol=1e-14, first=6, max_steps=40,
        backward_tol=BACKWARD_TOL)
    rejected = np.flatnonzero(res.status == modal_kernel.REJECTED)
    assert rejected.tolist() == [3, 17]
    # K - SHIFT = diag(...) here: the lowest eigenvalue is SHIFT + 10 (d_s = 10, 20, ...)
    fine = res.status == modal_kernel.CONVERGED
    assert fine.sum() == points - 2
    assert np.allclose(res.lam[fine], SHIFT + 10.0, rtol=1e-14, atol=0)


@needs_kernel
def test_rejected_points_are_solved_by_the_numpy_iteration(monkeypatch):
    mf = modal_form.modal_family(22, "symmetric")
    twist, nu = _points(22, 64)
    want = E.lowest_eigenpair(mf, twist, nu)[0]
    real = modal_kernel.modal_lowest

    def reject_some(*args, **kwargs):
        res = real(*args, **kwargs)
        res.status[::5] = modal_kernel.REJECTED
        res.lam[::5] = np.nan
        return res

    monkeypatch.setattr(modal_kernel, "modal_lowest", reject_some)
    lam, _, _, ok, _ = E.lowest_eigenpair(mf, twist, nu)
    assert ok.all()
    assert np.max(np.abs(lam / want - 1)) <= 1e-13


def test_without_the_kernel_the_numpy_iteration_answers(monkeypatch):
    from spectral_rod import critical_load

    d = load_figure1()
    twist, nu = d["twist_angle"].to_numpy()[::7], d["nu"].to_numpy()[::7]
    with_kernel = critical_load(twist, nu)
    monkeypatch.setattr(modal_kernel, "_library", lambda: None)
    assert not modal_kernel.available() and not E.uses_kernel(10)
    without = critical_load(twist, nu)
    # the same quotient from vectors that agree to rounding: within the round-off model
    assert np.max(np.abs(with_kernel / without - 1)) <= 1e-14


@needs_kernel
@pytest.mark.parametrize("family", ["symmetric", "antisymmetric"])
def test_double_double_terms_agree_with_longdouble_and_mpmath(family, monkeypatch):
    # the pencil quotient at large twist, where its terms cancel to ~lambda/Omega^2: the
    # kernel's double-double products against numpy's longdouble ones and 50-digit sums
    import mpmath as mp

    n = 56
    mf = modal_form.modal_family(n, family)
    twist, nu = np.linspace(20.5, 49.5, 24), np.linspace(1.0, 90.0, 24)
    _, z, w, ok, _ = E.lowest_eigenpair(mf, twist, nu)
    x, y = mf.right_vectors(z[ok]), mf.left_vectors(w[ok])
    op, tw, nv = mf.op, twist[ok], nu[ok]
    got = quotient._rayleigh_sums(op, tw, nv, y, x, np.longdouble)
    monkeypatch.setattr(modal_kernel, "_library", lambda: None)
    longdouble = quotient._rayleigh_sums(op, tw, nv, y, x, np.longdouble)
    assert np.max(np.abs(got / longdouble - 1)) <= 4 * np.finfo(float).eps
    shape, mats = quotient._term_matrices(n, family)
    with mp.workdps(50):
        for i in (0, len(tw) // 2, len(tw) - 1):
            terms = []
            for e_off, m_e, f_off, m_f, start in shape.tolist():
                mat = mats[start:start + m_e * m_f].reshape(m_e, m_f)
                terms.append(mp.fsum(mp.mpf(float(y[i, e_off + r])) * mp.mpf(float(mat[r, c]))
                                     * mp.mpf(float(x[i, f_off + c]))
                                     for r in range(m_e) for c in range(m_f)))
            om, nv_i = mp.mpf(float(tw[i])), mp.mpf(float(nv[i]))
            coef = [t.coefficient(om, nv_i) for t in E.INST1]
            exact = (mp.fsum(c * t for c, t in zip(coef, terms, strict=True))
                     / mp.fsum(terms[j] for j in quotient._MASS_TERMS))
            # the code's coefficients in longdouble carry ~1e-19 Omega^2: the result rounds
            # to double
            assert abs(float(got[i] / exact) - 1) <= 4 * np.finfo(float).eps


def test_array_addresses_for_the_kernel():
    # modal_kernel._ptr reads a writable array's address through its buffer: the address numpy
    # reports, for writable, read-only, empty and int32 arrays alike; None stays a null pointer
    a = np.arange(6.0)
    ro = np.arange(4.0)
    ro.flags.writeable = False
    for x in (a, a[2:], ro, np.empty(0), np.zeros((3, 2), dtype=np.int32)):
        assert modal_kernel._ptr(x) == x.ctypes.data
    assert modal_kernel._ptr(None) is None
    with pytest.raises(ValueError, match="C-contiguous"):
        modal_kernel._ptr(a[::2])
