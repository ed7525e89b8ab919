// What mdBook's pages need besides for the keyboard and screen readers (WCAG 2.1 AA):
// - a code block or a table wider than the page scrolls sideways, so it takes the
//   focus (the arrow keys then scroll it) and is named as a region (2.1.1, keyboard);
//   mdBook's left and right arrows, which go to another chapter, are kept from it;
// - the sidebar's toggle is a label for a hidden checkbox, which the keyboard cannot
//   reach and which may not carry `aria-expanded`: it becomes a button that takes the
//   focus and that Enter and Space press (4.1.2, name, role, value).
(function () {
  "use strict";
  const french = document.documentElement.lang.startsWith("fr");
  const names = french ? { PRE: "code, défile horizontalement", CODE: "code, défile horizontalement",
    DIV: "tableau, défile horizontalement" } : { PRE: "code, scrolls sideways", CODE: "code, scrolls sideways",
    DIV: "table, scrolls sideways" };

  /** Whether `box` scrolls sideways. */
  const scrolls = (box) => box.scrollWidth > box.clientWidth && /auto|scroll/.test(getComputedStyle(box).overflowX);

  /** Each code block or table that scrolls takes the focus; one that no longer
   * does, not. */
  function reachable() {
    for (const box of document.querySelectorAll("main pre, main pre > code, main .table-wrapper")) {
      const named = names[box.tagName];
      if (scrolls(box)) {
        box.tabIndex = 0;
        box.addEventListener("keydown", keepArrows);
        box.setAttribute("role", "region");
        box.setAttribute("aria-label", named);
      } else if (box.getAttribute("aria-label") === named) {
        box.removeAttribute("tabindex");
        box.removeAttribute("role");
        box.removeAttribute("aria-label");
      }
    }
  }

  /** Left and right scroll a focused code block or table sideways, rather than
   * (mdBook's keys) go to another chapter. */
  function keepArrows(e) {
    if ((e.key === "ArrowLeft" || e.key === "ArrowRight") && e.currentTarget.tabIndex === 0) e.stopPropagation();
  }

  /** The sidebar's toggle as a button. */
  function toggle() {
    const label = document.getElementById("mdbook-sidebar-toggle");
    if (!label) return;
    label.setAttribute("role", "button");
    label.tabIndex = 0;
    label.addEventListener("keydown", (e) => {
      if (e.key !== "Enter" && e.key !== " ") return;
      e.preventDefault();
      label.click();
    });
  }

  const start = () => {
    toggle();
    reachable();
    window.addEventListener("resize", reachable);
  };
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
