"""Every chapter teaches with exercises: at least one per section, four types per chapter,
hidden solutions that compute their answer and check it with an assertion, and the
exercises pages execute (so every solution's check runs).

Also the frame of each chapter: objectives and assumptions on its opening page, and a
closing summary page computed from the ledger.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

BOOK = Path(__file__).resolve().parents[1] / "book"
CHAPTERS = ["wf", "sp", "atc10", "kzl", "across"]
PAPER_CHAPTERS = {"wf": "WF", "sp": "SP", "atc10": "ATC10", "kzl": "KZL"}
TYPES = {"ex-predict", "ex-derive", "ex-erratum", "ex-open"}

_EXERCISE = re.compile(r"```\{exercise\}[^\n]*\n((?::[a-z]+:[^\n]*\n)+)")
_HEADING = re.compile(r"^## .*$", re.M)


def _sections(chapter: str) -> list[str]:
    """Docnames of a chapter's section pages (NN-topic.md with NN below 89)."""
    return sorted(p.stem for p in (BOOK / chapter).glob("[0-9][0-9]-*.md") if int(p.stem[:2]) < 89)


def _options(block: str) -> dict[str, str]:
    return dict(re.findall(r"^:([a-z]+): *(.*)$", block, flags=re.M))


def _exercises_by_section(chapter: str) -> dict[str, list[dict[str, str]]]:
    """Exercise options grouped by the section page their ``##`` heading links to."""
    text = (BOOK / chapter / "90-exercises.md").read_text()
    heads = list(_HEADING.finditer(text))
    out: dict[str, list[dict[str, str]]] = {}
    for n, h in enumerate(heads):
        body = text[h.end() : heads[n + 1].start() if n + 1 < len(heads) else len(text)]
        first = next((line for line in body.splitlines() if line.strip()), "")
        m = re.fullmatch(r"Exercises on \{doc\}`([^`]+)`\.", first.strip())
        assert m, f"{chapter}: the heading {h.group(0)!r} does not open with 'Exercises on {{doc}}`page`.'"
        out.setdefault(m.group(1), []).extend(_options(b) for b in _EXERCISE.findall(body))
    return out


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_every_section_has_an_exercise_and_the_chapter_all_four_types(chapter):
    by_section = _exercises_by_section(chapter)
    sections = _sections(chapter)
    assert sections, f"{chapter}: no section pages"
    missing = [s for s in sections if not by_section.get(s)]
    assert not missing, f"{chapter}: sections without an exercise: {missing}"
    assert set(by_section) <= set(sections), (
        f"{chapter}: exercises link to unknown pages {set(by_section) - set(sections)}"
    )
    kinds = [o.get("class", "") for opts in by_section.values() for o in opts]
    assert set(kinds) <= TYPES, f"{chapter}: unknown exercise classes {set(kinds) - TYPES}"
    assert set(kinds) == TYPES, f"{chapter}: exercise types missing: {TYPES - set(kinds)}"


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_every_exercise_has_a_hidden_solution_that_checks_its_answer(chapter):
    text = (BOOK / chapter / "90-exercises.md").read_text()
    labels = [_options(b)["label"] for b in _EXERCISE.findall(text)]
    assert len(labels) == len(set(labels)), f"{chapter}: duplicate exercise labels"
    for label in labels:
        assert label.startswith(f"{chapter}-ex-"), f"{chapter}: label {label} does not name its chapter"
        block = re.search(
            r"```\{solution-start\} " + re.escape(label) + r"\n:class: dropdown\n```(.*?)```\{solution-end\}",
            text,
            flags=re.S,
        )
        assert block, f"{chapter}: exercise {label} has no hidden solution"
        cells = re.findall(r"```\{code-cell\}[^\n]*\n(.*?)```", block.group(1), flags=re.S)
        assert cells, f"{chapter}: the solution of {label} computes nothing"
        assert any(re.search(r"^\s*assert\b", c, flags=re.M) for c in cells), (
            f"{chapter}: the solution of {label} does not check its answer"
        )


@pytest.mark.parametrize("chapter", list(PAPER_CHAPTERS))
def test_chapter_opens_with_objectives_and_closes_with_a_computed_summary(chapter):
    opening = (BOOK / chapter / "index.md").read_text()
    assert "After this chapter you will be able to" in opening
    assert "What it assumes" in opening
    closing = (BOOK / chapter / "89-summary.md").read_text()
    assert f'book.chapter_summary("{PAPER_CHAPTERS[chapter]}")' in closing
    assert "{glue:text}" in closing, f"{chapter}: the summary's findings are not computed"


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_exercise_solutions_execute(chapter, tmp_path):
    """Execute the chapter's exercises page: every solution's assertion runs."""
    jupytext = pytest.importorskip("jupytext")
    nbclient = pytest.importorskip("nbclient")
    nb = jupytext.read(BOOK / chapter / "90-exercises.md")
    env_path = os.environ.get("PYTHONPATH", "")
    root = str(BOOK.parent)
    os.environ["PYTHONPATH"] = root + (os.pathsep + env_path if env_path else "")
    try:
        client = nbclient.NotebookClient(
            nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(BOOK / chapter)}}
        )
        client.execute()
    finally:
        if env_path:
            os.environ["PYTHONPATH"] = env_path
        else:
            os.environ.pop("PYTHONPATH", None)
