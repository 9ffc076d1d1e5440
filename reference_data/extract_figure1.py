"""Regenerate figure1_digitised.csv (and figure1_picture.tex) from the paper's LaTeX source.

    python reference_data/extract_figure1.py [PATH_TO_TEX] [OUT_CSV]

Defaults: ../shared/paper/drozdov-rabin-buckling.tex (relative to the project root) and
spectral_rod/data/figure1_digitised.csv (shipped with the package). The picture environment is
also copied verbatim to figure1_picture.tex next to the CSV (its line formatting is evidence
for spectral_rod.figure1.forensics). See spectral_rod/data/figure1_digitised.md for the
provenance. Only this script needs the paper.
"""

from __future__ import annotations

import sys
from pathlib import Path

from reproduce.io import write_text, write_with
from spectral_rod.figure1.data import parse_figure1
from spectral_rod.figure1.forensics import picture_environment

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_TEX = ROOT.parent / "shared" / "paper" / "drozdov-rabin-buckling.tex"
DEFAULT_CSV = ROOT / "spectral_rod" / "data" / "figure1_digitised.csv"


def main(argv: list[str]) -> int:
    tex = Path(argv[1]) if len(argv) > 1 else DEFAULT_TEX
    out = Path(argv[2]) if len(argv) > 2 else DEFAULT_CSV
    source = tex.read_text(encoding="utf-8")
    df = parse_figure1(source)
    write_with(out, lambda p: df.to_csv(p, index=False, float_format="%.10g"))
    write_text(out.with_name("figure1_picture.tex"), picture_environment(source))
    counts = df.groupby("nu").size().to_dict()
    print(f"wrote {out}: {len(df)} points, per nu {counts}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
