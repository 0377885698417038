"""SP Tables 2.1-2.3: the state layouts have exactly the printed rows, in order and size.

Oracle: the rows as printed in the paper (declared once as inputs of navcore.papers.sp_architectures).
"""

from __future__ import annotations

from navcore.gnss.architectures import loosely_coupled_layout, receiver_pva_layout, tightly_coupled_layout
from navcore.papers.sp_architectures import IN, _printed_rows_match_layout


def test_layouts_have_the_printed_rows():
    assert _printed_rows_match_layout(IN.table_2_1, receiver_pva_layout().table())
    assert _printed_rows_match_layout(IN.table_2_2, loosely_coupled_layout().table())
    assert _printed_rows_match_layout(IN.table_2_3, tightly_coupled_layout().table())


def test_printed_totals():
    assert sum(k for _, k in IN.table_2_1) == receiver_pva_layout().size == 12
    assert sum(k for _, k in IN.table_2_2) == loosely_coupled_layout().size == 22
    assert sum(k for _, k in IN.table_2_3) == tightly_coupled_layout().size == 24


def test_a_mismatch_is_detected():
    assert not _printed_rows_match_layout(IN.table_2_2, tightly_coupled_layout().table())
