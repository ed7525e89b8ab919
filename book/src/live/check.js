// The check page: `<div class="live-check">` becomes `raycourse check` in the page.
// A student picks the stage and their image (PNG, JPEG or PPM, any size); a worker renders
// the stage's reference at that size with the crate itself and says what the command
// says: the verdict, the brightness ratio, where the image differs and the hint, with
// the picture of the differences. A teacher picks a class's folder (one folder per
// student, each image named after its stage) or one student's images, and gets what
// `raycourse check --all` prints and its grading sheet, to download. Nothing leaves
// the page.
(function () {
  "use strict";
  const { startWorkers, startEach, element, say, french } = window.raycourseLive;

  class LiveCheck {
    constructor(root) {
      this.root = root;
      this.job = 0;
      this.worker = startWorkers((message) => this.received(message), 1)[0];
      this.worker.postMessage({ kind: "stages" });
      root.dataset.state = "loading";
      root.textContent = say("page-loading");
    }

    received(message) {
      if (message.kind === "stages") return this.build(message.stages);
      if (message.job !== this.job) return;
      if (message.kind === "progress") {
        this.progress.hidden = false;
        this.status.textContent = say("page-check-rows", { rows: message.rows });
      }
      if (message.kind === "checked") this.show(message);
      if (message.kind === "graded") this.graded(message);
      if (message.kind === "sheet") this.sheet(message);
      if (message.kind === "error") this.fail(message.message);
    }

    build(stages) {
      this.stage = element("select", { className: "live-stage" },
        ...stages.map((s) => element("option", { value: s.name, textContent: say("page-check-stage", { session: s.session, stage: s.name }) })));
      this.file = element("input", { type: "file", accept: "image/png,image/jpeg,.ppm" });
      this.button = element("button", { textContent: say("page-check"), onclick: () => this.check() });
      this.progress = element("progress", { hidden: true });
      this.status = element("p", { className: "live-status" });
      this.status.setAttribute("role", "status");
      this.report = element("pre", { className: "live-report" });
      this.difference = element("img", { className: "live-difference", alt: say("page-check-differences"), hidden: true });
      this.root.textContent = "";
      this.root.append(
        element("p", {}, element("label", {}, `${say("page-stage")} `, this.stage), " ", element("label", {}, `${say("page-check-image")} `, this.file), " ", this.button),
        this.progress, this.status, this.report, this.difference, this.classForm());
      this.root.dataset.state = "ready";
    }

    /** The form that grades a class's folder, or one student's images. */
    classForm() {
      const files = { type: "file", multiple: true, accept: "image/png,image/jpeg,.ppm" };
      this.folder = element("input", { ...files, webkitdirectory: true, className: "live-class-folder" });
      this.images = element("input", { ...files, className: "live-class-images" });
      this.gradeButton = element("button", { textContent: say("page-grade"), onclick: () => this.grade() });
      this.lines = element("pre", { className: "live-report live-class-lines" });
      this.download = element("a", { className: "live-sheet", download: "grades.csv", hidden: true,
        textContent: say("page-grade-sheet") });
      return element("fieldset", { className: "live-class" },
        element("legend", { textContent: say("page-grade-legend") }),
        element("p", {}, element("label", {}, `${say("page-grade-folder")} `, this.folder)),
        element("p", {}, element("label", {}, `${say("page-grade-images")} `, this.images)),
        element("p", {}, this.gradeButton), this.lines, this.download);
    }

    /** Grades the folder or the images chosen, as `check --all` does. */
    async grade() {
      const chosen = [...this.folder.files, ...this.images.files];
      if (!chosen.length) return this.fail(say("page-grade-choose"));
      this.job += 1;
      this.root.dataset.state = "grading";
      this.lines.textContent = "";
      this.download.hidden = true;
      this.status.textContent = say("page-grading");
      const files = await Promise.all(chosen.map(async (file) =>
        ({ path: file.webkitRelativePath || file.name, bytes: await file.arrayBuffer() })));
      const language = french ? "fr" : "en";
      this.worker.postMessage({ kind: "grade", job: this.job, files, language }, files.map((f) => f.bytes));
    }

    /** One folder graded: its lines, as the command prints them. */
    graded(message) {
      this.progress.hidden = true;
      this.lines.textContent += `${message.lines}\n`;
      this.status.textContent = say("page-graded", { done: message.done, count: message.count });
    }

    /** Every folder graded: the sheet, offered for download. */
    sheet(message) {
      if (this.download.href) URL.revokeObjectURL(this.download.href);
      this.download.href = URL.createObjectURL(new Blob([message.csv], { type: "text/csv" }));
      this.download.dataset.csv = message.csv;
      this.download.hidden = false;
      this.status.textContent = say(message.passes ? "page-grade-matching" : "page-grade-differing");
      this.root.dataset.state = message.passes ? "graded-matching" : "graded-differing";
    }

    async check() {
      const file = this.file.files[0];
      if (!file) return this.fail(say("page-check-choose"));
      this.job += 1;
      this.root.dataset.state = "checking";
      this.report.textContent = "";
      this.difference.hidden = true;
      this.status.textContent = say("page-check-rendering");
      const bytes = await file.arrayBuffer();
      const language = french ? "fr" : "en";
      this.worker.postMessage({ kind: "check", job: this.job, stage: this.stage.value, file: bytes, language }, [bytes]);
    }

    show(message) {
      this.progress.hidden = true;
      this.status.textContent = say(message.matches ? "page-check-matches" : "page-check-differs");
      this.report.textContent = message.text;
      this.report.className = `live-report ${message.matches ? "live-matches" : "live-differs"}`;
      if (this.difference.src) URL.revokeObjectURL(this.difference.src);
      this.difference.src = URL.createObjectURL(new Blob([message.png], { type: "image/png" }));
      this.difference.hidden = false;
      this.root.dataset.state = message.matches ? "matches" : "differs";
    }

    fail(text) {
      this.progress.hidden = true;
      this.status.textContent = "";
      this.report.className = "live-report live-differs";
      this.report.textContent = text;
      this.root.dataset.state = "error";
    }
  }

  startEach(".live-check", (root) => { root.liveCheck = new LiveCheck(root); });
})();
