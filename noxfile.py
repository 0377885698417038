"""nox sessions: tests, book (HTML), pdf, reports, figures, lint, ledger, bench, mutation, inputs, layout.

Every session installs the full stack from ``requirements/lock.txt`` (a committed
``uv pip compile --generate-hashes`` lock), with every distribution's hash required, then
navcore itself without dependencies, so that a build next year computes the same numbers
from the same bytes. uv is the virtual-environment backend, with virtualenv as the
fallback.

    python3 -m pip install "nox[uv]" && nox -s tests     # the test command
    python3 -m pip install "nox[uv]" && nox -s book pdf   # the book, HTML and PDF
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import nox

ROOT = Path(__file__).resolve().parent
LOCK = ROOT / "requirements" / "lock.txt"
TEX_PACKAGES = [
    "texlive-latex-recommended",
    "texlive-latex-extra",
    "texlive-fonts-recommended",
    "texlive-xetex",
    "latexmk",
    "fonts-freefont-otf",
    "make",  # Sphinx's LaTeX Makefile runs latexmk
]

nox.options.default_venv_backend = "uv|virtualenv"
nox.options.sessions = ["lint", "tests", "book"]
nox.options.reuse_existing_virtualenvs = True
# uv must trust the system certificate store behind this network's TLS proxy
os.environ.setdefault("UV_SYSTEM_CERTS", "1")
# deterministic figures and hashing in every subprocess
os.environ.setdefault("PYTHONHASHSEED", "0")
os.environ.setdefault("SOURCE_DATE_EPOCH", "1767225600")
os.environ.setdefault("FORCE_SOURCE_DATE", "1")  # TeX: dates from SOURCE_DATE_EPOCH too
# a book build started by nox stops when nox is stopped or killed (tools/build_book.py)
os.environ.setdefault("NAVCORE_STOP_WITH_PARENT", "1")
HTML = ROOT / "_build" / "html"


def _install(session: nox.Session) -> None:
    """The locked stack, every distribution checked against its hash; then navcore itself.

    An editable install cannot be hash-checked, so navcore goes in separately, without
    dependencies and built with the locked (hash-checked) build backend already installed.
    """
    session.install("--require-hashes", "-r", str(LOCK))
    session.install("--no-deps", "--no-build-isolation", "-e", ".")


@nox.session
def tests(session: nox.Session) -> None:
    """Run pytest: unit tests against oracles, one test per ledger claim, figures, strict build.

    The whole suite runs on every core (pytest-xdist, ``-n auto``: two workers on CI's two
    cores; ``--dist loadgroup`` keeps the claims of one paper module, which share their model
    runs, on one worker) and prints its 25 slowest tests, so that CI's log says where its time
    goes; ``nox -s tests -- ARGS`` passes ARGS to pytest instead (one process unless ARGS ask
    for workers).
    """
    _install(session)
    args = session.posargs or ["-q", "-n", "auto", "--dist", "loadgroup", "--durations=25"]
    session.run("python", "-m", "pytest", *args, env=ONE_BLAS_THREAD)


# a build stopped by Ctrl-C stops its workers, kernels, Sphinx and LaTeX itself (within seconds):
# nox waits for that instead of killing it after half a second
STOPPABLE = {"interrupt_timeout": 20.0, "terminate_timeout": 10.0}

# The ledger and the tests run in parallel processes, one per core: a BLAS that also starts a
# thread per core oversubscribes them (one 168x42 by 42x135 product of the SP engine took 23 ms
# on two threads beside the other process, 0.07 ms on one)
ONE_BLAS_THREAD = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


def _requested(session: nox.Session) -> list[str]:
    """The sessions named on the command line (``nox -s book pdf``: both); [] if unknown."""
    try:
        return list(session._runner.global_config.sessions or [])
    except AttributeError:  # pragma: no cover - another nox
        return []


@nox.session
def book(session: nox.Session) -> None:
    """Build the HTML book strictly (-W -n, failing cells fail) into _build/html; check its links.

    Notebooks execute through a cache in which each page is keyed on the navcore modules and
    data files it imports (see tools/build_book.py): on a clean checkout everything executes,
    after a change only the pages that depend on it, and the PDF build reuses the results.
    With ``nox -s book pdf`` the HTML is built once, by the pdf session, after the PDF (so that
    it links it).
    """
    _install(session)
    if "pdf" in _requested(session):
        session.log("the pdf session builds the HTML book after the PDF, so that it links the PDF")
        return
    _build_html(session)


def _build_html(session: nox.Session) -> None:
    # the pages' source first (no build needed): no code cell a reader sees runs a build helper
    session.run("python", "tools/check_book.py", "pages", "book")
    session.run(
        "python", "tools/build_book.py", "--builder", "html", "--cache", *session.posargs, **STOPPABLE
    )  # fmt: skip
    # release gates: every internal link and anchor resolves; no code cell shows a build
    # helper; every downloadable notebook carries its outputs
    session.run("python", "tools/check_links.py", str(HTML))
    session.run("python", "tools/check_book.py", "html", str(HTML))
    session.log(f"HTML book: {HTML / 'index.html'}")


def _tex_missing() -> bool:
    if any(shutil.which(tool) is None for tool in ("xelatex", "latexmk", "make")):
        return True
    if shutil.which("fc-list") is None:
        return True
    return not subprocess.run(["fc-list", "FreeSerif"], capture_output=True, text=True).stdout.strip()


def _start_tex(session: nox.Session) -> subprocess.Popen | None:
    """Start installing TeX in the background (root, Debian), or fail early with the command.

    The install (about two minutes on a bare machine, mostly download and unpacking) runs while
    the Python environment installs and the notebooks execute; the LaTeX run waits for it.
    """
    if not _tex_missing():
        return None
    command = ["apt-get", "install", "-y", "--no-install-recommends", *TEX_PACKAGES]
    if not (hasattr(os, "geteuid") and os.geteuid() == 0 and shutil.which("apt-get")):
        session.error(
            "The PDF book needs XeLaTeX, latexmk, make and the FreeFont fonts. Install them with:\n"
            f"    sudo {' '.join(command)}"
        )
    session.log("installing the TeX packages for the PDF book with apt-get, in the background")
    log = ROOT / "_build" / "tex-install.log"
    log.parent.mkdir(parents=True, exist_ok=True)
    lock = ["-o", "DPkg::Lock::Timeout=600"]
    script = f"apt-get update -qq && {' '.join([*command[:2], *lock, *command[2:]])} -qq"
    with open(log, "w") as out:
        return subprocess.Popen(
            ["sh", "-c", script], stdout=out, stderr=subprocess.STDOUT,
            env={**os.environ, "DEBIAN_FRONTEND": "noninteractive"},
        )  # fmt: skip


def _wait_tex(session: nox.Session, proc: subprocess.Popen | None) -> None:
    if proc is None:
        return
    start = time.monotonic()
    code = proc.wait()
    log = ROOT / "_build" / "tex-install.log"
    if code != 0 or _tex_missing():
        session.error(f"installing TeX failed (exit {code}):\n{log.read_text()[-3000:]}")
    session.log(f"TeX is installed (waited {time.monotonic() - start:.0f} s for it)")


@nox.session
def pdf(session: nox.Session) -> None:
    """Build the PDF book with XeLaTeX into _build/latex/book.pdf (installs TeX if root).

    TeX installs in the background while the notebooks execute and Sphinx writes the LaTeX
    sources. If an HTML book already exists, or ``nox -s book pdf`` asked for one, the HTML is
    then built from the execution cache so that every page links the PDF.
    """
    tex = _start_tex(session)
    try:
        _install(session)
        pdf_path = ROOT / "_build" / "latex" / "book.pdf"
        pdf_path.unlink(missing_ok=True)
        session.run(
            "python", "tools/build_book.py", "--builder", "latex", "--cache", *session.posargs, **STOPPABLE
        )  # fmt: skip
        _wait_tex(session, tex)
        session.run("python", "tools/build_book.py", "--latex-to-pdf", **STOPPABLE)
    finally:
        if tex is not None and tex.poll() is None:  # stopped early: let apt finish what it unpacks
            tex.wait()
    if not pdf_path.exists():
        session.error(f"the LaTeX build did not produce {pdf_path}")
    # release gate: nothing runs off the page; no code listing shows a build helper
    session.run("python", "tools/check_book.py", "latex", str(pdf_path.parent))
    session.log(f"PDF book: {pdf_path}")
    if "book" in _requested(session):
        _build_html(session)
    elif (HTML / "book.pdf").exists():  # the HTML already links a PDF: give it the new one
        shutil.copy2(pdf_path, HTML / "book.pdf")
    elif (HTML / "index.html").exists():
        session.log("an HTML book exists without the PDF: rebuilding it to link the PDF")
        _build_html(session)


@nox.session
def reports(session: nox.Session) -> None:
    """Write each paper's verification report to _build/reports/<PAPER>.pdf and <PAPER>.md.

    The reports are built from the ledger, read through its on-disk cache
    (``_build/navcore-cache``, which the ledger and book sessions fill), and typeset with
    XeLaTeX strictly: a LaTeX error or an overfull box fails the session. Installs TeX as the
    pdf session does when it is missing (root, Debian).
    """
    tex = _start_tex(session)
    try:
        _install(session)
    finally:
        _wait_tex(session, tex)
    out = ROOT / "_build" / "reports"
    session.run(
        "python", "-c",
        "import sys; from navcore.report import write_reports; "
        "[print(p) for p in write_reports(sys.argv[1], sys.argv[2:] or ('WF', 'SP', 'ATC10', 'KZL'))]",
        str(out), *session.posargs,
    )  # fmt: skip
    session.log(f"verification reports: {out}")


REPRO = ROOT / "_build" / "reproducible"


def _checkout_fingerprint() -> str:
    """A hash of everything a book build reads from the checkout (library, pages, settings, tools)."""
    h = hashlib.sha256()
    files = [ROOT / "_config.yml", LOCK, *sorted((ROOT / "tools").glob("*.py"))]
    for folder in ("navcore", "book"):
        files += sorted(p for p in (ROOT / folder).rglob("*") if p.is_file() and "__pycache__" not in p.parts)
    for f in files:
        if "_toc_subset_" not in f.name:
            h.update(f.relative_to(ROOT).as_posix().encode() + b"\0" + f.read_bytes())
    return h.hexdigest()


def _execution_marker(ledger_from: Path | None) -> str:
    """What ``--execute-only`` records: the checkout, and the stored ledger it started from."""
    return _checkout_fingerprint() + (f"\nledger from {ledger_from}" if ledger_from else "")


def _executed_here(marker: Path, ledger_from: Path | None) -> bool:
    """Whether ``--execute-only`` completed on this very checkout, from the same stored ledger
    (else the clean build executes)."""
    return marker.exists() and marker.read_text() == _execution_marker(ledger_from)


@nox.session
def reproducible(session: nox.Session) -> None:
    """Two clean HTML builds of this commit (executing every page) must be byte-identical.

    Both builds use the same output and cache folders (emptied in between), so that only
    what the build itself does can differ; the first build's HTML is kept aside.

    ``nox -s reproducible -- --against _build/html`` makes one clean build and compares it
    with an existing one (CI passes the book it has just built from a clean checkout, so
    the notebooks execute twice in all, not three times). If that book links the PDF, the
    clean build is given the same PDF to link. ``-- --execute-only`` does the clean build's
    execution alone, with fresh execution and ledger caches in ``_build/reproducible``
    (CI runs it beside the other book build); a later ``--against`` run renders from it.
    ``--ledger-from DIR`` (with either) starts the clean build's ledger cache as a copy of the
    evaluations stored in DIR (CI passes its ledger gate's, ``_build/navcore-cache``): every
    page still executes afresh, but no claim is evaluated a second time; the claims' values
    are then re-evaluated and compared with the gate's by the test suite instead.
    """
    _install(session)
    args = list(session.posargs)
    ledger_from = None
    if "--ledger-from" in args:
        i = args.index("--ledger-from")
        if i + 1 >= len(args) or not (Path(args[i + 1]) / "claims").is_dir():
            session.error("--ledger-from DIR: DIR must hold a stored ledger (nox -s ledger -- --store)")
        ledger_from = Path(args[i + 1]).resolve() / "claims"
        del args[i : i + 2]
    out, cache, ledger_cache = REPRO / "out", REPRO / "cache", REPRO / "navcore-cache"
    # fresh execution and ledger caches, and a fresh temporary folder (the KZL Monte Carlo
    # keeps its runs there): nothing computed by another build is read
    scratch = Path(tempfile.mkdtemp(prefix="navcore-repro-"))
    env = {"NAVCORE_BOOK_CACHE": str(cache), "NAVCORE_CACHE": str(ledger_cache), "TMPDIR": str(scratch)}
    build = ["python", "tools/build_book.py", "--builder", "html", "--cache", "--out", str(out)]
    executed = REPRO / "executed"  # the execution-only run completed
    try:
        _reproducible(session, args, build, env, executed, out, ledger_from)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def _reproducible(
    session: nox.Session,
    args: list[str],
    build: list[str],
    env: dict[str, str],
    executed: Path,
    out: Path,
    ledger_from: Path | None,
) -> None:
    def seed_ledger() -> None:  # the clean build's ledger cache starts as a copy of a stored ledger
        if ledger_from is not None:
            shutil.copytree(ledger_from, Path(env["NAVCORE_CACHE"]) / "claims")

    if args == ["--execute-only"]:
        shutil.rmtree(REPRO, ignore_errors=True)
        seed_ledger()
        session.run(*build, "--execute-only", env=env, **STOPPABLE)
        executed.write_text(_execution_marker(ledger_from))
        return
    against = None
    if args:
        if len(args) != 2 or args[0] != "--against":
            usage = "[-- --against BUILT_HTML_DIR | -- --execute-only] [--ledger-from DIR]"
            session.error(f"usage: nox -s reproducible {usage}")
        against = Path(args[1]).resolve()
        if not (against / "index.html").exists():
            session.error(f"--against {against}: no built HTML book there")
    first = REPRO.with_name("reproducible-first")
    for run in ("first", "second") if against is None else ("second",):
        reuse = run == "second" and against is not None and _executed_here(executed, ledger_from)
        if reuse:
            session.log("rendering the clean execution that --execute-only made of this checkout")
        else:  # fresh execution and ledger caches, and an empty temporary folder
            shutil.rmtree(REPRO, ignore_errors=True)
            shutil.rmtree(env["TMPDIR"], ignore_errors=True)
            Path(env["TMPDIR"]).mkdir()
            seed_ledger()
        shutil.rmtree(out, ignore_errors=True)
        if against is not None and (against / "book.pdf").exists():
            (out / "_build" / "latex").mkdir(parents=True)
            shutil.copy2(against / "book.pdf", out / "_build" / "latex" / "book.pdf")
        session.run(*build, env=env, **STOPPABLE)
        if run == "first":
            shutil.rmtree(first, ignore_errors=True)
            shutil.move(str(out / "_build" / "html"), first)
    reference = first if against is None else against
    session.run("python", "tools/check_book.py", "same", str(reference), str(out / "_build" / "html"))


@nox.session
def figures(session: nox.Session) -> None:
    """Write every registered figure to figures/ as SVG and PNG."""
    _install(session)
    session.run("python", "-m", "navcore", "figures", "--out", "figures", *session.posargs)


@nox.session
def lint(session: nox.Session) -> None:
    """ruff check, ruff format --check, and mypy type-checking navcore (pyproject.toml [tool.mypy])."""
    _install(session)  # mypy reads numpy's and matplotlib's own type information
    session.run("ruff", "check", "navcore", "tests", "tools", "book/_ext", "noxfile.py")
    session.run("ruff", "format", "--check", "navcore", "tests", "tools", "book/_ext", "noxfile.py")
    session.run("mypy")


@nox.session
def ledger(session: nox.Session) -> None:
    """Print the ledger and write _build/ledger.json; fails if any claim fails its check.

    Every claim is computed afresh (the on-disk evaluation cache is off), so two runs of this
    session are an honest determinism check. ``nox -s ledger -- --twice`` is that check in
    one session: two fresh processes evaluate the ledger side by side, one in itself and one
    on two workers, and their JSON exports must be byte-identical (tools/ledger_twice.py); the
    first stores its evaluations in the cache (without reading it). ``nox -s ledger --
    --store`` (CI's gate) makes one fresh evaluation on every core and stores it the same
    way, so that the book built next, and the tests (``.ci/run`` runs this gate first), do
    not evaluate the ledger again; CI's determinism check of the ledger is then the test
    suite, which evaluates every claim's value again in its own processes and compares it bit
    for bit with what this gate stored (``--twice`` also compares the bands). Claims are
    evaluated under the test suite's numerical rules (``NAVCORE_LEDGER_STRICT=1``:
    floating-point errors raise, warnings are errors), so that the tests may read what the
    gate stored.
    """
    _install(session)
    env = {
        "NAVCORE_CACHE": "off",
        "NAVCORE_NO_DISK_CACHE": "1",
        "NAVCORE_LEDGER_STRICT": "1",
        **ONE_BLAS_THREAD,
    }
    out = ROOT / "_build" / "ledger.json"
    args = list(session.posargs)
    if "--twice" in args:
        args.remove("--twice")
        # both runs evaluate afresh; the first also stores its evaluations for the book and the tests
        twice_env = {"NAVCORE_NO_DISK_CACHE": "1", "NAVCORE_LEDGER_STRICT": "1", **ONE_BLAS_THREAD}
        session.run("python", "tools/ledger_twice.py", str(out), *args, env=twice_env)
    elif "--store" in args:
        args.remove("--store")
        # afresh on every core, never reading the cache, storing every evaluation in it
        store_env = {**env, "NAVCORE_CACHE": "", "NAVCORE_CACHE_REFRESH": "1"}
        ledger = ["python", "-m", "navcore", "ledger", "--jobs", "-1", "--times", "--json-out", str(out)]
        session.run(*ledger, *args, env=store_env)
    else:
        session.run("python", "-m", "navcore", "ledger", "--json-out", str(out), *args, env=env)
    session.log(f"ledger JSON: {out}")


@nox.session
def bench(session: nox.Session) -> None:
    """Clean full HTML build, each chapter's execution, the floor, and the library; write _build/bench.md.

    The library numbers: the Kalman filter step against filterpy's (a ratio from one run) and
    the covariance-analysis engine on a 104-minute mission. ``nox -s bench -- --library-only``
    measures only those; ``-- --build-only`` only the builds (clean, incremental after a comment
    in ``--touch MODULE``, floor); ``-- --ledger-from _build/navcore-cache`` starts the clean
    build from a stored ledger; ``-- --standalone --models`` also times every page alone in a
    fresh kernel and every paper's ledger and figure in a fresh process.
    """
    _install(session)
    session.run("python", "tools/bench.py", *session.posargs)


@nox.session
def inputs(session: nox.Session) -> None:
    """The input gate: every number that moves a claim must be a declared input (tools/input_gate.py).

    Traces which lines each claim runs, perturbs every numeric literal, module constant and
    default they run, and flags those that move a claim (by more than a tenth of its tolerance
    for a 10 % change, or flip a statement) while none of its recorded inputs changes. Writes
    ``_build/input_gate.json`` and ``_build/input_gate.md``; fails on a flagged number the
    allowlist (``tools/input_gate_allowlist.toml``) does not excuse. ``-- --paper WF``,
    ``--claim PREFIX``, ``--module NAME``, ``--sample N --seed S`` select; the whole ledger takes
    about 45 minutes of one core (WF 2, KZL 5, SP 11, ATC-10 27, measured one paper at a time
    with ``--jobs 1`` on a shared machine). A developer's session: ``.ci/run`` does not run it.
    """
    _install(session)
    session.run("python", "tools/input_gate.py", *session.posargs)


@nox.session
def layout(session: nox.Session) -> None:
    """The layout gate on a built HTML book, measured in headless Chromium (tools/check_layout.py).

    Loads every page at 1400 px and 420 px once MathJax has typeset it and fails on a display
    equation cut by its box, an output table wider than the text column or a cell of a
    fixed-width table (the ledger's) whose content runs past it, unless the item is
    in ``tools/layout_allowlist.json`` with its reason; an entry that no longer
    overflows fails too, so the list only shrinks. Builds the HTML book first (from the
    execution cache) unless ``_build/html`` exists; ``-- --list`` prints every overflow,
    ``-- --width 420`` measures one width, ``-- --tabs N`` sets how many pages load at once.
    Needs Chromium (installed with apt-get when run as root) and about two minutes on two
    busy cores (26 s of CPU); ``.ci/run`` runs it on the book it has built.
    """
    _install(session)
    if not (HTML / "index.html").exists():
        _build_html(session)
    session.run("python", "tools/check_layout.py", str(HTML), *session.posargs)


@nox.session
def mutation(session: nox.Session) -> None:
    """Mutation testing (mutmut) of navcore's packages, the tools and the book's extensions;
    writes _build/mutation.md.

    ``nox -s mutation`` runs the model packages (estimation, inertial, gnss, integration,
    detection, location, frames), then the ledger, units and validation, figures, the paper modules'
    functions, the tools and the book's extensions, one after another, each in its own scratch
    copy under ``_build/mutation/`` with only the test files that exercise it
    (tools/mutation.py); ``nox -s mutation -- gnss frames`` runs some,
    ``-- --budget-min 20`` bounds each package's wall-clock time (default 30 min on 2 cores),
    ``-- --report-only`` tabulates the last runs, ``-- papers --sample 300 --seed 0`` runs a seeded
    random sample of a package's mutants and reports its score with a 95 % interval. A developer's
    session: ``.ci/run`` does not run it. Equivalent mutants are documented in
    ``tests/mutation_equivalents.md``.
    """
    _install(session)
    session.run("python", "tools/mutation.py", *session.posargs)


if __name__ == "__main__":  # pragma: no cover - convenience
    sys.exit(subprocess.call(["nox", *sys.argv[1:]], cwd=ROOT))
