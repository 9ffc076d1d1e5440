"""Figure 1 of the paper as data: parse the LaTeX `picture`, load and validate the CSV.

The digitised points ship with the package (``spectral_rod/data/figure1_digitised.csv``, with
its provenance ``figure1_digitised.md`` and its schema ``figure1_digitised.json``, a Frictionless
tabular data resource: field names, units, source figure, curves, quantisation);
:func:`load_figure1` reads them through ``importlib.resources``, so an installed package needs no
source checkout and no paper, and validates any file against that schema: an error
(:class:`ReferenceDataError`, a ``ValueError``) names the file and the problem.

The figure is drawn with ``\\put(x, y){\\circle*{1.0}}`` in a 100 x 100 box: Omega(L) = x/10
(0..10) and p* = 1 + y/400 (1.00..1.25). The three curves follow each other in the source;
a new curve starts where x falls back to the left edge. Curves 1, 2, 3 are nu = 1.1, 1.3, 1.5.
"""

from __future__ import annotations

import json
import os
import re
from functools import cache
from importlib import resources
from pathlib import Path
from typing import overload

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from spectral_rod.errors import ReferenceDataError

#: nu = I2/I1 (dimensionless) of Figure 1's curves 1, 2, 3, in source order.
FIGURE1_NU = (1.1, 1.3, 1.5)
COLUMNS = ("curve", "nu", "picture_x", "picture_y", "twist_angle", "p_star")
#: Picture x units per radian of Omega(L), and picture y units per unit of p*: Omega(L) = x/10,
#: p* = 1 + y/400 (the schema's ``x-figure1.axes``).
FIGURE1_X_PER_TWIST, FIGURE1_Y_PER_P = 10.0, 400.0
#: Quantum of the picture's coordinates (printed with two decimals; the schema's
#: ``picture_unit_step``): the print quantum.
FIGURE1_PRINT_QUANTUM = 0.01
#: Diameter of a plotted dot (``\circle*{1.0}``) in picture units: what a reader can see (the
#: schema's ``dot_diameter``).
FIGURE1_DOT = 1.0
#: One point line of the picture: ``\put(x, y){\circle*...``.
_PUT = re.compile(r"^\\put\(\s*([-+0-9.]+)\s*,\s*([-+0-9.]+)\s*\)\s*\{\\circle\*")


def twist_from_picture(x: float | np.ndarray) -> float | np.ndarray:
    """Omega(L) from the picture's x coordinate (the axis runs 0..100 for 0.0..10.0).

    >>> twist_from_picture(31.25)
    3.125
    """
    return x / FIGURE1_X_PER_TWIST


@overload
def p_star_from_picture(y: np.ndarray) -> NDArray[np.float64]: ...
@overload
def p_star_from_picture(y: float) -> float: ...
def p_star_from_picture(y: float | np.ndarray) -> float | np.ndarray:
    """p* from the picture's y coordinate (the axis runs 0..100 for 1.00..1.25).

    >>> p_star_from_picture(10.0)
    1.025
    """
    return 1.0 + y / FIGURE1_Y_PER_P


@overload
def picture_y_from_p_star(p: np.ndarray) -> NDArray[np.float64]: ...
@overload
def picture_y_from_p_star(p: float) -> float: ...
def picture_y_from_p_star(p: float | np.ndarray) -> float | np.ndarray:
    """The picture's y coordinate of the load p* (the inverse of :func:`p_star_from_picture`).

    >>> round(float(picture_y_from_p_star(p_star_from_picture(18.98))), 9)
    18.98
    """
    return FIGURE1_Y_PER_P * (np.asarray(p, dtype=float) - 1.0)


def picture_environment(tex: str) -> str:
    r"""The lines from ``\begin{picture}`` to ``\end{picture}`` (inclusive), verbatim.

    >>> picture_environment(figure1_picture()).count(r"\circle*")
    1201
    """
    if not isinstance(tex, str):
        raise TypeError(f"tex must be the LaTeX source as a str, got {type(tex).__name__}")
    lines = tex.splitlines(keepends=True)
    begin = next((i for i, ln in enumerate(lines) if r"\begin{picture}" in ln), None)
    end = next((i for i, ln in enumerate(lines) if r"\end{picture}" in ln), None)
    if begin is None or end is None or end < begin:
        raise ValueError("tex: no \\begin{picture} ... \\end{picture} environment found")
    return "".join(lines[begin:end + 1])


