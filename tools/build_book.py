"""Build the book, or a subset of it, strictly.

Usage::

    python tools/build_book.py                 # whole book, HTML, into _build/html
    python tools/build_book.py --builder pdflatex
    python tools/build_book.py --only wf       # the WF chapter and the bibliography, strictly,
                                               # into _build/subset-wf (fast check of one chapter)

A subset build (``--only``) evaluates only the claims its pages use, and reads a reference to
a page outside the subset (another chapter, the front matter, the API reference) as plain text
when that page exists: the ``subset_references`` extension, which only subset builds load,
says in the log how many. A reference to nothing fails a subset build as it fails the full one.

``--cache`` executes through a jupyter-cache whose folder is keyed by the lock file, the
execution settings of ``_config.yml`` and this tool. Each executed page is stored with what
it depends on: the navcore modules it imported (directly, through the modules they import,
and through the modules that navcore itself imported by name, such as the ledger's paper
modules), the data files those modules read, the files beyond the package the page read while
it ran (book pages, tests, the papers' texts: the traceability index and the ledger's page
titles read them) and the folders it listed, and the list of navcore's module files, each
with a hash of its contents. A page is re-executed when its text changed or when one of those
contents changed, and the build prints which pages execute and why ("imports
navcore.gnss.tracking, changed"); every other page comes from the cache.

With ``--cache`` the notebooks to execute run *before* Sphinx, ``--jobs`` chapters at a time
(default: one more than the number of cores, :func:`default_jobs`), each chapter in one kernel
exactly as MyST-NB would execute it (same reader, same working directory, same executor), and
are stored in the cache; Sphinx then finds every notebook there. A chapter's kernel first
evaluates the chapter's ledger claims (filling the on-disk evaluation cache that the ledger and
errata pages read); when a page of the front or back matter executes, every paper's claims are
evaluated that way first, one paper per worker. A notebook that fails is not stored, so Sphinx
executes it again and the strict build fails with its traceback. The execution time of every
page and chapter is printed and written to ``<out>/_build/page-times.json``.

The build is strict: forced execution, a failing cell fails it (``nb_execution_raise_on_error``),
and ``-W -n --keep-going`` turns warnings, broken references and missing citations into errors.
Sphinx runs quietly (``-q``): the log holds the pages executed and why, the warnings the strict
build fails on, and the result. Paths are absolute because ``jupyter-book build .`` breaks
singlehtml and walks ``.nox/``.

SIGINT (Ctrl-C, to the process group or to this process alone) or SIGTERM stops the build at
any phase, and every process it started (workers, kernels, Sphinx, LaTeX) within seconds; the
execution cache stays valid.
"""

from __future__ import annotations

import argparse
import ast
import contextlib
import fnmatch
import hashlib
import json
import multiprocessing
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Iterator
from concurrent.futures import Future, ProcessPoolExecutor
from functools import cache
from pathlib import Path
from queue import Empty
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
PARTS = {
    "wf": "Wu & Fowler",
    "sp": "Schmidt & Phillips",
    "atc10": "ATC-10",
    "kzl": "Knedlik, Zhou & Loffeld",
    "reference": "Reference",
    "reports": "Verification reports",
}

REFERENCE_PAGES = (
    "units",
    "frames",
    "gravity",
    "estimation",
    "inertial",
    "gnss",
    "integration",
    "detection",
    "location",
    "ledger",
)
HOWTO_PAGES = ("dop", "outage", "kalman", "frames", "detection", "emitter")


def subset_toc(paper: str, book: Path = ROOT / "book") -> str:
    """The table of contents of a subset build (``--only``).

    A paper's chapter is built alone, rooted at its opening page, with the bibliography its
    citations need: no front or back matter that reads every paper's claims, so the build
    evaluates only the claims the chapter's own pages use. References to pages outside the
    subset read as plain text (the ``subset_references`` extension, loaded by subset builds only).
    """
    if paper == "reference":  # the how-to guides (executed) and the API reference
        howto = "".join(f"          - file: reference/howto/{name}\n" for name in HOWTO_PAGES)
        pages = "".join(f"      - file: reference/{name}\n" for name in REFERENCE_PAGES)
        return (
            "format: jb-book\nroot: reference/index\nparts:\n"
            "  - caption: Reference\n    chapters:\n"
            "      - file: reference/howto/index\n        sections:\n" + howto + pages
        )
    if paper == "reports":  # the four reports and the Verification pages they link to
        reports = "".join(f"          - file: reports/{key}\n" for key in ("wf", "sp", "atc10", "kzl"))
        return (
            "format: jb-book\nroot: intro\nparts:\n"
            "  - caption: Introduction\n    chapters:\n      - file: about\n      - file: notation\n"
            "      - file: glossary\n"
            "  - caption: Verification\n    chapters:\n      - file: ledger\n      - file: assumptions\n"
            "      - file: coverage\n      - file: errata\n"
            "      - file: reports/index\n        sections:\n" + reports + "      - file: bibliography\n"
        )
    bibliography = "      - file: bibliography\n" if (book / "bibliography.md").exists() else ""
    return (
        f"format: jb-book\nroot: {paper}/index\nparts:\n"
        f"  - caption: {PARTS.get(paper, paper)}\n    chapters:\n      - glob: {paper}/[0-9]*\n"
        + bibliography
    )


# configuration that only changes how executed pages are rendered (LaTeX, HTML theme,
# bibliography, numbering): a change there re-renders the book without re-executing it
_RENDER_ONLY = {"title", "author", "copyright", "logo", "latex", "html", "bibtex_bibfiles", "launch_buttons"}
_RENDER_ONLY_SPHINX = ("latex_", "html_", "bibtex_", "numfig", "math_", "suppress_warnings")


def _execution_config(config_file: Path | None = None) -> str:
    """The part of the configuration that can change what a notebook's execution produces."""
    import yaml

    config = yaml.safe_load((config_file or ROOT / "_config.yml").read_text())
    config = {k: v for k, v in config.items() if k not in _RENDER_ONLY}
    sphinx = dict(config.get("sphinx") or {})
    sphinx["config"] = {
        k: v for k, v in (sphinx.get("config") or {}).items() if not k.startswith(_RENDER_ONLY_SPHINX)
    }
    sphinx.pop("local_extensions", None)  # Sphinx extensions render; they never execute cells
    config["sphinx"] = sphinx
    return json.dumps(config, sort_keys=True, default=str)


