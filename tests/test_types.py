"""The package's type hints as a user's type checker sees them: mypy (config in pyproject.toml)
on spectral_rod/, and on a small user file that reveals a public signature and misspells a
public name. Slow (mypy analyses the whole package, ~10 s cold); skipped where mypy is not
installed.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

pytestmark = pytest.mark.slow


def _mypy(*args: str, cache: Path) -> subprocess.CompletedProcess[str]:
    pytest.importorskip("mypy")
    return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(cache), *args],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)


def test_user_file_sees_signatures_and_misspelled_names(tmp_path: Path) -> None:
    """critical_load's signature reaches a user (py.typed, typed face), a correct call passes
    and a misspelled public name is an error on its line (not Any: the import resolved)."""
    user = tmp_path / "user.py"
    user.write_text("import spectral_rod\n"
                    "reveal_type(spectral_rod.critical_load)\n"
                    "spectral_rod.critical_load(0.5, 1.5, tol=1e-10)\n"
                    "spectral_rod.critical_laod(0.5, 1.5)\n")
    # follow-imports=silent: the package is analysed but only the user file's errors are shown
    run = _mypy("--follow-imports=silent", str(user), cache=tmp_path / "cache")
    lines = [ln for ln in run.stdout.splitlines() if ln.startswith(str(user))]
    revealed = [ln for ln in lines if ":2: note: Revealed type is" in ln]
    assert revealed and "def (twist_angle:" in revealed[0] and "nu:" in revealed[0], run.stdout
    errors = [ln for ln in lines if ": error:" in ln]
    assert len(errors) == 1 and errors[0].startswith(f"{user}:4: error:"), run.stdout
    assert 'has no attribute "critical_laod"' in errors[0]
    assert run.returncode == 1


def test_package_passes_mypy(tmp_path: Path) -> None:
    """`mypy` (files = spectral_rod, pyproject.toml) reports no error."""
    run = _mypy(cache=tmp_path / "cache")
    assert run.returncode == 0, run.stdout
