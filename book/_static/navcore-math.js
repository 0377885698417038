// A display equation a little wider than its column is set smaller, down to 70 % of its
// size, instead of being cut at the column's edge; one still wider scrolls inside its own
// box. Runs once MathJax has typeset the page, and again when the window is resized.
(function () {
  "use strict";
  var SMALLEST = 0.7;

  function fit() {
    var blocks = document.querySelectorAll(".bd-article div.math");
    for (var i = 0; i < blocks.length; i++) {
      var eq = blocks[i].querySelector('mjx-container[display="true"]');
      if (!eq) continue;
      if (eq.dataset.navcoreSize === undefined) eq.dataset.navcoreSize = eq.style.fontSize || "";
      eq.style.fontSize = eq.dataset.navcoreSize;
      var need = eq.scrollWidth, room = eq.clientWidth;
      if (need <= room + 1) continue;
      var base = parseFloat(eq.dataset.navcoreSize) || 100;
      var scale = Math.max(SMALLEST, (room - 2) / need);
      eq.style.fontSize = (base * scale).toFixed(1) + "%";
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
  }

  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", start);
  } else {
    start();
  }
})();
