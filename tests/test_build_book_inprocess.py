"""The book's build driver (``tools/build_book.py``) called in-process on small synthetic inputs.

Its toy builds (``test_build_incremental``, ``test_build_interrupt``, ``test_build_subset``) run
it as a subprocess, which mutation testing cannot see; here it is loaded under its dotted name
(``tools.build_book``, the name mutmut's trampolines recognise) and its functions are called
directly:

* what a build reads: the subset tables of contents, the execution part of the configuration,
  the cache key, the cached and subset configurations, the pages a toc names, which page is a
  notebook;
* what a page depends on, on a fake ``navcore`` of a few modules in ``tmp_path``: the module
  and data files, the import statements (module level, in functions, relative), the static
  graph and the ledger's part of it, the dependencies reachable from a page's imports;
* the dependency records and why a cached page is stale (each one-sided case: a module, a
  data file or a listed folder changed or not, a missing record, the list of modules), and
  why a page executes, against a real jupyter-cache in ``tmp_path``;
* the grouping of pages by chapter, the default number of jobs, the time report, the
  builder's folder, the merging of stream outputs, the deferred interrupts, the quiet relay
  of Sphinx's output and the process table;
* the build's steps with Sphinx, LaTeX and the execution stood in for: ``build`` (the
  command, fresh output folders, the subset toc, the cache), ``latex_to_pdf``, ``main`` (its
  options, the stop on an interrupt or an error) and ``prefill``, whose chapter executor is a
  stand-in that runs in the real worker processes and stores into a real jupyter-cache.

Oracle in each test: the hand-made input and the result written out by hand (or, for a hash,
``hashlib`` applied to the bytes the docstring of the function says it hashes).
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import myst_nb.core.read  # noqa: F401 (imported once: mutation testing forks each run from here)
import nbformat
import pytest
import yaml
from jupyter_cache import get_cache
from jupyter_cache.base import CacheBundleIn

from tests._tools import help_text, load_tool

build_book = load_tool("build_book")


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def _h(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()[:20]


class _Log:
    """A stand-in for the ``print`` of ``build_book``: what it printed, and whether each line
    was flushed at once (the build's log interleaves with its children's output)."""

    def __init__(self):
        self.printed: list[tuple[str, object]] = []

    def __call__(self, *args, sep=" ", end="\n", file=None, flush=False):
        assert file is None, "printed to another stream"
        self.printed.append((sep.join(map(str, args)) + end, flush))

    def take(self) -> str:
        """What was printed since the last take, every line of it flushed."""
        assert [flush for _, flush in self.printed] == [True] * len(self.printed), "not flushed"
        text = "".join(line for line, _ in self.printed)
        self.printed = []
        return text


@pytest.fixture
def log(monkeypatch):
    """``build_book``'s ``print`` replaced by a :class:`_Log`."""
    stand_in = _Log()
    monkeypatch.setattr(build_book, "print", stand_in, raising=False)
    return stand_in


# --- a fake navcore -----------------------------------------------------------------------------

# module -> source: module-level, class-body, try-block, in-function and relative imports, a
# data file named by its source, a package reached only as the parent of an imported module
FAKE = {
    "__init__.py": "def version():\n    import navcore.c\n",
    "a.py": (
        "import json\n"
        "import navcore.b\n"
        "from navcore import c\n"
        "\n"
        "try:\n"
        "    import navcore.sub.x\n"
        "except ImportError:\n"
        "    pass\n"
        "\n"
        "\n"
        "class K:\n"
        "    import navcore.c as cc\n"
        "\n"
        "\n"
        "def f():\n"
        "    import navcore.d\n"
        "\n"
        "    return lambda: navcore.d\n"
    ),
    "b.py": 'from pathlib import Path\n\nITEMS = Path(__file__).parent / "data" / "items.json"\n',
    "c.py": "X = 1\n",
    "d.py": "def g():\n    from navcore.e import thing\n\n    return thing\n",
    "e.py": "thing = 1\n",
    "sub/__init__.py": "def lazy():\n    from .y import Y\n\n    return Y\n",
    "sub/x.py": "from ..e import thing\n",
    "sub/y.py": "Y = 2\n",
    "papers/__init__.py": "",
    "papers/p.py": "import navcore.sub.x\n\n\ndef claim():\n    from navcore import d\n\n    return d\n",
}

MODULES = [
    "navcore",
    "navcore.a",
    "navcore.b",
    "navcore.c",
    "navcore.d",
    "navcore.e",
    "navcore.papers",
    "navcore.papers.p",
    "navcore.sub",
    "navcore.sub.x",
    "navcore.sub.y",
]


@pytest.fixture
def repo(tmp_path):
    """A checkout: the fake package, its data files, a compiled file and a book folder."""
    root = tmp_path / "repo"
    for name, source in FAKE.items():
        _write(root / "navcore" / name, source)
    _write(root / "navcore" / "data" / "items.json", "{}\n")
    _write(root / "navcore" / "data" / "other.csv", "a,b\n")
    _write(root / "navcore" / "stale.pyc", "")
    _write(root / "navcore" / "__pycache__" / "a.cpython-311.pyc", "")
    _write(root / "navcore" / "__pycache__" / "notes.txt", "")
    _write(root / "book" / "intro.md", "# Intro\n")
    _write(root / "book" / "wf" / "01_a.md", "# A\n")
    return root


# --- subset tables of contents ----------------------------------------------------------------


def test_subset_toc_of_a_paper_with_and_without_a_bibliography(tmp_path):
    """Oracle: the toc written out by hand, its bibliography line there only when the book has
    ``bibliography.md``, and a folder that is not a part captioned by its own name."""
    assert build_book.subset_toc("wf", tmp_path) == (
        "format: jb-book\nroot: wf/index\nparts:\n"
        "  - caption: Wu & Fowler\n    chapters:\n      - glob: wf/[0-9]*\n"
    )
    _write(tmp_path / "bibliography.md", "# Bibliography\n")
    assert build_book.subset_toc("kzl", tmp_path) == (
        "format: jb-book\nroot: kzl/index\nparts:\n"
        "  - caption: Knedlik, Zhou & Loffeld\n    chapters:\n      - glob: kzl/[0-9]*\n"
        "      - file: bibliography\n"
    )
    assert build_book.subset_toc("misc", tmp_path) == (
        "format: jb-book\nroot: misc/index\nparts:\n"
        "  - caption: misc\n    chapters:\n      - glob: misc/[0-9]*\n"
        "      - file: bibliography\n"
    )


def test_subset_toc_of_a_paper_reads_the_repository_book_by_default():
    """Oracle: the repository's book has a bibliography page, so the default toc lists it."""
    assert (build_book.ROOT / "book" / "bibliography.md").exists()
    assert build_book.subset_toc("sp").endswith(
        "  - caption: Schmidt & Phillips\n    chapters:\n      - glob: sp/[0-9]*\n"
        "      - file: bibliography\n"
    )


def test_subset_toc_of_the_reference_and_the_reports(tmp_path):
    """Oracle: the two special tocs written out by hand, page by page."""
    assert build_book.subset_toc("reference", tmp_path) == (
        "format: jb-book\nroot: reference/index\nparts:\n"
        "  - caption: Reference\n    chapters:\n"
        "      - file: reference/howto/index\n        sections:\n"
        "          - file: reference/howto/dop\n"
        "          - file: reference/howto/outage\n"
        "          - file: reference/howto/kalman\n"
        "          - file: reference/howto/frames\n"
        "          - file: reference/howto/detection\n"
        "          - file: reference/howto/emitter\n"
        "      - file: reference/units\n"
        "      - file: reference/frames\n"
        "      - file: reference/gravity\n"
        "      - file: reference/estimation\n"
        "      - file: reference/inertial\n"
        "      - file: reference/gnss\n"
        "      - file: reference/integration\n"
        "      - file: reference/detection\n"
        "      - file: reference/location\n"
        "      - file: reference/ledger\n"
    )
    assert build_book.subset_toc("reports", tmp_path) == (
        "format: jb-book\nroot: intro\nparts:\n"
        "  - caption: Introduction\n    chapters:\n"
        "      - file: about\n      - file: notation\n      - file: glossary\n"
        "  - caption: Verification\n    chapters:\n"
        "      - file: ledger\n      - file: assumptions\n      - file: coverage\n      - file: errata\n"
        "      - file: reports/index\n        sections:\n"
        "          - file: reports/wf\n"
        "          - file: reports/sp\n"
        "          - file: reports/atc10\n"
        "          - file: reports/kzl\n"
        "      - file: bibliography\n"
    )


# --- configuration ------------------------------------------------------------------------------

CONFIG = """\
title: T
author: A
copyright: "2026"
logo: l.png
latex: {latex_engine: xelatex}
html: {x: 1}
bibtex_bibfiles: [r.bib]
launch_buttons: {a: 1}
only_build_toc_files: true
execute: {execute_notebooks: force, timeout: 900, stamp: 2026-12-07}
sphinx:
  local_extensions: {ext: book/_ext}
  extra_extensions: [x]
  config:
    latex_elements: {a: 1}
    html_theme: t
    bibtex_reference_style: s
    numfig: true
    numfig_secnum_depth: 2
    math_number_all: true
    suppress_warnings: [x]
    mathjax_path: m
    nb_execution_raise_on_error: true
"""

