"""A claim's :class:`Evaluation`: its value, band, readings and verdict, and the note text that says them."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from navcore.claims.declarations import Claim, Erratum, claim_errata
from navcore.claims.inputs import _label_and_unit, get_input
from navcore.claims.json_coding import _json_value
from navcore.claims.quotes import claim_quote, label_prints_value, quote_numbers
from navcore.claims.tolerances import (
    PRECISION_LOOSE,
    PRECISION_READING,
    PRECISION_STRICT,
    Tolerance,
    _number_math,
)
from navcore.claims.verdict import BAND_FACTOR, MAX_CORNER_INPUTS, _is_truth, _outcome
from navcore.formatting import unit_text

__all__ = ["Evaluation", "left_out_of_band"]


@dataclass(frozen=True)
class Evaluation:
    """The result of evaluating one claim: its value, band, inputs and derived verdict.

    ``passes`` is true when the derived ``status`` equals the claim's ``expected_status``
    and, for a discrepancy, the erratum is named and the oracle agrees. Built by
    :func:`~navcore.claims.runs.evaluate`.

    Attributes
    ----------
    claim : Claim
        The claim evaluated.
    reproduced : float, bool or None
        The value computed at the nominal inputs, in the claim's unit (a truth value for a
        statement); ``None`` when nothing was computed or the computation failed.
    passes : bool
        Whether the derived verdict is the expected one (and, for a discrepancy, the
        oracle agrees).
    detail : str
        Why it passes or fails, in words.
    oracle_value : float, bool or None
        The independent oracle's value (discrepant claims only).
    status : str
        The derived verdict, one of :data:`~navcore.claims.declarations.STATUSES`, or ``"error"`` when the
        tolerance, the computation, the band or the oracle raised.
    tolerance : Tolerance or None
        The claim's tolerance as resolved before the computation.
    inputs : tuple of dict
        The inputs the computation read, sorted by name: ``name``, ``provenance``,
        ``locator`` (published) or ``reason`` (the others), and ``value``.
    band : tuple of (float, float) or None
        Lowest and highest value across the assumed inputs' ranges (with the nominal);
        ``None`` when no assumed input was read.
    sensitivity : tuple
        Per assumed input, ``(name, ((point, value), ...))``: the claim's value at each band
        point of that input, the others nominal.
    readings : tuple of dict
        One per combination of the readings of the conventions read (empty when none is
        read), the reading used first: ``reading`` (input name -> label of its reading),
        ``nominal`` (the reading used), ``value`` (at the nominal assumed inputs), ``band``
        (``[low, high]`` over the assumed ranges when the verdict needed it, else ``None``),
        ``agrees`` (whether the printed value is accepted by the value, or by the band when
        one was run) and ``band_too_wide``.
    band_too_wide : bool
        Whether the verdict is ``not-reproducible`` because every band that agrees is too
        wide to decide (:func:`~navcore.claims.verdict.band_too_wide`; each reading's own flag is
        in ``readings``).
    left_out : tuple of dict
        The band runs left out as outside the model's domain (:mod:`navcore.claims.runs`, "Band runs"),
        one per case in the order met: ``case`` (the reader's words of the
        :class:`~navcore.ModelDomainError`) and ``runs`` (how many runs met it).
    envelope : tuple of (float, float) or None
        Set when the verdict is ``not-reproducible`` because, with more than
        :data:`~navcore.claims.verdict.MAX_CORNER_INPUTS` assumed inputs, the runs do not reach the printed
        value while the inputs' separate effects add up to it
        (:func:`~navcore.claims.verdict.additive_envelope`, of the reading used if it is the one, else of the
        first other reading that is; its entry in ``readings`` has ``undecided`` true;
        :mod:`navcore.claims.verdict`, "Beyond six inputs"); else ``None``.

    Examples
    --------
    >>> from navcore.claims import evaluate, printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> ev.status, ev.passes, round(ev.deviation, 6), ev.printed
    ('reproduced', True, 0.001, '17.67')
    """

    claim: Claim
    reproduced: Any
    passes: bool
    detail: str
    oracle_value: Any = None
    status: str = "not-reproducible"
    tolerance: Tolerance | None = None
    inputs: tuple[dict[str, Any], ...] = ()
    band: tuple[Any, Any] | None = None
    sensitivity: tuple[tuple[str, tuple[tuple[Any, Any], ...]], ...] = ()
    readings: tuple[dict[str, Any], ...] = ()
    band_too_wide: bool = False
    left_out: tuple[dict[str, Any], ...] = ()
    envelope: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        # comparisons on numpy scalars give numpy booleans: store a plain bool
        object.__setattr__(self, "passes", bool(self.passes))

    @property
    def deviation(self) -> float | None:
        """``reproduced - published`` for numeric claims, else ``None``."""
        if self.claim.is_statement or self.reproduced is None:
            return None
        return float(self.reproduced) - float(self.claim.published)

    @property
    def kind(self) -> str:
        """The claim's kind (:data:`~navcore.claims.declarations.KINDS`)."""
        return str(self.claim.kind)

    @property
    def printed(self) -> str:
        """The paper's text the claim quotes (:func:`~navcore.claims.quotes.claim_quote`); ``""``
        when unknown."""
        return claim_quote(self.claim, self.tolerance)[0]

    @property
    def agreeing_readings(self) -> tuple[dict[str, Any], ...]:
        """The readings (of :attr:`readings`) under which the printed value is accepted."""
        return tuple(r for r in self.readings if r["agrees"])

    def _reading_words(self, reading: dict[str, Any]) -> list[str]:
        """What a reading changes from the one used, in words, one phrase per changed input:
        "the chip rate read as the P code (...)", or, for an input described by a clause rather
        than a noun ("how much ... must fall"), "a change of more than 1 % for how much ..."."""
        changed = []
        for name, label in reading["reading"].items():
            if name == PRECISION_READING:
                if label != PRECISION_STRICT:
                    changed.append(f"the printed number's {label}")
                continue
            quantity, in_unit = _label_and_unit(name)
            in_unit = _unit_text(in_unit)
            try:
                inp = get_input(name)
            except ValueError:
                inp = None
            if inp is not None and label == inp.nominal_label:
                continue
            value = next((v for lab, v in (inp.readings if inp else ()) if lab == label), None)
            # a tuple's items go inside the one pair of parentheses below
            items = value if isinstance(value, tuple | list) else () if value is None else (value,)
            shown = ", ".join(_plain(v) for v in items)
            if items and all(_label_prints(label, v) for v in items):
                shown = ""  # "the C/A code, 1.023 Mchip/s" says its value: not again in Hz
            shown = f" ({shown}{' ' + in_unit if in_unit and shown else ''})" if shown else ""
            words = reader_label(label) + shown
            if quantity.lower().startswith(_CLAUSE_WORDS):
                changed.append(f"{words} for {quantity}")
            else:
                changed.append(f"the {quantity} read as {words}")
        return changed

    def _note_digits(self) -> int:
        """Significant digits of the numbers a note's generated sentences print: the printed
        value's, plus two (:func:`note_digits`)."""
        tol = self.tolerance if isinstance(self.tolerance, Tolerance) else None
        return note_digits(self.claim, tol)

    def _num(self, value: Any) -> str:
        """A value of the claim in a generated sentence, at the claim's :meth:`_note_digits`."""
        return _plain(value, self._note_digits())

    def _range(self, lo: Any, hi: Any, unit: str) -> str:
        """``"lo to hi unit"``; ``""`` when the two ends print the same."""
        a, b = self._num(lo), self._num(hi)
        return "" if a == b else f"{a} to {b}{unit}"

    def _unit(self, value: Any = None) -> str:
        """The claim's unit after a number (" m"); a count unit in the singular after one."""
        if self.claim.unit in ("", "statement"):
            return ""
        unit = self.claim.unit
        if unit in COUNT_UNITS and value is not None and not isinstance(value, bool):
            try:
                if float(value) == 1:
                    unit = unit[:-1]
            except (TypeError, ValueError):
                pass
        return f" {_unit_text(unit)}"

    def _reading_outcome(self, reading: dict[str, Any]) -> str:
        """What one reading gives and whether it agrees: the text after "With ...: "."""
        value = reading["value"]
        band = reading.get("band")
        # a claim with assumed inputs whose band this reading did not need (the verdict was settled)
        at_nominal = " at the nominal inputs" if band is None and self.band is not None else ""
        if not _is_truth(value):
            text = self._num(value) + self._unit(value) + at_nominal
            if band is not None:
                spans = self._range(band[0], band[1], self._unit())
                text += f" (over the assumed ranges {spans})" if spans else ""
        elif band is None or bool(band[0]) == bool(band[1]):
            text = ("holds" if value else "does not hold") + (
                " across the assumed ranges" if band else at_nominal
            )
        else:
            text = (
                "holds at the nominal inputs, not across all the assumed ranges"
                if value
                else "does not hold at the nominal inputs, but holds over part of the assumed ranges"
            )
        if reading["agrees"]:
            at_value = band is None or self._agrees_at_value(reading)
            too_wide = band is not None and reading.get("band_too_wide", False)
            if at_value and not too_wide:
                text += ", which agrees with the printed value"
            elif at_value:
                text += "; the value agrees with the printed value, but the range is too wide to decide"
            elif _is_truth(value):
                text += "; only part of the assumed ranges agrees with the printed value"
            else:
                text += "; the value does not agree with the printed value, only part of that range does"
        return text

    def _agrees_at_value(self, reading: dict[str, Any]) -> bool:
        """Whether a reading's value itself (not its band) agrees with the printed value."""
        tol = self.tolerance if isinstance(self.tolerance, Tolerance) else None
        if tol is None:
            return bool(reading["agrees"])
        if reading["reading"].get(PRECISION_READING) == PRECISION_LOOSE:
            tol = tol.loose() or tol
        try:
            return _outcome(self.claim, tol, reading["value"], ()).agrees_at_value
        except (TypeError, ValueError):
            return bool(reading["agrees"])

    def _reading_text(self, reading: dict[str, Any]) -> str:
        """One reading other than the one used, in words: what differs and what it gives."""
        return (
            "With " + " and ".join(self._reading_words(reading)) + ": " + self._reading_outcome(reading) + "."
        )

    def inert_conventions(self) -> tuple[str, ...]:
        """The conventions read whose other readings change nothing, when the claim reads more
        than one (a cross product of readings to thin out): every reading that differs from
        another only in one of them gives the same value, band and agreement (an input the
        claim's computation reads on its way but whose reading does not reach the result).
        ``()`` when there is no reading used to compare with."""
        nominal = next((r for r in self.readings if r["nominal"]), None)
        if nominal is None:
            return ()
        names = list(nominal["reading"])
        if len(names) < 2:
            return ()
        inert = []
        for name in names:
            used = nominal["reading"][name]
            groups: dict[tuple, list[tuple[bool, tuple]]] = {}
            for r in self.readings:
                key = tuple(sorted((k, v) for k, v in r["reading"].items() if k != name))
                groups.setdefault(key, []).append((r["reading"].get(name) == used, _reading_result(r)))
            varied = [g for g in groups.values() if any(not is_used for is_used, _ in g)]
            if varied and all(any(is_used for is_used, _ in g) and _same_results(g) for g in varied):
                inert.append(name)
        return tuple(inert)

    def shown_readings(self) -> tuple[dict[str, Any], ...]:
        """The readings other than the one used that a reader is shown: those whose inert
        conventions (:meth:`inert_conventions`) keep their reading used."""
        nominal = next((r for r in self.readings if r["nominal"]), None)
        inert = self.inert_conventions()
        return tuple(
            r
            for r in self.readings
            if not r["nominal"]
            and all(r["reading"].get(n) == nominal["reading"][n] for n in inert if nominal is not None)
        )

    def _readings_sentences(self) -> list[str]:
        """The sentences on the other readings: one per reading shown, or one for all of them
        when every combination gives the same; then one naming the conventions whose readings
        change nothing (:meth:`inert_conventions`)."""
        shown = self.shown_readings()
        tails = [self._reading_outcome(r) for r in shown]
        nominal = next((r for r in self.readings if r["nominal"]), None)
        extra: list[str] = []
        if nominal is not None and len(shown) > 1 and len(set(tails)) == 1:
            labels = _other_labels(nominal, shown)
            if len(shown) == math.prod(len(ls) + 1 for ls in labels.values()) - 1:
                together = ", alone or together," if len(labels) > 1 else ""
                phrases = "; ".join(_alternatives_phrase(n, ls) for n, ls in labels.items())
                extra.append(f"The other readings{together} give the same ({tails[0]}): {phrases}.")
                shown = ()
        extra += [self._reading_text(r) for r in shown]
        inert = self.inert_conventions()
        if inert and nominal is not None:
            labels = _other_labels(nominal, [r for r in self.readings if not r["nominal"]], only=inert)
            phrases = "; ".join(_alternatives_phrase(n, ls) for n, ls in labels.items())
            # a reading whose band the verdict did not need was compared at the nominal inputs only
            kept = [id(r) for r in self.shown_readings()]
            folded = [r for r in self.readings if not r["nominal"] and id(r) not in kept]
            what = (
                "the result at the nominal inputs"
                if self.band is not None and any(r.get("band") is None for r in folded)
                else "the result"
            )
            if len(labels) > 1 or any(len(ls) > 1 for ls in labels.values()):
                # "together" only where the readings combine them (else each was run alone)
                combined = any(
                    sum(r["reading"].get(n) != nominal["reading"][n] for n in inert) > 1
                    for r in self.readings
                )
                together = (
                    (", alone or together," if combined else ", each alone,") if len(labels) > 1 else ""
                )
                extra.append(f"The other readings{together} leave {what} unchanged: {phrases}.")
            else:
                extra.append(f"The other reading leaves {what} unchanged: {phrases}.")
        return extra

    def note(self) -> str:
        """The claim's note, then what the other readings give and why the verdict is what it is.

        Generated sentences follow the note: one per reading other than the one used (what
        it gives, and whether it agrees); where the reading used disagrees and another
        agrees, that the claim is therefore not discrepant; where the band is too wide, that
        the assumptions are too loose to decide.
        """
        text = self.claim.note.rstrip()
        extra = self._readings_sentences()
        nominal = next((r for r in self.readings if r["nominal"]), None)
        if (
            self.status == "consistent"
            and nominal is not None
            and not nominal["agrees"]
            and any(r["agrees"] for r in self.readings)
        ):
            extra.append(
                "The reading used disagrees and another admissible reading agrees: an open reading "
                "of the text, not a discrepancy."
            )
        if self.band_too_wide and self.band is not None:
            lo, hi = self.band
            unit = self._unit()
            if self.claim.is_statement:
                extra.append(
                    ("It" if nominal is None or nominal["agrees"] else "The reading that agrees")
                    + " holds for some of the assumed inputs and fails for others: the assumptions "
                    "are too loose to decide."
                )
            elif nominal is None or nominal["agrees"]:
                extra.append(
                    "Over the assumed inputs' ranges the value spans "
                    f"{self._num(lo)} to {self._num(hi)}{unit}, "
                    f"ends more than a factor {BAND_FACTOR:g} apart, and the printed value agrees with "
                    "only part of it: the assumptions are too loose to decide."
                )
            else:
                extra.append(
                    "The reading that agrees does so over only part of a band whose ends are more than "
                    f"a factor {BAND_FACTOR:g} apart: the assumptions are too loose to decide."
                )
        if self.envelope is not None and self.band is not None:
            unit = self._unit()
            n = sum(1 for i in self.inputs if i["provenance"] == "assumed")
            other = next((r for r in self.readings if r.get("undecided") and not r["nominal"]), None)
            if other is not None and not any(r.get("undecided") and r["nominal"] for r in self.readings):
                who = " and ".join(self._reading_words(other))
                lead = f"With {who}, the runs over the {n} assumed inputs do not reach the printed value"
            else:
                lead = f"The runs over the {n} assumed inputs do not reach the printed value"
            extra.append(
                f"{lead}, but the inputs' "
                "separate effects add up to "
                f"{self._num(self.envelope[0])} to {self._num(self.envelope[1])}{unit}, "
                f"which does: beyond {MAX_CORNER_INPUTS} inputs the corners run are a sample of the box, "
                "so the search cannot show the printed value out of reach."
            )
        if self.left_out:
            extra.append(
                "The band leaves out, as outside the model's domain, "
                + "; ".join(f"{_n_runs(c['runs'])} where {c['case']}" for c in self.left_out)
                + "."
            )
        if text and extra and not text.endswith((".", "!", "?", ")")):
            text += "."
        return " ".join([text, *extra]).strip()

    def as_json(self, errata: Sequence[Erratum] | None = None) -> dict[str, Any]:
        """The ledger's fields, and no others.

        Parameters
        ----------
        errata : sequence of Erratum or None, optional
            Where to look for the errata the claim is evidence for
            (:func:`~navcore.claims.declarations.claim_errata`); ``None`` for every erratum constructed in the
            process.
        """
        c = self.claim
        pub = c.published if isinstance(c.published, bool) else float(c.published)
        tol = self.tolerance if self.tolerance is not None else c.tolerance
        quote = claim_quote(c, tol if isinstance(tol, Tolerance) else None)[0]
        return {
            "id": c.id,
            "paper": c.paper,
            "locator": c.locator,
            "quantity": c.quantity,
            "published": pub,
            "relation": c.relation,
            "unit": c.unit,
            "printed": quote or None,
            "errata": claim_errata(c, errata),
            "kind": c.kind,
            "inputs": [dict(i) for i in self.inputs],
            "reproduced": _json_value(self.reproduced),
            "band": None if self.band is None else [_json_value(b) for b in self.band],
            "readings": [
                {
                    "reading": dict(r["reading"]),
                    "nominal": bool(r["nominal"]),
                    "value": _json_value(r["value"]),
                    "band": None if r.get("band") is None else [_json_value(b) for b in r["band"]],
                    "agrees": bool(r["agrees"]),
                    "band_too_wide": bool(r.get("band_too_wide", False)),
                }
                for r in self.readings
            ],
            "tolerance": tol.as_dict() if isinstance(tol, Tolerance) else None,
            "status": self.status,
            "note": self.note(),
        }


