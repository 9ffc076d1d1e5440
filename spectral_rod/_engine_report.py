"""What will run a solve of Eq. ``inst1`` on this install: the engine, its instruction-set
variant, the BLAS libraries and their threads, and the dependency versions.

:func:`engine_report` gathers it as a dict, :func:`format_engine_report` prints it (both public:
``spectral_rod.engine_report``); ``python -m spectral_rod`` and ``spectral-rod info`` show it,
and ``python -m reproduce`` records its ``summary`` line in its report's environment table.

The engine is the batched eigen-solver's compiled kernel
(:mod:`spectral_rod.rod.collocation.modal_kernel`) where it was built at install and loads, and its
numpy code otherwise (same algorithm, results equal to rounding; ~5 times slower on a batch and
~4 times on a scalar call, by ``python -m pytest -m bench`` with and without the kernel).
Where the kernel module offers ``engine_info()``, its entries are reported as they are; the
instruction-set variant is otherwise the best of the kernel's ``target_clones`` levels
(x86-64-v4, -v3, default) whose features ``/proc/cpuinfo`` lists, which is the one the loader
picks on a GCC/glibc x86-64 build.
"""

from __future__ import annotations

import importlib
import platform
import sys
from pathlib import Path
from typing import Any

__all__ = ["DEPENDENCIES", "engine_report", "engine_summary", "format_engine_report"]

#: Distributions whose versions are reported (the runtime dependencies of pyproject.toml).
DEPENDENCIES = ("numpy", "scipy", "pandas", "matplotlib", "mpmath", "sympy", "threadpoolctl")
#: CPU features each x86-64 micro-architecture level needs beyond the previous one (the psABI
#: levels the kernel is cloned for), as ``/proc/cpuinfo`` spells them.
X86_LEVELS = (
    ("x86-64-v4", ("avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl")),
    ("x86-64-v3", ("avx2", "fma", "bmi1", "bmi2", "movbe", "f16c", "abm", "xsave")),
)
#: How to get the kernel where it is missing.
KERNEL_HINT = ("install a C compiler (e.g. gcc) and reinstall spectral_rod "
               "(pip install --force-reinstall --no-deps .) to build the kernel")


def cpu_level(cpuinfo: str | None = None) -> str:
    """The highest x86-64 level of :data:`X86_LEVELS` whose features all appear in `cpuinfo`
    (default: ``/proc/cpuinfo``), ``"default"`` if none, ``"unknown"`` where it cannot be read.

    >>> cpu_level("flags : avx2 fma bmi1 bmi2 movbe f16c abm xsave")
    'x86-64-v3'
    >>> cpu_level("flags : sse2")
    'default'
    """
    if cpuinfo is None:
        try:
            cpuinfo = Path("/proc/cpuinfo").read_text(encoding="utf-8", errors="replace")
        except OSError:
            return "unknown"
    flags = set(cpuinfo.split())
    need: set[str] = set()
    found = "default"
    for level, features in reversed(X86_LEVELS):
        need |= set(features)
        if need <= flags:
            found = level
    return found


def _kernel_entries() -> dict[str, Any]:
    from spectral_rod.rod.collocation import modal_kernel

    kernel = bool(modal_kernel.available())
    info: dict[str, Any] = {"kernel": kernel, "engine": (
        "C kernel (spectral_rod.rod.collocation._modal_kernel)" if kernel
        else "numpy (no compiled kernel: " + KERNEL_HINT + ")")}
    engine_info = getattr(modal_kernel, "engine_info", None)
    if callable(engine_info):
        extra = engine_info()
        info.update({k: v for k, v in extra.items() if k not in ("engine", "available", "isa")})
        if kernel and extra.get("isa"):
            info["variant"] = f"{extra['isa']} (picked by the kernel's loader)"
    if kernel and "variant" not in info:
        machine = platform.machine().lower()
        info["variant"] = (f"{cpu_level()} (best target_clones level of this CPU)"
                           if machine in ("x86_64", "amd64") else f"default ({machine})")
    return info