def picture_points(tex: str) -> pd.DataFrame:
    r"""One row per ``\put(x, y){\circle*...}`` line of the picture environment, in source
    order: curve (1..3, a new curve where x falls back to the left), line (1-based line number
    within the environment), picture_x, picture_y, text (the line verbatim). The one parser of
    the picture (:func:`parse_figure1`, :func:`spectral_rod.figure1.forensics.picture_lines`).

    >>> picture_points(figure1_picture()).groupby("curve").size().tolist()
    [402, 399, 400]
    """
    env = picture_environment(tex).splitlines()
    rows, curve, last_x = [], 0, np.inf
    for k, text in enumerate(env):
        m = _PUT.match(text)
        if not m:
            continue
        x, y = float(m.group(1)), float(m.group(2))
        if x < last_x:  # x restarts at the left edge: next curve
            curve += 1
        last_x = x
        rows.append((curve, k + 1, x, y, text))
    if not rows:
        raise ValueError("no \\put(x,y){\\circle*} points found in the picture environment")
    if curve != len(FIGURE1_NU):
        raise ValueError(f"expected {len(FIGURE1_NU)} curves in Figure 1, found {curve}")
    return pd.DataFrame(rows, columns=["curve", "line", "picture_x", "picture_y", "text"])


def parse_figure1(tex: str) -> pd.DataFrame:
    """All filled circles of the paper's picture environment as a DataFrame (COLUMNS)."""
    df = picture_points(tex)[["curve", "picture_x", "picture_y"]]
    df["nu"] = np.asarray(FIGURE1_NU)[df["curve"] - 1]
    df["twist_angle"] = twist_from_picture(df["picture_x"])
    df["p_star"] = p_star_from_picture(df["picture_y"])
    return df[list(COLUMNS)]


def figure1_path() -> Path:
    """The packaged digitised Figure 1 (a file inside the installed package: read it only)."""
    return Path(str(resources.files("spectral_rod") / "data" / "figure1_digitised.csv"))


def figure1_picture(path: str | Path | None = None) -> str:
    """The paper's Figure 1 picture environment, verbatim (default: the packaged
    ``figure1_picture.tex``; the formatting of its lines is evidence for
    :mod:`spectral_rod.figure1.forensics`), checked before it is returned: it must hold one
    ``picture`` environment whose ``\\put`` points form the schema's three curves with their
    point counts and are the packaged digitised points (:func:`load_figure1`). A truncated,
    garbled, edited or unreadable file raises :class:`ReferenceDataError`
    (``FileNotFoundError`` if it is missing) naming the file and the problem.

    Returns
    -------
    str
        The LaTeX text of the ``picture`` environment.

    Examples
    --------
    >>> figure1_picture().count(r"\\circle*")
    1201
    """
    if path is not None and not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a str or os.PathLike, got {type(path).__name__}")
    source = resources.files("spectral_rod") / "data" / "figure1_picture.tex"
    where = Path(str(source)) if path is None else Path(path)
    try:
        tex = (source if path is None else where).read_text(encoding="utf-8")
    except FileNotFoundError as exc:
        raise FileNotFoundError(f"the LaTeX picture of Figure 1, {where}, is missing") from exc
    except UnicodeDecodeError as exc:
        raise ReferenceDataError(f"{where}: not UTF-8 text ({exc})") from exc
    except IsADirectoryError as exc:
        raise ReferenceDataError(f"{where} is a directory, not the LaTeX picture of "
                                 f"Figure 1") from exc
    _check_picture(tex, where)
    return tex


