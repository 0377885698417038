"""Counts and input summaries of a set of evaluations (terminal, book pages).

The ledger's summary (LEDGER.md): claims counted by paper, verdict and kind; the fitted
parameters with the claims each was fitted to and the claims that read it; the assumed
inputs with the claims each moves.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from navcore.ledger.core import KINDS, PAPERS, STATUSES, Evaluation
from navcore.ledger.inputs import Input, get_input

__all__ = ["count_table", "input_readers", "summary_text"]


def count_table(evals: Sequence[Evaluation]) -> list[dict[str, Any]]:
    """Rows ``{paper, kind, <status>: n, ..., total}`` per paper and kind present, then totals."""
    rows: list[dict[str, Any]] = []
    papers = [p for p in PAPERS if any(e.claim.paper == p for e in evals)]
    for p in papers:
        for k in KINDS:
            sel = [e for e in evals if e.claim.paper == p and e.kind == k]
            if not sel:
                continue
            row: dict[str, Any] = {"paper": p, "kind": k}
            for s in STATUSES:
                row[s] = sum(e.status == s for e in sel)
            row["error"] = sum(e.status not in STATUSES for e in sel)
            row["total"] = len(sel)
            rows.append(row)
    total: dict[str, Any] = {"paper": "all", "kind": "all"}
    for s in (*STATUSES, "error"):
        total[s] = sum(r[s] for r in rows)
    total["total"] = len(evals)
    rows.append(total)
    return rows


def input_readers(evals: Sequence[Evaluation], provenance: str) -> list[tuple[Input, list[str]]]:
    """The inputs of ``provenance`` read by ``evals``, each with the ids of the claims that read it."""
    readers: dict[str, list[str]] = {}
    for e in evals:
        for i in e.inputs:
            if i["provenance"] == provenance:
                readers.setdefault(i["name"], []).append(e.claim.id)
    return [(get_input(name), ids) for name, ids in sorted(readers.items())]


def summary_text(evals: Sequence[Evaluation]) -> str:
    """Counts by paper, kind and verdict; fitted parameters; assumed inputs (plain text)."""
    lines = []
    head = ["paper", "kind", *STATUSES, "total"]
    widths = [6, 13, *(max(len(s), 3) for s in STATUSES), 5]
    lines.append("  ".join(h.ljust(w) for h, w in zip(head, widths, strict=True)))
    for r in count_table(evals):
        cells = [r["paper"], r["kind"], *(str(r[s]) for s in STATUSES), str(r["total"])]
        lines.append("  ".join(c.ljust(w) for c, w in zip(cells, widths, strict=True)))
    failing = sum(not e.passes for e in evals)
    lines.append(f"{len(evals)} claims, {failing} failing their check")
    fitted = input_readers(evals, "fitted")
    if fitted:
        lines.append("")
        lines.append("fitted parameters (the claims they were fitted to are not evidence):")
        for inp, ids in fitted:
            lines.append(
                f"  {inp.name} = {inp.value!r}: fitted to {', '.join(inp.fitted_to)}; "
                f"read by {len(ids)} claims"
            )
    assumed = input_readers(evals, "assumed")
    if assumed:
        lines.append("")
        lines.append("assumed inputs (nominal, range) and the claims each moves:")
        for inp, ids in assumed:
            lines.append(
                f"  {inp.name} = {inp.value!r} [{inp.low!r}, {inp.high!r}] {inp.unit}: {len(ids)} claims"
            )
    return "\n".join(lines)
