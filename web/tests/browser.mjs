// The live book's pages in headless Chromium (Debian's `chromium`, driven by
// puppeteer-core), served by `cargo xtask serve` (the server of `cargo xtask book
// --open`). Run after `cargo xtask book` and `cargo build --release`:
//
//   node web/tests/browser.mjs           the tests
//   node web/tests/browser.mjs --speed   the demos' times at 256 x 256, for the book
//                                        (`--speed=3,6`: only those sessions')
//
// Each session chapter's demo renders its first stage at a small size; the pixels
// read back from its canvas must pass `raycourse check` for that stage, and moving a
// control must change them. The check page must pass a correct image (a PNG, and a
// PPM written by hand), fail a gamma-less one with the gamma hint, and refuse a file
// that is not an image, and grade a class as `check --all` does, to the sheet's last
// byte. The French book's demo must speak French, and each page link to the other
// language's. Every page of both editions, its demo rendered, must break none of
// axe-core's WCAG 2.1 A and AA rules; a demo read through Chromium's accessibility
// tree names its every control and its image, session 7's camera turns from the
// keyboard and under a finger on a phone, and a reader who asks for less motion sees
// each image drawn once. A
// page that throws, logs an error or loads anything from the network fails its
// test.
import { execFileSync, spawn, spawnSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import puppeteer from "puppeteer-core";

const root = path.resolve(import.meta.dirname, "../..");
const book = path.join(root, "book/build");
/** The sessions, as the built book has a chapter for each (session1.html, ...). */
const sessions = fs.readdirSync(book).map((f) => f.match(/^session(\d+)\.html$/)).filter(Boolean)
  .map((m) => Number(m[1])).sort((a, b) => a - b);
const raycourse = process.env.RAYCOURSE || path.join(root, "target/release/raycourse");
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), "raycourse-browser-"));
const xtask = process.env.XTASK || path.join(root, "target/debug/xtask");

/** Serves the built book on 127.0.0.1 with `cargo xtask serve` (built by `cargo
 * xtask book`); resolves to the server's process and its address, which the first
 * line it prints names. */
function serve() {
  const server = spawn(xtask, ["serve", book], { stdio: ["ignore", "pipe", "inherit"] });
  return new Promise((resolve, reject) => {
    let printed = "";
    server.on("error", reject);
    server.stdout.on("data", (chunk) => {
      printed += chunk;
      const address = printed.match(/ at (http:\/\/127\.0\.0\.1:\d+\/)/);
      if (address) resolve([server, address[1]]);
    });
  });
}

/** A new page that records what it throws and logs as an error; `before(page)`
 * runs before it loads. */
async function open(browser, url, before) {
  const page = await browser.newPage();
  if (before) await before(page);
  page.errors = [];
  page.on("pageerror", (error) => page.errors.push(error.message));
  page.on("console", (message) => message.type() === "error" && page.errors.push(message.text()));
  const origin = new URL(url).origin;
  page.on("request", (request) => {
    const asked = request.url();
    if (!asked.startsWith(origin) && !/^(data|blob):/.test(asked)) page.errors.push(`loaded from the network: ${asked}`);
  });
  await page.goto(url);
  return page;
}

/** Waits until the demo of `page` has rendered all its samples; returns its state. */
async function rendered(page, timeout = 300000) {
  await page.waitForSelector('.live-demo[data-state="done"], .live-demo[data-state="error"]', { timeout });
  return page.evaluate(() => {
    const demo = document.querySelector(".live-demo");
    return { state: demo.dataset.state, status: demo.querySelector(".live-status").textContent,
      png: demo.querySelector("canvas.live-image").toDataURL("image/png"), stage: demo.querySelector("select.live-stage").value,
      lookMs: Number(demo.dataset.lookMs), firstMs: Number(demo.dataset.firstMs), totalMs: Number(demo.dataset.totalMs),
      functions: demo.querySelector(".live-functions").textContent,
      ran: demo.querySelector("details summary").textContent,
      cost: demo.querySelector(".live-cost + figcaption")?.textContent };
  });
}