def check_picture_matches(picture: pd.DataFrame, points: pd.DataFrame,
                          where: str | Path = "figure1_picture.tex") -> None:
    """ReferenceDataError naming `where` unless the picture's points (:func:`picture_points`)
    are the digitised points (:func:`load_figure1`), one for one in source order."""
    a = picture[["picture_x", "picture_y"]].to_numpy(dtype=float)
    b = points[["picture_x", "picture_y"]].to_numpy(dtype=float)
    if a.shape != b.shape or not np.allclose(a, b, rtol=0, atol=1e-9):
        raise ReferenceDataError(f"{where}: its \\put points are not the digitised points of "
                                 f"figure1_digitised.csv (garbled or edited file?)")


def _check_picture(tex: str, where: Path) -> None:
    """The picture's points against the schema's curves (ReferenceDataError naming `where`)."""
    try:
        pts = picture_points(tex)
    except ValueError as exc:
        raise ReferenceDataError(f"{where}: {exc} (truncated or garbled file?)") from exc
    counts = pts.groupby("curve").size().to_dict()
    for spec in figure1_schema()["x-figure1"]["curves"]:
        got = int(counts.get(spec["curve"], 0))
        if got != spec["points"]:
            raise ReferenceDataError(f"{where}: curve {spec['curve']} (nu = {spec['nu']}) has "
                                     f"{got} \\put points, expected {spec['points']} (truncated "
                                     f"or garbled file?)")
    check_picture_matches(pts, load_figure1(), where)


@cache
def figure1_schema() -> dict:
    """The packaged schema of the digitised Figure 1 (``figure1_digitised.json``)."""
    text = (resources.files("spectral_rod") / "data" / "figure1_digitised.json").read_text(
        encoding="utf-8")
    return json.loads(text)


def _read_table(path: Path) -> pd.DataFrame:
    """The CSV as text cells, with its header checked against the schema's field names."""
    if not path.exists():
        raise FileNotFoundError(f"reference data file {path} is missing; regenerate it with "
                                f"`python reference_data/extract_figure1.py`")
    if path.is_dir():
        raise ReferenceDataError(f"{path} is a directory, not the CSV file of Figure 1")
    try:
        df = pd.read_csv(path, dtype=str, keep_default_na=False)
    except pd.errors.EmptyDataError as exc:
        raise ReferenceDataError(f"{path}: empty file, not a readable CSV (no header, no "
                                 f"data)") from exc
    except (ValueError, UnicodeDecodeError, pd.errors.ParserError) as exc:
        raise ReferenceDataError(f"{path}: not a readable CSV ({exc})") from exc
    fields = [f["name"] for f in figure1_schema()["schema"]["fields"]]
    if list(df.columns) != fields:
        missing = [c for c in fields if c not in df.columns]
        raise ReferenceDataError(f"{path}: columns {list(df.columns)} do not match the schema "
                                 f"{fields}" + (f" (missing columns {missing})" if missing else ""))
    if df.empty:
        raise ReferenceDataError(f"{path}: header only, no data rows")
    return df


def _numeric(df: pd.DataFrame, path: Path) -> pd.DataFrame:
    """Every cell as a finite number, within its field's constraints (errors name the row)."""
    num = df.apply(pd.to_numeric, errors="coerce")
    bad = ~np.isfinite(num.to_numpy(dtype=float))
    if bad.any():
        row, col = np.argwhere(bad)[0]
        raise ReferenceDataError(f"{path}: data row {row + 1}, column {df.columns[col]!r}: "
                                 f"{df.iat[row, col]!r} is non-numeric, empty or not finite")
    for f in figure1_schema()["schema"]["fields"]:
        c, v = f["constraints"], num[f["name"]]
        ok = v.between(c.get("minimum", -np.inf), c.get("maximum", np.inf))
        if "enum" in c:
            ok &= np.isclose(v.to_numpy()[:, None], np.asarray(c["enum"])[None, :]).any(axis=1)
        if not ok.all():
            row = int(np.flatnonzero(~ok.to_numpy())[0])
            raise ReferenceDataError(f"{path}: data row {row + 1}: {f['name']} = {v.iloc[row]} "
                                     f"breaks the schema ({c})")
    return num


