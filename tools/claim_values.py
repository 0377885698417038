"""The recorded values of every claim: a change that moves a reproduced number shows in review.

``tests/claim_values.json`` holds, for every claim of the ledger, what its evaluation
reproduced: the value at the nominal inputs, the band over the assumed inputs' ranges, and the
value and band under each reading of the conventions it reads. The claim tests compare each
claim's evaluation with it (:func:`differences`), so a change to a model, a scenario or an input
that moves any reproduced number fails a test until the record is written again, and the
record's diff shows the reviewer every number that moved, whether or not its verdict did.

The record is a regression check, not an oracle: it says that a number changed, not which of
the two is right. The claim's own check (against the published value, within the tolerance)
and the models' oracle tests say that.

Usage::

    python tools/claim_values.py --update [LEDGER_JSON]

writes the record from a ledger JSON export (``nox -s ledger`` writes ``_build/ledger.json``);
without ``LEDGER_JSON`` it evaluates the ledger itself, on every core.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
import tempfile
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

#: The fields of a claim's JSON export (:meth:`navcore.ledger.Evaluation.as_json`) recorded.
FIELDS = ("reproduced", "band", "readings")


def values(record: dict[str, Any]) -> dict[str, Any]:
    """What the record keeps of one claim's JSON export: its reproduced value, its band, and
    each reading's value and band (in the order the evaluation lists them).

    Parameters
    ----------
    record : dict
        One claim of the ledger's JSON export.

    Returns
    -------
    dict
        ``reproduced``, ``band`` and ``readings`` (a list of ``[value, band]``).

    Examples
    --------
    >>> values({"id": "X", "reproduced": 1.5, "band": [1.0, 2.0],
    ...         "readings": [{"reading": {}, "value": 1.4, "band": None}]})
    {'reproduced': 1.5, 'band': [1.0, 2.0], 'readings': [[1.4, None]]}
    """
    return {
        "reproduced": record["reproduced"],
        "band": record["band"],
        "readings": [[r["value"], r["band"]] for r in record["readings"]],
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
    >>> differences({"reproduced": 2.0, "band": None, "readings": []},
    ...             {"reproduced": 3.0, "band": None, "readings": []})
    ['reproduced: 2.0 -> 3.0']
    """
    return [
        f"{field}: {recorded.get(field)!r} -> {now.get(field)!r}"
        for field in FIELDS
        if not same(recorded.get(field), now.get(field), rtol)
    ]


def load(path: Path = RECORD) -> dict[str, dict[str, Any]]:
    """The record: claim id -> :func:`values`."""
    return json.loads(path.read_text())["claims"]


def write(export: dict[str, Any], path: Path = RECORD) -> int:
    """Write the record from a ledger JSON export; returns the number of claims."""
    claims = {c["id"]: values(c) for c in sorted(export["claims"], key=lambda c: c["id"])}
    doc = {
        "about": (
            "What each claim's evaluation reproduced (tools/claim_values.py): the claim tests "
            "compare every evaluation with it, to a relative 1e-6. Written with "
            "'python tools/claim_values.py --update'; its diff shows every number a change moved."
        ),
        "claims": claims,
    }
    # one claim a line, so that the diff of a change names each claim whose numbers it moved
    lines = [f" {json.dumps(cid)}: {json.dumps(v)}" for cid, v in claims.items()]
    path.write_text(
        "{\n"
        + f' "about": {json.dumps(doc["about"])},\n'
        + ' "claims": {\n'
        + ",\n".join(" " + line for line in lines)
        + "\n }\n}\n"
    )
    return len(claims)


def main(argv: list[str]) -> int:
    if not argv or argv[0] != "--update" or len(argv) > 2:
        print(__doc__.split("Usage::")[1].strip().splitlines()[0], file=sys.stderr)
        return 2
    if len(argv) == 2:
        export = json.loads(Path(argv[1]).read_text())
    else:
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp) / "ledger.json"
            cmd = [sys.executable, "-m", "navcore", "ledger", "--json-out", str(out)]
            subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL)
            export = json.loads(out.read_text())
    n = write(export)
    print(f"recorded the values of {n} claims in {RECORD.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
