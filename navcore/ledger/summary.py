"""Counts and input summaries of a set of evaluations (terminal, book pages).

The ledger's summary leads with the findings: the errata counted by basis
(``computed``, ``text-only``) and kind, each with the claims that are its evidence; then the
claims counted by paper, verdict and kind; the fitted parameters with the claims each was
fitted to and the claims that read it; the assumed inputs with the claims each moves.
"""

from __future__ import annotations

import re
import textwrap
from collections.abc import Sequence
from typing import Any

from navcore.claims.declarations import (
    ERRATUM_BASES,
    ERRATUM_KINDS,
    KINDS,
    PAPERS,
    STATUSES,
    TEXT_ONLY_CAVEAT,
    Erratum,
)
from navcore.claims.evaluation import Evaluation
from navcore.claims.inputs import Input, get_input
from navcore.formatting import unit_text
from navcore.ledger.text import format_value, published_text

__all__ = [
    "KIND_SHORT",
    "assumed_inputs_frame",
    "convention_inputs_frame",
    "count_table",
    "finding_evidence",
    "findings_count_table",
    "findings_phrase",
    "findings_text",
    "fitted_inputs_frame",
    "input_readers",
    "kind_counts_frame",
    "prose_words_frame",
    "sensitivity_frame",
    "summary_text",
]


def count_table(evals: Sequence[Evaluation]) -> list[dict[str, Any]]:
    """Rows ``{paper, kind, <status>: n, ..., total}`` per paper and kind present, then totals.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    list of dict
        One row per (paper, kind) with claims, in the order of
        :data:`~navcore.claims.declarations.PAPERS` and :data:`~navcore.claims.declarations.KINDS`: a count
        per verdict of :data:`~navcore.claims.declarations.STATUSES`, ``error`` (claims whose
        evaluation failed) and ``total``; the last row, paper and kind ``"all"``, sums them.

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> [(r["paper"], r["kind"], r["reproduced"], r["total"]) for r in count_table([ev])]
    [('SP', 'reproduction', 1, 1), ('all', 'all', 1, 1)]
    """
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


def finding_evidence(
    errata: Sequence[Erratum], evals: Sequence[Evaluation]
) -> list[tuple[Erratum, list[Evaluation]]]:
    """Each finding (erratum) with the claims among ``evals`` that are its evidence.

    A claim is evidence for an erratum it names (``erratum=``) or that names it (the
    erratum's ``claims`` hold its id or a former id).

    Parameters
    ----------
    errata : sequence of Erratum
        The findings, in the order they are shown.
    evals : sequence of Evaluation
        The evaluations to look in (their order is kept).

    Returns
    -------
    list of tuple of (Erratum, list of Evaluation)
        One pair per erratum; the list is empty for an erratum no claim checks.

    Examples
    --------
    >>> from navcore.ledger import EXACT, Claim, Erratum, evaluate
    >>> e = Erratum(id="SP-E7-doc", paper="SP", locator="Eq. (1)", printed="a + b", finding="a - b",
    ...             evidence="the derivation", kind="typography", basis="text-only",
    ...             claims=("SP-doc-sum",))
    >>> c = Claim(id="SP-doc-sum", paper="SP", locator="Eq. (1)", quantity="a sum", published=3.0,
    ...           unit="", compute=lambda: 3.0, tolerance=EXACT, expected_status="reproduced",
    ...           note="a synthetic claim")
    >>> [(f.id, [ev.status for ev in evs]) for f, evs in finding_evidence([e], [evaluate(c)])]
    [('SP-E7-doc', ['reproduced'])]
    """
    out = []
    for e in errata:
        named = set(e.claims)
        evidence = [
            ev
            for ev in evals
            if ev.claim.erratum == e.id or named.intersection((ev.claim.id, *ev.claim.aliases))
        ]
        out.append((e, evidence))
    return out