def source_key(config_file: Path | None = None) -> str:
    """Hash of what, besides a page's own text and the navcore files it uses, can change its outputs.

    The lock, the Python version, the execution-relevant part of the configuration and this
    file (which executes the notebooks); not the Sphinx extensions or the rendering settings.
    navcore's files are not in it: each page is keyed on the ones it uses
    (:func:`page_dependencies`).
    """
    h = hashlib.sha256(f"python {sys.version_info[:2]}".encode())
    for f in (ROOT / "requirements" / "lock.txt", Path(__file__).resolve()):
        if f.exists():
            h.update(f.name.encode())
            h.update(f.read_bytes())
    h.update(_execution_config(config_file).encode())
    return h.hexdigest()[:16]


def cached_config(config_file: Path | None = None) -> Path:
    """A copy of the configuration that executes through a jupyter-cache keyed by :func:`source_key`."""
    import yaml

    config_file = config_file or ROOT / "_config.yml"
    config = yaml.safe_load(config_file.read_text())
    config["execute"]["execute_notebooks"] = "cache"
    # NAVCORE_BOOK_CACHE chooses another parent folder (the benchmark's clean build does)
    parent = Path(os.environ.get("NAVCORE_BOOK_CACHE") or ROOT / "_build" / "jupyter_cache")
    config["execute"]["cache"] = str(parent / source_key(config_file))
    # local extension folders are relative to the config file, which moves to _build/
    local = (config.get("sphinx") or {}).get("local_extensions") or {}
    for name, folder in local.items():
        local[name] = str(config_file.parent / folder)
    path = parent / "_config_cached.yml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(yaml.safe_dump(config, sort_keys=False))
    return path


SUBSET_EXTENSION = "subset_references"  # book/_ext: loaded by subset builds only


def subset_config(config_file: Path, folder: Path) -> Path:
    """A copy of ``config_file`` (written into ``folder``) that also loads :data:`SUBSET_EXTENSION`.

    Only a subset build uses it, so the full book never sets a reference to a missing page as
    plain text. The execution cache stays the one ``config_file`` names (its key does not
    depend on the Sphinx extensions), so a subset build reuses the full build's executions.
    """
    import yaml

    config = yaml.safe_load(config_file.read_text())
    sphinx = config.setdefault("sphinx", {}) or {}
    config["sphinx"] = sphinx
    local = dict(sphinx.get("local_extensions") or {})
    for name, ext_folder in local.items():  # relative to the config file, which moves
        local[name] = str((config_file.parent / ext_folder).resolve())
    local[SUBSET_EXTENSION] = str(ROOT / "book" / "_ext")
    sphinx["local_extensions"] = local
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"_config_subset_{config_file.stem}.yml"
    path.write_text(yaml.safe_dump(config, sort_keys=False))
    return path


def toc_pages(toc: Path, book: Path = ROOT / "book") -> list[Path]:
    """The book pages a toc names, globs resolved, in toc order."""
    import yaml

    found: list[Path] = []

    def walk(node: object) -> None:
        if isinstance(node, dict):
            if "file" in node:
                found.extend(sorted(book.glob(node["file"] + ".*"))[:1])
            if "glob" in node:
                pattern = node["glob"]
                found.extend(
                    sorted(
                        p
                        for p in book.rglob("*.md")
                        if fnmatch.fnmatch(p.relative_to(book).with_suffix("").as_posix(), pattern)
                    )
                )
            for key in ("root",):
                if key in node:
                    found.extend(sorted(book.glob(node[key] + ".*"))[:1])
            for value in node.values():
                if isinstance(value, (list, dict)):
                    walk(value)
        elif isinstance(node, list):
            for item in node:
                walk(item)

    walk(yaml.safe_load(toc.read_text()))
    return list(dict.fromkeys(found))


def _is_notebook(path: Path) -> bool:
    text = path.read_text()
    return path.suffix == ".md" and text.startswith("---") and "kernelspec:" in text.split("\n---", 1)[0]


def _read_notebook(path: Path):
    """The notebook MyST-NB builds from a MyST Markdown page (same reader, same hash)."""
    from myst_nb.core.read import read_myst_markdown_notebook

    return read_myst_markdown_notebook(path.read_text(), path=str(path))


# --- what a page depends on ---------------------------------------------------------------------
# A chapter's pages share one kernel, so a page can use what an earlier page (or the ledger
# warm-up) loaded without loading it again. What a page depends on is therefore computed from
# what it *imports* (every import statement runs again in each page, even for a module that is
# already loaded) and from a graph of which navcore module imports which: the import statements
# of each module's source (at module level and inside functions, executed or not, in this
# process or another) and the imports that navcore made by name while the kernel ran (the
# ledger's paper modules, the figure modules). The page depends on every module reachable from
# its imports, their packages, the data files those modules name, and the list of navcore's
# module files (a new paper module changes what the registry loads). A module that changes
# process-wide state a later page may rely on without importing it (``navcore.book``: figure
# style, table formatters, numpy's print options) stays a dependency of every later page of
# the kernel once a page imported it.

PACKAGE = "navcore"
STICKY = ("navcore.book",)

