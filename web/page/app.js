// The halfplane page: a form that is a case file, the library (WebAssembly, halfplane-web) run on
// it at every edit, and the results as the command shows them, with SVG drawings. A classic
// script (no modules) so that the page works from file://. Every number comes from the binding;
// this script only writes the case file, places the answers and draws them.
"use strict";

// ---------------------------------------------------------------------------------------------
// The form: the case file's sections and fields, as the file names them.

// The fields of a load point (cycle.point1, cycle.point2). The moment M is the pressure's moment
// about x = 0 (its resultant acts at x = M/P); empty means 0, as in the case file.
const POINT_FIELDS = [
  { key: "normal", label: "normal load P", unit: "force" },
  { key: "shear", label: "shear load Q", unit: "force" },
  { key: "bulk", label: "bulk tension σ", unit: "stress", optional: true },
  { key: "moment", label: "moment M about x = 0", unit: "moment", optional: true },
];
const POINTS = [
  { key: "point1", defaults: { normal: "1000.0", shear: "-250.0", bulk: "-20.0" } },
  { key: "point2", defaults: { normal: "1400.0", shear: "250.0", bulk: "20.0" } },
];

// Each profile kind and its fields (profile.KEY).
const PROFILE_KINDS = {
  "hertz": [{ key: "radius", label: "relative radius of curvature R", unit: "length", value: "50.0" }],
  "flat-rounded": [
    { key: "flat_half_width", label: "flat half-width b", unit: "length", value: "0.3" },
    { key: "radius", label: "edge radius R (empty when the two below are given)", unit: "length", value: "50.0", optional: true },
    { key: "left_radius", label: "left edge radius R_L (unequal edges, with R_R)", unit: "length", value: "", optional: true },
    { key: "right_radius", label: "right edge radius R_R (unequal edges, with R_L)", unit: "length", value: "", optional: true },
  ],
  "power-law": [
    { key: "coefficient", label: "B in g = B|x|^k", value: "0.01" },
    { key: "exponent", label: "exponent k ≥ 1", value: "2.0" },
  ],
  "tabulated": [
    { key: "data", label: "table: CSV with a header x,g (x ≥ 0, or both sides)", type: "table", value: "" },
    { key: "kinks", label: "kinks: x where g' has a corner (optional, space-separated)", type: "list", optional: true, value: "" },
  ],
};

// The other sections: [section] and its fields. `type`: number (default), count, text, select.
const SECTIONS = [
  { name: "material", title: "Material", fields: [
    { key: "youngs_modulus", label: "Young's modulus E (both bodies)", unit: "stress", value: "200000.0" },
    { key: "poisson_ratio", label: "Poisson's ratio ν", value: "0.3" },
  ] },
  { name: "friction", title: "Friction", fields: [
    { key: "coefficient", label: "Coulomb friction coefficient f", value: "0.6" },
  ] },
  { name: "profile", title: "Profile" },
  { name: "cycle", title: "Cycle: its two end points" },
  { name: "history", title: "March the cycle", optional: true, fields: [
    { key: "cycles", label: "cycles (after the ramp)", type: "count", value: "2" },
    { key: "steps_per_half", label: "increments per half-cycle", type: "count", value: "50" },
    { key: "ramp", label: "ramp from zero", type: "select", options: ["normal-first", "proportional"], value: "normal-first" },
    { key: "ramp_steps", label: "ramp increments", type: "count", value: "20" },
  ] },
  { name: "solver", title: "Marching solver", fields: [
    { key: "cells", label: "cells across the largest contact", type: "count", value: "200" },
  ] },
  { name: "units", title: "Units (names only: no conversion)", fields: [
    { key: "force", label: "force", type: "text", value: "", optional: true, placeholder: "N" },
    { key: "length", label: "length", type: "text", value: "", optional: true, placeholder: "mm" },
    { key: "stress", label: "stress", type: "text", value: "", optional: true, placeholder: "MPa" },
  ] },
];
// Settings of the page, not of the case (the command's --points).
const PAGE_FIELDS = [
  { path: "points", label: "evolve: points per half-cycle (ends included)", type: "count", value: "21" },
];
// The regimes of the load-space map (halfplane-web's analyses::REGIMES) and their colours.
const REGIME_COLOURS = {
  "partial-slip": "#f7d9b5",
  "full-stick": "#cfe9d7",
  "gross-sliding": "#e4e4e4",
  "outside-analysis": "#f2c4c4",
  "solver": "#dcd3f2",
};
const REGIME_WORDS = {
  "partial-slip": "partial slip: permanent stick zone with slip at both edges",
  "full-stick": "full stick: no slip anywhere in the steady state",
  "gross-sliding": "gross sliding (|Q| ≥ fP at an end): no steady partial-slip state",
};
const MAP_SIZE = [60, 40];
const STICK = "#2e8b57";
const SLIP = "#e0802a";

