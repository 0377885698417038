"""A change to one navcore module re-executes only the book pages that depend on it, and says why.

The build keys each cached page on the navcore modules and data files it depends on
(tools/build_book.py): what the page imports, what those modules import (every import
statement of their source, and what navcore imported by name while the kernel ran), the data
files they name or open, and the list of navcore's modules. The oracles are written out by hand:
the import statements of a small package, and which toy pages import which module.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from _toybook import ROOT, make_book

spec = importlib.util.spec_from_file_location("tools.build_book", ROOT / "tools" / "build_book.py")
build_book = importlib.util.module_from_spec(spec)
spec.loader.exec_module(build_book)


def _package(root: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        path = root / "navcore" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def test_static_import_graph_follows_every_import_statement(tmp_path: Path) -> None:
    """Oracle: the imports of a hand-written package, inside functions and relative ones included."""
    root = _package(
        tmp_path,
        {
            "__init__.py": "",
            "a.py": "import numpy\nfrom navcore import b\n",
            "b.py": "def f():\n    from navcore.sub import c\n    return c\n",
            "sub/__init__.py": "",
            "sub/c.py": "from . import d\nfrom ..e import g\nTABLE = 'table.json'\n",
            "sub/d.py": "",
            "e.py": "g = 1\n",
            "lonely.py": "",
            "sub/table.json": "{}",
        },
    )
    graph = build_book.static_import_graph(root)
    assert graph["navcore.a"] == {"navcore", "navcore.b"}
    assert graph["navcore.b"] == {"navcore.sub", "navcore.sub.c"}
    assert graph["navcore.sub.c"] == {"navcore.sub", "navcore.sub.d", "navcore.e", "file:sub/table.json"}
    # b's function ran in the kernel, which recorded its import (b is no ledger paper module's:
    # without the record, only what b imports when it is imported counts; see the next test)
    assert build_book.page_dependencies({"navcore.a"}, {}, root)[0] == ["navcore", "navcore.a", "navcore.b"]
    modules, files = build_book.page_dependencies({"navcore.a"}, {"navcore.b": ["navcore.sub.c"]}, root)
    assert modules == [
        "navcore",
        "navcore.a",
        "navcore.b",
        "navcore.e",
        "navcore.sub",
        "navcore.sub.c",
        "navcore.sub.d",
    ]
    assert files == ["sub/table.json"]
    # what navcore imported by name while the kernel ran (the ledger's paper modules) counts too
    assert (
        "navcore.lonely"
        in build_book.page_dependencies({"navcore.e"}, {"navcore.e": ["navcore.lonely"]}, root)[0]
    )


def test_only_what_the_ledger_runs_keeps_the_imports_inside_its_functions(tmp_path: Path) -> None:
    """Oracle: a hand-written package with a paper module, a model and a page helper.

    The paper module's function imports a model, which the ledger may run in a worker process
    where nothing is recorded: a static edge. The page helper's function imports a paper module
    only when a page calls it, in the kernel, which records the import: no static edge, so a page
    that imports the helper depends on that paper only once the kernel saw the call.
    """
    root = _package(
        tmp_path,
        {
            "__init__.py": "",
            "papers/__init__.py": "",
            "papers/kzl.py": "def run():\n    from navcore import model\n    return model.X\n",
            "papers/sp.py": "",
            "model.py": "def f():\n    from navcore import deep\n",
            "deep.py": "",
            "helper.py": "from navcore import units\n\ndef glue(name):\n    from navcore.papers import sp\n",
            "units.py": "",
        },
    )
    graph = build_book.dependency_graph(root)
    assert graph["navcore.papers.kzl"] == {"navcore", "navcore.model"}
    assert graph["navcore.model"] == {"navcore", "navcore.deep"}  # reached by a paper module
    assert graph["navcore.helper"] == {"navcore", "navcore.units"}  # not: its function's import dropped
    assert build_book.static_import_graph(root)["navcore.helper"] == {
        "navcore",
        "navcore.units",
        "navcore.papers",
        "navcore.papers.sp",
    }
    modules, _ = build_book.page_dependencies({"navcore.helper"}, {}, root)
    assert modules == ["navcore", "navcore.helper", "navcore.units"]
    modules, _ = build_book.page_dependencies(
        {"navcore.helper"}, {"navcore.helper": ["navcore.papers.sp"]}, root
    )
    assert modules == ["navcore", "navcore.helper", "navcore.papers", "navcore.papers.sp", "navcore.units"]
    modules, _ = build_book.page_dependencies({"navcore.papers.kzl"}, {}, root)
    assert modules == ["navcore", "navcore.deep", "navcore.model", "navcore.papers", "navcore.papers.kzl"]


def test_a_listed_folder_ignores_a_subset_builds_temporary_toc(tmp_path: Path) -> None:
    """A subset build writes its table of contents into the book folder while it runs; a page
    that listed the folder must not look changed (oracle: the hash of the listing without it)."""
    root = _package(tmp_path, {"__init__.py": ""})
    book = tmp_path / "book"
    book.mkdir()
    (book / "intro.md").write_text("# Intro\n")
    before = build_book._dependency_hash(root, "../book/")
    (book / f"{build_book.SUBSET_TOC_PREFIX}abc123.yml").write_text("root: intro\n")
    assert build_book._dependency_hash(root, "../book/") == before
    (book / "new.md").write_text("# New\n")
    assert build_book._dependency_hash(root, "../book/") != before


def test_stale_reason_names_what_changed(tmp_path: Path) -> None:
    root = _package(tmp_path, {"__init__.py": "", "a.py": "x = 1\n", "data.json": "{}"})
    record = build_book.dependency_record(["navcore", "navcore.a"], ["data.json"], root)
    assert build_book.stale_reason(record, root) is None
    assert build_book.stale_reason(None, root) == "no record of what it imports"
    (root / "navcore" / "a.py").write_text("x = 1  # a comment\n")
    assert build_book.stale_reason(record, root) == "imports navcore.a, changed"
    (root / "navcore" / "a.py").write_text("x = 1\n")
    (root / "navcore" / "data.json").write_text("{} ")
    assert build_book.stale_reason(record, root) == "reads data.json, changed"
    (root / "navcore" / "data.json").write_text("{}")
    # what a page read beyond the package, named from the package folder: a book page, and a
    # folder it listed (its names, not their contents)
    (root / "book").mkdir()
    (root / "book" / "p.md").write_text("# P\n")
    pages = build_book.dependency_record(["navcore"], ["../book/", "../book/p.md"], root)
    assert build_book.stale_reason(pages, root) is None
    (root / "book" / "p.md").write_text("# P, retitled\n")
    assert build_book.stale_reason(pages, root) == "reads book/p.md, changed"
    (root / "book" / "p.md").write_text("# P\n")
    (root / "book" / "q.md").write_text("# Q\n")
    assert build_book.stale_reason(pages, root) == "reads book/, changed"
    (root / "book" / "q.md").unlink()
    assert build_book.stale_reason(pages, root) is None
    build_book._module_files.cache_clear()
    (root / "navcore" / "b.py").write_text("")
    assert build_book.stale_reason(record, root) == "navcore's list of modules changed"


PAGES = {
    "1-units.md": "from navcore import units\nprint(units.FT)",
    "2-frames.md": "from navcore import frames\nprint(frames.__name__)",
    # runs after 2-frames in the same kernel (frames is loaded) but imports only units
    "3-units-again.md": "import navcore.units as u\nprint(u.NMI)",
    "4-items.md": (
        "from pathlib import Path\nfrom navcore import trace\n"
        "print(len((Path(trace.__file__).parent / 'papers' / 'paper_items.json').read_text()) > 0)"
    ),
    # fails once its module carries a marker: its old outputs must not survive in the cache
    "5-diagrams.md": "from navcore import diagrams\nassert 'MARKER' not in open(diagrams.__file__).read()",
    # reads the book's pages beside the package (as the traceability index does) and lists them
    "6-pages.md": (
        "from pathlib import Path\nimport navcore\nbook = Path(navcore.__file__).parents[1] / 'book'\n"
        "print(sorted(p.name for p in book.glob('*.md')), (book / 'p.md').read_text())"
    ),
}

RUNNER = """
import sys
from pathlib import Path
sys.path.insert(0, {tools!r})
import build_book
book = Path({book!r})
build_book.prefill(Path({cache!r}), build_book.toc_pages(book / "_toc.yml", book), 1, book=book)
"""


def _executed(copy: Path, book: Path, cache: Path, failing: str | None = None) -> dict[str, str]:
    """Run the build's execution step against the copy of navcore; the pages executed, with why."""
    env = dict(os.environ, PYTHONPATH=str(copy), NAVCORE_CACHE="off")
    code = RUNNER.format(tools=str(ROOT / "tools"), book=str(book), cache=str(cache))
    proc = subprocess.run(
        [sys.executable, "-c", code], cwd=book, env=env, capture_output=True, text=True, timeout=600
    )
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    assert re.findall(r"prefill: b/(\S+) FAILED", proc.stdout) == ([failing] if failing else []), proc.stdout
    return dict(re.findall(r"prefill:   b/(\S+) \((.*)\)", proc.stdout))


