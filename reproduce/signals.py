"""Signals: SIGTERM is handled like SIGINT, and an interrupt at any moment ends the run with one
line on stderr, never a traceback.

Both signals raise :class:`Interrupted` (a :class:`KeyboardInterrupt`), so the ``finally``
clauses of :mod:`reproduce.io` remove the temporary file being written and earlier outputs
stay whole. After the first signal further ones are ignored while the run unwinds. The handlers
are in place from the first lines of ``reproduce/__main__.py`` on, before numpy, scipy or
matplotlib are imported; only during the interpreter's own start-up (~20 ms, before any code of
this package runs) does Python's default apply.

>>> interrupted_message(Interrupted(15))
'python -m reproduce: terminated (SIGTERM); earlier outputs are whole, no partial file left'
"""

from __future__ import annotations

import signal
import sys
from types import FrameType


class Interrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM arrived; `signum` says which."""

    def __init__(self, signum: int = signal.SIGINT) -> None:
        super().__init__(signum)
        self.signum = int(signum)


#: The signals received so far (the handler records each before raising).
_RECEIVED: list[int] = []


def _raise_interrupted(signum: int, frame: FrameType | None) -> None:
    _RECEIVED.append(int(signum))
    raise Interrupted(signum)


def received() -> int | None:
    """The first SIGINT or SIGTERM this process's handlers received, or None."""
    return _RECEIVED[0] if _RECEIVED else None


def install_handlers() -> None:
    """Turn SIGINT and SIGTERM into :class:`Interrupted` (call first thing in a CLI process).

    A signal the process inherited as ignored stays ignored (``nohup``, ``cmd &`` in a script).
    The record of :func:`received` starts empty (a second run in one process is not interrupted
    by the first one's signal).
    """
    _RECEIVED.clear()
    for sig in (signal.SIGINT, signal.SIGTERM):
        if signal.getsignal(sig) is not signal.SIG_IGN:
            signal.signal(sig, _raise_interrupted)


def ignore_signals() -> None:
    """Ignore SIGINT and SIGTERM from now on (the run is over or unwinding)."""
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, signal.SIG_IGN)


def interrupted_message(exc: BaseException) -> str:
    signum = getattr(exc, "signum", signal.SIGINT)
    what = "terminated (SIGTERM)" if signum == signal.SIGTERM else "interrupted"
    return f"python -m reproduce: {what}; earlier outputs are whole, no partial file left"


def interrupted_exit(exc: BaseException) -> int:
    """Ignore further signals, print the one-line message; return 128 + the signal number."""
    ignore_signals()
    print(interrupted_message(exc), file=sys.stderr, flush=True)
    return 128 + int(getattr(exc, "signum", signal.SIGINT))
