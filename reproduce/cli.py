"""The command line: ``python -m reproduce`` / ``spectral-rod``.

    spectral-rod {all | list | info | SCENE... | check [SCENE...]} [--out DIR] [--against DIR]
                 [--quiet] [--version]

``info`` prints the engine that will solve Eq. ``inst1`` (compiled kernel or numpy, its
instruction-set variant), the BLAS and its threads, and the dependency versions (as
``python -m spectral_rod``).

Exit status: 0 done (``check``: no regression), 1 ``check`` found a regression, 2 usage error,
unwritable output, missing or corrupt input (the message names the file), 130/143 interrupted by
SIGINT/SIGTERM (outputs written before the signal are whole; no partial file is left).
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable
from pathlib import Path

from reproduce._runner import SCENE_MODULES, load_scene, log_stderr, run_scenes
from reproduce.io import OutputFileError
from reproduce.paths import OUT_NAME, default_out
from reproduce.signals import interrupted_exit

PROG = "python -m reproduce"


def _version() -> str:
    from spectral_rod import __version__
    return f"spectral_rod {__version__}"


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=PROG, description="Rebuild the outputs of the Drozdov & Rabin reproduction, or "
        "check that a rebuild still matches the committed ones.",
        epilog=f"scenes: {', '.join(SCENE_MODULES)}. 'check [SCENE...]' regenerates into a "
        f"temporary directory and compares with --against (default ./{OUT_NAME}); exit 1 on "
        "any regression.")
    p.add_argument("targets", nargs="+", metavar="TARGET",
                   help="'all', 'list', 'info', one or more scene names, or 'check' [scene names]")
    p.add_argument("--out", type=Path, default=None,
                   help=f"output directory (default: ./{OUT_NAME} in the current directory)")
    p.add_argument("--against", type=Path, default=None,
                   help=f"check only: committed outputs to compare with (default ./{OUT_NAME})")
    p.add_argument("-q", "--quiet", action="store_true",
                   help="no progress messages (errors and the check's table still print)")
    p.add_argument("--version", action="version", version=_version())
    return p


def _scene_names(parser: argparse.ArgumentParser, targets: list[str]) -> list[str] | None:
    """Scene names for `targets` ('all' -> every scene; a repeated name runs once, in the place
    it was first given); None (after printing usage) if bad."""
    if "all" in targets and len(targets) > 1:
        parser.print_usage(sys.stderr)
        print(f"{PROG}: error: 'all' cannot be combined with scene names "
              f"({', '.join(t for t in targets if t != 'all')}): give 'all' alone, or the "
              "scenes alone", file=sys.stderr)
        return None
    names = list(SCENE_MODULES) if targets in (["all"], []) else list(dict.fromkeys(targets))
    unknown = [t for t in names if t not in SCENE_MODULES]
    if unknown:
        parser.print_usage(sys.stderr)
        print(f"{PROG}: error: unknown target(s) {unknown}; choose 'all', 'list', 'info', "
              f"'check' or scenes from {', '.join(SCENE_MODULES)}", file=sys.stderr)
        return None
    return names


def main(argv: list[str] | None = None) -> int:
    """Run the command line with `argv` (default ``sys.argv[1:]``); return the exit status."""
    parser = _parser()
    args = parser.parse_intermixed_args(argv)  # 'check --against DIR figure1' too
    targets: list[str] = args.targets
    if targets[0] == "info":
        if len(targets) > 1 or args.out is not None or args.against is not None:
            parser.print_usage(sys.stderr)
            print(f"{PROG}: error: 'info' takes no scene names, --out or --against",
                  file=sys.stderr)
            return 2
        from spectral_rod import format_engine_report

        print(format_engine_report())
        return 0
    if targets[0] == "list":
        if len(targets) > 1 or args.out is not None or args.against is not None:
            parser.print_usage(sys.stderr)
            print(f"{PROG}: error: 'list' takes no scene names, --out or --against",
                  file=sys.stderr)
            return 2
        for name in SCENE_MODULES:
            print(f"{name:12s} {load_scene(name).SUMMARY}")
        return 0
    checking = targets[0] == "check"
    if (args.against is not None and not checking) or (checking and args.out is not None):
        parser.print_usage(sys.stderr)
        print(f"{PROG}: error: --against goes with 'check' only, --out not with it",
              file=sys.stderr)
        return 2
    names = _scene_names(parser, targets[1:] if checking else targets)
    if names is None:
        return 2
    log = (lambda msg: None) if args.quiet else log_stderr
    return _run(names, args, checking, log)


def _run(names: list[str], args: argparse.Namespace, checking: bool,
         log: Callable[[str], None]) -> int:
    """Regenerate (or check) `names`; map input/output faults and signals to exit statuses."""
    from spectral_rod import ReferenceDataError  # lazily: --help needs no numpy

    t0 = time.perf_counter()
    try:
        if checking:
            from reproduce.check import run_check
            return run_check(names, args.against or default_out(), log)
        out = args.out if args.out is not None else default_out()
        run_scenes(names, out, log)
    except (OSError, ReferenceDataError, OutputFileError) as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        return interrupted_exit(exc)
    log(f"all done in {time.perf_counter() - t0:.1f} s; outputs in {out}")
    return 0
