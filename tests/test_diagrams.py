"""Block diagrams: each renders, shows the numbers it is given, and is reproducible.

Oracle: the text drawn on the figure must contain the quantities passed in (a diagram that
ignored its inputs would fail), and two renderings give identical PNG bytes.
"""

from __future__ import annotations

import io

import matplotlib.pyplot as plt
import pytest

from navcore import diagrams as D

CASES = {
    "ins": (lambda: D.ins_block_diagram(123), ["123 Hz"]),
    "receiver": (lambda: D.gnss_receiver_block_diagram(7), ["7 Hz"]),
    "tight": (lambda: D.tightly_coupled_feedback_diagram(19, 50, 2), ["19 states", "50 Hz", "2 Hz"]),
    "matched": (lambda: D.matched_filter_receiver_diagram("k"), ['matched filter "k"']),
    "architectures": (
        lambda: D.integration_architectures_diagram(12, 22, 24, 10, 100, 1, 4),
        [
            "12 states",
            "22 error states",
            "24 error states",
            "every 10 s",
            "EHE < 100 m",
            "1 Hz",
            "≥ 4 satellites",
        ],
    ),
}


def _texts(fig):
    return " ".join(t.get_text() for ax in fig.axes for t in ax.texts)


@pytest.mark.parametrize("name", list(CASES))
def test_diagram_shows_its_inputs(name):
    make, expected = CASES[name]
    fig = make()
    try:
        text = _texts(fig)
        for e in expected:
            assert e in text, f"{name}: '{e}' not drawn"
    finally:
        plt.close(fig)


@pytest.mark.parametrize("name", list(CASES))
def test_diagram_png_reproducible(name):
    make, _ = CASES[name]
    out = []
    for _ in range(2):
        fig = make()
        buf = io.BytesIO()
        fig.savefig(buf, format="png", metadata={"Software": None})
        plt.close(fig)
        out.append(buf.getvalue())
    assert out[0] == out[1]
