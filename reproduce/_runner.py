"""Scene registry and runner: each scene is one module in `reproduce/` with

    NAME: str          # the CLI name
    SUMMARY: str       # one line: what it models, compares and writes
    run(out: Path, progress: Callable[[str], None]) -> SceneOutput

The runner times every scene, stores its report section under ``<out>/sections/`` and rebuilds
``<out>/report.md`` from all sections present (so running one scene keeps the others' sections),
with package versions, the git commit and the wall time of each scene; the report opens with the
headline verdicts of ``claims.json``.

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
from reproduce.ledger import SCENE_ORDER, read_ledger, verdict_counts
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


def headline_verdicts(claims_json: Path) -> list[str]:
    """Markdown lines: the number of claims per verdict and one line per claim ([] if there is
    no ledger yet; :class:`reproduce.io.OutputFileError` if it is corrupt)."""
    rows = read_ledger(claims_json)
    if not rows:
        return []
    counts = verdict_counts(str(r["verdict"]) for r in rows)
    lines = ["## Verdicts", "",
             f"{len(rows)} claims of the paper checked (`claims.md`): "
             + ", ".join(f"**{v}** {n}" for v, n in counts.items() if n) + ".", ""]
    lines += [f"- **{r['verdict']}** `{r['id']}`: {r['claim']}" for r in rows]
    return [*lines, ""]


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
