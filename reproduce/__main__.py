"""`python -m reproduce {all,list,SCENE...} [--out DIR]`: regenerate the paper's figures,
tables, claims ledger and report from code."""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

# Every matrix in the pipeline is small (tens to hundreds of rows): a multi-threaded BLAS only
# adds synchronisation, 2-3x slower on a busy 2-core machine. Set before numpy is first imported
# (the scenes import it lazily); an explicit setting in the environment wins.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from reproduce._runner import (  # noqa: E402 - after the BLAS thread setting
    SCENE_MODULES,
    load_scene,
    log_stderr,
    run_scenes,
)
from reproduce.paths import OUT_NAME, default_out  # noqa: E402


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m reproduce",
        description="Rebuild the outputs of the Drozdov & Rabin reproduction.",
        epilog=f"scenes: {', '.join(SCENE_MODULES)}")
    p.add_argument("targets", nargs="+", metavar="TARGET",
                   help="'all', 'list', or one or more scene names")
    p.add_argument("--out", type=Path, default=None,
                   help=f"output directory (default: ./{OUT_NAME} in the current directory)")
    return p


def main(argv: list[str] | None = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    targets: list[str] = args.targets
    if targets == ["list"]:
        for name in SCENE_MODULES:
            print(f"{name:12s} {load_scene(name).SUMMARY}")
        return 0
    names = list(SCENE_MODULES) if targets == ["all"] else targets
    unknown = [t for t in names if t not in SCENE_MODULES]
    if unknown or ("all" in targets and len(targets) > 1) or "list" in targets:
        parser.print_usage(sys.stderr)
        print(f"python -m reproduce: error: unknown target(s) {unknown or targets}; "
              f"choose 'all', 'list' or scenes from {', '.join(SCENE_MODULES)}", file=sys.stderr)
        return 2
    out = args.out if args.out is not None else default_out()
    t0 = time.perf_counter()
    try:
        run_scenes(names, out, log_stderr)
    except OSError as exc:
        print(f"python -m reproduce: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        # every output is written to a temporary file and renamed (reproduce.io), so files
        # from before the interrupt are whole and no partial file is left behind
        print("python -m reproduce: interrupted; previous outputs left intact, no partial "
              "files written", file=sys.stderr)
        return 130
    log_stderr(f"all done in {time.perf_counter() - t0:.1f} s; outputs in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
