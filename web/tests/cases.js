// Bundled examples as the page takes them: every table given by its `file` put inline as
// `data = """..."""` (a page reads no files), the rest of the text unchanged.
"use strict";
const fs = require("node:fs");
const path = require("node:path");

function inlineTables(file) {
  const dir = path.dirname(file);
  return fs.readFileSync(file, "utf8").replace(/^file\s*=\s*"([^"]*)".*$/gm, (_, name) => {
    const csv = fs.readFileSync(path.join(dir, name), "utf8");
    return 'data = """\n' + csv + (csv.endsWith("\n") ? "" : "\n") + '"""';
  });
}

module.exports = { inlineTables };
