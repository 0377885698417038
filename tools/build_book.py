"""Build the book, or a subset of it, strictly.

Usage::

    python tools/build_book.py                 # whole book, HTML, into _build/html
    python tools/build_book.py --builder pdflatex
    python tools/build_book.py --only wf       # intro + the WF chapter + ledger/errata pages,
                                               # into _build/subset-wf (fast check of one chapter)

``--cache`` executes through a jupyter-cache whose folder is keyed by a hash of navcore's
sources, the lock file, ``_config.yml`` and the build tools: on a clean checkout every notebook
is executed (as with ``force``), and a second build with the same code (the PDF after the
HTML, or a rebuild after editing one chapter) re-executes only the notebooks whose text
changed. Any change to navcore changes the key, so results are never stale.

The build is strict: forced execution, a failing cell fails it (``nb_execution_raise_on_error``),
and ``-W -n --keep-going`` turns warnings, broken references and missing citations into errors.
Paths are absolute because ``jupyter-book build .`` breaks singlehtml and walks ``.nox/``.
"""

from __future__ import annotations

import argparse
import hashlib
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
        "  - caption: Introduction\n    chapters:\n      - file: about\n"
        f"  - caption: {PARTS[paper]}\n    chapters:\n      - file: {paper}/index\n"
        f"        sections:\n          - glob: {paper}/[0-9]*\n"
        "  - caption: Verification\n    chapters:\n      - file: ledger\n      - file: errata\n"
        "      - file: bibliography\n"
    )


def source_key() -> str:
    """Hash of everything besides a notebook's own text that can change its outputs."""
    h = hashlib.sha256()
    files = [
        *sorted((ROOT / "navcore").rglob("*.py")),
        ROOT / "requirements" / "lock.txt",
        ROOT / "_config.yml",
    ]
    files += sorted((ROOT / "tools").glob("*.py"))
    for f in files:
        if f.exists():
            h.update(str(f.relative_to(ROOT)).encode())
            h.update(f.read_bytes())
    return h.hexdigest()[:16]


def cached_config() -> Path:
    """A copy of _config.yml that executes through a source-keyed jupyter-cache."""
    import yaml

    config = yaml.safe_load((ROOT / "_config.yml").read_text())
    config["execute"]["execute_notebooks"] = "cache"
    config["execute"]["cache"] = str(ROOT / "_build" / "jupyter_cache" / source_key())
    path = ROOT / "_build" / "_config_cached.yml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(yaml.safe_dump(config, sort_keys=False))
    return path


def build(
    builder: str = "html", only: str | None = None, out: Path | None = None, cache: bool = False
) -> int:
    config = cached_config() if cache else ROOT / "_config.yml"
    toc = ROOT / "book" / "_toc.yml"
    tmp = None
    if only:
        if only not in PARTS:
            raise SystemExit(f"--only must be one of {list(PARTS)}, got {only!r}")
        # the subset toc must sit in book/ so that relative file names resolve
        tmp = tempfile.NamedTemporaryFile(
            "w", suffix=".yml", prefix="_toc_subset_", dir=ROOT / "book", delete=False
        )
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
    parser.add_argument("--cache", action="store_true", help="execute through a source-keyed jupyter-cache")
    args = parser.parse_args()
    return build(args.builder, args.only, args.out, args.cache)


if __name__ == "__main__":
    raise SystemExit(main())
