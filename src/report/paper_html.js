"use strict";
(function () {
  const claims = () => Array.from(document.querySelectorAll("details.claim"));
  const setAll = (open) => claims().forEach((d) => { d.open = open; });
  document.getElementById("unfold").addEventListener("click", () => setAll(true));
  document.getElementById("fold").addEventListener("click", () => setAll(false));
  // Printed as shown: a folded certificate prints as its one line. With the box ticked, every
  // certificate is unfolded for print, and what the reader had open is restored after.
  let before = null;
  window.addEventListener("beforeprint", () => {
    if (!document.getElementById("print-all").checked) return;
    before = claims().map((d) => d.open);
    setAll(true);
  });
  window.addEventListener("afterprint", () => {
    if (before) claims().forEach((d, i) => { d.open = before[i]; });
    before = null;
  });
  // A link to a claim (#C15) opens its certificate.
  const openTarget = () => {
    const id = decodeURIComponent(location.hash.slice(1));
    const target = id && document.getElementById(id);
    if (target && target.tagName === "DETAILS") target.open = true;
  };
  window.addEventListener("hashchange", openTarget);
  openTarget();
})();
