"""Benchmark the book build: clean full build, each chapter, and the floor.

Usage: ``python tools/bench.py [--jobs N] [--standalone] [--models] [--build-only]
[--ledger-from _build/navcore-cache] [--touch navcore/gnss/antijam.py] [--out _build/bench.md]``

1. **Clean full build.** The HTML book is built exactly as ``nox -s book`` builds it
   (``tools/build_book.py --cache``), but with empty caches: a fresh jupyter-cache folder, a
   fresh ledger evaluation cache and no KZL Monte Carlo disk cache, so every chapter executes.
   The wall-clock time is split into execution (before Sphinx) and Sphinx itself; each
   chapter's execution time comes from the build's own ``page-times.json``. Then the
   **incremental rebuild**: the same build again, after a comment is added to one model module
   (``--touch``, in a copy of navcore beside links to the book's pages, the tests and the
   papers' texts); only the pages that depend on it execute, the report lists them with the
   build's reason for each, and its ratio to the clean build is reported. ``--build-only``
   stops after the builds (no library or ledger timings); ``--ledger-from`` starts the clean
   build's ledger cache from a stored ledger, as CI's book build does.
2. **Floor.** The same book with every code cell removed, built with the same configuration
   and forced execution (a notebook without code cells still starts no computation), not
   strict (glued figures are missing, by construction). Its time is what the build costs
   without any of navcore's computation: Sphinx, MyST parsing and the themes.
3. ``--ledger`` only times the whole ledger with its bands (uncached, filling a fresh
   evaluation cache, and cached), without building the book; ``--models`` includes it.
4. ``--standalone`` also executes every page alone in a fresh kernel, cold, as a reader who
   downloads one notebook would; ``--models`` times each paper's ledger evaluation and each
   figure in a fresh process.
5. **Library.** Always (and alone with ``--library-only``, which skips the book builds): the
   Kalman filter step, a 9-state, 3-measurement predict + update with navcore's fast path
   (``kf_predict``/``kf_update`` with ``validate=False`` after one checked call) and with the
   default checked calls, against filterpy's ``KalmanFilter`` on the same problem,
   interleaved in one run and reported as ratios of CPU time (aims: at most 1.0 and 1.5);
   ``propagate_covariance`` over 10 000 steps of 15 states against the plain numpy loop of
   the same recursion (CPU time; aim: at most 1.2); and the covariance-analysis engine on the
   104-minute SP sequential-outage mission (five systems, 1-s steps), in a fresh process.
6. **Ledger, serial against parallel.** Always: ``python -m navcore ledger`` with the caches
   off, ``--jobs 1`` and then on every core, one after the other in one run; the ratio, and
   whether the two JSON exports are byte-identical (aim: 30 s or less on 2 cores).

The table is printed and written to ``_build/bench.md``; the aims (full build under 5 minutes
on 2 cores, within 1.3x of the floor) are reported, never asserted.
Timings are measurements for the reader, not tests.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))

import build_book  # noqa: E402


def _last_line(stderr: str) -> str:
    """The last line of a failed run's error output (the exception), or a note that it wrote none."""
    lines = stderr.strip().splitlines()
    return lines[-1] if lines else "no error output"