def _blas() -> list[dict[str, Any]]:
    """threadpoolctl's view of the BLAS and OpenMP libraries numpy and scipy.linalg load."""
    import numpy  # noqa: F401  (loads numpy's BLAS)
    import scipy.linalg  # noqa: F401  (scipy's own BLAS copy, used by the reference routes)
    from threadpoolctl import threadpool_info

    keys = ("user_api", "internal_api", "version", "num_threads", "threading_layer",
            "architecture", "filepath")
    return [{k: lib[k] for k in keys if k in lib} for lib in threadpool_info()]


def _version(name: str) -> str:
    try:
        return str(importlib.import_module(name).__version__)
    except Exception:  # a broken install is reported, not raised: this is a diagnostic
        return "not installed"


def engine_report() -> dict[str, Any]:
    """The install's engine, BLAS and versions, as a dict of plain values.

    Returns
    -------
    dict with keys ``version`` (spectral_rod's), ``python``, ``platform``, ``engine`` (the
    kernel's entries: ``kernel`` bool, ``engine`` text, the instruction-set ``variant``, and
    whatever ``modal_kernel.engine_info()`` adds), ``summary`` (one line: engine and variant),
    ``blas`` (one dict per library threadpoolctl finds), ``thread_policy`` (text),
    ``dependencies`` (name -> version).

    Examples
    --------
    >>> import spectral_rod
    >>> report = spectral_rod.engine_report()
    >>> isinstance(report["engine"]["kernel"], bool), report["version"] == spectral_rod.__version__
    (True, True)
    """
    from spectral_rod import __version__

    engine = _kernel_entries()
    return {
        "version": __version__,
        "python": platform.python_version(),
        "platform": platform.platform(),
        "engine": engine,
        "summary": engine_summary(engine),
        "blas": _blas(),
        "thread_policy": "solves run with every BLAS on one thread (threadpoolctl, "
                         "spectral_rod._blas_threads.one_blas_thread); the caller's setting "
                         "is restored after each call",
        "dependencies": {name: _version(name) for name in DEPENDENCIES},
    }


def engine_summary(engine: dict[str, Any] | None = None) -> str:
    """One line: the engine and its variant (`engine`: the ``engine`` entry of
    :func:`engine_report`, default this install's); ``python -m reproduce`` records it.

    >>> engine_summary({"kernel": False, "engine": "numpy"})
    'numpy'
    """
    engine = engine if engine is not None else _kernel_entries()
    variant = engine.get("variant")
    return str(engine["engine"]) + (f", variant {variant}" if variant else "")


def format_engine_report() -> str:
    """This install's :func:`engine_report` as the text ``python -m spectral_rod`` prints.

    Returns
    -------
    str: the version line, then the engine, BLAS and dependency blocks.

    Examples
    --------
    >>> import spectral_rod
    >>> print(spectral_rod.format_engine_report())  # doctest: +ELLIPSIS
    spectral_rod ... (Python ...)
    <BLANKLINE>
    engine:
      kernel: ...
    """
    return _format(engine_report())


def _format(report: dict[str, Any]) -> str:
    """`report` (an :func:`engine_report`) as text."""
    lines = [f"spectral_rod {report['version']} (Python {report['python']}, "
             f"{report['platform']})", "", "engine:"]
    lines += [f"  {k}: {v}" for k, v in report["engine"].items()]
    lines += ["", "BLAS / OpenMP (threadpoolctl):"]
    for lib in report["blas"] or [{"library": "none found"}]:
        lines.append("  " + ", ".join(f"{k} {v}" for k, v in lib.items()))
    lines += [f"  policy: {report['thread_policy']}", "", "dependencies:"]
    lines += [f"  {k}: {v}" for k, v in report["dependencies"].items()]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """``python -m spectral_rod [--json]``: print the report (text, or JSON with ``--json``)."""
    import argparse
    import json

    parser = argparse.ArgumentParser(
        prog="python -m spectral_rod",
        description="Print the engine that solves Eq. inst1 on this install (compiled kernel "
                    "or numpy, instruction-set variant), the BLAS and its threads, and the "
                    "dependency versions.")
    parser.add_argument("--json", action="store_true", help="print the report as JSON")
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    report = engine_report()
    print(json.dumps(report, indent=2) if args.json else _format(report))
    return 0
