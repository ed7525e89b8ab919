// The language switch of every page: a link in the menu bar to the same page in the
// other language. The English book is the book's root; the French one is its fr/
// folder (`cargo xtask book` builds both).
(function () {
  "use strict";
  const french = document.documentElement.lang.startsWith("fr");
  const page = location.pathname.split("/").pop() || "index.html";
  const root = typeof path_to_root === "string" ? path_to_root : "";
  const link = document.createElement("a");
  link.className = "language-switch";
  link.href = french ? `${root}../${page}` : `${root}fr/${page}`;
  link.textContent = french ? "English" : "Français";
  link.title = french ? "Read this page in English" : "Lire cette page en français";
  link.lang = french ? "en" : "fr";
  const place = () => {
    const buttons = document.querySelector(".right-buttons");
    if (buttons) buttons.prepend(link);
  };
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", place);
  else place();
})();
