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

  // The demos' and the check page's words in French: the English text is the key.
  const FRENCH = {
    "field of view (degrees)": "champ de vision (degrés)",
    "light x": "lumière x", "light y": "lumière y", "light z": "lumière z",
    "albedo of the sphere": "albédo de la sphère",
    "gamma correction (2.2)": "correction gamma (2,2)",
    "shadow ray's offset": "décalage du rayon d'ombre",
    "past the point's rounding error (the crate's)": "juste au-delà de l'erreur d'arrondi (celui de la crate)",
    "ε = 0: shadow acne": "ε = 0 : acné d'ombre",
    "the centre sphere": "la sphère centrale",
    "diffuse": "diffuse", "mirror": "miroir", "glass": "verre",
    "refractive index": "indice de réfraction",
    "samples per pixel": "échantillons par pixel",
    "sample per pixel": "échantillon par pixel",
    "bounces": "rebonds",
    "antialiasing": "anticrénelage",
    "light radius": "rayon de la source",
    "light sampling": "échantillonnage de la lumière",
    "aperture": "ouverture",
    "focus distance": "distance de mise au point",
    "search of the mesh": "recherche dans le maillage",
    "brute force": "force brute", "bounding box": "boîte englobante", "BVH": "BVH",
    "smooth normals": "normales lissées",
    "plunge (degrees); drag the image or use the arrow keys to orbit":
      "plongée (degrés)\u00a0; faites glisser l'image ou utilisez les flèches pour tourner",
    "on": "oui", "off": "non",
    "turned by": "tournée de", "degrees": "degrés",
    "rendering…": "calcul en cours…",
    "Arrow keys turn the camera, as dragging does.": "Les flèches tournent la caméra, comme le glisser.",
    "the cost image": "l'image du coût",
    "texture": "texture",
    "fast engine": "moteur rapide",
    "the fast engine (beyond the course: the same image)": "le moteur rapide (au-delà du cours\u00a0: la même image)",
    "loading the renderer…": "chargement du moteur de rendu…",
    "stage": "étape",
    "rendering": "calcul de",
    "in": "en",
    "refining…": "affinage…",
    "workers": "workers",
    "cost: tests per camera ray": "coût\u00a0: tests par rayon primaire",
    "tests per camera ray on average": "tests par rayon primaire en moyenne",
    "tests per camera ray": "tests par rayon primaire",
    "cost": "coût", "search": "recherche", "time": "temps", "samples": "échantillons",
    "the course functions this image ran": "les fonctions du cours qui ont fait cette image",
    "the fast engine's function that made this image (beyond the course)":
      "la fonction du moteur rapide qui a fait cette image (au-delà du cours)",
    "cost: counted for the course's searches only": "coût\u00a0: compté pour les recherches du cours seulement",
    "error": "erreur",
    "your image": "votre image",
    "check": "vérifier",
    "session": "séance",
    "rendering the reference…": "calcul de la référence…",
    "rendering the reference": "calcul de la référence",
    "rows": "lignes",
    "matches": "correspond",
    "differs": "diffère",
    "choose your image first (a PNG, JPEG or PPM file)": "choisissez d'abord votre image (un fichier PNG, JPEG ou PPM)",
    "the differences: differing pixels or blocks in red": "les différences\u00a0: pixels ou blocs différents en rouge",
    "the live demo": "la démo interactive",
    "grade": "noter",
    "the grading sheet, grades.csv": "la feuille de notes, grades.csv",
    "A class, as check --all grades it": "Une classe, notée comme le fait check --all",
    "the class's folder (a folder per student)": "le dossier de la classe (un dossier par étudiant)",
    "or one student's images, named after their stages": "ou les images d'un étudiant, nommées d'après leurs étapes",
    "choose a class's folder or a student's images first": "choisissez d'abord le dossier d'une classe ou les images d'un étudiant",
    "grading…": "notation…",
    "folders graded": "dossiers notés",
    "every image matches": "toutes les images correspondent",
    "some images differ": "des images diffèrent",
    "the check": "la vérification",
    "This browser cannot run": "Ce navigateur ne peut pas exécuter",
    "it needs WebAssembly and workers": "il faut WebAssembly et les workers",
  };

  /** `text` in the page's language. */
  const say = (text) => (french && FRENCH[text]) || text;

  /** A number with the page's decimal mark. */
  const number = (x, digits) => (french ? x.toFixed(digits).replace(".", ",") : x.toFixed(digits));

  /** A duration in milliseconds as a reader reads it: "84 ms", "3.2 s". */
  function duration(ms) {
    return ms < 1000 ? `${Math.round(ms)} ms` : `${number(ms / 1000, 1)} s`;
  }

  /** Once the page is read, `make(root)` for each element that `selector` finds, or
   * a sentence saying that this browser cannot run `what`. */
  function startEach(selector, what, make) {
    const start = () => {
      for (const root of document.querySelectorAll(selector)) {
        if (supported) make(root);
        else root.textContent = `${say("This browser cannot run")} ${say(what)} (${say("it needs WebAssembly and workers")}).`;
      }
    };
    if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
    else start();
  }

  window.raycourseLive = { startWorkers, startEach, element, duration, say, number, french };
})();
