"""Shared fixtures: the independent extended-precision reference (cached per session)."""

from __future__ import annotations

from functools import lru_cache

import pytest

from spectral_rod.rod.characteristic import characteristic_critical_load


@lru_cache(maxsize=4096)
def reference_p_star(twist_angle: float, nu: float) -> float:
    """p* from the paper's characteristic equation in mpmath (never from collocation)."""
    return float(characteristic_critical_load(twist_angle, nu).p_star)


@pytest.fixture(scope="session")
def reference():
    return reference_p_star