def clean_full_build(
    jobs: int | None, workdir: Path, source: Path | None = None, ledger_from: Path | None = None
) -> dict:
    """The HTML book built as ``nox -s book`` builds it, with the caches of ``workdir``.

    Empty caches: a clean build. ``source``: a copy of navcore (on ``PYTHONPATH``) to build
    against instead of the checkout's (the incremental rebuild). ``ledger_from``: a stored
    ledger (``nox -s ledger -- --store``) the clean build's ledger cache starts from, as CI's
    book build does, so that the build is timed without evaluating the ledger.
    """
    if ledger_from is not None and not (workdir / "ledger_cache" / "claims").exists():
        shutil.copytree(ledger_from / "claims", workdir / "ledger_cache" / "claims")
    env = dict(
        os.environ,
        NAVCORE_BOOK_CACHE=str(workdir / "jupyter_cache"),
        NAVCORE_CACHE=str(workdir / "ledger_cache"),
        NAVCORE_NO_DISK_CACHE="1",
    )
    if source is not None:
        env["PYTHONPATH"] = os.pathsep.join([str(source), *filter(None, [os.environ.get("PYTHONPATH")])])
    out = workdir / "full"
    cmd = [sys.executable, str(ROOT / "tools" / "build_book.py"), "--cache", "--out", str(out)]
    if jobs:
        cmd += ["--jobs", str(jobs)]
    start = time.perf_counter()
    sphinx_start = None
    log_lines = []
    with subprocess.Popen(
        cmd, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    ) as proc:
        assert proc.stdout is not None
        for line in proc.stdout:
            log_lines.append(line)
            if line.startswith("sphinx: ") and sphinx_start is None:
                sphinx_start = time.perf_counter()
            if line.startswith(("prefill:", "execution:")):
                print("   ", line.rstrip(), flush=True)
    total = time.perf_counter() - start
    if proc.returncode != 0:
        print("".join(log_lines[-40:]))
        raise SystemExit(f"the clean full build failed (exit {proc.returncode})")
    times_file = out / "_build" / "page-times.json"
    times = json.loads(times_file.read_text()) if times_file.exists() else {"chapters": {}, "pages": {}}
    times_file.unlink(missing_ok=True)
    executed = {
        m.group(1): m.group(2) for line in log_lines if (m := re.match(r"prefill:   (\S+) \((.*)\)$", line))
    }
    return {
        "total": total,
        "execution": (sphinx_start or start) - start,
        "sphinx": total - ((sphinx_start or start) - start),
        "chapters": times["chapters"],
        "pages": times["pages"],
        "executed": executed,
    }


def incremental_build(jobs: int | None, workdir: Path, module: str) -> dict:
    """The build again, after a comment added to one navcore module (in a copy of navcore).

    It reuses the clean build's caches in ``workdir``: only the pages that depend on the module
    execute (the build says which and why); Sphinx renders the whole book, as every build does.
    """
    source = workdir / "navcore-copy"
    shutil.copytree(ROOT / "navcore", source / "navcore", ignore=shutil.ignore_patterns("__pycache__"))
    # what the pages read beyond the package is found beside it (the book's pages, the tests, the
    # papers' texts next to the checkout): the same files, so that only the module differs
    for name in ("book", "tests"):
        (source / name).symlink_to(ROOT / name)
    shared = ROOT.parent / "shared"
    if shared.exists() and not (workdir / "shared").exists():
        (workdir / "shared").symlink_to(shared)
    with open(source / module, "a") as f:
        f.write("# a comment added by the benchmark\n")
    return clean_full_build(jobs, workdir, source)


def strip_code_cells(book: Path) -> int:
    """Remove every code cell from the MyST notebooks under ``book``; return how many pages."""
    import jupytext

    count = 0
    for page in book.rglob("*.md"):
        if not build_book._is_notebook(page):
            continue
        nb = jupytext.read(page)
        nb.cells = [cell for cell in nb.cells if cell.cell_type != "code"]
        jupytext.write(nb, page, fmt="md:myst")
        count += 1
    return count


def floor_build(workdir: Path) -> dict:
    """Build a copy of the book whose notebooks have no code cells (not strict)."""
    import yaml

    book = workdir / "floor-src"
    shutil.copytree(ROOT / "book", book, ignore=shutil.ignore_patterns("_build", "_toc_subset_*"))
    pages = strip_code_cells(book)
    config = yaml.safe_load((ROOT / "_config.yml").read_text())
    for name, folder in (config.get("sphinx", {}).get("local_extensions") or {}).items():
        config["sphinx"]["local_extensions"][name] = str(ROOT / folder)
    config["execute"]["execute_notebooks"] = "force"
    config["sphinx"]["config"]["nb_execution_raise_on_error"] = False
    config_path = workdir / "_config_floor.yml"
    config_path.write_text(yaml.safe_dump(config, sort_keys=False))
    cmd = [
        str(Path(sys.executable).with_name("jupyter-book")), "build", str(book),
        "--config", str(config_path), "--toc", str(book / "_toc.yml"),
        "--path-output", str(workdir / "floor"), "--builder", "html", "--all", "--keep-going", "-q",
    ]  # fmt: skip
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True)
    total = time.perf_counter() - start
    if proc.returncode != 0 and not (workdir / "floor" / "_build" / "html" / "index.html").exists():
        print(proc.stdout[-3000:], proc.stderr[-3000:])
        raise SystemExit("the floor build failed")
    return {"total": total, "pages": pages}