# Installed in each kernel before anything else runs: it records which navcore modules each
# import statement (or importlib.import_module call) brings in, and who imported them (a navcore
# module: an edge of the graph; anyone else, the page's own code included: a root of the page),
# which navcore data files a navcore module opens, and which book pages, tests and papers' texts
# the page itself read or listed while it ran.
_RECORDER = r"""
def _navcore_build_recorder():
    import builtins, importlib, importlib.util, json, os, sys, types

    rec = types.ModuleType("_navcore_build_deps")
    rec.edges, rec.roots = {}, set()
    package_dir = os.path.dirname(importlib.util.find_spec("navcore").origin) + os.sep
    original_import, original_import_module = builtins.__import__, importlib.import_module

    def ours(name):
        return name == "navcore" or name.startswith("navcore.")

    def note(importer, target):
        if ours(importer):
            rec.edges.setdefault(importer, set()).add(target)
        else:
            rec.roots.add(target)

    def hooked_import(name, globals=None, locals=None, fromlist=(), level=0):
        module = original_import(name, globals, locals, fromlist, level)
        g = globals or {}
        try:
            full = importlib.util.resolve_name("." * level + name, g.get("__package__")) if level else name
        except (ImportError, ValueError):
            return module
        if ours(full):
            importer = g.get("__name__") or ""
            note(importer, full)
            for item in fromlist or ():
                if full + "." + str(item) in sys.modules:
                    note(importer, full + "." + str(item))
        return module

    def import_module(name, package=None):
        module = original_import_module(name, package)
        if ours(module.__name__):
            note(sys._getframe(1).f_globals.get("__name__") or "", module.__name__)
        return module

    repo = os.path.dirname(package_dir.rstrip(os.sep)) + os.sep
    outside = (  # what the book reads beyond the package: its pages, the tests, the papers' texts
        os.path.join(repo, "book") + os.sep,
        os.path.join(repo, "tests") + os.sep,
        os.path.join(os.path.dirname(repo.rstrip(os.sep)), "shared", "papers") + os.sep,
    )
    rec.page_files = set()

    def audit(event, args):
        if event not in ("open", "os.scandir", "os.listdir") or not args or not isinstance(args[0], str):
            return
        path = os.path.abspath(args[0])
        if event != "open":  # a listing (a glob over the pages): the page depends on its names
            if (path + os.sep).startswith(outside):
                rec.page_files.add(os.path.relpath(path, package_dir) + "/")
            return
        if path.startswith(outside):
            # the page that ran when a file beyond the package was read depends on it (a navcore
            # module reading all the pages must not make every page of its kernel depend on them)
            rec.page_files.add(os.path.relpath(path, package_dir))
            return
        if not path.startswith(package_dir) or path.endswith((".py", ".pyc")):
            return
        frame, importer = sys._getframe(1), ""
        while frame is not None and not ours(importer):
            importer = frame.f_globals.get("__name__") or ""
            frame = frame.f_back
        note(importer, "file:" + path[len(package_dir):])

    def start_page():
        rec.roots, rec.page_files = set(), set()

    def take():
        return json.dumps(
            {
                "roots": sorted(rec.roots),
                "edges": {k: sorted(v) for k, v in rec.edges.items()},
                "files": sorted(rec.page_files),
            }
        )

    rec.start_page, rec.take = start_page, take
    sys.modules[rec.__name__] = rec
    builtins.__import__ = hooked_import
    importlib.import_module = import_module
    sys.addaudithook(audit)


_navcore_build_recorder()
del _navcore_build_recorder
"""
_TAKE = "import _navcore_build_deps as _d\nprint(_d.take())\ndel _d"


@cache
def navcore_root() -> Path:
    """The folder holding the navcore package that this process (and its kernels) import.

    The checkout's, unless ``PYTHONPATH`` puts another copy first (the tests build against one).
    """
    import importlib.util

    spec = importlib.util.find_spec(PACKAGE)
    if spec is None or spec.origin is None:
        return ROOT
    return Path(spec.origin).resolve().parents[1]


def _package_dir(root: Path) -> Path:
    return root / PACKAGE


