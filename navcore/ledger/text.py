"""The ledger's text as a reader sees it: numbers, verdict colours, inline math in HTML and TeX.

Notes, quantities and erratum texts may hold inline math as ``$...$`` (:func:`html_text`,
:func:`tex_text`); quotes of the papers keep their own math (:func:`quote_math`,
:func:`quote_text`); a value is printed by :func:`format_value`, a claim's published value with
its relation by :func:`published_text`. The tables (:mod:`navcore.ledger.tables`), the
interactive table and the summaries all set their text through these functions.
"""

from __future__ import annotations

import html
import math
import re
from typing import Any

from navcore.claims.evaluation import COUNT_UNITS, Evaluation, left_out_of_band, reader_label
from navcore.claims.inputs import _label_and_unit, get_input
from navcore.claims.quotes import claim_quote
from navcore.claims.tolerances import PRECISION_STRICT
from navcore.claims.verdict import _is_truth as _core_is_truth
from navcore.formatting import format_number, math_spans, unit_text

__all__ = [
    "STATUS_COLOURS",
    "claim_group",
    "format_value",
    "html_text",
    "mark_compared_number",
    "math_breaks",
    "published_text",
    "quote_math",
    "quote_text",
    "tex_breakable",
    "tex_escape",
    "tex_text",
]


# light-mode row colours (the PDF uses them too); the HTML sets them by class
# (``ledger-status-<verdict>``) so that the book's dark mode can override them
STATUS_COLOURS = {
    "reproduced": "#d8f0d8",
    "consistent": "#e6f0fa",
    "discrepant": "#fbe3d4",
    "inconsistent": "#f6d6e8",
    "not-reproducible": "#eeeeee",
    "error": "#ffb3b3",
}


def _status_colour(status: str) -> str:
    return STATUS_COLOURS.get(status, "#ffffff")


def _status_class(status: str) -> str:
    return "ledger-status-" + "".join(ch if ch.isalnum() or ch == "-" else "-" for ch in status)


def format_value(value: Any, digits: int = 5) -> str:
    """Format a published or reproduced value for a table.

    Parameters
    ----------
    value : float, bool or None
        The value (a number in the claim's unit, a truth value, or ``None`` when nothing was
        computed).
    digits : int, optional
        Significant digits of a non-integral number.

    Returns
    -------
    str
        ``"—"`` for ``None``; ``"true"``/``"false"`` for a truth value; ``"∞"``/``"−∞"``;
        an integral value below a million without decimals; otherwise ``digits``
        significant digits (trailing zeros dropped), fixed between 0.001 and a million and
        otherwise in the book's one number format (``navcore.formatting.format_number``:
        ``9.4007×10⁻⁴``, never ``9.4007e-04`` or ``0.00094007``).

    Examples
    --------
    >>> format_value(17.6712345), format_value(3.0), format_value(True), format_value(None)
    ('17.671', '3', 'true', '—')
    >>> format_value(0.00094007), format_value(3.98601e14), format_value(123456.7), format_value(-1e-9)
    ('9.4007×10⁻⁴', '3.986×10¹⁴', '123457', '-1×10⁻⁹')
    """
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "true" if value else "false"
    v = float(value)
    if math.isinf(v):
        return "∞" if v > 0 else "−∞"
    if v == int(v) and abs(v) < 1e6:
        return str(int(v))
    if 1e-3 <= abs(v) < 1e6:
        text = f"{v:.{digits}g}"
        return text if "e" not in text else format_number(v, digits=digits)
    mantissa, _, exponent = format_number(v, digits=digits).partition("×")
    if "." in mantissa:  # as the fixed form: significant digits without trailing zeros
        mantissa = mantissa.rstrip("0").rstrip(".")
    return mantissa + ("×" + exponent if exponent else "")


def published_text(e: Evaluation) -> str:
    """A claim's published value as the tables print it: its relation (``≤``, ``≥``, ``<``)
    before the value of :func:`format_value`; nothing before an equality.

    Parameters
    ----------
    e : Evaluation
        An evaluation of the claim.

    Returns
    -------
    str
        The published value with its relation (``"≤ 0.5"``, ``"17.67"``).

    Examples
    --------
    >>> from navcore.ledger import Claim, evaluate, printed
    >>> value, tol = printed("0.5")
    >>> c = Claim(id="SP-doc-bound", paper="SP", locator="Eq. (1)", quantity="a bound",
    ...           published=value, unit="m", relation="<=", compute=lambda: 0.4, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> published_text(evaluate(c))
    '≤ 0.5'
    """
    c = e.claim
    rel = "" if c.relation == "=" else c.relation.replace(">=", "≥").replace("<=", "≤") + " "
    return rel + format_value(c.published)


def _md_escape(s: str) -> str:
    return s.replace("|", "\\|").replace("\n", " ")


_TEX_SPECIAL = {
    "\\": r"\textbackslash{}",
    "&": r"\&",
    "%": r"\%",
    "$": r"\$",
    "#": r"\#",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "~": r"\textasciitilde{}",
    "^": r"\textasciicircum{}",
}


def tex_escape(text: str) -> str:
    r"""Escape LaTeX's special characters (the PDF engine is XeLaTeX: Unicode passes).

    Parameters
    ----------
    text : str
        Plain text; a newline becomes a space.

    Returns
    -------
    str
        The text with ``\ & % $ # _ { } ~ ^`` written as LaTeX sets them literally.

    Examples
    --------
    >>> print(tex_escape("50 % of R&D_1"))
    50 \% of R\&D\_1
    """
    return "".join(_TEX_SPECIAL.get(ch, ch) for ch in text.replace("\n", " "))


def tex_breakable(text: str) -> str:
    """Escaped text that may break after ``-``, ``.``, ``_`` and ``/``, inside a run of more than
    ten characters that is not a plain word (claim and erratum ids, locators with formulas), and
    inside a plain word only when it is longer than ``_LONG_WORD`` letters: a narrow table column
    never runs over, and the paper's words ("interpreted") stay whole.

    Parameters
    ----------
    text : str
        Plain text (escaped here with :func:`tex_escape`).

    Returns
    -------
    str
        The escaped text with ``\\allowbreak{}`` at the places it may break.

    Examples
    --------
    >>> "allowbreak" in tex_breakable("interpreted")
    False
    >>> tex_breakable("KZLsec36headingX").count("allowbreak")
    2
    >>> tex_breakable("0.0019 g, -3.5 dB")  # no break at a decimal point or after a minus sign
    '0.0019 g, -3.5 dB'
    """
    pieces = re.split(r"([-./_ ])", text)
    out = []
    for piece in pieces:
        if len(piece) > (_LONG_WORD if piece.isalpha() else 10):
            piece = "\x00".join(piece[i : i + 7] for i in range(0, len(piece), 7))
        out.append(piece)
    escaped = tex_escape("".join(out)).replace("\x00", r"\allowbreak{}")
    # a "." between two digits is a decimal point and a "-" before a digit that follows no
    # letter or digit is a minus sign: neither may end a line ("0." / "0019", "-" / "3.5")
    escaped = re.sub(r"\.(?!\d)|(?<!\d)\.", r".\\allowbreak{}", escaped)
    escaped = re.sub(r"-(?!\d)|(?<=[A-Za-z0-9])-", r"-\\allowbreak{}", escaped)
    escaped = escaped.replace("/", r"/\allowbreak{}")
    return escaped.replace(r"\_", r"\_\allowbreak{}")


_LONG_WORD = 14  # a longer word of a text cell may break (every 7 characters, or after - . / _)