EXECUTION = (
    '{"execute": {"execute_notebooks": "force", "stamp": "2026-12-07", "timeout": 900}, '
    '"only_build_toc_files": true, '
    '"sphinx": {"config": {"mathjax_path": "m", "nb_execution_raise_on_error": true}, '
    '"extra_extensions": ["x"]}}'
)


def test_execution_config_keeps_only_what_can_change_an_execution(tmp_path):
    """Oracle: the JSON written out by hand: no rendering keys, no rendering Sphinx settings
    (each prefix), no local extensions, a date turned into text, keys sorted."""
    config = _write(tmp_path / "_config.yml", CONFIG)
    assert build_book._execution_config(config) == EXECUTION


def test_execution_config_without_sphinx_settings(tmp_path):
    """Oracle: no ``sphinx`` key, or an empty ``config``, gives an empty ``sphinx.config``."""
    config = _write(tmp_path / "a.yml", "execute: {a: 1}\n")
    assert build_book._execution_config(config) == '{"execute": {"a": 1}, "sphinx": {"config": {}}}'
    config = _write(tmp_path / "b.yml", "execute: {a: 1}\nsphinx: {config: null, x: 2}\n")
    assert build_book._execution_config(config) == '{"execute": {"a": 1}, "sphinx": {"config": {}, "x": 2}}'


def test_execution_config_and_source_key_read_the_repository_config_by_default(tmp_path, monkeypatch):
    """Oracle: with the repository root moved to ``tmp_path``, no argument reads its ``_config.yml``."""
    monkeypatch.setattr(build_book, "ROOT", tmp_path)
    _write(tmp_path / "_config.yml", CONFIG)
    assert build_book._execution_config() == EXECUTION
    assert build_book.source_key() == build_book.source_key(tmp_path / "_config.yml")


def test_source_key_hashes_python_lock_tool_and_execution_config(tmp_path, monkeypatch):
    """Oracle: ``hashlib`` over the Python version, the lock's and the tool's names and bytes and
    the execution configuration; a rendering change keeps the key, an execution change or a
    new lock changes it."""
    monkeypatch.setattr(build_book, "ROOT", tmp_path)
    config = _write(tmp_path / "_config.yml", CONFIG)
    tool = Path(build_book.__file__).resolve()

    def expected(lock: bytes | None) -> str:
        h = hashlib.sha256(f"python {sys.version_info[:2]}".encode())
        if lock is not None:
            h.update(b"lock.txt" + lock)
        h.update(tool.name.encode() + tool.read_bytes())
        h.update(EXECUTION.encode())
        return h.hexdigest()[:16]

    key = build_book.source_key(config)
    assert key == expected(None)
    _write(
        tmp_path / "render.yml",
        CONFIG.replace("title: T", "title: Other").replace("html_theme: t", "html_theme: u"),
    )
    assert build_book.source_key(tmp_path / "render.yml") == key
    _write(tmp_path / "exec.yml", CONFIG.replace("timeout: 900", "timeout: 901"))
    assert build_book.source_key(tmp_path / "exec.yml") != key
    _write(tmp_path / "requirements" / "lock.txt", "numpy==2.0\n")
    assert build_book.source_key(config) == expected(b"numpy==2.0\n")


def test_cached_config_executes_through_a_cache_keyed_by_the_source_key(tmp_path, monkeypatch):
    """Oracle: the copy written out by hand: ``cache`` execution in the folder named by the
    source key under ``NAVCORE_BOOK_CACHE``, local extensions made relative to the original
    config's folder, the keys in their original order."""
    parent = tmp_path / "cache" / "deep"
    monkeypatch.setenv("NAVCORE_BOOK_CACHE", str(parent))
    config = _write(tmp_path / "conf" / "_config.yml", CONFIG)
    path = build_book.cached_config(config)
    assert path == parent / "_config_cached.yml"
    data = yaml.safe_load(path.read_text())
    assert data["execute"] == {
        "execute_notebooks": "cache",
        "timeout": 900,
        "stamp": yaml.safe_load("2026-12-07"),
        "cache": str(parent / build_book.source_key(config)),
    }
    assert data["sphinx"]["local_extensions"] == {"ext": str(tmp_path / "conf" / "book/_ext")}
    assert list(data) == list(yaml.safe_load(CONFIG))
    assert data["title"] == "T"
    assert build_book.cached_config(config) == path  # the folder exists: written again


def test_cached_config_defaults_to_the_build_folder_and_the_repository_config(tmp_path, monkeypatch):
    """Oracle: with the root moved to ``tmp_path`` and ``NAVCORE_BOOK_CACHE`` empty, the copy
    goes to ``_build/jupyter_cache``; a configuration with no Sphinx section is copied as is."""
    monkeypatch.setattr(build_book, "ROOT", tmp_path)
    monkeypatch.setenv("NAVCORE_BOOK_CACHE", "")
    config = _write(tmp_path / "_config.yml", "execute: {execute_notebooks: force}\n")
    path = build_book.cached_config()
    parent = tmp_path / "_build" / "jupyter_cache"
    assert path == parent / "_config_cached.yml"
    assert yaml.safe_load(path.read_text()) == {
        "execute": {"execute_notebooks": "cache", "cache": str(parent / build_book.source_key(config))}
    }


def test_subset_config_adds_the_subset_extension(tmp_path, monkeypatch):
    """Oracle: the copy written out by hand: absolute local extensions, the subset extension
    from the repository's ``book/_ext``, a nested output folder made, the file named after the
    config's stem, keys in their original order."""
    monkeypatch.setattr(build_book, "ROOT", tmp_path / "root")
    config = _write(tmp_path / "conf" / "_config.yml", CONFIG)
    folder = tmp_path / "out" / "_build"
    path = build_book.subset_config(config, folder)
    assert path == folder / "_config_subset__config.yml"
    data = yaml.safe_load(path.read_text())
    assert data["sphinx"]["local_extensions"] == {
        "ext": str(tmp_path / "conf" / "book" / "_ext"),
        "subset_references": str(tmp_path / "root" / "book" / "_ext"),
    }
    assert data["sphinx"]["extra_extensions"] == ["x"]
    assert data["execute"]["execute_notebooks"] == "force"
    assert list(data) == list(yaml.safe_load(CONFIG))
    assert list(data["sphinx"]) == ["local_extensions", "extra_extensions", "config"]


def test_subset_config_without_a_sphinx_section(tmp_path, monkeypatch):
    """Oracle: no ``sphinx`` key, or ``sphinx: null``, gets one holding only the subset extension."""
    monkeypatch.setattr(build_book, "ROOT", tmp_path)
    ext = {"subset_references": str(tmp_path / "book" / "_ext")}
    for stem, text in (("none", "title: T\n"), ("null", "title: T\nsphinx: null\n")):
        path = build_book.subset_config(_write(tmp_path / f"{stem}.yml", text), tmp_path)
        assert path.name == f"_config_subset_{stem}.yml"
        assert yaml.safe_load(path.read_text()) == {"title": "T", "sphinx": {"local_extensions": ext}}


# --- pages --------------------------------------------------------------------------------------


def test_toc_pages_resolves_files_globs_and_the_root_in_toc_order(tmp_path):
    """Oracle: a toy book and its toc; the list written out by hand: the root first, a file's
    first match by sorted name, a glob's Markdown pages sorted, a missing file skipped, a
    page named twice listed once."""
    book = tmp_path / "book"
    for name in (
        "intro.md",
        "about.md",
        "about.ipynb",
        "wf/index.md",
        "wf/05_e.md",
        "wf/04_d.md",
        "wf/03_c.md",
        "wf/02_b.md",
        "wf/01_a.md",
        "wf/notes.md",
        "wf/06_f.ipynb",
        "sp/01.md",
        "bibliography.md",
    ):
        _write(book / name, "x\n")
    toc = _write(
        book / "_toc.yml",
        "format: jb-book\nroot: intro\nparts:\n"
        "  - caption: X\n    chapters:\n"
        "      - file: wf/index\n        sections:\n          - glob: wf/[0-9]*\n"
        "      - file: about\n      - file: missing\n      - file: intro\n"
        "  - caption: Y\n    chapters:\n      - glob: sp/*\n      - file: bibliography\n",
    )
    root_only = _write(book / "_toc_root.yml", "root: about\n")
    assert build_book.toc_pages(root_only, book) == [book / "about.ipynb"]
    assert build_book.toc_pages(toc, book) == [
        book / "intro.md",
        book / "wf" / "index.md",
        *(book / "wf" / name for name in ("01_a.md", "02_b.md", "03_c.md", "04_d.md", "05_e.md")),
        book / "about.ipynb",
        book / "sp" / "01.md",
        book / "bibliography.md",
    ]


def test_toc_pages_of_the_repository_book_by_default(tmp_path):
    """Oracle: a toc naming the repository's intro page, resolved against the default book."""
    toc = _write(tmp_path / "_toc.yml", "root: intro\n")
    assert build_book.toc_pages(toc) == [build_book.ROOT / "book" / "intro.md"]


