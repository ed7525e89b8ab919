// The renderer's thread: the crate compiled to WebAssembly (pkg/, made by
// `cargo xtask book`), run in a Web Worker so that the page stays responsive. A page
// starts one worker per core; each renders the bands of rows it is given and posts
// each band's pixels as soon as it is done. A newer job makes the worker drop the
// rest of the older one between two bands.
import init, { Class, Demo, check_image, message as say, stages } from "./pkg/raycourse_web.js";

const ready = init();
let current = -1;

/** Waits for the messages already posted to this worker to be handled. */
const yieldToMessages = () => new Promise((resolve) => setTimeout(resolve, 0));

/** A message's error as text. */
const text = (error) => String(error && error.message ? error.message : error);

self.onmessage = async (event) => {
  const message = event.data;
  if (message.kind === "render" || message.kind === "cancel") current = message.job;
  try {
    await ready;
    if (message.kind === "stages") self.postMessage({ kind: "stages", stages: JSON.parse(stages()) });
    if (message.kind === "render") await render(message);
    if (message.kind === "cost") cost(message);
    if (message.kind === "check") check(message);
    if (message.kind === "grade") grade(message);
  } catch (error) {
    self.postMessage({ kind: "error", job: message.job, message: text(error) });
  }
};

/** Renders the job's passes, band by band. A pass is `{ samples, scale }`: the
 * samples per pixel, and 1, or the side of the blocks of pixels that a first look
 * renders one pixel for (the same scene at `width / scale` x `height / scale`), its
 * bands then `band / scale` rows from `first / scale`. */
async function render(job) {
  for (const [pass, { samples, scale }] of job.passes.entries()) {
    const demo = new Demo(job.stage, JSON.stringify(job.edits), job.width / scale, job.height / scale, samples);
    try {
      for (const first of job.bands) {
        if (job.job !== current) return;
        const started = performance.now();
        const rgba = demo.rows(first / scale, job.band / scale);
        const ms = performance.now() - started;
        self.postMessage({ kind: "rows", job: job.job, pass, first, rgba, ms }, [rgba.buffer]);
        await yieldToMessages();
      }
      const functions = JSON.parse(demo.functions());
      self.postMessage({ kind: "pass", job: job.job, pass, rays: demo.rays(), functions });
    } finally {
      demo.free();
    }
  }
}

/** The cost image of the job's scene, at its size. */
function cost(job) {
  const demo = new Demo(job.stage, JSON.stringify(job.edits), job.width, job.height, 1);
  try {
    const started = performance.now();
    const image = demo.cost();
    const ms = performance.now() - started;
    const rgba = image.rgba();
    self.postMessage({ kind: "cost", job: job.job, height: image.height(), mean: image.mean(), rgba, ms }, [rgba.buffer]);
    image.free();
  } finally {
    demo.free();
  }
}

/** `raycourse check` on the image file's bytes, telling the rows of the reference. */
function check(job) {
  self.raycourseProgress = (rows) => self.postMessage({ kind: "progress", job: job.job, rows });
  const checked = check_image(job.stage, new Uint8Array(job.file), job.language);
  const png = checked.difference_png();
  self.postMessage({ kind: "checked", job: job.job, matches: checked.matches(), text: checked.text(), png }, [png.buffer]);
  checked.free();
}

/** `raycourse check --all` on the files of a class's folder (or of one student's),
 * folder by folder, each reference rendered once for the whole class. */
function grade(job) {
  self.raycourseProgress = (rows) => self.postMessage({ kind: "progress", job: job.job, rows });
  const graded = new Class(job.language);
  try {
    for (const file of job.files) graded.add(file.path, new Uint8Array(file.bytes));
    const count = graded.folders();
    if (count === 0) throw new Error(say(job.language, "check-no-stage", "{}"));
    for (let done = 1, lines; (lines = graded.gradeNext()) !== undefined; done++) {
      self.postMessage({ kind: "graded", job: job.job, lines, done, count });
    }
    self.postMessage({ kind: "sheet", job: job.job, csv: graded.sheet(), passes: graded.passes() });
  } finally {
    graded.free();
  }
}