def findings_count_table(errata: Sequence[Erratum]) -> list[dict[str, Any]]:
    """Findings counted by paper, basis and kind: rows ``{paper, basis, <kind>: n, ..., total}``.

    Parameters
    ----------
    errata : sequence of Erratum
        The findings to count.

    Returns
    -------
    list of dict
        One row per (paper, basis) with findings, in the order of
        :data:`~navcore.claims.declarations.PAPERS` and :data:`~navcore.claims.declarations.ERRATUM_BASES`,
        a count per kind of :data:`~navcore.claims.declarations.ERRATUM_KINDS` and ``total``; then,
        for more than one paper, one row per basis over all papers (paper ``"all"``); the
        last row, paper and basis ``"all"``, sums them.

    Examples
    --------
    >>> from navcore.ledger import Erratum
    >>> e = Erratum(id="SP-E7-doc", paper="SP", locator="Eq. (1)", printed="a + b", finding="a - b",
    ...             evidence="the derivation", kind="typography", basis="text-only")
    >>> [(r["paper"], r["basis"], r["typography"], r["total"]) for r in findings_count_table([e])]
    [('SP', 'text-only', 1, 1), ('all', 'all', 1, 1)]
    """

    def row(paper: str, basis: str, sel: list[Erratum]) -> dict[str, Any]:
        r: dict[str, Any] = {"paper": paper, "basis": basis}
        for k in ERRATUM_KINDS:
            r[k] = sum(e.kind == k for e in sel)
        r["total"] = len(sel)
        return r

    rows = []
    papers = [p for p in PAPERS if any(e.paper == p for e in errata)]
    for p in papers:
        for b in ERRATUM_BASES:
            sel = [e for e in errata if e.paper == p and e.basis == b]
            if sel:
                rows.append(row(p, b, sel))
    if len(papers) > 1:
        for b in ERRATUM_BASES:
            rows.append(row("all", b, [e for e in errata if e.basis == b]))
    rows.append(row("all", "all", list(errata)))
    return rows


#: Short column heads of the erratum kinds for the terminal.
KIND_SHORT = {
    "typography": "typo",
    "units": "units",
    "convention": "conv",
    "derivation": "deriv",
    "unstated-assumption": "unstated",
    "inconsistent-numbers": "numbers",
    "overstatement": "overstate",
}


def findings_text(evals: Sequence[Evaluation], errata: Sequence[Erratum]) -> str:
    """The findings for a terminal: counts by paper, basis and kind, then each with its evidence.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations whose claims are shown as evidence.
    errata : sequence of Erratum
        The findings.

    Returns
    -------
    str
        The :func:`findings_count_table`, the text-only caveat (once, when a text-only
        finding is listed), then the findings by basis, each as ``id (kind; locator):``
        followed by its claims and their verdicts.

    Examples
    --------
    >>> from navcore.ledger import EXACT, Claim, Erratum, evaluate
    >>> e = Erratum(id="SP-E7-doc", paper="SP", locator="Eq. (1)", printed="a + b", finding="a - b",
    ...             evidence="the derivation", kind="typography", basis="text-only",
    ...             claims=("SP-doc-sum",))
    >>> c = Claim(id="SP-doc-sum", paper="SP", locator="Eq. (1)", quantity="a sum", published=3.0,
    ...           unit="", compute=lambda: 3.0, tolerance=EXACT, expected_status="reproduced",
    ...           note="a synthetic claim")
    >>> print(findings_text([evaluate(c)], [e]).splitlines()[-1])
      SP-E7-doc (typography; Eq. (1)): SP-doc-sum reproduced
    """
    lines = [f"findings (errata): {len(errata)}, by paper, basis and kind"]
    head = ["paper", "basis", *(KIND_SHORT[k] for k in ERRATUM_KINDS), "total"]
    widths = [6, 9, *(max(len(KIND_SHORT[k]), 3) for k in ERRATUM_KINDS), 5]
    lines.append("  ".join(h.ljust(w) for h, w in zip(head, widths, strict=True)).rstrip())
    for r in findings_count_table(errata):
        cells = [r["paper"], r["basis"], *(str(r[k]) for k in ERRATUM_KINDS), str(r["total"])]
        lines.append("  ".join(c.ljust(w) for c, w in zip(cells, widths, strict=True)).rstrip())
    if any(e.basis == "text-only" for e in errata):
        lines += textwrap.wrap(TEXT_ONLY_CAVEAT, 100)
    evidence = finding_evidence(errata, evals)
    for b in ERRATUM_BASES:
        sel = [(e, evs) for e, evs in evidence if e.basis == b]
        if not sel:
            continue
        lines.append("")
        lines.append(f"{b} findings and the claims that are their evidence:")
        for e, evs in sel:
            claims = ", ".join(f"{ev.claim.id} {ev.status}" for ev in evs) or "no claim checks it"
            lines.append(f"  {e.id} ({e.kind}; {e.locator}): {claims}")
    return "\n".join(lines)


