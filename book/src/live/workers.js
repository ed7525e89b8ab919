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

  /** A duration in milliseconds as a reader reads it: "84 ms", "3.2 s". */
  function duration(ms) {
    return ms < 1000 ? `${Math.round(ms)} ms` : `${(ms / 1000).toFixed(1)} s`;
  }

  /** Once the page is read, `make(root)` for each element that `selector` finds, or
   * a sentence saying that this browser cannot run `what`. */
  function startEach(selector, what, make) {
    const start = () => {
      for (const root of document.querySelectorAll(selector)) {
        if (supported) make(root);
        else root.textContent = `This browser cannot run ${what} (it needs WebAssembly and workers).`;
      }
    };
    if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
    else start();
  }

  window.raycourseLive = { startWorkers, startEach, element, duration };
})();
