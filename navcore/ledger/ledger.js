(function () {
  function ready(fn) {
    if (document.readyState !== "loading") fn(); else document.addEventListener("DOMContentLoaded", fn);
  }
  function csvCell(v) {
    if (v === null || v === undefined) return "";
    if (typeof v === "object") v = JSON.stringify(v);
    v = String(v);
    return /[",\n]/.test(v) ? '"' + v.replace(/"/g, '""') + '"' : v;
  }
  function flatten(rec) {
    var out = {};
    Object.keys(rec).forEach(function (k) {
      var v = rec[k];
      if (v && typeof v === "object" && !Array.isArray(v)) {
        Object.keys(v).forEach(function (j) { out[k + "." + j] = v[j]; });
      } else out[k] = v;
    });
    return out;
  }
  // what built the page (commit, lock hash, versions), which the book puts beside the ledger
  function provenance() {
    var el = document.getElementById("navcore-provenance");
    return el ? JSON.parse(el.textContent) : null;
  }
  function buildColumns(prov) {  // as BuildProvenance.flat(): build_commit, ..., build_numpy
    var out = {};
    if (!prov) return out;
    Object.keys(prov).forEach(function (k) {
      if (k !== "packages") out["build_" + k] = prov[k];
    });
    Object.keys(prov.packages || {}).forEach(function (name) {
      out["build_" + name.replace(/-/g, "_")] = prov.packages[name];
    });
    return out;
  }
  function download(name, type, text) {
    var a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([text], {type: type}));
    a.download = name;
    document.body.appendChild(a);
    a.click();
    setTimeout(function () { URL.revokeObjectURL(a.href); a.remove(); }, 0);
  }
  ready(function () {
    document.querySelectorAll("[data-ledger-app]").forEach(function (app) {
      if (app.dataset.ready) return;
      app.dataset.ready = "1";
      var data = JSON.parse(app.querySelector("script.ledger-data").textContent);
      var tbody = app.querySelector("tbody");
      var rows = Array.prototype.slice.call(tbody.querySelectorAll("tr[data-index]"));
      var search = app.querySelector("input[type=search]");
      var selects = app.querySelectorAll("select[data-filter]");
      var count = app.querySelector(".ledger-count");
      var sortKey = null, sortDir = 1;
      function visible() {
        var q = (search.value || "").toLowerCase().trim();
        var want = {};
        selects.forEach(function (s) { if (s.value) want[s.dataset.filter] = s.value; });
        return rows.filter(function (tr) {
          var rec = data[+tr.dataset.index];
          for (var k in want) if (String(rec[k]) !== want[k]) return false;
          // the soft hyphens of long locator words (U+00AD) are not part of the text searched
          return !q || tr.textContent.replace(/\u00ad/g, "").toLowerCase().indexOf(q) >= 0;
        });
      }
      function update() {
        var keep = visible();
        rows.forEach(function (tr) { tr.hidden = true; });
        keep.forEach(function (tr) { tr.hidden = false; });
        count.textContent = keep.length + " of " + rows.length + " claims";
      }
      function rank(v) {
        return typeof v === "number" ? 0 : v === null || v === undefined || v === "" ? 2 : 1;
      }
      function value(tr, key) {
        var v = data[+tr.dataset.index][key];
        if (v && typeof v === "object") v = JSON.stringify(v);
        return v;
      }
      var sortSelect = app.querySelector("select[data-sort]");
      var sortButton = app.querySelector("button[data-sort-dir]");
      // sort by a column (the headings on a wide screen, the sort menu on the cards);
      // no key restores the ledger's order
      function sortBy(key, dir) {
        sortKey = key;
        sortDir = dir;
        app.querySelectorAll("th[data-key]").forEach(function (o) {
          if (key && o.dataset.key === key) o.setAttribute("aria-sort", dir > 0 ? "ascending" : "descending");
          else o.removeAttribute("aria-sort");
        });
        if (sortSelect) sortSelect.value = key || "";
        if (sortButton) sortButton.textContent = dir > 0 ? "ascending" : "descending";
        rows.sort(function (a, b) {
          if (!key) return +a.dataset.index - +b.dataset.index;
          var x = value(a, key), y = value(b, key);
          var rx = rank(x), ry = rank(y);
          if (rx !== ry) return rx - ry;  // numbers, then text and true/false, then blanks
          if (rx === 0) return dir * (x - y);
          if (rx === 2) return 0;
          return dir * String(x).localeCompare(String(y), undefined, {numeric: true});
        });
        rows.forEach(function (tr) { tbody.appendChild(tr); });
      }
      app.querySelectorAll("th[data-key]").forEach(function (th) {
        th.querySelector("button").addEventListener("click", function () {
          var key = th.dataset.key;
          sortBy(key, sortKey === key ? -sortDir : 1);
        });
      });
      if (sortSelect) {
        sortSelect.addEventListener("change", function () { sortBy(sortSelect.value || null, 1); });
      }
      if (sortButton) sortButton.addEventListener("click", function () { sortBy(sortKey, -sortDir); });
      search.addEventListener("input", update);
      selects.forEach(function (s) { s.addEventListener("change", update); });
      app.querySelectorAll("button[data-download]").forEach(function (b) {
        b.addEventListener("click", function () {
          var recs = visible().map(function (tr) { return data[+tr.dataset.index]; });
          var prov = provenance();
          if (b.dataset.download === "json") {
            var doc = {provenance: prov, claims: recs};
            download("ledger.json", "application/json", JSON.stringify(doc, null, 2) + "\n");
          } else {
            var build = buildColumns(prov);
            var flat = recs.map(function (r) { return Object.assign(flatten(r), build); }), keys = [];
            flat.forEach(function (r) {
              Object.keys(r).forEach(function (k) { if (keys.indexOf(k) < 0) keys.push(k); });
            });
            var lines = [keys.map(csvCell).join(",")].concat(flat.map(function (r) {
              return keys.map(function (k) { return csvCell(r[k]); }).join(",");
            }));
            download("ledger.csv", "text/csv", lines.join("\n") + "\n");
          }
        });
      });
      app.classList.add("ledger-app-ready");
      update();
    });
  });
})();