def test_is_notebook_needs_markdown_and_a_kernelspec_in_the_front_matter(tmp_path):
    """Oracle: one page of each kind; only a Markdown page whose front matter names a kernel."""
    notebook = "---\njupytext: {}\nkernelspec:\n  name: python3\n---\n# x\n"
    assert build_book._is_notebook(_write(tmp_path / "nb.md", notebook))
    assert not build_book._is_notebook(_write(tmp_path / "nb.txt", notebook))
    assert not build_book._is_notebook(_write(tmp_path / "plain.md", "# x\nkernelspec: no\n"))
    assert not build_book._is_notebook(_write(tmp_path / "late.md", "---\ntitle: x\n---\nkernelspec: y\n"))
    ruled = "---\ntitle: x\n---\nkernelspec: y\n\n---\n"  # a rule further down: not front matter
    assert not build_book._is_notebook(_write(tmp_path / "ruled.md", ruled))
    assert not build_book._is_notebook(_write(tmp_path / "blank.md", "\n" + notebook))


def test_read_notebook_reads_a_myst_page(tmp_path):
    """Oracle: a page of one Markdown heading and one code cell, read as two cells."""
    page = _write(
        tmp_path / "p.md",
        "---\nkernelspec:\n  display_name: Python 3\n  language: python\n  name: python3\n---\n\n"
        "# T\n\n```{code-cell} ipython3\nprint(1)\n```\n",
    )
    nb = build_book._read_notebook(page)
    assert [(c.cell_type, c.source) for c in nb.cells] == [("markdown", "# T"), ("code", "print(1)")]
    assert nb.metadata["kernelspec"]["name"] == "python3"


# --- what a page depends on ---------------------------------------------------------------------


def test_module_and_data_files_of_the_fake_package(repo):
    """Oracle: the fake package's files listed by hand: modules by dotted name (a package by its
    ``__init__``), data files less Python, compiled files and ``__pycache__``."""
    files = build_book._module_files(repo)
    assert sorted(files) == MODULES
    assert files["navcore"] == repo / "navcore" / "__init__.py"
    assert files["navcore.sub.x"] == repo / "navcore" / "sub" / "x.py"
    assert build_book._data_files(repo) == ("data/items.json", "data/other.csv")
    assert build_book._package_dir(repo) == repo / "navcore"


@pytest.mark.parametrize(
    ("statement", "package", "refs"),
    [
        ("import a.b, c", "navcore", {"a.b", "c"}),
        ("from x import y, z", "navcore", {"x", "x.y", "x.z"}),
        ("from . import y", "navcore.sub", {"navcore.sub", "navcore.sub.y"}),
        ("from .. import y", "navcore.sub", {"navcore", "navcore.y"}),
        ("from .m import y", "navcore.sub", {"navcore.sub.m", "navcore.sub.m.y"}),
        ("from ..m import y", "navcore.sub", {"navcore.m", "navcore.m.y"}),
        ("from .m import y", "navcore", {"navcore.m", "navcore.m.y"}),
    ],
)
def test_import_refs(statement, package, refs):
    """Oracle: each statement's names worked out by hand, relative ones from their package."""
    import ast

    assert build_book._import_refs(ast.parse(statement).body[0], package) == refs


def test_import_statements_split_module_level_and_function_imports(repo):
    """Oracle: the fake package's imports listed by hand: module level (class bodies, ``try``
    blocks, the data file a source names) apart from those only in functions, navcore's only."""
    found = build_book._import_statements(repo)
    expected = {
        "navcore": (set(), {"navcore.c"}),
        "navcore.a": ({"navcore", "navcore.b", "navcore.c", "navcore.sub.x"}, {"navcore.d"}),
        "navcore.b": ({"file:data/items.json"}, set()),
        "navcore.c": (set(), set()),
        "navcore.d": (set(), {"navcore.e"}),
        "navcore.e": (set(), set()),
        "navcore.papers": (set(), set()),
        "navcore.papers.p": ({"navcore.sub.x"}, {"navcore", "navcore.d"}),
        "navcore.sub": (set(), {"navcore.sub.y"}),
        "navcore.sub.x": ({"navcore.e"}, set()),
        "navcore.sub.y": (set(), set()),
    }
    assert found == {k: (frozenset(a), frozenset(b)) for k, (a, b) in expected.items()}
    graph = build_book.static_import_graph(repo)
    assert graph == {k: frozenset(a | b) for k, (a, b) in expected.items()}


def test_a_function_import_also_made_at_module_level_counts_once(tmp_path):
    """Oracle: a module importing ``navcore.c`` at module level and in a function: at import only."""
    root = tmp_path / "r"
    _write(root / "navcore" / "__init__.py", "")
    _write(root / "navcore" / "c.py", "")
    _write(root / "navcore" / "m.py", "import navcore.c\n\n\ndef f():\n    import navcore.c\n")
    assert build_book._import_statements(root)["navcore.m"] == (frozenset({"navcore.c"}), frozenset())


def test_dependency_graph_keeps_function_imports_only_where_the_ledger_reaches(repo):
    """Oracle: a hand-built graph: the paper module and what it reaches (its imports, their
    packages, theirs) keep every import; the others (``a``, ``b``, ``papers``) only the
    module-level ones."""
    assert build_book.dependency_graph(repo) == {
        "navcore": frozenset({"navcore.c"}),
        "navcore.a": frozenset({"navcore", "navcore.b", "navcore.c", "navcore.sub.x"}),
        "navcore.b": frozenset({"file:data/items.json"}),
        "navcore.c": frozenset(),
        "navcore.d": frozenset({"navcore.e"}),
        "navcore.e": frozenset(),
        "navcore.papers": frozenset(),
        "navcore.papers.p": frozenset({"navcore", "navcore.d", "navcore.sub.x"}),
        "navcore.sub": frozenset({"navcore.sub.y"}),
        "navcore.sub.x": frozenset({"navcore.e"}),
        "navcore.sub.y": frozenset(),
    }


def test_with_packages_adds_every_parent_package_but_not_a_file_s(tmp_path):
    """Oracle: the parents written out by hand; a data file (with dots in its name) has none."""
    assert build_book._with_packages({"a.b.c", "file:data/x.json", "d"}) == {
        "a.b.c",
        "a.b",
        "a",
        "file:data/x.json",
        "d",
    }
    assert build_book._with_packages(set()) == set()


def test_page_dependencies_follow_the_graph_and_the_recorded_edges(repo):
    """Oracle: a hand-built traversal of the fake package from ``navcore.a``; the recorded edge
    to ``navcore.d`` (a function's import) adds it, and only it."""
    without = build_book.page_dependencies({"navcore.a"}, {}, repo)
    modules = [
        "navcore",
        "navcore.a",
        "navcore.b",
        "navcore.c",
        "navcore.e",
        "navcore.sub",
        "navcore.sub.x",
        "navcore.sub.y",
    ]
    assert without == (modules, ["data/items.json"])
    with_edge = build_book.page_dependencies({"navcore.a"}, {"navcore.a": ["navcore.d"]}, repo)
    assert with_edge == (sorted([*modules, "navcore.d"]), ["data/items.json"])


def test_page_dependencies_of_a_name_inside_a_module_and_of_nothing(repo):
    """Oracle: ``navcore.e.thing`` is no module: its packages are (and ``navcore.c``, which the
    package imports in a function the ledger reaches); no roots give nothing."""
    deps = build_book.page_dependencies({"navcore.e.thing"}, {}, repo)
    assert deps == (["navcore", "navcore.c", "navcore.e"], [])
    assert build_book.page_dependencies({"navcore.c"}, {}, repo) == (["navcore", "navcore.c"], [])
    assert build_book.page_dependencies(set(), {"navcore.c": ["navcore.d"]}, repo) == ([], [])


# --- records and staleness ----------------------------------------------------------------------


def test_file_hash_of_a_file_a_missing_file_and_a_folder(tmp_path):
    """Oracle: ``hashlib`` over the file's bytes, 20 hex digits; ``None`` when it cannot be read."""
    assert build_book._file_hash(_write(tmp_path / "f", "abc")) == _h(b"abc")
    assert len(build_book._file_hash(tmp_path / "f")) == 20
    assert build_book._file_hash(tmp_path / "missing") is None
    assert build_book._file_hash(tmp_path) is None


def test_dependency_hash_of_a_file_and_of_a_listed_folder(repo):
    """Oracle: ``hashlib`` over the file's bytes, or over the folder's sorted names less a
    subset build's toc; ``None`` for a missing file or folder."""
    assert build_book._dependency_hash(repo, "data/items.json") == _h(b"{}\n")
    assert build_book._dependency_hash(repo, "data/none.json") is None
    assert build_book._dependency_hash(repo, "../book/") == _h(b"intro.md\nwf")
    _write(repo / "book" / "_toc_subset_wf123.yml", "x")
    assert build_book._dependency_hash(repo, "../book/") == _h(b"intro.md\nwf")
    _write(repo / "book" / "a_toc_subset_.md", "x")
    assert build_book._dependency_hash(repo, "../book/") == _h(b"a_toc_subset_.md\nintro.md\nwf")
    assert build_book._dependency_hash(repo, "../nothing/") is None