def time_page(path: Path) -> tuple[float, str]:
    """Execute one page alone in a fresh kernel (as MyST-NB does), cold."""
    from jupyter_cache.executors.utils import single_nb_execution

    nb = build_book._read_notebook(path)
    result = single_nb_execution(nb, cwd=str(path.parent), allow_errors=False, timeout=1800)
    return result.time, "ok" if result.err is None else f"error: {type(result.err).__name__}"


def time_subprocess(code: str) -> tuple[float, str]:
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    return time.perf_counter() - start, "ok" if proc.returncode == 0 else "error"


def ledger_times() -> list[str]:
    """The whole ledger (bands included) evaluated in a fresh process: uncached, then from its cache.

    The first cached run fills a fresh on-disk evaluation cache (what the book build does once
    per source change); the second reads it (what every later page and build does).
    """
    rows = ["| ledger, fresh process, all claims with their bands | seconds | status |", "|---|---:|---|"]
    code = "from navcore import ledger; assert all(e.passes for e in ledger.evaluations())"
    with tempfile.TemporaryDirectory(prefix="navcore-ledger-bench-") as tmp:
        for label, env in (
            ("uncached (NAVCORE_CACHE=off)", {"NAVCORE_CACHE": "off"}),
            ("filling a fresh cache", {"NAVCORE_CACHE": tmp}),
            ("cached (read from the cache)", {"NAVCORE_CACHE": tmp}),
        ):
            start = time.perf_counter()
            proc = subprocess.run(
                [sys.executable, "-c", code],
                capture_output=True,
                text=True,
                cwd=ROOT,
                env={**os.environ, **env},
            )
            seconds = time.perf_counter() - start
            rows.append(f"| {label} | {seconds:.1f} | {'ok' if proc.returncode == 0 else 'error'} |")
            print(rows[-1], flush=True)
    return rows


FILTER_STEP_CODE = """
import time
import timeit
import numpy as np
from filterpy.kalman import KalmanFilter
from navcore.estimation import kf_predict, kf_update

n, m = 9, 3
rng = np.random.default_rng(0)
F = np.eye(n) + 0.01 * rng.standard_normal((n, n))
Q = 0.01 * np.eye(n)
H = rng.standard_normal((m, n))
R = np.eye(m)
zs = rng.standard_normal((256, m))

kf = KalmanFilter(dim_x=n, dim_z=m)
kf.F, kf.Q, kf.H, kf.R, kf.P, kf.x = F, Q, H, R, np.eye(n), np.zeros((n, 1))

def filterpy_steps():
    for z in zs:
        kf.predict()
        kf.update(z)

def navcore_steps():
    # checked once at the boundary (shapes, finiteness, P, Q, R), then the fast path
    x, P = kf_predict(np.zeros(n), np.eye(n), F, Q)
    x, P = kf_update(x, P, zs[0], H, R)[:2]
    for z in zs:
        x, P = kf_predict(x, P, F, Q, validate=False)
        x, P = kf_update(x, P, z, H, R, validate=False)[:2]

def checked_steps():
    x, P = np.zeros(n), np.eye(n)
    for z in zs:
        x, P = kf_predict(x, P, F, Q)
        x, P = kf_update(x, P, z, H, R)[:2]

best = {"filterpy": 1e9, "navcore": 1e9, "checked": 1e9}
def cpu_seconds_per_step(steps):
    # CPU time of the process: other work on the machine does not inflate it
    return timeit.timeit(steps, number=4, timer=time.process_time) / (4 * len(zs))

for _ in range(9):  # interleaved, so that all three see the same machine
    best["filterpy"] = min(best["filterpy"], cpu_seconds_per_step(filterpy_steps))
    best["navcore"] = min(best["navcore"], cpu_seconds_per_step(navcore_steps))
    best["checked"] = min(best["checked"], cpu_seconds_per_step(checked_steps))
print(best["filterpy"], best["navcore"], best["checked"])
"""

