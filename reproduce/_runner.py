"""Scene registry and runner: each scene is one module in `reproduce/` with

    NAME: str          # the CLI name
    SUMMARY: str       # one line: what it models, compares and writes
    run(out: Path, progress: Callable[[str], None]) -> SceneOutput

The runner times every scene, stores its report section under ``<out>/sections/`` and rebuilds
``<out>/report.md`` from all sections present (so running one scene keeps the others' sections),
with package versions, the git commit and the wall time of each scene. The report opens with a
headline built from ``claims.json`` alone (:func:`headline_verdicts`): the paper's statements
tallied apart from the package's checks and the modelling caveats, the failing statements grouped
by root cause (one line per independent error of the paper), the findings themselves (each row's
``numbers["finding"]``, sentences made from its computed numbers) and then every row.

One run at a time writes to an output directory (an advisory ``flock`` on the directory: a second
run waits for the first, and the lock dies with its process). Each run first removes the
temporary files of killed runs and re-assembles ``report.md`` from the sections on disk, so a run
killed between writing a section and the report leaves them out of step only until the next run.
"""

from __future__ import annotations

import contextlib
import datetime as _dt
import fcntl
import importlib
import importlib.util
import json
import os
import platform
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType

from reproduce.io import (
    ensure_writable_dir,
    json_value,
    read_json,
    remove_stale_temporaries,
    write_text,
)
from reproduce.ledger import KINDS, SCENE_ORDER, read_ledger, verdict_counts
from reproduce.paths import CODE_DIR

#: The scenes of :data:`reproduce.ledger.SCENE_ORDER` whose module exists in this checkout.
SCENE_MODULES = tuple(name for name in SCENE_ORDER
                      if importlib.util.find_spec(f"reproduce.{name}") is not None)


@dataclass
class SceneOutput:
    """What a scene wrote and the Markdown section it contributes to the report."""

    files: list[Path]
    report: str
    details: dict[str, object] = field(default_factory=dict)


def load_scene(name: str) -> ModuleType:
    if name not in SCENE_MODULES:
        raise KeyError(name)
    return importlib.import_module(f"reproduce.{name}")


def git_commit(out: Path | None = None) -> str:
    """HEAD of the code's checkout, with "+uncommitted changes" if a tracked file differs from
    it. Files under `out` (the outputs this run regenerates) do not count: they are not code,
    and a run into a cleared ``paper_figures/`` would otherwise always look uncommitted (unless
    `out` is the checkout's root itself: then everything counts)."""
    try:
        top = _git(["rev-parse", "--show-toplevel"]).strip()
        sha = _git(["rev-parse", "HEAD"]).strip()
        spec = ["."]
        if out is not None:
            try:
                rel = out.resolve().relative_to(Path(top).resolve())
            except ValueError:  # the outputs lie outside the checkout
                rel = None
            if rel is not None and rel.parts:
                spec.append(f":(exclude,literal){rel.as_posix()}")  # no glob in the name
        dirty = _git(["status", "--porcelain", "--untracked-files=no", "--", *spec], cwd=top)
        return sha + ("+uncommitted changes" if dirty.strip() else "")
    except (OSError, subprocess.SubprocessError):
        return "unknown (not a git checkout)"


def _git(args: list[str], cwd: Path | str | None = None) -> str:
    return subprocess.run(["git", *args], cwd=cwd or CODE_DIR, capture_output=True, text=True,
                          timeout=10, check=True).stdout


def versions() -> dict[str, str]:
    out = {"python": platform.python_version(), "platform": platform.platform()}
    for mod in ("spectral_rod", "numpy", "scipy", "pandas", "matplotlib", "mpmath", "sympy",
                "threadpoolctl"):
        try:
            out[mod] = importlib.import_module(mod).__version__
        except Exception:
            out[mod] = "not installed"
    from spectral_rod import engine_report  # the engine every solve ran on

    out["engine"] = engine_report()["summary"]
    return out