@cache
def _module_files(root: Path) -> dict[str, Path]:
    """navcore's modules by dotted name (a package by its ``__init__.py``)."""
    files = {}
    for path in sorted(_package_dir(root).rglob("*.py")):
        parts = list(path.relative_to(root).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        files[".".join(parts)] = path
    return files


@cache
def _data_files(root: Path) -> tuple[str, ...]:
    """navcore's data files (not Python), relative to the package folder."""
    return tuple(
        sorted(
            p.relative_to(_package_dir(root)).as_posix()
            for p in _package_dir(root).rglob("*")
            if p.is_file() and p.suffix not in (".py", ".pyc") and "__pycache__" not in p.parts
        )
    )


def _import_refs(node: ast.AST, package: str) -> set[str]:
    """The dotted names an ``import`` or ``from ... import`` statement refers to."""
    if isinstance(node, ast.Import):
        return {alias.name for alias in node.names}
    assert isinstance(node, ast.ImportFrom)
    base = node.module or ""
    if node.level:
        parts = package.split(".")[: len(package.split(".")) - node.level + 1]
        base = ".".join([*parts, *([node.module] if node.module else [])])
    return {base, *(f"{base}.{alias.name}" for alias in node.names)}


@cache
def _import_statements(root: Path) -> dict[str, tuple[frozenset[str], frozenset[str]]]:
    """For each navcore module: what it imports when it is imported, and what only its functions import.

    The first set holds the modules of the import statements that run when the module runs
    (at module level, in ``if``/``try`` blocks and class bodies) and the data files its source
    names (``file:papers/paper_items.json``); the second the modules that only statements
    inside functions (and lambdas) import, which run when the function is called.
    """
    modules = _module_files(root)
    data = _data_files(root)
    found: dict[str, tuple[frozenset[str], frozenset[str]]] = {}
    for name, path in modules.items():
        source = path.read_text()
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        at_import: set[str] = set()
        in_functions: set[str] = set()
        stack: list[tuple[ast.AST, bool]] = [(ast.parse(source), False)]
        while stack:
            node, in_function = stack.pop()
            for child in ast.iter_child_nodes(node):
                inner = in_function or isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
                if isinstance(child, (ast.Import, ast.ImportFrom)):
                    (in_functions if inner else at_import).update(_import_refs(child, package))
                stack.append((child, inner))
        refs = {m for m in at_import if m in modules}
        refs.update(f"file:{f}" for f in data if Path(f).name in source)
        found[name] = (frozenset(refs), frozenset(m for m in in_functions if m in modules) - refs)
    return found


@cache
def static_import_graph(root: Path) -> dict[str, frozenset[str]]:
    """For each navcore module, the navcore modules and data files its source refers to.

    Every ``import`` and ``from ... import`` statement counts, inside functions too; a data file
    (``file:papers/paper_items.json``) counts when the module's source names it.
    """
    return {
        name: at_import | in_functions for name, (at_import, in_functions) in _import_statements(root).items()
    }


PAPER_MODULES = PACKAGE + ".papers."  # the ledger's paper modules: what its evaluations run


@cache
def dependency_graph(root: Path) -> dict[str, frozenset[str]]:
    """The static part of a page's dependencies: which navcore module depends on which.

    A module that the ledger's paper modules reach (through every import statement, inside
    functions too: :func:`static_import_graph`) keeps every import statement of its source,
    because the ledger may run its code in worker processes, where the kernel records nothing.
    Every other module (what only the book's pages call: the page helpers, the glue registry,
    the figures, the reports) keeps the imports that run when it is imported; what its
    functions import when a page calls them runs in the kernel, which records it (an edge of
    ``page_dependencies``). So a page that glues one paper's number depends on that paper's
    models, not on every model the glue registry could import.
    """
    full = static_import_graph(root)
    statements = _import_statements(root)
    run_by_ledger: set[str] = set()
    todo = [name for name in full if name.startswith(PAPER_MODULES)]
    while todo:
        name = todo.pop()
        if name not in run_by_ledger:
            run_by_ledger.add(name)
            todo.extend(m for m in _with_packages(set(full.get(name, ()))) if m in full)
    return {name: full[name] if name in run_by_ledger else statements[name][0] for name in full}


def _with_packages(names: set[str]) -> set[str]:
    out = set(names)
    for name in names:
        while not name.startswith("file:") and "." in name:
            name = name.rpartition(".")[0]
            out.add(name)
    return out


def page_dependencies(
    roots: set[str], edges: dict[str, list[str]], root: Path
) -> tuple[list[str], list[str]]:
    """The navcore modules and data files reachable from a page's imports (sorted).

    ``edges`` are the imports that navcore modules made while the kernel ran; the static graph
    (:func:`dependency_graph`) adds the import statements of every module's source (those
    inside functions for the modules the ledger's paper modules reach).
    """
    graph = dependency_graph(root)
    seen: set[str] = set()
    todo = list(_with_packages(set(roots)))
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        todo.extend(_with_packages(set(graph.get(name, ())) | set(edges.get(name, ()))))
    modules = _module_files(root)
    return sorted(n for n in seen if n in modules), sorted(n[5:] for n in seen if n.startswith("file:"))


def _file_hash(path: Path) -> str | None:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()[:20]
    except OSError:
        return None


# the table of contents a subset build writes into the book folder while it runs: not part of
# what a page that lists the folder depends on (else every subset build, and the full build
# after it, would execute those pages again)
SUBSET_TOC_PREFIX = "_toc_subset_"


def _dependency_hash(root: Path, name: str) -> str | None:
    """Hash of a data dependency, named relative to the package folder: a file's contents, or
    for a name ending in ``/`` (a folder the page listed) the sorted names in it, less a subset
    build's temporary table of contents."""
    path = _package_dir(root) / name
    if not name.endswith("/"):
        return _file_hash(path)
    try:
        listing = "\n".join(
            sorted(p.name for p in path.iterdir() if not p.name.startswith(SUBSET_TOC_PREFIX))
        )
    except OSError:
        return None
    return hashlib.sha256(listing.encode()).hexdigest()[:20]


def _listing_hash(root: Path) -> str:
    return hashlib.sha256("\n".join(sorted(_module_files(root))).encode()).hexdigest()[:20]


def dependency_record(modules: list[str], files: list[str], root: Path) -> dict[str, Any]:
    """What is stored beside a cached page: each dependency with the hash of its contents."""
    paths = _module_files(root)
    return {
        "modules": {m: _file_hash(paths[m]) for m in modules},
        "files": {f: _dependency_hash(root, f) for f in files},
        "module_list": _listing_hash(root),
    }


def stale_reason(record: dict[str, Any] | None, root: Path) -> str | None:
    """Why a cached page is out of date (``None`` if it is not): the dependencies that changed."""
    if record is None:
        return "no record of what it imports"
    paths = _module_files(root)
    changed = [
        f"imports {m}"
        for m, digest in record.get("modules", {}).items()
        if m not in paths or _file_hash(paths[m]) != digest
    ]
    files = record.get("files", {})
    changed += [
        f"reads {f.removeprefix('../')}" for f, digest in files.items() if _dependency_hash(root, f) != digest
    ]
    if changed:
        shown = ", ".join(changed[:3]) + (f" and {len(changed) - 3} more" if len(changed) > 3 else "")
        return f"{shown}, changed"
    if record.get("module_list") != _listing_hash(root):
        return "navcore's list of modules changed"
    return None


# --- stopping a build -------------------------------------------------------------------------
# SIGINT (Ctrl-C: to the whole process group, or to this process alone) and SIGTERM stop the
# build and every process it started within seconds, at any phase. Only this process acts on
# them: its main thread never blocks for more than a fraction of a second (it waits with
# timeouts), so the Python handler runs promptly whichever thread the kernel delivered the signal
# to. The handler raises KeyboardInterrupt, except inside a critical section (storing a page in
# the cache), where it waits for the section to end; the stop itself is a critical section, so
# a second Ctrl-C cannot cut it short. The stop sends SIGTERM to every descendant (the pool's
# workers, their kernels, Sphinx and the LaTeX run), then SIGKILL to any left after two seconds.
# Behind it, each worker ignores SIGINT and dies at once on SIGTERM or when this process dies
# (Linux parent-death signal); each kernel dies with its worker, and Sphinx with this process.


class _Interrupts:
    """SIGINT/SIGTERM handler that raises KeyboardInterrupt, deferred inside critical sections."""

    def __init__(self) -> None:
        self.depth = 0
        self.pending: int | None = None

    def handler(self, signum: int, frame: object) -> None:
        if self.depth:
            self.pending = signum
            return
        raise KeyboardInterrupt(f"signal {signum}")

    @contextlib.contextmanager
    def critical(self) -> Iterator[None]:
        self.depth += 1
        try:
            yield
        finally:
            self.depth -= 1
            if not self.depth and self.pending is not None:
                signum, self.pending = self.pending, None
                raise KeyboardInterrupt(f"signal {signum}")

    def install(self) -> None:
        signal.signal(signal.SIGINT, self.handler)
        signal.signal(signal.SIGTERM, self.handler)


_INTERRUPTS = _Interrupts()


def _set_parent_death_signal(signum: int = signal.SIGTERM) -> None:
    """Ask Linux to send ``signum`` to this process when its parent exits (no-op elsewhere)."""
    if not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, int(signum), 0, 0, 0)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # pragma: no cover - no libc prctl
        pass


