"""Survivors of the ledger's seeded mutation sample (300 of 8652 mutants, seed 25; issue 31).

Each test pins one behaviour that a surviving mutant changed; its oracle is named in its
docstring (widths summed by hand from the metric table ``_EM``, units and texts written by hand,
the documented contract of a function). Nothing here evaluates a registered claim.
"""

from __future__ import annotations

import dataclasses
import sys
import types

import pytest

from navcore.claims.inputs import InputSet
from navcore.claims.json_coding import jsonable
from navcore.claims.run_store import RunMemo, RunStore
from navcore.formatting import number_formatter, unit_text
from navcore.ledger.summary import findings_phrase
from navcore.ledger.text import _text_em, math_breaks, math_em, quote_below, quote_math


def test_input_set_records_the_module_that_makes_it(monkeypatch):
    """Oracle: the documented rule of ``_declaring_module`` (the caller of ``InputSet.__init__``).

    A synthetic module's function makes the set and this test calls that function: the set
    belongs to the synthetic module, not to the test that called its maker.
    """
    module = types.ModuleType("synthetic_paper_s25")
    source = "from navcore.claims.inputs import InputSet\ndef make():\n    return InputSet('S25', 'made')\n"
    exec(source, module.__dict__)
    monkeypatch.setitem(sys.modules, module.__name__, module)
    made = module.make()
    assert object.__getattribute__(made, "_module") == "synthetic_paper_s25"
    direct = InputSet("S25", "direct")
    assert object.__getattribute__(direct, "_module") == __name__


def test_round_trip_keeps_keys_as_they_are():
    """Oracle: ``jsonable``'s docstring: for a round trip, keys are kept as they are; for a
    reader, a key is text."""
    assert jsonable({1: 0.5, "a": 2}, round_trip=True) == {1: 0.5, "a": 2}
    assert jsonable({1: 0.5}) == {"1": 0.5}


@dataclasses.dataclass
class _Run:
    value: float


def test_batched_bound_is_named_exactly(tmp_path):
    """Oracle: the message written by hand, ``rows_per_call must be at least 1`` (the existing
    test's ``match`` also accepts a name with text around it)."""
    memo = RunMemo(RunStore("runs", modules=("navcore.units",), root=tmp_path), _Run, size=2)
    with pytest.raises(ValueError, match=r"^rows_per_call must be at least 1, got 0$"):
        memo.get_or_run_batched(
            [1],
            key=str,
            label=lambda s: "demo",
            group=lambda s: 0,
            rows=lambda s: 1,
            run_batch=lambda items: [_Run(float(i)) for i in items],
            rows_per_call=0,
        )


def test_number_formatter_default_is_three_significant_digits():
    """Oracle: the docstring's example, 1.6344... shown as ``1.63`` (three digits), by hand."""
    assert number_formatter()(1.6344416666666666) == "1.63"


def test_formula_units_with_a_root_and_a_power_of_ten():
    """Oracle: the LaTeX written by hand: a root's unit stays upright (``\\mathrm``) inside
    ``\\sqrt`` even in a formula, whose letters are italic; a number's power is a superscript."""
    assert unit_text("N tau_c / sqrt(Hz)") == r"$N \tau_{c} / \sqrt{\mathrm{Hz}}$"
    assert unit_text("N tau_c / 10^8") == r"$N \tau_{c} / 10^{8}$"


def test_findings_phrase_plural():
    """Oracle: English, by hand: ``2 findings`` (the one-finding case is the docstring's)."""
    from navcore.ledger import Erratum

    items = [
        Erratum(id=f"SP-E{i}-doc", paper="SP", locator="Eq. (1)", printed="m", finding="km",
                evidence="the scale", kind="units", basis="text-only")
        for i in (7, 8)
    ]  # fmt: skip
    assert findings_phrase(items) == "2 findings: 2 text-only (2 units)"


def test_text_widths_by_hand():
    """Oracle: ``_EM`` summed by hand: a capital 0.72, a lower-case letter 0.5 (``text``), a
    space 0.25; ``\\text`` joins its tokens (no space) and adds nothing else."""
    assert _text_em("A b") == pytest.approx(0.72 + 0.25 + 0.5)
    assert math_em(r"\text{Ab}") == pytest.approx(0.72 + 0.5)


