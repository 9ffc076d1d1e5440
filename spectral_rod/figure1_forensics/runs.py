"""Two runs and clusters: a switch twist between two models per curve, runs of points a model
does not reproduce, and the straight chord between flanking points.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

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
    with s_first..s_last the splits reaching the largest count of reproduced points. Example:
    ok_low = [1, 1, 0, 0], ok_high = [0, 0, 1, 1] -> (2, 2, 4).
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

    Example: find_runs([0, 1, 1, 0, 1, 0, 0, 0, 1], 1) -> [(1, 4), (8, 8)].
    """
    idx = np.flatnonzero(np.asarray(bad, dtype=bool))
    if not idx.size:
        return []
    runs, first, last = [], int(idx[0]), int(idx[0])
    for i in idx[1:]:
        if i - last - 1 <= merge_gap:
            last = int(i)
        else:
            runs.append((first, last))
            first = last = int(i)
    runs.append((first, last))
    return runs


def chord_values(x: NDArray[np.float64], left: tuple[float, float], right: tuple[float, float]
                 ) -> NDArray[np.float64]:
    """y on the straight line through the flanking points `left` = (x0, y0), `right`."""
    (x0, y0), (x1, y1) = left, right
    return y0 + (y1 - y0) * (np.asarray(x, dtype=float) - x0) / (x1 - x0)