def _check_consistency(num: pd.DataFrame, path: Path) -> None:
    """Curve -> nu, picture -> (Omega, p*) mapping and the two-decimal picture grid."""
    if not np.allclose(num["nu"], np.asarray(FIGURE1_NU)[num["curve"].astype(int) - 1]):
        raise ReferenceDataError(f"{path}: column 'nu' does not match curves 1,2,3 = nu "
                                 f"{FIGURE1_NU}")
    if not (np.allclose(num["twist_angle"], twist_from_picture(num["picture_x"]))
            and np.allclose(num["p_star"], p_star_from_picture(num["picture_y"]))):
        raise ReferenceDataError(f"{path}: twist_angle/p_star do not follow from "
                                 f"picture_x/picture_y (Omega = x/{FIGURE1_X_PER_TWIST:g}, "
                                 f"p* = 1 + y/{FIGURE1_Y_PER_P:g})")
    xy = num[["picture_x", "picture_y"]].to_numpy() / FIGURE1_PRINT_QUANTUM
    if not np.allclose(xy, np.round(xy), rtol=0, atol=1e-6):
        raise ReferenceDataError(f"{path}: picture coordinates are not on the "
                                 f"{FIGURE1_PRINT_QUANTUM} grid the paper prints")


def _check_curves(num: pd.DataFrame, path: Path) -> None:
    """No duplicates; curves in order with the schema's point counts; x strictly increasing
    within a curve by one of the schema's steps (the paper's grid has a few irregular ones)."""
    dup = num.duplicated(subset=["curve", "picture_x"], keep="first").to_numpy()
    if dup.any():
        raise ReferenceDataError(f"{path}: {int(dup.sum())} duplicated (curve, picture_x) "
                                 f"row(s), the first at data row {int(np.argmax(dup)) + 1}")
    curve = num["curve"].to_numpy()
    if (np.diff(curve) < 0).any():
        raise ReferenceDataError(f"{path}: rows are not grouped by curve 1, 2, 3 in order")
    meta = figure1_schema()["x-figure1"]
    for spec in meta["curves"]:
        count = int((curve == spec["curve"]).sum())
        if count != spec["points"]:
            raise ReferenceDataError(f"{path}: curve {spec['curve']} (nu = {spec['nu']}) has "
                                     f"{count} points, expected {spec['points']} (truncated or "
                                     f"edited file?)")
    steps = np.asarray(meta["x_steps"]["picture_units"])
    for c, x in num.groupby("curve")["picture_x"]:
        dx = np.diff(x.to_numpy())
        odd = ~np.isclose(dx[:, None], steps[None, :], rtol=0, atol=1e-9).any(axis=1)
        if odd.any():
            at = float(x.to_numpy()[int(np.argmax(odd))])
            raise ReferenceDataError(f"{path}: curve {c}: x step {dx[np.argmax(odd)]:g} after "
                                     f"picture_x = {at:g} is not one of {steps.tolist()} (x "
                                     f"must increase strictly along the paper's grid)")


def load_figure1(path: str | Path | None = None) -> pd.DataFrame:
    """The digitised Figure 1 (default: the packaged CSV), validated against the packaged
    schema; errors (:class:`ReferenceDataError`, ``FileNotFoundError``) name the file and the
    problem.

    Returns
    -------
    pandas.DataFrame
        One row per digitised point (the schema's columns, among them twist, nu and p_star).

    Examples
    --------
    >>> df = load_figure1()
    >>> len(df), sorted(df["nu"].unique().tolist())
    (1201, [1.1, 1.3, 1.5])
    """
    if path is not None and not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be None, a str or a path, got {type(path).__name__}")
    if isinstance(path, str) and not path.strip():
        raise ValueError("path must name a CSV file (or be None for the packaged one), got ''")
    path = figure1_path() if path is None else Path(path)
    num = _numeric(_read_table(path), path)
    _check_consistency(num, path)
    _check_curves(num, path)
    num["curve"] = num["curve"].astype(int)
    return num
