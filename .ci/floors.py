"""Print pip constraints pinning every declared dependency to its lower bound.

Reads ``[project] dependencies`` and the ``test`` extra of pyproject.toml and writes one
``name==floor`` line per ``name>=floor`` requirement, so the floors step of ``.ci/run`` installs
exactly what pyproject.toml promises (the two cannot drift apart). A requirement without a
``>=`` lower bound is an error: every dependency must declare a tested floor.

    python .ci/floors.py > floors.txt && pip install -c floors.txt '.[test]'
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import tomllib

_REQ = re.compile(r"^\s*([A-Za-z0-9_.\-]+)\s*>=\s*([0-9][A-Za-z0-9_.]*)\s*(?:,.*)?$")


def floor_pins(pyproject: Path) -> list[str]:
    """``name==floor`` for each runtime and test requirement of `pyproject`."""
    project = tomllib.loads(pyproject.read_text(encoding="utf-8"))["project"]
    reqs = list(project["dependencies"]) + list(project["optional-dependencies"]["test"])
    pins = []
    for req in reqs:
        m = _REQ.match(req)
        if m is None:
            raise SystemExit(f"{pyproject}: requirement {req!r} has no '>=' lower bound")
        pins.append(f"{m[1]}=={m[2]}")
    return pins


if __name__ == "__main__":
    root = Path(__file__).resolve().parent.parent
    print("\n".join(floor_pins(root / "pyproject.toml")))
    sys.exit(0)