const $ = (id) => document.getElementById(id);
const inputs = new Map(); // dotted path -> input element
// Declared by the glue (halfplane_web.js) as a global binding, not a property of window.
const wasm = wasm_bindgen; // eslint-disable-line no-undef
let generation = 0;
// Sections of a linked case that the form does not write, kept as written (TOML text).
let otherSections = "";
let formHistory = true; // whether the form writes [history] and [solver]
let firstResultShown = false;

// ---------------------------------------------------------------------------------------------
// Building the form.

function make(tag, attrs = {}, parent = null, text = null) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== null) e.textContent = text;
  if (parent) parent.appendChild(e);
  return e;
}

function fieldInput(path, spec, parent) {
  const box = make("div", { class: "field", "data-field": path }, parent);
  const id = "in-" + path.replace(/\./g, "-");
  const label = make("label", { for: id }, box, spec.label + " ");
  if (spec.unit) make("span", { class: "unit", "data-unit": spec.unit }, label);
  let input;
  if (spec.type === "select") {
    input = make("select", { id }, box);
    for (const o of spec.options) make("option", { value: o }, input, o);
  } else if (spec.type === "table") {
    input = make("textarea", { id, rows: "6", spellcheck: "false" }, box);
    const load = make("input", { type: "file", accept: ".csv,text/csv,text/plain", "aria-label": "load a CSV file" }, box);
    load.addEventListener("change", () => {
      const file = load.files[0];
      if (!file) return;
      const reader = new FileReader();
      reader.onload = () => { input.value = String(reader.result); schedule(); };
      reader.readAsText(file);
    });
  } else {
    input = make("input", { id, type: "text", inputmode: spec.type === "text" ? "text" : "decimal", spellcheck: "false" }, box);
    if (spec.placeholder) input.placeholder = spec.placeholder;
  }
  input.value = spec.value ?? "";
  input.dataset.path = path;
  input.dataset.type = spec.type || "number";
  if (spec.optional) input.dataset.optional = "1";
  make("div", { class: "field-error", "data-error-for": path }, box);
  inputs.set(path, input);
  input.addEventListener("input", schedule);
  input.addEventListener("change", schedule);
  return input;
}

function buildForm() {
  const root = $("form-sections");
  for (const section of SECTIONS) {
    const set = make("fieldset", { "data-section": section.name }, root);
    const legend = make("legend", {}, set);
    if (section.optional) {
      const on = make("input", { type: "checkbox", id: "on-" + section.name, checked: "" }, legend);
      on.addEventListener("change", () => { showSections(); schedule(); });
    }
    legend.append(section.title + " ");
    make("code", {}, legend, `[${section.name}]`);
    if (section.name === "profile") {
      const kind = fieldInput("profile.kind", { label: "kind", type: "select", options: Object.keys(PROFILE_KINDS), value: "hertz" }, set);
      kind.addEventListener("change", showSections);
      for (const [name, fields] of Object.entries(PROFILE_KINDS)) {
        const group = make("div", { "data-kind": name }, set);
        for (const f of fields) {
          // A key two kinds share (radius) is one input per kind, told apart by the kind.
          fieldInput(`profile.${name}.${f.key}`, f, group).dataset.key = `profile.${f.key}`;
        }
      }
    } else if (section.name === "cycle") {
      const table = make("table", { class: "point-table" }, set);
      const head = make("tr", {}, make("thead", {}, table));
      make("th", {}, head);
      for (const p of POINTS) make("th", {}, head, p.key);
      const body = make("tbody", {}, table);
      for (const f of POINT_FIELDS) {
        const row = make("tr", {}, body);
        const th = make("th", {}, row, f.label + " ");
        make("span", { class: "unit", "data-unit": f.unit }, th);
        for (const p of POINTS) {
          const path = `cycle.${p.key}.${f.key}`;
          const input = make("input", { type: "text", inputmode: "decimal", "aria-label": `${p.key} ${f.label}`, "data-path": path }, make("td", {}, row));
          input.value = p.defaults[f.key] ?? "";
          input.dataset.type = "number";
          if (f.optional) input.dataset.optional = "1";
          inputs.set(path, input);
          input.addEventListener("input", schedule);
        }
      }
      for (const p of POINTS) {
        for (const f of POINT_FIELDS) make("div", { class: "field-error", "data-error-for": `cycle.${p.key}.${f.key}` }, set);
      }
    } else {
      for (const f of section.fields) fieldInput(`${section.name}.${f.key}`, f, set);
    }
  }
  const page = make("fieldset", { "data-section": "page" }, root);
  make("legend", {}, page, "Page");
  for (const f of PAGE_FIELDS) fieldInput(f.path, f, page);
  showSections();
}

function marchOn() {
  return formHistory && $("on-history").checked;
}