def _plain_with_unit(value: str, unit: str) -> str:
    """A value and its unit as a reader sees them: a unit with a power or a formula as
    ``$...$`` math (:func:`~navcore.formatting.unit_text`), which :func:`html_text` and
    :func:`tex_text` set."""
    if value in ("", "—") or unit in ("", "statement"):
        return value
    if value == "1" and unit in _COUNT_UNITS:  # "1 state", not "1 states"
        unit = unit[:-1]
    return f"{value} {unit_text(unit)}"


#: Plural count units that read in the singular after exactly one (the core's list).
_COUNT_UNITS = COUNT_UNITS


#: A formula of more characters than this (spaces aside) may break in a table of text or a
#: claim row.
_LONG_FORMULA = 12


#: A piece of a claim row's formula longer than this (spaces aside) is also cut inside its
#: parentheses and brackets (about the TeX of what a claim column holds).
_LONG_PIECE = 36


_TEX_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\s+|.", re.S)


#: TeX breaks inline math after a relation or a binary operator at the formula's outer level
_TEX_RELATIONS = frozenset(
    ["=", "<", ">", r"\le", r"\leq", r"\ge", r"\geq", r"\ne", r"\neq", r"\approx", r"\sim",
     r"\simeq", r"\equiv", r"\propto", r"\to", r"\rightarrow", r"\ll", r"\gg"]
)  # fmt: skip


_TEX_BINARY = frozenset(["+", "-", r"\pm", r"\mp", r"\times", r"\cdot"])


_TEX_OPEN = frozenset(["(", "[", r"\{", r"\langle", r"\lvert", r"\lVert"])


_TEX_CLOSE = frozenset([")", "]", r"\}", r"\rangle", r"\rvert", r"\rVert"])


_TEX_BARS = frozenset(["|", r"\|", r"\vert", r"\Vert"])


def math_breaks(tex: str, *, brackets: bool = False) -> list[str]:
    r"""A long inline formula cut where TeX may break it in a paragraph: after a relation or a
    binary operator at its outer level (not inside braces, brackets or bars; with
    ``brackets``, inside the outermost plain parentheses and brackets too, as TeX also may).

    MathJax 3 never breaks an inline formula, so in a table of text one long formula sets
    the least width of its column however the words around it wrap. Each piece but the last
    ends with an empty group, so that its operator keeps the spacing it has between two
    operands; the pieces set side by side read as the whole formula. A formula of at most
    ``_LONG_FORMULA`` characters, and a last piece of fewer than three, stay whole.

    Parameters
    ----------
    tex : str
        The formula's TeX, without its ``$`` delimiters.
    brackets : bool, optional
        Also cut inside the outermost plain parentheses and brackets.

    Returns
    -------
    list of str
        The pieces, in order; one piece when the formula stays whole.

    Examples
    --------
    >>> math_breaks(r"\mathrm{Exp}_g = a^2/(2p)")
    ['\\mathrm{Exp}_g ={}', 'a^2/(2p)']
    >>> math_breaks(r"C/N_0 - 10\log_{10} B_L")
    ['C/N_0 -{}', '10\\log_{10} B_L']
    >>> math_breaks(r"|\ln \mathrm{bound} - \ln p_f|"), math_breaks("P_{DL} = 0.999")
    (['|\\ln \\mathrm{bound} - \\ln p_f|'], ['P_{DL} = 0.999'])
    >>> math_breaks(r"\left| a - b \right| = -c + d^{-1}")
    ['\\left| a - b \\right| ={}', '-c +{}', 'd^{-1}']
    >>> math_breaks(r"[a(k-1) + b_1 + c_2]^{-1}", brackets=True)
    ['[a(k-1) +{}', 'b_1 +{}', 'c_2]^{-1}']
    >>> math_breaks(r"E[x] = \begin{cases} a, & i = 0 \\ b, & i > 0 \end{cases}")
    ['E[x] ={}', '\\begin{cases} a, & i = 0 \\\\ b, & i > 0 \\end{cases}']
    """
    if len(re.sub(r"\s", "", tex)) <= _LONG_FORMULA:
        return [tex]
    cuts: list[int] = []
    braces, fences, environments, depth = 0, [], 0, 0
    prev = ""  # the previous token at the outer level ("" at the start)
    delimiter = False  # the token after \left or \right
    for m in _TEX_TOKEN.finditer(tex):
        tok = m.group(0)
        if tok.isspace():
            continue
        if delimiter:
            delimiter = False
            continue
        # a matrix or cases environment is one unit: never cut inside it
        environments += {r"\begin": 1, r"\end": -1}.get(tok, 0)
        if environments or tok == r"\end":
            prev = "}"
            continue
        braces += {"{": 1, "}": -1}.get(tok, 0)
        if braces or tok == "}":
            prev = "}"
            continue
        if tok in (r"\left", r"\right"):
            if tok == r"\left":
                fences.append(tok)
            elif fences:
                fences.pop()
            delimiter, prev = True, ")"
            continue
        if brackets and tok in ("(", "[", ")", "]"):  # cut inside the outermost pair only
            depth += 1 if tok in "([" else -1
            prev = "(" if tok in "([" else ")"
            continue
        if brackets and depth > 1:
            prev = tok
            continue
        if tok in _TEX_OPEN or (tok in _TEX_BARS and not (fences and fences[-1] == tok)):
            fences.append(tok)
            prev = "("
            continue
        if tok in _TEX_CLOSE or tok in _TEX_BARS:
            if fences:
                fences.pop()
            prev = ")"
            continue
        operators = _TEX_RELATIONS | _TEX_BINARY
        operand_before = prev and prev not in ("(", "^", "_", ",") and prev not in operators
        if not fences and operand_before and tok in operators:
            cuts.append(m.end())
        prev = tok
    pieces, start = [], 0
    for cut in cuts:
        if len(re.sub(r"\s", "", tex[cut:])) >= 3:
            pieces.append(tex[start:cut].strip() + "{}")
            start = cut
    return [*pieces, tex[start:].strip()]


def html_text(text: str, *, wide: int = 0) -> str:
    r"""Escaped HTML with ``$...$`` as MathJax inline math, marked up as Sphinx does.

    Parameters
    ----------
    text : str
        A note, quantity or erratum text (:func:`~navcore.formatting.math_spans` says what is math).
    wide : int, optional
        A math piece longer than this many characters is wrapped in a
        ``<span class="ledger-math-wide">`` (0: never), so that one long formula does not
        widen its column past the page: it is cut where TeX may break it (after a relation or
        a binary operator at its outer level), its pieces joined by line-break opportunities,
        so that it wraps inside its box; a piece still wider than the box is set smaller by
        the book's equation fitting, and scrolls inside the box only beyond that.

    Returns
    -------
    str
        The text HTML-escaped, each math piece escaped inside ``\(...\)`` in a
        ``<span class="math notranslate nohighlight">``.

    Examples
    --------
    >>> print(html_text("gain $K_1 < 2$ & more"))
    gain <span class="math notranslate nohighlight">\(K_1 &lt; 2\)</span> &amp; more
    >>> print(html_text("$x = a + b$", wide=5))
    <span class="ledger-math-wide"><span class="math notranslate nohighlight">\(x = a + b\)</span></span>
    >>> out = html_text("$x_{\\rm long} = a + b$", wide=5)
    >>> print(out.replace(' class="math notranslate nohighlight"', ""))
    <span class="ledger-math-wide"><span>\(x_{\rm long} ={}\)</span><wbr><span>\(a + b\)</span></span>
    """
    out = []
    for is_math, piece in math_spans(text):
        out.append(_math_html(piece, wide) if is_math else html.escape(piece))
    return "".join(out)