def input_readers(evals: Sequence[Evaluation], provenance: str) -> list[tuple[Input, list[str]]]:
    """The inputs of ``provenance`` read by ``evals``, each with the ids of the claims that read it.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).
    provenance : str
        One of :data:`~navcore.claims.inputs.PROVENANCES` (the ledger's rules, "Provenance of an
        input").

    Returns
    -------
    list of tuple of (Input, list of str)
        Each input read, sorted by full name, with the ids of the claims that read it.

    Raises
    ------
    ValueError
        If an input read is no longer registered.

    Examples
    --------
    >>> from navcore.ledger import Claim, InputSet, evaluate, printed
    >>> IN = InputSet("SP", "doc_summary")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", quantity="implementation loss",
    ...            reason="typical receivers")
    >>> IN.fitted("gain_db", 14.0, fitted_to=["SP-doc-margin"], unit="dB", quantity="antenna gain",
    ...           reason="solved from the printed margin")
    >>> IN.convention("scale", 1.0, alternative=0.5, quantity="loss scale",
    ...               reason="the loss counted once or split in two")
    >>> value, tol = printed("12.0")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: IN.gain_db - IN.scale * IN.loss_db,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> [(inp.name, ids) for inp, ids in input_readers([ev], "assumed")]
    [('SP.doc_summary.loss_db', ['SP-doc-margin'])]
    """
    readers: dict[str, list[str]] = {}
    for e in evals:
        for i in e.inputs:
            if i["provenance"] == provenance:
                readers.setdefault(i["name"], []).append(e.claim.id)
    return [(get_input(name), ids) for name, ids in sorted(readers.items())]


def summary_text(evals: Sequence[Evaluation], errata: Sequence[Erratum] | None = None) -> str:
    """Findings first, then counts by paper, kind and verdict; fitted parameters; assumed inputs.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).
    errata : sequence of Erratum or None, optional
        The findings to lead with; ``None`` for the registered errata of the papers of
        ``evals``.

    Returns
    -------
    str
        The ledger's summary for a terminal: the findings (:func:`findings_text`), then
        the claims by verdict (:func:`count_table`), the number of claims failing their
        check, the fitted parameters and the assumed inputs read.

    Examples
    --------
    >>> from navcore.ledger import Claim, InputSet, evaluate, printed
    >>> IN = InputSet("SP", "doc_summary")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", quantity="implementation loss",
    ...            reason="typical receivers")
    >>> IN.fitted("gain_db", 14.0, fitted_to=["SP-doc-margin"], unit="dB", quantity="antenna gain",
    ...           reason="solved from the printed margin")
    >>> IN.convention("scale", 1.0, alternative=0.5, quantity="loss scale",
    ...               reason="the loss counted once or split in two")
    >>> value, tol = printed("12.0")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: IN.gain_db - IN.scale * IN.loss_db,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> for line in summary_text([ev], errata=[]).splitlines()[4:]:
    ...     print(line.rstrip())
    claims by paper, kind and verdict:
    paper   kind           reproduced  consistent  inconsistent  discrepant  not-reproducible  total
    SP      reproduction   0           1           0             0           0                 1
    all     all            0           1           0             0           0                 1
    1 claims, 0 failing their check
    <BLANKLINE>
    fitted parameters (the claims they were fitted to are not evidence):
      SP.doc_summary.gain_db = 14.0: fitted to SP-doc-margin; read by 1 claims
    <BLANKLINE>
    assumed inputs (nominal, range) and the claims each moves:
      SP.doc_summary.loss_db = 2.0 [1.0, 3.0] dB: 1 claims
    """
    if errata is None:
        from navcore.ledger.registry import errata as registered

        errata = [e for p in PAPERS if any(ev.claim.paper == p for ev in evals) for e in registered(p)]
    lines = [findings_text(evals, errata), "", "claims by paper, kind and verdict:"]
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


def _breakable(text: str) -> str:
    """``text`` with zero-width spaces after ``-``, ``.``, ``_``, ``,`` and ``/`` inside long
    tokens, where the printed table may break a claim id or an input name."""
    out = []
    for word in str(text).split(" "):
        if len(word) > 14:
            for ch in "-._,/":
                word = word.replace(ch, ch + "\u200b")
        out.append(word)
    return " ".join(out)