/** Moves the first control of the demo of `page` away from where it is. */
function moveControl(page) {
  return page.evaluate(() => {
    const input = [...document.querySelectorAll(".live-controls input, .live-controls select")].find((i) => !i.closest("label").hidden);
    if (input.type === "checkbox") { input.checked = !input.checked; input.dispatchEvent(new Event("change")); return input.dataset.control; }
    if (input.tagName === "SELECT") { input.selectedIndex = (input.selectedIndex + 1) % input.options.length; input.dispatchEvent(new Event("change")); return input.dataset.control; }
    input.value = Number(input.value) === Number(input.min) ? input.max : input.min;
    input.dispatchEvent(new Event("input"));
    return input.dataset.control;
  });
}

/** Writes the data URL `png` to a file; returns its path. */
function save(png, name) {
  const file = path.join(scratch, name);
  fs.writeFileSync(file, Buffer.from(png.split(",")[1], "base64"));
  return file;
}

/** `raycourse ARGS...`: its exit code and output. */
function command(...args) {
  return commandIn(root, ...args);
}

/** `raycourse ARGS...` run in the folder `cwd`: its exit code and output. */
function commandIn(cwd, ...args) {
  const run = spawnSync(raycourse, args, { encoding: "utf8", cwd });
  return { code: run.status, output: `${run.stdout}${run.stderr}` };
}

const results = [];
async function test(name, body) {
  try {
    await body();
    results.push([name, null]);
    console.log(`ok: ${name}`);
  } catch (error) {
    results.push([name, error]);
    console.log(`FAILED: ${name}\n  ${String(error.stack || error).split("\n").join("\n  ")}`);
  }
}

function assert(condition, message) {
  if (!condition) throw new Error(message);
}

/** Each session's demo: the stage's image, and a control that changes it. */
async function demos(browser, base) {
  // Small sizes: the white disk and shading need a few pixels more, brute force fewer.
  const size = (session) => (session <= 2 ? 64 : session === 5 ? 24 : 32);
  for (const session of sessions) {
    await test(`session ${session}'s demo renders its stage, which check passes, and a control changes it`, async () => {
      const page = await open(browser, `${base}session${session}.html?live-size=${size(session)}`);
      const first = await rendered(page);
      assert(first.state === "done", `the demo says: ${first.status}`);
      const file = save(first.png, `s${session}-${first.stage}.png`);
      const checked = command("check", first.stage, file, "--quiet", "--cache", path.join(scratch, "cache"));
      assert(checked.code === 0, `raycourse check ${first.stage}: exit ${checked.code}\n${checked.output}`);
      const control = await moveControl(page);
      const second = await rendered(page);
      assert(second.state === "done", `after moving ${control}, the demo says: ${second.status}`);
      assert(second.png !== first.png, `moving ${control} left the image as it was`);
      assert(page.errors.length === 0, `the page reported errors: ${page.errors.join("; ")}`);
      await page.close();
    });
  }
}

/** Sets the demo's control (or stage list, `stage`) `id` of `page` to `value`,
 * and waits for the image. */
async function setControl(page, id, value) {
  await page.evaluate((id, value) => {
    const input = id === "stage" ? document.querySelector(".live-demo select.live-stage")
      : document.querySelector(`.live-demo [data-control="${id}"]`);
    input.value = value;
    input.dispatchEvent(new Event(input.type === "range" ? "input" : "change"));
  }, id, value);
  return rendered(page);
}

/** Turns the fast engine of the demo of `page` on or off, and waits for the image. */
async function setFast(page, on) {
  await page.evaluate((on) => {
    const input = document.querySelector('.live-demo [data-control="fast"]');
    input.checked = on;
    input.dispatchEvent(new Event("change"));
  }, on);
  return rendered(page);
}

/** What the controls teach, seen through `check`: acne, the orbit, and the fast
 * engine's image, the course's. */