def _math_html(piece: str, wide: int) -> str:
    r"""A formula as MathJax inline math; one longer than ``wide`` characters (``wide`` > 0) in
    a ``ledger-math-wide`` box, cut where TeX may break it (:func:`math_breaks`).

    Examples
    --------
    >>> print(_math_html("K_1", 24))
    <span class="math notranslate nohighlight">\(K_1\)</span>
    """
    span = '<span class="math notranslate nohighlight">\\({}\\)</span>'
    if not wide or len(piece) <= wide:
        return span.format(html.escape(piece))
    pieces = "<wbr>".join(span.format(html.escape(p)) for p in _math_parts(piece))
    return f'<span class="ledger-math-wide">{pieces}</span>'


def _math_parts(piece: str) -> list[str]:
    r"""The pieces a long formula of a claim row is cut into (:func:`_math_html`): where TeX may
    break it, and a piece still longer than a claim column holds inside its brackets too.

    Examples
    --------
    >>> _math_parts(r"x_{\rm long} = a + b")
    ['x_{\\rm long} ={}', 'a + b']
    """
    return [
        q
        for p in math_breaks(piece)
        for q in (math_breaks(p, brackets=True) if len(re.sub(r"\s", "", p)) > _LONG_PIECE else [p])
    ]


#: Widths in em of what inline TeX math sets (Computer Modern's metrics, rounded): an
#: italic letter, a capital, a digit, a Greek letter, a fence, a relation and a binary
#: operator with the spaces TeX puts around them, a named operator's letter.
_EM = {
    "letter": 0.52, "capital": 0.75, "digit": 0.5, "greek": 0.58, "Greek": 0.72, "fence": 0.39,
    "relation": 1.33, "binary": 1.22, "sign": 0.78, "comma": 0.45, "thin": 0.28, "text": 0.5,
    "space": 0.25, "script": 0.71, "frac": 0.24, "sqrt": 0.85, "delimiter": 0.45, "other": 0.6,
}  # fmt: skip


_EM_SPACES = {
    r"\,": 0.17, r"\:": 0.22, r"\;": 0.28, r"\ ": 0.25, r"\!": -0.17, r"\quad": 1.0, r"\qquad": 2.0,
}  # fmt: skip


_EM_FONTS = {
    r"\mathbf": 1.1, r"\boldsymbol": 1.1, r"\bm": 1.1, r"\mathrm": 0.95, r"\mathcal": 1.2, r"\mathbb": 1.2,
}  # fmt: skip


#: symbols of their own widths (a large operator with the thin space after it)
_EM_SYMBOLS = {
    r"\ldots": 1.17, r"\cdots": 1.17, r"\dots": 1.17, r"\infty": 1.0, r"\partial": 0.57, r"\nabla": 0.83,
    r"\ell": 0.42, r"\prime": 0.28, r"\{": 0.5, r"\}": 0.5, r"\|": 0.5, r"\langle": 0.39, r"\rangle": 0.39,
    r"\vert": 0.28, r"\Vert": 0.5, r"\%": 0.83, r"\sum": 1.22, r"\prod": 1.12, r"\bigcap": 1.02,
    r"\bigcup": 1.02, r"\int": 0.77, r"|": 0.28, "/": 0.5, ".": 0.28, "!": 0.28,
}  # fmt: skip


_EM_TEXT = frozenset([r"\text", r"\textrm", r"\mbox", r"\textit", r"\textbf", r"\operatorname"])


_EM_ACCENTS = frozenset([r"\hat", r"\bar", r"\tilde", r"\dot", r"\ddot", r"\vec", r"\widehat", r"\overline"])


_EM_NAMED = frozenset(
    [r"\exp", r"\ln", r"\log", r"\sin", r"\cos", r"\tan", r"\arctan", r"\min", r"\max", r"\det", r"\lim",
     r"\sup", r"\inf", r"\tr", r"\sinh", r"\cosh", r"\tanh", r"\arg", r"\Pr"]
)  # fmt: skip


_EM_GREEK_CAPITALS = frozenset(
    [r"\Gamma", r"\Delta", r"\Theta", r"\Lambda", r"\Xi", r"\Pi", r"\Sigma", r"\Phi", r"\Psi", r"\Omega"]
)


_EM_BIG = frozenset(
    [r"\left", r"\right", r"\big", r"\Big", r"\bigg", r"\Bigg", r"\bigl", r"\bigr", r"\Bigl", r"\Bigr"]
)


_EM_FENCES = {"bmatrix": 0.9, "pmatrix": 0.9, "vmatrix": 0.6, "Bmatrix": 1.0, "cases": 0.6}


def _text_em(text: str) -> float:
    return sum(_EM["space"] if ch == " " else 0.72 if ch.isupper() else _EM["text"] for ch in text)


def math_em(tex: str) -> float:
    r"""About how wide a formula sets as inline TeX math, in em of its font, from its source
    alone (no browser): each symbol's width from Computer Modern's metrics, a script at 71 %,
    a fraction as wide as its wider part at script size, a matrix or cases environment as its
    columns' widest cells side by side, the spaces TeX puts around relations and operators.

    A rough measure (MathJax sets the claim rows' formulas 1.18 to 1.5 times wider than this,
    in em of the table's text, median 1.35, over every formula the claim tables quote): it
    ranks formulas by width, which is what :func:`quote_below` needs.

    Examples
    --------
    >>> math_em("x"), math_em("x = 1")
    (0.52, 2.35)
    >>> round(math_em(r"\frac{a}{b}"), 2), round(math_em(r"x^{2}"), 3)
    (0.61, 0.925)
    >>> round(math_em(r"\begin{bmatrix} a & b \\ c & d \end{bmatrix}"), 2)
    3.27
    """
    toks = [t for t in _TEX_TOKEN.findall(tex) if not t.isspace()]
    pos = 0

    def argument() -> list[str]:  # a {group} or one token
        nonlocal pos
        if pos >= len(toks):
            return []
        if toks[pos] != "{":
            pos += 1
            return [toks[pos - 1]]
        depth, start = 0, pos
        while pos < len(toks):
            depth += {"{": 1, "}": -1}.get(toks[pos], 0)
            pos += 1
            if depth == 0:
                break
        return toks[start + 1 : pos - 1]

    def em(ts: list[str]) -> float:
        return math_em(" ".join(ts))

    def scripts(base: float) -> float:  # a base with the scripts after it
        nonlocal pos
        sup = sub = 0.0
        while pos < len(toks) and toks[pos] in ("^", "_", "'"):
            pos += 1
            if toks[pos - 1] == "'":
                sup += _EM["thin"]
            elif toks[pos - 1] == "^":
                sup = max(sup, _EM["script"] * em(argument()))
            else:
                sub = max(sub, _EM["script"] * em(argument()))
        return base + (max(sup, sub) + 0.05 if sup or sub else 0.0)

    def environment(name: str) -> float:  # columns side by side, 1 em apart
        nonlocal pos
        depth, start = 1, pos
        while pos < len(toks) and depth:
            depth += {r"\begin": 1, r"\end": -1}.get(toks[pos], 0)
            pos += 1
        body = toks[start : pos - 1]
        argument()  # the environment's name after \end
        rows: list[list[list[str]]] = [[[]]]
        depth = 0
        for t in body:
            depth += {"{": 1, "}": -1, r"\begin": 1, r"\end": -1}.get(t, 0)
            if depth == 0 and t == "&":
                rows[-1].append([])
            elif depth == 0 and t == r"\\":
                rows.append([[]])
            else:
                rows[-1][-1].append(t)
        ncol = max(len(row) for row in rows)
        cols = [max(em(row[j]) if j < len(row) else 0.0 for row in rows) for j in range(ncol)]
        return sum(cols) + (ncol - 1) + _EM_FENCES.get(name, 0.0) + (0.33 if name != "matrix" else 0.0)

    width, operand = 0.0, False  # operand: the token before was an operand (a sign is binary)
    while pos < len(toks):
        t = toks[pos]
        pos += 1
        if t == "{":
            pos -= 1
            width += scripts(em(argument()))
        elif t == r"\begin":
            width += environment("".join(argument()))
        elif t in (r"\frac", r"\tfrac", r"\dfrac"):
            parts = max(em(argument()), em(argument()))
            width += scripts((1.0 if t == r"\dfrac" else _EM["script"]) * parts + _EM["frac"])
        elif t == r"\sqrt":
            width += scripts(em(argument()) + _EM["sqrt"])
        elif t == r"\substack":
            rows: list[list[str]] = []
            row: list[str] = []
            for s in argument():
                if s == r"\\":
                    rows.append(row)
                    row = []
                else:
                    row.append(s)
            width += max(em(r) for r in [*rows, row])
        elif t in _EM_BIG:
            width += scripts(0.12 if pos < len(toks) and toks[pos] == "." else _EM["delimiter"])
            pos += 1
        elif t in _EM_TEXT:
            width += scripts(_text_em("".join(argument())) + (0.17 if t == r"\operatorname" else 0.0))
        elif t in _EM_FONTS:
            width += scripts(_EM_FONTS[t] * em(argument()))
        elif t in _EM_ACCENTS:
            width += scripts(em(argument()))
        elif t in _EM_NAMED:
            width += scripts(_EM["text"] * (len(t) - 1)) + 0.17
        elif t in _EM_SPACES:
            width += _EM_SPACES[t]
        elif t in _TEX_RELATIONS:
            width += _EM["relation"] if operand else 1.05
        elif t in _TEX_BINARY:
            width += _EM["binary"] if operand else _EM["sign"]
            operand = False
            continue
        elif t in (",", ";"):
            width += _EM["comma"]
        elif t in ("(", "[", ")", "]"):
            width += scripts(_EM["fence"])
            operand = t in ")]"
            continue
        elif t in ("^", "_", "'"):
            pos -= 1
            width += scripts(0.0)
        elif t in _EM_SYMBOLS:
            width += scripts(_EM_SYMBOLS[t])
        elif t in _EM_GREEK_CAPITALS:
            width += scripts(_EM["Greek"])
        elif t.startswith("\\") and len(t) > 2:
            width += scripts(_EM["greek"])
        elif t.isdigit():
            width += scripts(_EM["digit"])
        elif t.isalpha():
            width += scripts(_EM["capital"] if t.isupper() else _EM["letter"])
        elif t not in ("&", r"\\", "}"):
            width += scripts(_EM["other"])
        operand = True
    return width


