// The live demo of a session chapter: `<div class="live-demo" data-session="N">`
// becomes a canvas rendered by the crate itself, compiled to WebAssembly and run in
// one Web Worker per core (workers.js), with the controls that session teaches. Each
// demo starts from its stage's own scene file; a control edits keys of that file,
// and the image is rendered again: first a quick look (one pixel for each block of
// 4 x 4, drawn as a block), then with one sample per pixel, then with all of them,
// band by band. `?live-size=64` in the page's address renders smaller (the
// book's browser tests use it).
(function () {
  "use strict";
  const { startWorkers, startEach, element, duration, say } = window.raycourseLive;

  // A control: its id, its label (a message of the catalogue, with its arguments:
  // `["page-light-axis", { axis: "x" }]`, or its id alone), how it reads its starting value from a stage's
  // scene file and its render settings as the renderer reads them, defaults
  // included (`read(file, settings)`; `undefined`: the stage has nothing it could
  // change, and it is hidden), and the keys of the file it changes (`edit(value, values)`, where
  // `values` holds every control's value by id).
  const range = (id, label, [min, max, step], read, edit, show) =>
    ({ id, kind: "range", label, min, max, step, read, edit, show });
  const toggle = (id, label, read, edit) => ({ id, kind: "checkbox", label, read, edit });
  const choice = (id, label, options, read, edit) => ({ id, kind: "select", label, options, read, edit });
  /** A control's or an option's label in the page's language. */
  const labelOf = (label) => (Array.isArray(label) ? say(...label) : say(label));

  const light = (values) => ({ "light.position": [values.lightX, values.lightY, values.lightZ] });
  const lightAxis = (id, axis, limits) =>
    range(id, ["page-light-axis", { axis: "xyz"[axis] }], limits, (f) => f.light && f.light.position[axis], (_, v) => light(v));
  const centre = (f) => (f.spheres && f.spheres[0] && f.spheres[0].material) || {};
  const materialName = (f) => {
    const m = centre(f);
    return m === "mirror" ? "mirror" : m.glass !== undefined ? "glass" : m.diffuse ? "diffuse" : undefined;
  };
  const material = (v) =>
    v.material === "mirror" ? "mirror" : v.material === "glass" ? { glass: v.index } : { diffuse: [1, 1, 1] };
  const offsets = [
    ["robust", "page-offset-robust"],
    ["0.1", ["page-offset", { epsilon: 0.1 }]],
    ["0.001", ["page-offset", { epsilon: 0.001 }]],
    ["1e-9", ["page-offset", { epsilon: "10⁻⁹" }]],
    ["1e-14", ["page-offset", { epsilon: "10⁻¹⁴" }]],
    ["0", "page-offset-none"],
  ];
  const samples = range("samples", "page-samples", [1, 256, 1], (f, s) => s.samples, () => ({}));
  const accelerations = (names) =>
    choice("acceleration", "page-search", names, (f) => f.render.acceleration || "none",
      (v) => ({ "render.acceleration": v }));
  const meshes = [["none", "page-brute-force"], ["bbox", "page-bounding-box"], ["bvh", "page-bvh"]];
  // Beyond the course: the same image by the fast engine, in less time.
  const fast = toggle("fast", "page-fast", (f) => !!f.render.fast,
    (on) => ({ "render.fast": on || null }));

  // The controls that each session teaches, and the size its demo renders at.
  const SESSIONS = {
    1: { size: 256, controls: [
      range("fov", "page-field-of-view", [20, 120, 1], (f) => f.camera.fov, (x) => ({ "camera.fov": x })),
      lightAxis("lightX", 0, [-50, 50, 1]), lightAxis("lightY", 1, [-9, 55, 1]), lightAxis("lightZ", 2, [-55, 55, 1]),
      range("albedo", "page-albedo", [0, 1, 0.05], (f) => f.light && centre(f).diffuse && centre(f).diffuse[0],
        (x) => ({ "spheres.0.material": { diffuse: [x, x, x] } })),
    ] },
    2: { size: 256, controls: [
      // Off: no gamma key, the renderer's default; on: the file's own gamma.
      toggle("gamma", "page-gamma", (f, s) => s.gamma !== 1,
        (on) => (on ? {} : { "render.gamma": null })),
      choice("offset", "page-shadow-offset", offsets, (f) => (f.render.shadows ? "robust" : undefined),
        (x) => ({ "render.shadow_offset": x === "robust" ? null : Number(x) })),
      choice("material", "page-centre-sphere", [["diffuse", "page-diffuse"], ["mirror", "page-mirror"], ["glass", "page-glass"]],
        (f) => (f.render.shadows ? materialName(f) : undefined), (_, v) => ({ "spheres.0.material": material(v) })),
      range("index", "page-refractive-index", [1, 2.5, 0.05], (f) => (f.render.shadows ? centre(f).glass || 1.5 : undefined),
        (_, v) => ({ "spheres.0.material": material(v) }), (v) => v.material === "glass"),
    ] },
    3: { size: 256, controls: [
      samples,
      range("bounces", "page-bounces", [0, 10, 1], (f, s) => s.bounces, (x) => ({ "render.bounces": x })),
      toggle("antialiasing", "page-antialiasing", (f) => f.camera.antialiasing !== undefined,
        (on) => ({ "camera.antialiasing": on ? 0.5 : null })),
      fast,
    ] },
    4: { size: 256, controls: [
      samples,
      range("radius", "page-light-radius", [0.5, 15, 0.5], (f) => f.light && f.light.radius, (x) => ({ "light.radius": x })),
      toggle("sampling", "page-light-sampling", (f) => (f.light && f.light.radius ? !!f.render.light_sampling : undefined),
        (on) => ({ "render.light_sampling": on })),
      range("aperture", "page-aperture", [0.1, 5, 0.1], (f) => f.camera.lens && f.camera.lens.aperture,
        (_, v) => ({ "camera.lens": { aperture: v.aperture, focus: v.focus } })),
      range("focus", "page-focus", [20, 90, 1], (f) => f.camera.lens && f.camera.lens.focus,
        (_, v) => ({ "camera.lens": { aperture: v.aperture, focus: v.focus } })),
      fast,
    ] },
    5: { size: 128, cost: true, controls: [samples, accelerations(meshes.slice(0, 2)), fast] },
    6: { size: 256, cost: true, controls: [
      samples, accelerations(meshes),
      toggle("smooth", "page-smooth-normals", (f) => !!f.meshes[0].smooth_normals, (on) => ({ "meshes.0.smooth_normals": on })),
      fast,
    ] },
    7: { size: 256, orbit: true, controls: [
      samples,
      range("plunge", "page-plunge", [-10, 80, 1], (f) => f.camera.plunge || 0, () => ({})),
      toggle("texture", "page-texture", (f) => !!f.meshes[0].textured, (on) => ({ "meshes.0.textured": on })),
      fast,
    ] },
  };

  /** Whether the reader asked for less motion: each render is then drawn once, when
   * done, rather than a first pass and then band by band. */
  const still = window.matchMedia("(prefers-reduced-motion: reduce)").matches;

  /** Arrow keys on session 7's image: how far each turns the camera, in degrees of
   * azimuth and of plunge, as dragging by 20 pixels and by 10 does. */
  const KEYS = { ArrowLeft: [10, 0], ArrowRight: [-10, 0], ArrowUp: [0, -5], ArrowDown: [0, 5] };

  /** The page's `?live-size=N`, if any. */
  const sizeOverride = Number(new URLSearchParams(location.search).get("live-size")) || 0;
  const BAND = 8;
  /** The side of the blocks of a render's first look, which traces one pixel in
   * PREVIEW x PREVIEW (a sixteenth of the rays): brute force's first picture in a
   * sixteenth of its first pass's time. */
  const PREVIEW = 4;

  class LiveDemo {
    constructor(root) {
      this.root = root;
      this.session = Number(root.dataset.session);
      this.setup = SESSIONS[this.session];
      this.size = sizeOverride || this.setup.size;
      this.job = 0;
      this.times = {};
      this.workers = startWorkers((message, worker) => this.received(message, worker));
      this.workers[0].postMessage({ kind: "stages" });
      this.status(say("page-loading"));
    }

    status(text, state) {
      this.root.dataset.state = state || "working";
      (this.statusLine || this.root).textContent = text;
    }

    received(message, worker) {
      if (message.kind === "stages") return this.build(message.stages);
      if (message.job !== undefined && message.job !== this.job) return;
      if (message.kind === "rows") this.paint(message);
      if (message.kind === "pass") this.passDone(message);
      if (message.kind === "cost") this.costDone(message);
      if (message.kind === "error") this.status(say("page-error", { message: message.message }), "error");
    }

    /** Builds the stage list, the canvases and the controls once the stages are known. */
    build(stages) {
      this.stages = stages.filter((s) => s.session === this.session);
      this.root.textContent = "";
      this.select = element("select", { className: "live-stage", onchange: () => this.pickStage() },
        ...this.stages.map((s) => element("option", { value: s.name, textContent: say("page-stage-option", { stage: s.name, title: s.title }) })));
      this.canvas = element("canvas", { className: "live-image", width: this.size, height: this.size });
      this.canvas.setAttribute("role", "img");
      const images = element("div", { className: "live-images" }, this.canvas);
      if (this.setup.cost) {
        this.costCanvas = element("canvas", { className: "live-cost", width: this.size, height: this.size });
        this.costCaption = element("figcaption", { textContent: say("page-cost-caption") });
        this.costCanvas.setAttribute("role", "img");
        this.costCanvas.setAttribute("aria-label", say("page-cost-image", { caption: this.costCaption.textContent }));
        images.append(element("figure", {}, this.costCanvas, this.costCaption));
      }
      if (this.setup.orbit) this.orbit();
      this.controls = element("div", { className: "live-controls" });
      this.statusLine = element("p", { className: "live-status" });
      this.statusLine.setAttribute("role", "status");
      this.timesTable = element("table", { className: "live-times" });
      this.functions = element("code", { className: "live-functions" });
      this.functionsTitle = element("summary", { textContent: say("page-functions-course") });
      const ran = element("details", {}, this.functionsTitle, this.functions);
      this.root.append(element("p", {}, element("label", {}, `${say("page-stage")} `, this.select)), images, this.controls,
        this.statusLine, this.timesTable, ran);
      this.pickStage();
    }

    /** Starts the chosen stage from its own scene file. */
    pickStage() {
      this.stage = this.stages.find((s) => s.name === this.select.value);
      this.values = {};
      this.start = {};
      this.azimuth = 0;
      this.controls.textContent = "";
      this.inputs = [];
      for (const control of this.setup.controls) {
        const value = control.read(this.stage.file, this.stage.settings);
        if (value === undefined) continue;
        this.values[control.id] = this.start[control.id] = value;
        this.controls.append(this.input(control, value));
      }
      this.showControls();
      this.render();
    }

    /** The input of `control`, starting at `value`. */
    input(control, value) {
      // The value beside a slider, for the eye: a screen reader reads the slider's own.
      const shown = element("output", { textContent: say("page-number", { value }) });
      shown.setAttribute("aria-hidden", "true");
      let input;
      if (control.kind === "select") {
        input = element("select", {}, ...control.options.map(([v, label]) => element("option", { value: v, textContent: labelOf(label) })));
        input.value = value;
      } else {
        input = element("input", { type: control.kind, min: control.min, max: control.max, step: control.step });
        if (control.kind === "checkbox") input.checked = value; else input.value = value;
      }
      input.dataset.control = control.id;
      input.shown = shown;
      const changed = () => {
        const v = control.kind === "checkbox" ? input.checked : control.kind === "range" ? Number(input.value) : input.value;
        this.values[control.id] = v;
        shown.textContent = say("page-number", { value: v });
        this.showControls();
        this.render();
      };
      input.addEventListener(control.kind === "range" ? "input" : "change", changed);
      const label = element("label", { className: "live-control" }, `${labelOf(control.label)} `, input);
      if (control.kind === "range") label.append(" ", shown);
      label.liveControl = control;
      this.inputs.push(label);
      return label;
    }

    showControls() {
      for (const label of this.inputs) {
        label.hidden = label.liveControl.show ? !label.liveControl.show(this.values) : false;
      }
    }

    /** The edits of the stage's scene file that the controls ask for. */
    edits() {
      const edits = {};
      for (const control of this.setup.controls) {
        if (!(control.id in this.values) || this.values[control.id] === this.start[control.id]) continue;
        Object.assign(edits, control.edit(this.values[control.id], this.values));
      }
      if (this.setup.orbit && (this.azimuth !== 0 || this.values.plunge !== this.start.plunge)) {
        const a = this.azimuth * Math.PI / 180;
        const [x, y, z] = this.stage.file.camera.position;
        const r = Math.hypot(x, y, z);
        Object.assign(edits, {
          "camera.look_at": [0, 0, 0],
          "camera.position": [r * Math.sin(a), 0, r * Math.cos(a)],
          "camera.plunge": this.values.plunge,
        });
      }
      return edits;
    }

    /** Renders the scene again: where it takes several samples, a first look in
     * blocks and one sample per pixel first, then all of them. */
    render() {
      this.job += 1;
      const samples = this.values.samples || this.stage.settings.samples;
      const pass = (count, scale = 1) => ({ samples: count, scale });
      const passes = samples > 1 && !still ? [pass(1, PREVIEW), pass(1), pass(samples)] : [pass(samples)];
      this.held = [];
      delete this.root.dataset.lookMs;
      this.describe(0);
      this.pending = { passes, bands: Math.ceil(this.size / BAND), done: 0, rays: 0, started: performance.now() };
      this.edited = this.edits();
      this.status(say("page-rendering", { stage: this.stage.name }));
      const count = this.workers.length;
      this.workers.forEach((worker, i) => {
        const bands = [];
        for (let first = i * BAND; first < this.size; first += count * BAND) bands.push(first);
        worker.postMessage({ kind: "render", job: this.job, stage: this.stage.name, edits: this.edited,
          width: this.size, height: this.size, passes, bands, band: BAND });
      });
    }

    /** Draws a band's pixels; a first look's, each pixel as a block of its scale. */
    paint(message) {
      const scale = this.pending.passes[message.pass].scale;
      const width = this.size / scale;
      const rows = message.rgba.length / (4 * width);
      const pixels = new ImageData(new Uint8ClampedArray(message.rgba.buffer), width, rows);
      const context = this.canvas.getContext("2d");
      if (still) this.held.push([pixels, message.first]);
      else if (scale === 1) context.putImageData(pixels, 0, message.first);
      else {
        this.small = this.small || element("canvas");
        [this.small.width, this.small.height] = [width, rows];
        this.small.getContext("2d").putImageData(pixels, 0, 0);
        context.imageSmoothingEnabled = false;
        context.drawImage(this.small, 0, 0, width, rows, 0, message.first, this.size, rows * scale);
      }
    }

    /** The image's text alternative, which follows it: the stage, what the controls
     * set, and the samples per pixel drawn so far. */
    describe(samples) {
      const set = this.inputs.filter((label) => !label.hidden).map((label) => {
        const input = label.querySelector("[data-control]");
        const value = input.type === "checkbox" ? say(input.checked ? "page-on" : "page-off")
          : input.tagName === "SELECT" ? input.selectedOptions[0].textContent : say("page-number", { value: Number(input.value) });
        return say("page-setting", { control: labelOf(label.liveControl.label), value });
      });
      if (this.setup.orbit) set.push(say("page-turned", { degrees: Math.round(this.azimuth) }));
      const done = samples ? say("page-samples-done", { samples }) : say("page-not-done");
      this.canvas.setAttribute("aria-label", say(this.setup.orbit ? "page-image-orbit" : "page-image", {
        session: this.session, stage: say("page-stage-option", { stage: this.stage.name, title: this.stage.title }),
        settings: set.join(say("page-separator")), done }));
    }

    /** One worker finished a pass; when all have, the pass's time is shown. */
    passDone(message) {
      const p = this.pending;
      p.rays += message.rays;
      p[message.pass] = (p[message.pass] || 0) + 1;
      if (p[message.pass] < this.workers.length) return;
      const ms = performance.now() - p.started;
      const { samples, scale } = p.passes[message.pass];
      const look = scale > 1;
      if (look) this.root.dataset.lookMs = Math.round(ms);
      else if (p.firstMs === undefined) p.firstMs = this.root.dataset.firstMs = Math.round(ms);
      this.functions.textContent = message.functions.join(", ");
      this.functionsTitle.textContent = say(this.values.fast ? "page-functions-fast" : "page-functions-course");
      const last = message.pass === p.passes.length - 1;
      if (still && last) for (const [pixels, first] of this.held) this.canvas.getContext("2d").putImageData(pixels, 0, first);
      if (last || !(still || look)) this.describe(samples);
      const pass = { stage: this.stage.name, size: this.size, samples, scale, time: duration(ms), workers: this.workers.length };
      this.status(say(last ? "page-pass-done" : look ? "page-pass-look" : "page-pass-refining", pass), last ? "done" : "working");
      if (!last) return;
      this.root.dataset.totalMs = Math.round(ms);
      this.root.dataset.edits = JSON.stringify(this.edited);
      if (this.setup.cost) this.record(ms, samples);
    }

    /** For the mesh sessions: the time of this search, and its cost image. */
    record(ms, samples) {
      const search = this.values.acceleration;
      const fast = !!this.values.fast;
      this.timesKey = `${search}${fast ? " fast" : ""}`;
      this.times[this.timesKey] = { search, fast, ms, samples, size: this.size };
      if (fast) {
        this.costCanvas.getContext("2d").clearRect(0, 0, this.size, this.size);
        this.costCaption.textContent = say("page-cost-fast");
        this.costCanvas.setAttribute("aria-label", say("page-cost-image", { caption: this.costCaption.textContent }));
        this.showTimes();
        return;
      }
      this.workers[0].postMessage({ kind: "cost", job: this.job, stage: this.stage.name, edits: this.edited,
        width: this.size, height: this.size });
    }

    costDone(message) {
      this.costCanvas.height = message.height;
      const pixels = new ImageData(new Uint8ClampedArray(message.rgba.buffer), this.size, message.height);
      this.costCanvas.getContext("2d").putImageData(pixels, 0, 0);
      this.costCaption.textContent = say("page-cost-mean", { mean: message.mean });
      this.costCanvas.setAttribute("aria-label", say("page-cost-image", { caption: this.costCaption.textContent }));
      this.times[this.timesKey].cost = message.mean;
      this.showTimes();
    }

    showTimes() {
      const name = (t) => {
        const search = say(meshes.find((m) => m[0] === t.search)[1]);
        return t.fast ? say("page-times-fast", { search }) : search;
      };
      const rows = Object.values(this.times).map((t) => element("tr", {},
        element("td", { textContent: name(t) }),
        element("td", { textContent: say("page-times-time", { time: duration(t.ms), samples: t.samples, size: t.size }) }),
        element("td", { textContent: t.cost === undefined ? "" : say("page-times-cost", { cost: t.cost }) })));
      const head = (id) => element("th", { scope: "col", textContent: say(id) });
      this.timesTable.replaceChildren(element("tr", {}, head("page-times-search"), head("page-times-duration"), head("page-times-cost-head")), ...rows);
    }

    /** Session 7: dragging the image (by mouse, pen or finger) turns the camera
     * around the cow and raises it; so do the arrow keys, the image having the focus. */
    orbit() {
      let from = null;
      this.canvas.classList.add("live-orbit");
      this.canvas.tabIndex = 0;
      this.canvas.addEventListener("pointerdown", (e) => { from = [e.clientX, e.clientY]; this.canvas.setPointerCapture(e.pointerId); });
      for (const end of ["pointerup", "pointercancel"]) this.canvas.addEventListener(end, () => { from = null; });
      this.canvas.addEventListener("pointermove", (e) => {
        if (!from) return;
        this.turn(-(e.clientX - from[0]) * 0.5, (e.clientY - from[1]) * 0.5);
        from = [e.clientX, e.clientY];
      });
      this.canvas.addEventListener("keydown", (e) => {
        if (!KEYS[e.key] || e.altKey || e.ctrlKey || e.metaKey) return;
        // The arrows turn the camera here, rather than scroll the page or (mdBook's
        // left and right) go to another chapter.
        e.preventDefault();
        e.stopPropagation();
        this.turn(...KEYS[e.key]);
      });
    }

    /** Turns the camera by `azimuth` degrees around the cow and raises it by `plunge`
     * (kept within the plunge control's range), and renders again. */
    turn(azimuth, plunge) {
      this.azimuth += azimuth;
      this.values.plunge = Math.round(Math.max(-10, Math.min(80, this.values.plunge + plunge)));
      const input = this.controls.querySelector('[data-control="plunge"]');
      if (input) { input.value = this.values.plunge; input.shown.textContent = say("page-number", { value: this.values.plunge }); }
      this.render();
    }
  }

  startEach(".live-demo[data-session]", (root) => { root.liveDemo = new LiveDemo(root); });
})();
