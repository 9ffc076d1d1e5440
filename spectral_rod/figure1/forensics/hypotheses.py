"""The hypotheses, fitted: every quantisation, scan and variant model against the picture, and
the best two-run combination per curve.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import cast

import numpy as np
from numpy.typing import NDArray

from spectral_rod.figure1.data import FIGURE1_X_PER_TWIST, picture_y_from_p_star, twist_from_picture
from spectral_rod.figure1.forensics.quantisation import (
    ROUNDINGS,
    VARIABLES,
    Hypothesis,
    fit_quantisation,
    quantisation_model,
    quantise,
    reproduced,
)
from spectral_rod.figure1.forensics.runs import fit_switch
from spectral_rod.figure1.forensics.scan import (
    REPORT_RULES,
    RULES_BY_NAME,
    ScanResult,
    scan_model,
    scan_sign_change,
)

#: Scan variables: the load and the two coefficients of Eq. inst1, the coefficients scanned
#: from where they vanish (v >= 0).
SCAN_VARIABLES = (("lambda", False), ("lambda - nu Omega^2", True), ("lambda - Omega^2", True))
#: Approximations of pi tried in the normalisation p* = lambda / pi^2.
PI_APPROXIMATIONS = (3.14, 3.1416, 3.14159)
#: Twist offsets (in picture x units) tried for "the x coordinate is not the twist computed".
X_SHIFTS = (-0.125, 0.125)


def quantisation_hypotheses(p_true: NDArray, twist: NDArray, nu: NDArray, picture_y: NDArray
                            ) -> list[Hypothesis]:
    """Every variable x rounding rule of :data:`VARIABLES`, the step fitted on its grid."""
    return [fit_quantisation(p_true, twist, nu, picture_y, v, r)
            for v in VARIABLES for r in ROUNDINGS]


def _scan_hypothesis(scan: ScanResult, rule: str, twist: NDArray, nu: NDArray,
                     picture_y: NDArray, label: str = "", note: str = "") -> Hypothesis:
    y = scan_model(scan, rule, twist, nu)
    return Hypothesis(f"scan{label} {rule}({scan.variable}, {scan.step:g})", scan.variable,
                      scan.step, f"bracket {rule}", y, reproduced(y, picture_y),
                      f"first sign change of D_sym D_anti on {scan.variable} = k {scan.step:g}"
                      f", reported at {RULES_BY_NAME[rule].words}{note}", scan=scan, scan_rule=rule)


def scan_hypotheses(twist: NDArray, nu: NDArray, picture_y: NDArray, steps: dict[str, float]
                    ) -> list[Hypothesis]:
    """Scan simulations (real wavenumbers) on each scan variable's fitted ceil lattice, every
    report rule (the hypotheses share one scan per variable, :attr:`Hypothesis.scan`)."""
    hyps = []
    for var, start in SCAN_VARIABLES:
        scan = scan_sign_change(twist, nu, var, steps[var], start_at_zero=start)
        hyps += [_scan_hypothesis(scan, rule.name, twist, nu, picture_y) for rule in REPORT_RULES]
    return hyps


def variant_hypotheses(bases: list[Hypothesis], best_q: Hypothesis, p_true: NDArray,
                       twist: NDArray, nu: NDArray, picture_y: NDArray,
                       p_star_fn: Callable[[NDArray, NDArray], NDArray]) -> list[Hypothesis]:
    """Single precision, the continued (cosh/sinh) determinant, pi approximations, twist shifts.

    bases: scan hypotheses whose procedure is varied (single precision, continued
    determinant; the rest of its scan's settings and its report rule kept); best_q: the best
    quantisation hypothesis, varied in the normalisation (pi approximations in p* =
    lambda/pi^2) and in the twist (x shifted by X_SHIFTS).
    """
    out = []
    for base in bases:
        sc0 = cast(ScanResult, base.scan)  # bases are scan hypotheses
        for label, kw, note in (
                (" single", {"dtype": np.float32}, " (single precision)"),
                (" continued", {"real_wavenumbers": False},
                 " (determinant continued to X_- < 0 by cosh/sinh: imaginary beta_1 handled)")):
            sc = scan_sign_change(twist, nu, sc0.variable, sc0.step, **sc0.settings(**kw))
            out.append(_scan_hypothesis(sc, cast(str, base.scan_rule), twist, nu, picture_y,
                                        label, note))
    var, step = VARIABLES[best_q.variable], cast(float, best_q.step)  # a quantisation: one step
    p_q = var.inverse(quantise(var.forward(p_true, twist, nu), step, best_q.rounding),
                      twist, nu)
    lam = VARIABLES["lambda"].forward(p_q, twist, nu)
    for pa in PI_APPROXIMATIONS:
        y = picture_y_from_p_star(lam / pa**2)
        out.append(Hypothesis(f"{best_q.name} with pi = {pa}", best_q.variable, best_q.step,
                              best_q.rounding, y, reproduced(y, picture_y),
                              f"{best_q.description}, converted to p* with pi = {pa}"))
    for dx in X_SHIFTS:
        tw = twist + twist_from_picture(dx)
        y = quantisation_model(p_star_fn(tw, nu), tw, nu, best_q.variable, step,
                               best_q.rounding)
        at = f"(x {dx:+g})/{FIGURE1_X_PER_TWIST:g}"
        out.append(Hypothesis(f"{best_q.name} at Omega = {at}", best_q.variable,
                              best_q.step, best_q.rounding, y, reproduced(y, picture_y),
                              f"{best_q.description}, computed at twist {at}"))
    return out


def best_two_runs(hyps: list[Hypothesis], twist: NDArray, curve: NDArray, label: str = "",
                  edited: NDArray[np.bool_] | None = None
                  ) -> tuple[Hypothesis, Hypothesis, Hypothesis, dict[int, tuple[int, int]]]:
    """The pair (low, high) of hypotheses and per-curve switch accounting for the most points.

    Every ordered pair is tried with :func:`fit_switch` on each curve (the earliest optimal
    split is used); a point counts if reproduced or, with `edited` given, if the model
    yields no value where the line was inserted separately (:meth:`Hypothesis.credit`). Returns
    (composite, low, high, {curve: (s_first, s_last)}).
    """
    best: tuple[int, Hypothesis, Hypothesis, dict[int, tuple[int, int, int]]] | None = None
    credit = {id(h): h.credit(edited) for h in hyps}
    for lo in hyps:
        for hi in hyps:
            if lo is hi:
                continue
            cl, ch = credit[id(lo)], credit[id(hi)]
            fits = {c: fit_switch(twist[curve == c], cl[curve == c], ch[curve == c])
                    for c in np.unique(curve)}
            total = sum(f[2] for f in fits.values())
            if best is None or total > best[0]:
                best = (total, lo, hi, fits)
    assert best is not None  # fewer than two hypotheses: no pair to try
    _, lo, hi, fits = best
    steps = [cast(float, lo.step), cast(float, hi.step)]  # single-model hypotheses: one step
    y, ok = np.empty_like(lo.y_model), np.empty_like(lo.ok)
    for c, (s, _, _) in fits.items():
        idx = np.flatnonzero(curve == c)
        y[idx] = np.concatenate([lo.y_model[idx[:s]], hi.y_model[idx[s:]]])
        ok[idx] = np.concatenate([lo.ok[idx[:s]], hi.ok[idx[s:]]])
    comp = Hypothesis(f"two runs{label}: {lo.name} below the switch, {hi.name} above",
                      f"{lo.variable} | {hi.variable}", steps,
                      f"{lo.rounding} | {hi.rounding}", y, ok,
                      f"low twist: {lo.description}; high twist: {hi.description}; switch "
                      f"fitted per curve")
    return comp, lo, hi, {c: (f[0], f[1]) for c, f in fits.items()}