@pytest.mark.slow
def test_one_module_change_re_executes_exactly_the_pages_that_import_it(tmp_path: Path) -> None:
    copy = tmp_path / "src"
    shutil.copytree(ROOT / "navcore", copy / "navcore", ignore=shutil.ignore_patterns("__pycache__"))
    (copy / "book").mkdir()
    (copy / "book" / "p.md").write_text("# P\n")
    book, _ = make_book(tmp_path, {"b": PAGES})
    cache = tmp_path / "cache"
    assert _executed(copy, book, cache) == dict.fromkeys(PAGES, "not in the cache")
    assert _executed(copy, book, cache) == {}
    with open(copy / "navcore" / "frames.py", "a") as f:
        f.write("# a comment\n")
    with open(copy / "navcore" / "papers" / "paper_items.json", "a") as f:
        f.write("\n")
    assert _executed(copy, book, cache) == {
        "2-frames.md": "imports navcore.frames, changed",
        "4-items.md": "reads papers/paper_items.json, changed",
    }
    with open(copy / "navcore" / "units.py", "a") as f:
        f.write("# a comment\n")
    assert _executed(copy, book, cache) == dict.fromkeys(
        ["1-units.md", "2-frames.md", "3-units-again.md"], "imports navcore.units, changed"
    )
    # a page's text changed: the page that read it executes again, no other
    (copy / "book" / "p.md").write_text("# P, retitled\n")
    assert _executed(copy, book, cache) == {"6-pages.md": "reads book/p.md, changed"}
    (copy / "book" / "q.md").write_text("# Q\n")
    assert _executed(copy, book, cache) == {"6-pages.md": "reads book/, changed"}
    with open(copy / "navcore" / "diagrams.py", "a") as f:
        f.write("# MARKER\n")
    assert _executed(copy, book, cache, failing="5-diagrams.md") == {
        "5-diagrams.md": "imports navcore.diagrams, changed"
    }
    from jupyter_cache import get_cache

    with pytest.raises(KeyError):  # Sphinx executes it again and the strict build fails
        get_cache(str(cache)).match_cache_notebook(build_book._read_notebook(book / "b" / "5-diagrams.md"))
