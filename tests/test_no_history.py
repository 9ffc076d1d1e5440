"""The library, the pipeline and the README state contracts and provenance, never history
(issue 36, item 7): no ISO dates and no narrating phrases in spectral_rod/, reproduce/ and
README.md. History belongs in CHANGELOG.md and tests/bench/HISTORY.md."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
#: An ISO date (2026-12-05), and phrases that narrate how the code came to be.
HISTORY = re.compile(
    r"\b(?:19|20)\d\d-[01]\d-[0-3]\d\b"
    r"|\bad hoc\b|\bnot kept\b|\buntil this\b|\ba later\b|\bthis session\b"
    r"|\bissue \d+\b|\bbefore \d{4}\b", re.IGNORECASE)


def history_lines(path: Path) -> list[str]:
    """``path:line: text`` for each line of `path` that narrates history."""
    lines = path.read_text(encoding="utf-8").splitlines()
    return [f"{path.relative_to(ROOT)}:{i}: {line.strip()}"
            for i, line in enumerate(lines, 1) if HISTORY.search(line)]


def test_the_pattern_finds_history_and_spares_contracts(tmp_path):
    for text, found in (("measured 2026-12-05 on one machine", True),
                        ("gained 7-10 % ad hoc, not kept", True),
                        ("Until this session the pencils answered", True),
                        ("see issue 14's targets", True),
                        ("tol in [1e-14, 1e-2]; p* = 1.164464854", False),
                        ("the O(Omega^-3) term, e.g. 1e-12 relative", False)):
        probe = ROOT / "tests" / "_history_probe.txt"  # inside ROOT: relative_to needs it
        try:
            probe.write_text(text, encoding="utf-8")
            assert bool(history_lines(probe)) is found, text
        finally:
            probe.unlink()


@pytest.mark.xfail(strict=False, reason="the other modules' owners are removing their history "
                   "text in parallel; flip to a plain test once their branches are merged")
def test_no_history_in_the_library_pipeline_and_readme():
    files = [*sorted((ROOT / "spectral_rod").rglob("*.py")),
             *sorted((ROOT / "reproduce").rglob("*.py")), ROOT / "README.md"]
    found = [hit for path in files if path.is_file() for hit in history_lines(path)]
    assert not found, f"{len(found)} lines narrate history:\n" + "\n".join(found[:40])
