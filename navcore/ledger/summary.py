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

__all__ = [
    "assumed_inputs_frame",
    "convention_inputs_frame",
    "count_table",
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
        :data:`~navcore.ledger.core.PAPERS` and :data:`~navcore.ledger.core.KINDS`: a count
        per verdict of :data:`~navcore.ledger.core.STATUSES`, ``error`` (claims whose
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


def input_readers(evals: Sequence[Evaluation], provenance: str) -> list[tuple[Input, list[str]]]:
    """The inputs of ``provenance`` read by ``evals``, each with the ids of the claims that read it.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).
    provenance : str
        One of :data:`~navcore.ledger.inputs.PROVENANCES` (LEDGER.md, "Provenance of an
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


def summary_text(evals: Sequence[Evaluation]) -> str:
    """Counts by paper, kind and verdict; fitted parameters; assumed inputs (plain text).

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    str
        The summary of LEDGER.md for a terminal: the :func:`count_table`, the number of
        claims failing their check, then the fitted parameters and the assumed inputs read.

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
    >>> for line in summary_text([ev]).splitlines()[3:]:
    ...     print(line.rstrip())
    1 claims, 0 failing their check
    <BLANKLINE>
    fitted parameters (the claims they were fitted to are not evidence):
      SP.doc_summary.gain_db = 14.0: fitted to SP-doc-margin; read by 1 claims
    <BLANKLINE>
    assumed inputs (nominal, range) and the claims each moves:
      SP.doc_summary.loss_db = 2.0 [1.0, 3.0] dB: 1 claims
    """
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
    from navcore.ledger.render import format_value

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
        One row per word of :data:`~navcore.ledger.core.PROSE_WORDS`, columns ``Word in the
        paper`` and ``Band the ledger uses`` (LEDGER.md, "Tolerance: fixed before the value
        is computed").

    Examples
    --------
    >>> print(prose_words_frame().head(2).to_string(index=False))
    Word in the paper Band the ledger uses
                about         within ±10 %
        approximately         within ±10 %
    """
    import pandas as pd

    from navcore.ledger.core import PROSE_WORDS

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
                "Unit": inp.unit,
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
            "Unit": inp.unit,
            "Fitted to": _breakable(", ".join(inp.fitted_to)),
            "Reason": inp.reason,
            "Claims reading it": len(readers),
        }
        for inp, readers in _inputs_of(evals, "fitted")
    ]
    return pd.DataFrame(
        rows, columns=["Paper", "Parameter", "Value", "Unit", "Fitted to", "Reason", "Claims reading it"]
    )


def convention_inputs_frame(evals: Sequence[Evaluation]) -> Any:
    """Every convention: the reading used, the other reading and the reason.

    Parameters
    ----------
    evals : sequence of Evaluation
        The evaluations to summarise (from :func:`~navcore.ledger.registry.evaluations`).

    Returns
    -------
    pandas.DataFrame
        One row per convention input read, columns ``Paper``, ``Convention``, ``Reading
        used``, ``Other reading``, ``Unit``, ``Reason`` and ``Claims``.

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
    >>> print(frame[["Convention", "Reading used", "Other reading", "Claims"]].to_string(index=False))
    Convention Reading used Other reading  Claims
    loss scale            1           0.5       1
    """
    import pandas as pd

    rows = [
        {
            "Paper": inp.paper,
            "Convention": _label(inp),
            "Reading used": _fmt(inp.value),
            "Other reading": _fmt(inp.alternative),
            "Unit": inp.unit,
            "Reason": inp.reason,
            "Claims": len(readers),
        }
        for inp, readers in _inputs_of(evals, "convention")
    ]
    return pd.DataFrame(
        rows, columns=["Paper", "Convention", "Reading used", "Other reading", "Unit", "Reason", "Claims"]
    )


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

    from navcore.ledger.render import _published

    rows = []
    for inp, readers in _inputs_of(evals, "assumed"):
        label = _label(inp)
        for e in readers:
            row = dict(e.sensitivity).get(inp.name)
            if row is None:
                continue
            unit = e.claim.unit if e.claim.unit != "statement" else ""
            rows.append(
                {
                    "Assumed input / claim": f"{label}: " + _breakable(e.claim.id),
                    "Low end": _fmt(row[0][1]),
                    "Nominal": _fmt(e.reproduced),
                    "High end": _fmt(row[-1][1]),
                    "Printed": _published(e) + (f" {unit}" if unit else ""),
                    "Verdict": e.status,
                }
            )
    columns = ["Assumed input / claim", "Low end", "Nominal", "High end", "Printed", "Verdict"]
    return pd.DataFrame(rows, columns=columns)
