"""Build the book, or a subset of it, strictly.

Usage::

    python tools/build_book.py                 # whole book, HTML, into _build/html
    python tools/build_book.py --builder pdflatex
    python tools/build_book.py --only wf       # intro + the WF chapter + ledger/errata pages,
                                               # into _build/subset-wf (fast check of one chapter)

``--cache`` executes through a jupyter-cache whose folder is keyed by a hash of navcore's
sources, the lock file, the execution settings of ``_config.yml`` and this tool: on a clean
checkout every notebook is executed (as with ``force``), and a second build with the same
code (the PDF after the HTML, or a rebuild after editing one chapter) re-executes only the
notebooks whose text changed. Any change to navcore changes the key, so results are never stale.

With ``--cache`` the notebooks that the cache lacks are executed *before* Sphinx runs,
``--jobs`` at a time (default: the number of cores), each in its own kernel exactly as
MyST-NB would execute it (same reader, same working directory, same executor), and stored in
the cache; Sphinx then finds every notebook there. The ledger's on-disk evaluation cache is
filled first, one paper per worker, so that the pages' claims tables, the ledger page and the
errata page read the same evaluations instead of recomputing them. A notebook that fails
is not stored, so Sphinx executes it again and the strict build fails with its traceback.
The execution time of every page and chapter is printed and written to
``<out>/_build/page-times.json``.

The build is strict: forced execution, a failing cell fails it (``nb_execution_raise_on_error``),
and ``-W -n --keep-going`` turns warnings, broken references and missing citations into errors.
Paths are absolute because ``jupyter-book build .`` breaks singlehtml and walks ``.nox/``.
"""

from __future__ import annotations

import argparse
import fnmatch
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PARTS = {
    "wf": "Wu & Fowler",
    "sp": "Schmidt & Phillips",
    "atc10": "ATC-10",
    "kzl": "Knedlik, Zhou & Loffeld",
    "reference": "Reference",
}

REFERENCE_PAGES = (
    "units",
    "frames",
    "gravity",
    "estimation",
    "inertial",
    "gnss",
    "detection",
    "location",
    "ledger",
)
HOWTO_PAGES = ("dop", "outage", "kalman", "frames", "detection", "emitter")


def subset_toc(paper: str) -> str:
    if paper == "reference":  # the how-to guides (executed) and the API reference
        howto = "".join(f"          - file: reference/howto/{name}\n" for name in HOWTO_PAGES)
        pages = "".join(f"      - file: reference/{name}\n" for name in REFERENCE_PAGES)
        return (
            "format: jb-book\nroot: reference/index\nparts:\n"
            "  - caption: Reference\n    chapters:\n"
            "      - file: reference/howto/index\n        sections:\n" + howto + pages
        )
    return (
        "format: jb-book\nroot: intro\nparts:\n"
        "  - caption: Introduction\n    chapters:\n      - file: about\n"
        f"  - caption: {PARTS[paper]}\n    chapters:\n      - file: {paper}/index\n"
        f"        sections:\n          - glob: {paper}/[0-9]*\n"
        "  - caption: Verification\n    chapters:\n      - file: ledger\n      - file: errata\n"
        "      - file: bibliography\n"
    )


# configuration that only changes how executed pages are rendered (LaTeX, HTML theme,
# bibliography, numbering): a change there re-renders the book without re-executing it
_RENDER_ONLY = {"title", "author", "copyright", "logo", "latex", "html", "bibtex_bibfiles", "launch_buttons"}
_RENDER_ONLY_SPHINX = ("latex_", "html_", "bibtex_", "numfig", "math_", "suppress_warnings")


def _execution_config() -> str:
    """The part of _config.yml that can change what a notebook's execution produces."""
    import yaml

    config = yaml.safe_load((ROOT / "_config.yml").read_text())
    config = {k: v for k, v in config.items() if k not in _RENDER_ONLY}
    sphinx = dict(config.get("sphinx") or {})
    sphinx["config"] = {
        k: v for k, v in (sphinx.get("config") or {}).items() if not k.startswith(_RENDER_ONLY_SPHINX)
    }
    sphinx.pop("local_extensions", None)  # Sphinx extensions render; they never execute cells
    config["sphinx"] = sphinx
    return json.dumps(config, sort_keys=True, default=str)


