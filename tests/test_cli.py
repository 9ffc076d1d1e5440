"""The reproduce CLI: usage errors, unwritable output, interrupted runs (issue 6, bad input)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

import reproduce.__main__ as cli
import reproduce.cli
from reproduce.io import write_text, write_with

ROOT = Path(__file__).resolve().parent.parent


def test_unknown_scene_prints_usage_and_exits_2(capsys, tmp_path):
    assert cli.main(["no_such_scene", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "usage:" in err and "no_such_scene" in err
    assert list(tmp_path.iterdir()) == []  # nothing written


@pytest.mark.parametrize("argv", [["--bogus", "extremes"], [], ["extremes", "--out"]])
def test_bad_option_prints_usage_and_exits_2(capsys, argv):
    with pytest.raises(SystemExit) as info:
        cli.main(argv)
    assert info.value.code == 2
    assert "usage:" in capsys.readouterr().err


@pytest.mark.parametrize("argv", [["list", "figure1"], ["list", "--out", "x"],
                                  ["list", "--against", "x"]])
def test_list_takes_nothing_else(capsys, argv):
    # exited 0 ignoring the option, or blamed the target 'list' (before 2026-12-04)
    assert cli.main(argv) == 2
    assert "'list' takes no scene names" in capsys.readouterr().err


def test_options_before_scene_names(capsys, tmp_path):
    # argparse's 'unrecognized arguments: figure1' before 2026-12-04
    assert cli.main(["check", "--against", str(tmp_path / "none"), "figure1"]) == 2
    assert "no committed outputs to check against" in capsys.readouterr().err


def test_list_is_ok(capsys):
    assert cli.main(["list"]) == 0
    assert "extremes" in capsys.readouterr().out


def test_unwritable_output_directory_is_a_clear_error(capsys, tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("x", encoding="utf-8")
    assert cli.main(["extremes", "--out", str(blocker / "out")]) == 2
    err = capsys.readouterr().err
    assert "error" in err and str(blocker / "out") in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a_file"]


@pytest.mark.skipif(os.geteuid() == 0, reason="root ignores directory permissions")
def test_read_only_output_directory(capsys, tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        assert cli.main(["extremes", "--out", str(ro)]) == 2
        assert "not writable" in capsys.readouterr().err
        assert list(ro.iterdir()) == []
    finally:
        ro.chmod(0o700)


def test_interrupted_write_keeps_previous_file_whole(tmp_path):
    target = write_text(tmp_path / "table.csv", "old,complete\n")

    def writer(p: Path) -> None:
        p.write_text("new,partial", encoding="utf-8")
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_with(target, writer)
    assert target.read_text(encoding="utf-8") == "old,complete\n"
    assert [p.name for p in tmp_path.iterdir()] == ["table.csv"]  # no temporary left behind


def test_interrupted_run_exits_130_with_message(monkeypatch, capsys, tmp_path):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(reproduce.cli, "run_scenes", interrupted)
    assert cli.main(["extremes", "--out", str(tmp_path)]) == 130
    assert "interrupted" in capsys.readouterr().err


def test_module_entry_point_exit_status():
    proc = subprocess.run([sys.executable, "-m", "reproduce", "no_such_scene"], cwd=ROOT,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2
    assert "usage:" in proc.stderr and proc.stdout == ""


@pytest.mark.parametrize("argv", [["all", "figure1"], ["figure1", "all"],
                                  ["check", "all", "figure1"]])
def test_all_with_scenes_is_a_usage_error(capsys, argv):
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert "'all' cannot be combined with scene names (figure1)" in err
    assert "unknown target" not in err


@pytest.mark.parametrize("argv", [["info", "figure1"], ["info", "--out", "x"]])
def test_info_takes_nothing_else(capsys, argv):
    assert cli.main(argv) == 2
    assert "'info' takes no scene names" in capsys.readouterr().err


def test_info_prints_the_engine(capsys):
    from spectral_rod.rod.collocation.modal_kernel import available

    assert cli.main(["info"]) == 0
    out = capsys.readouterr().out
    assert f"kernel: {available()}" in out and "numpy:" in out and "BLAS" in out


def test_python_m_spectral_rod_prints_the_engine(tmp_path):
    # run outside the checkout: the package these tests import, not a source tree in the cwd
    import json

    import spectral_rod
    from spectral_rod.rod.collocation.modal_kernel import available

    text = subprocess.run([sys.executable, "-m", "spectral_rod"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120, check=True).stdout
    assert text.startswith(f"spectral_rod {spectral_rod.__version__} (Python ")
    assert ("engine: C kernel" if available() else "engine: numpy (no compiled kernel") in text
    report = json.loads(subprocess.run([sys.executable, "-m", "spectral_rod", "--json"],
                                       cwd=tmp_path, capture_output=True, text=True,
                                       timeout=120, check=True).stdout)
    assert report["engine"]["kernel"] is available()
    assert set(report["dependencies"]) >= {"numpy", "scipy", "threadpoolctl"}