async function controls(browser, base) {
  await test("the fast engine draws the course's very pixels, from session 3 on", async () => {
    for (const session of sessions.filter((s) => s >= 3)) {
      const page = await open(browser, `${base}session${session}.html?live-size=24`);
      const course = await rendered(page);
      const fast = await setFast(page, true);
      assert(fast.state === "done", `session ${session}, the fast engine: ${fast.status}`);
      assert(fast.png === course.png, `session ${session}: the fast engine's image differs`);
      assert(fast.functions === "paths_at_once::row" && course.functions.includes("pixel"),
        `session ${session}: the fast engine did not render: ${fast.functions}`);
      assert(fast.ran.includes("fast engine") && course.ran.includes("course functions"),
        `session ${session}: the list of functions is titled ${fast.ran}`);
      const costed = session === 5 || session === 6;
      assert(costed ? fast.cost.includes("course's searches only") && !course.cost.includes("only") : fast.cost === undefined,
        `session ${session}: the fast engine's cost says ${fast.cost}`);
      assert(page.errors.length === 0, `the page reported errors: ${page.errors.join("; ")}`);
      await page.close();
    }
  });
  await test("brute force's first look: a pixel for each block of 4 x 4, the command's render at a quarter of the size, drawn before the first pass", async () => {
    // Each draw on the demo's image, in order: a first look's band with its pixels
    // (drawn from the page's small canvas), or a pass's band.
    const recordDraws = (page) => page.evaluateOnNewDocument(() => {
      window.draws = [];
      const prototype = CanvasRenderingContext2D.prototype;
      const [draw, put] = [prototype.drawImage, prototype.putImageData];
      const onImage = (context) => context.canvas.classList.contains("live-image");
      prototype.drawImage = function (source, sx, sy, sw, sh, dx, dy, dw, dh) {
        if (onImage(this)) window.draws.push({ kind: "look", first: dy, rows: sh, scale: dh / sh,
          rgba: [...source.getContext("2d").getImageData(sx, sy, sw, sh).data] });
        return draw.apply(this, arguments);
      };
      prototype.putImageData = function (pixels, x, y) {
        if (onImage(this)) window.draws.push({ kind: "pass", first: y });
        return put.apply(this, arguments);
      };
    });
    const size = 24;
    const page = await open(browser, `${base}session5.html?live-size=${size}`, recordDraws);
    const shown = await rendered(page);
    assert(shown.state === "done" && shown.stage === "mesh", `the demo says: ${shown.status}`);
    const draws = await page.evaluate(() => window.draws);
    const looks = draws.filter((d) => d.kind === "look");
    const firstPass = draws.findIndex((d) => d.kind === "pass");
    assert(looks.length > 0 && draws.slice(0, looks.length).every((d) => d.kind === "look"),
      `the first look is not drawn first: ${draws.map((d) => d.kind).join(" ")}`);
    assert(firstPass === looks.length && looks.every((d) => d.scale === 4), `the looks' scales: ${looks.map((d) => d.scale)}`);
    const rows = looks.sort((a, b) => a.first - b.first);
    assert(rows.reduce((sum, d) => sum + d.rows * d.scale, 0) === size, "the first look does not cover the image");
    const look = rows.flatMap((d) => d.rgba.filter((_, i) => i % 4 !== 3));
    const file = path.join(scratch, "look.png");
    execFileSync(raycourse, ["s5", "mesh", "--width", `${size / 4}`, "--height", `${size / 4}`, "--spp", "1",
      "--out", file, "--quiet"]);
    const command = (await plainPpm(browser, file)).split("\n").slice(4).join(" ").trim().split(/\s+/).map(Number);
    assert(look.join(" ") === command.join(" "), `the first look is not the command's ${size / 4} x ${size / 4} render`);
    assert(shown.lookMs > 0 && shown.lookMs <= shown.firstMs, `the first look took ${shown.lookMs} ms, the first pass ${shown.firstMs} ms`);
    assert(page.errors.length === 0, `the page reported errors: ${page.errors.join("; ")}`);
    await page.close();
  });
  await test("session 2's shadow offset at 0 shows the acne that check names", async () => {
    const page = await open(browser, `${base}session2.html?live-size=64`);
    await rendered(page);
    const clean = await setControl(page, "stage", "shadows");
    const acne = await setControl(page, "offset", "0");
    assert(acne.state === "done" && acne.png !== clean.png, `the offset changed nothing: ${acne.status}`);
    const checked = command("check", "shadows", save(acne.png, "acne.png"), "--quiet", "--cache", path.join(scratch, "cache"));
    assert(checked.code === 1 && /hint \(shadow acne\)/.test(checked.output), `check says:\n${checked.output}`);
    assert(page.errors.length === 0, `the page reported errors: ${page.errors.join("; ")}`);
    await page.close();
  });
  await test("session 7's image turns when dragged", async () => {
    const page = await open(browser, `${base}session7.html?live-size=24`);
    const before = await rendered(page);
    const canvas = await page.$(".live-demo canvas.live-image");
    await canvas.scrollIntoView();
    const box = await canvas.boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 40, box.y + box.height / 2 + 10, { steps: 4 });
    await page.mouse.up();
    const after = await rendered(page);
    assert(after.state === "done" && after.png !== before.png, `dragging changed nothing: ${after.status}`);
    assert(page.errors.length === 0, `the page reported errors: ${page.errors.join("; ")}`);
    await page.close();
  });
}

