"""Running a claim: its nominal run, its band runs, the readings of its conventions, :func:`evaluate`.

:func:`evaluate` runs a claim's computation, then its band and readings as the verdict needs
them, and weighs them with :mod:`navcore.claims.verdict`'s rule into an
:class:`~navcore.claims.evaluation.Evaluation`.

Band runs
---------
The band runs each assumed input one at a time over its band points and then the corners of
the box: every corner for up to :data:`~navcore.claims.verdict.MAX_CORNER_INPUTS` inputs; beyond that, the two
diagonal corners (all low, all high), the two half-and-half corners (the first half of the
inputs low and the rest high, and the reverse), and, for a numeric value, the two corners
where each input sits at the end of its range that raised (lowered) the value in its
one-at-a-time run (the extremes of a response monotone in each input, which the diagonals can
miss). A run whose inputs are each in range but together describe a case the model does not
cover (it raises ``ModelDomainError``, for example no four satellites stay above the mask
along the whole flight for fixed channels) gives no value: it is left out of the band, and
the evaluation's ``left_out`` records which case was left out and in how many runs; the note
says it. A statement whose nominal and one-at-a-time runs already hold both truth values
skips its corners: its band is ``(False, True)`` whatever they give; under a reading other
than the one used, whose one-at-a-time runs are not shown, its runs stop as soon as both truth
values are in (``left_out`` counts the runs made). Each batch of runs (the one-at-a-time
runs, then the corners) is announced before it is made (``band_ahead`` in
:mod:`navcore.claims.inputs`), so that a model whose runs batch well can compute the whole
batch in one call when the first run asks, and serve the others from its
:func:`~navcore.claims.inputs.input_cache`; such a model gives each run the result it gives
that run alone (KZL's Monte Carlo does, bit for bit, and its tests check it).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import Any

from navcore._validate import ModelDomainError
from navcore.claims.declarations import Claim, resolve_tolerance
from navcore.claims.evaluation import Evaluation
from navcore.claims.inputs import Input, band_ahead, overriding, recording
from navcore.claims.json_coding import jsonable
from navcore.claims.tolerances import PRECISION_LOOSE, PRECISION_READING, PRECISION_STRICT
from navcore.claims.verdict import (
    _AGREEMENT,
    MAX_CORNER_INPUTS,
    _outcome,
    additive_envelope,
    derive_status,
    precision_status,
)

__all__ = ["MAX_READING_COMBINATIONS", "evaluate"]


def _coerce(value: Any, claim: Claim) -> Any:
    if claim.is_statement:
        if not isinstance(value, bool | int) and not hasattr(value, "__bool__"):
            raise TypeError(f"claim {claim.id}: a statement must compute to a truth value")
        return bool(value)
    out = float(value)
    return out


def _run(claim: Claim, overrides: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
    assert claim.compute is not None
    with recording() as reads:
        if overrides:
            with overriding(overrides):
                value = _coerce(claim.compute(), claim)
        else:
            value = _coerce(claim.compute(), claim)
    if not claim.is_statement and math.isnan(value):
        raise ValueError("the computation returned NaN")
    return value, reads


#: Up to this many combinations of the readings of the conventions a claim reads are run (all
#: of them); beyond it, each convention's readings one at a time, the others at the reading used.
MAX_READING_COMBINATIONS = 16


def _band_runs(
    claim: Claim,
    assumed: list[Any],
    base: dict[str, Any] | None = None,
    excluded: list[str] | None = None,
    nominal: Any = None,
) -> tuple[list[Any], list[tuple[str, tuple[tuple[Any, Any], ...]]]]:
    """Values across the assumed inputs' ranges: one at a time, and every corner of the box for up
    to :data:`~navcore.claims.verdict.MAX_CORNER_INPUTS` inputs (extremes of a monotone response lie at
    corners).

    ``base`` holds the overrides of a reading other than the one used (every run keeps them).
    ``nominal`` is the value at the nominal inputs of that reading: a statement whose nominal and
    one-at-a-time runs already hold both truth values has the band ``(False, True)`` whatever the
    corners give, so its corners are not run; under another reading (``base``), whose
    one-at-a-time runs are not shown, its runs stop there (module docstring, "Band runs").
    A run the model does not cover (it raises :class:`~navcore.ModelDomainError`)
    gives no value: its case in a reader's words is appended to ``excluded`` (module docstring,
    "Band runs").
    """
    base = base or {}
    values: list[Any] = []
    sensitivity = []

    def run(overrides: dict[str, Any]) -> tuple[bool, Any]:
        try:
            return True, _run(claim, overrides)[0]
        except ModelDomainError as exc:
            if excluded is not None:
                excluded.append(exc.case)
            return False, None

    # each batch of runs is announced first, so that a model can run it in one call (band_ahead)
    def both_truth_values() -> bool:
        return claim.is_statement and {bool(v) for v in (nominal, *values) if v is not None} == {False, True}

    with band_ahead([{**base, inp.name: point} for inp in assumed for point in inp.band_points]):
        for inp in assumed:
            row = []
            for point in inp.band_points:
                if base and both_truth_values():
                    break  # another reading's statement: its band is settled, its runs are not shown
                ok, v = run({**base, inp.name: point})
                if ok:
                    values.append(v)
                    row.append((point, v))
            sensitivity.append((inp.name, tuple(row)))

    if both_truth_values():
        corners: Any = []  # the band already holds both truth values
    elif 2 <= len(assumed) <= MAX_CORNER_INPUTS:
        corners = itertools.product(*[(inp.low, inp.high) for inp in assumed])
    elif len(assumed) > MAX_CORNER_INPUTS:  # the diagonal and the two half-and-half corners
        lows, highs = [inp.low for inp in assumed], [inp.high for inp in assumed]
        half = len(assumed) // 2
        corners = [lows, highs, lows[:half] + highs[half:], highs[:half] + lows[half:]]
        corners += _steepest_corners(assumed, sensitivity)
    else:
        corners = []
    corner_runs = [
        {**base, **{inp.name: p for inp, p in zip(assumed, corner, strict=True)}} for corner in corners
    ]
    with band_ahead(corner_runs):
        for overrides in corner_runs:
            ok, v = run(overrides)
            if ok:
                values.append(v)
    return values, sensitivity


def _steepest_corners(
    assumed: list[Any], sensitivity: list[tuple[str, tuple[tuple[Any, Any], ...]]]
) -> list[list[Any]]:
    """The corners at which a monotone numeric response is largest and smallest.

    Each input goes to the end of its range where the one-at-a-time run gave the larger value
    (and, for the other corner, the smaller); none when a value is not a finite real number.
    """
    up, down = [], []
    for inp, (_, row) in zip(assumed, sensitivity, strict=True):
        if len(row) < 2 or isinstance(row[0][1], bool) or isinstance(row[-1][1], bool):
            return []
        if row[0][0] != inp.low or row[-1][0] != inp.high:
            return []  # an end of the range lies outside the model's domain: no direction to take
        try:  # the first and last band points are the ends of the range
            v_low, v_high = float(row[0][1]), float(row[-1][1])
        except (TypeError, ValueError):
            return []
        if not (math.isfinite(v_low) and math.isfinite(v_high)):
            return []
        up.append(inp.high if v_high >= v_low else inp.low)
        down.append(inp.low if v_high >= v_low else inp.high)
    return [up, down]


def reading_combinations(conventions: Sequence[Input]) -> list[tuple[tuple[Input, str, Any], ...]]:
    """The combinations of readings a claim is run under, the readings used first.

    Parameters
    ----------
    conventions : sequence of Input
        The convention inputs the claim read.

    Returns
    -------
    list of tuple of (Input, str, Any)
        Each combination as ``(input, label, value)`` per convention; the first is every
        reading used. Every combination when there are at most
        :data:`MAX_READING_COMBINATIONS`; else each convention's other readings one at a
        time, the others at the reading used.

    Examples
    --------
    >>> from navcore.claims.inputs import Input
    >>> a = Input(name="WF.doc.a", paper="WF", value=1.0, provenance="convention",
    ...           alternative=2.0, reason="two readings")
    >>> [[label for _, label, _ in combo] for combo in reading_combinations([a])]
    [['the reading used'], ['the other reading']]
    """
    per = [
        [(inp, inp.nominal_label, inp.value), *((inp, lab, v) for lab, v in inp.other_readings)]
        for inp in conventions
    ]
    if math.prod(len(p) for p in per) <= MAX_READING_COMBINATIONS:
        return [tuple(combo) for combo in itertools.product(*per)]
    nominal = tuple(p[0] for p in per)
    return [nominal, *((*nominal[:i], r, *nominal[i + 1 :]) for i, p in enumerate(per) for r in p[1:])]


def evaluate(claim: Claim, *, bands: bool = True) -> Evaluation:
    """Compute a claim, its band and inputs, derive its verdict and check it against the expected one.

    The tolerance is resolved first, where no input can be read; then ``compute`` runs at the
    nominal inputs with every read recorded; then across each assumed input's range (the
    band, unless ``bands`` is false) and under every other admissible reading of each
    convention read (across the assumed ranges too, where the verdict needs it). The
    verdict follows the ledger's rules (:mod:`navcore.claims.verdict`); a discrepant claim's value
    must also agree with its independent oracle.

    Parameters
    ----------
    claim : Claim
        The claim to evaluate (registered or not).
    bands : bool, optional
        Evaluate across the assumed inputs' ranges (one at a time and at the corners of
        their box). ``False`` computes the nominal value only, so a claim that needs the band
        to agree gets a stricter verdict; the ledger always uses ``True``.

    Returns
    -------
    Evaluation
        The value, inputs, band, readings, derived verdict and whether it is the expected
        one. A failure of the tolerance, the computation, the band or the oracle does not
        raise: it is an evaluation with status ``"error"`` (or a failing check) whose
        ``detail`` says what raised.

    Examples
    --------
    >>> from navcore.claims import printed
    >>> from navcore.ledger import InputSet
    >>> IN = InputSet("SP", "doc_evaluate")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", reason="typical receivers")
    >>> value, tol = printed("12.5")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: 14.0 - IN.loss_db, tolerance=tol,
    ...           expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> ev.reproduced, ev.band, ev.status, ev.passes
    (12.0, (11.0, 13.0), 'consistent', True)
    >>> evaluate(c, bands=False).status  # 12 is outside 12.5 +- 0.05 at the nominal
    'inconsistent'

    A convention with two readings, of which only the other one agrees:

    >>> IN.convention("per_cycle_ft", 1.0, quantity="range per carrier cycle",
    ...               readings={"one foot per cycle": 1.0, "the L1 wavelength": 0.62},
    ...               reason="the text says both")
    >>> value, tol = printed("6.2")
    >>> c = Claim(id="SP-doc-peak", paper="SP", locator="Fig. 2.1", quantity="peak error",
    ...           published=value, unit="ft", compute=lambda: 10.0 * IN.per_cycle_ft,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> ev.status, [r["reading"]["SP.doc_evaluate.per_cycle_ft"] for r in ev.agreeing_readings]
    ('consistent', ['the L1 wavelength'])
    """
    try:
        tol = resolve_tolerance(claim)
    except Exception as exc:
        return Evaluation(
            claim,
            None,
            False,
            f"tolerance could not be resolved: {type(exc).__name__}: {exc}",
            status="error",
        )
    if claim.compute is None:
        ok = claim.expected_status == "not-reproducible"
        detail = (
            "not reproducible: " + claim.note
            if ok
            else "nothing is computed: the verdict is not-reproducible"
        )
        return Evaluation(claim, None, ok, detail, status="not-reproducible", tolerance=tol)
    try:
        value, reads = _run(claim)
    except Exception as exc:  # a claim whose computation fails is a failing claim
        return Evaluation(
            claim, None, False, f"compute raised {type(exc).__name__}: {exc}", status="error", tolerance=tol
        )

    read: list[Input] = [reads[k] for k in sorted(reads)]
    inputs = tuple(
        {
            "name": i.name,
            "provenance": i.provenance,
            ("locator" if i.provenance == "published" else "reason"): i.source(),
            "value": jsonable(i.value),
        }
        for i in read
    )
    assumed = [i for i in read if i.provenance == "assumed"]
    conventions = [i for i in read if i.provenance == "convention"]
    provenances: set[str] = {str(i.provenance) for i in read}
    admissible = bool(assumed) and all(i.admissible for i in assumed)
    run_bands = bool(assumed) and bands
    try:
        excluded: list[str] = []
        values, sensitivity = (
            _band_runs(claim, assumed, excluded=excluded, nominal=value) if run_bands else ([], [])
        )
        # beyond six inputs the corners are a sample of the box: what the inputs' separate
        # effects add up to bounds what the runs cannot rule out (verdict.py, "Beyond six inputs")
        sampled = run_bands and len(assumed) > MAX_CORNER_INPUTS
        envelope = additive_envelope(value, sensitivity) if sampled else None
        first = _outcome(claim, tol, value, values, envelope)
        # the other readings: their values always (they are shown); their bands only where the
        # readings used do not already agree with a band that decides
        combos = reading_combinations(conventions)[1:] if conventions else []
        others = []
        for combo in combos:
            overrides = {inp.name: v for inp, _, v in combo}
            others.append([combo, overrides, _run(claim, overrides)[0], [], None])
        # in order, until one agrees with a band that decides (the verdict is then settled)
        decided = first.agrees and not first.too_wide
        for other in others if run_bands else []:
            if decided:
                break
            other[3], other_sensitivity = _band_runs(
                claim, assumed, base=other[1], excluded=excluded, nominal=other[2]
            )
            other[4] = additive_envelope(other[2], other_sensitivity) if sampled else None
            o = _outcome(claim, tol, other[2], other[3], other[4])
            decided = o.agrees and not o.too_wide
    except Exception as exc:
        return Evaluation(
            claim,
            value,
            False,
            f"the band or a convention's other reading raised {type(exc).__name__}: {exc}",
            status="error",
            tolerance=tol,
            inputs=inputs,
        )
    band = (min([value, *values]), max([value, *values])) if assumed else None
    other_runs = [(v, vs, env) for _, _, v, vs, env in others]
    status = derive_status(claim, tol, value, values, provenances, admissible, other_runs, envelope)
    # a whole number's trailing zeros: the loose precision is weighed where the strict one does not agree
    loose = tol.loose() if status not in _AGREEMENT else None
    final_tol = tol
    if loose is not None:
        status = precision_status(
            derive_status(claim, loose, value, values, provenances, admissible, other_runs, envelope)
        )
        final_tol = loose
    readings: list[dict[str, Any]] = []
    if conventions or loose is not None:
        nominal_combo = tuple((inp, inp.nominal_label, inp.value) for inp in conventions)
        runs = [(nominal_combo, value, values, envelope, True)] + [
            (c, v, vs, env, False) for c, _, v, vs, env in others
        ]
        precisions = [(None, tol)] if loose is None else [(PRECISION_STRICT, tol), (PRECISION_LOOSE, loose)]
        for precision, t in precisions:
            for combo, v, vs, env, nominal in runs:
                o = first if nominal and t is tol else _outcome(claim, t, v, vs, env)
                reading = {inp.name: label for inp, label, _ in combo}
                if precision is not None:
                    reading[PRECISION_READING] = precision
                readings.append(
                    {
                        "reading": reading,
                        "nominal": nominal and t is tol,
                        "value": v,
                        "band": (min([v, *vs]), max([v, *vs])) if vs else None,
                        "agrees": o.agrees,
                        "band_too_wide": o.too_wide,
                        "undecided": o.undecided,
                    }
                )

    # not-reproducible: a band too wide to decide, or (beyond six inputs) a printed value the runs
    # do not reach and the inputs' separate effects add up to
    final = [
        (env, _outcome(claim, final_tol, v, vs, env))
        for v, vs, env in [(value, values, envelope), *other_runs]
    ]
    undecided = status == "not-reproducible" and not any(o.agrees for _, o in final)
    # the envelope that leaves it undecided: the reading used's, else the first other reading's
    undecided_envelope = next((env for env, o in final if o.undecided), None) if undecided else None
    left_out = tuple({"case": m, "runs": excluded.count(m)} for m in dict.fromkeys(excluded))
    common: dict[str, Any] = dict(
        status=status,
        tolerance=tol,
        inputs=inputs,
        band=band,
        sensitivity=tuple(sensitivity),
        readings=tuple(readings),
        band_too_wide=status == "not-reproducible" and not undecided,
        envelope=undecided_envelope,
        left_out=left_out,
    )
    if status != claim.expected_status:
        return Evaluation(
            claim,
            value,
            False,
            f"derived verdict {status!r} differs from the expected {claim.expected_status!r}",
            **common,
        )
    if status != "discrepant":
        return Evaluation(claim, value, True, f"derived verdict {status}", **common)
    # discrepant: an erratum, and the book's value must agree with its independent oracle
    if not claim.erratum or claim.oracle is None or claim.oracle_tolerance is None:
        return Evaluation(
            claim, value, False, "a discrepancy needs its erratum and an independent oracle", **common
        )
    try:
        with recording():
            oracle_value = _coerce(claim.oracle(), claim)
    except Exception as exc:
        return Evaluation(claim, value, False, f"oracle raised {type(exc).__name__}: {exc}", **common)
    if claim.is_statement:
        matches = oracle_value == value
    else:
        matches = abs(value - oracle_value) <= claim.oracle_tolerance.allowed(oracle_value)
    detail = (
        "discrepancy confirmed by an independent oracle"
        if matches
        else f"disagrees with its independent oracle ({oracle_value!r})"
    )
    return Evaluation(claim, value, matches, detail, oracle_value, **common)