def _die_with_parent() -> None:
    """``preexec_fn`` of a kernel: SIGKILL when the worker that started it dies."""
    _set_parent_death_signal(signal.SIGKILL)


_RESULTS: Any = None  # in a worker: the queue that takes each page's result as soon as it is ready


def _worker_init(parent: int, results: Any = None) -> None:
    """Pool initializer: the parent stops the workers, so ignore Ctrl-C; die with the parent."""
    global _RESULTS
    _RESULTS = results
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    _set_parent_death_signal(signal.SIGKILL)
    if os.getppid() != parent:  # the parent died before the death signal was armed
        os._exit(1)


def _process_table() -> dict[int, tuple[int, str]]:
    """pid -> (parent pid, state) of every process (Linux /proc; empty elsewhere)."""
    table = {}
    for entry in Path("/proc").iterdir() if Path("/proc/self/stat").exists() else ():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        table[int(entry.name)] = (int(fields[1]), fields[0])
    return table


def descendants(pid: int) -> set[int]:
    """Every live process below ``pid`` (Linux; an empty set elsewhere)."""
    children: dict[int, list[int]] = {}
    for child, (parent, state) in _process_table().items():
        if state != "Z":
            children.setdefault(parent, []).append(child)
    found, todo = set(), [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            if child not in found:
                found.add(child)
                todo.append(child)
    return found


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        try:
            os.kill(pid, 0)
        except OSError:
            return False
        return not Path("/proc").exists()
    return state != "Z"


def _reap() -> None:
    with contextlib.suppress(ChildProcessError):
        while os.waitpid(-1, os.WNOHANG)[0]:
            pass


def stop_started(known: frozenset[int] = frozenset(), grace: float = 2.0) -> int:
    """SIGTERM every process this one started (and ``known``), then SIGKILL what is left; how many."""
    pids = descendants(os.getpid()) | set(known)
    count = len(pids)
    for signum in (signal.SIGTERM, signal.SIGKILL):
        for pid in pids:
            with contextlib.suppress(OSError):
                os.kill(pid, signum)
        deadline = time.monotonic() + grace
        while time.monotonic() < deadline:
            _reap()
            pids = {p for p in pids if _alive(p)}
            if not pids:
                break
            time.sleep(0.05)
        if not pids:
            break
    return count


# --- executing the pages ------------------------------------------------------------------------

_RESET = """\
%reset -f
import os as _os
import matplotlib.pyplot as _plt
import _navcore_build_deps as _d
_plt.close("all")
_os.chdir({cwd!r})
_d.start_page()
del _os, _plt, _d
"""

PAPERS = ("KZL", "SP", "ATC10", "WF")  # the chapters whose kernels evaluate claims first


def _merge_streams(nb) -> None:
    """One stream output per name and cell, the chunks joined exactly as they were written.

    The kernel sends a cell's printed text in chunks whose boundaries depend on timing, and
    MyST-NB joins stored chunks with a newline after stripping each; merging them here first
    makes the stored and rendered output the same on every run.
    """
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        merged: list = []
        first: dict = {}
        for out in cell.get("outputs", []):
            if out.get("output_type") == "stream":
                if out["name"] in first:
                    first[out["name"]]["text"] += out["text"]
                    continue
                first[out["name"]] = out
            merged.append(out)
        cell.outputs = merged


def _execute_group(
    paper: str | None, paths: list[str], timeout: int, book: Path = ROOT / "book"
) -> list[dict[str, Any]]:
    """Execute a chapter's pages one after another in ONE kernel (in a worker process).

    The kernel first installs the import recorder (:data:`_RECORDER`) and evaluates the
    chapter's ledger claims (filling the on-disk evaluation cache that the ledger and errata
    pages read); then, before each page, the user namespace is reset (``%reset -f``), open
    figures are closed and the working directory is set to the page's folder, so a page sees
    none of the previous page's variables. What carries over is what Python keeps per process:
    imported modules and navcore's pure-function caches (``functools.cache``), which is what
    makes a chapter's pages cheaper together than apart. After each page the recorder says what
    it imported, and the page's dependencies (:func:`page_dependencies`) are stored with it.
    ``tools/bench.py`` executes every page alone in a fresh kernel, as a reader would.

    The kernel talks to this worker over local sockets (the ``ipc`` transport) and dies with it.
    """
    import nbformat
    from jupyter_client.manager import KernelManager
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    root = navcore_root()
    # a short folder: a socket's path may not exceed about 100 characters
    ipc_dir = tempfile.mkdtemp(prefix="nbk-", dir="/tmp" if os.path.isdir("/tmp") else None)
    km = KernelManager(kernel_name="python3", transport="ipc", ip=os.path.join(ipc_dir, "k"))
    km.start_kernel(cwd=str(book), preexec_fn=_die_with_parent)
    kc = None
    results: list[dict[str, Any]] = []

    def emit(result: dict[str, Any]) -> None:  # to the parent at once (in a pool worker), or returned
        if _RESULTS is not None:
            _RESULTS.put(result)
        else:
            results.append(result)

    python3 = {"name": "python3", "display_name": "Python 3", "language": "python"}

    def notebook(source: str, kernelspec: dict | None = None):
        nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(source)])
        nb.metadata["kernelspec"] = kernelspec or python3
        return nb

    def run(nb, cwd: str):
        nonlocal kc
        client = NotebookClient(
            nb,
            km=km,
            kc=kc,
            timeout=timeout,
            allow_errors=False,
            record_timing=False,
            resources={"metadata": {"path": cwd}},
        )
        client.execute()
        kc = client.kc
        return nb

    def recorded() -> dict[str, Any]:
        outputs = run(notebook(_TAKE), str(book)).cells[0].outputs
        text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
        return json.loads(text.strip().splitlines()[-1])

    try:
        run(notebook(_RECORDER), str(book))
        if paper is not None:
            print(f"prefill: {paper}: evaluating the chapter's claims", flush=True)
            start = time.perf_counter()
            warm = f"from navcore import ledger\n_ = ledger.evaluations({paper!r})\ndel _, ledger"
            run(notebook(warm), str(book))
            emit({"path": f"(ledger {paper})", "seconds": time.perf_counter() - start})
        sticky: set[str] = set()
        for path_str in paths:
            path = Path(path_str)
            nb = _read_notebook(path)
            start = time.perf_counter()
            err, deps = None, None
            try:
                reset = notebook(_RESET.format(cwd=str(path.parent)), nb.metadata.get("kernelspec"))
                run(reset, str(path.parent))
                run(nb, str(path.parent))
                seen = recorded()
                roots = set(seen["roots"]) | sticky
                sticky |= {m for m in roots if m in STICKY}
                modules, files = page_dependencies(roots, seen["edges"], root)
                deps = dependency_record(modules, sorted({*files, *seen.get("files", ())}), root)
            except CellExecutionError as exc:
                err = f"CellExecutionError: {exc}"[:2000]
            except Exception as exc:  # a dead kernel, a timeout: report, let Sphinx re-run it
                err = f"{type(exc).__name__}: {exc}"[:2000]
            _merge_streams(nb)
            count = 0
            for cell in nb.cells:  # number the cells as a fresh kernel would
                if cell.cell_type == "code" and cell.get("execution_count") is not None:
                    count += 1
                    cell.execution_count = count
                    for out in cell.get("outputs", []):
                        if "execution_count" in out:
                            out["execution_count"] = count
            emit(
                {"path": path_str, "seconds": time.perf_counter() - start, "nb": nb, "err": err, "deps": deps}
            )
    finally:
        if kc is not None:
            kc.stop_channels()
        km.shutdown_kernel(now=True)
        shutil.rmtree(ipc_dir, ignore_errors=True)
    return results