def test_listing_hash_and_dependency_record(repo):
    """Oracle: ``hashlib`` over the sorted module names, one a line, and over each file; the
    record written out by hand."""
    listing = _h("\n".join(MODULES).encode())
    assert build_book._listing_hash(repo) == listing
    record = build_book.dependency_record(["navcore.c", "navcore.a"], ["data/items.json", "../book/"], repo)
    assert record == {
        "modules": {"navcore.c": _h(b"X = 1\n"), "navcore.a": _h(FAKE["a.py"].encode())},
        "files": {"data/items.json": _h(b"{}\n"), "../book/": _h(b"intro.md\nwf")},
        "module_list": listing,
    }
    assert list(record["modules"]) == ["navcore.c", "navcore.a"]


def test_stale_reason_of_no_record_and_of_an_up_to_date_one(repo):
    """Oracle: the reader's text for a missing record; ``None`` while nothing changed, even
    after a subset build's toc appears in a listed folder."""
    assert build_book.stale_reason(None, repo) == "no record of what it imports"
    record = build_book.dependency_record(["navcore.a", "navcore.c"], ["data/items.json", "../book/"], repo)
    assert build_book.stale_reason(record, repo) is None
    _write(repo / "book" / "_toc_subset_x.yml", "x")
    _write(repo / "navcore" / "e.py", "thing = 2\n")  # not a dependency of this record
    _write(repo / "navcore" / "data" / "other.csv", "c\n")
    assert build_book.stale_reason(record, repo) is None


def test_stale_reason_names_a_changed_module(repo):
    """Oracle: one of two recorded modules edited: only it is named, as a reader sees it."""
    record = build_book.dependency_record(["navcore.a", "navcore.c"], [], repo)
    _write(repo / "navcore" / "c.py", "X = 2\n")
    assert build_book.stale_reason(record, repo) == "imports navcore.c, changed"


def test_stale_reason_names_a_module_that_is_gone(repo):
    """Oracle: a record naming a module the package no longer has (its hash irrelevant)."""
    record = build_book.dependency_record(["navcore.c"], [], repo)
    record["modules"]["navcore.gone"] = None
    assert build_book.stale_reason(record, repo) == "imports navcore.gone, changed"


def test_stale_reason_names_a_changed_data_file_and_a_changed_listing(repo):
    """Oracle: a data file edited, then a page added to a listed folder: each named once,
    modules first, a folder beyond the package without its leading ``../``."""
    record = build_book.dependency_record(["navcore.c"], ["data/items.json", "../book/"], repo)
    _write(repo / "navcore" / "data" / "items.json", "[]\n")
    assert build_book.stale_reason(record, repo) == "reads data/items.json, changed"
    _write(repo / "book" / "new.md", "x")
    assert build_book.stale_reason(record, repo) == "reads data/items.json, reads book/, changed"
    _write(repo / "navcore" / "c.py", "X = 3\n")
    assert build_book.stale_reason(record, repo) == (
        "imports navcore.c, reads data/items.json, reads book/, changed"
    )


def test_stale_reason_shows_three_changes_and_counts_the_rest(repo):
    """Oracle: four changed modules: three named and "and 1 more"; five: "and 2 more"."""
    names = ["navcore.a", "navcore.b", "navcore.c", "navcore.d", "navcore.e"]
    record = {
        "modules": dict.fromkeys(names, "0"),
        "files": {},
        "module_list": build_book._listing_hash(repo),
    }
    assert build_book.stale_reason(record, repo) == (
        "imports navcore.a, imports navcore.b, imports navcore.c and 2 more, changed"
    )
    record["modules"] = dict.fromkeys(names[:4], "0")
    assert build_book.stale_reason(record, repo) == (
        "imports navcore.a, imports navcore.b, imports navcore.c and 1 more, changed"
    )


def test_stale_reason_with_exactly_three_changes_counts_none_more(repo):
    """Oracle: three changed dependencies (two modules, one file): all named, no count."""
    record = {
        "modules": {"navcore.a": "0", "navcore.b": "0"},
        "files": {"data/items.json": "0"},
        "module_list": build_book._listing_hash(repo),
    }
    assert build_book.stale_reason(record, repo) == (
        "imports navcore.a, imports navcore.b, reads data/items.json, changed"
    )


def test_stale_reason_of_a_changed_list_of_modules(repo):
    """Oracle: a record whose listing hash differs (a stored one, then a module added to the
    package): the list is named; a changed dependency is named before it; an empty record
    has no list."""
    record = build_book.dependency_record(["navcore.c"], [], repo)
    assert build_book.stale_reason({**record, "module_list": "0" * 20}, repo) == (
        "navcore's list of modules changed"
    )
    assert build_book.stale_reason({}, repo) == "navcore's list of modules changed"
    _write(repo / "navcore" / "new.py", "")
    build_book._module_files.cache_clear()
    try:
        assert build_book.stale_reason(record, repo) == "navcore's list of modules changed"
        _write(repo / "navcore" / "c.py", "X = 4\n")
        assert build_book.stale_reason(record, repo) == "imports navcore.c, changed"
    finally:
        build_book._module_files.cache_clear()


# --- why a page executes (a real jupyter-cache) --------------------------------------------------

PAGE = (
    "---\nkernelspec:\n  display_name: Python 3\n  language: python\n  name: python3\n---\n\n"
    "# T\n\n```{code-cell} ipython3\nprint(1)\n```\n"
)


@pytest.fixture
def cached(repo, tmp_path):
    """A page of the fake book stored in a jupyter-cache with its dependency record."""
    page = _write(repo / "book" / "wf" / "02_p.md", PAGE)
    cache = get_cache(str(tmp_path / "jcache"))
    record = cache.cache_notebook_bundle(
        CacheBundleIn(build_book._read_notebook(page), str(page)), check_validity=False, overwrite=True
    )
    folder = build_book._record_dir(cache, record.hashkey)
    deps = build_book.dependency_record(["navcore.c"], ["data/items.json"], repo)
    (folder / "navcore-deps.json").write_text(json.dumps(deps))
    return cache, page, record, folder


def test_why_execute_a_page_the_cache_lacks(repo, tmp_path):
    """Oracle: an empty cache: "its text changed" when the page's uri has a record, else
    "not in the cache"."""
    cache = get_cache(str(tmp_path / "empty"))
    page = _write(repo / "book" / "wf" / "02_p.md", PAGE)
    assert build_book._why_execute(cache, page, {}, repo) == ("not in the cache", None)
    assert build_book._why_execute(cache, page, {str(page): object()}, repo) == ("its text changed", None)
    other = {str(page) + "x": object()}
    assert build_book._why_execute(cache, page, other, repo) == ("not in the cache", None)


def test_why_execute_an_up_to_date_and_a_stale_page(repo, cached):
    """Oracle: nothing changed: no reason and no record; the module it imports edited: the
    reason and the stale record, which stays in the cache."""
    cache, page, record, folder = cached
    assert build_book._record_dir(cache, record.hashkey) == folder
    assert folder.parent.name == "executed"
    assert build_book._why_execute(cache, page, {}, repo) == (None, None)
    _write(repo / "navcore" / "c.py", "X = 9\n")
    reason, stale = build_book._why_execute(cache, page, {}, repo)
    assert reason == "imports navcore.c, changed"
    assert stale.pk == record.pk
    assert [r.pk for r in cache.list_cache_records()] == [record.pk]


@pytest.mark.parametrize("damage", ["no deps", "bad deps", "no notebook", "no folder"])
def test_why_execute_drops_a_record_that_is_not_whole(repo, cached, damage):
    """Oracle: a record without its dependencies (missing, not JSON), without its notebook or
    without its folder: "no record of what it imports", no record returned, the record and its
    folder gone."""
    cache, page, _, folder = cached
    if damage == "no deps":
        (folder / "navcore-deps.json").unlink()
    elif damage == "bad deps":
        (folder / "navcore-deps.json").write_text("{not json")
    elif damage == "no notebook":
        (folder / "base.ipynb").unlink()
    else:
        shutil.rmtree(folder)
    assert build_book._why_execute(cache, page, {}, repo) == ("no record of what it imports", None)
    assert cache.list_cache_records() == []
    assert not folder.exists()
    assert build_book._why_execute(cache, page, {}, repo) == ("not in the cache", None)


# --- grouping, jobs, times ----------------------------------------------------------------------


def test_group_pages_papers_first_in_their_order_then_the_rest_by_size(tmp_path):
    """Oracle: the groups written out by hand: the paper chapters in KZL, SP, ATC10, WF order
    (upper-cased folder names), then the others by page count, the front and back matter
    (group ``""``) after a chapter of as many pages, pages in their given order."""
    book = tmp_path / "book"
    names = [
        "intro.md",
        "wf/02.md",
        "other/01.md",
        "ledger.md",
        "wf/01.md",
        "across/01.md",
        "sp/01.md",
        "kzl/01.md",
        "across/02.md",
        "big/01.md",
        "big/02.md",
        "big/03.md",
    ]
    pages = [book / n for n in names]
    papers, later = build_book._group_pages(pages, book)
    s = str
    assert papers == [
        ("KZL", [s(book / "kzl/01.md")]),
        ("SP", [s(book / "sp/01.md")]),
        ("WF", [s(book / "wf/02.md"), s(book / "wf/01.md")]),
    ]
    assert later == [
        ("BIG", [s(book / "big/01.md"), s(book / "big/02.md"), s(book / "big/03.md")]),
        ("ACROSS", [s(book / "across/01.md"), s(book / "across/02.md")]),
        ("", [s(book / "intro.md"), s(book / "ledger.md")]),
        ("OTHER", [s(book / "other/01.md")]),
    ]


