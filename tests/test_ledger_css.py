"""The interactive ledger fits its page: the stylesheet's column shares add up to at most
100 % (issue 32 item 1), and every column the renderer writes has a share.

Oracle: the stylesheet's own text, parsed here independently of the renderer; the layout
itself is measured in Chromium by the layout gate (``nox -s layout``).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from navcore.ledger import Claim, evaluate, printed
from navcore.ledger.interactive import InteractiveLedger

CSS = Path(__file__).resolve().parents[1] / "book" / "_static" / "navcore.css"
WIDTH = re.compile(r'table\.ledger-interactive th\[data-key="(\w+)"\]\s*\{\s*width:\s*([\d.]+)%;?\s*\}')


def column_shares(css: str) -> dict[str, float]:
    """Each interactive-ledger column's width share in percent, as the stylesheet sets it.

    A rule that gives one column two widths, a width that is not in percent or a selector
    list the pattern does not read fails, so that no share hides from the sum.
    """
    shares: dict[str, float] = {}
    for key, share in WIDTH.findall(css):
        if key in shares:
            raise ValueError(f"column {key!r} has two widths in the stylesheet")
        shares[key] = float(share)
    rules = re.findall(r"table\.ledger-interactive th\[data-key=[^{]*\{[^}]*width[^}]*\}", css)
    if len(rules) != len(shares):
        raise ValueError(f"{len(rules)} width rules but {len(shares)} read: one width per rule, in %")
    return shares


def ledger_html(*, with_band: bool = False) -> str:
    """A two-claim ledger; ``with_band`` gives the first a band, so the second's band is empty."""
    value, tol = printed("17.67")
    evals = [
        evaluate(
            Claim(
                id=f"SP-test-columns-{i}", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
                published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
                expected_status="reproduced", note="a synthetic claim", kind="reproduction",
            )
        )
        for i in (1, 2)
    ]  # fmt: skip
    table = InteractiveLedger(evals)
    if with_band:
        table.records[0]["band"] = [17.0, 18.0]
    return table._repr_html_()


def test_column_shares_add_up_to_at_most_the_text_column():
    shares = column_shares(CSS.read_text(encoding="utf-8"))
    total = sum(shares.values())
    assert total <= 100.0 + 1e-9, f"the ledger's columns take {total} % of the text column: {shares}"


def test_every_column_has_a_share():
    shares = column_shares(CSS.read_text(encoding="utf-8"))
    keys = set(re.findall(r'<th data-key="(\w+)"', ledger_html())) | {"band"}  # band: when a claim has one
    assert keys <= set(shares), f"columns without a width share: {sorted(keys - set(shares))}"


@pytest.mark.parametrize(
    ("css", "message"),
    [
        ('table.ledger-interactive th[data-key="id"] { width: 60%; }\n'
         'table.ledger-interactive th[data-key="quantity"] { width: 50%; }', None),
        ('table.ledger-interactive th[data-key="id"] { width: 10em; }', "one width per rule"),
        ('table.ledger-interactive th[data-key="id"] { width: 10%; }\n'
         'table.ledger-interactive th[data-key="id"] { width: 20%; }', "two widths"),
    ],
)  # fmt: skip
def test_the_gate_catches_an_overfull_or_unreadable_stylesheet(css, message):
    if message is None:
        assert sum(column_shares(css).values()) > 100
    else:
        with pytest.raises(ValueError, match=message):
            column_shares(css)


def test_cards_leave_out_empty_fields_and_offer_a_sort_menu():
    html = ledger_html(with_band=True)
    assert "<select data-sort>" in html and "data-sort-dir" in html
    cells = re.findall(r'<td class="([^"]*)" data-label="([^"]*)">(.*?)</td>', html)
    assert ("ledger-col-band ledger-empty", "Band", "") in cells  # the second claim has no band
    assert all(("ledger-empty" in attrs) == (body == "") for attrs, _, body in cells)
    css = CSS.read_text(encoding="utf-8")
    assert re.search(r"td\.ledger-empty[^{]*\{\s*display:\s*none", css)


def test_a_claims_long_quantity_formula_wraps_in_its_column():
    """Oracle: the quantity's formula cut by hand after its relation, in a box of its own whose
    pieces wrap in the narrow column (and are set smaller by the book's equation fitting); a
    short formula stays inline."""
    value, tol = printed("17.67")
    long = r"\mathbf{P}_{NG} = \mathbf{H}^T \mathbf{W} \mathbf{H}"
    quantities = (f"the block ${long}$ holds", "a gain $K_1 < 2$")
    evals = [
        evaluate(
            Claim(
                id=f"SP-test-quantity-{i}", paper="SP", locator="Eq. (1)", quantity=q,
                published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
                expected_status="reproduced", note="a synthetic claim", kind="reproduction",
            )
        )
        for i, q in enumerate(quantities)
    ]  # fmt: skip
    html = InteractiveLedger(evals)._repr_html_()
    m = '<span class="math notranslate nohighlight">'
    assert (
        f'the block <span class="ledger-math-wide">{m}\\(\\mathbf{{P}}_{{NG}} ={{}}\\)</span><wbr>'
        f"{m}\\(\\mathbf{{H}}^T \\mathbf{{W}} \\mathbf{{H}}\\)</span></span> holds<details>"
    ) in html
    assert f"a gain {m}\\(K_1 &lt; 2\\)</span><details>" in html