def _unit_text(unit: str) -> str:
    """A unit as a reader sees it in a note (:func:`navcore.formatting.unit_text`: ``m³/s²``,
    not ``m^3/s^2``)."""
    return unit_text(unit) if unit else unit


def _plain(value: Any, digits: int = 6) -> str:
    r"""A value in a note's text: ``digits`` significant digits (six unless a claim's note asks
    for its own, :func:`note_digits`), a very large or small number as inline math (never a
    program's ``1.023e+06`` or a string of zeros such as ``0.00094007``), an infinite one as
    the symbol.

    Examples
    --------
    >>> _plain(1023000.0), _plain(0.00094007), _plain(0.0226556), _plain(2.5), _plain(True)
    ('$1.023 \\times 10^{6}$', '$9.4007 \\times 10^{-4}$', '0.0226556', '2.5', 'true')
    >>> _plain(0.00353918)
    '$3.53918 \\times 10^{-3}$'
    >>> _plain(72.4315, 4), _plain(476.476, 4), _plain(float("inf")), _plain(-float("inf"))
    ('72.43', '476.5', '∞', '−∞')

    A tuple (a reading that sets several numbers) lists its items, each written the same way:

    >>> _plain((6, 4, 55.0, 0.0))
    '(6, 4, 55, 0)'
    """
    if isinstance(value, tuple | list):
        return "(" + ", ".join(_plain(v, digits) for v in value) + ")"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if math.isinf(value):
            return "∞" if value > 0 else "−∞"
        if 1 <= abs(value) < 1e6:  # every digit before the point, never 1.2e+03 for 1234.5
            digits = max(digits, math.floor(math.log10(abs(value))) + 1)
        text = f"{value:.{digits}g}"
        if value != 0 and abs(value) < 1e-2 and "e" not in text:  # else eight decimals or more
            mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
            text = mantissa.rstrip("0").rstrip(".") + "e" + exponent
        return _number_math(text)
    return str(value)