def tex_text(text: str) -> str:
    r"""Escaped LaTeX with ``$...$`` passed through as math.

    Parameters
    ----------
    text : str
        A note, quantity or erratum text (:func:`~navcore.formatting.math_spans` says what is math).

    Returns
    -------
    str
        The text with LaTeX's special characters escaped outside the math, and each math
        piece as written between dollar signs.

    Examples
    --------
    >>> print(tex_text("50% of $K_1$"))
    50\% of $K_1$
    """
    return "".join(f"${piece}$" if is_math else tex_escape(piece) for is_math, piece in math_spans(text))


_GROUP_PATTERNS = (
    r"\bTables?\s+[A-Z]?\d+(?:\.\d+)*",
    r"\bFigs?\.\s+\d+(?:\.\d+)*(?:\s*-\s*\d+(?:\.\d+)*)?",
    r"\bTheorem(?:\s+\d+(?:\.\d+)*)?",
    r"\bRemark\s+\([ivx]+\)",
    r"\bProposition\b",
    r"\bEqs?\.\s+\([^)]*\)(?:\s*-\s*\([^)]*\))?",
    r"\b(?:Appendix|App\.)\s+[A-Z]\b",
    r"\bSecs?\.\s+(?:[IVX]+(?:\.[A-Z0-9]+)*|\d+(?:\.\d+)*)",
)


def claim_group(locator: str) -> str:
    """What a claim checks, from its locator: the table, figure, theorem, equation, appendix
    or section it names (in that order of preference).

    ``"Table 2.6, column 2"`` -> ``"Table 2.6"``; ``"Sec. 3.6, discussion of Fig. 5"`` ->
    ``"Fig. 5"``; ``"Sec. III, after Eq. (9)"`` -> ``"Eq. (9)"``; a locator naming none of
    them is its own group.

    Parameters
    ----------
    locator : str
        A claim's locator, in the paper's words.

    Returns
    -------
    str
        The group's label: the first table, figure, theorem, remark, proposition, equation,
        appendix or section named, else the locator without surrounding spaces.

    Examples
    --------
    >>> claim_group("Table 2.6, column 2"), claim_group("Sec. 3.6, discussion of Fig. 5")
    ('Table 2.6', 'Fig. 5')
    >>> claim_group("abstract")
    'abstract'
    """
    for pattern in _GROUP_PATTERNS:
        m = re.search(pattern, locator)
        if m:
            return m.group(0)
    return locator.strip()


def _is_truth(value: Any) -> bool:
    """A Python or numpy boolean (:func:`navcore.claims.verdict._is_truth`, its one home)."""
    return _core_is_truth(value)


def _statement_word(value: Any, *, printed: bool) -> str:
    """Words for a truth value: printed ``stated`` (``stated not to hold`` for a printed
    falsehood), reproduced ``holds`` / ``does not hold``."""
    if printed:
        return "stated" if value else "stated not to hold"
    return "holds" if value else "does not hold"


def mark_compared_number(quote: str, digits: str) -> str:
    r"""A claim's quote with the number it compares set in bold (Markdown bold), where the quote
    holds more than that number (a printed table row, a sentence) and names it once.

    The number is the one the claim's tolerance was given as printed (``digits``). It is marked
    only where the reader could not tell it for sure otherwise, and only where marking cannot
    misread the quote: it must stand in the quote's words (not in a formula) exactly once, as a
    whole number (no digit or decimal point touching it), and the quote must hold no emphasis of
    its own and no LaTeX outside its formulas. Any other quote is returned as it is.

    Parameters
    ----------
    quote : str
        What the claim quotes of the paper (its ``printed``).
    digits : str
        The number as the paper printed it, as the claim's tolerance holds it (``"0.011"``);
        ``""`` when the tolerance holds none.

    Returns
    -------
    str
        The quote, with the number between double asterisks when it is marked.

    Examples
    --------
    >>> mark_compared_number("10 nmi/h 1880 0.011 g 0.77", "0.011")
    '10 nmi/h 1880 **0.011** g 0.77'
    >>> mark_compared_number("10 nmi/h 1880 0.011 g 0.77", "18")  # not a whole number there
    '10 nmi/h 1880 0.011 g 0.77'
    >>> mark_compared_number("50 nsec 50 nsec", "50")  # twice: which one is not sure
    '50 nsec 50 nsec'
    >>> mark_compared_number("0.77", "0.77")  # the quote is the number
    '0.77'
    """
    digits = digits.strip()
    if not digits or quote.strip() == digits or "*" in quote or "$$" in quote:
        return quote
    if not re.fullmatch(r"[\d.]+", digits):
        return quote
    number = re.compile(r"(?<![\d.])" + re.escape(digits) + r"(?![\d]|\.\d)")
    hits, pos = [], 0
    for is_math, piece in math_spans(quote):
        width = len(piece) + 2 if is_math else len(piece)  # a formula's piece lost its two "$"
        if is_math and number.search(piece):
            return quote
        if not is_math:
            if "\\" in piece.replace("\\$", ""):  # LaTeX outside a formula: shown as source
                return quote
            hits += [(pos + m.start(), pos + m.end()) for m in number.finditer(piece)]
        pos += width
    if len(hits) != 1 or pos != len(quote):
        return quote
    ((a, b),) = hits
    return quote[:a] + "**" + quote[a:b] + "**" + quote[b:]


