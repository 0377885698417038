"""Layout gate on a built HTML book, measured in headless Chromium: nothing a reader must
scroll sideways to read.

Usage::

    python tools/check_layout.py _build/html                  # 1400 px and 420 px
    python tools/check_layout.py _build/html --width 420 --list

Every page of the book (not the API reference's highlighted sources, the search page or the
indexes) is loaded once, at the first width; once MathJax has typeset it, it is measured, the
viewport is resized to the next width (``Emulation.setDeviceMetricsOverride``: the
stylesheet's media queries follow it) and it is measured again. Four things are measured:

``math``
    a display equation whose rendered width exceeds its box (``scrollWidth > clientWidth``
    of the equation's block, or of MathJax's container inside it), so that the reader sees
    it cut and must scroll it sideways; and a formula elsewhere (in a sentence, a table cell,
    a claim row's quote of a displayed equation) wider than the nearest box that clips it
    (a box of overflow other than ``visible`` that holds no table: a claim row's
    ``ledger-math-wide``): the typeset formula's right edge past the box's width (MathJax's
    ``mjx-math``; the box's ``scrollWidth`` also counts a glyph's side bearing), measured with
    every folded ``details`` opened, as a reader opens them, and named by the nearest anchor
    (``wf-eq6-montecarlo-inline-math-1``). Such a formula in a chapter's claim table
    (``table.ledger-claims``) is reported as ``math``; elsewhere (the interactive ledger's
    narrow columns, a sentence at a phone's width, a report's table) as ``inline``;
``table``
    a table in a cell's output (``div.cell_output``) that is wider than the text column;
``cell``
    a table laid out with fixed column widths (the ledger page's interactive table), which
    keeps its width whatever its cells hold, with a cell whose content runs past the cell:
    a verdict, a heading or the part of a claim id between two hyphens wider than its
    column. Its column widths must also add up to at most the text column (a test reads
    the stylesheet's shares);
``word``
    a table of text (``navcore-text-table``: reasons, sections, readings) whose first
    column, which names the rows, breaks a word across lines ("Appendi" / "x D") rather
    than only after a hyphen, dot, slash or underscore; in a table whose page keeps its
    words whole (``navcore-whole-words``, the Assumptions page's), any column that does
    ("determinis" / "tic").

Several pages are measured at once (``--tabs``, default 4), each in its own tab over the one
DevTools connection; nothing waits a fixed time: each measurement waits for the page's load
event, MathJax's own promise, the fonts and two animation frames. On the same build, on two
cores shared with other work (load 7-15), the whole book took 113-140 s, against 206-259 s
measured one page and one width at a time, for about the same CPU time (26 s against 30 s
in the gate and its browser), with the same overflows found.

The book sets a display equation that is a little too wide smaller, down to 70 % of its size
(``book/_static/navcore-math.js``); the gate reports how many it set smaller, and how small.

At 1400 px nothing may overflow. At 420 px (a phone) an equation that cannot be broken into
lines of that width, or a table whose columns cannot be narrowed further, may scroll inside
its own box: each such item is listed, with the reason, in ``tools/layout_allowlist.json``
(``{"420": {"math": {"page#equation": "why"}, "table": {...}}}``). The gate fails on an
overflow not in the list and on a list entry that no longer overflows (so the list only
shrinks). Equations and tables are named by page and by their anchor (an equation's label)
or their position on the page (``math-3``, ``table-2``; a pandas Styler table's generated id,
which changes with its numbers, is not used), so that the list survives a rebuild.

Chromium is found on the PATH (``chromium``, ``chromium-browser``, ``google-chrome``); when
it is missing and the gate runs as root on Debian it is installed with apt-get, otherwise
the gate fails with the command to install it. It is driven through the DevTools protocol
(a websocket; ``tornado``, which the notebook stack installs, is the client).

Exit status 1 and one line per problem when the gate fails.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ALLOWLIST = ROOT / "tools" / "layout_allowlist.json"
WIDTHS = (1400, 420)
# pages that are not the book's text
SKIP = re.compile(r"^(?:_modules/|_sources/|_static/|_images/|genindex|py-modindex|search\.html)")
BROWSERS = ("chromium", "chromium-browser", "google-chrome")
# what MEASURE reports; "smaller" and "inline" are not problems, only counted (and listed)
KINDS = ("math", "table", "cell", "word", "smaller", "inline")
# pages measured at once, each in its own tab
TABS = 4
# a page not loaded and measured within this many seconds fails the gate (it never hangs)
PAGE_TIMEOUT = 180

# measured in the page once MathJax has typeset it; returns {"math": [...], "table": [...]}
MEASURE = r"""
(async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
  }
  if (document.fonts && document.fonts.ready) { await document.fonts.ready; }
  // the book's equation fitting (navcore-math.js) at this viewport's width, as a fresh load
  // or a resize would run it
  if (window.navcoreFitMath) { window.navcoreFitMath(); }
  await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
  const root = document.querySelector('article.bd-article') || document.body;
  const over = el => el.scrollWidth > el.clientWidth + 1;
  const out = {math: [], table: [], cell: [], word: [], smaller: [], inline: []};
  let i = 0;
  for (const block of root.querySelectorAll('div.math')) {
    i += 1;
    const inner = block.querySelector('mjx-container[display="true"]');
    const size = inner ? inner.dataset.navcoreSize : undefined;
    if (size !== undefined && inner.style.fontSize !== size) {
      const base = parseFloat(size) || 100;
      out.smaller.push({name: block.id || ('math-' + i), scale: parseFloat(inner.style.fontSize) / base});
    }
    if (over(block) || (inner && over(inner))) {
      const el = inner && over(inner) ? inner : block;
      out.math.push({name: block.id || ('math-' + i), scroll: el.scrollWidth, client: el.clientWidth,
                     text: (block.textContent || '').trim().slice(0, 60)});
    }
  }
  let j = 0;
  const column = root.clientWidth;
  for (const table of root.querySelectorAll('div.cell_output table')) {
    j += 1;
    const box = table.closest('div.output') || table.parentElement;
    const width = table.getBoundingClientRect().width;
    if (width > box.clientWidth + 1 || width > column + 1) {
      const head = Array.from(table.querySelectorAll('th')).map(t => t.textContent.trim()).join(' | ');
      // a pandas Styler table's id (T_ and a hash of its content) changes with its numbers: by position
      const named = table.id && !/^T_[0-9a-f]+$/.test(table.id);
      out.table.push({name: named ? table.id : ('table-' + j), scroll: Math.round(width),
                      client: box.clientWidth, text: head.slice(0, 60)});
    }
  }
  // a table of fixed column widths (the interactive ledger) keeps its width whatever its
  // cells hold: a word wider than its column (a verdict, a claim id's part between hyphens,
  // a heading) runs past its cell instead, so each cell is measured
  let k = 0;
  for (const table of root.querySelectorAll('table')) {
    if (getComputedStyle(table).tableLayout !== 'fixed') continue;
    k += 1;
    let worst = null, n = 0;
    for (const cell of table.querySelectorAll('th, td')) {
      if (cell.closest('tr[hidden]') || cell.offsetParent === null) continue;
      if (over(cell)) {
        n += 1;
        const by = c => c.scrollWidth - c.clientWidth;
        if (!worst || by(cell) > by(worst)) worst = cell;
      }
    }
    if (worst) {
      const col = (worst.className.match(/ledger-col-(\w+)/) || [])[1] || worst.cellIndex;
      out.cell.push({name: (table.id || ('fixed-table-' + k)), scroll: worst.scrollWidth,
                     client: worst.clientWidth,
                     text: n + ' cell(s) wider than their column, e.g. column ' + col + ': ' +
                           (worst.textContent || '').trim().slice(0, 40)});
    }
  }
  // a table of text names its rows in its first column ("Appendix D", "Sec. 2.5"): a word
  // there broken across lines ("Appendi/x") is measured as a piece of it, between two
  // hyphens, dots, slashes or underscores, whose text spans more than one line box
  let m = 0;
  for (const table of root.querySelectorAll('table.navcore-text-table')) {
    m += 1;
    // a table whose page keeps its words whole (navcore-whole-words) is measured in every cell
    const whole = table.classList.contains('navcore-whole-words');
    for (const cell of table.querySelectorAll(whole ? 'tbody td' : 'tbody td:first-child')) {
      if (cell.offsetParent === null) continue;
      const walker = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT);
      let broken = null;
      for (let node = walker.nextNode(); node && !broken; node = walker.nextNode()) {
        const re = /[^\s\-./_\u200b]+/g;
        let w;
        while ((w = re.exec(node.data)) !== null) {
          const range = document.createRange();
          range.setStart(node, w.index);
          range.setEnd(node, w.index + w[0].length);
          const rects = Array.from(range.getClientRects()).filter(r => r.width > 0);
          const tops = new Set(rects.map(r => Math.round(r.top)));
          if (tops.size > 1) { broken = w[0]; break; }
        }
      }
      if (broken) {
        const where = cell.cellIndex === 0 ? 'first column' : 'column ' + (cell.cellIndex + 1);
        out.word.push({name: 'text-table-' + m, scroll: cell.scrollWidth, client: cell.clientWidth,
                       text: where + ' breaks inside "' + broken + '"'});
        break;
      }
    }
  }
  // math outside the page's display blocks: a formula in a text, a table cell or a claim row
  // (a quoted display equation set inline, in a box of its own that scrolls,
  // .ledger-math-wide), measured with every folded "details" opened, as a reader opens them.
  // A formula overflows when the nearest box that clips it (overflow other than visible) is
  // narrower than what it holds; a box that holds a table is the table's scroller (the
  // "table" and "cell" measurements), not the formula's. Display math in such a place
  // clips in its own container.
  const folded = Array.from(root.querySelectorAll('details:not([open])'));
  folded.forEach(d => { d.open = true; });
  if (folded.length) {
    if (window.navcoreFitMath) { window.navcoreFitMath(); }
    await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
  }
  const boxes = new Set();
  const counts = {};
  for (const c of root.querySelectorAll('mjx-container')) {
    if (c.closest('div.math') || c.offsetParent === null) continue;
    let box = null;
    if (c.getAttribute('display') === 'true') {
      box = c;
    } else {
      for (let el = c.parentElement; el && el !== root; el = el.parentElement) {
        if (getComputedStyle(el).overflowX !== 'visible') { box = el; break; }
      }
    }
    if (!box || boxes.has(box) || box.querySelector('table')) continue;
    boxes.add(box);
    // what the reader sees: the typeset formulas' extent past the box's left edge (its
    // scrollWidth also counts a glyph's few pixels of side bearing)
    const left = box.getBoundingClientRect().left + box.clientLeft;
    let need = 0;
    for (const m of box.querySelectorAll('mjx-math')) {
      need = Math.max(need, Math.round(m.getBoundingClientRect().right - left));
    }
    if (need <= box.clientWidth + 1) continue;
    const anchor = box.closest('[id]');
    const at = anchor && anchor !== root ? anchor.id : 'page';
    counts[at] = (counts[at] || 0) + 1;
    // a claim row of a chapter's claim table is held to it; elsewhere it is counted
    const kind = box.closest('table.ledger-claims') ? 'math' : 'inline';
    out[kind].push({name: at + '-inline-math-' + counts[at], scroll: need,
                    client: box.clientWidth, text: (box.textContent || '').trim().slice(0, 60)});
  }
  folded.forEach(d => { d.open = false; });
  return JSON.stringify(out);
})()
"""


def find_browser() -> str:
    """The Chromium executable, installed with apt-get when missing and running as root."""
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    command = ["apt-get", "install", "-y", "--no-install-recommends", "chromium"]
    if hasattr(os, "geteuid") and os.geteuid() == 0 and shutil.which("apt-get"):
        env = {**os.environ, "DEBIAN_FRONTEND": "noninteractive"}
        subprocess.run(["apt-get", "update", "-qq"], check=True, env=env)
        subprocess.run(command, check=True, env=env)
        path = shutil.which("chromium")
        if path:
            return path
    raise SystemExit(f"check_layout: Chromium is needed; install it with:\n    sudo {' '.join(command)}")


class Browser:
    """One headless Chromium, driven over one DevTools connection.

    Each page is measured in a tab of its own (a target attached in flat mode, its commands
    and events carried on the browser's connection with the tab's ``sessionId``), several tabs
    at once; one reader task hands each reply to the command that waits for it and each event
    to its tab's queue.
    """

    def __init__(self, executable: str):
        self.profile = tempfile.mkdtemp(prefix="navcore-layout-")
        self.proc = subprocess.Popen(
            [
                executable,
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                "--no-first-run",
                "--hide-scrollbars",
                # tabs measured side by side are all "visible": none is throttled
                "--disable-background-timer-throttling",
                "--disable-renderer-backgrounding",
                "--disable-backgrounding-occluded-windows",
                f"--user-data-dir={self.profile}",
                "--remote-debugging-port=0",
                "about:blank",
            ],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
        )
        assert self.proc.stderr is not None
        for line in self.proc.stderr:
            m = re.search(r"DevTools listening on (ws://\S+)", line)
            if m:
                self.browser_ws = m.group(1)
                break
        else:
            raise SystemExit("check_layout: Chromium did not start its DevTools endpoint")
        # keep reading Chromium's log, so that a full pipe never blocks it
        self._drain = threading.Thread(target=lambda: [None for _ in self.proc.stderr or ()], daemon=True)
        self._drain.start()
        self.ids = 0
        self.pending: dict[int, asyncio.Future] = {}
        self.events: dict[str, asyncio.Queue] = {}

    async def connect(self) -> None:
        from tornado.websocket import websocket_connect

        self.ws = await websocket_connect(self.browser_ws, max_message_size=1 << 26)
        self.reader = asyncio.ensure_future(self._read())

    async def _read(self) -> None:
        while True:
            msg = await self.ws.read_message()
            if msg is None:
                for future in self.pending.values():
                    if not future.done():
                        future.set_exception(SystemExit("check_layout: Chromium closed the connection"))
                return
            data = json.loads(msg)
            if "id" in data:
                future = self.pending.pop(data["id"], None)
                if future is not None and not future.done():
                    future.set_result(data)
            elif data.get("sessionId") in self.events:
                self.events[data["sessionId"]].put_nowait(data)

    async def call(self, method: str, params: dict | None = None, session: str | None = None) -> dict:
        self.ids += 1
        ident = self.ids
        future = asyncio.get_running_loop().create_future()
        self.pending[ident] = future
        message: dict = {"id": ident, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        self.ws.write_message(json.dumps(message))
        data = await future
        if "error" in data:
            raise RuntimeError(f"{method}: {data['error']}")
        return data.get("result", {})

    async def open_tab(self) -> str:
        """A new tab in a window of its own (a background tab is not rendered: its animation
        frames never come), attached: its session id."""
        target = await self.call("Target.createTarget", {"url": "about:blank", "newWindow": True})
        attached = await self.call("Target.attachToTarget", {"targetId": target["targetId"], "flatten": True})
        session = attached["sessionId"]
        self.events[session] = asyncio.Queue()
        await self.call("Page.enable", {}, session)
        return session

    async def measure(self, session: str, url: str, widths: tuple[int, ...]) -> dict[int, dict]:
        """The page's measurements at each width: loaded once, at the first width, then the
        viewport resized to each other width (the stylesheet's media queries and the book's
        equation fitting follow the viewport, as on a fresh load at that width)."""
        events = self.events[session]
        out: dict[int, dict] = {}
        for n, width in enumerate(widths):
            await self.call(
                "Emulation.setDeviceMetricsOverride",
                {"width": width, "height": 1200, "deviceScaleFactor": 1, "mobile": False},
                session,
            )
            if n == 0:
                while not events.empty():  # events of the tab's previous page
                    events.get_nowait()
                await self.call("Page.navigate", {"url": url}, session)
                while (await events.get()).get("method") != "Page.loadEventFired":
                    pass
            result = await self.call(
                "Runtime.evaluate",
                {"expression": MEASURE, "awaitPromise": True, "returnByValue": True, "timeout": 60000},
                session,
            )
            value = result.get("result", {}).get("value")
            if value is None:
                raise RuntimeError(f"{url} at {width} px: measurement failed: {result}")
            out[width] = json.loads(value)
        return out

    def close(self) -> None:
        if hasattr(self, "ws"):  # the connection and its reader first, then Chromium
            # tornado waits up to 5 s for Chromium's half of the close handshake, on an event
            # loop that ends with the measurement: close the socket itself too (an unclosed one
            # is reported when it is collected, in whatever runs next)
            stream = getattr(getattr(self.ws, "protocol", None), "stream", None)
            self.ws.close()
            if stream is not None:
                stream.close()
            self.reader.cancel()
        self.proc.terminate()
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self._drain.join(timeout=10)
        if self.proc.stderr is not None:
            self.proc.stderr.close()
        shutil.rmtree(self.profile, ignore_errors=True)


def pages(root: Path) -> list[Path]:
    """The book's pages: not the skipped ones, nor a page that only redirects (index.html)."""
    return [
        p
        for p in sorted(root.rglob("*.html"))
        if not SKIP.match(p.relative_to(root).as_posix())
        and 'http-equiv="Refresh"' not in p.read_text(encoding="utf-8", errors="replace")[:2000]
    ]


