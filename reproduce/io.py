"""Atomic output: a file appears complete or not at all, so an interrupted run leaves the
previous results intact (write to a temporary file in the same directory, then rename).

- Temporary files are named ``.NAME~PID~XXXXXXXX.SUFFIX``: a run killed outright (SIGKILL,
  power loss) cannot clean up, so :func:`remove_stale_temporaries` deletes, at the start of the
  next run, those whose process is gone (a concurrent live run's files are left alone), and
  the ``.NAME-XXXXXXXX.SUFFIX`` files that earlier versions of this module left behind.
- Outputs get the permissions of a normally created file (``0o666`` less the umask), not the
  ``0o600`` of :func:`tempfile.mkstemp`, which would survive the rename.
- A failed write (disk full, quota, I/O error) raises :class:`OSError` naming the output file.
- An earlier output read back (the ledger, a report section) that is not what the pipeline
  wrote raises :class:`OutputFileError` naming the file, so the CLI can exit 2 with one line.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import tempfile
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any


class OutputFileError(ValueError):
    """An output of an earlier run is unreadable or not of the shape this pipeline writes; the
    message names the file and how to recover."""


def _current_umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def output_mode() -> int:
    """Permission bits of a new output file: ``0o666`` less the process umask."""
    return 0o666 & ~_current_umask()


def _temp_prefix(path: Path) -> str:
    return f".{path.name}~{os.getpid()}~"


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path next to `path`; on success rename it onto `path`.

    >>> with atomic_path(Path(tempfile.mkdtemp()) / "a.txt") as tmp:
    ...     _ = tmp.write_text("x")
    """
    path = Path(path)
    tmp_path: Path | None = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=_temp_prefix(path), suffix=path.suffix,
                                   dir=path.parent)
        os.close(fd)
        tmp_path = Path(tmp)
        yield tmp_path
        os.chmod(tmp_path, output_mode())
        os.replace(tmp_path, path)
    except OSError as exc:
        raise OSError(exc.errno, f"cannot write {path}: {exc.strerror or exc}") from exc
    finally:
        if tmp_path is not None and tmp_path.exists():
            tmp_path.unlink()


def write_text(path: str | os.PathLike[str], text: str) -> Path:
    """Write `text` to `path` atomically (UTF-8)."""
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


def write_with(path: str | os.PathLike[str], writer: Callable[[Path], object]) -> Path:
    """Call `writer(tmp_path)` (e.g. ``fig.savefig`` or ``df.to_csv``) and rename atomically."""
    with atomic_path(path) as tmp:
        writer(tmp)
    return Path(path)


def write_csv(path: str | os.PathLike[str], frame: Any, *, float_format: str | None = None
              ) -> Path:
    """Write the DataFrame `frame` to `path` atomically (no index column)."""
    return write_with(path, lambda p: frame.to_csv(p, index=False, float_format=float_format))


def write_figure(path: str | os.PathLike[str], fig: Any, dpi: int = 150, *,
                 close: bool = True) -> Path:
    """Save the matplotlib figure `fig` to `path` atomically, in the format its suffix names,
    then close it (``close=False`` to save the same figure again in another format)."""
    fmt = Path(path).suffix.lstrip(".")
    written = write_with(path, lambda p: fig.savefig(p, format=fmt, dpi=dpi))
    if close:
        import matplotlib.pyplot as plt  # lazily: the CLI's --help must not load matplotlib

        plt.close(fig)
    return written


def json_value(value: Any) -> Any:
    """``default=`` of :func:`json.dumps` for the outputs: numpy scalars and arrays as the JSON
    type of their value (bool, int, float, list), other real numbers (mpmath's) as floats, paths
    as text; anything else is an error, not text, so that a number never reaches a JSON output
    as a string and a flag never as a float.

    >>> import numpy as np
    >>> json.dumps({"n": np.int64(3), "ok": np.bool_(True), "x": np.float64(0.5)},
    ...            default=json_value)
    '{"n": 3, "ok": true, "x": 0.5}'
    """
    if hasattr(value, "tolist") and hasattr(value, "dtype"):  # numpy scalar or array
        return value.tolist()
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if hasattr(value, "__float__") and not isinstance(value, (str, bytes)):  # e.g. mpmath.mpf
        return float(value)
    raise TypeError(f"{type(value).__name__} {value!r} is not a JSON value")


def read_json(path: str | os.PathLike[str], kind: type = dict, keys: Sequence[str] = ()
              ) -> Any:
    """The JSON document at `path`, checked to be a `kind` (dict or list) and, for a dict, to
    have `keys`; :class:`OutputFileError` naming the file otherwise."""
    path = Path(path)
    fix = "delete it to rebuild it"
    try:
        value = json.loads(path.read_text(encoding="utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise OutputFileError(f"{path} is not valid JSON ({exc}); {fix}") from exc
    if not isinstance(value, kind):
        raise OutputFileError(f"{path} must hold a JSON {kind.__name__}; {fix}")
    missing = [k for k in keys if k not in value] if isinstance(value, dict) else []
    if missing:
        raise OutputFileError(f"{path} lacks the keys {missing}; {fix}")
    return value


#: ``.NAME~PID~XXXXXXXX.SUFFIX`` (this module) and ``.STEM-XXXXXXXX.SUFFIX`` (earlier versions,
#: whose mkstemp names had 8 random characters) and ``.probe-XXXXXXXX``.
_TEMP = re.compile(r"^\.(?P<name>.+)~(?P<pid>\d+)~[a-z0-9_]{8}(?P<suffix>\.\w+)?$")
_LEGACY = re.compile(r"^\.(?P<stem>.+)-[a-z0-9_]{8}(?P<suffix>\.\w+)?$")


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # exists, owned by someone else
        return True
    return True


def _is_stale(entry: Path) -> bool:
    m = _TEMP.match(entry.name)
    if m:
        return not _alive(int(m["pid"]))
    m = _LEGACY.match(entry.name)
    return bool(m) and (m["stem"] == "probe"
                        or (entry.parent / f"{m['stem']}{m['suffix'] or ''}").exists())


def remove_stale_temporaries(directory: str | os.PathLike[str]) -> list[Path]:
    """Delete temporary files of dead runs in `directory` and its ``sections/``; return them."""
    removed = []
    for folder in (Path(directory), Path(directory) / "sections"):
        if not folder.is_dir():
            continue
        for entry in folder.iterdir():
            if entry.name.startswith(".") and entry.is_file() and _is_stale(entry):
                with contextlib.suppress(FileNotFoundError):
                    entry.unlink()
                    removed.append(entry)
    return removed


def ensure_writable_dir(directory: str | os.PathLike[str]) -> Path:
    """Create `directory` if needed and check that files can be created in it.

    Raises OSError naming the directory otherwise, before any output is written.
    """
    directory = Path(directory)
    try:
        directory.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=directory, prefix=f".probe~{os.getpid()}~"):
            pass
    except OSError as exc:
        raise OSError(exc.errno, f"output directory {directory} is not writable: "
                                 f"{exc.strerror or exc}") from exc
    return directory
