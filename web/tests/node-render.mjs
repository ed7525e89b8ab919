// Renders a stage with the live book's WebAssembly module in Node, whose V8 engine is
// Chromium's, and prints the time and the rays traced: for profiling the module
// outside a page. Run after `cargo xtask book`:
//
//   node web/tests/node-render.mjs STAGE [course|fast] [SIZE] [SAMPLES]
//   node --cpu-prof web/tests/node-render.mjs soft-shadows fast 128 50
//
// `fast` renders with the fast engine (`render.fast`, as the demos' box does). The
// image is rendered in bands of eight rows on one thread, as one worker renders its
// bands; `--cpu-prof` writes a profile that Chromium's DevTools open.
import fs from "node:fs";
import path from "node:path";
import init, { Demo } from "../../book/src/live/pkg/raycourse_web.js";

const pkg = path.resolve(import.meta.dirname, "../../book/src/live/pkg");
const [stage, engine = "course", size = "128", samples = "50"] = process.argv.slice(2);
const whole = (text) => /^[1-9][0-9]*$/.test(text);
if (!stage || !["course", "fast"].includes(engine) || !whole(size) || !whole(samples)) {
  console.error("usage: node web/tests/node-render.mjs STAGE [course|fast] [SIZE] [SAMPLES]");
  process.exit(2);
}
await init({ module_or_path: fs.readFileSync(path.join(pkg, "raycourse_web_bg.wasm")) });
const edits = engine === "fast" ? { "render.fast": true } : {};
let demo;
try {
  demo = new Demo(stage, JSON.stringify(edits), Number(size), Number(size), Number(samples));
} catch (error) {
  console.error(`node-render: ${error.message}`);
  process.exit(1);
}
const started = performance.now();
for (let first = 0; first < Number(size); first += 8) demo.rows(first, 8);
const seconds = (performance.now() - started) / 1000;
console.log(`${stage}, ${engine === "fast" ? "the fast engine" : "the course's code"}, ${size} x ${size}, ` +
  `${samples} samples: ${seconds.toFixed(2)} s, ${demo.rays()} rays`);
demo.free();