def source_key() -> str:
    """Hash of everything besides a notebook's own text that can change its outputs.

    navcore's sources, the lock, the execution-relevant part of ``_config.yml`` and this
    file (which executes the notebooks); not the Sphinx extensions or the rendering settings.
    """
    h = hashlib.sha256()
    files = [*sorted((ROOT / "navcore").rglob("*.py")), ROOT / "requirements" / "lock.txt"]
    files.append(Path(__file__).resolve())
    for f in files:
        if f.exists():
            h.update(str(f.relative_to(ROOT)).encode())
            h.update(f.read_bytes())
    h.update(_execution_config().encode())
    return h.hexdigest()[:16]


def cached_config() -> Path:
    """A copy of _config.yml that executes through a source-keyed jupyter-cache."""
    import yaml

    config = yaml.safe_load((ROOT / "_config.yml").read_text())
    config["execute"]["execute_notebooks"] = "cache"
    # NAVCORE_BOOK_CACHE chooses another parent folder (the benchmark's clean build does)
    parent = Path(os.environ.get("NAVCORE_BOOK_CACHE") or ROOT / "_build" / "jupyter_cache")
    config["execute"]["cache"] = str(parent / source_key())
    # local extension folders are relative to the config file, which moves to _build/
    local = config.get("sphinx", {}).get("local_extensions") or {}
    for name, folder in local.items():
        local[name] = str(ROOT / folder)
    path = parent / "_config_cached.yml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(yaml.safe_dump(config, sort_keys=False))
    return path


def toc_pages(toc: Path) -> list[Path]:
    """The book pages a toc names, globs resolved, in toc order."""
    import yaml

    book = ROOT / "book"
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


# --- stopping a build -------------------------------------------------------------------------
# Ctrl-C (SIGINT to the process group) or SIGTERM stops every process a build started within
# seconds: the parent terminates its workers and the Sphinx subprocess; each worker kills its
# kernel and exits (a pool worker would otherwise treat KeyboardInterrupt as one task's result
# and go on with the next task); a worker whose parent dies gets SIGTERM from the kernel
# (Linux parent-death signal). The parent stores executed notebooks with both signals blocked,
# so an interrupt never leaves a half-written cache entry.

_KERNEL_PIDS: set[int] = set()


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


def _worker_stop(signum: int, frame: object) -> None:
    for pid in list(_KERNEL_PIDS):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    os._exit(128 + signum)


def _worker_init() -> None:
    """Pool initializer: die with the parent, and on SIGINT/SIGTERM kill the kernel and exit."""
    _set_parent_death_signal()
    signal.signal(signal.SIGINT, _worker_stop)
    signal.signal(signal.SIGTERM, _worker_stop)
    if os.getppid() == 1:  # the parent died before the death signal was armed
        _worker_stop(signal.SIGTERM, None)


def _raise_interrupt(signum: int, frame: object) -> None:
    raise KeyboardInterrupt(f"signal {signum}")


def _stop_pool(pool: ProcessPoolExecutor, grace: float = 5.0) -> None:
    """Terminate the pool's workers (each kills its kernel), then kill any that linger."""
    procs = list((getattr(pool, "_processes", None) or {}).values())
    for proc in procs:
        if proc.is_alive():
            proc.terminate()
    deadline = time.monotonic() + grace
    for proc in procs:
        proc.join(max(0.0, deadline - time.monotonic()))
        if proc.is_alive():
            proc.kill()
            proc.join(1.0)
    pool.shutdown(wait=False, cancel_futures=True)


_RESET = """\
%reset -f
import os as _os
import matplotlib.pyplot as _plt
_plt.close("all")
_os.chdir({cwd!r})
del _os, _plt
"""


def _merge_streams(nb) -> None:
    """One stream output per name and cell, the chunks joined exactly as they were written.

    The kernel sends a cell's printed text in chunks whose boundaries depend on timing, and
    MyST-NB joins stored chunks with a newline after stripping each; merging them here first
    makes the stored and rendered output the same on every run.
    """
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        merged, first = [], {}
        for out in cell.get("outputs", []):
            if out.get("output_type") == "stream":
                if out["name"] in first:
                    first[out["name"]]["text"] += out["text"]
                    continue
                first[out["name"]] = out
            merged.append(out)
        cell.outputs = merged


