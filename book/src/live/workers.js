// The workers that run the crate in a page: one per core (at most eight), each a
// Web Worker running worker.js. Loaded on every page of the book before demo.js
// and check.js, which use it through `window.raycourseLive`.
(function () {
  "use strict";
  // This script's folder: the workers and the WebAssembly module are beside it.
  const folder = new URL("./", document.currentScript.src);

  /** A pool of `count` workers; `onMessage(message, worker)` gets what they post. */
  function startWorkers(onMessage, count) {
    const cores = navigator.hardwareConcurrency || 2;
    const size = count || Math.max(1, Math.min(cores, 8));
    const workers = [];
    for (let i = 0; i < size; i++) {
      const worker = new Worker(new URL("worker.js", folder), { type: "module" });
      worker.onmessage = (event) => onMessage(event.data, i);
      worker.onerror = (event) => onMessage({ kind: "error", message: event.message || "the worker could not start (was the book built with `cargo xtask book`?)" }, i);
      workers.push(worker);
    }
    return workers;
  }

  /** Whether the page can run the crate: workers and WebAssembly. */
  const supported = typeof WebAssembly === "object" && typeof Worker === "function";

  /** An element of `tag` with `properties` and children. */
  function element(tag, properties, ...children) {
    const node = Object.assign(document.createElement(tag), properties || {});
    for (const child of children) node.append(child);
    return node;
  }

  /** Whether the page is the French book's. */
  const french = document.documentElement.lang.startsWith("fr");

  // The page's words come from the program's message catalogue (messages/*/page.ftl),
  // through the crate's WebAssembly module, loaded on this thread for them once a
  // page has a demo or the check page.
  let catalogue = null;
  let loading = null;
  const loadWords = () => loading || (loading = import(new URL("pkg/raycourse_web.js", folder).href)
    .then(async (module) => { await module.default(); catalogue = module; }));

  /** The message `id` in the page's language, with `args` (texts and numbers). */
  const say = (id, args) => catalogue.message(document.documentElement.lang, id, JSON.stringify(args || {}));

  /** A duration in milliseconds as a reader reads it: "84 ms", "3.2 s". */
  function duration(ms) {
    return ms < 1000 ? say("page-milliseconds", { ms }) : say("page-seconds", { seconds: ms / 1000 });
  }

  /** Once the page is read and its words loaded, `make(root)` for each element that
   * `selector` finds. A browser without workers or WebAssembly keeps the element's
   * own text, the chapter's sentence saying what it would need. */
  function startEach(selector, make) {
    const start = async () => {
      const roots = document.querySelectorAll(selector);
      if (!supported || !roots.length) return;
      await loadWords();
      for (const root of roots) make(root);
    };
    if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
    else start();
  }

  window.raycourseLive = { startWorkers, startEach, element, duration, say, french };
})();