def _fmt(value: Any) -> str:

    if isinstance(value, tuple | list):
        return "(" + ", ".join(_fmt(v) for v in value) + ")"
    if isinstance(value, str):
        return value
    return format_value(value)


def kind_counts_frame(evals: Sequence[Evaluation]) -> Any:
    """Claims counted by paper, kind and derived verdict, as a DataFrame (for the book).

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    pandas.DataFrame
        The rows of :func:`count_table` (without ``error``), columns ``Paper``, ``Kind``,
        one per verdict and ``Total``.

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> frame = kind_counts_frame([ev])
    >>> print(frame[["Paper", "Kind", "reproduced", "consistent", "Total"]].to_string(index=False))
    Paper         Kind  reproduced  consistent  Total
       SP reproduction           1           0      1
      all          all           1           0      1
    """
    import pandas as pd

    rows = count_table(evals)
    cols = ["paper", "kind", *STATUSES, "total"]
    frame = pd.DataFrame([{k: r[k] for k in cols} for r in rows], columns=cols)
    return frame.rename(columns={"paper": "Paper", "kind": "Kind", "total": "Total"})


def prose_words_frame() -> Any:
    """The one table of prose words and the bands the ledger gives them.

    Returns
    -------
    pandas.DataFrame
        One row per word of :data:`~navcore.claims.tolerances.PROSE_WORDS`, columns ``Word in the
        paper`` and ``Band the ledger uses`` (the ledger's rules, "Tolerance: fixed before the value
        is computed").

    Examples
    --------
    >>> print(prose_words_frame().head(2).to_string(index=False))
    Word in the paper Band the ledger uses
                about         within ±10 %
        approximately         within ±10 %
    """
    import pandas as pd

    from navcore.claims.tolerances import PROSE_WORDS

    return pd.DataFrame(
        [{"Word in the paper": w, "Band the ledger uses": b["meaning"]} for w, b in PROSE_WORDS.items()]
    )


def _label(inp: Input) -> str:
    """What an input is, in words: its quantity, else its attribute name spelled out."""
    return inp.quantity or inp.name.rsplit(".", 1)[-1].replace("_", " ")


def _inputs_of(evals: Sequence[Evaluation], provenance: str) -> list[tuple[Input, list[Evaluation]]]:
    by_id = {e.claim.id: e for e in evals}
    return [(inp, [by_id[i] for i in ids]) for inp, ids in input_readers(evals, provenance)]


def assumed_inputs_frame(evals: Sequence[Evaluation]) -> Any:
    """Every assumed input read by ``evals``: nominal, range, reason and the claims it moves.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    pandas.DataFrame
        One row per assumed input, columns ``Paper``, ``Input``, ``Nominal``, ``Range``,
        ``Unit``, ``Reason`` and ``Claims`` (the number of claims that read it).

    Examples
    --------
    >>> from navcore.ledger import Claim, InputSet, evaluate, printed
    >>> IN = InputSet("SP", "doc_summary")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", quantity="implementation loss",
    ...            reason="typical receivers")
    >>> IN.fitted("gain_db", 14.0, fitted_to=["SP-doc-margin"], unit="dB", quantity="antenna gain",
    ...           reason="solved from the printed margin")
    >>> IN.convention("scale", 1.0, alternative=0.5, quantity="loss scale",
    ...               reason="the loss counted once or split in two")
    >>> value, tol = printed("12.0")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: IN.gain_db - IN.scale * IN.loss_db,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> frame = assumed_inputs_frame([ev])
    >>> print(frame[["Input", "Nominal", "Range", "Unit", "Claims"]].to_string(index=False))
                  Input Nominal  Range Unit  Claims
    implementation loss       2 1 to 3   dB       1
    """
    import pandas as pd

    rows = []
    for inp, readers in _inputs_of(evals, "assumed"):
        rows.append(
            {
                "Paper": inp.paper,
                "Input": _label(inp),
                "Nominal": _fmt(inp.value),
                "Range": f"{_fmt(inp.low)} to {_fmt(inp.high)}",
                "Unit": unit_text(inp.unit),
                "Reason": inp.reason,
                "Claims": len(readers),
            }
        )
    return pd.DataFrame(rows, columns=["Paper", "Input", "Nominal", "Range", "Unit", "Reason", "Claims"])