def test_group_pages_of_the_repository_book_by_default():
    """Oracle: one page of the repository's ATC-10 chapter, grouped by the default book folder."""
    page = build_book.ROOT / "book" / "atc10" / "x.md"
    assert build_book._group_pages([page]) == ([("ATC10", [str(page)])], [])


def test_group_pages_of_nothing_and_of_the_front_matter_alone(tmp_path):
    """Oracle: no pages, no groups; front matter only: one group ``""``."""
    assert build_book._group_pages([], tmp_path) == ([], [])
    assert build_book._group_pages([tmp_path / "a.md"], tmp_path) == ([], [("", [str(tmp_path / "a.md")])])


def test_default_jobs_is_one_more_than_the_cores(monkeypatch):
    """Oracle: three cores give four jobs; an unknown count (``None``) gives two."""
    monkeypatch.setattr(build_book.os, "cpu_count", lambda: 3)
    assert build_book.default_jobs() == 4
    monkeypatch.setattr(build_book.os, "cpu_count", lambda: None)
    assert build_book.default_jobs() == 2


def test_report_times_sums_chapters_prints_and_writes_them(tmp_path, log):
    """Oracle: the lines and the JSON written out by hand: a chapter's claims counted in its
    chapter, pages by their first folder, top-level pages as the front and back matter."""
    times = {"(ledger WF)": 2.0, "wf/01.md": 1.5, "wf/a/02.md": 0.25, "intro.md": 3.0, "sp/01.md": 10.0}
    out = tmp_path / "deep" / "_build" / "page-times.json"
    build_book.report_times(times, out)
    assert log.take().split("\n") == [
        "execution:     3.0 s  (front and back matter)",
        "execution:    10.0 s  sp",
        "execution:     3.8 s  wf",
        "",
    ]
    assert out.read_text() == (
        "{\n"
        ' "chapters": {\n  "(front and back matter)": 3.0,\n  "sp": 10.0,\n  "wf": 3.75\n },\n'
        ' "pages": {\n  "(ledger WF)": 2.0,\n  "intro.md": 3.0,\n  "sp/01.md": 10.0,\n'
        '  "wf/01.md": 1.5,\n  "wf/a/02.md": 0.25\n }\n'
        "}\n"
    )


def test_report_times_of_nothing(tmp_path, log):
    """Oracle: no times: nothing printed, empty tables written."""
    build_book.report_times({}, tmp_path / "t.json")
    assert log.take() == ""
    assert json.loads((tmp_path / "t.json").read_text()) == {"pages": {}, "chapters": {}}


def test_builder_dir():
    """Oracle: jupyter-book writes the PDF builder's output to ``latex``, the others to their name."""
    assert build_book.builder_dir("pdflatex") == "latex"
    assert build_book.builder_dir("html") == "html"
    assert build_book.builder_dir("latex") == "latex"
    assert build_book.builder_dir("linkcheck") == "linkcheck"


# --- outputs, interrupts, the relay, processes ---------------------------------------------------


def test_merge_streams_joins_each_stream_of_a_cell_in_place():
    """Oracle: outputs written out by hand: each stream's chunks joined where it first appeared,
    other outputs kept in order, cells merged separately, Markdown cells untouched."""
    v4 = nbformat.v4
    first = v4.new_code_cell("x")
    first.outputs = [
        v4.new_output("stream", name="stdout", text="a"),
        v4.new_output("stream", name="stderr", text="e1\n"),
        v4.new_output("display_data", data={"text/plain": "d"}),
        v4.new_output("stream", name="stdout", text="b\n"),
        v4.new_output("stream", name="stderr", text="e2"),
        v4.new_output("stream", name="stdout", text="c"),
    ]
    second = v4.new_code_cell("y")
    second.outputs = [
        v4.new_output("stream", name="stdout", text="z"),
        v4.new_output("stream", name="stdout", text="w"),
    ]
    empty = v4.new_code_cell("z")
    text = v4.new_markdown_cell("m")
    nb = v4.new_notebook(cells=[first, text, second, empty])
    del empty["outputs"]  # a cell stored without outputs
    build_book._merge_streams(nb)
    assert [(o["output_type"], o.get("name"), o.get("text")) for o in first.outputs] == [
        ("stream", "stdout", "ab\nc"),
        ("stream", "stderr", "e1\ne2"),
        ("display_data", None, None),
    ]
    assert [o["text"] for o in second.outputs] == ["zw"]
    assert empty.outputs == []
    assert "outputs" not in text


def test_interrupts_raise_at_once_or_after_the_critical_section():
    """Oracle: outside a critical section the signal raises; inside (nested) it waits for the
    outermost section to end, then raises once with the signal's number."""
    interrupts = build_book._Interrupts()
    assert (interrupts.depth, interrupts.pending) == (0, None)
    with pytest.raises(KeyboardInterrupt, match=r"^signal 15$"):
        interrupts.handler(15, None)
    with pytest.raises(KeyboardInterrupt, match=r"^signal 2$"):
        with interrupts.critical():
            with interrupts.critical():
                assert interrupts.depth == 2
                interrupts.handler(2, None)
                assert interrupts.pending == 2
            assert (interrupts.depth, interrupts.pending) == (1, 2)
    assert (interrupts.depth, interrupts.pending) == (0, None)
    with interrupts.critical():
        pass
    assert interrupts.depth == 0


def test_relay_quietly_drops_jupyter_books_banners(capsys):
    """Oracle: a log of banners (coloured or not) and two real lines: only the real lines pass."""
    lines = [
        "Running Jupyter-Book v1\n",
        "=======\n",
        "Source Folder: /x\n",
        "\x1b[32mFinished generating HTML for book.\x1b[0m\n",
        "file:///tmp/_build/html/index.html\n",
        "\n",
        "WARNING: a real warning\n",
        "last line\n",
    ]
    build_book._relay_quietly(iter(lines))
    assert capsys.readouterr().out == "WARNING: a real warning\nlast line\n"


_CHILD = """
import ctypes, subprocess, sys, time
ctypes.CDLL(None).prctl(15, b"x) 1 2 3", 0, 0, 0)  # PR_SET_NAME: a name holding ") " and numbers
grandchild = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
print(grandchild.pid, flush=True)
grandchild.wait()
time.sleep(60)
"""


def _wait_for(condition) -> None:
    deadline = time.monotonic() + 10
    while not condition() and time.monotonic() < deadline:
        time.sleep(0.01)


def test_process_table_descendants_and_alive_see_a_child():
    """Oracle: a sleeping child of this process, named ``x) 1 2 3`` (its ``stat`` line must be
    read from the last parenthesis), with a child of its own: in the table with their parents,
    both descendants, alive; the grandchild killed and reaped: gone; the child killed, a zombie
    (state ``Z``): in the table, neither a descendant nor alive; reaped, nowhere."""
    with subprocess.Popen([sys.executable, "-c", _CHILD], stdout=subprocess.PIPE, text=True) as child:
        try:
            grandchild = int(child.stdout.readline())
            table = build_book._process_table()
            assert table[child.pid][0] == os.getpid()
            assert table[child.pid][1] in "RSD"
            assert table[grandchild][0] == child.pid
            assert {child.pid, grandchild} <= build_book.descendants(os.getpid())
            assert build_book.descendants(child.pid) == {grandchild}
            assert build_book._alive(child.pid)
            assert build_book._alive(grandchild)
            os.kill(grandchild, 9)
            _wait_for(lambda: grandchild not in build_book._process_table())
            assert not build_book._alive(grandchild)
            assert build_book.descendants(child.pid) == set()
            child.kill()
            _wait_for(lambda: build_book._process_table()[child.pid][1] == "Z")
            assert build_book._process_table()[child.pid] == (os.getpid(), "Z")
            assert child.pid not in build_book.descendants(os.getpid())
            assert not build_book._alive(child.pid)
        finally:
            child.kill()
            child.wait()
    assert not build_book._alive(child.pid)
    assert child.pid not in build_book.descendants(os.getpid())
    assert child.pid not in build_book._process_table()


def test_alive_without_a_readable_stat_line(monkeypatch):
    """Oracle: a live child whose ``stat`` line cannot be read: dead where ``/proc`` exists
    (Linux), alive where it does not (signal 0 finds it), and never signalled; a pid that no
    process has: dead."""

    class NoStat(type(Path())):
        def read_text(self, *args, **kwargs):
            if self.name == "stat":
                raise OSError("no stat")
            return super().read_text(*args, **kwargs)

        def exists(self, *args, **kwargs):
            return proc[0] if str(self) == "/proc" else super().exists(*args, **kwargs)

    proc = [True]
    monkeypatch.setattr(build_book, "Path", NoStat)
    with subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"]) as child:
        try:
            assert build_book._alive(child.pid) is False
            proc[0] = False
            assert build_book._alive(child.pid) is True
            with pytest.raises(subprocess.TimeoutExpired):  # not signalled: still sleeping
                child.wait(timeout=0.3)
        finally:
            child.kill()
    assert build_book._alive(child.pid) is False