/** The French book: its demo speaks French, and every page links to the English. */
async function french(browser, base) {
  await test("the French book's demo runs in French, and its page links to the English one", async () => {
    const page = await open(browser, `${base}fr/session1.html?live-size=32`);
    const shown = await rendered(page);
    assert(shown.state === "done", `the demo says: ${shown.status}`);
    const words = await page.evaluate(() => [document.documentElement.lang,
      document.querySelector(".live-controls").textContent, document.querySelector(".language-switch").href]);
    assert(words[0] === "fr" && words[1].includes("champ de vision"), `the page says: ${words.join(" | ")}`);
    assert(words[2] === `${base}session1.html`, `the switch leads to ${words[2]}`);
    const english = await open(browser, words[2]);
    const back = await english.evaluate(() => document.querySelector(".language-switch").href);
    assert(back === `${base}fr/session1.html`, `the English page's switch leads to ${back}`);
    assert(page.errors.length === 0 && english.errors.length === 0, `errors: ${[...page.errors, ...english.errors].join("; ")}`);
    await english.close();
    await page.close();
  });
}

/** The PNG at `file` as a plain PPM (`P3`), the text a renderer in C++ writes by
 * hand: its pixels read back from a canvas in the browser. */
async function plainPpm(browser, file) {
  const page = await browser.newPage();
  const text = await page.evaluate(async (png) => {
    const image = new Image();
    image.src = `data:image/png;base64,${png}`;
    await image.decode();
    const canvas = document.createElement("canvas");
    [canvas.width, canvas.height] = [image.width, image.height];
    const context = canvas.getContext("2d");
    context.drawImage(image, 0, 0);
    const data = context.getImageData(0, 0, image.width, image.height).data;
    const lines = [`P3`, `# written by hand`, `${image.width} ${image.height}`, `255`];
    for (let i = 0; i < data.length; i += 4) lines.push(`${data[i]} ${data[i + 1]} ${data[i + 2]}`);
    return lines.join("\n") + "\n";
  }, fs.readFileSync(file).toString("base64"));
  await page.close();
  return text;
}

/** The check page with a file: its verdict and report. */
async function checkPage(browser, base, stage, file) {
  const page = await open(browser, `${base}check.html`);
  await page.waitForSelector('.live-check[data-state="ready"]', { timeout: 60000 });
  await page.select(".live-check select.live-stage", stage);
  const input = await page.$('.live-check input[type="file"]');
  await input.uploadFile(file);
  const started = Date.now();
  await page.click(".live-check button");
  await page.waitForSelector('.live-check[data-state="matches"], .live-check[data-state="differs"], .live-check[data-state="error"]', { timeout: 300000 });
  const answer = await page.evaluate(() => {
    const root = document.querySelector(".live-check");
    return { state: root.dataset.state, report: root.querySelector(".live-report").textContent };
  });
  answer.ms = Date.now() - started;
  answer.errors = page.errors;
  await page.close();
  return answer;
}

/** The check page at `url` grading the class folder `klass`: its state, lines,
 * sheet and report. */
