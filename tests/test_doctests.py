"""Every docstring example in the library and the pipeline's helpers runs and prints what it
says (an example that rots is a wrong statement)."""

from __future__ import annotations

import doctest
import importlib
import importlib.util
import pkgutil
from pathlib import Path

import pytest

import spectral_rod

CANDIDATES = sorted(
    [m.name for m in pkgutil.walk_packages(spectral_rod.__path__, "spectral_rod.")]
    + ["spectral_rod", "reproduce.ledger", "reproduce.tables", "reproduce.compare",
       "reproduce.io", "reproduce.ties"])


def _has_examples(name: str) -> bool:
    spec = importlib.util.find_spec(name)  # a compiled module's origin is not Python source
    return (spec is not None and spec.origin is not None and spec.origin.endswith(".py")
            and ">>> " in Path(spec.origin).read_text())


#: The modules with docstring examples (each must run at least one).
MODULES = [name for name in CANDIDATES if _has_examples(name)]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0, f"no example of {name} was run"
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {name}"
