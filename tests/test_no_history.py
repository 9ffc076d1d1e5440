"""The library, the pipeline and the README state contracts and provenance, never history
(issue 36, item 7): no ISO dates and no narrating phrases in spectral_rod/, reproduce/ and
README.md. History belongs in CHANGELOG.md and tests/bench/HISTORY.md."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
#: An ISO date (2026-12-05), a commit named as a time ("at 1b2e152"), and phrases that narrate
#: how the code came to be. "a later", "before" and "until" narrate only before a word of
#: development ("a later session", "before the fix", "until this change", "was 20 until"):
#: "a later maximum", "before it builds" and "until round-off takes over" are contracts.
DEVELOPMENT = (r"(?:session|version|commit|change|fix|refactor|rewrite|merge|wave|engineer"
               r"|branch|kernel|release)s?")
HISTORY = re.compile(
    r"\b(?:19|20)\d\d-[01]\d-[0-3]\d\b"
    r"|\bat [0-9a-f]{7,40}\b"
    r"|\bad hoc\b|\b(?:not|none|was|were) kept\b|\bsessions?\b|\bissues? #?\d+"
    r"|\buntil (?:this|that)\b|\bwas \S+ until\b|\bas before\b"
    r"|\bbefore (?:\d{4}\b|it was\b|its \w+ was\b|(?:the|this|that) (?:\w+ )?" + DEVELOPMENT
    + r"\b)"
    r"|\b(?:a|the) (?:later|earlier|previous) " + DEVELOPMENT + r"\b",
    re.IGNORECASE)
#: The files that must carry no history: the library and the pipeline (code, C sources and
#: their headers, any text shipped with them) and the README.
SUFFIXES = (".py", ".c", ".h", ".md", ".txt")


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
                        ("It was 20 until the kernel took the scalar calls", True),
                        ("defensive, as before the kernel was shared", True),
                        ("1.15 us a point before its workspace was aligned", True),
                        ("by hand, at 1b2e152, on a shared machine", True),
                        ("a later session measured it again", True),
                        ("tol in [1e-14, 1e-2]; p* = 1.164464854", False),
                        ("the O(Omega^-3) term, e.g. 1e-12 relative", False),
                        ("local, not global: a later maximum is higher", False),
                        ("C h^2 until round-off ~ eps N^2 takes over", False),
                        ("the sites it depends on before it builds the Forensics", False),
                        ("history [(M, q)] of the truncations tried", False),
                        ("Set to 1 (before the first solve) to run the numpy reference", False)):
        probe = ROOT / "tests" / "_history_probe.txt"  # inside ROOT: relative_to needs it
        try:
            probe.write_text(text, encoding="utf-8")
            assert bool(history_lines(probe)) is found, text
        finally:
            probe.unlink()


def test_no_history_in_the_library_pipeline_and_readme():
    files = [path for package in ("spectral_rod", "reproduce")
             for path in sorted((ROOT / package).rglob("*")) if path.suffix in SUFFIXES]
    files.append(ROOT / "README.md")
    found = [hit for path in files if path.is_file() for hit in history_lines(path)]
    assert not found, f"{len(found)} lines narrate history:\n" + "\n".join(found[:40])