def _group_pages(
    pages: list[Path], book: Path = ROOT / "book"
) -> tuple[list[tuple[str, list[str]]], list[tuple[str, list[str]]]]:
    """Split pages into the paper chapters' groups and the groups that read every paper's claims.

    One group per chapter folder (named by the folder, upper case). The chapters named for a
    paper come first, heaviest ledger first (:data:`PAPERS`); the others (the chapter across the
    papers) and the front and back matter (group ``""``) read every paper's claims, so they
    run after those, from the evaluation cache that the paper chapters filled.
    """
    chapters: dict[str, list[str]] = {}
    for page in pages:
        rel = page.relative_to(book)
        chapters.setdefault(rel.parts[0].upper() if len(rel.parts) > 1 else "", []).append(str(page))
    papers = [(name, chapters.pop(name)) for name in PAPERS if name in chapters]
    later = sorted(chapters.items(), key=lambda item: (-len(item[1]), item[0] == ""))
    return papers, later


def _record_dir(cache, hashkey: str) -> Path:
    return Path(cache._get_notebook_path_cache(hashkey)).parent


def _drop_record(cache, record) -> None:
    """Remove a cache record and its files (its notebook may be missing: a killed store)."""
    from jupyter_cache.cache.db import NbCacheRecord

    shutil.rmtree(_record_dir(cache, record.hashkey), ignore_errors=True)
    NbCacheRecord.remove_records([record.pk], cache.db)


def _why_execute(cache, page: Path, by_uri: dict[str, Any], root: Path) -> tuple[str | None, Any]:
    """Why ``page`` must execute (``None`` when its cached execution is valid), and its stale record.

    A stale record stays in the cache while the page executes again (an interrupted build
    leaves it, so the next build still says why the page executes); a record that is not
    whole (no notebook or no list of dependencies, a store that was killed) is dropped at once.
    """
    try:
        record = cache.match_cache_notebook(_read_notebook(page))
    except KeyError:
        return ("its text changed" if str(page) in by_uri else "not in the cache"), None
    folder = _record_dir(cache, record.hashkey)
    deps = None
    if (folder / "base.ipynb").exists():
        try:
            deps = json.loads((folder / "navcore-deps.json").read_text())
        except (OSError, ValueError):
            deps = None
    if deps is None:
        with _INTERRUPTS.critical():
            _drop_record(cache, record)
        return "no record of what it imports", None
    reason = stale_reason(deps, root)
    return reason, (record if reason is not None else None)


def default_jobs() -> int:
    """Chapters executed at once by default: one more than the cores.

    A chapter's kernel leaves its core idle part of the time (between cells, while its worker
    stores a page), so one chapter more than the cores keeps them busy: a clean execution of
    the book's 64 pages with the ledger stored took 89.7 s with two workers, 79.5 s with three
    and 77.6 s with four on two cores (6 December 2026).
    """
    return (os.cpu_count() or 1) + 1