def note_digits(claim: Claim, tol: Tolerance | None = None) -> int:
    """Significant digits of the numbers in a claim's generated sentences: those of the
    printed number plus two, between 3 and 6 (4 for a statement). The printed number's digits
    are counted as printed when its tolerance was fixed from them; else they are those its
    tolerance resolves (an absolute half unit, or a relative one: 10 % is one digit); else
    those of the published value.

    Examples
    --------
    >>> from navcore.claims import printed
    >>> value, tol = printed("11")
    >>> c = Claim(id="SP-doc-digits", paper="SP", locator="T", quantity="q", published=value,
    ...           unit="m", compute=lambda: 1.0, tolerance=tol, expected_status="reproduced", note="n")
    >>> note_digits(c, tol), note_digits(c, printed("5.250")[1]), note_digits(c, printed("0.5")[1])
    (4, 6, 3)
    """
    if claim.is_statement or isinstance(claim.published, bool):
        return 4
    pub = abs(float(claim.published))
    source = claim_quote(claim, tol)[1] if tol is not None else "none"
    if source == "digits" and tol is not None:
        number = re.search(r"\d[\d.]*", tol.quote.replace(" ", ""))
        sig = len((number.group(0) if number else "").replace(".", "").lstrip("0"))
    elif tol is not None and tol.abs and pub > 0:
        sig = math.floor(math.log10(pub)) - math.floor(math.log10(2 * tol.abs)) + 1
    elif tol is not None and tol.rel:
        sig = max(1, -math.floor(math.log10(tol.rel)))
    else:
        sig = len(f"{pub:.6g}".split("e")[0].replace(".", "").lstrip("0").rstrip("0"))
    return min(6, max(3, sig + 2))


