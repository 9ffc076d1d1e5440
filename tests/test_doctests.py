"""Every docstring example in the library and the pipeline's helpers runs and prints what it
says (an example that rots is a wrong statement), and every public name of
``spectral_rod.__all__`` is documented for the API reference: a function has a numpydoc Returns
section and an example, a class an example, a constant a ``#:`` comment where it is defined."""

from __future__ import annotations

import ast
import doctest
import importlib
import importlib.util
import inspect
import pkgutil
import re
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


#: a numpydoc Returns section header: the title alone on its line, underlined by dashes
_RETURNS = re.compile(r"^[ \t]*Returns[ \t]*\n[ \t]*-{7}[ \t]*$", re.MULTILINE)


def api_gaps(obj: object) -> list[str]:
    """What the API reference lacks for the public function or class `obj`: "Returns" (a
    function without a numpydoc Returns section), "example" (no docstring example that doctest
    collects), "module" (its module's examples are not run by :func:`test_docstring_examples`)."""
    doc = inspect.getdoc(obj) or ""
    gaps = []
    if inspect.isfunction(obj) and not _RETURNS.search(doc):
        gaps.append("Returns")
    if not doctest.DocTestParser().get_examples(doc):
        gaps.append("example")
    if getattr(obj, "__module__", None) not in MODULES:
        gaps.append("module")
    return gaps


def _public(kind) -> list[str]:
    return [name for name in spectral_rod.__all__ if kind(getattr(spectral_rod, name))]


@pytest.mark.parametrize("name", _public(inspect.isfunction) + _public(inspect.isclass))
def test_public_name_has_returns_and_example(name):
    """Issue 39's API-reference line: the face's functions and classes carry their sections."""
    gaps = api_gaps(getattr(spectral_rod, name))
    assert not gaps, f"spectral_rod.{name}'s docstring lacks: {gaps}"


def test_api_gaps_sees_a_missing_section():
    """The check above notices a docstring without a Returns section or without an example."""
    def documented(x: float) -> float:
        """Twice x.

        Returns
        -------
        float
            2 x.

        Examples
        --------
        >>> documented(1.0)
        2.0
        """
        return 2 * x

    documented.__module__ = "spectral_rod.rod.measures"
    assert api_gaps(documented) == []
    documented.__doc__ = documented.__doc__.replace("Returns", "Result")
    assert api_gaps(documented) == ["Returns"]
    documented.__doc__ = "Twice x.\n\nReturns\n-------\nfloat\n    2 x.\n"
    assert api_gaps(documented) == ["example"]
    documented.__module__ = "elsewhere"
    assert api_gaps(documented) == ["example", "module"]


def constant_comment(name: str) -> list[str]:
    """The ``#:`` comment lines right above the assignment that defines the public constant
    `name` (the module named in ``spectral_rod._EXPORTS``, or a submodule of that package);
    a tuple assignment documents each of its names, as Sphinx reads it."""
    module, _, attr = spectral_rod._EXPORTS[name].partition(":")
    attr = attr or name
    modules = [f"spectral_rod.{module}"]
    package = importlib.import_module(modules[0])
    if hasattr(package, "__path__"):
        modules += [m.name for m in pkgutil.iter_modules(package.__path__, f"{modules[0]}.")]
    for candidate in modules:
        lines = Path(importlib.util.find_spec(candidate).origin).read_text().split("\n")
        for node in ast.parse("\n".join(lines)).body:
            targets = (node.targets if isinstance(node, ast.Assign)
                       else [node.target] if isinstance(node, ast.AnnAssign) else [])
            names = {n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)}
            if attr in names:
                k = node.lineno - 1
                while k > 0 and lines[k - 1].lstrip().startswith("#:"):
                    k -= 1
                return lines[k:node.lineno - 1]
    return []


CONSTANTS = [name for name in spectral_rod.__all__
             if not (inspect.isfunction(getattr(spectral_rod, name))
                     or inspect.isclass(getattr(spectral_rod, name)))]


@pytest.mark.parametrize("name", CONSTANTS)
def test_public_constant_has_a_comment(name):
    """The API page of a constant shows its ``#:`` comment (docs/conf.py: data_comment)."""
    assert constant_comment(name), f"spectral_rod.{name} has no #: comment where it is defined"


def test_constant_comment_sees_a_missing_comment():
    assert constant_comment("ROD_METHODS")
    assert constant_comment("FIGURE1_Y_PER_P")  # the second name of a tuple assignment
    assert not constant_comment("critical_load")  # a function: no assignment, no comment
