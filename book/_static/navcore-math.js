// A display equation a little wider than its column is set smaller, down to 70 % of its
// size, instead of being cut at the column's edge; one still wider scrolls inside its own
// box. So is a long formula of a claim row (a box of its own, .ledger-math-wide, in which the
// formula's pieces wrap where TeX may break it): its widest piece sets its width. Runs once
// MathJax has typeset the page, again when the window is resized and when a folded "details"
// is opened (a formula folded away has no width until then). An inline formula of running
// text wider than its line is set smaller the same way (fitInline below).
(function () {
  "use strict";
  var SMALLEST = 0.7;

  // Sizes are restored first, then everything measured, then the sizes written (as in
  // fitInline): the page is laid out once, not once per equation.
  function fit() {
    fitInline();
    var blocks = document.querySelectorAll(".bd-article div.math"), eqs = [];
    for (var i = 0; i < blocks.length; i++) {
      var eq = blocks[i].querySelector('mjx-container[display="true"]');
      if (!eq) continue;
      if (eq.dataset.navcoreSize === undefined) eq.dataset.navcoreSize = eq.style.fontSize || "";
      eq.style.fontSize = eq.dataset.navcoreSize;
      eqs.push(eq);
    }
    // the box's own width is in em of the text around it: the formula's pieces are set
    // smaller, not the box
    var boxes = document.querySelectorAll(".bd-article .ledger-math-wide"), pieces = [];
    for (var j = 0; j < boxes.length; j++) {
      var parts = boxes[j].querySelectorAll("mjx-container");
      for (var k = 0; k < parts.length; k++) {
        if (parts[k].dataset.navcoreSize === undefined) parts[k].dataset.navcoreSize = parts[k].style.fontSize || "";
        parts[k].style.fontSize = parts[k].dataset.navcoreSize;
      }
      pieces.push(parts);
    }
    var writes = [];
    for (var a = 0; a < eqs.length; a++) {
      var need = eqs[a].scrollWidth, room = eqs[a].clientWidth;
      if (need <= room + 1) continue;
      var base = parseFloat(eqs[a].dataset.navcoreSize) || 100;
      writes.push([eqs[a], base * Math.max(SMALLEST, (room - 2) / need)]);
    }
    for (var b = 0; b < boxes.length; b++) {
      var box = boxes[b];
      // the typeset formula's extent (the box's scrollWidth also counts a glyph's side bearing)
      var left = box.getBoundingClientRect().left + box.clientLeft, wide = 0;
      var maths = box.querySelectorAll("mjx-math");
      for (var n = 0; n < maths.length; n++) {
        wide = Math.max(wide, maths[n].getBoundingClientRect().right - left);
      }
      var width = box.clientWidth;
      if (!pieces[b].length || width === 0 || wide <= width + 1) continue;
      var shrink = Math.max(SMALLEST, (width - 2) / wide);
      for (var m = 0; m < pieces[b].length; m++) {
        writes.push([pieces[b][m], (parseFloat(pieces[b][m].dataset.navcoreSize) || 100) * shrink]);
      }
    }
    for (var w = 0; w < writes.length; w++) writes[w][0].style.fontSize = writes[w][1].toFixed(1) + "%";
  }

  // An inline formula of running text wider than the line it sits on (an erratum's corrected
  // formula on a phone, a claim's formula in a narrow ledger column) is set smaller, down to
  // 70 %, like a display equation; one still wider keeps its size. Its room: from the start of
  // its block's content to the right edge of the nearest box that clips or scrolls (what the
  // layout gate measures). In a table that sizes its columns by their content, a smaller
  // formula would narrow its column and move the others: only fixed columns (the ledger's)
  // are fitted. The sizes an earlier fitting set are restored first, then everything is
  // measured, then the few sizes written: a page of thousands of formulas is laid out once.
  var BLOCKS = "p, li, td, th, dd, dt, div, figcaption, blockquote, h1, h2, h3, h4, h5, h6";

  function fitInline() {
    var all = document.querySelectorAll('.bd-article mjx-container:not([display="true"])');
    for (var i = 0; i < all.length; i++) {
      if (all[i].dataset.navcoreInline !== undefined) all[i].style.fontSize = all[i].dataset.navcoreInline;
    }
    var clips = new Map(), fixed = new Map(), shrink = [];
    function clipping(el) {
      for (var e = el.parentElement; e && e !== document.body; e = e.parentElement) {
        if (!clips.has(e)) clips.set(e, getComputedStyle(e).overflowX !== "visible");
        if (clips.get(e)) return e;
      }
      return null;
    }
    for (var j = 0; j < all.length; j++) {
      var f = all[j];
      // folded away in a closed "details" (asked of the element tree: offsetParent would lay
      // out the page again for every formula)
      if (f.closest("div.math, .ledger-math-wide, details:not([open]) > :not(summary)")) continue;
      var table = f.closest("table");
      if (table) {
        if (!fixed.has(table)) fixed.set(table, getComputedStyle(table).tableLayout === "fixed");
        if (!fixed.get(table)) continue;
      }
      var box = clipping(f), block = f.parentElement && f.parentElement.closest(BLOCKS);
      if (!box || !block) continue;
      var start = block.getBoundingClientRect().left + block.clientLeft + (parseFloat(getComputedStyle(block).paddingLeft) || 0);
      var room = box.getBoundingClientRect().left + box.clientLeft + box.clientWidth - start;
      var wide = f.getBoundingClientRect().width;
      if (room > 0 && wide > room + 1 && SMALLEST * wide <= room - 2) shrink.push([f, (room - 2) / wide]);
    }
    for (var k = 0; k < shrink.length; k++) {
      var c = shrink[k][0];
      if (c.dataset.navcoreInline === undefined) c.dataset.navcoreInline = c.style.fontSize || "";
      var size = parseFloat(c.dataset.navcoreInline) || 100;
      c.style.fontSize = (size * shrink[k][1]).toFixed(1) + "%";
    }
  }

  var timer = null;
  function refit() {
    if (timer) clearTimeout(timer);
    timer = setTimeout(fit, 150);
  }

  // the layout gate measures each width after running the fitting itself, not after a timer
  window.navcoreFitMath = fit;

  function start() {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
      MathJax.startup.promise.then(fit);
    }
    window.addEventListener("resize", refit);
    // "toggle" does not bubble: listen in the capture phase
    document.addEventListener("toggle", refit, true);
  }

  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", start);
  } else {
    start();
  }
})();
