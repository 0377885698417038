"""SP Sections 2.1-2.2: the state vectors of the receiver and the two integration filters.

Published inputs are the component rows of Tables 2.1-2.3; the totals are claims, computed
from the layouts of :mod:`navcore.gnss.architectures`.
"""

from __future__ import annotations

from navcore.claims import EXACT, Claim, InputSet
from navcore.gnss.architectures import (
    loosely_coupled_layout,
    receiver_pva_layout,
    tightly_coupled_layout,
)
from navcore.papers.sp_quotes import quoted

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


def _printed_rows_match_layout(rows: tuple[tuple[str, int], ...], layout_rows: list[tuple[str, int]]) -> bool:
    """The layout has the printed rows, in order, with the printed sizes."""
    norm = {
        "gyro drift": "gyro bias",  # the paper's name for the gyro bias block
        "user clock bias": "clock bias",
        "user clock drift": "clock drift",
        "accel. bias": "accel bias",
        "accel. scale factor": "accel scale factor",
    }
    printed_rows = [(norm.get(n.lower(), n.lower()), k) for n, k in rows]
    return printed_rows == [(n.lower(), k) for n, k in layout_rows]


def _layout_size(layout, rows: tuple[tuple[str, int], ...]) -> int:
    """The layout's state count, after checking that its blocks are the printed rows."""
    if not _printed_rows_match_layout(rows, layout.table()):
        raise ValueError("the library layout does not have the printed rows")
    return layout.size


def _tight_within_loose_cascade() -> bool:
    tight = tightly_coupled_layout()
    return tight.issubset(receiver_pva_layout().union(loosely_coupled_layout()))


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
    ),
    Claim(
        id="SP-sec2.2-same-states",
        locator="Sec. 2.2",
        quantity="the tightly coupled states all appear in the cascaded loosely coupled filters",
        published=True,
        unit="statement",
        compute=_tight_within_loose_cascade,
        tolerance=EXACT,
        expected_status="reproduced",
        note="Set inclusion of the Table 2.3 blocks in the union of the Table 2.1 and 2.2 "
        "blocks, with equal block sizes.",
    ),
]

CLAIMS = quoted(CLAIMS)
