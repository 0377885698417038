"""Each paper chapter ends with an exercises page: at least three exercises, each with a
hidden (dropdown) solution that computes its answer (a code cell inside the solution)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

BOOK = Path(__file__).resolve().parents[1] / "book"


@pytest.mark.parametrize("chapter", ["wf", "sp", "atc10", "kzl"])
def test_chapter_has_exercises_with_hidden_computed_solutions(chapter):
    text = (BOOK / chapter / "90-exercises.md").read_text()
    labels = re.findall(r"```\{exercise\}[^\n]*\n:label: (\S+)", text)
    assert len(labels) >= 3
    for label in labels:
        block = re.search(
            r"```\{solution-start\} " + re.escape(label) + r"\n:class: dropdown\n```(.*?)```\{solution-end\}",
            text,
            flags=re.S,
        )
        assert block, f"{chapter}: exercise {label} has no hidden solution"
        assert "```{code-cell}" in block.group(1), f"{chapter}: the solution of {label} computes nothing"