async function gradeInPage(browser, url, klass) {
  const page = await open(browser, url);
  await page.waitForSelector('.live-check[data-state="ready"]', { timeout: 60000 });
  const folder = await page.$(".live-check input.live-class-folder");
  await folder.uploadFile(klass);
  await page.click(".live-class button");
  await page.waitForSelector('.live-check[data-state^="graded"], .live-check[data-state="error"]', { timeout: 300000 });
  const graded = await page.evaluate(() => {
    const root = document.querySelector(".live-check");
    return { state: root.dataset.state, lines: root.querySelector(".live-class-lines").textContent,
      csv: root.querySelector("a.live-sheet").dataset.csv, report: root.querySelector(".live-report").textContent };
  });
  graded.errors = page.errors;
  await page.close();
  return graded;
}

async function checks(browser, base) {
  const good = path.join(scratch, "shading.png");
  execFileSync(raycourse, ["s1", "shading", "--width", "64", "--height", "48", "--out", good, "--quiet"]);
  await test("the check page passes a correct image, as the command does", async () => {
    const answer = await checkPage(browser, base, "shading", good);
    assert(answer.state === "matches", `the page says: ${answer.report}`);
    const said = command("check", "shading", good, "--quiet", "--cache", path.join(scratch, "cache")).output.trim();
    assert(answer.report.trim() === said, `the page says\n${answer.report}\nthe command says\n${said}`);
    assert(answer.errors.length === 0, `the page reported errors: ${answer.errors.join("; ")}`);
  });
  await test("the check page reads a PPM written by hand (P3), as the command does", async () => {
    const ppm = path.join(scratch, "shading.ppm");
    fs.writeFileSync(ppm, await plainPpm(browser, good));
    const answer = await checkPage(browser, base, "shading", ppm);
    assert(answer.state === "matches", `the page says: ${answer.report}`);
    const said = command("check", "shading", ppm, "--quiet", "--cache", path.join(scratch, "cache")).output.trim();
    assert(answer.report.trim() === said, `the page says\n${answer.report}\nthe command says\n${said}`);
  });
  await test("the check page fails a gamma-less image with the gamma hint", async () => {
    const scene = path.join(scratch, "no-gamma.toml");
    fs.writeFileSync(scene, fs.readFileSync(path.join(root, "sessions/s2/gamma.toml"), "utf8").replace(/^gamma = 2\.2$/m, ""));
    const linear = path.join(scratch, "no-gamma.png");
    execFileSync(raycourse, ["render", scene, "--width", "64", "--height", "64", "--out", linear, "--quiet"]);
    const answer = await checkPage(browser, base, "gamma", linear);
    assert(answer.state === "differs", `the page says: ${answer.report}`);
    assert(/hint \([^)]*gamma/.test(answer.report), `no gamma hint in: ${answer.report}`);
  });
  await test("the check page grades a class as check --all does: its lines, and its sheet to the byte, in both languages", async () => {
    const gamma = path.join(scratch, "gamma.png");
    execFileSync(raycourse, ["s2", "gamma", "--width", "64", "--height", "64", "--out", gamma, "--quiet"]);
    const files = { "alice/shading.png": good, "alice/gamma.png": gamma, "bob/shading.png": good,
      "bob/gamma.png": path.join(scratch, "no-gamma.png"), "carol/shading.png": path.join(scratch, "notes.png") };
    const klass = path.join(scratch, "class");
    fs.writeFileSync(path.join(scratch, "notes.png"), "not a picture");
    for (const [name, from] of Object.entries(files)) {
      fs.mkdirSync(path.dirname(path.join(klass, name)), { recursive: true });
      fs.copyFileSync(from, path.join(klass, name));
    }
    for (const [language, edition] of [["en", ""], ["fr", "fr/"]]) {
      const sheet = `sheet-${language}.csv`;
      const said = commandIn(scratch, "check", "--all", "class", "--lang", language, "--csv", sheet, "--quiet",
        "--cache", path.join(scratch, "cache"));
      assert(said.code === 1, `check --all --lang ${language}: exit ${said.code}\n${said.output}`);
      const graded = await gradeInPage(browser, `${base}${edition}check.html`, klass);
      assert(graded.state === "graded-differing", `the ${language} page says ${graded.state}: ${graded.report}`);
      const lines = said.output.split("\n").filter((l) => /^(alice|bob|carol) /.test(l)).join("\n");
      assert(graded.lines.trim() === lines, `the ${language} page printed\n${graded.lines}\nthe command\n${lines}`);
      const written = fs.readFileSync(path.join(scratch, sheet), "utf8");
      assert(graded.csv === written, `the ${language} page's sheet\n${graded.csv}\nthe command's\n${written}`);
      assert(graded.errors.length === 0, `the ${language} page reported errors: ${graded.errors.join("; ")}`);
    }
  });
  await test("the check page says, in its reader's language, that a folder holds no stage's image", async () => {
    const empty = path.join(scratch, "no-stages");
    fs.mkdirSync(path.join(empty, "alice"), { recursive: true });
    fs.writeFileSync(path.join(empty, "alice", "notes.png"), "not a picture");
    for (const [edition, said] of [["", "no image of a stage here"], ["fr/", "aucune image d'une étape ici"]]) {
      const graded = await gradeInPage(browser, `${base}${edition}check.html`, empty);
      assert(graded.state === "error" && graded.report.includes(said), `the ${edition || "en/"} page says ${graded.state}: ${graded.report}`);
    }
  });
  await test("the check page refuses a file that is not an image", async () => {
    const text = path.join(scratch, "notes.png");
    fs.writeFileSync(text, "not a picture");
    const answer = await checkPage(browser, base, "shading", text);
    assert(answer.state === "error", `the page says: ${answer.state}: ${answer.report}`);
    assert(/not a PNG, JPEG or PPM/.test(answer.report), `the page says: ${answer.report}`);
  });
}