def _printed_text(e: Evaluation, *, mark: bool = True) -> str:
    """What the paper printed: its words as the claim quotes them (with the number the claim
    compares in bold, :func:`mark_compared_number`, unless ``mark`` is false); else the number
    as printed with its relation and unit, or "stated" for a statement the book checks."""
    c = e.claim
    quote, source = claim_quote(c, e.tolerance)
    if source == "claim":
        return mark_compared_number(quote, getattr(e.tolerance, "quote", "")) if mark else quote
    if _is_truth(c.published):
        return _statement_word(c.published, printed=True)
    rel = "" if c.relation == "=" else c.relation.replace(">=", "≥").replace("<=", "≤") + " "
    return _plain_with_unit(rel + format_value(c.published), c.unit)


def soft_hyphens(text: str) -> str:
    """``text`` with a soft hyphen (``&shy;``) at each syllable break of the long words the
    ledger's narrow columns hold (:data:`_SOFT_HYPHENS`: verdicts, kinds, and the papers' locator
    words, "Appendix" among them, wider than the interactive ledger's locator column at 1400 px);
    a browser breaks such a word there, with a hyphen, only where it does not fit its column,
    instead of at the column's edge. Other words are left as they are.

    Examples
    --------
    >>> soft_hyphens("Appendix E, (E.1)")
    'Ap&shy;pen&shy;dix E, (E.1)'
    >>> soft_hyphens("Sec. 2.5 (acquisition)")
    'Sec. 2.5 (ac&shy;qui&shy;si&shy;tion)'
    >>> soft_hyphens("Eq. (3)")
    'Eq. (3)'
    """
    return re.sub(r"[A-Za-z]{7,}", lambda m: _SOFT_HYPHENS.get(m.group(0), m.group(0)), text)


#: A formula longer than this many characters is set in a box scaled to its table column
#: when wider than it (:func:`fit_math`); a shorter one as inline math.
_FIT_MATH_CHARS = 24


#: An erratum's formula longer than this many characters of TeX is set in a box of its own,
#: cut where TeX may break it (:func:`html_text`), so that a corrected equation wraps on a
#: phone instead of running past the text column; shorter ones stay inline in the sentence.
_ERRATUM_WIDE_MATH = 40


#: The LaTeX macro :func:`fit_math` calls, defined in the book's preamble (``_config.yml``) and
#: in the verification reports' (:mod:`navcore.report`); it needs graphicx. The formula is set
#: as inline math in a box, scaled down to the line width (a table cell's column) only when
#: wider than it, so that a narrow column holds a long formula without an overfull box.
FIT_MATH_PREAMBLE = (
    r"\newsavebox{\navcorefitbox}"
    r"\newcommand{\navcorefitmath}[1]{\sbox{\navcorefitbox}{$#1$}"
    r"\ifdim\wd\navcorefitbox>\linewidth\resizebox{\linewidth}{!}{\usebox{\navcorefitbox}}"
    r"\else\usebox{\navcorefitbox}\fi}"
)


def fit_math(piece: str) -> str:
    r"""A formula of a printed table cell as LaTeX math: inline if short, else in a box scaled
    down to its column only when wider than it (:data:`FIT_MATH_PREAMBLE`).

    Parameters
    ----------
    piece : str
        The formula, without its dollar signs.

    Returns
    -------
    str
        ``$piece$``, or ``\navcorefitmath{piece}`` for a formula longer than 24 characters.

    Examples
    --------
    >>> print(fit_math("K_1"))
    $K_1$
    >>> print(fit_math("\\sigma_{\\xi\\tau_0}^2 = \\sigma^2 \\gamma_0 + \\sigma^2 \\gamma_1"))
    \navcorefitmath{\sigma_{\xi\tau_0}^2 = \sigma^2 \gamma_0 + \sigma^2 \gamma_1}
    """
    return f"${piece}$" if len(piece) <= _FIT_MATH_CHARS else r"\navcorefitmath{" + piece + "}"


_DISPLAY = re.compile(r"\$\$(.*?)\$\$", re.S)


_EQ_NUMBER = re.compile(r"\\(?:quad|qquad)\s*\(?(?:\\text\{[\w.]+\}|[\w.]+)\)?\s*$|\\tag\{[^}]*\}")


_MATH_TOKEN = re.compile(r"\\(?:begin|end)\{[^}]*\}|\\(?:left|right)(?![A-Za-z])|\\[A-Za-z]+|\\.|[{}&]")


#: Unicode a quote's formulas use, as math commands (the PDF's math fonts are not Unicode).
_TEX_MATH_CHARS = {
    "×": r"\times ",
    "·": r"\cdot ",
    "≤": r"\leq ",
    "≥": r"\geq ",
    "≈": r"\approx ",
    "−": "-",
    **{
        ch: "\\" + name + " "
        for ch, name in zip(
            "αβγδεθλμνξπρστφχψωΓΔΘΛΞΠΣΦΨΩ",
            "alpha beta gamma delta epsilon theta lambda mu nu xi pi rho sigma tau phi chi psi "
            "omega Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi Omega".split(),
            strict=True,
        )
    },
}


def quote_math(piece: str) -> str:
    r"""A formula of a quote made whole for typesetting: a quote may cut a displayed equation
    (the transcription's alignment ``&``, a matrix's rows, an open ``\left`` or brace).

    The equation number (``\tag{..}``, ``\quad (3)``) is left out; a matrix fragment (rows
    ``\\`` outside an environment) is set as a matrix, and an alignment ``&`` outside one is
    dropped; a ``\left`` or ``\right`` without its partner is closed by an empty delimiter and
    an open brace by an ellipsis and its brace, so that the formula typesets as far as the
    paper's words go. The symbols stay the paper's.

    Parameters
    ----------
    piece : str
        The formula, without its dollar signs.

    Returns
    -------
    str
        The formula, typesettable by MathJax and LaTeX (Unicode letters and operators such as
        ``σ`` and ``×``, which the PDF's math fonts lack, as math commands).

    Examples
    --------
    >>> quote_math(r"\gamma_n &= \frac{a}{b} \tag{4.5.31}")
    '\\gamma_n = \\frac{a}{b}'
    >>> quote_math(r"\exp \left[(K t + 1) \ln")
    '\\exp \\left[(K t + 1) \\ln\\right.'
    >>> quote_math(r"\sqrt{2 \frac{\partial^2}{\partial r^2}")
    '\\sqrt{2 \\frac{\\partial^2}{\\partial r^2}\\ldots}'
    >>> quote_math(r"a & b \\ c & d")
    '\\begin{matrix}a & b \\\\ c & d\\end{matrix}'
    >>> quote_math(r"\sum_{\substack{j=1 \\ j \neq i}}^N x_j")
    '\\sum_{\\substack{j=1 \\\\ j \\neq i}}^N x_j'
    >>> quote_math("1.61×10^{-4}")
    '1.61\\times 10^{-4}'
    """
    piece = _EQ_NUMBER.sub("", piece).strip()
    depth, stack, lead, amps = 0, [], [], []
    rows = False
    for m in _MATH_TOKEN.finditer(piece):
        tok = m.group(0)
        if tok.startswith("\\begin"):
            depth += 1
        elif tok.startswith("\\end"):
            depth -= 1
        elif tok in ("{", "\\left"):
            stack.append(tok)
        elif tok in ("}", "\\right"):
            if stack and stack[-1] == ("{" if tok == "}" else "\\left"):
                stack.pop()
            else:
                lead.append("{" if tok == "}" else "\\left.")
        elif depth == 0 and "{" not in stack and tok == "&":
            amps.append(m.start())
        elif depth == 0 and "{" not in stack and tok == "\\\\":  # not a \substack's lines
            rows = True
    if amps and not rows:  # an alignment point of the paper's display: no alignment inline
        piece = "".join(ch for i, ch in enumerate(piece) if i not in amps)
    tail = "".join("}" if tok == "{" else "\\right." for tok in reversed(stack))
    if "{" in stack:
        tail = "\\ldots" + tail
    piece = "".join(reversed(lead)) + re.sub(r"\s{2,}", " ", piece) + tail
    if rows:
        piece = "\\begin{matrix}" + piece + "\\end{matrix}"
    return "".join(_TEX_MATH_CHARS.get(ch, ch) for ch in piece).strip()