# --- the build's steps, Sphinx and LaTeX stood in for -------------------------------------------


def test_run_quietly_relays_output_less_banners_in_the_folder_and_environment_given(tmp_path, capsys):
    """Oracle: a child that runs for half a second (longer than one short wait), prints a
    banner, its folder, an environment variable, a byte that is not UTF-8 and the signal it
    gets when its parent dies, then exits 3: its exit status, and its lines less the banner,
    the bad byte replaced, SIGTERM armed."""
    code = (
        "import ctypes, os, sys, time\n"
        "time.sleep(0.5)\n"
        "print('Running Jupyter-Book v1')\n"
        "print(os.getcwd())\n"
        "print(os.environ.get('TOY_VALUE'), flush=True)\n"
        "sys.stdout.buffer.write(b'bad \\xff\\n')\n"
        "sig = ctypes.c_int()\n"
        "ctypes.CDLL(None).prctl(2, ctypes.byref(sig), 0, 0, 0)  # PR_GET_PDEATHSIG\n"
        "sys.stdout.buffer.write(f'{sig.value}\\n'.encode())\n"
        "sys.exit(3)\n"
    )
    env = {**os.environ, "TOY_VALUE": "seen"}
    assert build_book._run_quietly([sys.executable, "-c", code], tmp_path, env) == 3
    assert capsys.readouterr().out == f"{tmp_path}\nseen\nbad \ufffd\n{int(signal.SIGTERM)}\n"


@pytest.fixture
def sphinx(monkeypatch):
    """Stand-in for the Sphinx run: records each command, its folder and environment, and the
    table of contents it names (read while it runs); returns ``sphinx.code``."""

    class Sphinx:
        def __init__(self):
            self.code = 0
            self.calls = []
            self.remove_toc = False

        def __call__(self, cmd, cwd, env=None):
            toc = Path(cmd[cmd.index("--toc") + 1])
            self.calls.append({"cmd": cmd, "cwd": cwd, "env": env, "toc": toc.read_text()})
            if self.remove_toc:
                toc.unlink()
            return self.code

    stand_in = Sphinx()
    monkeypatch.setattr(build_book, "_run_quietly", stand_in)
    return stand_in


def _toy(tmp_path):
    book = tmp_path / "book"
    _write(book / "_toc.yml", "format: jb-book\nroot: intro\n")
    _write(book / "intro.md", "# Intro\n")
    config = _write(tmp_path / "_config.yml", "title: T\nexecute: {execute_notebooks: force}\n")
    return book, config


def _sphinx_cmd(book, config, toc, out, builder):
    return [
        str(Path(sys.executable).with_name("jupyter-book")),
        "build",
        str(book),
        "--config",
        str(config),
        "--toc",
        str(toc),
        "--path-output",
        str(out),
        "--builder",
        builder,
        "--all",
        "-W",
        "-n",
        "--keep-going",
        "-q",
    ]


def test_build_runs_sphinx_strictly_on_fresh_output_folders(tmp_path, sphinx, log):
    """Oracle: the command written out by hand; the builder's output and doctree folders left
    by an earlier build removed first, another builder's kept; the log lines as a reader sees
    them."""
    book, config = _toy(tmp_path)
    out = tmp_path / "out"
    for folder in ("html", ".doctrees", "latex"):
        _write(out / "_build" / folder / "old.txt", "x")
    assert build_book.build("html", out=out, book=book, config_file=config) == 0
    assert [c["cmd"] for c in sphinx.calls] == [_sphinx_cmd(book, config, book / "_toc.yml", out, "html")]
    assert sphinx.calls[0]["cwd"] == build_book.ROOT
    assert not (out / "_build" / "html").exists()
    assert not (out / "_build" / ".doctrees").exists()
    assert (out / "_build" / "latex" / "old.txt").exists()
    assert log.take() == f"sphinx: html build of book/_toc.yml into {out / '_build'}\nsphinx: done\n"


def test_build_reports_a_failed_sphinx_run_and_skips_the_pdf(tmp_path, sphinx, log, monkeypatch):
    """Oracle: Sphinx exits 2: the build returns 2, says so, and does not typeset the PDF."""
    book, config = _toy(tmp_path)
    typeset: list = []
    monkeypatch.setattr(build_book, "latex_to_pdf", lambda out: typeset.append(out) or 0)
    sphinx.code = 2
    assert build_book.build("pdflatex", out=tmp_path, book=book, config_file=config) == 2
    assert typeset == []
    assert log.take().splitlines()[-1] == "sphinx: FAILED (exit 2): see the messages above"


def test_build_of_the_pdf_runs_the_latex_builder_then_typesets(tmp_path, sphinx, log, monkeypatch):
    """Oracle: ``pdflatex``: Sphinx's ``latex`` builder into a fresh ``latex`` folder, then
    :func:`latex_to_pdf` on the output folder, whose status the build returns."""
    book, config = _toy(tmp_path)
    out = tmp_path / "out"
    _write(out / "_build" / "latex" / "old.tex", "x")
    typeset: list = []
    monkeypatch.setattr(build_book, "latex_to_pdf", lambda folder: typeset.append(folder) or 5)
    assert build_book.build("pdflatex", out=out, book=book, config_file=config) == 5
    assert typeset == [out]
    assert sphinx.calls[0]["cmd"] == _sphinx_cmd(book, config, book / "_toc.yml", out, "latex")
    assert not (out / "_build" / "latex").exists()
    assert "sphinx: latex build of book/_toc.yml into" in log.take()


def test_build_of_a_subset_writes_and_removes_its_toc(tmp_path, sphinx, monkeypatch):
    """Oracle: ``--only wf`` with the repository root moved to ``tmp_path``: Sphinx reads the
    subset toc from a temporary file in the book folder (gone afterwards, even when Sphinx
    fails), the subset configuration, and writes to ``_build/subset-wf``."""
    monkeypatch.setattr(build_book, "ROOT", tmp_path)
    book, config = _toy(tmp_path)
    assert build_book.build("html", only="wf", book=book, config_file=config) == 0
    (call,) = sphinx.calls
    out = tmp_path / "_build" / "subset-wf"
    toc = Path(call["cmd"][call["cmd"].index("--toc") + 1])
    assert toc.parent == book
    assert toc.name.startswith("_toc_subset_")
    assert toc.suffix == ".yml"
    assert call["toc"] == build_book.subset_toc("wf", book)
    assert call["cmd"] == _sphinx_cmd(book, out / "_build" / "_config_subset__config.yml", toc, out, "html")
    assert not toc.exists()
    assert sorted(p.name for p in book.iterdir()) == ["_toc.yml", "intro.md"]
    sphinx.code = 1
    assert build_book.build("html", only="kzl", out=tmp_path / "o", book=book, config_file=config) == 1
    assert sphinx.calls[1]["cmd"][sphinx.calls[1]["cmd"].index("--path-output") + 1] == str(tmp_path / "o")
    assert sorted(p.name for p in book.iterdir()) == ["_toc.yml", "intro.md"]
    sphinx.remove_toc = True  # gone before the build removes it: no error
    assert build_book.build("html", only="sp", out=tmp_path / "o", book=book, config_file=config) == 1


def test_build_refuses_an_unknown_subset(tmp_path, sphinx):
    """Oracle: the message a reader sees, listing the parts; nothing run."""
    book, config = _toy(tmp_path)
    with pytest.raises(SystemExit) as stop:
        build_book.build("html", only="xx", book=book, config_file=config)
    assert str(stop.value) == (
        "--only must be one of ['wf', 'sp', 'atc10', 'kzl', 'reference', 'reports'], got 'xx'"
    )
    assert sphinx.calls == []


def test_build_with_the_cache_executes_first_and_reports_the_times(tmp_path, sphinx, monkeypatch):
    """Oracle: a stand-in for :func:`prefill`: it gets the cache folder the cached configuration
    names, the toc's pages, the default jobs and the book; its times are written to
    ``page-times.json``; Sphinx reads the cached configuration; ``execute_only`` stops there."""
    book, config = _toy(tmp_path)
    monkeypatch.setenv("NAVCORE_BOOK_CACHE", str(tmp_path / "jc"))
    monkeypatch.setattr(build_book, "default_jobs", lambda: 7)
    calls: list = []

    def prefill(cache_path, pages, jobs, book):
        calls.append((cache_path, pages, jobs, book))
        return {"intro.md": 1.0}

    monkeypatch.setattr(build_book, "prefill", prefill)
    out = tmp_path / "out"
    assert build_book.build(out=out, cache=True, book=book, config_file=config) == 0  # html by default
    cached = tmp_path / "jc" / "_config_cached.yml"
    assert calls == [(tmp_path / "jc" / build_book.source_key(config), [book / "intro.md"], 7, book)]
    assert json.loads((out / "_build" / "page-times.json").read_text())["chapters"] == {
        "(front and back matter)": 1.0
    }
    assert sphinx.calls[0]["cmd"] == _sphinx_cmd(book, cached, book / "_toc.yml", out, "html")
    out2 = tmp_path / "out2"
    assert (
        build_book.build(out=out2, cache=True, jobs=2, book=book, config_file=config, execute_only=True) == 0
    )
    assert calls[1][2] == 2
    assert len(sphinx.calls) == 1
    assert (out2 / "_build" / "page-times.json").exists()
    monkeypatch.setattr(build_book, "prefill", lambda *args, **kwargs: {})
    out3 = tmp_path / "out3"
    assert build_book.build(out=out3, cache=True, book=book, config_file=config, execute_only=True) == 0
    assert not (out3 / "_build" / "page-times.json").exists()