#: Plural count units that read in the singular after exactly one ("1 interval").
COUNT_UNITS = ("states", "channels", "satellites", "entries", "cases", "intervals", "lists", "units", "runs")


#: Words that open a clause rather than a noun phrase: an input described so ("how much the
#: velocity error must fall ...") is named after its reading, not after "the".
_CLAUSE_WORDS = ("how ", "what ", "whether ", "which ", "when ", "where ", "why ", "who ")


def reader_label(label: str) -> str:
    """A reading's label as a generated sentence shows it: "the prose table" named for a
    reader, as the ledger page names it.

    Examples
    --------
    >>> reader_label("within 10 %, the prose table's 'nearly'")
    "within 10 % ('nearly' in the ledger's table of prose words)"
    >>> reader_label("2 to 5 s, the prose table's reading")
    "2 to 5 s, the reading of the ledger's table of prose words"
    """
    label = re.sub(r",? the prose table's ('[^']*')", r" (\1 in the ledger's table of prose words)", label)
    label = label.replace("the prose table's reading", "the reading of the ledger's table of prose words")
    return label.replace("the prose table", "the ledger's table of prose words")


def _input_or_none(name: str) -> Any:
    try:
        return get_input(name)
    except ValueError:
        return None


def _quantity_phrase(name: str) -> str:
    """An input named in a sentence: "the chip rate", or its clause as it stands."""
    quantity = _label_and_unit(name)[0]
    return quantity if quantity.lower().startswith(_CLAUSE_WORDS) else f"the {quantity}"


