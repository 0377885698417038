"""Release gates on a built book: what a reader sees, and that two builds are the same.

Usage::

    python tools/check_book.py html _build/html        # helpers in code cells; notebook outputs
    python tools/check_book.py latex _build/latex      # overfull boxes; helpers in code listings
    python tools/check_book.py same BUILD_A BUILD_B    # byte-identical trees (PDF: up to its dates)

``html``: no rendered code cell shows a build helper (``glue(...)``, ``show_figure``,
``book.setup()``, ``%matplotlib``), and every downloadable notebook under ``_sources`` is
executed (each code cell has an execution count) and carries outputs.
``latex``: the LaTeX log reports no overfull box wider than ``--max-overfull`` points, and
no code listing shows a build helper.
``same``: every file of the two trees is byte-identical, except that PDFs are compared
without their creation and modification dates and document id.

Exit status 1 and one line per problem when a gate fails.
"""

from __future__ import annotations

import argparse
import html
import json
import re
import sys
from pathlib import Path

HELPERS = re.compile(
    r"(?m)^\s*(?:glue\s*\(|(?:book\.)?show_figure\s*\(|book\.setup\s*\(|%matplotlib|from myst_nb import glue)"
)
CELL_PRE = re.compile(
    r'class="cell_input[^"]*"[^>]*>\s*<div class="highlight-[^"]*"><div class="highlight"><pre>(.*?)</pre>',
    re.S,
)
OVERFULL = re.compile(r"^Overfull \\hbox \((\d+(?:\.\d+)?)pt too wide\)(.*)$", re.M)
VERBATIM = re.compile(r"\\begin\{sphinxVerbatim\}.*?\n(.*?)\\end\{sphinxVerbatim\}", re.S)


def _text(fragment: str) -> str:
    return html.unescape(re.sub(r"<[^>]+>", "", fragment))


def check_html(root: Path) -> list[str]:
    problems = []
    for page in sorted(root.rglob("*.html")):
        if "_sources" in page.parts or "_static" in page.parts:
            continue
        for block in CELL_PRE.findall(page.read_text(encoding="utf-8", errors="replace")):
            m = HELPERS.search(_text(block))
            if m:
                problems.append(f"{page.relative_to(root)}: a code cell shows {m.group(0).strip()!r}")
    for nb_path in sorted((root / "_sources").rglob("*.ipynb")):
        nb = json.loads(nb_path.read_text(encoding="utf-8"))
        code = [c for c in nb.get("cells", []) if c.get("cell_type") == "code"]
        if not code:
            continue
        unrun = sum(c.get("execution_count") is None for c in code)
        if unrun or not any(c.get("outputs") for c in code):
            problems.append(
                f"{nb_path.relative_to(root)}: download is not executed "
                f"({unrun} of {len(code)} code cells without execution count, "
                f"{sum(bool(c.get('outputs')) for c in code)} with outputs)"
            )
    return problems


def check_latex(root: Path, max_overfull: float = 3.0) -> list[str]:
    problems = []
    logs = sorted(root.glob("*.log"))
    if not logs:
        problems.append(f"{root}: no LaTeX log")
    for log in logs:
        text = log.read_text(encoding="utf-8", errors="replace")
        for width, where in OVERFULL.findall(text):
            if float(width) > max_overfull:
                problems.append(f"{log.name}: overfull box {width} pt too wide{where}")
    for tex in sorted(root.glob("*.tex")):
        for block in VERBATIM.findall(tex.read_text(encoding="utf-8", errors="replace")):
            m = HELPERS.search(block)
            if m:
                problems.append(f"{tex.name}: a code listing shows {m.group(0).strip()!r}")
    return problems


_PDF_DATES = re.compile(rb"/(?:CreationDate|ModDate)\s*\(D:[^)]*\)|/ID\s*\[<[0-9A-Fa-f]+>\s*<[0-9A-Fa-f]+>\]")


def same_trees(a: Path, b: Path) -> list[str]:
    files_a = {p.relative_to(a) for p in a.rglob("*") if p.is_file()}
    files_b = {p.relative_to(b) for p in b.rglob("*") if p.is_file()}
    problems = [f"only in {a}: {p}" for p in sorted(files_a - files_b)]
    problems += [f"only in {b}: {p}" for p in sorted(files_b - files_a)]
    for rel in sorted(files_a & files_b):
        x, y = (a / rel).read_bytes(), (b / rel).read_bytes()
        if rel.suffix == ".pdf":
            x, y = _PDF_DATES.sub(b"", x), _PDF_DATES.sub(b"", y)
        if x != y:
            problems.append(f"differs: {rel}")
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("gate", choices=["html", "latex", "same"])
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--max-overfull", type=float, default=3.0, help="points (latex gate)")
    args = parser.parse_args(argv)
    if args.gate == "html":
        problems = check_html(args.paths[0])
    elif args.gate == "latex":
        problems = check_latex(args.paths[0], args.max_overfull)
    else:
        if len(args.paths) != 2:
            parser.error("same needs two build folders")
        problems = same_trees(*args.paths)
    for line in problems:
        print(line)
    print(f"check_book {args.gate}: {len(problems)} problem(s)", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