function showSections() {
  const kind = inputs.get("profile.kind").value;
  for (const group of document.querySelectorAll("[data-kind]")) group.hidden = group.dataset.kind !== kind;
  for (const name of ["history", "solver"]) {
    const set = document.querySelector(`fieldset[data-section=${name}]`);
    for (const box of set.querySelectorAll(".field")) box.hidden = !marchOn();
  }
}

// ---------------------------------------------------------------------------------------------
// The case file the form stands for.

// A number as TOML writes it: the shortest form that reads back exactly; `nan` for text that is
// no number, which the library then refuses with its own message naming the field.
function tomlFloat(text) {
  const t = text.trim();
  if (t === "") return null;
  const x = Number(t);
  if (!Number.isFinite(x)) return "nan";
  const s = String(x);
  return /[.eE]/.test(s) ? s : s + ".0";
}

function tomlCount(text) {
  const t = text.trim();
  if (t === "") return null;
  if (/^\d+$/.test(t)) return BigInt(t).toString();
  const x = Number(t);
  return Number.isFinite(x) ? tomlFloat(t) : JSON.stringify(t);
}

function tomlValue(input) {
  const text = input.value;
  switch (input.dataset.type) {
    case "count": return tomlCount(text);
    case "text": return text.trim() === "" ? null : JSON.stringify(text.trim());
    case "select": return JSON.stringify(text);
    case "list": {
      const items = text.split(/[\s,;]+/).filter((s) => s !== "");
      return items.length ? "[" + items.map(tomlFloat).join(", ") + "]" : null;
    }
    case "table": {
      if (text.trim() === "") return null;
      const body = text.replace(/\\/g, "\\\\").replace(/"""/g, '""\\"');
      return '"""\n' + body + (body.endsWith("\n") ? "" : "\n") + '"""';
    }
    default: return tomlFloat(text);
  }
}

function caseToml() {
  const lines = [];
  const put = (key, input) => {
    const v = tomlValue(input);
    if (v !== null) lines.push(`${key} = ${v}`);
  };
  for (const section of SECTIONS) {
    if ((section.name === "history" || section.name === "solver") && !marchOn()) continue;
    const start = lines.length;
    if (section.name === "profile") {
      const kind = inputs.get("profile.kind").value;
      lines.push(`kind = ${JSON.stringify(kind)}`);
      for (const f of PROFILE_KINDS[kind]) put(f.key, inputs.get(`profile.${kind}.${f.key}`));
    } else if (section.name === "cycle") {
      // A case without a cycle (a linked one) stays without: every point field empty.
      if (POINTS.every((p) => POINT_FIELDS.every((f) => inputs.get(`cycle.${p.key}.${f.key}`).value.trim() === ""))) continue;
      for (const p of POINTS) {
        const parts = [];
        for (const f of POINT_FIELDS) {
          const v = tomlValue(inputs.get(`cycle.${p.key}.${f.key}`));
          if (v !== null) parts.push(`${f.key} = ${v}`);
        }
        lines.push(`${p.key} = { ${parts.join(", ")} }`);
      }
    } else {
      if (section.name === "history") lines.push('kind = "cycle"');
      for (const f of section.fields) put(f.key, inputs.get(`${section.name}.${f.key}`));
    }
    if (lines.length > start) lines.splice(start, 0, (start ? "\n" : "") + `[${section.name}]`);
  }
  const text = lines.join("\n") + "\n";
  return otherSections ? text + "\n" + otherSections : text;
}

// Fills the form from case text (a #case= link); returns the fields the form does not show.
function fillForm(text) {
  const answer = call("case_fields", text);
  if (answer.error) return { error: answer.error };
  const fields = answer.ok;
  const used = new Set();
  const kind = fields["profile.kind"];
  if (kind in PROFILE_KINDS) {
    inputs.get("profile.kind").value = kind;
    used.add("profile.kind");
  }
  const history = fields["history.kind"];
  // A history the form cannot show (a harmonic or tabulated one) is kept as written.
  formHistory = history === undefined || history === "cycle";
  $("on-history").checked = history === "cycle";
  $("on-history").disabled = !formHistory;
  if (history === "cycle") used.add("history.kind");
  const owned = ["material", "friction", "profile", "cycle", "units"].concat(formHistory ? ["history", "solver"] : []);
  const others = call("other_sections", text, owned.join(","));
  otherSections = others.ok || "";
  for (const [path, input] of inputs) {
    if (path === "profile.kind" || path === "points") continue;
    const key = input.dataset.key || path;
    if (key.startsWith("profile.") && !path.startsWith(`profile.${kind}.`)) continue;
    if ((key.startsWith("history.") || key.startsWith("solver.")) && history !== "cycle") continue;
    if (key in fields) {
      input.value = fields[key];
      used.add(key);
    } else if (input.dataset.type === "select") {
      input.selectedIndex = 0;
    } else {
      input.value = "";
    }
  }
  // A table given by its file is left for the binding, which names the field.
  if (fields["profile.file"] !== undefined) inputs.get("profile.tabulated.data").value = "";
  showSections();
  const ownedKey = (k) => owned.includes(k.split(".")[0]);
  const kept = [...new Set(Object.keys(fields).filter((k) => !ownedKey(k)).map((k) => `[${k.split(".")[0]}]`))];
  return { notShown: Object.keys(fields).filter((k) => ownedKey(k) && !used.has(k)), kept };
}

// ---------------------------------------------------------------------------------------------
// Calling the library.

function call(name, ...args) {
  return JSON.parse(wasm[name](...args));
}

function schedule() {
  clearTimeout(schedule.timer);
  schedule.timer = setTimeout(update, 200);
}

function fmt(x, decimals = 6) {
  return x === null || x === undefined ? "–" : x.toFixed(decimals);
}

// A result number: the text as the command's table writes it, every digit in data-value.
function setNumber(id, x, decimals = 6) {
  const e = $(id);
  e.textContent = fmt(x, decimals);
  e.dataset.value = x === null || x === undefined ? "" : x.toPrecision(17);
}

function clearErrors() {
  for (const e of document.querySelectorAll(".field-error")) e.textContent = "";
  for (const e of document.querySelectorAll(".invalid")) e.classList.remove("invalid");
  $("error").textContent = "";
  $("error").dataset.value = "";
  $("hint").hidden = true;
  $("evolve-error").textContent = "";
}

// An error beside its field (when it names one the form has) and in `where`.
function showError(error, where) {
  const field = error.field === "profile.file" ? "profile.data" : error.field;
  if (field) {
    const kind = inputs.get("profile.kind").value;
    const path = field.startsWith("profile.") && field !== "profile.kind" ? `profile.${kind}.${field.slice(8)}` : field;
    const box = document.querySelector(`[data-error-for="${CSS.escape(path)}"]`);
    if (box) {
      box.textContent = error.message;
      const input = inputs.get(path);
      if (input) (input.closest(".field") || input).classList.add("invalid");
    }
  }
  if (where) {
    where.textContent = error.message;
    where.dataset.value = error.message;
  }
  if (error.hint) {
    $("hint").textContent = error.hint + ".";
    $("hint").hidden = false;
  }
}

function update() {
  const gen = ++generation;
  const toml = caseToml();
  share(toml);
  clearErrors();
  const started = performance.now();
  const steady = call("steady", toml);
  if (steady.error) {
    showError(steady.error, $("error"));
    $("steady-results").hidden = true;
    $("evolve-results").hidden = steady.error.kind !== "outside-analysis";
    $("evolution").textContent = "";
    $("evolve-table").textContent = "";
    $("evolve-warnings").textContent = "";
    markFirstResult();
    if (steady.error.kind === "outside-analysis" && marchOn()) later(gen, () => runMarch(gen, toml, null));
    return;
  }
  const report = steady.ok.report;
  showSteady(steady.ok);
  const contact = call("contact", toml);
  if (contact.ok) drawContact(report, contact.ok);
  drawLoadSpace(report, null);
  const evolve = call("evolve", toml, inputs.get("points").value);
  $("evolve-results").hidden = false;
  let evolution = null;
  if (evolve.error) {
    showError(evolve.error, $("evolve-error"));
    $("evolution").textContent = "";
    $("evolve-table").textContent = "";
    $("evolve-warnings").textContent = "";
  } else {
    evolution = evolve.ok.report;
    $("evolve-table").textContent = evolve.ok.table;
    $("evolve-warnings").textContent = evolution.warnings.join("\n");
    drawEvolution(evolution, null);
  }
  $("timing").dataset.computeMs = (performance.now() - started).toFixed(1);
  markFirstResult();
  later(gen, () => {
    const map = call("regime_map", toml, MAP_SIZE[0], MAP_SIZE[1]);
    if (map.ok) drawLoadSpace(report, map.ok);
  });
  if (marchOn()) later(gen, () => runMarch(gen, toml, evolution));
  else $("march-status").textContent = "";
}

// Runs `work` after the browser has drawn what is on screen, unless the form changed meanwhile.
function later(gen, work) {
  setTimeout(() => { if (gen === generation) work(); }, 0);
}

function runMarch(gen, toml, evolution) {
  const t0 = performance.now();
  const march = call("march", toml);
  const ms = performance.now() - t0;
  if (gen !== generation) return;
  const status = $("march-status");
  if (march.error) {
    showError(march.error, null);
    status.textContent = "march: " + march.error.message;
    return;
  }
  const m = march.ok;
  status.textContent = `Dots: the stick zone of the last cycle marched numerically (${m.cells} cells, ` +
    `${m.increments} increments, ${ms.toFixed(0)} ms in this browser), as halfplane march gives it.`;
  status.dataset.marchMs = ms.toFixed(1);
  if (m.stick) drawEvolution(evolution, m.stick);
}

function markFirstResult() {
  if (firstResultShown) return;
  firstResultShown = true;
  // After the browser has painted the result.
  requestAnimationFrame(() => setTimeout(() => {
    const ms = performance.now();
    document.documentElement.dataset.firstResultMs = ms.toFixed(0);
    $("timing").textContent = `First result ${ms.toFixed(0)} ms after the page started loading.`;
  }, 0));
}

// ---------------------------------------------------------------------------------------------
// The results.

function unitNames(report) {
  const u = report.units;
  return { force: `${u.force}/${u.length}`, length: u.length, stress: u.stress, moment: `${u.force}·${u.length}/${u.length}` };
}

function showUnits(report) {
  const names = unitNames(report);
  for (const e of document.querySelectorAll("[data-unit]")) {
    const name = names[e.dataset.unit];
    e.textContent = e.tagName === "TD" ? name : `(${name})`;
  }
}

function showSteady(answer) {
  const r = answer.report;
  $("steady-results").hidden = false;
  showUnits(r);
  $("regime").textContent = r.regime;
  $("regime").dataset.value = r.regime;
  $("regime-words").textContent = "— " + REGIME_WORDS[r.regime];
  const c = r.criteria;
  const ratio = c.full_stick_ratio === null ? "infinite (ΔP = 0)" : fmt(c.full_stick_ratio);
  $("criteria").textContent = `|Q|/P = ${fmt(c.shear_ratio_1)} at point1, ${fmt(c.shear_ratio_2)} at point2 ` +
    `(gross sliding when ≥ f = ${c.friction}); ` +
    (r.contact.left_1 !== -r.contact.right_1 || r.contact.left_2 !== -r.contact.right_2
      ? `eq. (1) edge by edge: max |ΔS|/|ΔP_edge| along the cycle = ${ratio} `
      : `eq. (1): (|ΔQ| + π a_max |Δσ|/4)/|ΔP| = ${ratio} `) +
    `(full stick when ≤ f).`;
  setNumber("half-width-1", r.contact.half_width_1);
  setNumber("half-width-2", r.contact.half_width_2);
  const z = r.stick_zone;
  setNumber("stick-left", z && z.left);
  setNumber("stick-right", z && z.right);
  $("stick-extra").textContent = z ? `d = ${fmt(z.half_width)}, e = ${fmt(z.eccentricity)}` : "(none: the contact slides)";
  const s = r.slip_zones;
  setNumber("slip-left-1", s && s.left.at_point1);
  setNumber("slip-left-2", s && s.left.at_point2);
  setNumber("slip-right-1", s && s.right.at_point1);
  setNumber("slip-right-2", s && s.right.at_point2);
  $("note").hidden = !answer.note;
  $("note").textContent = answer.note || "";
  $("steady-table").textContent = answer.table;
}

function share(toml) {
  $("case-toml").textContent = toml;
  const download = $("download");
  if (download.href.startsWith("blob:")) URL.revokeObjectURL(download.href);
  download.href = URL.createObjectURL(new Blob([toml], { type: "application/toml" }));
  const hash = "#case=" + encodeURIComponent(toml);
  const link = location.href.split("#")[0] + hash;
  $("share-link").href = link;
  try { history.replaceState(null, "", hash); } catch (e) { /* some file:// pages refuse */ }
}

// ---------------------------------------------------------------------------------------------
// Drawing: a small SVG chart with linear axes.

const SVG = "http://www.w3.org/2000/svg";

function svg(tag, attrs, parent) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

function ticks(lo, hi, count = 6) {
  const span = hi - lo;
  let step = Math.pow(10, Math.floor(Math.log10(span / count)));
  for (const m of [1, 2, 2.5, 5, 10]) {
    if (span / (step * m) <= count) { step *= m; break; }
  }
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  let decimals = 0;
  while (decimals < 10 && Math.abs(Math.round(step * 10 ** decimals) - step * 10 ** decimals) > 1e-6) decimals++;
  return out.map((v) => [v, v.toFixed(decimals)]);
}

class Chart {
  constructor(parent, { width = 640, height = 300, x, y, xlabel, ylabel, title }) {
    this.m = { left: 64, right: 14, top: title ? 26 : 10, bottom: 42 };
    this.w = width;
    this.h = height;
    this.x = x;
    this.y = y;
    this.root = svg("svg", { viewBox: `0 0 ${width} ${height}`, width, height, role: "img" }, parent);
    if (title) this.text(width / 2, 16, title, { "text-anchor": "middle", "font-weight": "600" });
    this.clip = "clip" + Math.random().toString(36).slice(2);
    const defs = svg("defs", {}, this.root);
    svg("rect", { x: this.m.left, y: this.m.top, width: this.pw(), height: this.ph() }, svg("clipPath", { id: this.clip }, defs));
    this.plot = svg("g", { "clip-path": `url(#${this.clip})` }, this.root);
    this.axes(xlabel, ylabel);
  }
  pw() { return this.w - this.m.left - this.m.right; }
  ph() { return this.h - this.m.top - this.m.bottom; }
  sx(v) { return this.m.left + (v - this.x[0]) / (this.x[1] - this.x[0]) * this.pw(); }
  sy(v) { return this.m.top + (this.y[1] - v) / (this.y[1] - this.y[0]) * this.ph(); }
  text(x, y, s, attrs = {}, parent = this.root) {
    const t = svg("text", { x, y, ...attrs }, parent);
    t.textContent = s;
    return t;
  }
  axes(xlabel, ylabel) {
    const g = svg("g", { class: "axes" }, this.root);
    const [x0, x1, y0, y1] = [this.m.left, this.w - this.m.right, this.m.top, this.h - this.m.bottom];
    svg("rect", { x: x0, y: y0, width: x1 - x0, height: y1 - y0, fill: "none", stroke: "#8a939c" }, g);
    for (const [v, label] of ticks(...this.x)) {
      const px = this.sx(v);
      svg("line", { x1: px, x2: px, y1: y1, y2: y1 + 4, stroke: "#8a939c" }, g);
      this.text(px, y1 + 16, label, { "text-anchor": "middle" }, g);
    }
    for (const [v, label] of ticks(...this.y, 5)) {
      const py = this.sy(v);
      svg("line", { x1: x0 - 4, x2: x0, y1: py, y2: py, stroke: "#8a939c" }, g);
      this.text(x0 - 6, py + 4, label, { "text-anchor": "end" }, g);
    }
    this.text((x0 + x1) / 2, this.h - 6, xlabel, { "text-anchor": "middle" }, g);
    this.text(14, (y0 + y1) / 2, ylabel, { "text-anchor": "middle", transform: `rotate(-90 14 ${(y0 + y1) / 2})` }, g);
  }
  line(points, attrs) {
    const d = points.map(([x, y], i) => `${i ? "L" : "M"}${this.sx(x).toFixed(2)},${this.sy(y).toFixed(2)}`).join("");
    return svg("path", { d, fill: "none", ...attrs }, this.plot);
  }
  polygon(points, attrs) {
    return svg("polygon", { points: points.map(([x, y]) => `${this.sx(x).toFixed(2)},${this.sy(y).toFixed(2)}`).join(" "), ...attrs }, this.plot);
  }
  rect(x0, y0, x1, y1, attrs) {
    const [a, b] = [this.sx(x0), this.sx(x1)];
    const [c, d] = [this.sy(y1), this.sy(y0)];
    return svg("rect", { x: Math.min(a, b), y: Math.min(c, d), width: Math.abs(b - a), height: Math.abs(d - c), ...attrs }, this.plot);
  }
  dot(x, y, r, attrs) {
    return svg("circle", { cx: this.sx(x), cy: this.sy(y), r, ...attrs }, this.plot);
  }
}

// A legend below a chart: [label, colour, "line" | "dash" | "fill" | "dot"].
function legend(parent, items) {
  const box = document.createElement("div");
  box.className = "legend";
  const width = 640;
  const row = 18;
  const perRow = 3;
  const height = row * Math.ceil(items.length / perRow) + 4;
  const root = svg("svg", { viewBox: `0 0 ${width} ${height}`, width, height }, box);
  items.forEach(([label, colour, kind], i) => {
    const x = 64 + (i % perRow) * 190;
    const y = 10 + Math.floor(i / perRow) * row;
    if (kind === "fill") svg("rect", { x, y: y - 6, width: 18, height: 12, fill: colour, stroke: "#8a939c" }, root);
    else if (kind === "dot") svg("circle", { cx: x + 9, cy: y, r: 3.5, fill: colour }, root);
    else svg("line", { x1: x, x2: x + 18, y1: y, y2: y, stroke: colour, "stroke-width": 2, "stroke-dasharray": kind === "dash" ? "5 3" : "none" }, root);
    const t = svg("text", { x: x + 24, y: y + 4 }, root);
    t.textContent = label;
  });
  parent.appendChild(box);
}

// The load space: the P-Q path of the cycle, the friction lines Q = ±fP, and the regime the
// steady analysis finds with point 2 moved to each place (point 1 and σ2 as given).
function drawLoadSpace(r, map) {
  const box = $("load-space");
  box.textContent = "";
  const units = unitNames(r);
  const f = r.friction;
  const p1 = r.points.at_point1;
  const p2 = r.points.at_point2;
  const top = 1.25 * Math.max(p1.normal, p2.normal);
  const chart = new Chart(box, {
    height: 340, x: [0, top], y: [-f * top, f * top],
    xlabel: `normal load P (${units.force})`, ylabel: `shear load Q (${units.force})`,
    title: "Regime with point 2 moved over the load space (point 1, σ and M/P at point 2 as given)",
  });
  const used = new Set();
  if (map) {
    const [n, m] = [map.normal.length - 1, map.shear.length - 1];
    for (let j = 0; j < m; j++) {
      for (let i = 0; i < n; i++) {
        const regime = map.regimes[map.codes[j * n + i]];
        used.add(regime);
        chart.rect(map.normal[i], map.shear[j], map.normal[i + 1], map.shear[j + 1], { fill: REGIME_COLOURS[regime], stroke: REGIME_COLOURS[regime], "stroke-width": 0.5 });
      }
    }
  }
  chart.line([[0, 0], [top, f * top]], { stroke: "#333", "stroke-dasharray": "6 4" });
  chart.line([[0, 0], [top, -f * top]], { stroke: "#333", "stroke-dasharray": "6 4" });
  chart.line([[p1.normal, p1.shear], [p2.normal, p2.shear]], { stroke: "#1f5fa8", "stroke-width": 2.5 });
  for (const [p, name] of [[p1, "1"], [p2, "2"]]) {
    chart.dot(p.normal, p.shear, 5, { fill: "#1f5fa8" });
    chart.text(chart.sx(p.normal) + 8, chart.sy(p.shear) - 6, name, { "font-weight": "600" }, chart.plot);
  }
  const items = [["cycle, point1 → point2", "#1f5fa8", "line"], ["friction lines Q = ±fP", "#333", "dash"]];
  for (const regime of Object.keys(REGIME_COLOURS)) if (used.has(regime)) items.push([regime, REGIME_COLOURS[regime], "fill"]);
  if (!map) items.push(["(regime map: computing)", "#ffffff", "fill"]);
  legend(box, items);
}

// The contact at both ends: the pressure, and the stick and slip zones on the contact (its ends
// b1, b2 move off centre under a moment).
function drawContact(r, contact) {
  const box = $("contact");
  box.textContent = "";
  const units = unitNames(r);
  const ends = [["point1", contact.at_point1, r.points.at_point1], ["point2", contact.at_point2, r.points.at_point2]];
  const lo = Math.min(contact.at_point1.left, contact.at_point2.left);
  const hi = Math.max(contact.at_point1.right, contact.at_point2.right);
  const margin = 0.15 * 0.5 * (hi - lo);
  const pMax = Math.max(...contact.at_point1.pressure, ...contact.at_point2.pressure);
  const band = 0.16 * pMax;
  for (const [name, c, load] of ends) {
    const which = name === "point1" ? "at_point1" : "at_point2";
    const moment = load.moment ? `, M = ${load.moment} ${units.moment}` : "";
    const chart = new Chart(box, {
      height: 230, x: [lo - margin, hi + margin], y: [-band * 1.6, 1.1 * pMax],
      xlabel: `x (${units.length})`, ylabel: `pressure p (${units.stress})`,
      title: `${name}: P = ${load.normal}, Q = ${load.shear} ${units.force}, σ = ${load.bulk} ${units.stress}${moment}`,
    });
    const [b1, b2] = [c.left, c.right];
    const slip = r.slip_zones;
    const y0 = -1.4 * band;
    const y1 = -0.3 * band;
    if (r.regime === "gross-sliding") {
      chart.rect(b1, y0, b2, y1, { fill: SLIP });
    } else if (r.regime === "full-stick") {
      chart.rect(b1, y0, b2, y1, { fill: STICK });
    } else {
      const left = b1 + slip.left[which];
      const right = b2 - slip.right[which];
      chart.rect(b1, y0, left, y1, { fill: SLIP });
      chart.rect(left, y0, right, y1, { fill: STICK });
      chart.rect(right, y0, b2, y1, { fill: SLIP });
    }
    chart.line([[chart.x[0], 0], [chart.x[1], 0]], { stroke: "#8a939c" });
    chart.line(c.x.map((x, i) => [x, c.pressure[i]]), { stroke: "#1d232b", "stroke-width": 2 });
  }
  legend(box, [["pressure p(x)", "#1d232b", "line"], ["stick", STICK, "fill"], ["slip", SLIP, "fill"]]);
}

// The stick zone along the cycle (evolve), with the marched stick zone of the last cycle as dots.
function drawEvolution(ev, marched) {
  const box = $("evolution");
  box.textContent = "";
  const rows = ev ? ev.points : [];
  const t = (p) => (p.half === 1 ? p.fraction : 1 + p.fraction);
  let lo = Math.min(0, ...rows.map((p) => p.contact_left));
  let hi = Math.max(0, ...rows.map((p) => p.contact_right));
  if (marched) {
    lo = Math.min(lo, ...marched.map(([, l]) => l));
    hi = Math.max(hi, ...marched.map(([, , r]) => r));
  }
  const margin = 0.15 * 0.5 * (hi - lo);
  const length = ev ? ev.units.length : (inputs.get("units.length").value.trim() || "mm");
  const chart = new Chart(box, {
    height: 320, x: [0, 2], y: [lo - margin, hi + margin],
    xlabel: "time: half 1 (point1 → point2) from 0 to 1, half 2 (back) from 1 to 2",
    ylabel: `x (${length})`, title: "Contact, stick and slip zones along the steady cycle",
  });
  const items = [];
  if (rows.length) {
    for (const half of [1, 2]) {
      const h = rows.filter((p) => p.half === half);
      chart.polygon([...h.map((p) => [t(p), p.contact_right]), ...h.slice().reverse().map((p) => [t(p), p.contact_left])], { fill: "#f7d9b5" });
      chart.polygon([...h.map((p) => [t(p), p.stick_right]), ...h.slice().reverse().map((p) => [t(p), p.stick_left])], { fill: "#cfe9d7" });
      chart.line(h.map((p) => [t(p), p.contact_right]), { stroke: "#1d232b", "stroke-width": 1.5 });
      chart.line(h.map((p) => [t(p), p.contact_left]), { stroke: "#1d232b", "stroke-width": 1.5 });
      chart.line(h.map((p) => [t(p), p.stick_left]), { stroke: "#2e8b57", "stroke-width": 2 });
      chart.line(h.map((p) => [t(p), p.stick_right]), { stroke: "#2e8b57", "stroke-width": 2 });
      chart.line(h.map((p) => [t(p), p.asymptotic_stick_left]), { stroke: "#6b4fa0", "stroke-dasharray": "5 3" });
      chart.line(h.map((p) => [t(p), p.asymptotic_stick_right]), { stroke: "#6b4fa0", "stroke-dasharray": "5 3" });
    }
    items.push(["contact edges", "#1d232b", "line"], ["stick zone (exact)", "#2e8b57", "line"],
      ["asymptotic estimate", "#6b4fa0", "dash"], ["stick", "#cfe9d7", "fill"], ["slip", "#f7d9b5", "fill"]);
  }
  if (marched) {
    for (const [tm, l, r] of marched) {
      chart.dot(tm, l, 2, { fill: "#111" });
      chart.dot(tm, r, 2, { fill: "#111" });
    }
    items.push(["marched stick zone", "#111", "dot"]);
  }
  chart.line([[1, chart.y[0]], [1, chart.y[1]]], { stroke: "#8a939c", "stroke-dasharray": "2 3" });
  legend(box, items);
}

// ---------------------------------------------------------------------------------------------
// Start: the WebAssembly from its base64 script, the case from the link (or the defaults).

function caseFromLocation() {
  const hash = location.hash;
  if (!hash.startsWith("#case=")) return null;
  try {
    return decodeURIComponent(hash.slice(6));
  } catch (e) {
    return hash.slice(6);
  }
}

function loadFromLocation() {
  const text = caseFromLocation();
  const note = $("not-shown");
  note.hidden = true;
  if (text === null) return;
  const filled = fillForm(text);
  if (filled.error) {
    // Case text that is not TOML: shown as the error, the form as it was.
    clearErrors();
    showError(filled.error, $("error"));
    markFirstResult();
    return "failed";
  }
  const words = [];
  if (filled.kept.length) words.push(`Kept from the linked case as written (not shown in the form): ${filled.kept.join(", ")}.`);
  if (filled.notShown.length) words.push(`Fields of the linked case that this page does not show, left out: ${filled.notShown.join(", ")}.`);
  note.textContent = words.join(" ");
  note.hidden = words.length === 0;
}

async function start() {
  buildForm();
  const base64 = window.HALFPLANE_WASM;
  const bytes = new Uint8Array(base64.length * 3 / 4 - (base64.endsWith("==") ? 2 : base64.endsWith("=") ? 1 : 0));
  const text = atob(base64);
  for (let i = 0; i < bytes.length; i++) bytes[i] = text.charCodeAt(i);
  await wasm({ module_or_path: bytes });
  $("version").textContent = wasm.version();
  $("copy-link").addEventListener("click", async () => {
    const link = $("share-link").href;
    try { await navigator.clipboard.writeText(link); } catch (e) { window.prompt("Copy this link:", link); }
  });
  window.addEventListener("hashchange", () => { if (loadFromLocation() !== "failed") update(); });
  if (loadFromLocation() !== "failed") update();
}

start().catch((e) => {
  $("error").textContent = "The page could not start: " + e;
});