def _other_labels(
    nominal: dict[str, Any], readings: Sequence[dict[str, Any]], only: Sequence[str] | None = None
) -> dict[str, list[str]]:
    """Per input, the labels other than the one used that the readings give it, in order."""
    labels: dict[str, list[str]] = {}
    for r in readings:
        for name, label in r["reading"].items():
            if (only is None or name in only) and label != nominal["reading"].get(name, PRECISION_STRICT):
                labels.setdefault(name, [])
                if label not in labels[name]:
                    labels[name].append(label)
    return labels


def _alternatives_phrase(name: str, labels: Sequence[str]) -> str:
    """An input and its other readings in words: "the chip rate read as the P code or as ...",
    or "x or y for how much ..." for an input described by a clause."""
    if name == PRECISION_READING:  # "trailing zeros not significant": taken so
        return "the printed number's " + " or ".join(
            lab.replace("trailing zeros ", "trailing zeros taken as ", 1) for lab in labels
        )
    words = [reader_label(lab) for lab in labels]
    quantity = _label_and_unit(name)[0]
    if quantity.lower().startswith(_CLAUSE_WORDS):
        return " or ".join(words) + f" for {quantity}"
    return f"the {quantity} read as " + " or as ".join(words)


def _label_prints(label: str, value: Any) -> bool:
    """Whether a reading's label prints this one of its values, as far as a reader can tell:
    :func:`~navcore.claims.quotes.label_prints_value`, or one of the label's numbers (times a
    power of 1000) within its last printed digits of the value (0.98357 ft/ns for 0.983571), or
    a zero the label prints; a code word (a string) is never shown, so it counts as printed."""
    if isinstance(value, str):
        return True
    if isinstance(value, bool) or not isinstance(value, int | float):
        return False
    if value == 0:
        return 0.0 in quote_numbers(label)
    target = float(value)
    return label_prints_value(label, value) or any(
        abs(n * 1000.0**k - target) <= 5e-6 * abs(target) for n in quote_numbers(label) for k in range(-4, 5)
    )


