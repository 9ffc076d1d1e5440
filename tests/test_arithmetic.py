"""Each rule of the degree loop is written once (spectral_rod.rod.collocation.arithmetic): the
scalar path runs it on Python floats, batches on numpy arrays. Both must give the same bits."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from spectral_rod.rod.collocation.arithmetic import FLOATS
from spectral_rod.rod.collocation.resolution import (
    N_MAX,
    N_MIN,
    error_estimate,
    initial_degree,
    raised_degree,
    roundoff_floor,
    shortfall,
    truncation_error,
)

twists = st.floats(0.0, 1e4)
tols = st.floats(1e-14, 1e-2)
tails = st.one_of(st.floats(0.0, 1.0), st.just(np.inf))
degrees = st.integers(N_MIN // 2, N_MAX // 2).map(lambda k: 2 * k)

@settings(max_examples=400, deadline=None)
@given(twists, tols)
def test_initial_degree_is_one_rule(twist, tol):
    a = initial_degree(twist, tol, FLOATS)
    b = initial_degree(np.array([twist]), tol)[0].item()
    assert type(a) is int and a % 2 == 0 and N_MIN <= a <= N_MAX
    # numpy's cbrt and v ** (1/3) may differ in the last bit, which can move an even degree by 2
    # only where the formula lands within an ulp of it
    assert abs(a - b) <= 2

@settings(max_examples=400, deadline=None)
@given(tails, twists, degrees, tols)
def test_estimate_shortfall_and_raise_are_one_rule(tail, twist, n, tol):
    assert truncation_error(tail, n, FLOATS) == truncation_error(np.array([tail]), n)[0]
    assert roundoff_floor(twist, n, FLOATS) == roundoff_floor(np.array([twist]), n)[0]
    assert error_estimate(tail, twist, n, FLOATS) == \
        error_estimate(np.array([tail]), np.array([twist]), np.array([n]))[0]
    short = shortfall(tail, tol, n, FLOATS)
    assert short == shortfall(np.array([tail]), tol, n)[0]
    if short > 1.0:
        raised = raised_degree(n, short, FLOATS)
        assert type(raised) is int
        assert raised == raised_degree(np.array([n]), np.array([short]))[0]
        assert n < raised <= N_MAX or n == N_MAX

def test_a_changed_rule_is_seen():
    """The comparison can fail: a namespace whose where picks the other branch gives other
    estimates."""
    import types

    wrong = types.SimpleNamespace(**{**vars(FLOATS), "where": lambda c, a, b: b if c else a})
    assert truncation_error(1e-3, 16, wrong) != truncation_error(np.array([1e-3]), 16)[0]