async def _measure_all(
    root: Path, widths: tuple[int, ...], tabs: int
) -> dict[int, dict[str, list[tuple[str, dict]]]]:
    browser = Browser(find_browser())
    todo = pages(root)
    got: dict[Path, dict[int, dict]] = {}
    try:
        await browser.connect()
        queue: asyncio.Queue[Path] = asyncio.Queue()
        for page in todo:
            queue.put_nowait(page)

        async def worker() -> None:
            session = await browser.open_tab()
            while not queue.empty():
                page = queue.get_nowait()
                try:
                    got[page] = await asyncio.wait_for(
                        browser.measure(session, page.resolve().as_uri(), widths), PAGE_TIMEOUT
                    )
                except TimeoutError:
                    late = f"check_layout: {page} was not measured within {PAGE_TIMEOUT} s"
                    raise SystemExit(late) from None

        await asyncio.gather(*(worker() for _ in range(max(1, min(tabs, len(todo))))))
    finally:
        browser.close()
    found: dict[int, dict[str, list[tuple[str, dict]]]] = {w: {k: [] for k in KINDS} for w in widths}
    for page in todo:  # in the pages' order, whichever tab finished first
        rel = page.relative_to(root).as_posix()
        for width in widths:
            for kind in KINDS:
                for item in got[page][width].get(kind, []):
                    found[width][kind].append((f"{rel}#{item['name']}", item))
    return found