#: The covariance engine (``propagate_covariance``: 10 000 steps, 15 states, no measurement)
#: against the plain numpy loop it runs (propagate, symmetrize, keep prior and posterior);
#: the two must give the same matrices, bit for bit.
COVARIANCE_LOOP_CODE = """
import time
import timeit
import numpy as np
from navcore.estimation.covariance import propagate_covariance

n, N = 15, 10_000
rng = np.random.default_rng(1)
F = np.eye(n) + 0.01 * rng.standard_normal((n, n))
A = rng.standard_normal((n, n))
Q = 1e-3 * (A @ A.T)
P0 = np.eye(n)
t = np.arange(N + 1, dtype=float)

def engine():
    return propagate_covariance(P0, t, F, Q).posterior[-1]

def plain():
    P = P0.copy()
    prior = np.empty((N + 1, n, n))
    post = np.empty((N + 1, n, n))
    for k in range(N + 1):
        if k > 0:
            P = F @ P @ F.T + Q
            P = 0.5 * (P + P.T)
        prior[k] = P
        post[k] = P
    return post[-1]

assert np.array_equal(engine(), plain())
best = {"engine": 1e9, "plain": 1e9}
for _ in range(5):  # interleaved; CPU time of the process, which other work does not inflate
    best["engine"] = min(best["engine"], timeit.timeit(engine, number=1, timer=time.process_time))
    best["plain"] = min(best["plain"], timeit.timeit(plain, number=1, timer=time.process_time))
print(best["engine"], best["plain"])
"""

MISSION_CODE = """
import os, time
os.environ["NAVCORE_CACHE"] = "off"
os.environ["NAVCORE_NO_DISK_CACHE"] = "1"
from navcore.papers import sp_mission_flights as s
start = time.perf_counter()
runs = s.sequential_outage(False)
elapsed = time.perf_counter() - start
t = next(iter(runs.values())).t
print(elapsed, float(t[-1] - t[0]) / 60.0, len(runs))
"""


def library_benchmarks() -> tuple[list[str], bool]:
    """The filter step against filterpy (one run, interleaved) and a 104-min covariance mission."""
    lines = ["", "| library | value |", "|---|---:|"]
    proc = subprocess.run([sys.executable, "-c", FILTER_STEP_CODE], capture_output=True, text=True, cwd=ROOT)
    ok = proc.returncode == 0
    if ok:
        filterpy_s, navcore_s, checked_s = map(float, proc.stdout.split())
        ratio, checked_ratio = navcore_s / filterpy_s, checked_s / filterpy_s
        lines += [
            f"| filter step (9 states, 3 measurements), filterpy KalmanFilter, µs | {filterpy_s * 1e6:.1f} |",
            f"| filter step, navcore fast path (validate=False), µs | {navcore_s * 1e6:.1f} |",
            f"| filter step, navcore checked on every call (the default), µs | {checked_s * 1e6:.1f} |",
            f"| ratio navcore fast path / filterpy, same run (aim: at most 1.0) | {ratio:.2f} |",
            f"| ratio navcore checked / filterpy, same run (aim: at most 1.5) | {checked_ratio:.2f} |",
        ]
        us = f"navcore {navcore_s * 1e6:.1f}, checked {checked_s * 1e6:.1f} us"
        print(f"filter step: {us}, filterpy {filterpy_s * 1e6:.1f} us, ratio {ratio:.2f}|{checked_ratio:.2f}")
    else:
        lines.append(f"| filter step benchmark | failed: {_last_line(proc.stderr)} |")
    proc = subprocess.run([sys.executable, "-c", MISSION_CODE], capture_output=True, text=True, cwd=ROOT)
    if proc.returncode == 0:
        seconds, minutes, systems = proc.stdout.split()
        lines.append(
            f"| covariance analysis, SP sequential-outage mission ({float(minutes):.0f} min, "
            f"{systems} systems, 1-s steps), s | {float(seconds):.1f} |"
        )
        print(f"covariance analysis: {float(minutes):.0f}-min mission in {float(seconds):.1f} s")
    else:
        ok = False
        lines.append(f"| covariance-analysis mission | failed: {_last_line(proc.stderr)} |")
    more, more_ok = covariance_loop_ratio()
    return lines + more, ok and more_ok


def covariance_loop_ratio() -> tuple[list[str], bool]:
    """``propagate_covariance`` (10 000 steps, 15 states) against the plain numpy loop, one run."""
    code = COVARIANCE_LOOP_CODE
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    if proc.returncode != 0:
        return [f"| covariance engine against a numpy loop | failed: {_last_line(proc.stderr)} |"], False
    engine_s, plain_s = map(float, proc.stdout.split())
    ratio = engine_s / plain_s
    print(f"covariance engine: {engine_s:.3f} s, plain numpy loop {plain_s:.3f} s, ratio {ratio:.2f}")
    return [
        f"| propagate_covariance, 10 000 steps, 15 states, s | {engine_s:.3f} |",
        f"| the same recursion as a plain numpy loop, s | {plain_s:.3f} |",
        f"| ratio engine / plain loop, same run (aim: at most 1.2) | {ratio:.2f} |",
    ], True