#: The headline's wording: templates with named fields (numbers come from ``claims.json``).
HEADLINE = {
    "title": "## Headline",
    "paper": "**What the paper says**: {n} claims of the paper (its own statements) checked "
             "— {tally}.",
    "others": "Not counted above: {n_package} check(s) of the package's own methods "
              "({package}) and {n_caveat} modelling caveat(s) about what the paper leaves open "
              "({caveat}).",
    "causes": "**The paper's errors**: the {n_fails} failing statements trace back to "
              "{n_causes} independent error(s):",
    "cause": "- {cause} — {ids}",
    "uncaused": "- `{id}` (no shared root cause stated): {claim}",
    "findings": "**What was found** (from the computed numbers in `claims.json`):",
    "finding": "- {finding}",
    "all": "## Verdicts, row by row",
    "kind": "*{kind}* ({n}):",
    "row": "- **{verdict}** `{id}`: {claim}",
}
#: How each kind of row is named in the headline.
KIND_NAMES = {"paper": "statements of the paper", "package": "checks of the package",
              "caveat": "modelling caveats"}


def _tally(rows: list[dict[str, object]]) -> str:
    counts = verdict_counts(str(r["verdict"]) for r in rows)
    return ", ".join(f"**{v}** {n}" for v, n in counts.items() if n) or "none"


def _dig(row: dict[str, object] | None, *keys: str) -> object:
    """numbers[keys[0]][keys[1]]... of a row (KeyError/TypeError if absent)."""
    value: object = row["numbers"] if row is not None else None
    for k in keys:
        value = value[k]  # type: ignore[index]
    return value


#: Findings of rows that carry no ``numbers["finding"]``, made from their numbers (the ring's
#: converged loads against Eq. crit2): (row id, template, key paths of its fields).
FALLBACK_FINDINGS = (
    ("ring-circular-limit", "For a circular section the converged ring load is {num:.3f} "
     "E₁I₁/R³ out of plane (E₂ = E₁; {iso:.3f} for an isotropic material), not the 3 of the text "
     "(3 is the in-plane load under hydrostatic pressure: {inplane:.3f}).",
     {"num": ("per_e", "e=1", "numerical", "hydrostatic"),
      "iso": ("per_e", "isotropic", "numerical", "hydrostatic"),
      "inplane": ("per_e", "e=1", "in_plane", "hydrostatic")}),
    ("ring-crit2", "Eq. crit2 is off the converged ring load by up to {dev:.0f}× (N = {N}, "
     "ν = {nu:g}); the converged load is never below {qmin:.3f} E₁I₁/R³, so there is no "
     "spontaneous instability.",
     {"dev": ("hydrostatic", "max_rel_dev"), "N": ("hydrostatic", "at_N"),
      "nu": ("hydrostatic", "at_nu"), "qmin": ("hydrostatic", "min_numerical")}),
)


def _findings(rows: list[dict[str, object]]) -> list[str]:
    by_id = {str(r["id"]): r for r in rows}
    out = [str(r["numbers"]["finding"]) for r in rows  # type: ignore[index]
           if isinstance(r.get("numbers"), dict) and r["numbers"].get("finding")]
    for row_id, template, paths in FALLBACK_FINDINGS:
        row = by_id.get(row_id)
        if row is None or row["numbers"].get("finding"):  # type: ignore[union-attr]
            continue
        try:
            out.append(template.format(**{k: _dig(row, *p) for k, p in paths.items()}))
        except (KeyError, TypeError, ValueError, IndexError):
            continue  # the ring scene's numbers changed shape: it states its own finding
    return out


def headline_verdicts(claims_json: Path) -> list[str]:
    """The report's first screen ([] if there is no ledger yet;
    :class:`reproduce.io.OutputFileError` if it is corrupt): the paper's statements tallied
    apart from package checks and caveats, the failing statements grouped by identical
    ``root_cause`` (a failing statement without one on a line of its own), the findings, and
    every row by kind."""
    rows = read_ledger(claims_json)
    if not rows:
        return []
    kinds = {k: [r for r in rows if r.get("kind", "paper") == k] for k in KINDS}
    paper = kinds["paper"]
    fails = [r for r in paper if r["verdict"] == "fails"]
    causes: dict[str, list[str]] = {}
    for r in fails:
        if r.get("root_cause"):
            causes.setdefault(str(r["root_cause"]), []).append(str(r["id"]))
    uncaused = [r for r in fails if not r.get("root_cause")]
    h = HEADLINE
    lines = [h["title"], "", h["paper"].format(n=len(paper), tally=_tally(paper)), "",
             h["others"].format(n_package=len(kinds["package"]), package=_tally(kinds["package"]),
                                n_caveat=len(kinds["caveat"]), caveat=_tally(kinds["caveat"])),
             ""]
    if fails:
        lines += [h["causes"].format(n_fails=len(fails), n_causes=len(causes) + len(uncaused)),
                  ""]
        lines += [h["cause"].format(cause=c, ids=", ".join(f"`{i}`" for i in ids))
                  for c, ids in causes.items()]
        lines += [h["uncaused"].format(id=r["id"], claim=r["claim"]) for r in uncaused]
        lines.append("")
    findings = _findings(rows)
    if findings:
        lines += [h["findings"], "", *[h["finding"].format(finding=f) for f in findings], ""]
    lines += [h["all"], ""]
    for kind in KINDS:
        if kinds[kind]:
            lines += [h["kind"].format(kind=KIND_NAMES[kind], n=len(kinds[kind])), ""]
            lines += [h["row"].format(verdict=r["verdict"], id=r["id"], claim=r["claim"])
                      for r in kinds[kind]]
            lines.append("")
    return lines


