// Shared by the page checks: the browser (BROWSER = chromium, the default, or firefox; its
// executable in BROWSER_PATH), the checks' report, and the page's problems (script errors,
// console errors and warnings, failed requests, any request beyond the page).
import puppeteer from "puppeteer-core";
import { pathToFileURL } from "node:url";

/** Runs `body({ page, url, check, name })` on a fresh page at FILE; exits 1 on any failure. */
export async function inBrowser(what, file, viewport, body) {
  const firefox = process.env.BROWSER === "firefox";
  const name = firefox ? "firefox" : "chromium";
  const url = pathToFileURL(file).href;
  const failures = [];
  const check = (ok, text) => {
    console.log(`${ok ? "ok  " : "FAIL"} ${what} (${name}): ${text}`);
    if (!ok) failures.push(text);
  };
  const browser = await puppeteer.launch(
    firefox
      ? { browser: "firefox", executablePath: process.env.BROWSER_PATH, headless: true }
      : { executablePath: process.env.BROWSER_PATH, headless: true, args: ["--no-sandbox", "--disable-gpu"] },
  );
  try {
    const page = await browser.newPage();
    const problems = [];
    page.on("console", (m) => { if (m.type() === "error" || m.type() === "warn") problems.push(`console ${m.type()}: ${m.text()}`); });
    page.on("pageerror", (e) => problems.push(`script error: ${e}`));
    page.on("requestfailed", (r) => problems.push(`request failed: ${r.url()}`));
    // data: URLs are the browser's own (Firefox's built-in MathML font), not the network.
    page.on("request", (r) => {
      if (!r.url().startsWith(url.split("#")[0]) && !r.url().startsWith("data:")) problems.push(`request beyond the page: ${r.url()}`);
    });
    await page.setViewport(viewport);
    await page.goto(url, { waitUntil: "load" });
    await moduleReady(page);
    await body({ page, url, check, name });
    for (const p of problems) check(false, p);
  } finally {
    await browser.close();
  }
  if (failures.length) {
    console.log(`${failures.length} browser checks failed`);
    process.exit(1);
  }
}

/**
 * Waits until a page that computes with rodimpact's WebAssembly module has started it and shown
 * its first answer (or said that it could not): at once for a page without the module.
 */
export async function moduleReady(page) {
  await page.waitForFunction(
    () => {
      const check = document.getElementById("self-check");
      return !document.getElementById("rodimpact-wasm") || document.querySelector(".load-error")
        || (document.documentElement.dataset.firstAnswerMs && (!check || check.textContent));
    },
    { timeout: 30000 },
  );
}
