"""One place for the pipeline's paths.

Outputs go to ``./paper_figures`` under the current working directory unless ``--out`` says
otherwise (a source checkout run from its root writes into its own ``paper_figures/``); nothing
is ever written inside the installed package. The digitised Figure 1 is read from the package
(:func:`spectral_rod.load_figure1`).
"""

from __future__ import annotations

from pathlib import Path

#: Name of the default output directory (relative to the current working directory).
OUT_NAME = "paper_figures"
#: Where this copy of the pipeline's code lives (a git checkout, or site-packages).
CODE_DIR = Path(__file__).resolve().parent


def default_out() -> Path:
    """``./paper_figures`` under the current working directory."""
    return Path.cwd() / OUT_NAME
