"""Sphinx configuration of the spectral_rod manual.

Build (warnings are errors)::

    python -m pip install -e '.[docs]'
    python -m sphinx -W -b html docs docs/_build/html

Generated inputs: :func:`copy_generated` copies the committed outputs of
``python -m reproduce all`` (``paper_figures/report.md``, ``claims.md`` and the PNGs) and the
top-level ``CHANGELOG.md`` and ``CITATION.cff`` into ``docs/_generated/`` at every build, so the
findings pages show exactly what the pipeline wrote and cannot drift from it; a file that is
absent gets a one-line page saying so. The tutorials in ``docs/tutorials_src/`` are executed by
sphinx-gallery at every build and their figures captured.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path
from typing import Any

import spectral_rod

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
GENERATED = DOCS / "_generated"
FIGURES = ROOT / "paper_figures"

project = "spectral_rod"
author = "spectral_rod contributors"
copyright = "spectral_rod contributors"
version = release = spectral_rod.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "matplotlib.sphinxext.plot_directive",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
#: the generated pages that other pages include (they are not pages of their own)
exclude_patterns = ["_build", "tutorials_src", "sg_execution_times.rst",
                    "_generated/changelog.md", "_generated/findings/figures.md"]
root_doc = "index"

# --- API reference ---------------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = True
autodoc_default_options = {"members": False}
autodoc_typehints = "none"  # the signatures carry them; numpydoc renders the sections
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# --- MyST (the Markdown pages and the copied pipeline outputs) -----------------------------
myst_enable_extensions = ["dollarmath", "colon_fence"]
myst_heading_anchors = 3

# --- the "first figure" of getting_started.md (matplotlib's plot directive, run at build) ----
plot_html_show_source_link = False
plot_html_show_formats = False
plot_formats = [("png", 110)]

# --- tutorials -------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "tutorials_src",
    "gallery_dirs": "tutorials",
    "filename_pattern": r"/plot_",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "min_reported_time": 1,
}

# --- HTML ------------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"spectral_rod {release}"
html_static_path = ["_static"]
html_css_files = ["spectral_rod.css"]
html_theme_options = {
    "navigation_with_keys": False,
    "header_links_before_dropdown": 4,
    "show_toc_level": 2,
    # an API page documents one name: its own table of contents would only repeat it
    "secondary_sidebar_items": {"*": ["page-toc"], "tutorials/*": ["page-toc"],
                                "_generated/findings/*": ["page-toc"], "generated/*": []},
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
#: pages without sub-pages have no section navigation to show
html_sidebars = {page: [] for page in ("index", "getting_started", "how_it_works", "pipeline",
                                       "changelog", "citing")}


# --- generated inputs --------------------------------------------------------------------------
#: (source, copy under _generated/, title of the stand-in page when the source is absent)
COPIED = (
    (ROOT / "CHANGELOG.md", "changelog.md", "Changelog"),
    (ROOT / "CITATION.cff", "CITATION.cff", None),
    (FIGURES / "report.md", "findings/report.md", "Reproduction report"),
    (FIGURES / "claims.md", "findings/claims.md", "Claims ledger"),
)

#: The report's scene table links to raw-HTML anchors (``<a id="figure1">``), which MyST does
#: not know as targets; each becomes a MyST label on the heading that follows it.
_HTML_ANCHOR = re.compile(r'<a id="([\w-]+)"></a>\s*\n\s*\n(#+ )')


def _markdown_copy(text: str) -> str:
    return _HTML_ANCHOR.sub(r"(\1)=\n\2", text)


def copy_generated() -> None:
    """Copy the pipeline's outputs and the top-level files the manual shows into _generated/."""
    shutil.rmtree(GENERATED, ignore_errors=True)
    (GENERATED / "findings").mkdir(parents=True)
    for source, name, title in COPIED:
        target = GENERATED / name
        if source.exists():
            text = source.read_text(encoding="utf-8")
            target.write_text(_markdown_copy(text) if name.endswith(".md") else text,
                              encoding="utf-8")
        elif title is not None:
            target.write_text(f"# {title}\n\n`{source.relative_to(ROOT)}` is not in this "
                              "checkout.\n", encoding="utf-8")
    for png in sorted(FIGURES.glob("*.png")):
        shutil.copy2(png, GENERATED / "findings" / png.name)
    (GENERATED / "findings" / "figures.md").write_text(figures_page(), encoding="utf-8")