def prefill(
    cache_path: Path,
    pages: list[Path],
    jobs: int,
    timeout: int = 900,
    book: Path = ROOT / "book",
) -> dict[str, float]:
    """Execute the pages the jupyter-cache lacks or holds out of date, ``jobs`` chapters at a time.

    An interrupt (KeyboardInterrupt, which SIGINT and SIGTERM raise in the build) propagates at
    once, and the caller stops the workers and their kernels; what was stored before it stays
    valid, and a record is never half-written (stores are critical sections).
    """
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn

    root = navcore_root()
    cache = get_cache(str(cache_path))
    by_uri = {r.uri: r for r in cache.list_cache_records()}
    notebooks = [p for p in pages if _is_notebook(p)]
    todo: list[tuple[Path, str]] = []
    stale: dict[str, Any] = {}  # page -> its out-of-date record, replaced when the page is stored
    for page in notebooks:
        reason, record = _why_execute(cache, page, by_uri, root)
        if reason is not None:
            todo.append((page, reason))
        if record is not None:
            stale[str(page)] = record
    times: dict[str, float] = {}
    if not todo:
        print(f"prefill: all {len(notebooks)} notebooks are in the cache and up to date", flush=True)
        return times
    print(f"prefill: executing {len(todo)} of {len(notebooks)} notebooks:", flush=True)
    for page, reason in todo:
        print(f"prefill:   {page.relative_to(book).as_posix()} ({reason})", flush=True)
    groups, later = _group_pages([p for p, _ in todo], book)
    if later:
        # the pages that read every paper's claims run after every paper's claims are
        # evaluated, one paper per worker (from the evaluation cache where it is up to date)
        present = {name for name, _ in groups}
        groups += [(p, []) for p in PAPERS if p not in present and (book / p.lower()).is_dir()]
    jobs = max(1, min(jobs, max(len(groups), len(later))))
    start = time.perf_counter()

    def store(results: list[dict[str, Any]]) -> None:
        for result in results:
            path_str, seconds = result["path"], result["seconds"]
            if "nb" not in result:
                times[path_str] = seconds
                print(f"prefill: {seconds:7.1f} s  {path_str}", flush=True)
                continue
            rel = Path(path_str).relative_to(book).as_posix()
            if result["err"] is not None:
                first = result["err"].splitlines()[0]
                print(f"prefill: {rel} FAILED ({first}); Sphinx will re-run it", flush=True)
                continue
            times[rel] = seconds
            stale.pop(path_str, None)  # storing the page replaces its out-of-date record
            with _INTERRUPTS.critical():  # no interrupt between the record, its notebook, its dependencies
                record = cache.cache_notebook_bundle(
                    CacheBundleIn(result["nb"], path_str, data={"execution_seconds": seconds}),
                    check_validity=False,
                    overwrite=True,
                )
                deps = _record_dir(cache, record.hashkey) / "navcore-deps.json"
                tmp = deps.with_suffix(".tmp")
                tmp.write_text(json.dumps(result["deps"], sort_keys=True))
                tmp.replace(deps)
            print(f"prefill: {seconds:7.1f} s  {rel}", flush=True)

    def run_all(pool: ProcessPoolExecutor, batch: list[tuple[str, list[str]]]) -> None:
        pending: set[Future] = {
            pool.submit(_execute_group, name if name in PAPERS else None, paths, timeout, book)
            for name, paths in batch
        }
        # one result per page, and one per chapter for its claims
        expected = sum(len(paths) + (name in PAPERS) for name, paths in batch)
        while expected:  # short waits: the interrupt handler runs between them
            try:
                store([queue.get(timeout=0.25)])  # each page as soon as its worker has it
                expected -= 1
                continue
            except Empty:
                pass
            for fut in [fut for fut in pending if fut.done()]:
                fut.result()  # a worker's error, if any, is raised here
                pending.discard(fut)

    queue = multiprocessing.get_context("fork").Queue()
    pool = ProcessPoolExecutor(
        max_workers=jobs,
        mp_context=multiprocessing.get_context("fork"),
        initializer=_worker_init,
        initargs=(os.getpid(), queue),
    )
    try:
        run_all(pool, groups)
        if later:
            run_all(pool, later)
    except KeyboardInterrupt:
        print("prefill: interrupted", flush=True)
        raise
    pool.shutdown(wait=True)
    with _INTERRUPTS.critical():  # a page that failed: Sphinx must not find its old outputs
        for record in stale.values():
            _drop_record(cache, record)
    print(
        f"prefill: {len(todo)} pages in {time.perf_counter() - start:.1f} s with {jobs} workers", flush=True
    )
    return times


def report_times(times: dict[str, float], out: Path) -> None:
    """Print the execution time of each chapter (sum of its pages) and write them as JSON."""
    chapters: dict[str, float] = {}
    for rel, seconds in times.items():
        if rel.startswith("(ledger "):
            chapter = rel[len("(ledger ") : -1].lower()  # the chapter's claims, evaluated first
        else:
            chapter = rel.split("/")[0] if "/" in rel else "(front and back matter)"
        chapters[chapter] = chapters.get(chapter, 0.0) + seconds
    for chapter, seconds in sorted(chapters.items()):
        print(f"execution: {seconds:7.1f} s  {chapter}", flush=True)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"pages": times, "chapters": chapters}, indent=1, sort_keys=True) + "\n")


def builder_dir(builder: str) -> str:
    """The folder of ``_build`` that jupyter-book writes ``builder``'s output to."""
    return {"pdflatex": "latex"}.get(builder, builder)


# jupyter-book's banners on stdout, which tell a reader of the log nothing to act on (Sphinx's
# warnings and errors go to stderr, untouched; what the LaTeX run prints stays too)
_BANNER = re.compile(
    r"^\s*(?:=+|Running Jupyter-Book.*|Source Folder:.*|Config Path:.*|Output Path:.*|"
    r"Finished generating .*|Your book's .* here:|You can look at your book by .*|Or paste this line .*|"
    r"\S*file://\S*|\S*_build/\S*/|\S*_build/\S*index\.html|"
    r"Building your book, returns a non-zero exit code.*)?\s*$"
)
_ANSI = re.compile(r"\x1b\[[0-9;]*m")


def _relay_quietly(stream) -> None:
    """Print what Sphinx's process writes to stdout, less jupyter-book's banners."""
    for line in stream:
        if not _BANNER.match(_ANSI.sub("", line)):
            sys.stdout.write(line)
            sys.stdout.flush()


def _sphinx_preexec() -> None:
    """``preexec_fn`` of the Sphinx run: SIGTERM when this process dies (Linux)."""
    _set_parent_death_signal(signal.SIGTERM)


def _run_quietly(cmd: list[str], cwd: Path, env: dict[str, str] | None = None) -> int:
    """Run a step of the build (Sphinx, the LaTeX run) in this process group and wait for it.

    Its stdout is relayed less jupyter-book's banners; it dies with this process (Linux); the
    wait is a loop of short waits, so that an interrupt is acted on at once.
    """
    proc = subprocess.Popen(
        cmd, cwd=cwd, env=env, preexec_fn=_sphinx_preexec, stdout=subprocess.PIPE, text=True, errors="replace"
    )
    relay = threading.Thread(target=_relay_quietly, args=(proc.stdout,), daemon=True)
    relay.start()
    while True:
        try:
            code = proc.wait(timeout=0.25)
            break
        except subprocess.TimeoutExpired:
            continue
    relay.join(5)
    if not relay.is_alive() and proc.stdout is not None:
        proc.stdout.close()  # the relay has read it to its end
    return code