def quote_text(text: str) -> str:
    r"""A quote of the paper with every formula as inline ``$...$`` math made whole
    (:func:`quote_math`): a display formula inline and unnumbered, a cut one closed.

    Parameters
    ----------
    text : str
        A claim's quote (its ``printed``), whose ``$...$`` and ``$$...$$`` are its formulas.

    Returns
    -------
    str
        The quote's words as they are and each formula as ``$...$``.

    Examples
    --------
    >>> print(quote_text("so that $$x &= 1 \\quad (3)$$ holds for $p_d$"))
    so that $x = 1$ holds for $p_d$
    """
    text = _DISPLAY.sub(lambda m: "$" + m.group(1).strip() + "$", text)
    return "".join(f"${quote_math(piece)}$" if is_math else piece for is_math, piece in math_spans(text))


#: A dollar sign of the paper's words in HTML, which MathJax leaves as it is.
_HTML_DOLLAR = '<span class="tex2jax_ignore mathjax_ignore">$</span>'


#: A power in a quote's words (``5 parts in 10^8``, ``e^*``): the transcription's mark for a
#: superscript, set as math by :func:`_quote_markup`.
_QUOTE_POWER = re.compile(r"(?<![\w^\\])(\w+)\^([-+]?\d+|\w|\*)(?![\w^])")


#: A quote's emphasis as the transcription marks it: ``**word**`` (strong), ``*word*``.
_QUOTE_EMPHASIS = re.compile(
    r"\*\*(?=\S)(?P<strong>.+?)(?<=\S)\*\*|(?<![\w*])\*(?=[^\s*])(?P<em>[^*]+?)(?<=[^\s*])\*(?![\w*])"
)


def _quote_markup(text: str) -> str:
    """A quote with each power its words mark (``10^8``) as ``$...$`` math, the rest as it is.

    Examples
    --------
    >>> print(_quote_markup("better than 5 parts in 10^8, is e^* and $x^2$"))
    better than 5 parts in $10^{8}$, is $e^{*}$ and $x^2$
    """
    return "".join(
        f"${piece}$" if is_math else _QUOTE_POWER.sub(r"$\1^{\2}$", piece)
        for is_math, piece in math_spans(text)
    )


def _emphasis(text: str, escape: Any, strong: str, em: str) -> str:
    """A quote's words escaped by ``escape``, with its marked emphasis (``**word**``,
    ``*word*``) set by the templates ``strong`` and ``em`` (``{}``: the escaped words).

    Examples
    --------
    >>> _emphasis("the detector **deteriorates**, *a priori*", html.escape, "<b>{}</b>", "<em>{}</em>")
    'the detector <b>deteriorates</b>, <em>a priori</em>'
    """
    out, pos = [], 0
    for m in _QUOTE_EMPHASIS.finditer(text):
        out.append(escape(text[pos : m.start()]))
        out.append((strong if m.group("strong") else em).format(escape(m.group("strong") or m.group("em"))))
        pos = m.end()
    return "".join(out) + escape(text[pos:])


def _latex_source(piece: str) -> bool:
    """Whether a piece of a quote outside its math is LaTeX source (a backslash other than an
    escaped dollar sign, ``\\$``, which is the paper's own)."""
    return "\\" in piece.replace("\\$", "")


def _printed_tex(text: str) -> str:
    r"""The Printed cell of a PDF claim table: the paper's words as text, its formulas as math
    (a long one scaled down to the column when wider than it, :func:`fit_math`; a display
    formula inline, without its equation number), and LaTeX transcribed without math
    delimiters as small source text that may break anywhere, so that a narrow column never
    runs over.

    Examples
    --------
    >>> print(_printed_tex("about $10^{-6}$ of it"))
    about $10^{-6}$ of it
    >>> long = "$$\\frac{2\\pi}{\\lambda}\\left(l_{t}^{(m),n} - l_{t}^{(n),n}\\right)^T x \\quad (17)$$"
    >>> print(_printed_tex(long))
    \navcorefitmath{\frac{2\pi}{\lambda}\left(l_{t}^{(m),n} - l_{t}^{(n),n}\right)^T x}
    >>> "\\ttfamily" in _printed_tex("\\mathbf{P}_N \\mathbf{P}_N^T = \\sigma_N^2 \\mathbf{I}")
    True
    """
    text = _DISPLAY.sub(lambda m: "$" + _EQ_NUMBER.sub("", m.group(1)).strip() + "$", text)
    pieces = math_spans(text)
    if any(_latex_source(piece) for is_math, piece in pieces if not is_math):  # LaTeX without delimiters
        return r"{\scriptsize\ttfamily " + tex_breakable(text) + "}"
    out = []
    for is_math, piece in math_spans(_quote_markup(text)):
        out.append(
            fit_math(quote_math(piece))
            if is_math
            else _emphasis(piece.replace("\\$", "$"), tex_breakable, r"\textbf{{{}}}", r"\emph{{{}}}")
        )
    return "".join(out)


#: A quote of at most 16 characters besides the bold of its compared number
#: (:func:`mark_compared_number`), kept on one line like a short value.
_MARKED_SHORT = re.compile(r"(?=.{0,20}$)([^$\\^*]*)\*\*([\d.]+)\*\*([^$\\^*]*)")


