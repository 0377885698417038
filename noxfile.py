"""nox sessions: tests, book (HTML), pdf, figures, lint, ledger, bench, mutation, inputs.

Every session installs the full stack from ``requirements/lock.txt`` (a committed
``uv pip compile`` lock), then navcore itself without dependencies, so that a build next year
computes the same numbers. uv is the virtual-environment backend, with virtualenv as the
fallback.

    python3 -m pip install "nox[uv]" && nox -s tests     # the test command
    python3 -m pip install "nox[uv]" && nox -s book pdf   # the book, HTML and PDF
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
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
    session.install("-r", str(LOCK))
    session.install("--no-deps", "-e", ".")


@nox.session
def tests(session: nox.Session) -> None:
    """Run pytest: unit tests against oracles, one test per ledger claim, figures, strict build.

    The whole suite runs on every core (pytest-xdist, ``-n auto``: two workers on CI's two
    cores); ``nox -s tests -- ARGS`` passes ARGS to pytest instead (one process unless ARGS
    ask for workers).
    """
    _install(session)
    session.run("python", "-m", "pytest", *(session.posargs or ["-q", "-n", "auto"]))


@nox.session
def book(session: nox.Session) -> None:
    """Build the HTML book strictly (-W -n, failing cells fail) into _build/html; check its links.

    Notebooks execute through a cache keyed by navcore's sources (see tools/build_book.py),
    so on a clean checkout everything executes and the PDF build reuses the results.
    """
    _install(session)
    _build_html(session)


def _build_html(session: nox.Session) -> None:
    session.run("python", "tools/build_book.py", "--builder", "html", "--cache", *session.posargs)
    # release gates: every internal link and anchor resolves; no code cell shows a build
    # helper; every downloadable notebook carries its outputs
    session.run("python", "tools/check_links.py", str(HTML))
    session.run("python", "tools/check_book.py", "html", str(HTML))
    session.log(f"HTML book: {HTML / 'index.html'}")


def _ensure_tex(session: nox.Session) -> None:
    missing = [tool for tool in ("xelatex", "latexmk") if shutil.which(tool) is None]
    fonts = (
        subprocess.run(["fc-list", "FreeSerif"], capture_output=True, text=True).stdout
        if shutil.which("fc-list")
        else ""
    )
    if not missing and fonts.strip():
        return
    command = ["apt-get", "install", "-y", "--no-install-recommends", *TEX_PACKAGES]
    if hasattr(os, "geteuid") and os.geteuid() == 0 and shutil.which("apt-get"):
        session.log("installing the TeX packages for the PDF book with apt-get")
        env = {"DEBIAN_FRONTEND": "noninteractive"}
        session.run("apt-get", "update", "-qq", external=True, env=env)
        session.run(*command, "-qq", external=True, env=env)
    else:
        session.error(
            "The PDF book needs XeLaTeX, latexmk and the FreeFont fonts. Install them with:\n"
            f"    sudo {' '.join(command)}"
        )


@nox.session
def pdf(session: nox.Session) -> None:
    """Build the PDF book with XeLaTeX into _build/latex/book.pdf (installs TeX if root).

    If an HTML book already exists (``nox -s book pdf`` builds it first), it is rebuilt from
    the execution cache so that every page links the PDF, whatever the order of the sessions.
    """
    _ensure_tex(session)
    _install(session)
    pdf_path = ROOT / "_build" / "latex" / "book.pdf"
    pdf_path.unlink(missing_ok=True)
    session.run("python", "tools/build_book.py", "--builder", "pdflatex", "--cache", *session.posargs)
    if not pdf_path.exists():
        session.error(f"the LaTeX build did not produce {pdf_path}")
    # release gate: nothing runs off the page; no code listing shows a build helper
    session.run("python", "tools/check_book.py", "latex", str(pdf_path.parent))
    session.log(f"PDF book: {pdf_path}")
    if (HTML / "book.pdf").exists():  # the HTML already links a PDF: give it the new one
        shutil.copy2(pdf_path, HTML / "book.pdf")
    elif (HTML / "index.html").exists():
        session.log("an HTML book exists without the PDF: rebuilding it to link the PDF")
        _build_html(session)


@nox.session
def reproducible(session: nox.Session) -> None:
    """Two clean HTML builds of this commit (executing every page) must be byte-identical.

    Both builds use the same output and cache folders (emptied in between), so that only
    what the build itself does can differ; the first build's HTML is kept aside.

    ``nox -s reproducible -- --against _build/html`` makes one clean build and compares it
    with an existing one (CI passes the book it has just built from a clean checkout, so
    the notebooks execute twice in all, not three times). If that book links the PDF, the
    clean build is given the same PDF to link.
    """
    _install(session)
    import tempfile

    against = None
    if session.posargs:
        if len(session.posargs) != 2 or session.posargs[0] != "--against":
            session.error("usage: nox -s reproducible [-- --against BUILT_HTML_DIR]")
        against = Path(session.posargs[1]).resolve()
        if not (against / "index.html").exists():
            session.error(f"--against {against}: no built HTML book there")
    with tempfile.TemporaryDirectory(prefix="navcore-repro-") as tmp:
        out, cache, first = Path(tmp) / "out", Path(tmp) / "cache", Path(tmp) / "first"
        ledger_cache = Path(tmp) / "navcore-cache"  # the claims are evaluated afresh too
        for run in ("first", "second") if against is None else ("second",):
            for folder in (out, cache, ledger_cache):
                shutil.rmtree(folder, ignore_errors=True)
            if against is not None and (against / "book.pdf").exists():
                (out / "_build" / "latex").mkdir(parents=True)
                shutil.copy2(against / "book.pdf", out / "_build" / "latex" / "book.pdf")
            session.run(
                "python", "tools/build_book.py", "--builder", "html", "--cache", "--out", str(out),
                env={"NAVCORE_BOOK_CACHE": str(cache), "NAVCORE_CACHE": str(ledger_cache)},
            )  # fmt: skip
            if run == "first":
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
    one session (CI's gate): two fresh processes evaluate the ledger side by side, one per
    core, and their JSON exports must be byte-identical (tools/ledger_twice.py).
    """
    _install(session)
    env = {"NAVCORE_CACHE": "off", "NAVCORE_NO_DISK_CACHE": "1"}
    out = ROOT / "_build" / "ledger.json"
    args = list(session.posargs)
    if "--twice" in args:
        args.remove("--twice")
        session.run("python", "tools/ledger_twice.py", str(out), *args, env=env)
    else:
        session.run("python", "-m", "navcore", "ledger", "--json-out", str(out), *args, env=env)
    session.log(f"ledger JSON: {out}")


