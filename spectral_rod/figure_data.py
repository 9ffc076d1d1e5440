"""Figure 1 of the paper as data: parse the LaTeX `picture`, load and validate the CSV.

The digitised points ship with the package (``spectral_rod/data/figure1_digitised.csv``, with
its provenance ``figure1_digitised.md``); :func:`load_figure1` reads them through
``importlib.resources``, so an installed package needs no source checkout and no paper.

The figure is drawn with ``\\put(x, y){\\circle*{1.0}}`` in a 100 x 100 box: Omega(L) = x/10
(0..10) and p* = 1 + y/400 (1.00..1.25). The three curves follow each other in the source;
a new curve starts where x falls back to the left edge. Curves 1, 2, 3 are nu = 1.1, 1.3, 1.5.
"""

from __future__ import annotations

import re
from importlib import resources
from pathlib import Path

import numpy as np
import pandas as pd

FIGURE1_NU = (1.1, 1.3, 1.5)
COLUMNS = ("curve", "nu", "picture_x", "picture_y", "twist_angle", "p_star")
_PUT = re.compile(r"\\put\(\s*([-+0-9.]+)\s*,\s*([-+0-9.]+)\s*\)\s*\{\\circle\*")


def twist_from_picture(x: float | np.ndarray) -> float | np.ndarray:
    """Omega(L) from the picture's x coordinate (the axis runs 0..100 for 0.0..10.0)."""
    return x / 10.0


def p_star_from_picture(y: float | np.ndarray) -> float | np.ndarray:
    """p* from the picture's y coordinate (the axis runs 0..100 for 1.00..1.25)."""
    return 1.0 + y / 400.0


def parse_figure1(tex: str) -> pd.DataFrame:
    """All filled circles of the paper's picture environment as a DataFrame (COLUMNS)."""
    body = tex[tex.index(r"\begin{picture}"):tex.index(r"\end{picture}")]
    pts = [(float(a), float(b)) for a, b in _PUT.findall(body)]
    if not pts:
        raise ValueError("no \\put(x,y){\\circle*} points found in the picture environment")
    curve, rows, last_x = 0, [], np.inf
    for x, y in pts:
        if x < last_x:  # x restarts at the left edge: next curve
            curve += 1
        last_x = x
        rows.append((curve, x, y))
    if curve != len(FIGURE1_NU):
        raise ValueError(f"expected {len(FIGURE1_NU)} curves in Figure 1, found {curve}")
    df = pd.DataFrame(rows, columns=["curve", "picture_x", "picture_y"])
    df["nu"] = np.asarray(FIGURE1_NU)[df["curve"] - 1]
    df["twist_angle"] = twist_from_picture(df["picture_x"])
    df["p_star"] = p_star_from_picture(df["picture_y"])
    return df[list(COLUMNS)]


def figure1_path() -> Path:
    """The packaged digitised Figure 1 (a file inside the installed package: read it only)."""
    return Path(str(resources.files("spectral_rod") / "data" / "figure1_digitised.csv"))


def figure1_picture() -> str:
    """The paper's Figure 1 picture environment, verbatim (shipped with the package: the
    formatting of its lines is evidence for :mod:`spectral_rod.figure1_forensics`)."""
    return (resources.files("spectral_rod") / "data" / "figure1_picture.tex").read_text(
        encoding="utf-8")


def load_figure1(path: str | Path | None = None) -> pd.DataFrame:
    """The digitised Figure 1 (default: the packaged CSV), checked; errors name the file and
    the problem.

    >>> df = load_figure1()
    >>> len(df), sorted(df["nu"].unique().tolist())
    (1201, [1.1, 1.3, 1.5])
    """
    path = figure1_path() if path is None else Path(path)
    if not path.exists():
        raise FileNotFoundError(f"reference data file {path} is missing; regenerate it with "
                                f"`python reference_data/extract_figure1.py`")
    try:
        df = pd.read_csv(path)
    except Exception as exc:
        raise ValueError(f"{path}: not a readable CSV ({exc})") from exc
    missing = [c for c in COLUMNS if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (expected {list(COLUMNS)})")
    num = df[list(COLUMNS)].apply(pd.to_numeric, errors="coerce")
    if num.isna().any().any():
        bad = int(num.isna().any(axis=1).to_numpy().argmax())
        raise ValueError(f"{path}: non-numeric or empty value in data row {bad + 1}")
    if not set(num["curve"].unique()) <= {1, 2, 3}:
        raise ValueError(f"{path}: column 'curve' must be 1, 2 or 3")
    if not np.allclose(num["nu"], np.asarray(FIGURE1_NU)[num["curve"].astype(int) - 1]):
        raise ValueError(f"{path}: column 'nu' does not match curves 1,2,3 = nu {FIGURE1_NU}")
    if not (np.allclose(num["twist_angle"], twist_from_picture(num["picture_x"]))
            and np.allclose(num["p_star"], p_star_from_picture(num["picture_y"]))):
        raise ValueError(f"{path}: twist_angle/p_star do not follow from picture_x/picture_y "
                         f"(Omega = x/10, p* = 1 + y/400)")
    if not ((num["twist_angle"] >= 0) & (num["twist_angle"] <= 10)).all():
        raise ValueError(f"{path}: twist_angle outside the figure's range [0, 10]")
    num["curve"] = num["curve"].astype(int)
    return num