def _printed_html(text: str, *, fold: int = 0) -> str:
    r"""The Printed cell of an HTML claim table: the paper's words as text and its formulas as
    MathJax math (a display formula inline, without its equation number), a long formula in a
    box of its own, cut where TeX may break it so that it wraps in a narrow column
    (:func:`_math_html`), and LaTeX transcribed without math delimiters as small source text
    that may break anywhere. A short value stays on one line.

    Parameters
    ----------
    text : str
        What the paper printed (:func:`_printed_text`).
    fold : int, optional
        A quote longer than this many characters is folded behind a "quote" disclosure
        (0: never), so that a narrow column is not a long thin paragraph; so is a shorter one
        that the interactive ledger's Printed column cannot hold (:func:`_fits_printed_column`).

    Examples
    --------
    >>> print(_printed_html("about 10 m"))
    about&nbsp;10&nbsp;m
    >>> print(_printed_html("$$x = 1 \\quad (3)$$"))
    <span class="math notranslate nohighlight">\(x = 1\)</span>
    >>> "<details" in _printed_html("a long sentence the paper printed, word for word", fold=20)
    True
    >>> [_printed_html(q, fold=40).startswith("<details") for q in ("$p = 50$", "$y = (G'G)^{-1}G'z$")]
    [False, True]
    """
    if len(text) <= 16 and not any(ch in text for ch in "$\\^*"):
        return _nowrap(text)
    marked = _MARKED_SHORT.fullmatch(text)
    if marked:  # a short quote with its compared number in bold (:func:`mark_compared_number`)
        before, number, after = (html.escape(g).replace(" ", "&nbsp;") for g in marked.groups())
        return f"{before}<strong>{number}</strong>{after}"
    text = _DISPLAY.sub(lambda m: "$" + _EQ_NUMBER.sub("", m.group(1)).strip() + "$", text)
    pieces = math_spans(text)
    if any(_latex_source(piece) for is_math, piece in pieces if not is_math):  # LaTeX without delimiters
        body = f'<code class="ledger-latex">{html.escape(text)}</code>'
    else:
        out = []
        for is_math, piece in math_spans(_quote_markup(text)):
            if not is_math:  # a dollar sign of the paper's (a price) is not a math delimiter
                out.append(
                    _emphasis(piece, html.escape, "<strong>{}</strong>", "<em>{}</em>").replace(
                        "\\$", _HTML_DOLLAR
                    )
                )
                continue
            out.append(_math_html(quote_math(piece), _FIT_MATH_CHARS))
        body = "".join(out)
    plain = text.replace("**", "")  # a quote's bold (the compared number) is no wider
    if fold and (len(plain) > fold or not _fits_printed_column(plain)):
        return f'<details class="ledger-quote"><summary>quote</summary>{body}</details>'
    return body


#: The interactive ledger's Printed column is about 55 px wide at 1400 px (8 % of its table): a
#: word of more than this many characters breaks inside itself there ("resultin-g")...
_PRINTED_COLUMN_WORD = 8


#: ... and it holds a formula of about 5.7 em as MathJax sets it at the equation fitting's 70 %,
#: which :func:`math_em` puts at 3.3 to 4.8 em (MathJax sets 1.18 to 1.75 times its measure;
#: ``\text{Exp}g = 12.5``, 3.57 em here, sets 85 px and was cut in its 55 px box, December 2026).
_PRINTED_COLUMN_MATH_EM = 3.0


def _fits_printed_column(text: str) -> bool:
    r"""Whether a short quote can stand unfolded in the interactive ledger's narrow Printed
    column: no word longer than :data:`_PRINTED_COLUMN_WORD` characters and no formula whose
    widest unbreakable piece is wider than :data:`_PRINTED_COLUMN_MATH_EM` by :func:`math_em`.

    Examples
    --------
    >>> _fits_printed_column("282 ft"), _fits_printed_column("The resulting error statistics")
    (True, False)
    >>> _fits_printed_column("Appendix G"), _fits_printed_column("Appendices")
    (True, False)
    >>> _fits_printed_column("$p = 50$"), _fits_printed_column(r"$\text{Exp}g = 12.5$")
    (True, False)
    """
    words, wide = [], 0.0
    for is_math, piece in math_spans(text):
        if is_math:
            wide = max(wide, *(math_em(part) for part in _math_parts(quote_math(piece))))
        else:
            words += piece.split()
    return wide <= _PRINTED_COLUMN_MATH_EM and all(len(w) <= _PRINTED_COLUMN_WORD for w in words)


#: A quoted formula whose widest unbreakable piece sets wider than this (:func:`math_em`) does
#: not fit the Printed column even set at 70 % (its box is 16 em of the table's text, so 22.9
#: em of it at 70 %; MathJax sets 1.18 to 1.5 times :func:`math_em`, median 1.35). Calibrated
#: on every formula the claim tables quoted (December 2026): the seven that scrolled in their
#: box measure 19.1 to 31.8 em here (26 to 43 em of text as set), the widest of those that fit
#: 16.2 em (21.8 em as set); 17.5 lies between, so that none of those that fit moves.
_QUOTE_BELOW_EM = 17.5


def quote_below(text: str) -> bool:
    r"""Whether a claim's printed quote is shown in a full-width line under its claim's row (in
    the Printed column, "the equation below"): a formula of it that cannot be cut where TeX
    may break it into pieces the column holds, its widest piece (:func:`_math_parts`) wider
    than 17.5 em by :func:`math_em`, a measure of the formula's source alone, so that the
    layout does not depend on the browser.

    Parameters
    ----------
    text : str
        What the paper printed (:func:`_printed_text`).

    Returns
    -------
    bool
        True if the quote goes under its claim's row.

    Examples
    --------
    >>> quote_below("$$x = a + b \\quad (3)$$"), quote_below("about 10 m")
    (False, False)
    >>> quote_below("$$(G'P_n^{-1}G)^{-1}G'P_n^{-1}FP_{\\xi_x}F'P_n^{-1}G(G'P_n^{-1}G)^{-1}$$")
    True
    """
    text = _DISPLAY.sub(lambda m: "$" + _EQ_NUMBER.sub("", m.group(1)).strip() + "$", text)
    pieces = math_spans(text)
    if not any(is_math for is_math, _ in pieces) or any(
        _latex_source(piece) for is_math, piece in pieces if not is_math
    ):
        return False
    widths = [
        math_em(part)
        for is_math, piece in math_spans(_quote_markup(text))
        if is_math
        for part in _math_parts(quote_math(piece))
    ]
    return max(widths) > _QUOTE_BELOW_EM


def _below_words(text: str) -> str:
    """The Printed cell of a claim whose quote is shown under its row (:func:`quote_below`)."""
    text = _DISPLAY.sub(lambda m: "$" + m.group(1) + "$", text)
    words = "".join(piece for is_math, piece in math_spans(text) if not is_math).strip(" .,;:")
    return "the quote below" if words else "the equation below"


def _reproduced_text(e: Evaluation) -> str:
    if _is_truth(e.reproduced):
        return _statement_word(bool(e.reproduced), printed=False)
    return _plain_with_unit(format_value(e.reproduced), e.claim.unit)


def _value_html(text: str) -> str:
    r"""A value with its unit (:func:`_plain_with_unit`) as HTML: the number and a plain unit
    kept on one line (:func:`_nowrap`), a unit set as math typeset.

    Examples
    --------
    >>> print(_value_html("3.986×10¹⁴ $\\mathrm{m}^{3}$"))
    3.986×10¹⁴&nbsp;<span class="math notranslate nohighlight">\(\mathrm{m}^{3}\)</span>
    """
    return "".join(
        html_text(f"${piece}$") if is_math else _nowrap(piece) for is_math, piece in math_spans(text)
    )


def _nowrap(text: str) -> str:
    """A short value kept on one line (number and unit together); words ("does not hold")
    and long text may wrap at their spaces."""
    escaped = html.escape(text)
    short_number = len(text) <= 16 and any(ch.isdigit() for ch in text)
    return escaped.replace(" ", "&nbsp;") if short_number else escaped


def _tolerance_text(e: Evaluation) -> str:
    """The tolerance and its reason in one phrase; empty for an exact truth value (a
    statement either holds or not)."""
    tol = e.tolerance if e.tolerance is not None else e.claim.tolerance
    if not hasattr(tol, "describe"):
        return ""
    size, reason = tol.describe(), getattr(tol, "reason", "")
    if size == "exact" and e.claim.is_statement:
        return ""
    if reason.lower().startswith(size.lower()):
        return reason
    return f"{size}: {reason}" if reason else size


def _reading_label(name: str, value: Any) -> str | None:
    """The words of a convention's reading whose value is the code word ``value`` (``"C/N0"``:
    "$C/N_0$ in dB-Hz"), as the conventions table shows it; ``None`` for anything else."""
    if not isinstance(value, str):
        return None
    try:
        inp = get_input(name)
    except (KeyError, ValueError):
        return None
    return next((label for label, v in inp.readings if v == value), None)


