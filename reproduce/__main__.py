"""`python -m reproduce` and the ``spectral-rod`` console script (the CLI is
:mod:`reproduce.cli`).

Only the standard library is imported before the signal handlers are in place, so SIGINT or
SIGTERM during the (slow) imports of numpy, scipy and matplotlib still ends with the one-line
message and status 130/143.
"""

from __future__ import annotations

import os
import sys

# Every matrix in the pipeline is small (tens to hundreds of rows): a multi-threaded BLAS only
# adds synchronisation, 2-3x slower on a busy 2-core machine. Set before numpy is first imported
# (the scenes import it lazily); an explicit setting in the environment wins.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")


def main(argv: list[str] | None = None) -> int:
    """The CLI (:func:`reproduce.cli.main`) without signal handlers: for tests and callers."""
    from reproduce.cli import main as cli_main

    return cli_main(argv)


def entry_point(argv: list[str] | None = None) -> int:
    """Install the signal handlers, then run the CLI; an interrupt anywhere gives one line."""
    from reproduce.signals import (
        Interrupted,
        ignore_signals,
        install_handlers,
        interrupted_exit,
        received,
    )

    install_handlers()
    try:
        status = main(argv)
        ignore_signals()  # done: a late signal must not turn a finished run into a traceback
    except KeyboardInterrupt as exc:
        return interrupted_exit(exc)
    except Exception:
        signum = received()
        if signum is None:
            raise
        # The interrupt was raised inside a C extension's initialisation, which turned it into
        # another exception (seen in CI: SIGINT in matplotlib's ft2font import gave
        # "ImportError: initialization failed"), and the half-built module then crashed the
        # interpreter's finalisation. The outputs are whole (the finally clauses ran): skip it.
        status = interrupted_exit(Interrupted(signum))
        sys.stdout.flush()
        os._exit(status)
    return status


if __name__ == "__main__":
    sys.exit(entry_point())