def test_build_without_the_cache_and_execute_only_runs_nothing(tmp_path, sphinx, monkeypatch):
    """Oracle: no cache and ``execute_only``: neither execution nor Sphinx."""
    book, config = _toy(tmp_path)
    monkeypatch.setattr(build_book, "prefill", lambda *args, **kwargs: pytest.fail("executed"))
    assert build_book.build(out=tmp_path, book=book, config_file=config, execute_only=True) == 0
    assert sphinx.calls == []


def test_latex_to_pdf_typesets_quietly_and_reports(tmp_path, log, monkeypatch):
    """Oracle: the ``make all-pdf`` call in the LaTeX folder with latexmk silent (unless the
    caller chose other options), and the log lines written out by hand: a successful run
    prints no error of the LaTeX log (a warning there that looks like one)."""
    latex = tmp_path / "_build" / "latex"
    _write(latex / "book.tex", "x")
    _write(latex / "book.log", "! looks like an error\n")
    monkeypatch.delenv("LATEXMKOPTS", raising=False)
    monkeypatch.delenv("MAKE", raising=False)
    calls: list = []
    monkeypatch.setattr(build_book, "_run_quietly", lambda cmd, cwd, env: calls.append((cmd, cwd, env)) or 0)
    assert build_book.latex_to_pdf(tmp_path) == 0
    ((cmd, cwd, env),) = calls
    assert (cmd, cwd, env["LATEXMKOPTS"]) == (["make", "all-pdf"], latex, "-silent")
    assert env["PATH"] == os.environ["PATH"]
    assert log.take() == f"latex: typesetting {latex / 'book.tex'}\nlatex: done\n"
    monkeypatch.setenv("LATEXMKOPTS", "-verbose")
    monkeypatch.setenv("MAKE", "gmake")
    build_book.latex_to_pdf(tmp_path)
    assert (calls[1][0], calls[1][2]["LATEXMKOPTS"]) == (["gmake", "all-pdf"], "-verbose")


@pytest.mark.parametrize("code", [1, 2])
def test_latex_to_pdf_prints_the_errors_of_a_failed_run(tmp_path, log, monkeypatch, code):
    """Oracle: a failed run (exit 1 or 2) and a LaTeX log of two errors, one line of it not
    UTF-8: each error with the two lines after it (fewer at the end of the log, the bad byte
    replaced), then the failure."""
    latex = tmp_path / "_build" / "latex"
    latex.mkdir(parents=True)
    (latex / "book.log").write_bytes(
        b"ok\n! Undefined control sequence.\nl.5 \\foo\xff\nctx\nafter\n! Emergency stop.\n"
    )
    _write(latex / "notes.txt", "! not a log\n")
    monkeypatch.setattr(build_book, "_run_quietly", lambda cmd, cwd, env: code)
    assert build_book.latex_to_pdf(tmp_path) == code
    assert log.take().split("\n")[1:] == [
        "book.log:",
        "    ! Undefined control sequence.",
        "    l.5 \\foo\ufffd",
        "    ctx",
        "book.log:",
        "    ! Emergency stop.",
        f"latex: FAILED (exit {code})",
        "",
    ]


@pytest.fixture
def main_env(monkeypatch):
    """``main`` with the build, the signal handlers, the parent-death signal, the stop and the
    process exit stood in for: what each was called with."""
    seen: dict = {"signal": [], "death": [], "stopped": 0, "exit": None}

    def build(*args):
        seen["build"] = args
        if isinstance(seen.get("raise"), BaseException):
            raise seen["raise"]
        return seen.get("code", 0)

    def stop_started():
        seen["stopped"] += 1
        return 4

    def exit_now(code):
        seen["exit"] = code
        raise SystemExit(f"os._exit({code})")

    monkeypatch.setattr(build_book, "build", build)
    monkeypatch.setattr(build_book, "latex_to_pdf", lambda out: seen.setdefault("latex", out) and 9)
    monkeypatch.setattr(
        build_book.signal, "signal", lambda signum, handler: seen["signal"].append((signum, handler))
    )
    monkeypatch.setattr(build_book, "_set_parent_death_signal", lambda *args: seen["death"].append(args))
    monkeypatch.setattr(build_book, "stop_started", stop_started)
    monkeypatch.setattr(build_book.os, "_exit", exit_now)
    monkeypatch.delenv("NAVCORE_STOP_WITH_PARENT", raising=False)
    monkeypatch.setenv("COLUMNS", "300")
    return seen


def _main(monkeypatch, *args):
    monkeypatch.setattr(sys, "argv", ["build_book.py", *args])
    return build_book.main()


def test_main_passes_the_defaults_to_build(main_env, monkeypatch):
    """Oracle: no arguments: an HTML build of the repository's book, no subset, no cache,
    default jobs; the interrupt handlers installed, no parent-death signal."""
    main_env["code"] = 3
    assert _main(monkeypatch) == 3
    root = build_book.ROOT
    assert main_env["build"] == (
        "html",
        None,
        None,
        False,
        None,
        (root / "book").resolve(),
        (root / "_config.yml").resolve(),
        False,
    )
    handler = build_book._INTERRUPTS.handler
    assert main_env["signal"] == [(signal.SIGINT, handler), (signal.SIGTERM, handler)]
    assert main_env["death"] == []


def test_main_passes_every_option_to_build(main_env, monkeypatch, tmp_path):
    """Oracle: each option given: passed on as given (book and config made absolute); with
    ``NAVCORE_STOP_WITH_PARENT`` the parent-death signal is armed."""
    monkeypatch.setenv("NAVCORE_STOP_WITH_PARENT", "1")
    monkeypatch.chdir(tmp_path)
    args = ["--builder", "pdflatex", "--only", "wf", "--out", "o", "--cache", "--jobs", "3"]
    assert _main(monkeypatch, *args, "--execute-only", "--book", "b", "--config", "c.yml") == 0
    assert main_env["build"] == (
        "pdflatex",
        "wf",
        Path("o"),
        True,
        3,
        tmp_path / "b",
        tmp_path / "c.yml",
        True,
    )
    assert main_env["death"] == [()]


def test_main_typesets_only_with_latex_to_pdf(main_env, monkeypatch, tmp_path):
    """Oracle: ``--latex-to-pdf`` typesets the output folder given (else the repository's) and
    builds nothing."""
    assert _main(monkeypatch, "--latex-to-pdf", "--out", str(tmp_path)) == 9
    assert main_env["latex"] == tmp_path
    assert "build" not in main_env
    del main_env["latex"]
    _main(monkeypatch, "--latex-to-pdf")
    assert main_env["latex"] == build_book.ROOT


def test_main_stops_what_it_started_when_interrupted(main_env, monkeypatch, capsys):
    """Oracle: an interrupt during the build: further signals ignored, the processes stopped,
    the count said on stderr, exit 130 at once."""
    main_env["raise"] = KeyboardInterrupt()
    with pytest.raises(BaseException) as stop:  # not the interrupt itself: that would stop pytest
        _main(monkeypatch)
    assert (stop.type, str(stop.value)) == (SystemExit, "os._exit(130)")
    assert main_env["signal"][2:] == [(signal.SIGINT, signal.SIG_IGN), (signal.SIGTERM, signal.SIG_IGN)]
    assert main_env["stopped"] == 1
    assert capsys.readouterr().err == "build_book: interrupted; stopped 4 processes it started\n"


def test_main_stops_what_it_started_and_reraises_an_error(main_env, monkeypatch):
    """Oracle: an error during the build: the processes stopped, the error raised, no exit 130."""
    main_env["raise"] = ValueError("boom")
    with pytest.raises(ValueError, match="boom"):
        _main(monkeypatch)
    assert main_env["stopped"] == 1
    assert main_env["exit"] is None