/** The demos' times at their sizes (256 x 256, but 128 x 128 for session 5): in
 * sessions 1 and 2, a control's change to the image, the median of five; in the
 * Monte Carlo sessions, the first look (a pixel for each block of 4 x 4), the first
 * pass at one sample per pixel and all the samples,
 * as the page opens, then with the fast engine. Then the check page's, from its
 * button to its answer, on an image of `glass` and one of `indirect` that the command
 * rendered. Printed, not asserted: a timed test would fail on a busy machine. */
async function speed(browser, base) {
  console.log(`Chromium ${await browser.version()}, ${os.cpus()[0].model}, ${os.cpus().length} cores`);
  console.log("session | stage | size | samples | first look | first pass | all samples | first look, fast | first pass, fast | all samples, fast");
  const chosen = process.argv.find((a) => a.startsWith("--speed="));
  const measured = chosen ? chosen.slice(8).split(",").map(Number) : sessions;
  for (const session of measured) {
    const page = await open(browser, `${base}session${session}.html`);
    const times = [await rendered(page)];
    if (session <= 2) {
      times.length = 0;
      for (let i = 0; i < 5; i++) {
        await moveControl(page);
        times.push(await rendered(page));
      }
    }
    const median = (key) => times.map((t) => t[key]).sort((a, b) => a - b)[Math.floor(times.length / 2)];
    const [, size, samples] = times[0].status.match(/(\d+) × \d+: (\d+)/);
    const ms = (value) => (value ? `${value} ms` : "-");
    let fast = "- | - | -";
    if (session >= 3) {
      // The mesh sessions' cost image is rendered on a worker after the image: the
      // fast engine's render is timed once it is done, so that it waits for nothing.
      await page.waitForFunction(() => !document.querySelector(".live-cost")
        || /\d/.test(document.querySelector(".live-cost + figcaption").textContent), { timeout: 300000 });
      const timed = await setFast(page, true);
      fast = `${ms(timed.lookMs)} | ${timed.firstMs} ms | ${timed.totalMs} ms`;
    }
    console.log(`${session} | ${times[0].stage} | ${size} | ${samples} | ${ms(median("lookMs"))} | ${median("firstMs")} ms | ${median("totalMs")} ms | ${fast}`);
    await page.close();
  }
  console.log("check page | stage | size | answer | seconds");
  for (const [scene, size] of [["s2/glass", 512], ["s3/indirect", 256]]) {
    const stage = path.basename(scene);
    const file = path.join(scratch, `${stage}.png`);
    execFileSync(raycourse, ["render", path.join(root, `sessions/${scene}.toml`), "--width", `${size}`,
      "--height", `${size}`, "--out", file, "--quiet"]);
    const answer = await checkPage(browser, base, stage, file);
    console.log(`check page | ${stage} | ${size} x ${size} | ${answer.state} | ${(answer.ms / 1000).toFixed(2)} s`);
  }
}

