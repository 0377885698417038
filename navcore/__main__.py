"""Command line: ``python -m navcore ledger|report|figures``.

``python -m navcore ledger [--paper KEY] [--json] [--csv] [--jobs N] [--claim ID] [--times]``
    print the verification ledger, evaluated on every core (``--jobs 1``: in this process;
    the same result bit for bit); ``--claim ID`` evaluates one claim and says how long it
    took; ``--times`` prints the seconds of each parallel task (a paper module's claims);
    exit status 1 if any claim fails its own check. The JSON export is an object
    ``{"provenance": ..., "claims": [...]}``; every CSV row carries the same ``build_*``
    columns (commit, clean or dirty tree, commit date, lock hash, versions).
``python -m navcore report PAPER [--pdf [OUT]] [--jobs N]``
    print the findings section of the paper's verification report (plain text, 100
    columns); with ``--pdf`` also typeset the stand-alone report with XeLaTeX (to OUT,
    default ``_build/reports/<PAPER>.pdf``). Without ``--pdf`` nothing is written.
``python -m navcore figures [--out DIR] [--only ID ...]``
    write every registered figure to ``DIR`` (default ``figures/``) as SVG and PNG.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def _cmd_ledger(args: argparse.Namespace) -> int:
    import time

    from navcore import ledger
    from navcore.ledger.tables import csv_export, json_export, text_table
    from navcore.provenance import build_provenance

    start = time.perf_counter()
    if args.claim:
        evals = [ledger.evaluate_claim(args.claim)]
    else:
        if args.times:
            from navcore.ledger.registry import evaluate_in_parallel, ledger_task

            seconds = evaluate_in_parallel([c.id for c in ledger.claims(args.paper)], n_jobs=args.jobs)
            tasks: dict[str, float] = {}
            for cid, s in seconds.items():
                tasks[ledger_task(cid)] = tasks.get(ledger_task(cid), 0.0) + s
            for task, s in sorted(tasks.items(), key=lambda kv: -kv[1]):  # on stderr, as --claim's time
                print(f"{s:8.1f} s  {task}", file=sys.stderr)
        evals = ledger.evaluations(paper=args.paper, n_jobs=args.jobs)
    elapsed = time.perf_counter() - start
    provenance = build_provenance()  # the exports name the commit, lock and versions
    if args.json_out:
        Path(args.json_out).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json_out).write_text(json_export(evals, provenance) + "\n")
    if args.json:
        print(json_export(evals, provenance))
    elif args.csv:
        sys.stdout.write(csv_export(evals, provenance))
    else:
        print(text_table(evals))
    failing = [e for e in evals if not e.passes]
    for e in failing:
        print(f"FAIL {e.claim.id}: {e.detail}", file=sys.stderr)
    if args.claim:  # on stderr: the JSON and CSV on stdout stay what they are
        print(f"{evals[0].claim.id}: evaluated in {elapsed:.2f} s", file=sys.stderr)
    return 1 if failing else 0


def _cmd_report(args: argparse.Namespace) -> int:
    from navcore import ledger
    from navcore.report import build_report, to_text, write_pdf

    evals = ledger.evaluations(paper=args.paper, n_jobs=args.jobs)
    report = build_report(args.paper, evals)
    sys.stdout.write(to_text(report.section("findings")))
    if args.pdf is not None:
        out = Path(args.pdf or Path("_build") / "reports" / f"{args.paper}.pdf")
        try:
            write_pdf(report, out)
        except (FileNotFoundError, RuntimeError) as exc:
            print(f"report {args.paper}: {exc}", file=sys.stderr)
            return 1
        print(f"wrote {out}", file=sys.stderr)
    return 0


def _paper_key(text: str) -> str:
    return text.upper()


def _cmd_figures(args: argparse.Namespace) -> int:
    from navcore import figures

    out = Path(args.out)
    written = figures.write_all(out, only=args.only or None)
    for path in written:
        print(path)
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m navcore", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p_ledger = sub.add_parser("ledger", help="print the verification ledger")
    p_ledger.add_argument("--paper", choices=["WF", "SP", "ATC10", "KZL"], default=None)
    fmt = p_ledger.add_mutually_exclusive_group()
    fmt.add_argument(
        "--json", action="store_true", help="JSON: the build's provenance and the array of claim objects"
    )
    fmt.add_argument("--csv", action="store_true", help="CSV rows, each with the build's provenance columns")
    p_ledger.add_argument("--json-out", default=None, help="also write the JSON export to this file")
    p_ledger.add_argument(
        "--claim",
        default=None,
        metavar="ID",
        help="evaluate this claim alone (and the model runs it reads) and say how long it took",
    )
    p_ledger.add_argument(
        "--times",
        action="store_true",
        help="also print, on stderr, the seconds each parallel task's claims took in their worker "
        "(claims not already evaluated)",
    )
    p_ledger.add_argument(
        "--jobs",
        type=int,
        default=-1,
        metavar="N",
        help="worker processes for the claims (default -1: every core; 1: this process alone); "
        "the result is the same bit for bit",
    )
    p_ledger.set_defaults(func=_cmd_ledger)
    p_report = sub.add_parser(
        "report",
        help="print the findings of a paper's verification report; --pdf also writes the PDF",
        description="Print the findings section of PAPER's verification report (plain text, "
        "100 columns). The stand-alone PDF is written only when asked, with --pdf (it needs "
        "xelatex on the PATH): nothing is written by default.",
    )
    p_report.add_argument(
        "paper", metavar="PAPER", type=_paper_key, choices=["WF", "SP", "ATC10", "KZL"],
        help="the paper: WF, SP, ATC10 or KZL",
    )  # fmt: skip
    p_report.add_argument(
        "--pdf", nargs="?", const="", default=None, metavar="OUT",
        help="also typeset the stand-alone report with XeLaTeX, strictly, to OUT "
        "(default: _build/reports/PAPER.pdf)",
    )  # fmt: skip
    p_report.add_argument(
        "--jobs", type=int, default=None, metavar="N",
        help="worker processes for claims not yet in the ledger's cache (default: this process)",
    )  # fmt: skip
    p_report.set_defaults(func=_cmd_report)
    p_fig = sub.add_parser("figures", help="write every registered figure as SVG and PNG")
    p_fig.add_argument("--out", default="figures", help="output folder (default: figures)")
    p_fig.add_argument("--only", nargs="*", help="figure ids to write")
    p_fig.set_defaults(func=_cmd_figures)
    args = parser.parse_args(argv)
    return int(args.func(args))


if __name__ == "__main__":
    sys.exit(main())
