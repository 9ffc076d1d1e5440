"""`python -m reproduce check [SCENE...] [--against DIR]`: does a regenerated result still match?

Regenerates the scenes into a temporary directory and compares every CSV and JSON output with
the committed one (default ``./paper_figures``) under the tolerances each scene declares in its
module-level ``CHECK`` (rules in :mod:`reproduce.compare`): numbers within a relative tolerance
per column (the solver's own error estimate as a floor where the file has one), achieved errors
of solves at a stated tol still within that tol, every verdict and label identical except a
mode family at a tie of the two families (:mod:`reproduce.ties`); figures, Markdown and
measured timings are not compared. Prints one line
per file and a table of the regressions; exit status 1 on any regression, 0 otherwise.

The scene's report section ``sections/NAME.json`` is compared too, without the runner's own
keys (wall time, finish time, commit); CSV/JSON files a scene writes but does not declare are
compared by :data:`reproduce.compare.DEFAULT_RULE` and named as undeclared.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

from reproduce._runner import load_scene, run_scenes
from reproduce.compare import FileComparison, compare_file
from reproduce.io import read_json

#: Keys of ``sections/NAME.json`` that the runner writes and that differ on every run.
RUNNER_KEYS = {"seconds": "ignore", "finished": "ignore", "commit": "ignore"}
#: Regressions listed in full per file (the count is always printed).
MAX_ROWS = 20


def scene_specs(name: str, fresh: Path) -> dict[str, Any]:
    """File -> spec for scene `name`: its ``CHECK``, its section JSON, and any data file it
    wrote (per ``fresh/sections/NAME.json``) that ``CHECK`` does not name (compared at the
    default rule)."""
    specs: dict[str, Any] = dict(getattr(load_scene(name), "CHECK", {}))
    section = f"sections/{name}.json"
    specs[section] = {**RUNNER_KEYS, **specs.get(section, {})}
    meta = fresh / section
    if meta.exists():
        for written in read_json(meta).get("files", []):
            if written.endswith((".csv", ".json")) and written not in specs:
                specs[written] = {}
    return specs


def compare_scenes(names: list[str], committed: Path, fresh: Path
                   ) -> list[tuple[str, FileComparison]]:
    """Compare every declared output of each scene in `names` (fresh vs committed)."""
    return [(name, compare_file(file, committed, fresh, spec, name))
            for name in names for file, spec in scene_specs(name, fresh).items()]


def _short(x: Any) -> str:
    text = f"{x:.12g}" if isinstance(x, float) else str(x)
    return text if len(text) <= 40 else text[:37] + "..."


def format_report(results: list[tuple[str, FileComparison]]) -> str:
    """Per file: values compared, changed within tolerance, regressions; then the regressions."""
    lines = [f"{'scene':12s} {'file':32s} {'compared':>8s} {'ignored':>7s} {'changed':>7s} "
             f"{'REGRESSED':>9s}"]
    detail = []
    for scene, r in results:
        bad = r.regressions
        lines.append(f"{scene:12s} {r.file:32s} {r.compared:8d} {r.ignored:7d} "
                     f"{len(r.differences) - len(bad):7d} {len(bad):9d}")
        if r.undeclared:
            lines.append(f"{'':12s}   undeclared (compared at the default rule): "
                         + ", ".join(sorted(r.undeclared)[:8])
                         + (" ..." if len(r.undeclared) > 8 else ""))
        for d in bad[:MAX_ROWS]:
            detail.append(f"| {r.file} | {d.where} | {_short(d.committed)} | "
                          f"{_short(d.regenerated)} | {d.allowed} |")
        if len(bad) > MAX_ROWS:
            detail.append(f"| {r.file} | ... {len(bad) - MAX_ROWS} more | | | |")
    if detail:
        lines += ["", "Regressions:", "", "| file | where | committed | regenerated | allowed |",
                  "|---|---|---|---|---|", *detail]
    return "\n".join(lines)


def run_check(names: list[str], against: Path, log: Callable[[str], None],
              fresh: Path | None = None) -> int:
    """Regenerate `names` (into a temporary directory unless `fresh` already holds them),
    compare with `against`, print the report; 1 on any regression, else 0."""
    if not against.is_dir():
        raise FileNotFoundError(f"no committed outputs to check against: {against} is not a "
                                f"directory")
    if fresh is None:
        with tempfile.TemporaryDirectory(prefix="spectral-rod-check-") as tmp:
            run_scenes(names, Path(tmp), log)
            return run_check(names, against, log, fresh=Path(tmp))
    from spectral_rod import engine_report  # which engine regenerated the values compared

    results = compare_scenes(names, against, fresh)
    print(f"engine: {engine_report()['summary']}\n")
    print(format_report(results))
    n_bad = sum(len(r.regressions) for _, r in results)
    n_changed = sum(len(r.differences) for _, r in results) - n_bad
    total = sum(r.compared for _, r in results)
    print(f"\ncheck: {total} values in {len(results)} files compared with {against}: "
          f"{n_changed} changed within tolerance, {n_bad} regression(s)"
          + (" -> FAIL" if n_bad else " -> ok"))
    return 1 if n_bad else 0
