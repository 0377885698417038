"""A toy book for the build tool's tests: a few MyST notebooks, a minimal configuration.

Each page is one code cell. The tests build it with ``tools/build_book.py --book --config`` (the
real build, a tiny input), so that a build costs seconds rather than minutes.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BUILD = ROOT / "tools" / "build_book.py"

HEADER = """---
jupytext:
  text_representation:
    extension: .md
    format_name: myst
kernelspec:
  display_name: Python 3
  language: python
  name: python3
---

# {title}

```{{code-cell}} ipython3
{code}
```
"""

CONFIG = """title: Toy
author: tests
only_build_toc_files: true
execute:
  execute_notebooks: force
  timeout: 900
latex:
  latex_engine: xelatex
  use_jupyterbook_latex: false
  latex_documents:
    targetname: book.tex
sphinx:
  local_extensions:
    toy_phases: book/_ext
  config:
    nb_execution_raise_on_error: true
    latex_elements:
      preamble: |
{preamble}
"""

# a Sphinx extension that says when Sphinx reads and writes, and can linger there
EXTENSION = """
import os
import time


def _linger(phase):
    print(f"toy: sphinx {phase}", flush=True)
    if os.environ.get("TOY_LINGER") == phase:
        time.sleep(600)


def setup(app):
    app.connect("source-read", lambda app, docname, source: _linger("reading"))
    app.connect("html-page-context", lambda app, *args: _linger("writing"))
    return {"parallel_read_safe": True}
"""

# TeX busy for about a minute: the PDF phase lasts long enough to be interrupted
LATEX_LOOP = r"""        \newcount\toyn
        \loop\advance\toyn by 1 \ifnum\toyn<400000000 \repeat"""


def page(title: str, code: str) -> str:
    return HEADER.format(title=title, code=code)


def make_book(
    folder: Path, chapters: dict[str, dict[str, str]], slow_latex: bool = False
) -> tuple[Path, Path]:
    """Write a toy book: ``chapters`` maps a folder name to ``{file name: code}``.

    Returns the book folder and its configuration file.
    """
    book = folder / "book"
    (book / "_ext").mkdir(parents=True, exist_ok=True)
    (book / "_ext" / "toy_phases.py").write_text(EXTENSION)
    (book / "intro.md").write_text("# Toy\n\nA toy book.\n")
    toc = "format: jb-book\nroot: intro\nparts:\n"
    for name, pages in chapters.items():
        (book / name).mkdir(exist_ok=True)
        (book / name / "index.md").write_text(f"# Chapter {name}\n\nPages.\n")
        for file, code in pages.items():
            (book / name / file).write_text(page(file, code))
        toc += f"  - caption: {name}\n    chapters:\n      - file: {name}/index\n"
        toc += f"        sections:\n          - glob: {name}/[0-9]*\n"
    (book / "_toc.yml").write_text(toc)
    config = folder / "_config.yml"
    config.write_text(CONFIG.format(preamble=LATEX_LOOP if slow_latex else "        % none"))
    return book, config


def build_command(book: Path, config: Path, out: Path, builder: str = "html") -> list[str]:
    return [
        sys.executable, str(BUILD), "--cache", "--book", str(book), "--config", str(config),
        "--out", str(out), "--builder", builder, "--jobs", "2",
    ]  # fmt: skip


def build_env(tmp: Path, **extra: str) -> dict[str, str]:
    env = dict(os.environ, NAVCORE_BOOK_CACHE=str(tmp / "jupyter_cache"), NAVCORE_CACHE=str(tmp / "ledger"))
    env.pop("NAVCORE_STOP_WITH_PARENT", None)
    env.update(extra)
    return env