def _same_results(group: list[tuple[bool, tuple]]) -> bool:
    """Whether readings give the same (:func:`_reading_result`): the same value and agreement,
    and the same band and band flag among those that ran one (a reading whose band the verdict
    did not need has none)."""
    results = [res for _, res in group]
    banded = [r for r in results if r[1] is not None]
    return (
        len({(r[0], r[2]) for r in results}) == 1
        and len({r[1] for r in banded}) <= 1
        and len({r[3] for r in banded}) <= 1
    )


def _reading_result(reading: dict[str, Any]) -> tuple:
    """What a reading gives, comparable: value, band, agreement and band flag."""

    def key(v: Any) -> Any:
        try:
            return _json_value(v)
        except (TypeError, ValueError):
            return repr(v)

    band = reading.get("band")
    return (
        key(reading["value"]),
        None if band is None else tuple(key(b) for b in band),
        bool(reading["agrees"]),
        bool(reading.get("band_too_wide", False)),
    )


def _n_runs(n: int) -> str:
    """``"1 run"``, ``"3 runs"``: a count of band runs in words.

    Examples
    --------
    >>> _n_runs(1), _n_runs(3)
    ('1 run', '3 runs')
    """
    return f"{n} run{'' if n == 1 else 's'}"


def left_out_of_band(ev: Evaluation) -> str:
    """The band runs an evaluation left out as outside the model's domain, in words ("" if none).

    Parameters
    ----------
    ev : Evaluation
        An evaluation (its ``left_out`` field).

    Returns
    -------
    str
        Each case left out and how many runs met it, ``"; "``-separated.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> left_out_of_band(SimpleNamespace(left_out=()))
    ''
    >>> left_out_of_band(SimpleNamespace(left_out=({"case": "no fix", "runs": 2},)))
    'no fix (2 runs)'
    """
    return "; ".join(f"{c['case']} ({_n_runs(c['runs'])})" for c in ev.left_out)