/** Every chapter of both editions: the pages but the print, table-of-contents and
 * not-found ones. */
function chapters() {
  const pages = (folder) => fs.readdirSync(path.join(book, folder))
    .filter((f) => f.endsWith(".html") && !["print.html", "toc.html", "404.html"].includes(f)).map((f) => `${folder}${f}`);
  return [...pages(""), ...pages("fr/")];
}

/** axe-core's WCAG 2.1 A and AA rules on `page`, once its demos have rendered and
 * its check page is ready: each rule broken, with how many elements break it. */
async function violations(page) {
  await page.waitForFunction(() => [...document.querySelectorAll(".live-demo")].every((d) => /done|error/.test(d.dataset.state))
    && [...document.querySelectorAll(".live-check")].every((c) => c.dataset.state === "ready"), { timeout: 300000 });
  await page.addScriptTag({ path: path.join(root, "web/node_modules/axe-core/axe.min.js") });
  return page.evaluate(async () => {
    const tags = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"];
    const found = await window.axe.run(document, { runOnly: { type: "tag", values: tags } });
    return found.violations.map((v) => `${v.id} (${v.impact}, ${v.nodes.length}): ${v.help}: ${v.nodes[0].target.join(" ")}`);
  });
}

/** The nodes of the page's accessibility tree, as a screen reader reads them. */
async function readAloud(page) {
  const nodes = [];
  const walk = (node) => { nodes.push(node); (node.children || []).forEach(walk); };
  walk(await page.accessibility.snapshot());
  return nodes;
}

/** What a reader of every page needs: WCAG 2.1 AA by axe's rules, names for every
 * control and image, the keyboard, and less motion when asked for. */
