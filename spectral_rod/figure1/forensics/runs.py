"""Two runs and clusters: a switch twist between two models per curve, runs of points a model
does not reproduce, their flanking points, and the straight chord between them.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["MERGE_GAP", "chord_values", "find_runs", "fit_switch", "flank_positions"]

#: Non-reproduced runs separated by at most this many reproduced points form one cluster.
#: Why: inside an inserted block a model that always yields a value (a quantisation model)
#: agrees with an inserted value by chance with probability about (print quantum)/(its lattice step
#: in y), 0.01/0.04 ... 0.01/0.08, so a run can be split by one or two coincidences. For the
#: scan model of Figure 1 the clusters are contiguous: the same clusters for gaps 0 to 5
#: (measured when this was written).
MERGE_GAP = 2


def fit_switch(twist: NDArray[np.float64], ok_low: NDArray[np.bool_], ok_high: NDArray[np.bool_]
               ) -> tuple[int, int, int]:
    """Best split of one curve's points (sorted by twist) between two models.

    Points [0, s) use the low model and [s, n) the high one; returns (s_first, s_last, count)
    with s_first..s_last the splits reaching the largest count of reproduced points.

    >>> fit_switch(np.arange(4.0), np.array([1, 1, 0, 0]), np.array([0, 0, 1, 1]))
    (2, 2, 4)
    """
    if np.any(np.diff(twist) < 0):
        raise ValueError("twist must be sorted (one curve in source order)")
    low = np.concatenate([[0], np.cumsum(ok_low)])
    high = np.concatenate([np.cumsum(ok_high[::-1])[::-1], [0]])
    count = low + high
    best = np.flatnonzero(count == count.max())
    return int(best[0]), int(best[-1]), int(count.max())


def find_runs(bad: NDArray[np.bool_], merge_gap: int = MERGE_GAP) -> list[tuple[int, int]]:
    """Index ranges [first, last] of runs of True, merging runs separated by <= merge_gap False.

    >>> bad = np.array([0, 1, 1, 0, 1, 0, 0, 0, 1])
    >>> find_runs(bad, 1), find_runs(bad, 0)
    ([(1, 4), (8, 8)], [(1, 2), (4, 4), (8, 8)])
    """
    b = np.concatenate([[False], np.asarray(bad, dtype=bool), [False]])
    edges = np.flatnonzero(b[1:] != b[:-1])
    runs: list[tuple[int, int]] = []
    for f, e in zip(edges[::2].tolist(), edges[1::2].tolist(), strict=True):
        if runs and f - runs[-1][1] - 1 <= merge_gap:
            runs[-1] = (runs[-1][0], e - 1)
        else:
            runs.append((f, e - 1))
    return runs


def flank_positions(ok: NDArray[np.bool_], first: int, last: int) -> tuple[int | None, int | None]:
    """Positions of the nearest True of `ok` before `first` and after `last` (None if none).

    >>> flank_positions(np.array([1, 0, 0, 1, 0, 1], dtype=bool), 1, 2)
    (0, 3)
    """
    ok = np.asarray(ok, dtype=bool)
    before, after = np.flatnonzero(ok[:first]), np.flatnonzero(ok[last + 1:]) + last + 1
    return (int(before[-1]) if before.size else None, int(after[0]) if after.size else None)


def chord_values(x: NDArray[np.float64], left: tuple[float, float], right: tuple[float, float]
                 ) -> NDArray[np.float64]:
    """y on the straight line through the flanking points `left` = (x0, y0), `right`.

    >>> chord_values(np.array([1.0, 2.0]), (0.0, 0.0), (4.0, 2.0)).tolist()
    [0.5, 1.0]
    """
    (x0, y0), (x1, y1) = left, right
    return y0 + (y1 - y0) * (np.asarray(x, dtype=float) - x0) / (x1 - x0)