@pytest.mark.parametrize(
    ("tex", "width"),
    [
        (r"\Gamma", 0.72),  # a Greek capital
        (r"\alpha", 0.58),  # a lower-case Greek letter
        (r"^{2}", 0.71 * 0.5 + 0.05),  # a script with no base: the script at 71 % and 0.05
        (r"\substack{a \\ bc}", 2 * 0.52),  # the wider row, b c
        (r"a & b", 2 * 0.52),  # an alignment tab sets no glyph
        # a matrix in a matrix's first cell: two columns (0.52 each), 1 em apart; no fence
        (r"\begin{matrix} \begin{matrix} a \end{matrix} & b \end{matrix}", 0.52 + 1.0 + 0.52),
    ],
)
def test_math_widths_by_hand(tex, width):
    """Oracle: Computer Modern widths of ``_EM`` summed by hand for each formula."""
    assert math_em(tex) == pytest.approx(width)


def test_envelope_lead_names_only_an_undecided_other_reading():
    """Oracle: ``Evaluation.note``'s rule, sentences written by hand: the envelope sentence's
    lead names another reading only when that reading is undecided; a decided other reading
    (listed first) is not named."""
    from test_ledger_mutation_note import NAME, OTHER, USED, ev, reading

    inputs = ({"name": "x", "provenance": "assumed"}, {"name": "p", "provenance": "published"})
    kw = dict(band=(1.0, 90.0), envelope=(0.5, 150.0), inputs=inputs, status="not-reproducible")
    tail = "runs over the 1 assumed inputs do not reach the printed value, but the inputs' "
    decided = (reading(USED, 2.0, nominal=True), reading(OTHER, 20.0))
    assert ". The " + tail in ev(readings=decided, **kw).note()
    code = {NAME + "code": "the other reading"}
    both = (*decided, reading(code, 30.0, undecided=True))
    lead = "With the chip rate read as the other reading ($1.023 \\times 10^{7}$ Hz), the " + tail
    assert lead in ev(readings=both, **kw).note()


def test_math_breaks_after_a_right_delimiter_and_inside_brackets():
    """Oracle: ``math_breaks``'s docstring examples, cut by hand at the outer relations and
    operators (after ``\\right|``'s delimiter the scan goes on; with ``brackets``, inside the
    outermost bracket only, not inside ``(k-1)``)."""
    assert math_breaks(r"\left| a - b \right| = -c + d^{-1}") == [
        r"\left| a - b \right| ={}",
        "-c +{}",
        "d^{-1}",
    ]
    assert math_breaks(r"[a(k-1) + b_1 + c_2]^{-1}", brackets=True) == ["[a(k-1) +{}", "b_1 +{}", "c_2]^{-1}"]


def test_math_breaks_never_after_a_subscript_sign():
    """Oracle: TeX's rule, by hand: the ``-`` of ``\\sigma_-`` is a subscript, not a binary
    operator, so no piece ends after it; the pieces still read as the whole formula."""
    tex = r"\sigma_- = a_1 b_1 + a_2 b_2"
    pieces = math_breaks(tex)
    assert not any(p.endswith("_-{}") for p in pieces)
    assert " ".join(p.removesuffix("{}") for p in pieces).split() == tex.split()


def test_quote_math_closes_two_unopened_groups_in_order():
    """Oracle: the opening written by hand: a quote that begins inside ``\\left( ... {`` gets
    the empty ``\\left.`` and then the brace, outermost first."""
    assert quote_math(r"x} \right) = 2") == r"\left.{x} \right) = 2"


def test_quote_below_only_when_strictly_wider_than_the_bound():
    """Oracle: ``quote_below``'s docstring ("wider than 17.5 em") and ``_EM`` by hand: 35 digits
    are 35 x 0.5 = 17.5 em exactly (binary-exact), not wider; 36 digits are 18 em."""
    assert quote_below("$" + "1" * 35 + "$") is False
    assert quote_below("$" + "1" * 36 + "$") is True
