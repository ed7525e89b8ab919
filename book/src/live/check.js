// The check page: `<div class="live-check">` becomes `raycourse check` in the page.
// A student picks the stage and their image (PNG, JPEG or PPM, any size); a worker renders
// the stage's reference at that size with the crate itself and says what the command
// says: the verdict, the brightness ratio, where the image differs and the hint, with
// the picture of the differences. The image never leaves the page.
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
      root.textContent = say("loading the renderer…");
    }

    received(message) {
      if (message.kind === "stages") return this.build(message.stages);
      if (message.job !== this.job) return;
      if (message.kind === "progress") {
        this.progress.hidden = false;
        this.status.textContent = `${say("rendering the reference")}${french ? "\u00a0" : ""}: ${message.rows} ${say("rows")}`;
      }
      if (message.kind === "checked") this.show(message);
      if (message.kind === "error") this.fail(message.message);
    }

    build(stages) {
      this.stage = element("select", { className: "live-stage" },
        ...stages.map((s) => element("option", { value: s.name, textContent: `${say("session")} ${s.session}${french ? "\u00a0" : ""}: ${s.name}` })));
      this.file = element("input", { type: "file", accept: "image/png,image/jpeg,.ppm" });
      this.button = element("button", { textContent: say("check"), onclick: () => this.check() });
      this.progress = element("progress", { hidden: true });
      this.status = element("p", { className: "live-status" });
      this.report = element("pre", { className: "live-report" });
      this.difference = element("img", { className: "live-difference", alt: say("the differences: differing pixels or blocks in red"), hidden: true });
      this.root.textContent = "";
      this.root.append(
        element("p", {}, element("label", {}, `${say("stage")} `, this.stage), " ", element("label", {}, `${say("your image")} `, this.file), " ", this.button),
        this.progress, this.status, this.report, this.difference);
      this.root.dataset.state = "ready";
    }

    async check() {
      const file = this.file.files[0];
      if (!file) return this.fail(say("choose your image first (a PNG, JPEG or PPM file)"));
      this.job += 1;
      this.root.dataset.state = "checking";
      this.report.textContent = "";
      this.difference.hidden = true;
      this.status.textContent = say("rendering the reference…");
      const bytes = await file.arrayBuffer();
      const language = french ? "fr" : "en";
      this.worker.postMessage({ kind: "check", job: this.job, stage: this.stage.value, file: bytes, language }, [bytes]);
    }

    show(message) {
      this.progress.hidden = true;
      this.status.textContent = say(message.matches ? "matches" : "differs");
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

  startEach(".live-check", "the check", (root) => { root.liveCheck = new LiveCheck(root); });
})();
