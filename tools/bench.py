"""Benchmark: execution time of each book page, of the ledger per paper, and of each figure.

Usage: ``python tools/bench.py [--pages GLOB ...] [--out _build/bench.md]``

Each page is executed in a fresh kernel with nbclient (as the book build does) and timed
wall-clock; the ledger and figure timings run in this process, each in a fresh subprocess so
that caches from one measurement don't flatter the next. The table is printed and written to
``_build/bench.md``. Timings are measurements for the reader, not assertions.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def time_page(path: Path) -> tuple[float, str]:
    import jupytext
    from nbclient import NotebookClient

    nb = jupytext.read(path)
    client = NotebookClient(
        nb, timeout=1800, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}
    )
    start = time.perf_counter()
    try:
        client.execute()
        status = "ok"
    except Exception as exc:  # report, don't stop the benchmark
        status = f"error: {type(exc).__name__}"
    return time.perf_counter() - start, status


def time_subprocess(code: str) -> tuple[float, str]:
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    return time.perf_counter() - start, "ok" if proc.returncode == 0 else "error"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pages", nargs="*", default=None, help="page paths (default: every book page)")
    parser.add_argument("--out", type=Path, default=ROOT / "_build" / "bench.md")
    parser.add_argument("--skip-pages", action="store_true")
    args = parser.parse_args()

    rows: list[tuple[str, str, float, str]] = []
    if not args.skip_pages:
        pages = (
            [Path(p) for p in args.pages]
            if args.pages
            else sorted(
                p
                for p in (ROOT / "book").rglob("*.md")
                if "_build" not in p.parts and p.read_text().startswith("---")
            )
        )
        for page in pages:
            seconds, status = time_page(page)
            rows.append(("page", str(page.relative_to(ROOT)), seconds, status))
            print(f"{seconds:8.2f} s  {page.relative_to(ROOT)}  {status}", flush=True)
    for paper in ("WF", "SP", "ATC10", "KZL"):
        code = (
            f"from navcore import ledger; ev = ledger.evaluations('{paper}'); "
            "assert all(e.passes for e in ev)"
        )
        seconds, status = time_subprocess(code)
        rows.append(("ledger", paper, seconds, status))
        print(f"{seconds:8.2f} s  ledger {paper}  {status}", flush=True)
    from navcore import figures

    for fig_id in figures.registry():
        code = f"from navcore import figures; figures.render('{fig_id}')"
        seconds, status = time_subprocess(code)
        rows.append(("figure", fig_id, seconds, status))
        print(f"{seconds:8.2f} s  figure {fig_id}  {status}", flush=True)

    lines = ["| kind | item | seconds | status |", "|---|---|---:|---|"]
    lines += [f"| {k} | {item} | {s:.2f} | {st} |" for k, item, s, st in rows]
    total_pages = sum(s for k, _, s, _ in rows if k == "page")
    lines.append(f"| total | all pages | {total_pages:.2f} | |")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"written to {args.out}")
    return 0 if all(st == "ok" for *_, st in rows) else 1


if __name__ == "__main__":
    raise SystemExit(main())