def ledger_parallel_ratio() -> tuple[list[str], bool]:
    """The ledger, cache off, in one process (``--jobs 1``) and on every core, in one run.

    Both write their JSON export; the two must be byte-identical.
    """
    env = {**os.environ, "NAVCORE_CACHE": "off", "NAVCORE_NO_DISK_CACHE": "1"}
    seconds = {}
    with tempfile.TemporaryDirectory(prefix="navcore-bench-ledger-") as tmp:
        outputs = {}
        for jobs in ("1", "-1"):
            out = Path(tmp) / f"ledger-{jobs}.json"
            start = time.perf_counter()
            proc = subprocess.run(
                [sys.executable, "-m", "navcore", "ledger", "--jobs", jobs, "--json-out", str(out)],
                cwd=ROOT,
                env=env,
                capture_output=True,
                text=True,
            )
            seconds[jobs] = time.perf_counter() - start
            if proc.returncode != 0:
                return [f"| ledger --jobs {jobs} | failed: {_last_line(proc.stderr)} |"], False
            outputs[jobs] = out.read_bytes()
        same = outputs["1"] == outputs["-1"]
    cores = os.cpu_count() or 1
    serial, parallel = seconds["1"], seconds["-1"]
    print(f"ledger, cache off: {serial:.1f} s in one process, {parallel:.1f} s on {cores} cores")
    return [
        f"| ledger, cache off, one process (--jobs 1), s | {serial:.1f} |",
        f"| ledger, cache off, every core ({cores}), s (aim: at most 30 on 2 cores) | {parallel:.1f} |",
        f"| ratio serial / parallel, same run | {serial / parallel:.2f} |",
        f"| the two JSON exports byte-identical | {'yes' if same else 'NO'} |",
    ], same


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=None, help="workers for the build (default: the cores)")
    parser.add_argument("--standalone", action="store_true", help="also time each page alone, cold")
    parser.add_argument("--models", action="store_true", help="also time each ledger paper and figure")
    parser.add_argument(
        "--ledger",
        action="store_true",
        help="only time the whole ledger, uncached and cached (no book build)",
    )
    parser.add_argument(
        "--library-only", action="store_true", help="only the library numbers (filter step, mission)"
    )
    parser.add_argument(
        "--build-only",
        action="store_true",
        help="only the book builds (clean, incremental, floor): no library or ledger timings",
    )
    parser.add_argument(
        "--ledger-from",
        type=Path,
        default=None,
        help="start the clean build's ledger cache from this stored ledger (nox -s ledger -- --store "
        "writes _build/navcore-cache), as CI's book build does: the build is timed without the ledger",
    )
    parser.add_argument("--out", type=Path, default=ROOT / "_build" / "bench.md")
    parser.add_argument(
        "--touch",
        default="navcore/location/emitter.py",
        help="the module a comment is added to (in a copy) for the incremental rebuild",
    )
    args = parser.parse_args()
    if args.ledger:
        lines = ["# Ledger benchmark", "", *ledger_times()]
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text("\n".join(lines) + "\n")
        print("\n".join(lines))
        return 0
    if args.library_only:
        lines, ok = library_benchmarks()
        ledger_lines, ledger_ok = ledger_parallel_ratio()
        lines, ok = [*lines, "", "| ledger | value |", "|---|---:|", *ledger_lines], ok and ledger_ok
        text = "# Library benchmark\n" + "\n".join(lines) + "\n"
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(text)
        print(text)
        return 0 if ok else 1
    cores = os.cpu_count() or 1
    lines = [
        f"# Build benchmark ({cores} cores, jobs = {args.jobs or cores})",
        "",
        "The clean build's ledger: "
        + (f"read from the store {args.ledger_from}" if args.ledger_from else "evaluated (empty cache)"),
        "",
        "| measurement | seconds |",
        "|---|---:|",
    ]
    with tempfile.TemporaryDirectory(prefix="navcore-bench-") as tmp:
        workdir = Path(tmp)
        print("clean full build (HTML, every chapter executed) ...", flush=True)
        ledger_from = args.ledger_from.resolve() if args.ledger_from else None
        if ledger_from is not None and not (ledger_from / "claims").is_dir():
            raise SystemExit(f"--ledger-from {args.ledger_from}: no stored ledger (a claims folder) there")
        full = clean_full_build(args.jobs, workdir, ledger_from=ledger_from)
        print(f"incremental rebuild after a comment in {args.touch} ...", flush=True)
        incremental = incremental_build(args.jobs, workdir, args.touch)
        print("floor build (the same book without code cells) ...", flush=True)
        floor = floor_build(workdir)
    lines += [
        f"| clean full build, total | {full['total']:.1f} |",
        f"| of which: executing the notebooks (parallel, before Sphinx) | {full['execution']:.1f} |",
        f"| of which: Sphinx (reading from the cache, writing HTML) | {full['sphinx']:.1f} |",
        f"| floor: the same build without code cells ({floor['pages']} notebooks) | {floor['total']:.1f} |",
        f"| ratio full / floor (aim: at most 1.3) | {full['total'] / floor['total']:.2f} |",
        f"| incremental rebuild after a comment in {args.touch}, total | {incremental['total']:.1f} |",
        f"| of which: executing the {len(incremental['executed'])} pages that depend on it "
        f"| {incremental['execution']:.1f} |",
        f"| ratio incremental / clean full build | {incremental['total'] / full['total']:.2f} |",
        "",
        "| chapter | execution in the build (s, one kernel per chapter, ledger included) |",
        "|---|---:|",
    ]
    lines += [f"| {name} | {seconds:.1f} |" for name, seconds in sorted(full["chapters"].items())]
    lines += ["", "| page | execution in the build (s) |", "|---|---:|"]
    lines += [f"| {name} | {seconds:.1f} |" for name, seconds in sorted(full["pages"].items())]
    lines += ["", f"Pages the incremental rebuild executed ({len(incremental['executed'])}), and why:", ""]
    lines += [f"- {page} ({why})" for page, why in incremental["executed"].items()] or ["- none"]
    aims = [
        ("full build under 5 min", full["total"] < 300),
        ("full build within 1.3x of the floor", full["total"] <= 1.3 * floor["total"]),
    ]
    lines += ["", *[f"- {'met' if ok else 'NOT met'}: {aim}" for aim, ok in aims]]
    ok = True
    if args.standalone:
        lines += [
            "",
            "| page alone, fresh kernel, cold (as a reader runs it) | seconds | status |",
            "|---|---:|---|",
        ]
        for page in build_book.toc_pages(ROOT / "book" / "_toc.yml"):
            if not build_book._is_notebook(page):
                continue
            seconds, status = time_page(page)
            ok &= status == "ok"
            rel = page.relative_to(ROOT / "book").as_posix()
            lines.append(f"| {rel} | {seconds:.1f} | {status} |")
            print(f"{seconds:8.1f} s  {rel} (alone)  {status}", flush=True)
    if args.models:
        from navcore import figures

        lines += ["", *ledger_times()]

        lines += ["", "| model, fresh process | seconds | status |", "|---|---:|---|"]
        for paper in ("WF", "SP", "ATC10", "KZL"):
            code = (
                "import os; os.environ['NAVCORE_CACHE'] = 'off'; os.environ['NAVCORE_NO_DISK_CACHE'] = '1'\n"
                f"from navcore import ledger; assert all(e.passes for e in ledger.evaluations('{paper}'))"
            )
            seconds, status = time_subprocess(code)
            ok &= status == "ok"
            lines.append(f"| ledger {paper} | {seconds:.1f} | {status} |")
        for fig_id in figures.registry():
            seconds, status = time_subprocess(f"from navcore import figures; figures.render('{fig_id}')")
            ok &= status == "ok"
            lines.append(f"| figure {fig_id} | {seconds:.1f} | {status} |")
    if args.build_only:
        return _write(args.out, lines, ok)
    library, library_ok = library_benchmarks()
    lines += library
    ok &= library_ok
    ledger_lines, ledger_ok = ledger_parallel_ratio()
    lines += ["", "| ledger | value |", "|---|---:|", *ledger_lines]
    ok &= ledger_ok
    return _write(args.out, lines, ok)


def _write(out: Path, lines: list[str], ok: bool) -> int:
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"written to {out}")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
