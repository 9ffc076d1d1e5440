"""The LaTeX picture of Figure 1 as data: its point lines, their format, the x-grid and its gaps.

Picture coordinates, the print quantum and the dot size are those of
:mod:`spectral_rod.figure1.data` (Omega(L) = x/10, p* = 1 + y/400, two printed decimals), and so
is the parser (:func:`spectral_rod.figure1.data.picture_points`); this module adds the lines'
formatting.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from spectral_rod.figure1.data import FIGURE1_DOT, picture_environment, picture_points
from spectral_rod.figure1.forensics.runs import find_runs

#: The fixed-width format of the picture's point lines (Fortran-like F7.2, F8.2 fields).
PUT_FORMAT = "\\put(%7.2f,%8.2f){\\circle*{" + f"{FIGURE1_DOT:.1f}" + "}}"
#: Tolerance of "x lies on the grid" in grid steps (x is printed to 0.01, the grid step 0.25).
_ON_GRID = 1e-6

__all__ = ["PUT_FORMAT", "missing_grid_points", "off_grid_runs", "picture_environment",
           "picture_lines"]


def picture_lines(tex: str) -> pd.DataFrame:
    r"""One row per ``\put(x, y){\circle*...}`` line of the picture, in source order.

    Columns of :func:`spectral_rod.figure1.data.picture_points` (curve, line, picture_x,
    picture_y, text) plus trailing_blank (the line ends in a blank, as most lines do),
    after_blank_line (the previous line is empty: a block boundary), fixed_format (the line,
    without trailing blanks, is exactly :data:`PUT_FORMAT`).

    Returns
    -------
    pandas.DataFrame
        One row per ``\\put`` line with the columns above.

    Examples
    --------
    >>> put = PUT_FORMAT
    >>> tex = "\n".join(["\\begin{picture}(100,100)", put % (0.25, 0.1) + " ", "",
    ...                   put % (0.5, 0.2), put % (0.25, 5.0) + " ", put % (0.5, 5.1) + " ",
    ...                   put % (0.25, 9.0) + " ", "\\end{picture}"])
    >>> df = picture_lines(tex)
    >>> df["curve"].tolist(), df["line"].tolist(), df["trailing_blank"].tolist()
    ([1, 1, 2, 2, 3], [2, 4, 5, 6, 7], [True, False, True, True, True])
    >>> df["after_blank_line"].tolist(), df["fixed_format"].tolist()
    ([False, True, False, False, False], [True, True, True, True, True])
    """
    env = picture_environment(tex).splitlines()
    out = picture_points(tex)
    text, prev = out["text"], [env[k - 2] if k > 1 else "x" for k in out["line"]]
    out["trailing_blank"] = text.str.endswith(" ")
    out["after_blank_line"] = [not ln.strip() for ln in prev]
    out["fixed_format"] = [t.rstrip(" ") == PUT_FORMAT % (x, y) for t, x, y in
                           zip(text, out["picture_x"], out["picture_y"], strict=True)]
    return out[["curve", "line", "picture_x", "picture_y", "trailing_blank", "after_blank_line",
                "fixed_format", "text"]]


def _on_grid(x: NDArray[np.float64], step: float) -> NDArray[np.bool_]:
    return np.abs(x / step - np.round(x / step)) < _ON_GRID


def missing_grid_points(x: NDArray[np.float64], step: float | None = None
                        ) -> tuple[NDArray[np.float64], NDArray[np.float64], float | None]:
    """(grid points absent from x, x values off the grid, grid step) for one curve.

    The regular grid is step k, k = 1 .. round(max(x)/step), step the most common spacing of
    x (printed to 0.01, so compared to 1e-6). Without a step and fewer than two distinct x, or
    without any x, there is no grid: nothing is missing or off it (step None if not given).

    >>> missing, off, step = missing_grid_points([0.25, 0.5, 1.0, 1.1, 1.25, 1.5])
    >>> missing.tolist(), off.tolist(), step
    ([0.75], [1.1], 0.25)
    >>> missing_grid_points([0.25])
    (array([], dtype=float64), array([], dtype=float64), None)
    """
    x = np.asarray(x, dtype=float)
    if step is None:
        gaps, counts = np.unique(np.round(np.diff(np.sort(x)), 6), return_counts=True)
        counts[gaps <= 0] = 0  # repeated x are no spacing
        step = float(gaps[np.argmax(counts)]) if counts.any() else None
    if step is None or not x.size:
        return np.empty(0), np.empty(0), step
    grid = step * np.arange(1, round(x.max() / step) + 1)
    on = _on_grid(x, step)
    present = np.round(x[on] / step).astype(int)
    missing = grid[~np.isin(np.arange(1, grid.size + 1), present)]
    return missing, x[~on], step


def off_grid_runs(x: NDArray[np.float64], step: float) -> list[dict]:
    """Runs of consecutive off-grid x (source order) and how they subdivide their gap.

    For each run: its first/last x and count, the on-grid neighbours left/right, the spacing
    (right - left)/(count + 1) of an equal subdivision, and the largest |x - subdivision|.

    >>> (run,) = off_grid_runs([0.25, 0.33, 0.42, 0.5], 0.25)
    >>> run["count"], round(run["spacing"], 4), round(run["max_deviation"], 4)
    (2, 0.0833, 0.0033)
    """
    x = np.asarray(x, dtype=float)
    runs = []
    for first, last in find_runs(~_on_grid(x, step), merge_gap=0):
        if first == 0 or last == x.size - 1:
            continue  # no on-grid neighbour on one side
        left, right, n = x[first - 1], x[last + 1], last - first + 1
        sub = left + (right - left) * np.arange(1, n + 1) / (n + 1)
        runs.append({"first": float(x[first]), "last": float(x[last]), "count": n,
                     "left": float(left), "right": float(right),
                     "spacing": float((right - left) / (n + 1)),
                     "max_deviation": float(np.max(np.abs(x[first:last + 1] - sub)))})
    return runs
