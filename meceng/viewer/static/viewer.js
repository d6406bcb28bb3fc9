// MecEng viewer: the index table over window.MECENG_DATA (written by `meceng view` into data.js).
// Filters and sorting work on the row arrays; only one page of rows is in the DOM at a time, so
// 20 000 records filter in milliseconds. The filter state lives in the URL's hash (#task=...),
// which is how `meceng report` links a task model's row to its records.
(function () {
  "use strict";
  var t0 = performance.now();
  var D = window.MECENG_DATA;
  if (!D) { throw new Error("data.js did not load: window.MECENG_DATA is missing"); }
  var F = {};
  D.fields.forEach(function (name, i) { F[name] = i; });
  var rows = D.rows;
  var FILTERS = ["run", "model", "level", "task", "status", "failure", "category", "q"];
  var STATUS = ["failed", "passed", "infrastructure"];
  var PAGE = 100;
  var state = { sort: null, desc: false, page: 0 };
  var search = null;  // lower-cased text per row, made on the first search
  var shown = [];

  function esc(s) {
    return String(s).replace(/[&<>"']/g, function (c) {
      return { "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" }[c];
    });
  }
  function value(row, key) {  // what a filter compares
    switch (key) {
      case "run": return String(row[F.run]);
      case "model": return D.runs[row[F.run]].model;
      case "level": return row[F.level];
      case "task": return row[F.slug];
      case "status": return STATUS[row[F.status]];
      case "failure": return row[F.failure] || "(none)";
      default: return "";
    }
  }
  function readHash() {
    var out = {};
    location.hash.replace(/^#/, "").split("&").forEach(function (kv) {
      var i = kv.indexOf("=");
      if (i > 0) { out[decodeURIComponent(kv.slice(0, i))] = decodeURIComponent(kv.slice(i + 1)); }
    });
    if (out.rundir) {  // a run by its folder's name (what `meceng report` knows of a run)
      D.runs.forEach(function (r, i) { if (r.path.split("/").pop() === out.rundir) { out.run = String(i); } });
    }
    return out;
  }
  function filters() {
    var f = {};
    document.querySelectorAll("[data-filter]").forEach(function (el) {
      if (el.value) { f[el.getAttribute("data-filter")] = el.value; }
    });
    return f;
  }
  function writeHash(f) {
    var parts = [];
    FILTERS.forEach(function (k) { if (f[k]) { parts.push(k + "=" + encodeURIComponent(f[k])); } });
    if (state.sort !== null) { parts.push("sort=" + state.sort + (state.desc ? "-" : "")); }
    history.replaceState(null, "", parts.length ? "#" + parts.join("&") : location.pathname);
  }
  function options(select, key, labels) {
    var counts = {};
    rows.forEach(function (r) {
      if (key === "category") {
        (r[F.categories] ? r[F.categories].split("|") : []).forEach(function (c) { counts[c] = (counts[c] || 0) + 1; });
      } else { var v = value(r, key); counts[v] = (counts[v] || 0) + 1; }
    });
    var html = "<option value=''>all</option>";
    Object.keys(counts).sort().forEach(function (v) {
      html += "<option value='" + esc(v) + "'>" + esc(labels ? labels(v) : v) + " (" + counts[v] + ")</option>";
    });
    select.innerHTML = html;
  }
  function matches(f) {
    var q = (f.q || "").toLowerCase();
    if (q && search === null) {
      search = rows.map(function (r) {
        return [r[F.slug], r[F.name], r[F.origin], r[F.draft], r[F.failure], r[F.detail], r[F.categories], r[F.level],
                "seed " + r[F.seed], D.runs[r[F.run]].label].join(" ").toLowerCase();
      });
    }
    var keys = FILTERS.filter(function (k) { return f[k] && k !== "q" && k !== "category"; });
    var out = [];
    for (var i = 0; i < rows.length; i++) {
      var r = rows[i], ok = true;
      for (var k = 0; k < keys.length && ok; k++) { ok = value(r, keys[k]) === f[keys[k]]; }
      if (ok && f.category) { ok = ("|" + r[F.categories] + "|").indexOf("|" + f.category + "|") >= 0; }
      if (ok && q) { ok = search[i].indexOf(q) >= 0; }
      if (ok) { out.push(i); }
    }
    return out;
  }
  function sortKey(i) {
    var r = rows[i];
    switch (state.sort) {
      case "run": return D.runs[r[F.run]].label;
      case "tokens": return r[F.tokens];
      case "llm": return r[F.llm_s];
      case "eval": return r[F.eval_s];
      case "seed": return r[F.seed];
      case "level": return r[F.level];
      case "task": return r[F.slug];
      case "failure": return r[F.failure];
      case "categories": return r[F.categories];
      default: {  // a stage column: failed first when ascending
        var s = r[F.stages].charAt(Number(state.sort.slice(1)));
        return { F: 0, N: 1, R: 2, P: 3, ".": 4 }[s];
      }
    }
  }
  function sortRows(list) {
    if (state.sort === null) { return list; }
    var keyed = list.map(function (i) { return [sortKey(i), i]; });
    keyed.sort(function (a, b) {
      var c = a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : a[1] - b[1];
      return state.desc ? -c : c;
    });
    return keyed.map(function (p) { return p[1]; });
  }
  function header() {
    var cols = [["run", "run"], ["level", "level"], ["task", "task"], ["seed", "seed"]];
    D.stage_labels.forEach(function (label, k) { cols.push(["s" + k, label, D.stages[k]]); });
    cols.push(["failure", "first failure"], ["categories", "error categories"], ["tokens", "tokens"],
              ["llm", "LLM s"], ["eval", "eval. s"]);
    document.querySelector("#records thead").innerHTML = "<tr>" + cols.map(function (c) {
      var arrow = state.sort === c[0] ? (state.desc ? " ▼" : " ▲") : "";
      return "<th data-sort='" + c[0] + "' title='" + esc(c[2] || "sort by " + c[1]) + "'" +
        (c[0].charAt(0) === "s" && c[0] !== "seed" ? " class='st'" : "") + ">" + esc(c[1]) + arrow + "</th>";
    }).join("") + "</tr>";
  }
  function rowHtml(i) {
    var r = rows[i], run = D.runs[r[F.run]], cells = [];
    cells.push("<td title='" + esc(run.label) + "'>" + esc(run.model) + "</td>", "<td>" + esc(r[F.level]) + "</td>");
    cells.push("<td><a href='" + esc(r[F.href]) + "'>" + esc(r[F.slug]) + "</a>" +
               (r[F.origin] ? " <span class='muted'>for " + esc(r[F.origin]) + "</span>" : "") +
               (r[F.rounds] >= 0 ? " <span class='muted'>agent, " + r[F.rounds] + " rounds</span>" : "") +
               (r[F.draft] ? " <span class='muted'>draft " + esc(r[F.draft]) + "</span>" : "") +
               (run.texts && run.texts !== "paper" ? " <span class='texts'>" + esc(run.texts) + " text</span>" : "") +
               "</td>");
    cells.push("<td>" + r[F.seed] + "</td>");
    var codes = r[F.stages];
    for (var k = 0; k < codes.length; k++) {
      var c = codes.charAt(k);
      cells.push("<td class='st " + (c === "." ? "x" : c) + "' title='" + esc(D.stages[k]) + "'></td>");
    }
    var detail = r[F.detail] || "";
    cells.push("<td class='fail" + (r[F.status] === 2 ? " infra" : "") + "' title='" + esc(detail) + "'>" +
               esc(r[F.failure]) + (detail ? "<div class='detail'>" + esc(detail.slice(0, 90)) + "</div>" : "") + "</td>");
    cells.push("<td>" + esc(r[F.categories].split("|").join(", ")) + "</td>",
               "<td class='num'>" + r[F.tokens] + "</td>", "<td class='num'>" + r[F.llm_s].toFixed(2) + "</td>",
               "<td class='num'>" + r[F.eval_s].toFixed(2) + "</td>");
    return "<tr class='" + STATUS[r[F.status]] + "'>" + cells.join("") + "</tr>";
  }
  function pager() {
    var pages = Math.max(1, Math.ceil(shown.length / PAGE)), p = state.page;
    var html = "page " + (p + 1) + " of " + pages;
    if (p > 0) { html = "<a href='#' data-page='" + (p - 1) + "'>◀ previous</a> " + html; }
    if (p < pages - 1) { html += " <a href='#' data-page='" + (p + 1) + "'>next ▶</a>"; }
    document.getElementById("pager").innerHTML = html;
  }
  function render() {
    var body = [], start = state.page * PAGE;
    for (var k = start; k < Math.min(shown.length, start + PAGE); k++) { body.push(rowHtml(shown[k])); }
    document.querySelector("#records tbody").innerHTML = body.join("");
    var count = document.getElementById("count");
    count.textContent = shown.length + " of " + rows.length + " records";
    count.setAttribute("data-shown", shown.length);
    count.setAttribute("data-total", rows.length);
    pager();
  }
  function update(keepPage) {
    var t = performance.now(), f = filters();
    shown = sortRows(matches(f));
    if (!keepPage) { state.page = 0; }
    header();
    render();
    writeHash(f);
    var ms = performance.now() - t;
    document.getElementById("timing").setAttribute("data-filter-ms", ms.toFixed(1));
    return ms;
  }

  document.getElementById("runs").textContent = D.runs.length + " run(s): " +
    D.runs.map(function (r) { return r.label; }).join("; ");
  document.querySelectorAll("select[data-filter]").forEach(function (el) {
    var key = el.getAttribute("data-filter");
    options(el, key, key === "run" ? function (v) { return D.runs[Number(v)].label; } : null);
  });
  var initial = readHash();
  document.querySelectorAll("[data-filter]").forEach(function (el) {
    var key = el.getAttribute("data-filter");
    if (initial[key] !== undefined) { el.value = initial[key]; }
    el.addEventListener(el.tagName === "INPUT" ? "input" : "change", function () { update(false); });
  });
  if (initial.sort) { state.sort = initial.sort.replace(/-$/, ""); state.desc = /-$/.test(initial.sort); }
  document.getElementById("reset").addEventListener("click", function () {
    document.querySelectorAll("[data-filter]").forEach(function (el) { el.value = ""; });
    state.sort = null;
    update(false);
  });
  document.querySelector("#records thead").addEventListener("click", function (e) {
    var key = e.target.getAttribute && e.target.getAttribute("data-sort");
    if (!key) { return; }
    state.desc = state.sort === key ? !state.desc : false;
    state.sort = key;
    update(false);
  });
  document.getElementById("pager").addEventListener("click", function (e) {
    var p = e.target.getAttribute && e.target.getAttribute("data-page");
    if (p === null || p === undefined) { return; }
    e.preventDefault();
    state.page = Number(p);
    render();
  });
  update(false);
  var timing = document.getElementById("timing");
  timing.setAttribute("data-ready-ms", performance.now().toFixed(1));  // since navigation started
  timing.setAttribute("data-script-ms", (performance.now() - t0).toFixed(1));
  timing.textContent = rows.length + " records ready " + performance.now().toFixed(0) + " ms after the page was opened";
  if (initial.bench) {  // measure filtering as a user triggers it: "failed" in a select, then a search typed
    var select = document.querySelector("select[data-filter='status']"), input = document.querySelector("input[data-filter='q']");
    var t = performance.now();
    select.value = "failed";
    select.dispatchEvent(new Event("change"));
    var afterSelect = document.getElementById("count").getAttribute("data-shown");
    input.value = initial.bench === "1" ? "pendulum" : initial.bench;
    input.dispatchEvent(new Event("input"));
    timing.setAttribute("data-bench-ms", (performance.now() - t).toFixed(1));
    timing.setAttribute("data-bench-counts", afterSelect + "," + document.getElementById("count").getAttribute("data-shown"));
  }
}());
