"""Bad input: every public function answers with ValueError/TypeError naming the argument."""

from __future__ import annotations

import math

import numpy as np
import pytest

from spectral_rod.figure1.data import load_figure1
from spectral_rod.rod.closed_form import large_twist_expansion, large_twist_limit
from spectral_rod.rod.critical import critical_load
from spectral_rod.rod.increment import critical_load_increment

PUBLIC = {
    "critical_load": critical_load,
    "critical_load_increment": critical_load_increment,
    "large_twist_expansion": large_twist_expansion,
}


@pytest.mark.parametrize("func", PUBLIC.values(), ids=PUBLIC.keys())
@pytest.mark.parametrize("bad, exc", [
    (math.nan, ValueError), (math.inf, ValueError), (-math.inf, ValueError),
    ("1.0", TypeError), (None, TypeError), (1 + 2j, TypeError), (True, TypeError),
    (["a"], TypeError), ([1.0, math.nan], ValueError), (object(), TypeError),
])
def test_bad_twist(func, bad, exc):
    if func is large_twist_expansion and isinstance(bad, list):
        exc = TypeError  # a scalar function: "twist_angle must be a scalar"
    with pytest.raises(exc, match="twist_angle"):
        func(bad, 1.5)


@pytest.mark.parametrize("func", [*PUBLIC.values(), None], ids=[*PUBLIC.keys(), "limit"])
@pytest.mark.parametrize("bad, exc, msg", [
    (math.nan, ValueError, "finite"), (math.inf, ValueError, "finite"),
    (0.0, ValueError, "A1 <= A2"), (-2.0, ValueError, "A1 <= A2"), (0.5, ValueError, "1/nu"),
    (1e5, ValueError, "<= 10000"), ("2", TypeError, "nu"), (None, TypeError, "nu"),
    (False, TypeError, "nu"),
])
def test_bad_nu(func, bad, exc, msg):
    with pytest.raises(exc, match="nu") as info:
        if func is None:
            large_twist_limit(bad)
        else:
            func(10.0, bad)
    assert msg in str(info.value)


def test_nu_below_one_is_an_error_not_a_mapping():
    # the convention is A1 <= A2; the message explains the swap (pass 1/nu)
    with pytest.raises(ValueError, match=r"I2/I1 must be >= 1.*swap the axes"):
        critical_load(2.0, 1 / 1.5)


@pytest.mark.parametrize("n, exc", [(7, ValueError), (4, ValueError), (1024, ValueError),
                                    (16.0, TypeError), ("16", TypeError), (True, TypeError)])
def test_bad_resolution(n, exc):
    with pytest.raises(exc, match=r"\bn\b"):
        critical_load(1.0, 1.5, n=n)


@pytest.mark.parametrize("tol, exc", [(0.0, ValueError), (1e-16, ValueError), (0.5, ValueError),
                                      (math.nan, ValueError), ("1e-8", TypeError)])
def test_bad_tol(tol, exc):
    with pytest.raises(exc, match="tol"):
        critical_load(1.0, 1.5, tol=tol)


def test_bad_full_output():
    with pytest.raises(TypeError, match="full_output"):
        critical_load(100.0, 1.5, full_output="yes")


def test_twist_ranges_are_stated():
    with pytest.raises(ValueError, match=r"\|twist_angle\| <= 10000"):
        critical_load(2e4, 1.5)
    with pytest.raises(ValueError, match=r"\|twist_angle\| <= 1000"):
        critical_load_increment(1500.0, 1.5)
    with pytest.raises(ValueError, match=r"2 pi <= \|twist_angle\|"):
        large_twist_expansion(0.0, 1.5)


def test_negative_twist_is_accepted_and_even():
    assert critical_load(-3.0, 1.4) == critical_load(3.0, 1.4)
    assert critical_load_increment(-3.0, 1.4) == critical_load_increment(3.0, 1.4)
    # the large-twist route's array path (numpy's sin/cos) and scalar path (libm's) may differ
    # by an ulp, depending on numpy's build (measured at the dependency floors): 4 eps relative
    both = critical_load(np.array([-200.0, 200.0]), 2.0)
    assert both[0] == both[1]
    assert np.allclose(both, critical_load(200.0, 2.0), rtol=4 * np.finfo(float).eps, atol=0)


def test_missing_reference_data_names_the_file(tmp_path):
    path = tmp_path / "figure1_digitised.csv"
    with pytest.raises(FileNotFoundError, match=r"figure1_digitised\.csv.*missing"):
        load_figure1(path)


@pytest.mark.parametrize("content, msg", [
    ("", "not a readable CSV"),
    ("a,b\n1,2\n", "missing columns"),
    ("curve,nu,picture_x,picture_y,twist_angle,p_star\n1,1.1,10,4,1.0,x\n", "non-numeric"),
    ("curve,nu,picture_x,picture_y,twist_angle,p_star\n1,1.3,10,4,1.0,1.01\n", "nu"),
    ("curve,nu,picture_x,picture_y,twist_angle,p_star\n1,1.1,10,4,2.0,1.01\n", "follow from"),
])
def test_corrupt_reference_data_names_file_and_problem(tmp_path, content, msg):
    path = tmp_path / "figure1_digitised.csv"
    path.write_text(content, encoding="utf-8")
    with pytest.raises(ValueError, match=msg) as info:
        load_figure1(path)
    assert str(path) in str(info.value)