def latex_to_pdf(out: Path) -> int:
    """Typeset ``<out>/_build/latex`` into ``book.pdf`` (Sphinx's Makefile: latexmk, XeLaTeX), quietly.

    latexmk runs silent (XeLaTeX in batch mode); on failure the errors of the LaTeX log are
    printed, each with the two lines after it.
    """
    latex = out / "_build" / "latex"
    print(f"latex: typesetting {latex / 'book.tex'}", flush=True)
    env = dict(os.environ, LATEXMKOPTS=os.environ.get("LATEXMKOPTS", "-silent"))
    code = _run_quietly([os.environ.get("MAKE", "make"), "all-pdf"], latex, env)
    if code != 0:
        for log in sorted(latex.glob("*.log")):
            lines = log.read_text(errors="replace").splitlines()
            for n, line in enumerate(lines):
                if line.startswith("! "):
                    print(f"{log.name}:", *lines[n : n + 3], sep="\n    ", flush=True)
    print(f"latex: {'done' if code == 0 else f'FAILED (exit {code})'}", flush=True)
    return code


def build(
    builder: str = "html",
    only: str | None = None,
    out: Path | None = None,
    cache: bool = False,
    jobs: int | None = None,
    book: Path = ROOT / "book",
    config_file: Path = ROOT / "_config.yml",
    execute_only: bool = False,
) -> int:
    """Execute what the cache lacks (``cache``), then run Sphinx; ``pdflatex``: then typeset the PDF."""
    config = cached_config(config_file) if cache else config_file
    toc = book / "_toc.yml"
    tmp = None
    if only:
        if only not in PARTS:
            raise SystemExit(f"--only must be one of {list(PARTS)}, got {only!r}")
        # the subset toc must sit in book/ so that relative file names resolve
        tmp = tempfile.NamedTemporaryFile(
            "w", suffix=".yml", prefix=SUBSET_TOC_PREFIX, dir=book, delete=False
        )
        tmp.write(subset_toc(only, book))
        tmp.close()
        toc = Path(tmp.name)
        out = out or ROOT / "_build" / f"subset-{only}"
    out = out or ROOT
    sphinx_config = subset_config(config, out / "_build") if only else config
    try:
        if cache:
            import yaml

            cache_path = Path(yaml.safe_load(config.read_text())["execute"]["cache"])
            times = prefill(cache_path, toc_pages(toc, book), jobs or default_jobs(), book=book)
            if times:
                report_times(times, out / "_build" / "page-times.json")
        if execute_only:
            return 0
        # every build starts from empty output and doctree folders (the execution cache is kept):
        # Sphinx stamps asset links with checksums of files a previous build left and merges the
        # previous search index, so a rebuild would differ from a clean build of the same commit
        for stale in (out / "_build" / builder_dir(builder), out / "_build" / ".doctrees"):
            shutil.rmtree(stale, ignore_errors=True)
        sphinx_builder = "latex" if builder == "pdflatex" else builder  # the PDF: latex_to_pdf
        cmd = [
            str(Path(sys.executable).with_name("jupyter-book")), "build", str(book),
            "--config", str(sphinx_config), "--toc", str(toc), "--path-output", str(out),
            "--builder", sphinx_builder, "--all", "-W", "-n", "--keep-going", "-q",
        ]  # fmt: skip
        print(
            f"sphinx: {sphinx_builder} build of {toc.relative_to(book.parent)} into {out / '_build'}",
            flush=True,
        )
        code = _run_quietly(cmd, ROOT)
        print(
            f"sphinx: {'done' if code == 0 else f'FAILED (exit {code}): see the messages above'}", flush=True
        )
        if code == 0 and builder == "pdflatex":
            code = latex_to_pdf(out)
        return code
    finally:
        if tmp is not None:
            Path(tmp.name).unlink(missing_ok=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--builder", default="html", choices=["html", "pdflatex", "latex", "linkcheck"])
    parser.add_argument(
        "--only",
        default=None,
        help="build one paper's chapter (wf, sp, atc10, kzl), the API reference (reference) "
        "or the verification reports (reports)",
    )
    parser.add_argument("--out", type=Path, default=None, help="output folder (default: the repository)")
    parser.add_argument("--cache", action="store_true", help="execute through a jupyter-cache (see above)")
    parser.add_argument(
        "--jobs",
        type=int,
        default=None,
        help="with --cache: chapters executed at once (default: one more than the cores)",
    )
    parser.add_argument(
        "--execute-only", action="store_true", help="with --cache: execute what the cache lacks, no Sphinx"
    )
    parser.add_argument(
        "--latex-to-pdf",
        action="store_true",
        help="only typeset the LaTeX sources of an earlier --builder latex build into book.pdf",
    )
    # the tests' toy books
    parser.add_argument("--book", type=Path, default=ROOT / "book", help=argparse.SUPPRESS)
    parser.add_argument("--config", type=Path, default=ROOT / "_config.yml", help=argparse.SUPPRESS)
    args = parser.parse_args()
    _INTERRUPTS.install()
    if os.environ.get("NAVCORE_STOP_WITH_PARENT"):  # nox sets it: a killed nox stops the build
        _set_parent_death_signal()
    try:
        if args.latex_to_pdf:
            return latex_to_pdf(args.out or ROOT)
        book, config = args.book.resolve(), args.config.resolve()
        return build(
            args.builder, args.only, args.out, args.cache, args.jobs, book, config, args.execute_only
        )
    except BaseException as exc:
        # stop everything this build started, whatever stopped it; a second Ctrl-C cannot cut it short
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        stopped = stop_started()
        if not isinstance(exc, KeyboardInterrupt):
            raise
        print(f"build_book: interrupted; stopped {stopped} processes it started", file=sys.stderr, flush=True)
        sys.stdout.flush()
        os._exit(130)  # not sys.exit: nothing may wait on a worker that is gone


if __name__ == "__main__":
    raise SystemExit(main())