#: Captions of the pipeline's figures; a figure not named here is shown under its file name.
CAPTIONS = {
    "claims_load.png": "p* to Ω(L) = 20π with the limit 2ν/(1+ν), and the approach to it",
    "claims_wavenumbers.png": "β₁L, β₂L and β₂ − β₁ against Ω(L), with the imaginary-β₁ window",
    "claims_mode.png": "The 3-D buckling centreline against the planar Euler mode",
    "ring.png": "Eq. crit2 against the converged ring",
    "convergence_resolution.png": "Error against resolution",
    "convergence_time.png": "Error against wall time",
    "convergence_coefficients.png": "The mode's Chebyshev coefficients at the automatic degree",
    "extremes.png": "Accuracy at the edges of the (Ω(L), ν) plane",
}
#: Figures findings.md shows beside its own text, left out of the generated list.
SHOWN_IN_TEXT = ("figure1.png", "figure1_forensics.png")


def figures_page() -> str:
    """A Markdown section per figure the pipeline wrote (other than those in SHOWN_IN_TEXT),
    so that the findings page shows whatever ``reproduce all`` produced."""
    parts = []
    for png in sorted(FIGURES.glob("*.png")):
        if png.name in SHOWN_IN_TEXT:
            continue
        caption = CAPTIONS.get(png.name, png.name)
        parts.append(f"### {caption}\n\n`{png.name}`\n\n![{caption}]({png.name})\n")
    return "\n".join(parts) or "No other figures in `paper_figures/`.\n"


def citation_text() -> str:
    """CITATION.cff's text, or a stand-in line when the checkout has none."""
    cff = GENERATED / "CITATION.cff"
    if cff.exists():
        return cff.read_text(encoding="utf-8")
    return "# CITATION.cff is not in this checkout\n"


copy_generated()
(GENERATED / "citation.txt").write_text(citation_text(), encoding="utf-8")


# --- docstrings written in plain-text notation -------------------------------------------------
# The library's docstrings write mathematics as plain text (|Omega(L)|, X_-, "name   text"
# tables), which reStructuredText would read as substitutions, hyperlink targets and block
# quotes. The hook below escapes those characters outside literals and code, and sets a
# column-aligned field table as a literal block, so the rendered page shows the text as written.

#: |...| (absolute values, also across lines) that reST would take for a substitution reference;
#: the docstrings use no line blocks or grid tables, so every bar in prose is a character
_BAR = re.compile(r"(?<!\\)\|")
#: a word's trailing underscore that reST would take for a hyperlink reference (X_-, x_)
_TRAILING_UNDERSCORE = re.compile(r"(?<=\w)_(?=[^\w`]|$)")
#: inline literals and roles, left alone
_CODE = re.compile(r"(``.+?``|:[\w:]+:`[^`]+`|`[^`]+`)")
#: a line of a column-aligned field table: "name   text"
_FIELD_ROW = re.compile(r"^(\s*)[A-Za-z_][\w]*(?: \S+)? {3,}\S")


def _escape_prose(line: str) -> str:
    parts = _CODE.split(line)
    for k in range(0, len(parts), 2):  # even parts lie outside code spans
        parts[k] = _TRAILING_UNDERSCORE.sub(r"\\_", _BAR.sub(r"\\|", parts[k]))
    return "".join(parts)


def _field_tables_as_literal(lines: list[str]) -> list[str]:
    """Turn runs of column-aligned "name   text" lines (with their indented continuation lines)
    into literal blocks."""
    out: list[str] = []
    k = 0
    while k < len(lines):
        if _FIELD_ROW.match(lines[k]) and k + 1 < len(lines) and (
                _FIELD_ROW.match(lines[k + 1]) or lines[k + 1].startswith(" " * 8)):
            indent = _FIELD_ROW.match(lines[k]).group(1)
            block = []
            while k < len(lines) and lines[k].strip() and lines[k].startswith(indent):
                block.append(lines[k])
                k += 1
            if out and out[-1].strip():
                out.append("")
            out += [indent + "::", ""] + ["    " + line for line in block] + [""]
            continue
        out.append(lines[k])
        k += 1
    return out


