"""Second-order finite differences of Eq. inst1 against the mpmath characteristic equation."""

from __future__ import annotations

import numpy as np
import pytest

from spectral_rod.rod.finite_difference import fd_critical_load, fd_operator


@pytest.mark.parametrize("twist,nu", [(0.0, 1.5), (2.0, 1.5), (7.0, 1.1), (20.0, 3.0)])
def test_error_is_second_order_in_h(reference, twist, nu):
    ref = reference(twist, nu)
    ns = np.array([128, 256, 512, 1024])
    err = np.array([fd_critical_load(twist, nu, int(n)) / ref - 1 for n in ns])
    # halving h divides the error by 4: observed order within 2 +- 0.1, one-signed error
    order = np.log2(np.abs(err[:-1] / err[1:]))
    assert np.all(np.abs(order - 2.0) < 0.1), order
    assert np.all(np.sign(err) == np.sign(err[0]))


def test_zero_twist_matches_the_closed_form_of_the_discrete_laplacian():
    # at Omega = 0 the lowest eigenvalue of -D2 is (4/h^2) sin^2(pi h / 2) exactly
    n = 50
    h = 1.0 / n
    exact = 4.0 / h**2 * np.sin(np.pi * h / 2) ** 2 / np.pi**2
    assert fd_critical_load(0.0, 2.0, n) == pytest.approx(exact, rel=1e-13)


def test_operator_is_symmetric_and_sign_of_twist_irrelevant():
    op = fd_operator(3.0, 1.7, 40)
    assert abs(op - op.T).max() == 0.0
    assert fd_critical_load(-3.0, 1.7, 200) == pytest.approx(fd_critical_load(3.0, 1.7, 200),
                                                             rel=1e-14)


def test_bad_resolution_raises():
    with pytest.raises(ValueError, match="intervals"):
        fd_operator(1.0, 1.5, 2)
