r"""Figure 1 point by point: how the published values were produced, and why each one differs.

The paper's Figure 1 (p* against Omega(L) for nu = 1.1, 1.3, 1.5; hinged straight rod, Eq.
``inst1``, characteristic equation of :mod:`spectral_rod.rod.characteristic`) is a LaTeX picture of
``\put(x, y){\circle*{1.0}}`` lines, Omega(L) = x/10 and p* = 1 + y/400, printed with two
decimals (:mod:`spectral_rod.figure1.data`). Against the converged p* (the truth here) every
printed point is either *reproduced exactly* -- the same two-decimal y -- by a stated model of
the authors' procedure, or it belongs to a cluster or a missing grid point whose cause is
computed. Nothing below is fitted to a single point; every interval and count comes from code.

Models tested
-------------
* **Quantisation** of a variable v(p*) -- p*, lambda = pi^2 p*, the picture y = 400 (p* - 1)
  (p* - 1 needs no variable of its own: its lattices are p*'s, 1 being a multiple of every
  candidate step), and the two coefficients of Eq. ``inst1``, P - A2 omega30^2 and P - A1 omega30^2
  (lambda - nu Omega^2 and lambda - Omega^2 in units A1/L^2) -- onto the lattice k h (nearest,
  floor, ceil, truncation), h on a fixed grid of candidate steps (m 10^e, m in 1, 2, 2.5, 4, 5),
  then printed with two decimals. The step is fitted per variable and rounding rule.
* **Sign-change scan** (the paper's "standard methods"): step v through the lattice, evaluate
  the sign of the 4x4 boundary determinant (= 16 Omega^2 D_sym D_anti,
  :func:`spectral_rod.rod.characteristic_mode.boundary_determinant_4x4`; here D_sym D_anti in double
  precision from :func:`spectral_rod.rod.characteristic.determinants`), stop at the first sign
  change
  and report the bracket's upper end, lower end, midpoint or linear interpolation. Variants:
  the determinant written with *real* wavenumbers beta_k = sqrt(X_k) (undefined, NaN, where
  X_- < 0), single precision, and the lattice start v >= 0 for the coefficient variables (the
  scan begins where the coefficient vanishes). Each scan variable is stepped on the lattice that
  the ceil quantisation of the converged p* fits best (so the step comes from p*), but the
  scan's value does not: it comes from the determinant's signs alone, so the scan can fail (no
  sign change, or a wrong root), and where it fails is a prediction to compare with where the
  data are irregular.
* **Two runs**: one model below a switch twist and another above it, the switch fitted per
  curve (every split of the sorted twists is tried), for every ordered pair of hypotheses.

The *best* model is the two-run combination of scan (procedure) hypotheses that accounts for
the most points: reproduced exactly, or -- where the scan yields no value -- the LaTeX line was
inserted separately (:meth:`Hypothesis.credit`). A procedure must say where it fails; a quantisation
model yields a value everywhere and so also matches inserted values by coincidence (its best
two-run combination is reported alongside, with the count of such coincidences visible in the
window column of the table).

Beyond the model
----------------
Contiguous runs of points the best model does not reproduce (merged across at most
:data:`MERGE_GAP` reproduced points) are *clusters*; points of the regular x-grid absent from the
picture are *missing points*. Each gets computed evidence: the imaginary-beta_1 window
(:func:`spectral_rod.imaginary_beta1_window`, and X_- < 0 at the point itself), both families'
lowest roots in one scan step (a double sign change, invisible to a sign scan; family crossings
:func:`spectral_rod.rod.closed_form.crossing_closed_form`), the scan's own result there, and the
LaTeX lines themselves (lines without the trailing blank of the program's lines, blank-line
block boundaries, off-grid x) and what was printed instead (a straight line between the
flanking computed points to the print precision -- :func:`straight_line`, slips set
aside --, a flanking value, or the lattice point below both roots).

Modules
-------
One step of the analysis each: :mod:`.picture` (the LaTeX lines as data), :mod:`.physics`
(wavenumbers and family loads at a point), :mod:`.quantisation`, :mod:`.scan` (the sign-change
procedure), :mod:`.runs` (switches and clusters), :mod:`.hypotheses` (all models fitted),
:mod:`.explain` (causes of each cluster and missing point), :mod:`.analysis`
(:func:`analyse_figure1`). The public names below are re-exported here; the helpers stay in
their modules.
"""

from __future__ import annotations

from spectral_rod.figure1.forensics.analysis import Forensics, analyse_figure1
from spectral_rod.figure1.forensics.explain import (
    CAUSE_DOUBLE_ROOT,
    CAUSE_EDITED,
    CAUSE_IMAGINARY_BETA1,
    CAUSE_NO_SIGN_CHANGE,
    CLUSTER_DOUBLE_ROOT,
    CLUSTER_EDITED,
    CLUSTER_KINDS,
    CLUSTER_NO_SIGN_CHANGE,
    CLUSTER_UNEXPLAINED,
    CLUSTER_WINDOW,
    POINT_CAUSES,
    explain_cluster,
    explain_missing,
    site_physics,
    straight_line,
)
from spectral_rod.figure1.forensics.hypotheses import (
    best_two_runs,
    quantisation_hypotheses,
    scan_hypotheses,
    variant_hypotheses,
)
from spectral_rod.figure1.forensics.physics import family_loads, twist_ranges
from spectral_rod.figure1.forensics.picture import (
    missing_grid_points,
    off_grid_runs,
    picture_environment,
    picture_lines,
)
from spectral_rod.figure1.forensics.quantisation import (
    Hypothesis,
    fit_quantisation,
    printed,
    quantise,
    reproduced,
)
from spectral_rod.figure1.forensics.runs import MERGE_GAP, find_runs, fit_switch
from spectral_rod.figure1.forensics.scan import ScanResult, determinant_product, scan_sign_change

__all__ = [
    "CAUSE_DOUBLE_ROOT",
    "CAUSE_EDITED",
    "CAUSE_IMAGINARY_BETA1",
    "CAUSE_NO_SIGN_CHANGE",
    "CLUSTER_DOUBLE_ROOT",
    "CLUSTER_EDITED",
    "CLUSTER_KINDS",
    "CLUSTER_NO_SIGN_CHANGE",
    "CLUSTER_UNEXPLAINED",
    "CLUSTER_WINDOW",
    "MERGE_GAP",
    "POINT_CAUSES",
    "Forensics",
    "Hypothesis",
    "ScanResult",
    "analyse_figure1",
    "best_two_runs",
    "determinant_product",
    "explain_cluster",
    "explain_missing",
    "family_loads",
    "find_runs",
    "fit_quantisation",
    "fit_switch",
    "missing_grid_points",
    "off_grid_runs",
    "picture_environment",
    "picture_lines",
    "printed",
    "quantisation_hypotheses",
    "quantise",
    "reproduced",
    "scan_hypotheses",
    "scan_sign_change",
    "site_physics",
    "straight_line",
    "twist_ranges",
    "variant_hypotheses",
]
