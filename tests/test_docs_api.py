"""The manual's sources: every public name is in the API reference, and the examples written
in its Markdown pages run (as the docstrings' do in ``test_doctests.py``).

The manual itself is built by ``python -m sphinx -W -b html docs docs/_build/html`` (the
``docs`` extra installs the build); these checks need no Sphinx.
"""

from __future__ import annotations

import doctest
import re
from pathlib import Path

import pytest

import spectral_rod

DOCS = Path(__file__).resolve().parents[1] / "docs"
API = DOCS / "api.rst"

pytestmark = pytest.mark.skipif(not API.exists(), reason="needs a source checkout with docs/")

#: an entry of an autosummary table in api.rst: an indented name alone on its line
_ENTRY = re.compile(r"^   ([A-Za-z_]\w*)\s*$", re.MULTILINE)


def api_entries(text: str) -> list[str]:
    """The names listed in the autosummary tables of `text` (api.rst's source)."""
    return _ENTRY.findall(text)


def test_every_public_name_is_in_the_api_reference() -> None:
    entries = api_entries(API.read_text(encoding="utf-8"))
    missing = sorted(set(spectral_rod.__all__) - set(entries))
    assert not missing, f"public names missing from docs/api.rst: {missing}"
    unknown = sorted(set(entries) - set(spectral_rod.__all__))
    assert not unknown, f"docs/api.rst lists names that are not public: {unknown}"
    assert len(entries) == len(set(entries)), "a name is listed twice in docs/api.rst"


def test_api_entries_sees_a_removed_name() -> None:
    """The parser behind the check above notices a name taken out of the reference."""
    text = API.read_text(encoding="utf-8")
    assert "critical_load" in api_entries(text)
    assert "critical_load" not in api_entries(text.replace("   critical_load\n", ""))


#: fenced code block markers of the Markdown pages, dropped before doctest reads the text (a
#: fence right after an example's output would otherwise be read as part of that output)
_FENCE = re.compile(r"^\s*```.*$", re.MULTILINE)

PAGES = sorted(p for p in DOCS.glob("*.md") if ">>> " in p.read_text(encoding="utf-8"))


def test_some_page_has_examples() -> None:
    assert PAGES, "no Markdown page of docs/ has a >>> example"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_markdown_examples(page: Path) -> None:
    text = _FENCE.sub("", page.read_text(encoding="utf-8"))
    test = doctest.DocTestParser().get_doctest(text, {}, page.name, str(page), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.attempted > 0
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {page}"