def measure(
    root: Path, widths: tuple[int, ...] = WIDTHS, tabs: int = TABS
) -> dict[int, dict[str, list[tuple[str, dict]]]]:
    """Overflowing display equations, output tables and table cells of every page, per width."""
    return asyncio.run(_measure_all(root, widths, tabs))


def check(
    root: Path, widths: tuple[int, ...] = WIDTHS, list_all: bool = False, tabs: int = TABS
) -> list[str]:
    allow = json.loads(ALLOWLIST.read_text(encoding="utf-8")) if ALLOWLIST.exists() else {}
    found = measure(root, widths, tabs=tabs)
    problems = []
    for width in widths:
        smaller = found[width].get("smaller", [])
        if smaller:
            least = min(item["scale"] for _, item in smaller)
            print(
                f"check_layout: {width} px: {len(smaller)} display equation(s) set smaller to fit "
                f"(smallest at {100 * least:.0f} %)",
                file=sys.stderr,
            )
            if list_all:
                for name, item in smaller:
                    print(f"{width} px: smaller {name} at {100 * item['scale']:.0f} %")
        for kind in ("math", "inline", "table", "cell", "word"):
            allowed = allow.get(str(width), {}).get(kind, {})
            names = set()
            for name, item in found[width].get(kind, []):
                names.add(name)
                size = f"{item['scroll']} px in a {item['client']} px box"
                line = f"{width} px: {kind} {name} is {size}: {item['text']}"
                if list_all:
                    print(line)
                if name not in allowed:
                    problems.append(line)
            problems += [
                f"{width} px: {kind} {name} is in the allowlist but no longer overflows: remove it"
                for name in sorted(set(allowed) - names)
            ]
            print(
                f"check_layout: {width} px: {len(found[width].get(kind, []))} overflowing {kind} "
                f"({len(allowed)} allowed)",
                file=sys.stderr,
            )
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("html", type=Path, help="the built HTML book (_build/html)")
    parser.add_argument("--width", type=int, action="append", help="px (default: 1400 and 420)")
    parser.add_argument("--list", action="store_true", help="print every overflow, allowed or not")
    parser.add_argument("--tabs", type=int, default=TABS, help=f"pages measured at once (default: {TABS})")
    args = parser.parse_args(argv)
    if args.tabs < 1:
        parser.error(f"--tabs must be at least 1, not {args.tabs}")
    widths = tuple(args.width) if args.width else WIDTHS
    problems = check(args.html, widths, args.list, args.tabs)
    for line in problems:
        print(line)
    print(f"check_layout: {len(problems)} problem(s)", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
