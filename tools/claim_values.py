"""The recorded values of every claim: a change that moves a reproduced number shows in review.

``tests/claim_values.json`` holds, for every claim of the ledger, what its evaluation
reproduced: the value at the nominal inputs, the band over the assumed inputs' ranges, the value
and band under each reading of the conventions it reads, the value of each one-at-a-time run of
the band (each assumed input at each of its band points), and the independent oracle's value of
a discrepant claim; and what the claim declares that a verdict reads or a reader sees beside it:
the published value, its unit, the tolerance, the locator, the kind, the verdict it expects,
whether it computes at all and the page that derives it (:func:`declared`, which a test reads
without evaluating). The claim tests compare each claim's evaluation with it
(:func:`differences`), so a change to a model, a scenario or an input that moves any reproduced
number fails a test until the record is written again, and the record's diff shows the reviewer
every number that moved, whether or not its verdict did.

The record is a regression check, not an oracle: it says that a number changed, not which of
the two is right. The claim's own check (against the published value, within the tolerance)
and the models' oracle tests say that.

Usage::

    python tools/claim_values.py --update

evaluates the ledger on every core (reading the evaluations the ledger's on-disk cache holds
for this checkout: after ``nox -s ledger -- --store`` it takes seconds) and writes the record.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
RECORD = ROOT / "tests" / "claim_values.json"

#: Two values agree when they differ by at most this fraction of the larger. The same checkout
#: gives the same bits on one machine, but another processor's vectorised ``exp`` or BLAS may
#: round the last bits differently, and a long covariance or Monte Carlo run carries that on
#: (1e-12 relative, at most, in the runs compared); a change of a model moves a number by far
#: more, and the papers print no number to more than five significant digits.
RTOL = 1e-6

#: Values within this distance of zero are zero: a difference that vanishes in exact arithmetic
#: and leaves round-off (the smallest non-zero value the ledger reproduces is about 1e-5).
ATOL = 1e-12

#: The fields a claim declares (:func:`declared`), read without evaluating it.
DECLARED = (
    "published", "unit", "tolerance", "locator", "kind", "expected_status", "computes", "discussed_in",
)  # fmt: skip

#: The fields recorded of each claim: what its evaluation reproduced, then what it declares.
FIELDS = ("reproduced", "band", "readings", "sensitivity", "oracle", *DECLARED)


def declared(claim: Any) -> dict[str, Any]:
    """What a claim declares beside its computation, as the record keeps it: its published
    value, unit, resolved tolerance (as the JSON export writes it), locator, kind, expected
    verdict, whether it has a computation, and the page that derives it (the ledger links it).

    Parameters
    ----------
    claim : navcore.ledger.Claim
        The claim (not evaluated: only its tolerance is resolved, which reads no input).

    Returns
    -------
    dict
        The fields of :data:`DECLARED`.

    Examples
    --------
    >>> from navcore import ledger
    >>> c = ledger.Claim(id="WF-doc-x", paper="WF", locator="Eq. (1)", quantity="q", published=2,
    ...                  unit="m", compute=None, tolerance=ledger.EXACT,
    ...                  expected_status="not-reproducible", note="n")
    >>> d = declared(c)
    >>> d["published"], d["unit"], d["tolerance"]["policy"], d["computes"]
    (2.0, 'm', 'exact', False)
    """
    from navcore.claims.declarations import resolve_tolerance

    return {
        "published": claim.published if isinstance(claim.published, bool) else float(claim.published),
        "unit": claim.unit,
        "tolerance": resolve_tolerance(claim).as_dict(),
        "locator": claim.locator,
        "kind": claim.kind,
        "expected_status": claim.expected_status,
        "computes": claim.compute is not None,
        "discussed_in": claim.discussed_in,
    }


def values(evaluation: Any) -> dict[str, Any]:
    """What the record keeps of one claim's evaluation, as plain JSON: its reproduced value, its
    band, each reading's value and band (in the order the evaluation lists them), each
    one-at-a-time band run (input name, then ``[point, value]`` pairs) and the oracle's value.

    Parameters
    ----------
    evaluation : navcore.ledger.Evaluation
        One claim's evaluation.

    Returns
    -------
    dict
        ``reproduced``, ``band``, ``readings`` (a list of ``[value, band]``), ``sensitivity``
        (a list of ``[name, [[point, value], ...]]``), ``oracle``, and what the claim declares
        (:func:`declared`).

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> from navcore import ledger
    >>> claim = ledger.Claim(id="WF-doc-x", paper="WF", locator="Eq. (1)", quantity="q",
    ...                      published=1.5, unit="m", compute=lambda: 1.5, tolerance=ledger.EXACT,
    ...                      expected_status="reproduced", note="n")
    >>> ev = SimpleNamespace(
    ...     claim=claim,
    ...     as_json=lambda: {"reproduced": 1.5, "band": [1.0, 2.0],
    ...                      "readings": [{"reading": {}, "value": 1.4, "band": None}]},
    ...     sensitivity=(("P.m.x", ((0.5, 1.0), (2.0, 2.0))),), oracle_value=None)
    >>> values(ev)["readings"], values(ev)["sensitivity"]
    ([[1.4, None]], [['P.m.x', [[0.5, 1.0], [2.0, 2.0]]]])
    """
    from navcore.claims.json_coding import jsonable

    record = evaluation.as_json()
    return {
        "reproduced": record["reproduced"],
        "band": record["band"],
        "readings": [[r["value"], r["band"]] for r in record["readings"]],
        "sensitivity": [
            [name, [[jsonable(p), jsonable(v)] for p, v in row]] for name, row in evaluation.sensitivity
        ],
        "oracle": jsonable(evaluation.oracle_value),
        **declared(evaluation.claim),
    }


def same(a: Any, b: Any, rtol: float = RTOL) -> bool:
    """Whether two recorded values agree: numbers within ``rtol`` (or both within
    :data:`ATOL` of zero), everything else (truth values, ``None``, ``"Infinity"``) equal, lists
    item by item.

    Examples
    --------
    >>> same(1.0, 1.0 + 1e-9), same(1.0, 1.0 + 1e-5), same(True, 1.0), same(0.0, 1e-15)
    (True, False, False, True)
    >>> same([1.0, None], [1.0, None]), same([1.0], [1.0, 2.0])
    (True, False)
    """
    if isinstance(a, list) or isinstance(b, list):
        return (
            isinstance(a, list)
            and isinstance(b, list)
            and len(a) == len(b)
            and all(same(x, y, rtol) for x, y in zip(a, b, strict=True))
        )
    numbers = [isinstance(x, int | float) and not isinstance(x, bool) for x in (a, b)]
    if all(numbers):
        return math.isclose(a, b, rel_tol=rtol, abs_tol=ATOL)
    return type(a) is type(b) and a == b


def differences(recorded: dict[str, Any], now: dict[str, Any], rtol: float = RTOL) -> list[str]:
    """The fields of one claim whose values moved from the record, in words ("" if none).

    Parameters
    ----------
    recorded, now : dict
        :func:`values` of the record and of the current evaluation.
    rtol : float
        Relative tolerance (:data:`RTOL`).

    Returns
    -------
    list of str
        ``"field: recorded -> now"`` for each field that differs.

    Examples
    --------
    >>> differences({"reproduced": 2.0, "band": None, "sensitivity": [["x", [[1, 2.0]]]]},
    ...             {"reproduced": 3.0, "band": None, "sensitivity": [["x", [[1, 2.5]]]]})
    ['reproduced: 2.0 -> 3.0', 'sensitivity to x: [[1, 2.0]] -> [[1, 2.5]]']
    """
    out = []
    for field in FIELDS:
        was, is_ = recorded.get(field), now.get(field)
        if same(was, is_, rtol):
            continue
        if field == "sensitivity" and isinstance(was, list) and isinstance(is_, list):
            old_rows, new_rows = dict(map(tuple, was)), dict(map(tuple, is_))
            for name in sorted(set(old_rows) | set(new_rows)):
                if not same(old_rows.get(name), new_rows.get(name), rtol):
                    out.append(
                        f"sensitivity to {name}: {_short(old_rows.get(name))} -> {_short(new_rows.get(name))}"
                    )
        else:
            out.append(f"{field}: {_short(was)} -> {_short(is_)}")
    return out


def _short(value: Any, limit: int = 300) -> str:
    """``repr`` of a value, cut to ``limit`` characters."""
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def load(path: Path | None = None) -> dict[str, dict[str, Any]]:
    """The record (default :data:`RECORD`, read when called): claim id -> :func:`values`."""
    return json.loads((RECORD if path is None else path).read_text())["claims"]


def write(records: dict[str, dict[str, Any]], path: Path) -> int:
    """Write the record (claim id -> :func:`values`) to ``path``, one claim a line; returns the
    number of claims."""
    about = (
        "What each claim's evaluation reproduced (tools/claim_values.py): the claim tests "
        "compare every evaluation with it, to a relative 1e-6. Written with "
        "'python tools/claim_values.py --update'; its diff shows every number a change moved."
    )
    # one claim a line, so that the diff of a change names each claim whose numbers it moved
    lines = [f"  {json.dumps(cid)}: {json.dumps(records[cid])}" for cid in sorted(records)]
    path.write_text(
        "{\n" + f' "about": {json.dumps(about)},\n' + ' "claims": {\n' + ",\n".join(lines) + "\n }\n}\n"
    )
    return len(records)


def main(argv: list[str]) -> int:
    if argv != ["--update"]:
        print("usage: python tools/claim_values.py --update", file=sys.stderr)
        return 2
    from navcore.ledger import registry

    evs = registry.evaluations(n_jobs=-1)
    n = write({ev.claim.id: values(ev) for ev in evs}, RECORD)
    print(f"recorded the values of {n} claims in {RECORD.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