def test_main_refuses_an_unknown_builder_and_documents_its_options(main_env, monkeypatch, capsys):
    """Oracle: argparse's exit status 2 for an unknown builder; the help text holds each
    option's help (the tests' options hidden) and the docstring's first line."""
    with pytest.raises(SystemExit) as stop:
        _main(monkeypatch, "--builder", "epub")
    assert stop.value.code == 2
    text = " " + help_text(lambda argv: _main(monkeypatch, *argv), capsys) + " "
    for words in (
        "Build the book, or a subset of it, strictly.",
        "--builder {html,pdflatex,latex,linkcheck}",
        "output folder (default: the repository)",
        "execute through a jupyter-cache (see above)",
        "with --cache: chapters executed at once (default: one more than the cores)",
        "with --cache: execute what the cache lacks, no Sphinx",
        "only typeset the LaTeX sources of an earlier --builder latex build into book.pdf",
        "build one paper's chapter (wf, sp, atc10, kzl), the API reference (reference) "
        "or the verification reports (reports)",
    ):
        assert f" {words} " in text  # whole: no text added around it
    assert "--book" not in text
    assert "--config" not in text


# --- prefill: the pages executed in worker processes, each chapter's kernel stood in for ---------

_STAND_IN_CALLS: list[Path] = []  # the file the stand-in executor appends its calls to (forked)


def _stand_in_group(paper, paths, timeout, book):
    """Stand-in for ``_execute_group`` (runs in a worker): the chapter's claims take 0.5 s, each
    page 1 s, a page whose text says ``FAIL`` fails and one that says ``RAISE`` breaks the
    worker; every result goes to the worker's queue."""
    with _STAND_IN_CALLS[0].open("a") as log:
        log.write(json.dumps([paper, paths, timeout, str(book)]) + "\n")
    results = build_book._RESULTS
    if paper is not None:
        results.put({"path": f"(ledger {paper})", "seconds": 0.5})
    deps = build_book.dependency_record(["navcore.units"], [], build_book.navcore_root())
    for path in paths:
        if "RAISE" in Path(path).read_text():
            raise RuntimeError(f"the worker broke on {Path(path).name}")
        nb = build_book._read_notebook(Path(path))
        err = "CellExecutionError: boom\nin a cell" if "FAIL" in Path(path).read_text() else None
        results.put({"path": path, "seconds": 1.0, "nb": nb, "err": err, "deps": deps})
    return []


@pytest.fixture
def prefill_book(tmp_path, monkeypatch):
    """A book of two WF notebooks, a front-matter notebook, an SP folder without notebooks and
    a plain page; the stand-in executor; a cache folder."""
    book = tmp_path / "book"
    for name in ("wf/01.md", "wf/02.md", "intro.md"):
        _write(book / name, PAGE.replace("print(1)", f"print({name!r})"))
    _write(book / "sp" / "plain.md", "# no kernel\n")
    _write(book / "about.md", "# no kernel\n")
    calls = tmp_path / "calls.jsonl"
    monkeypatch.setattr(sys.modules[__name__], "_STAND_IN_CALLS", [calls])
    monkeypatch.setattr(build_book, "_execute_group", _stand_in_group)
    pages = [book / "intro.md", book / "wf" / "01.md", book / "wf" / "02.md", book / "about.md"]
    return book, pages, tmp_path / "cache", calls


def _calls(path):
    return [json.loads(line) for line in path.read_text().splitlines()] if path.exists() else []


def test_prefill_executes_what_the_cache_lacks_then_nothing(prefill_book, log):
    """Oracle: an empty cache: the three notebooks execute (said why, in page order), the WF
    chapter with its claims and, because the front matter executes, the SP chapter's claims
    (its folder exists) in the first round, the front matter in the second; the times; every
    page stored with its dependencies. Again: nothing executes."""
    book, pages, cache_path, calls = prefill_book
    times = build_book.prefill(cache_path, pages, jobs=4, timeout=7, book=book)
    assert times == {
        "(ledger WF)": 0.5,
        "(ledger SP)": 0.5,
        "wf/01.md": 1.0,
        "wf/02.md": 1.0,
        "intro.md": 1.0,
    }
    wf = [str(book / "wf" / "01.md"), str(book / "wf" / "02.md")]
    assert sorted(_calls(calls)[:2]) == sorted([["WF", wf, 7, str(book)], ["SP", [], 7, str(book)]])
    assert _calls(calls)[2:] == [[None, [str(book / "intro.md")], 7, str(book)]]
    out = log.take().splitlines()
    assert out[:4] == [
        "prefill: executing 3 of 3 notebooks:",
        "prefill:   intro.md (not in the cache)",
        "prefill:   wf/01.md (not in the cache)",
        "prefill:   wf/02.md (not in the cache)",
    ]
    assert sorted(out[4:-1]) == sorted(
        f"prefill:     {s} s  {p}"
        for s, p in [
            ("0.5", "(ledger WF)"),
            ("0.5", "(ledger SP)"),
            ("1.0", "wf/01.md"),
            ("1.0", "wf/02.md"),
            ("1.0", "intro.md"),
        ]
    )
    summary = re.fullmatch(r"prefill: 3 pages in (\d+\.\d) s with 2 workers", out[-1])
    assert summary is not None
    assert 0 <= float(summary[1]) < 60  # the time since the executions started
    cache = get_cache(str(cache_path))
    records = {r.uri: r for r in cache.list_cache_records()}
    assert sorted(records) == sorted([str(book / "intro.md"), *wf])
    stored = (build_book._record_dir(cache, records[wf[0]].hashkey) / "navcore-deps.json").read_text()
    deps = build_book.dependency_record(["navcore.units"], [], build_book.navcore_root())
    assert stored == json.dumps(deps, sort_keys=True)  # keys sorted: the same record on every run
    assert records[wf[0]].data == {"execution_seconds": 1.0}
    assert build_book.prefill(cache_path, pages, jobs=4, book=book) == {}
    assert log.take() == "prefill: all 3 notebooks are in the cache and up to date\n"
    assert len(_calls(calls)) == 3


def test_prefill_executes_a_stale_page_alone_and_replaces_its_record(prefill_book, log):
    """Oracle: one page's stored dependency changed: only it executes, said why, in one worker
    of its chapter with the chapter's claims; its record is replaced, the others kept."""
    book, pages, cache_path, calls = prefill_book
    build_book.prefill(cache_path, pages, jobs=2, book=book)
    cache = get_cache(str(cache_path))
    stale = str(book / "wf" / "02.md")
    (record,) = [r for r in cache.list_cache_records() if r.uri == stale]
    deps_file = build_book._record_dir(cache, record.hashkey) / "navcore-deps.json"
    deps = json.loads(deps_file.read_text())
    deps_file.write_text(json.dumps({**deps, "modules": {"navcore.units": "0"}}))
    log.take()
    calls.unlink()
    assert build_book.prefill(cache_path, pages, jobs=2, book=book) == {"(ledger WF)": 0.5, "wf/02.md": 1.0}
    assert _calls(calls) == [["WF", [stale], 900, str(book)]]
    out = log.take().splitlines()
    assert out[:2] == [
        "prefill: executing 1 of 3 notebooks:",
        "prefill:   wf/02.md (imports navcore.units, changed)",
    ]
    assert out[-1].endswith(" s with 1 workers")
    assert len(cache.list_cache_records()) == 3
    assert build_book._why_execute(cache, Path(stale), {}, build_book.navcore_root()) == (None, None)
    intro = book / "intro.md"
    intro.write_text(intro.read_text().replace("print(", "print(2, "))
    log.take()
    assert build_book.prefill(cache_path, pages, jobs=2, book=book)["intro.md"] == 1.0
    assert "prefill:   intro.md (its text changed)\n" in log.take()


def test_prefill_leaves_a_failed_page_to_sphinx_and_drops_its_stale_record(prefill_book, log):
    """Oracle: a stale page (a changed list of modules) whose execution fails: said so with the
    error's first line, not stored, no time, and its out-of-date record dropped (Sphinx must
    not find old outputs)."""
    book, pages, cache_path, _ = prefill_book
    build_book.prefill(cache_path, pages, jobs=2, book=book)
    cache = get_cache(str(cache_path))
    page = book / "wf" / "01.md"
    (record,) = [r for r in cache.list_cache_records() if r.uri == str(page)]
    deps_file = build_book._record_dir(cache, record.hashkey) / "navcore-deps.json"
    deps_file.write_text(json.dumps({**json.loads(deps_file.read_text()), "module_list": "0"}))
    page.write_text(page.read_text().replace("# T", "# T FAIL"))
    log.take()
    assert build_book.prefill(cache_path, pages, jobs=2, book=book) == {"(ledger WF)": 0.5}
    out = log.take()
    assert "prefill:   wf/01.md (navcore's list of modules changed)\n" in out
    assert "prefill: wf/01.md FAILED (CellExecutionError: boom); Sphinx will re-run it\n" in out
    assert sorted(r.uri for r in cache.list_cache_records()) == [
        str(book / "intro.md"),
        str(book / "wf" / "02.md"),
    ]


def test_prefill_raises_a_worker_s_error_instead_of_waiting(prefill_book, log):
    """Oracle: the executor of a chapter raises before sending its pages: the error reaches the
    caller (who stops the workers), rather than the build waiting for pages that never come."""
    book, pages, cache_path, _ = prefill_book
    page = book / "wf" / "02.md"
    page.write_text(page.read_text().replace("# T", "# T RAISE"))
    with pytest.raises(RuntimeError, match=r"^the worker broke on 02\.md$"):
        build_book.prefill(cache_path, pages, jobs=2, book=book)
    assert "prefill:   wf/02.md (not in the cache)\n" in log.take()
