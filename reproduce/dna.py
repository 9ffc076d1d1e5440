"""Scene `dna`: the paper's motivation at its physical scale -- Figure 1's twist axis in lengths
of B-DNA, and which part of Figure 1 a DNA segment can reach within the rod model's validity.

Models: the hinged straight rod with spontaneous twist (Eq. ``inst1``), p*(Omega(L), nu) by
:func:`spectral_rod.critical_load`; the spontaneous twist of B-DNA is one turn per helical
repeat h, so omega30 = 2 pi / h and Omega(L) = 2 pi L / h.
Compares: the lengths at which Figure 1's range (Omega(L) <= 10) ends with the lengths at which
the rod model applies (L >> a: here L >= :data:`VALIDITY_DIAMETERS` diameters) and at which a
static (athermal) buckling analysis is meaningful (L up to the persistence length); p* there
against the large-twist limit p_inf = 2 nu / (1 + nu) (claims row ``rod-limit``).
Writes: dna.json (the literature values used, the twist-to-length conversion, the window), the
ledger row ``caveat-dna-scale`` (a modelling caveat: which part of Figure 1 DNA reaches) and the
report section.

Literature values (cited, not fetched; each is an assumption of this scene):

* helical repeat of B-DNA in solution 10.5 bp per turn (J. C. Wang, PNAS 76, 200 (1979); 10.4 to
  10.6 depending on conditions), rise 0.34 nm per bp (fibre B-DNA, 3.4 nm per 10 bp: Watson &
  Crick, Nature 171, 737 (1953); Arnott & Hukins, BBRC 47, 1504 (1972)); both pitches are used;
* diameter about 2 nm (Watson & Crick 1953: 20 A);
* bending persistence length about 50 nm (P. J. Hagerman, Annu. Rev. Biophys. Biophys. Chem.
  17, 265 (1988));
* the ratio nu of the two bending stiffnesses is model-dependent: anisotropic rod models of
  DNA treat it as a parameter of order 1 to a few (e.g. F. Mohammad-Rafiee & R. Golestanian,
  arXiv cond-mat/0207477; B. Eslami-Mossallam & M. R. Ejtehadi, J. Chem. Phys. 128, 125106
  (2008), who also find that an anisotropic DNA under tension behaves as an isotropic one with
  the harmonic mean of the two stiffnesses -- the p_inf of this package). No value is taken
  from them: :data:`NUS` spans the plausible range and every conclusion is stated for all of it.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from reproduce._runner import SceneOutput
from reproduce.io import json_value, write_text
from reproduce.ledger import (
    LEDGER_CHECK,
    Claim,
    ClaimSpec,
    Condition,
    Measured,
    Method,
    judge,
    tiered_rule,
    update_ledger,
)
from reproduce.tables import markdown_table
from spectral_rod import critical_load, large_twist_limit

NAME = "dna"
SUMMARY = ("B-DNA scale: Omega(L) in nanometres and base pairs, the part of Figure 1 a DNA "
           "segment reaches within the rod model's validity -> dna.json, ledger row "
           "caveat-dna-scale")

#: Literature values (module docstring): base pairs per turn (solution, fibre), rise per base
#: pair [nm], diameter [nm], persistence length [nm].
BP_PER_TURN = {"solution (Wang 1979)": 10.5, "fibre (Watson-Crick, Arnott)": 10.0}
RISE_NM = 0.34
DIAMETER_NM = 2.0
PERSISTENCE_NM = 50.0
#: "L >> a" made concrete: the segment at least this many diameters long (an assumption).
VALIDITY_DIAMETERS = 10.0
#: Stiffness ratios spanned (an assumption: the module docstring says why no single value).
NUS = (1.5, 2.0, 4.0)
#: The twist range Figure 1 plots.
FIGURE1_TWIST_MAX = 10.0
#: Points per nu on the DNA window's twist grid.
WINDOW_POINTS = 401
TOL = 1e-12

CHECK = {"dna.json": {"*.citation": "exact", "*": {"rel": 1e-9, "abs": 1e-12}},
         "claims.json": LEDGER_CHECK,
         "sections/dna.json": {"details.seconds": "ignore",
                               "details.*": {"rel": 1e-9, "abs": 1e-12}, "*": "exact"}}

SECTION = (
    "## DNA: the physical scale of the paper's motivation\n\n"
    "B-DNA turns once per helical repeat h = {h_lo:.2f} … {h_hi:.2f} nm ({bp_lo:g} … {bp_hi:g} "
    "bp of {rise:g} nm), so Ω(L) = 2πL/h. Figure 1 (Ω(L) ≤ {fig_max:g}) ends at L = "
    "{l_fig_lo:.2f} … {l_fig_hi:.2f} nm ({bp_fig_lo:.1f} … {bp_fig_hi:.1f} bp), "
    "{d_fig:.1f} … {d_fig_hi:.1f} diameters of {diam:g} nm; its first maximum (Ω(L) ≈ 2π) is "
    "a segment of one helical turn, {turn_lo:.2f} … {turn_hi:.2f} nm = {turn_d_lo:.1f} … "
    "{turn_d_hi:.1f} diameters. **No point of Figure 1 is a DNA "
    "segment within the rod model's validity** (L ≥ {valid:g} diameters = {l_valid:g} nm, i.e. "
    "Ω(L) ≥ {om_valid_lo:.1f} … {om_valid_hi:.1f}). Between that length and the persistence "
    "length {lp:g} nm (beyond which thermal bending, not a static load, dominates), Ω(L) runs "
    "over [{om_valid_lo:.1f}, {om_lp_hi:.1f}] ≈ [{n_lo:.1f}π, {n_hi:.1f}π]: deep in the "
    "large-twist regime, where p* is within {worst_rel:.2%} of the rise to p∞ = 2ν/(1+ν) for "
    "every ν in {nus} (ν assumed: the module docstring of `reproduce/dna.py` says why). A "
    "twisted DNA segment under end compression buckles at the harmonic mean of its two bending "
    "stiffnesses, as an isotropic rod would; the oscillations and the maxima near 2π and 3π of "
    "Figure 1 are out of reach.\n\n"
    "Literature values (assumed, cited in `reproduce/dna.py`): rise {rise:g} nm/bp, {bp_lo:g} … "
    "{bp_hi:g} bp/turn (Wang 1979; Watson & Crick 1953, Arnott & Hukins 1972), diameter {diam:g} "
    "nm, persistence length {lp:g} nm (Hagerman 1988).\n\n")


def pitch_nm(bp_per_turn: float) -> float:
    """The helical repeat h [nm] of B-DNA with `bp_per_turn` base pairs per turn."""
    return bp_per_turn * RISE_NM


def twist_of_length(length_nm: float | np.ndarray, pitch: float) -> float | np.ndarray:
    """Omega(L) = omega30 L = 2 pi L / h for a B-DNA segment of length L [nm]."""
    return 2.0 * math.pi * np.asarray(length_nm, dtype=float) / pitch


def length_of_twist(twist: float, pitch: float) -> float:
    """L [nm] of a B-DNA segment with total twist angle `twist` (inverse of
    :func:`twist_of_length`)."""
    return twist * pitch / (2.0 * math.pi)


def window(pitch: float) -> dict[str, float]:
    """The twists of the valid, athermal window [VALIDITY_DIAMETERS a, persistence length]."""
    return {"pitch_nm": pitch,
            "twist_min": float(twist_of_length(VALIDITY_DIAMETERS * DIAMETER_NM, pitch)),
            "twist_max": float(twist_of_length(PERSISTENCE_NM, pitch)),
            "figure1_length_nm": length_of_twist(FIGURE1_TWIST_MAX, pitch)}


def settled(nu: float, twist_min: float, twist_max: float) -> dict[str, float]:
    """max over the window of (p_inf - p*) / (p_inf - 1), and p* there (collocation)."""
    grid = np.linspace(twist_min, twist_max, WINDOW_POINTS)
    p = critical_load(grid, nu, tol=TOL)
    p_inf = large_twist_limit(nu)
    rel = (p_inf - p) / (p_inf - 1.0)
    return {"nu": nu, "p_inf": p_inf, "p_min": float(p.min()), "p_max": float(p.max()),
            "max_rel_deficit": float(np.max(np.abs(rel)))}


def compute() -> dict[str, object]:
    """Every number of the scene."""
    pitches = {k: pitch_nm(v) for k, v in BP_PER_TURN.items()}
    windows = {k: window(h) for k, h in pitches.items()}
    lo = min(w["twist_min"] for w in windows.values())
    hi = max(w["twist_max"] for w in windows.values())
    return {"literature": {"bp_per_turn": BP_PER_TURN, "rise_nm": RISE_NM,
                           "diameter_nm": DIAMETER_NM, "persistence_nm": PERSISTENCE_NM,
                           "citation": "Wang 1979; Watson & Crick 1953; Arnott & Hukins 1972; "
                                       "Hagerman 1988 (reproduce/dna.py)"},
            "assumed": {"validity_diameters": VALIDITY_DIAMETERS, "nus": list(NUS)},
            "windows": windows,
            "settled": [settled(nu, lo, hi) for nu in NUS],
            "twist_window": [lo, hi]}


def section(data: dict[str, object]) -> str:
    w = data["windows"]
    pitches = sorted(v["pitch_nm"] for v in w.values())  # type: ignore[union-attr]
    bps = sorted(BP_PER_TURN.values())
    lo, hi = data["twist_window"]  # type: ignore[misc]
    fig_l = sorted(v["figure1_length_nm"] for v in w.values())  # type: ignore[union-attr]
    valid_tw = sorted(v["twist_min"] for v in w.values())  # type: ignore[union-attr]
    worst = max(s["max_rel_deficit"] for s in data["settled"])  # type: ignore[union-attr]
    text = SECTION.format(
        h_lo=pitches[0], h_hi=pitches[1], bp_lo=bps[0], bp_hi=bps[1], rise=RISE_NM,
        fig_max=FIGURE1_TWIST_MAX, l_fig_lo=fig_l[0], l_fig_hi=fig_l[1],
        bp_fig_lo=fig_l[0] / RISE_NM, bp_fig_hi=fig_l[1] / RISE_NM,
        d_fig=fig_l[0] / DIAMETER_NM, d_fig_hi=fig_l[1] / DIAMETER_NM, diam=DIAMETER_NM,
        turn_lo=pitches[0], turn_hi=pitches[1], turn_d_lo=pitches[0] / DIAMETER_NM,
        turn_d_hi=pitches[1] / DIAMETER_NM,
        valid=VALIDITY_DIAMETERS, l_valid=VALIDITY_DIAMETERS * DIAMETER_NM,
        om_valid_lo=valid_tw[0], om_valid_hi=valid_tw[1], lp=PERSISTENCE_NM, om_lp_hi=hi,
        n_lo=lo / math.pi, n_hi=hi / math.pi, worst_rel=worst,
        nus=", ".join(f"{nu:g}" for nu in NUS))
    table = markdown_table(
        ["ν (assumed)", "p∞ = 2ν/(1+ν)", "p* in the window", "max (p∞ − p*)/(p∞ − 1)"],
        [[f"{s['nu']:g}", f"{s['p_inf']:.4f}", f"{s['p_min']:.4f} … {s['p_max']:.4f}",
          f"{s['max_rel_deficit']:.1e}"] for s in data["settled"]])  # type: ignore[union-attr]
    return text + table + "\n"


#: The row's finding (the report's headline), a template with named fields.
FINDING = ("No point of Figure 1 is a DNA segment within the rod model's validity: Ω(L) ≤ "
           "{fig_max:g} is L ≤ {l_fig:.1f} nm, under {d_fig:.0f} diameters; valid, athermal B-DNA "
           "segments ({l_valid:g}–{lp:g} nm) sit at Ω(L) = {lo:.0f}–{hi:.0f}, where p* is within "
           "{worst:.2%} of the rise to p∞ = 2ν/(1+ν) (ν = {nus}, assumed).")

SCALE = ClaimSpec(
    id="caveat-dna-scale", section="Introduction (the motivation: DNA) and Figure 1",
    claim="(Physical scale) The paper motivates the twisted rod by DNA, but Figure 1's twists "
          "(Ω(L) ≤ 10) are shorter than any DNA segment within the rod model's validity (L ≫ a): "
          "for DNA, only the approach of p* to its large-twist limit is physical.",
    test="Ω(L) = 2πL/h with B-DNA's helical repeat h = 3.40-3.57 nm (cited in reproduce/dna.py): "
         "the longest segment Figure 1 shows against the shortest the rod model admits "
         f"({VALIDITY_DIAMETERS:g} diameters of {DIAMETER_NM:g} nm); p* by collocation over the "
         "valid, athermal window (up to the persistence length).",
    methods=(Method("B-DNA literature values (reproduce/dna.py)", "literature values"),
             Method("Chebyshev collocation (spectral_rod.critical_load)", "inst1")),
    rule=tiered_rule([("holds", (Condition(
        "figure1_over_valid_length", "<", "the longest segment of Figure 1 over the shortest "
        "valid one", 1.0),))], "fails",
        note="holds: no part of Figure 1 is a valid DNA segment"),
    kind="caveat", related=("rod-limit", "fig1-curves"))


def scale_claim(data: dict[str, object]) -> Claim:
    """The ledger row :data:`SCALE` judged on the scene's numbers."""
    w = data["windows"]
    fig_l = max(v["figure1_length_nm"] for v in w.values())  # type: ignore[union-attr]
    valid = VALIDITY_DIAMETERS * DIAMETER_NM
    lo, hi = data["twist_window"]  # type: ignore[misc]
    worst = max(s["max_rel_deficit"] for s in data["settled"])  # type: ignore[union-attr]
    finding = FINDING.format(fig_max=FIGURE1_TWIST_MAX, l_fig=fig_l, d_fig=fig_l / DIAMETER_NM,
                             l_valid=valid, lp=PERSISTENCE_NM, lo=lo, hi=hi, worst=worst,
                             nus=", ".join(f"{nu:g}" for nu in NUS))
    measured = Measured(
        numbers={"finding": finding, "figure1_over_valid_length": fig_l / valid,
                 "figure1_length_nm": fig_l, "valid_length_nm": valid,
                 "twist_window": [lo, hi], "max_rel_deficit": worst},
        evidence=f"{finding} The first maximum of Figure 1 (Ω(L) ≈ 2π) is one helical turn. "
                 "The paper's conclusions for the straight rod reach DNA only through the "
                 "large-twist limit (rod-limit).")
    return judge(SCALE, measured, NAME)


def run(out: Path, progress: Callable[[str], None]) -> SceneOutput:
    t0 = time.perf_counter()
    data = compute()
    lo, hi = data["twist_window"]  # type: ignore[misc]
    progress(f"DNA window Omega(L) in [{lo:.1f}, {hi:.1f}]")
    files = [write_text(out / "dna.json", json.dumps(data, indent=1, default=json_value) + "\n")]
    claim = scale_claim(data)
    files += update_ledger(out, NAME, [claim])
    details = {"twist_window": data["twist_window"],
               "max_rel_deficit": max(s["max_rel_deficit"]
                                      for s in data["settled"]),  # type: ignore[union-attr]
               "verdict": claim.verdict, "seconds": time.perf_counter() - t0}
    return SceneOutput(files=files, report=section(data), details=details)
