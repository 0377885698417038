"""Build the book, or a subset of it, strictly.

Usage::

    python tools/build_book.py                 # whole book, HTML, into _build/html
    python tools/build_book.py --builder pdflatex
    python tools/build_book.py --only wf       # intro + the WF chapter + ledger/errata pages,
                                               # into _build/subset-wf (fast check of one chapter)

The build is strict: forced execution, a failing cell fails it (``nb_execution_raise_on_error``),
and ``-W -n --keep-going`` turns warnings, broken references and missing citations into errors.
Paths are absolute because ``jupyter-book build .`` breaks singlehtml and walks ``.nox/``.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PARTS = {
    "wf": "Wu & Fowler",
    "sp": "Schmidt & Phillips",
    "atc10": "ATC-10",
    "kzl": "Knedlik, Zhou & Loffeld",
}


def subset_toc(paper: str) -> str:
    return (
        "format: jb-book\nroot: intro\nparts:\n"
        f"  - caption: {PARTS[paper]}\n    chapters:\n      - file: {paper}/index\n"
        f"        sections:\n          - glob: {paper}/[0-9]*\n"
        "  - caption: Verification\n    chapters:\n      - file: ledger\n      - file: errata\n"
        "      - file: bibliography\n"
    )


def build(builder: str = "html", only: str | None = None, out: Path | None = None) -> int:
    config = ROOT / "_config.yml"
    toc = ROOT / "book" / "_toc.yml"
    tmp = None
    if only:
        if only not in PARTS:
            raise SystemExit(f"--only must be one of {list(PARTS)}, got {only!r}")
        # the subset toc must sit in book/ so that relative file names resolve
        tmp = tempfile.NamedTemporaryFile("w", suffix=".yml", prefix="_toc_subset_", dir=ROOT / "book", delete=False)
        tmp.write(subset_toc(only))
        tmp.close()
        toc = Path(tmp.name)
        out = out or ROOT / "_build" / f"subset-{only}"
    out = out or ROOT
    cmd = [
        str(Path(sys.executable).with_name("jupyter-book")), "build", str(ROOT / "book"),
        "--config", str(config), "--toc", str(toc), "--path-output", str(out),
        "--builder", builder, "--all", "-W", "-n", "--keep-going",
    ]  # fmt: skip
    print("+", " ".join(cmd), flush=True)
    try:
        return subprocess.call(cmd, cwd=ROOT)
    finally:
        if tmp is not None:
            Path(tmp.name).unlink(missing_ok=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--builder", default="html", choices=["html", "pdflatex", "latex", "linkcheck"])
    parser.add_argument("--only", default=None, help="build only one paper's chapter: wf, sp, atc10, kzl")
    parser.add_argument("--out", type=Path, default=None, help="output folder (default: the repository)")
    args = parser.parse_args()
    return build(args.builder, args.only, args.out)


if __name__ == "__main__":
    raise SystemExit(main())