#: numpydoc sections whose entries are "name : type" lines with indented descriptions
_ENTRY_SECTIONS = ("Parameters", "Other Parameters", "Attributes")
_ENTRY = re.compile(r"^(\s*)(\*{0,2}\w+(?:, \*{0,2}\w+)*)(?: : (.*))?$")
#: a "type" longer than this many words (or ending in a full stop) is a description written on
#: the name's line
_TYPE_WORDS = 5


def _section_headers(lines: list[str]) -> list[int]:
    return [k for k in range(len(lines) - 1)
            if lines[k].strip() and set(lines[k + 1].strip()) == {"-"}
            and len(lines[k + 1].strip()) == len(lines[k].strip())]


def _numpydoc_entries(lines: list[str]) -> list[str]:
    """In a Parameters-like section: a description written on the name's line ("nu : I2/I1 in
    [1, 1e4] ...") moves to the next line, and prose that follows the entries at their
    indentation (which numpydoc would read as more entries) opens a Notes section."""
    headers = _section_headers(lines)
    titles = {lines[k].strip() for k in headers}
    out = list(lines)
    for k in reversed(headers):
        if out[k].strip() not in _ENTRY_SECTIONS:
            continue
        base = len(out[k]) - len(out[k].lstrip())
        end = next((h for h in headers if h > k), len(out))
        j = k + 2
        while j < end:
            line = out[j]
            stripped = line.strip()
            if not stripped or len(line) - len(line.lstrip()) != base:
                j += 1
                continue
            entry = _ENTRY.match(line)
            if entry is None:  # prose at the entries' indentation: the entries have ended
                if "Notes" not in titles:
                    out[j:j] = [" " * base + "Notes", " " * base + "-----"]
                    titles.add("Notes")
                break
            kind = entry.group(3)
            if kind is not None and (len(kind.split()) > _TYPE_WORDS or kind.endswith(".")):
                out[j:j + 1] = [" " * base + entry.group(2), " " * (base + 4) + kind]
                end += 1
                j += 1
            j += 1
    return out


def data_comment(name: str) -> list[str]:
    """The ``#:`` comment that documents the public constant `name` ("spectral_rod.X") where it
    is defined (the module in ``spectral_rod._EXPORTS``, or a submodule of that package)."""
    import importlib
    import pkgutil

    from sphinx.pycode import ModuleAnalyzer

    short = name.rpartition(".")[2]
    target = spectral_rod._EXPORTS.get(short)
    if target is None:
        return []
    module, _, attr = target.partition(":")
    candidates = [f"spectral_rod.{module}"]
    package = importlib.import_module(candidates[0])
    if hasattr(package, "__path__"):
        candidates += [m.name for m in pkgutil.iter_modules(package.__path__,
                                                             f"{candidates[0]}.")]
    for candidate in candidates:
        docs = ModuleAnalyzer.for_module(candidate).find_attr_docs()
        comment = docs.get(("", attr or short))
        if comment:
            return list(comment)
    return []


def plain_text_docstring(app: Any, what: str, name: str, obj: Any, options: Any,
                         lines: list[str]) -> None:
    """autodoc-process-docstring, before numpydoc: read the library's plain-text docstrings
    as numpydoc and reST would (see above); a public constant gets the comment it is
    documented with where it is defined, not its type's docstring."""
    if not name.startswith("spectral_rod"):
        return
    if what == "data":
        lines[:] = data_comment(name)
    lines[:] = _numpydoc_entries(list(lines))
    result: list[str] = []
    literal_indent: int | None = None
    in_doctest = False
    for line in _field_tables_as_literal(list(lines)):
        stripped = line.lstrip()
        indent = len(line) - len(stripped)
        if literal_indent is not None and stripped and indent <= literal_indent:
            literal_indent = None
        if stripped.startswith(">>>"):
            in_doctest = True
        elif not stripped:
            in_doctest = False
        if in_doctest or literal_indent is not None or not stripped:
            result.append(line)
        else:
            result.append(_escape_prose(line))
        if stripped.endswith("::") and literal_indent is None:
            literal_indent = indent
    lines[:] = result


def setup(app: Any) -> None:
    # numpydoc's own handler runs at the default priority 500; this one must see the raw text
    app.connect("autodoc-process-docstring", plain_text_docstring, priority=400)
