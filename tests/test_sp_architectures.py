"""SP Tables 2.1-2.3: the state layouts have exactly the printed rows, in order and size.

Oracle: the rows as printed in the paper (declared once as inputs of navcore.papers.sp_architectures).
"""

from __future__ import annotations

import pytest

from navcore.gnss.architectures import loosely_coupled_layout, receiver_pva_layout, tightly_coupled_layout
from navcore.papers.sp_architectures import IN, _layout_size


def test_layouts_have_the_printed_rows():
    assert _layout_size(receiver_pva_layout(), IN.table_2_1) == 12
    assert _layout_size(loosely_coupled_layout(), IN.table_2_2) == 22
    assert _layout_size(tightly_coupled_layout(), IN.table_2_3) == 24


def test_printed_totals():
    assert sum(k for _, k in IN.table_2_1) == receiver_pva_layout().size == 12
    assert sum(k for _, k in IN.table_2_2) == loosely_coupled_layout().size == 22
    assert sum(k for _, k in IN.table_2_3) == tightly_coupled_layout().size == 24


def test_a_mismatch_is_detected():
    with pytest.raises(ValueError, match="printed rows"):
        _layout_size(tightly_coupled_layout(), IN.table_2_2)


def test_block_units_are_dimensionally_consistent():
    """Oracle: dimensional analysis with sympy symbols for metre, second and radian: each rate
    state has the unit of its integral per second (velocity of position, acceleration of
    velocity, clock drift of clock bias, gyro drift of the misalignment angle), biases have the
    unit of what they bias, scale factors are dimensionless and the altimeter bias is a length."""
    import sympy as sp

    m, s, rad = sp.symbols("m s rad", positive=True)

    def dim(unit: str):
        return (
            sp.Integer(1)
            if unit in ("-", "")
            else sp.sympify(unit.replace("^", "**"), {"m": m, "s": s, "rad": rad})
        )

    units = {}
    for layout in (receiver_pva_layout(), loosely_coupled_layout(), tightly_coupled_layout()):
        for b in layout.blocks:
            assert units.setdefault(b.name, b.unit) == b.unit  # one unit per name across layouts
    u = {k: dim(v) for k, v in units.items()}
    assert sp.simplify(u["velocity"] / u["position"] - 1 / s) == 0
    assert sp.simplify(u["acceleration"] / u["velocity"] - 1 / s) == 0
    assert sp.simplify(u["clock drift"] / u["clock bias"] - 1 / s) == 0
    assert sp.simplify(u["gyro bias"] / u["misalignment"] - 1 / s) == 0
    assert u["position"] == m and u["misalignment"] == rad
    assert u["accel bias"] == u["acceleration"] and u["altimeter bias"] == m and u["clock bias"] == m
    assert u["gyro scale factor"] == 1 and u["accel scale factor"] == 1