def _execute_group(
    paper: str | None, paths: list[str], timeout: int
) -> list[tuple[str, float, object, str | None]]:
    """Execute a chapter's pages one after another in ONE kernel (in a worker process).

    The kernel first evaluates the chapter's ledger claims (filling the on-disk evaluation
    cache that the ledger and errata pages read); then, before each page, the user namespace
    is reset (``%reset -f``), open figures are closed and the working directory is set to the
    page's folder, so a page sees none of the previous page's variables. What carries over
    is what Python keeps per process: imported modules and navcore's pure-function caches
    (``functools.cache``), which is what makes a chapter's pages cheaper together than apart.
    ``tools/bench.py`` executes every page alone in a fresh kernel, as a reader would.
    """
    import nbformat
    from jupyter_client.manager import KernelManager
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    km = KernelManager(kernel_name="python3")
    km.start_kernel(cwd=str(ROOT / "book"))
    kernel_pid = getattr(km.provisioner, "pid", None)
    if kernel_pid:
        _KERNEL_PIDS.add(kernel_pid)
    kc = None
    results = []

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

    try:
        if paper is not None:
            start = time.perf_counter()
            warm = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(
                f"from navcore import ledger\n_ = ledger.evaluations({paper!r})\ndel _, ledger"
            )])  # fmt: skip
            warm.metadata["kernelspec"] = {
                "name": "python3",
                "display_name": "Python 3",
                "language": "python",
            }
            run(warm, str(ROOT / "book"))
            results.append((f"(ledger {paper})", time.perf_counter() - start, None, None))
        for path_str in paths:
            path = Path(path_str)
            nb = _read_notebook(path)
            start = time.perf_counter()
            err = None
            try:
                reset = nbformat.v4.new_notebook(
                    cells=[nbformat.v4.new_code_cell(_RESET.format(cwd=str(path.parent)))]
                )
                reset.metadata["kernelspec"] = nb.metadata.get("kernelspec", {})
                run(reset, str(path.parent))
                run(nb, str(path.parent))
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
            results.append((path_str, time.perf_counter() - start, nb, err))
    finally:
        if kc is not None:
            kc.stop_channels()
        km.shutdown_kernel(now=True)
        _KERNEL_PIDS.discard(kernel_pid)
    return results


def _group_pages(
    pages: list[Path], book: Path = ROOT / "book"
) -> tuple[list[tuple[str | None, list[str]]], list[str]]:
    """Split pages into one group per chapter folder and the front and back matter."""
    chapters: dict[str, list[str]] = {}
    other: list[str] = []
    for page in pages:
        rel = page.relative_to(book)
        if len(rel.parts) > 1:
            chapters.setdefault(rel.parts[0], []).append(str(page))
        else:
            other.append(str(page))
    # the biggest chapters first, so that two workers finish at about the same time
    groups = sorted(chapters.items(), key=lambda item: -len(item[1]))
    return [(name.upper(), paths) for name, paths in groups], other