@nox.session
def bench(session: nox.Session) -> None:
    """Clean full HTML build, each chapter's execution, the floor, and the library; write _build/bench.md.

    The library numbers: the Kalman filter step against filterpy's (a ratio from one run) and
    the covariance-analysis engine on a 104-minute mission. ``nox -s bench -- --library-only``
    measures only those; ``-- --standalone --models`` also times every page alone in a fresh
    kernel and every paper's ledger and figure in a fresh process.
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
    hours on two cores. A developer's session: ``.ci/run`` does not run it.
    """
    _install(session)
    session.run("python", "tools/input_gate.py", *session.posargs)


@nox.session
def mutation(session: nox.Session) -> None:
    """Mutation testing (mutmut) of the model packages; writes _build/mutation.md.

    ``nox -s mutation`` runs estimation, inertial, gnss, detection, location and frames one
    after another, each in its own scratch copy under ``_build/mutation/`` with only the test
    files that exercise it (tools/mutation.py); ``nox -s mutation -- gnss frames`` runs some,
    ``-- --budget-min 20`` bounds each package's wall-clock time (default 30 min on 2 cores),
    ``-- --report-only`` tabulates the last runs. A developer's session: ``.ci/run`` does not
    run it. Equivalent mutants are documented in ``tests/mutation_equivalents.md``.
    """
    _install(session)
    session.run("python", "tools/mutation.py", *session.posargs)


if __name__ == "__main__":  # pragma: no cover - convenience
    sys.exit(subprocess.call(["nox", *sys.argv[1:]], cwd=ROOT))
