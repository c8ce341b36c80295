// The binding against the command: on every bundled example, the page's steady and evolve
// reports equal `halfplane steady --json` and `halfplane evolve --json` (every key and text
// exactly, every number to 1e-12 relative: see `close`),
// an example the command refuses is refused with the command's message, and the marched stick
// zone of the last cycle equals the command's march, increment by increment.
//
// Run by scripts/web-check after ./scripts/web: node --test web/tests/ (HALFPLANE_CLI names the
// command, default target/debug/halfplane).
"use strict";
const test = require("node:test");
const assert = require("node:assert");
const fs = require("node:fs");
const path = require("node:path");
const { spawnSync } = require("node:child_process");
const { inlineTables } = require("./cases.js");

const root = path.resolve(__dirname, "../..");
const web = path.join(root, "target/web");
const cli = process.env.HALFPLANE_CLI || path.join(root, "target/debug/halfplane");
const glue = fs.readFileSync(path.join(web, "halfplane_web.js"), "utf8");
const binding = new Function(glue + "\nreturn wasm_bindgen;")();
binding.initSync({ module: fs.readFileSync(path.join(web, "halfplane_web_bg.wasm")) });

function run(...args) {
  const r = spawnSync(cli, args, { encoding: "utf8" });
  assert.ok(r.status === 0 || r.status === 2, `${args.join(" ")}: exit ${r.status} ${r.stderr}`);
  return r;
}

function ask(name, ...args) {
  return JSON.parse(binding[name](...args));
}

// Numbers of the page and of the command agree to 1e-12 relative (or 1e-14 absolute, for values
// that are zero in exact arithmetic): the command uses the system's libm (glibc) for sin, cos,
// asin..., the WebAssembly build Rust's own port of musl's, and the two may differ in the last
// bit, which an iterative solve carries to a few units in the last place (2 ulps seen in evolve
// on the flat-rounded and tabulated examples; steady agreed exactly on every example).
function close(a, b, where) {
  if (typeof a === "number" && typeof b === "number") {
    const ok = a === b || Math.abs(a - b) <= 1e-12 * Math.max(Math.abs(a), Math.abs(b)) || Math.abs(a - b) <= 1e-14;
    assert.ok(ok, `${where}: ${a} (page) and ${b} (command)`);
  } else if (Array.isArray(a) && Array.isArray(b)) {
    assert.strictEqual(a.length, b.length, `${where}: lengths`);
    a.forEach((x, i) => close(x, b[i], `${where}[${i}]`));
  } else if (a && b && typeof a === "object" && typeof b === "object") {
    assert.deepStrictEqual(Object.keys(a).sort(), Object.keys(b).sort(), `${where}: keys`);
    for (const k of Object.keys(a)) close(a[k], b[k], `${where}.${k}`);
  } else {
    assert.strictEqual(a, b, where);
  }
}

// The binding's answer against the command's: the same report, or both refuse with its message.
function same(answer, command, what) {
  if (command.status === 0) {
    assert.ok(answer.ok, `${what}: the command succeeds, the page says ${JSON.stringify(answer.error)}`);
    close(answer.ok.report, JSON.parse(command.stdout), what);
  } else {
    assert.ok(answer.error, `${what}: the command fails (${command.stderr.trim()}), the page does not`);
    assert.ok(command.stderr.includes(answer.error.message),
      `${what}: the page's message\n  ${answer.error.message}\nis not the command's\n  ${command.stderr}`);
  }
}

const examples = fs.readdirSync(path.join(root, "examples")).filter((f) => f.endsWith(".toml")).sort();

test("there are examples to compare", () => assert.ok(examples.length >= 10, examples.join(" ")));

for (const name of examples) {
  const file = path.join(root, "examples", name);
  const text = inlineTables(file);
  test(`steady and evolve of ${name} are the command's`, () => {
    same(ask("steady", text), run("steady", file, "--json"), `steady ${name}`);
    same(ask("evolve", text, "21"), run("evolve", file, "--points", "21", "--json"), `evolve ${name}`);
  });
  test(`the march of ${name} is the command's`, (t) => {
    const answer = ask("march", text);
    if (answer.error) {
      t.diagnostic(`not marched on the page: ${answer.error.message}`);
      return;
    }
    const fields = ask("case_fields", text).ok;
    if (answer.ok.stick === null) return; // no cycle structure: nothing drawn
    const steps = JSON.parse(run("march", file, "--json").stdout).steps;
    const perCycle = Number(fields["history.steps_per_cycle"] || 2 * fields["history.steps_per_half"]);
    assert.ok(perCycle > 0, `${name}: steps per cycle`);
    const last = steps.slice(steps.length - perCycle).filter((s) => s.largest_stick !== null);
    close(answer.ok.stick.map(([, l, r]) => [l, r]), last.map((s) => s.largest_stick), `march ${name}`);
  });
}

test("an invalid field is refused with the library's message and its field", () => {
  const text = inlineTables(path.join(root, "examples/hertz.toml")).replace("coefficient = 0.6", "coefficient = -0.6");
  const answer = ask("steady", text);
  assert.strictEqual(answer.error.field, "friction.coefficient");
  assert.match(answer.error.message, /^invalid friction\.coefficient = -0\.6: must be/);
  const missing = ask("steady", text.replace("-0.6", "0.6").replace(/radius = 50\.0.*/, ""));
  assert.strictEqual(missing.error.field, "profile.radius");
  const file = ask("steady", fs.readFileSync(path.join(root, "examples/tabulated.toml"), "utf8"));
  assert.strictEqual(file.error.field, "profile.file");
  const points = ask("evolve", text.replace("-0.6", "0.6"), "1");
  assert.strictEqual(points.error.field, "points");
});