def prefill(
    cache_path: Path, pages: list[Path], jobs: int, timeout: int = 900, book: Path = ROOT / "book"
) -> dict[str, float]:
    """Execute the pages missing from the jupyter-cache, ``jobs`` chapters at a time, and store them.

    An interrupt (SIGINT, or SIGTERM, which raises KeyboardInterrupt here) stops the workers
    and their kernels and re-raises; what was stored before it stays valid.
    """
    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn

    cache = get_cache(str(cache_path))
    todo = []
    for page in pages:
        if not _is_notebook(page):
            continue
        try:
            cache.match_cache_notebook(_read_notebook(page))
        except KeyError:
            todo.append(page)
    times: dict[str, float] = {}
    if not todo:
        print(f"prefill: all {len(pages)} pages are in the cache", flush=True)
        return times
    groups, other = _group_pages(todo, book)
    papers = {"WF", "SP", "ATC10", "KZL"}
    jobs = max(1, min(jobs, len(groups) or 1))
    start = time.perf_counter()

    def store(results) -> None:
        for path_str, seconds, nb, err in results:
            if nb is None:
                times[path_str] = seconds
                print(f"prefill: {seconds:7.1f} s  {path_str}", flush=True)
                continue
            rel = Path(path_str).relative_to(book).as_posix()
            if err is not None:
                print(f"prefill: {rel} FAILED ({err.splitlines()[0]}); Sphinx will re-run it", flush=True)
                continue
            times[rel] = seconds
            # no interrupt between the cache's database record and its notebook file
            blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
            try:
                cache.cache_notebook_bundle(
                    CacheBundleIn(nb, path_str, data={"execution_seconds": seconds}),
                    check_validity=False,
                    overwrite=True,
                )
            finally:
                signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
            print(f"prefill: {seconds:7.1f} s  {rel}", flush=True)

    previous = signal.signal(signal.SIGTERM, _raise_interrupt)
    pool = ProcessPoolExecutor(max_workers=jobs, initializer=_worker_init)
    try:
        futures = [
            pool.submit(_execute_group, name if name in papers else None, paths, timeout)
            for name, paths in groups
        ]
        for fut in as_completed(futures):
            store(fut.result())
        # the front and back matter (intro, about, ledger, errata) read every paper's claims:
        # they run last, from the evaluation cache that the chapters filled
        if other:
            store(pool.submit(_execute_group, None, other, timeout).result())
    except BaseException:
        print("prefill: interrupted; stopping the workers and their kernels", flush=True)
        _stop_pool(pool)
        raise
    else:
        pool.shutdown(wait=True)
    finally:
        signal.signal(signal.SIGTERM, previous)
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


def build(
    builder: str = "html",
    only: str | None = None,
    out: Path | None = None,
    cache: bool = False,
    jobs: int | None = None,
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
    # every build starts from empty output and doctree folders (the execution cache is kept):
    # Sphinx stamps asset links with checksums of files a previous build left and merges the
    # previous search index, so a rebuild would differ from a clean build of the same commit
    for stale in (out / "_build" / builder_dir(builder), out / "_build" / ".doctrees"):
        shutil.rmtree(stale, ignore_errors=True)
    if cache:
        import yaml

        cache_path = Path(yaml.safe_load(config.read_text())["execute"]["cache"])
        times = prefill(cache_path, toc_pages(toc), jobs or os.cpu_count() or 1)
        if times:
            report_times(times, out / "_build" / "page-times.json")
    cmd = [
        str(Path(sys.executable).with_name("jupyter-book")), "build", str(ROOT / "book"),
        "--config", str(config), "--toc", str(toc), "--path-output", str(out),
        "--builder", builder, "--all", "-W", "-n", "--keep-going",
    ]  # fmt: skip
    print("+", " ".join(cmd), flush=True)
    previous = signal.signal(signal.SIGTERM, _raise_interrupt)
    proc = subprocess.Popen(cmd, cwd=ROOT)
    try:
        return proc.wait()
    except BaseException:  # SIGINT or SIGTERM: stop Sphinx (and its kernels) too
        proc.terminate()
        try:
            proc.wait(5)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        raise
    finally:
        signal.signal(signal.SIGTERM, previous)
        if tmp is not None:
            Path(tmp.name).unlink(missing_ok=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--builder", default="html", choices=["html", "pdflatex", "latex", "linkcheck"])
    parser.add_argument(
        "--only",
        default=None,
        help="build one paper's chapter (wf, sp, atc10, kzl) or the API reference (reference)",
    )
    parser.add_argument("--out", type=Path, default=None, help="output folder (default: the repository)")
    parser.add_argument("--cache", action="store_true", help="execute through a source-keyed jupyter-cache")
    parser.add_argument(
        "--jobs", type=int, default=None, help="with --cache: pages executed at once (default: the cores)"
    )
    args = parser.parse_args()
    if os.environ.get("NAVCORE_STOP_WITH_PARENT"):  # nox sets it: a killed nox stops the build
        _set_parent_death_signal()
    try:
        return build(args.builder, args.only, args.out, args.cache, args.jobs)
    except KeyboardInterrupt:
        print("build_book: interrupted", file=sys.stderr, flush=True)
        return 130


if __name__ == "__main__":
    raise SystemExit(main())