def fitted_inputs_frame(evals: Sequence[Evaluation]) -> Any:
    """Every fitted parameter: value, the claims it was fitted to, and the claims that read it.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    pandas.DataFrame
        One row per fitted input read, columns ``Paper``, ``Parameter``, ``Value``, ``Unit``,
        ``Fitted to``, ``Reason`` and ``Claims reading it``.

    Examples
    --------
    >>> from navcore.ledger import Claim, InputSet, evaluate, printed
    >>> IN = InputSet("SP", "doc_summary")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", quantity="implementation loss",
    ...            reason="typical receivers")
    >>> IN.fitted("gain_db", 14.0, fitted_to=["SP-doc-margin"], unit="dB", quantity="antenna gain",
    ...           reason="solved from the printed margin")
    >>> IN.convention("scale", 1.0, alternative=0.5, quantity="loss scale",
    ...               reason="the loss counted once or split in two")
    >>> value, tol = printed("12.0")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: IN.gain_db - IN.scale * IN.loss_db,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> frame = fitted_inputs_frame([ev])
    >>> print(frame[["Parameter", "Value", "Fitted to", "Claims reading it"]].to_string(index=False))
       Parameter Value     Fitted to  Claims reading it
    antenna gain    14 SP-doc-margin                  1
    """
    import pandas as pd

    rows = [
        {
            "Paper": inp.paper,
            "Parameter": _label(inp),
            "Value": _fmt(inp.value),
            "Unit": unit_text(inp.unit),
            "Fitted to": _breakable(", ".join(inp.fitted_to)),
            "Reason": inp.reason,
            "Claims reading it": len(readers),
        }
        for inp, readers in _inputs_of(evals, "fitted")
    ]
    return pd.DataFrame(
        rows, columns=["Paper", "Parameter", "Value", "Unit", "Fitted to", "Reason", "Claims reading it"]
    )


def _reading(label: str, value: Any) -> str:
    """A convention's reading for a table: its label, and its value where the label does not say it.

    A reading's value that is a code word (``"loop"``, ``"atan2"``) is what the label says in
    words, and a number the label already states (``"30 runs"``) would only repeat it; neither is
    shown.

    Examples
    --------
    >>> _reading("the reading used", 1.0)
    'the reading used (1)'
    >>> _reading("30 runs (the book's ensemble)", 30)
    "30 runs (the book's ensemble)"
    >>> _reading("$C/N_0$ in dB-Hz", "C/N0")
    '$C/N_0$ in dB-Hz'
    """
    if isinstance(value, str):
        return label
    text = _fmt(value)
    if re.search(rf"(?<![\d.]){re.escape(text)}(?![\d.])", label):
        return label
    return f"{label} ({text})"


def convention_inputs_frame(evals: Sequence[Evaluation]) -> Any:
    """Every convention: the reading used, the other admissible readings, and the claims they move.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    pandas.DataFrame
        One row per convention input read, columns ``Paper``, ``Convention``, ``Reading
        used`` (its label, with its value where the label does not already state it),
        ``Other readings`` (each the same way), ``Unit``,
        ``Reason``, ``Claims`` (the number that read it) and ``Agree only under another
        reading`` (the ids of the claims whose printed value only another reading accepts).

    Examples
    --------
    >>> from navcore.ledger import Claim, InputSet, evaluate, printed
    >>> IN = InputSet("SP", "doc_summary")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", quantity="implementation loss",
    ...            reason="typical receivers")
    >>> IN.fitted("gain_db", 14.0, fitted_to=["SP-doc-margin"], unit="dB", quantity="antenna gain",
    ...           reason="solved from the printed margin")
    >>> IN.convention("scale", 1.0, alternative=0.5, quantity="loss scale",
    ...               reason="the loss counted once or split in two")
    >>> value, tol = printed("12.0")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: IN.gain_db - IN.scale * IN.loss_db,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> frame = convention_inputs_frame([ev])
    >>> print(frame[["Convention", "Reading used", "Other readings", "Claims"]].to_string(index=False))
    Convention             Reading used                Other readings  Claims
    loss scale the reading used (1) the other reading (0.5)       1
    """
    import pandas as pd

    rows = []
    for inp, readers in _inputs_of(evals, "convention"):
        only_other = [
            e.claim.id
            for e in readers
            if any(r["agrees"] for r in e.readings)
            and not any(r["agrees"] for r in e.readings if r["reading"].get(inp.name) == inp.nominal_label)
        ]
        rows.append(
            {
                "Paper": inp.paper,
                "Convention": _label(inp),
                "Reading used": _reading(inp.nominal_label, inp.value),
                "Other readings": "; ".join(_reading(label, v) for label, v in inp.other_readings),
                "Unit": unit_text(inp.unit),
                "Reason": inp.reason,
                "Claims": len(readers),
                "Agree only under another reading": _breakable(", ".join(only_other)),
            }
        )
    columns = [
        "Paper",
        "Convention",
        "Reading used",
        "Other readings",
        "Unit",
        "Reason",
        "Claims",
        "Agree only under another reading",
    ]
    return pd.DataFrame(rows, columns=columns)