#: Keys of ``sections/NAME.json`` that the report needs (written by :func:`_run_one`).
SECTION_KEYS = ("seconds", "finished", "commit")


def _assemble_report(out: Path) -> Path:
    sections = out / "sections"
    lines = ["# spectral_rod reproduction report", "", *headline_verdicts(out / "claims.json"),
             "## Scenes", "",
             "Regenerated by `python -m reproduce all` (or one scene at a time). Each section "
             "records when it was run, from which commit, and how long it took.", "",
             "| scene | wall time [s] | run at (UTC) | commit |", "|---|---|---|---|"]
    bodies = []
    for name in SCENE_MODULES:
        meta_path, body_path = sections / f"{name}.json", sections / f"{name}.md"
        if not (meta_path.exists() and body_path.exists()):
            continue
        meta = read_json(meta_path, dict, SECTION_KEYS)
        lines.append(f"| [{name}](#{name}) | {meta['seconds']:.2f} | {meta['finished']} "
                     f"| `{meta['commit'][:12]}` |")
        bodies += ["", body_path.read_text(encoding="utf-8")]
    meta_all = sections / "_environment.json"
    if meta_all.exists():
        env = read_json(meta_all, dict, ("versions", "commit"))
        lines += ["", "## Environment", "", "| package | version |", "|---|---|"]
        lines += [f"| {k} | {v} |" for k, v in env["versions"].items()]
        lines += ["", f"Commit: `{env['commit']}`"]
    return write_text(out / "report.md", "\n".join(lines + bodies) + "\n")


@contextlib.contextmanager
def exclusive_output(out: Path, log: Callable[[str], None]) -> Iterator[None]:
    """Hold an exclusive advisory lock on the directory `out` (waiting for another run)."""
    fd = os.open(out, os.O_RDONLY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            log(f"another run is writing to {out}; waiting for it to finish")
            fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)  # releases the lock


def run_scenes(names: list[str], out: Path, log: Callable[[str], None]) -> dict[str, float]:
    """Run scenes in order, logging progress; return their wall times."""
    out = ensure_writable_dir(out)
    with exclusive_output(out, log):
        for stale in remove_stale_temporaries(out):
            log(f"removed {stale.name}, a temporary file of an interrupted earlier run")
        _assemble_report(out)
        commit = git_commit(out)
        write_text(out / "sections" / "_environment.json",
                   json.dumps({"versions": versions(), "commit": commit}, indent=2))
        times: dict[str, float] = {}
        for i, name in enumerate(names, 1):
            times[name] = _run_one(name, f"[{i}/{len(names)}]", out, commit, log)
            _assemble_report(out)
    return times


def _run_one(name: str, counter: str, out: Path, commit: str, log: Callable[[str], None]
             ) -> float:
    """Run one scene, write its section (Markdown and JSON); return its wall time."""
    module = load_scene(name)
    log(f"{counter} {name}: {module.SUMMARY}")
    t0 = time.perf_counter()
    result: SceneOutput = module.run(out, lambda msg, _n=name: log(f"    {_n}: {msg}"))
    seconds = time.perf_counter() - t0
    finished = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M:%S")
    write_text(out / "sections" / f"{name}.md", f'<a id="{name}"></a>\n\n' + result.report)
    write_text(out / "sections" / f"{name}.json",
               json.dumps({"seconds": seconds, "finished": finished, "commit": commit,
                           "files": [str(p.relative_to(out)) if p.is_relative_to(out)
                                     else str(p) for p in result.files],
                           "details": result.details}, indent=2, default=json_value))
    log(f"    {name}: done in {seconds:.1f} s, wrote {len(result.files)} files")
    return seconds


def log_stderr(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)
