"""Every docstring example in the library and the pipeline's helpers runs and prints what it
says (an example that rots is a wrong statement)."""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import spectral_rod

MODULES = sorted(
    [m.name for m in pkgutil.walk_packages(spectral_rod.__path__, "spectral_rod.")]
    + ["spectral_rod", "reproduce.ledger", "reproduce.tables", "reproduce.compare",
       "reproduce.io"])


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {name}"
