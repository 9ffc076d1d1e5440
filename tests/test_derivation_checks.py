"""The derivations' step checks: a failed step is reported by name, also under ``python -O``
(the checks are explicit, not ``assert`` statements), and the shared sympy helpers."""

from __future__ import annotations

import functools
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

import spectral_rod.derivations.ring_linearisation as ring
from spectral_rod.derivations import derivation_status
from spectral_rod.derivations._sympy import DerivationError, check, z

ROOT = Path(__file__).resolve().parent.parent


def _misprinted_munder(Ft, w, M, m=(0, 0, 0), q=(0, 0, 0)):  # type: ignore[no-untyped-def]
    """Eq. Munder with the sign of the hoop-force term of line 3 reversed (a misprint)."""
    from spectral_rod.derivations.straight_rod import munder

    lines = munder(Ft, w, M, m, q)
    return [lines[0], lines[1], lines[2] + 2 * w[0] * Ft, lines[3]]


def test_failed_step_is_named(monkeypatch: pytest.MonkeyPatch) -> None:
    # a fresh cache, so that derive() runs (and the module's real cache is left alone)
    monkeypatch.setattr(ring, "derive", functools.lru_cache(maxsize=1)(ring.derive.__wrapped__))
    monkeypatch.setattr(ring, "munder", _misprinted_munder)
    assert derivation_status("ring_linearisation") == (
        "a step failed: 2: line 3 of Eq. Munder gives F_t = -q R")
    with pytest.raises(DerivationError, match=r"line 3 of Eq\. Munder") as info:
        ring.derive()
    assert info.value.step == "2: line 3 of Eq. Munder gives F_t = -q R"


def test_checks_run_under_python_O() -> None:
    """Under -O every ``assert`` is stripped; the step checks must still fail on a misprint."""
    code = (
        "import functools\n"
        "import spectral_rod.derivations.ring_linearisation as ring\n"
        "from spectral_rod.derivations import derivation_status\n"
        "from spectral_rod.derivations.straight_rod import munder\n"
        "def wrong(Ft, w, M, m=(0, 0, 0), q=(0, 0, 0)):\n"
        "    lines = munder(Ft, w, M, m, q)\n"
        "    return [lines[0], lines[1], lines[2] + 2 * w[0] * Ft, lines[3]]\n"
        "ring.derive = functools.lru_cache(maxsize=1)(ring.derive.__wrapped__)\n"
        "ring.munder = wrong\n"
        "print(__debug__, derivation_status('ring_linearisation'))\n")
    out = subprocess.run([sys.executable, "-O", "-c", code], cwd=ROOT, capture_output=True,
                         text=True, timeout=120, check=True).stdout
    assert out.strip() == "False a step failed: 2: line 3 of Eq. Munder gives F_t = -q R"


def test_check_and_zero_test() -> None:
    check(True, "fine")
    with pytest.raises(DerivationError, match=r"derivation step failed: the name") as info:
        check(0, "the name")
    assert isinstance(info.value, AssertionError) and info.value.step == "the name"
    x = sp.Symbol("x", real=True)
    assert z(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1) and not z(sp.sin(x) - sp.cos(x))


def test_derivation_status_rejects_unknown_names() -> None:
    with pytest.raises(ValueError, match="name"):
        derivation_status("ring")
    with pytest.raises(TypeError, match="name"):
        derivation_status(1)  # type: ignore[arg-type]