#: Longest text of a table-valued input in a claim's inputs; longer ones end after a row.
_TABLE_TEXT_WIDTH = 100


def _table_value_text(value: Any) -> str | None:
    r"""A table-valued input (rows of cells, or a mapping) as a reader reads it, never as Python
    prints a list: a numeric matrix by its size ("a $3 \times 6$ matrix"), other rows as
    their cells ("Position 3, Velocity 3, ..."), cut after a row and counted when long;
    ``None`` for a value that is not a table.

    Examples
    --------
    >>> _table_value_text([["Position", 3], ["Velocity", 3]])
    'Position 3, Velocity 3'
    >>> _table_value_text([[1, 0, -1], [0, 1, 0]])
    'a $2 \\times 3$ matrix'
    >>> _table_value_text([["a long row name " * 3, i] for i in range(5)])[-8:]
    '(5 rows)'
    >>> _table_value_text([1, 2]) is None
    True
    """
    if isinstance(value, dict):
        rows: list[Any] = [[k, v] for k, v in value.items()]
    elif isinstance(value, list | tuple) and value and all(isinstance(r, list | tuple) for r in value):
        rows = list(value)
    else:
        return None
    numeric = all(isinstance(c, int | float) and not isinstance(c, bool) for r in rows for c in r)
    widths = {len(r) for r in rows}
    if numeric and len(widths) == 1:
        return f"a ${len(rows)} \\times {widths.pop()}$ matrix"

    def cell(c: Any) -> str:
        return format_value(c) if isinstance(c, int | float) else str(c)

    texts = [" ".join(cell(c) for c in r) for r in rows]
    whole = ", ".join(texts)
    if len(whole) <= _TABLE_TEXT_WIDTH:
        return whole
    kept: list[str] = []
    for t in texts:
        if len(", ".join([*kept, t])) > _TABLE_TEXT_WIDTH - 12:
            break
        kept.append(t)
    return ", ".join(kept) + f", … ({len(rows)} rows)"


def _inputs_text(e: Evaluation) -> str:
    """The inputs the computation read: name, value (a convention's code word as its reading's
    words), where it comes from."""
    parts = []
    for i in e.inputs:
        value = i.get("value")
        label, unit = _label_and_unit(i["name"])
        reading = _reading_label(i["name"], value)
        if reading is not None:  # words written for a reader: whole, never cut inside a formula
            shown = reading
        elif isinstance(value, list | tuple) and all(
            isinstance(v, int | float) and not isinstance(v, bool) for v in value
        ):  # a reading that sets several numbers: each as a number, not as Python prints a list
            shown = "(" + ", ".join(format_value(v) for v in value) + ")"
        elif (table := _table_value_text(value)) is not None:
            shown = table
            reading = table  # already short: not cut below
        else:
            shown = format_value(value) if isinstance(value, int | float) else str(value)
        if reading is None and len(shown) > 40:
            shown = shown[:39] + "…"
        elif isinstance(value, int | float) and not isinstance(value, bool):
            shown = _plain_with_unit(shown, unit)
        where = i.get("provenance", "")
        if i.get("locator"):
            where += f", {i['locator']}"
        parts.append(f"{label} = {shown} ({where})")
    return "; ".join(parts)


def _band_text(e: Evaluation) -> str:
    """The details' band line: its ends at the digits of the note's sentences (one precision per
    claim, :func:`~navcore.claims.evaluation.note_digits`); ``""`` when they print the same."""
    if e.band is None or e.claim.is_statement:
        return ""
    lo, hi = e.band
    digits = e._note_digits()
    low, high = format_value(lo, digits), format_value(hi, digits)
    if low == high:  # a range whose two ends print the same: no range
        return ""
    left_out = left_out_of_band(e)
    return (
        f"{low} to {high}"
        + (f" {unit_text(e.claim.unit)}" if e.claim.unit not in ("", "statement") else "")
        + (f" (left out, outside the model's domain: {left_out})" if left_out else "")
    )


def _agreeing_reading_text(e: Evaluation) -> str:
    """Where only readings other than the one used agree, or the one used agrees only over a
    band too wide to decide while another decides: "agrees under: <labels>".

    Each agreeing reading the note shows (:meth:`~navcore.claims.evaluation.Evaluation.shown_readings`:
    not those that differ only in conventions whose readings change nothing) is named by what
    it changes from the one used (the labels of the reading used are not repeated); a reading
    that only adds changes to another agreeing reading listed is left out."""
    nominal = next((r for r in e.readings if r["nominal"]), None)
    if nominal is None:
        return ""
    # the readings the note shows: those of conventions that change nothing are folded away
    shown = e.shown_readings()
    if nominal["agrees"]:
        if not nominal.get("band_too_wide") or e.status != "consistent":
            return ""
        agreeing = [r for r in shown if r["agrees"] and not r.get("band_too_wide")]
    else:
        agreeing = [r for r in shown if r["agrees"]]
    inert = set(e.inert_conventions())
    changes = []
    for r in agreeing:
        changed = tuple(
            (name, label)
            for name, label in r["reading"].items()
            if name not in inert and label != nominal["reading"].get(name, PRECISION_STRICT)
        )
        if changed and changed not in changes:
            changes.append(changed)
    # a reading whose changes include another listed reading's adds nothing to "agrees under"
    minimal = [c for c in changes if not any(set(o) < set(c) for o in changes)]
    labels = ["; ".join(reader_label(label) for _, label in c) for c in minimal]
    return "agrees under: " + " / ".join(labels) if labels else ""


_SOFT_HYPHENS = {
    "typography": "typo&shy;graphy",
    "convention": "con&shy;vention",
    "derivation": "deri&shy;vation",
    "assumption": "as&shy;sumption",
    "overstatement": "over&shy;statement",
    "reproduced": "repro&shy;duced",
    "consistent": "consis&shy;tent",
    "inconsistent": "incon&shy;sistent",
    "discrepant": "discrep&shy;ant",
    "reproducible": "repro&shy;ducible",
    # the papers' locator words
    "Appendix": "Ap&shy;pen&shy;dix",
    "discussion": "dis&shy;cus&shy;sion",
    "approximation": "ap&shy;prox&shy;i&shy;ma&shy;tion",
    "acceleration": "ac&shy;cel&shy;er&shy;a&shy;tion",
    "sensitivity": "sen&shy;si&shy;tiv&shy;i&shy;ty",
    "covariance": "co&shy;vari&shy;ance",
    "corollary": "cor&shy;ol&shy;lary",
    "assertion": "as&shy;ser&shy;tion",
    "acquisition": "ac&shy;qui&shy;si&shy;tion",
    "inertial": "in&shy;er&shy;tial",
    "residual": "resid&shy;ual",
    "equation": "equa&shy;tion",
    "comment": "com&shy;ment",
    "Theorem": "The&shy;o&shy;rem",
    "caption": "cap&shy;tion",
    "paragraph": "para&shy;graph",
    "conclusion": "con&shy;clu&shy;sion",
    "Introduction": "In&shy;tro&shy;duc&shy;tion",
    "abstract": "ab&shy;stract",
    "Abstract": "Ab&shy;stract",
    "definition": "def&shy;i&shy;ni&shy;tion",
    "footnote": "foot&shy;note",
}


def _breakable_heading(text: str) -> str:
    """A column heading that may break in a narrow window: between words, after a hyphen,
    and at a soft hyphen inside the verdict names."""
    words = []
    for word in text.split(" "):
        parts = [_SOFT_HYPHENS.get(part, html.escape(part)) for part in word.split("-")]
        words.append("-<wbr>".join(parts))
    return "<br>".join(words)