async function access(browser, base) {
  await test("every page of both editions, its demo rendered, breaks none of axe-core's WCAG 2.1 A and AA rules", async () => {
    const found = [];
    for (const chapter of chapters()) {
      const page = await open(browser, `${base}${chapter}?live-size=16`);
      found.push(...(await violations(page)).map((v) => `${chapter}: ${v}`));
      assert(page.errors.length === 0, `${chapter} reported errors: ${page.errors.join("; ")}`);
      await page.close();
    }
    assert(found.length === 0, `${found.length} rules broken:\n${found.join("\n")}`);
  });
  await test("session 7's demo read as a screen reader reads it, and its camera turned from the keyboard", async () => {
    const page = await open(browser, `${base}session7.html?live-size=24`);
    const before = await rendered(page);
    const nodes = await readAloud(page);
    const named = (role, pattern) => nodes.find((n) => role.test(n.role) && pattern.test(n.name || ""));
    for (const [role, name] of [[/combobox/, /^stage/], [/slider/, /^samples per pixel/], [/slider/, /^plunge/],
      [/checkbox/, /^texture/], [/^(img|image)$/, /^session 7, stage .*samples per pixel\. Arrow keys/],
      [/StaticText/, /^textures, 24 × 24: \d+ samples per pixel in/]]) {
      assert(named(role, name), `no ${role} named ${name} among: ${nodes.map((n) => `${n.role} "${n.name}"`).join(", ")}`);
    }
    const status = nodes.findIndex((n) => n.role === "status");
    assert(status >= 0 && /samples per pixel in/.test(nodes[status + 1].name), "the status line is no live region");
    const start = await page.evaluate(() => Number(document.querySelector('[data-control="plunge"]').value));
    await page.focus(".live-demo canvas.live-image");
    await page.keyboard.press("ArrowLeft");
    const turned = await rendered(page);
    assert(turned.png !== before.png, `the left arrow changed nothing: ${turned.status}`);
    await page.keyboard.press("ArrowDown");
    const lowered = await rendered(page);
    const seen = await page.evaluate(() => {
      const canvas = document.querySelector(".live-demo canvas.live-image");
      return { label: canvas.getAttribute("aria-label"), outline: getComputedStyle(canvas).outlineStyle,
        plunge: document.querySelector('[data-control="plunge"]').value };
    });
    assert(lowered.png !== turned.png && /turned by 10 degrees/.test(seen.label), `the image says: ${seen.label}`);
    assert(seen.outline === "solid", `the focused image shows no outline: ${seen.outline}`);
    assert(Number(seen.plunge) === Math.min(80, start + 5), `the down arrow took the plunge from ${start} to ${seen.plunge}`);
    assert(page.errors.length === 0, `the page reported errors: ${page.errors.join("; ")}`);
    await page.close();
  });
  await test("session 6's cost image is named by what it shows, as its caption says", async () => {
    const page = await open(browser, `${base}session6.html?live-size=16`);
    await rendered(page);
    await page.waitForFunction(() => /on average/.test(document.querySelector(".live-cost + figcaption").textContent),
      { timeout: 120000 });
    const label = await page.evaluate(() => document.querySelector("canvas.live-cost").getAttribute("aria-label"));
    assert(/^the cost image, cost: [\d.]+ tests per camera ray on average$/.test(label), `the cost image says: ${label}`);
    await page.close();
  });
  await test("on a phone, session 7's image turns under a finger, and the page does not scroll", async () => {
    const phone = (page) => page.setViewport({ width: 360, height: 740, isMobile: true, hasTouch: true });
    const page = await open(browser, `${base}session7.html?live-size=24`, phone);
    const before = await rendered(page);
    const canvas = await page.$(".live-demo canvas.live-image");
    await canvas.scrollIntoView();
    const box = await canvas.boundingBox();
    const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
    const scrolled = await page.evaluate(() => window.scrollY);
    await page.touchscreen.touchStart(x, y);
    await page.touchscreen.touchMove(x + 40, y + 30);
    await page.touchscreen.touchEnd();
    const after = await rendered(page);
    assert(after.state === "done" && after.png !== before.png, `the finger changed nothing: ${after.status}`);
    const still = await page.evaluate(() => window.scrollY);
    assert(still === scrolled, `the page scrolled from ${scrolled} to ${still} under the finger`);
    assert(page.errors.length === 0, `the page reported errors: ${page.errors.join("; ")}`);
    await page.close();
  });
  await test("a reader who asks for less motion sees each image drawn once, when done", async () => {
    const counting = async (page) => {
      await page.emulateMediaFeatures([{ name: "prefers-reduced-motion", value: "reduce" }]);
      await page.evaluateOnNewDocument(() => {
        window.painted = [];
        const put = CanvasRenderingContext2D.prototype.putImageData;
        CanvasRenderingContext2D.prototype.putImageData = function (...args) {
          window.painted.push(document.querySelector(".live-status")?.textContent);
          return put.apply(this, args);
        };
      });
    };
    const page = await open(browser, `${base}session3.html?live-size=24`, counting);
    const shown = await rendered(page);
    const painted = await page.evaluate(() => window.painted);
    assert(shown.state === "done" && painted.length === 3, `${painted.length} bands painted: ${painted.join(" | ")}`);
    assert(painted.every((status) => !/refining/.test(status)), `painted while refining: ${painted.join(" | ")}`);
    const sliding = await page.evaluate(() => getComputedStyle(document.querySelector(".sidebar")).transitionDuration);
    assert(sliding.split(",").every((d) => parseFloat(d) === 0), `the sidebar still slides: ${sliding}`);
    await page.close();
  });
}

const [server, base] = await serve();
const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
    "--disable-component-update", "--disable-sync"],
});
try {
  if (process.argv.some((a) => a.startsWith("--speed"))) {
    await speed(browser, base);
  } else {
    await demos(browser, base);
    await controls(browser, base);
    await french(browser, base);
    await checks(browser, base);
    await access(browser, base);
  }
} finally {
  await browser.close();
  server.kill();
}
const failed = results.filter(([, error]) => error).length;
if (results.length) console.log(`${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
