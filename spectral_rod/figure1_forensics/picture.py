"""The LaTeX picture of Figure 1 as data: its point lines, their format, the x-grid and its gaps.

Picture coordinates: Omega(L) = x/10, p* = 1 + y/400, two printed decimals
(:mod:`spectral_rod.figure_data`).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from spectral_rod.figure1_forensics.runs import find_runs
from spectral_rod.figure_data import FIGURE1_NU

#: Picture y units per unit of p* (p* = 1 + y/400, :mod:`spectral_rod.figure_data`).
Y_PER_P = 400.0
#: Picture x units per radian of Omega(L).
X_PER_TWIST = 10.0
#: The print quantum of the picture coordinates (two decimals).
PRINT_QUANTUM = 0.01
#: Diameter of a plotted dot (\circle*{1.0}) in picture units: what the reader can see.
DOT = 1.0
_PUT_LINE = re.compile(r"^\\put\(\s*([-+0-9.]+)\s*,\s*([-+0-9.]+)\s*\)\s*\{\\circle\*")
#: The fixed-width format of the picture's point lines (Fortran-like F7.2, F8.2 fields).
PUT_FORMAT = "\\put(%7.2f,%8.2f){\\circle*{1.0}}"

def picture_environment(tex: str) -> str:
    r"""The lines from ``\begin{picture}`` to ``\end{picture}`` (inclusive), verbatim.

    Example: ``picture_environment(open(paper).read()).count(r"\circle*") == 1201``.
    """
    if not isinstance(tex, str):
        raise TypeError(f"tex must be the LaTeX source as a str, got {type(tex).__name__}")
    lines = tex.splitlines(keepends=True)
    begin = next((i for i, ln in enumerate(lines) if r"\begin{picture}" in ln), None)
    end = next((i for i, ln in enumerate(lines) if r"\end{picture}" in ln), None)
    if begin is None or end is None or end < begin:
        raise ValueError("tex: no \\begin{picture} ... \\end{picture} environment found")
    return "".join(lines[begin:end + 1])


def picture_lines(tex: str) -> pd.DataFrame:
    r"""One row per ``\put(x, y){\circle*...}`` line of the picture, in source order.

    Columns: curve (1..3, a new curve where x falls back), line (1-based line number within
    the picture environment), picture_x, picture_y, trailing_blank (the line ends in a blank,
    as most lines do), after_blank_line (the previous line is empty: a block boundary),
    fixed_format (the line, without trailing blanks, is exactly :data:`PUT_FORMAT`), text (the
    line verbatim).
    """
    env = picture_environment(tex).splitlines()
    rows, curve, last_x = [], 0, math.inf
    for k, text in enumerate(env):
        m = _PUT_LINE.match(text)
        if not m:
            continue
        x, y = float(m.group(1)), float(m.group(2))
        if x < last_x:
            curve += 1
        last_x = x
        rows.append((curve, k + 1, x, y, text.endswith(" "), k > 0 and not env[k - 1].strip(),
                     text.rstrip(" ") == PUT_FORMAT % (x, y), text))
    if curve != len(FIGURE1_NU):
        raise ValueError(f"tex: expected {len(FIGURE1_NU)} curves in the picture, found {curve}")
    return pd.DataFrame(rows, columns=["curve", "line", "picture_x", "picture_y",
                                       "trailing_blank", "after_blank_line", "fixed_format",
                                       "text"])


def missing_grid_points(x: NDArray[np.float64], step: float | None = None
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64], float]:
    """(grid points absent from x, x values off the grid, grid step) for one curve.

    The regular grid is step k, k = 1 .. round(max(x)/step), step the most common spacing of
    x (printed to 0.01, so compared to 1e-6). Example: x = [0.25, 0.5, 1.0] -> ([0.75], [], 0.25).
    """
    x = np.asarray(x, dtype=float)
    if step is None:
        gaps, counts = np.unique(np.round(np.diff(np.sort(x)), 6), return_counts=True)
        step = float(gaps[np.argmax(counts)])
    grid = step * np.arange(1, round(x.max() / step) + 1)
    on = np.abs(x / step - np.round(x / step)) < 1e-6
    present = np.round(x[on] / step).astype(int)
    missing = grid[~np.isin(np.arange(1, grid.size + 1), present)]
    return missing, x[~on], step


def off_grid_runs(x: NDArray[np.float64], step: float) -> list[dict]:
    """Runs of consecutive off-grid x (source order) and how they subdivide their gap.

    For each run: its first/last x and count, the on-grid neighbours left/right, the spacing
    (right - left)/(count + 1) of an equal subdivision, and the largest |x - subdivision|.
    Example: x = [0.25, 0.33, 0.42, 0.5], step 0.25 -> one run of 2 with spacing 0.0833.
    """
    x = np.asarray(x, dtype=float)
    off = np.abs(x / step - np.round(x / step)) >= 1e-6
    runs = []
    for first, last in find_runs(off, merge_gap=0):
        if first == 0 or last == x.size - 1:
            continue  # no on-grid neighbour on one side
        left, right, n = x[first - 1], x[last + 1], last - first + 1
        sub = left + (right - left) * np.arange(1, n + 1) / (n + 1)
        runs.append({"first": float(x[first]), "last": float(x[last]), "count": n,
                     "left": float(left), "right": float(right),
                     "spacing": float((right - left) / (n + 1)),
                     "max_deviation": float(np.max(np.abs(x[first:last + 1] - sub)))})
    return runs


