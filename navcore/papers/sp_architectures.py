"""SP Sections 2.1-2.2: the state vectors of the receiver and the two integration filters.

Published inputs are the component rows of Tables 2.1-2.3; the totals and each printed cell
(the state count of one block) are claims, computed from the layouts of
:mod:`navcore.gnss.architectures`.
"""

from __future__ import annotations

from navcore.claims import EXACT, Claim, InputSet, with_quotes
from navcore.gnss.architectures import (
    loosely_coupled_layout,
    receiver_pva_layout,
    tightly_coupled_layout,
)
from navcore.papers.sp_quotes import QUOTES

#: Table rows as printed (state element, components).
_TABLE_2_1 = (
    ("Position", 3),
    ("Velocity", 3),
    ("Acceleration", 3),
    ("User clock bias", 1),
    ("User clock drift", 1),
    ("Altimeter bias", 1),
)
_TABLE_2_2 = (
    ("Position", 3),
    ("Velocity", 3),
    ("Misalignment", 3),
    ("Gyro drift", 3),
    ("Gyro scale factor", 3),
    ("Accel. bias", 3),
    ("Accel. scale factor", 3),
    ("Altimeter bias", 1),
)
_TABLE_2_3 = (
    ("Position", 3),
    ("Velocity", 3),
    ("User clock bias", 1),
    ("User clock drift", 1),
    ("Misalignment", 3),
    ("Gyro drift", 3),
    ("Gyro scale factor", 3),
    ("Accel. bias", 3),
    ("Accel. scale factor", 3),
    ("Altimeter bias", 1),
)


IN = InputSet("SP", "architectures")
IN.published("table_2_1", _TABLE_2_1, locator="Table 2.1", quantity="receiver PVA filter states (rows)")
IN.published("table_2_2", _TABLE_2_2, locator="Table 2.2", quantity="loosely coupled filter states (rows)")
IN.published("table_2_3", _TABLE_2_3, locator="Table 2.3", quantity="tightly coupled filter states (rows)")


#: The library layouts' block names for the printed row labels that differ (lower case).
_NORM = {
    "gyro drift": "gyro bias",  # the paper's name for the gyro bias block
    "user clock bias": "clock bias",
    "user clock drift": "clock drift",
    "accel. bias": "accel bias",
    "accel. scale factor": "accel scale factor",
}


def _layout_size(layout, rows: tuple[tuple[str, int], ...]) -> int:
    """The layout's state count, after checking that its blocks are the printed rows, in order,
    with the printed sizes."""
    printed_rows = [(_NORM.get(n.lower(), n.lower()), k) for n, k in rows]
    if printed_rows != [(n.lower(), k) for n, k in layout.table()]:
        raise ValueError("the library layout does not have the printed rows")
    return layout.size


def _tight_within_loose_cascade() -> bool:
    tight = tightly_coupled_layout()
    return tight.issubset(receiver_pva_layout().union(loosely_coupled_layout()))


# --- Tables 2.1-2.3: one claim per printed cell ------------------------------------------
PAGE = "sp/01-architectures"

_TABLES = {
    "2.1": ("table_2_1", receiver_pva_layout, "the GPS receiver's PVA filter"),
    "2.2": ("table_2_2", loosely_coupled_layout, "the loosely coupled integration filter"),
    "2.3": ("table_2_3", tightly_coupled_layout, "the tightly coupled integration filter"),
}
#: printed rows (row label, printed count) per table; the same rows are the published inputs
#: ``table_2_x`` (the claims read the row labels there)
_ROWS = {
    "2.1": _TABLE_2_1,
    "2.2": _TABLE_2_2,
    "2.3": _TABLE_2_3,
}


def _slug(label: str) -> str:
    return label.lower().replace(".", "").replace(" ", "-")


def layout_block_size(table: str, row: int) -> int:
    """Size of the layout block named by printed row ``row`` of Table ``table`` (the row
    label is read from the published input; the count comes from the library layout)."""
    name, layout, _ = _TABLES[table]
    label = getattr(IN, name)[row][0]
    key = _NORM.get(label.lower(), label.lower())
    sizes = dict(layout().table())
    return int(sizes[key])


def _state_claim(table: str, row: int) -> Claim:
    label, count = _ROWS[table][row]
    return Claim(
        id=f"SP-tab{table}-{_slug(label)}",
        locator=f"Table {table}",
        quantity=f"states of the '{label}' block of {_TABLES[table][2]}",
        published=count,
        unit="states",
        compute=lambda t=table, r=row: layout_block_size(t, r),
        tolerance=EXACT,
        expected_status="reproduced",
        note="Block size of the library's state layout used by the SP mission and flyby runs (the "
        "integration architectures), looked up by the printed row label.",
        discussed_in=PAGE,
    )


CLAIMS = [
    Claim(
        id="SP-tab2.1-total",
        locator="Table 2.1",
        quantity="number of states of the GPS receiver's PVA filter",
        published=12,
        unit="states",
        compute=lambda: _layout_size(receiver_pva_layout(), IN.table_2_1),
        tolerance=EXACT,
        expected_status="reproduced",
        note="Sum of the block sizes of the receiver layout (PVA + clock + altimeter bias), "
        "whose rows match the printed rows. The table's caption is lost in the source text.",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-tab2.2-total",
        locator="Table 2.2",
        quantity="number of error states of the loosely coupled integration filter",
        published=22,
        unit="states",
        compute=lambda: _layout_size(loosely_coupled_layout(), IN.table_2_2),
        tolerance=EXACT,
        expected_status="reproduced",
        note="INS core (9) + IMU errors (12) + altimeter bias (1); no clock states, which "
        "live in the receiver's filter.",
        discussed_in=PAGE,
    ),
    Claim(
        id="SP-tab2.3-total",
        locator="Table 2.3",
        quantity="number of error states of the tightly coupled integration filter",
        published=24,
        unit="states",
        compute=lambda: _layout_size(tightly_coupled_layout(), IN.table_2_3),
        tolerance=EXACT,
        expected_status="reproduced",
        note="The loosely coupled states plus user clock bias and drift.",
        discussed_in=PAGE,
    ),
    Claim.statement(
        id="SP-sec2.2-same-states",
        locator="Sec. 2.2",
        quantity="the tightly coupled states all appear in the cascaded loosely coupled filters",
        compute=_tight_within_loose_cascade,
        note="Set inclusion of the Table 2.3 blocks in the union of the Table 2.1 and 2.2 "
        "blocks, with equal block sizes.",
        discussed_in=PAGE,
    ),
    *(_state_claim(t, r) for t in ("2.1", "2.2", "2.3") for r in range(len(_ROWS[t]))),
    Claim.statement(
        id="SP-sec2.1-fixes-decorrelated",
        locator="Sec. 2.1",
        quantity="receiver position solutions 10 s apart are not significantly correlated",
        compute=None,
        expected_status="not-reproducible",
        note="The statement is about the magnitude of the receiver filter's process noise, which Sec. 2.1 "
        "(Table 2.1) does not give; any value the book assumed would decide the answer by itself.",
        discussed_in=PAGE,
    ),
]

CLAIMS = with_quotes(CLAIMS, QUOTES)