def sensitivity_frame(evals: Sequence[Evaluation]) -> Any:
    """How far each claim moves across each assumed input's range (computed, one input at a time).

    One row per (assumed input, claim): the claim's value with that input at the low end of
    its range, at the nominal value and at the high end (the other inputs nominal), the
    printed value and the derived verdict. The band over all the assumed inputs a claim
    reads is on the ledger page.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    pandas.DataFrame
        Columns ``Assumed input / claim``, ``Low end``, ``Nominal``, ``High end``,
        ``Printed`` and ``Verdict``.

    Examples
    --------
    >>> from navcore.ledger import Claim, InputSet, evaluate, printed
    >>> IN = InputSet("SP", "doc_summary")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", quantity="implementation loss",
    ...            reason="typical receivers")
    >>> IN.fitted("gain_db", 14.0, fitted_to=["SP-doc-margin"], unit="dB", quantity="antenna gain",
    ...           reason="solved from the printed margin")
    >>> IN.convention("scale", 1.0, alternative=0.5, quantity="loss scale",
    ...               reason="the loss counted once or split in two")
    >>> value, tol = printed("12.0")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: IN.gain_db - IN.scale * IN.loss_db,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> print(sensitivity_frame([ev]).to_string(index=False))
                 Assumed input / claim Low end Nominal High end Printed    Verdict
    implementation loss: SP-doc-margin      13      12       11   12 dB consistent
    """
    import pandas as pd

    rows = []
    for inp, readers in _inputs_of(evals, "assumed"):
        label = _label(inp)
        for e in readers:
            row = dict(e.sensitivity).get(inp.name)
            if row is None:
                continue
            unit = unit_text(e.claim.unit) if e.claim.unit != "statement" else ""
            rows.append(
                {
                    "Assumed input / claim": f"{label}: " + _breakable(e.claim.id),
                    "Low end": _fmt(row[0][1]),
                    "Nominal": _fmt(e.reproduced),
                    "High end": _fmt(row[-1][1]),
                    "Printed": published_text(e) + (f" {unit}" if unit else ""),
                    "Verdict": e.status,
                }
            )
    columns = ["Assumed input / claim", "Low end", "Nominal", "High end", "Printed", "Verdict"]
    return pd.DataFrame(rows, columns=columns)


def findings_phrase(items: Sequence[Erratum]) -> str:
    """The findings in one phrase: their number, then per basis its count and its kinds
    (``"9 findings: 4 computed (2 inconsistent numbers, ...), 5 text-only (...)"``).

    Parameters
    ----------
    items : sequence of Erratum
        The findings (errata) to count.

    Returns
    -------
    str
        The phrase, bases in the order of :data:`~navcore.claims.declarations.ERRATUM_BASES` and kinds
        in that of :data:`~navcore.claims.declarations.ERRATUM_KINDS`; ``"0 findings"`` for none.

    Examples
    --------
    >>> findings_phrase([])
    '0 findings'
    >>> from navcore.ledger import Erratum
    >>> findings_phrase([Erratum(id="SP-E9-doc", paper="SP", locator="Eq. (1)", printed="m",
    ...                          finding="km", evidence="the scale", kind="units", basis="text-only")])
    '1 finding: 1 text-only (1 unit)'
    """
    parts = []
    for b in ERRATUM_BASES:
        sel = [e for e in items if e.basis == b]
        if sel:
            kinds = ", ".join(
                f"{n} {'unit' if n == 1 and k == 'units' else k.replace('-', ' ')}"
                for k in ERRATUM_KINDS
                if (n := sum(e.kind == k for e in sel))
            )
            parts.append(f"{len(sel)} {b} ({kinds})")
    n = len(items)
    return f"{n} finding{'' if n == 1 else 's'}" + (": " + ", ".join(parts) if parts else "")
