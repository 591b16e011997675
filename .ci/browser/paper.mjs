// The report page of `rodimpact paper --format html` in headless Chromium, and its summary
// edition (`--summary`), as printed.
// Usage: node paper.mjs PAGE.html CLAIMS SCREENSHOT_DIR SUMMARY.html
import { inBrowser } from "./common.mjs";
import { printed } from "./print.mjs";

const [file, claimCount, shots, summaryFile] = process.argv.slice(2);

/** The ids of the certificates open while the page is being printed (the print events sent by hand). */
const openInPrint = (page) => page.evaluate(() => {
  window.dispatchEvent(new Event("beforeprint"));
  const open = [...document.querySelectorAll("details.claim")].filter((d) => d.open).length;
  window.dispatchEvent(new Event("afterprint"));
  return open;
});

await inBrowser("paper", file, { width: 1100, height: 1400 }, async ({ page, url, check, name }) => {

  const facts = await page.evaluate(() => {
    const details = [...document.querySelectorAll("details.claim")];
    const frac = document.querySelector("table#T2 mfrac");
    const svgs = [...document.querySelectorAll("figure svg")].map((s) => s.getBoundingClientRect());
    return {
      title: document.title,
      claims: details.length,
      open: details.filter((d) => d.open).length,
      maths: document.querySelectorAll("math").length,
      // MathML laid out: a fraction stacks its numerator over its denominator.
      fracHeight: frac ? frac.getBoundingClientRect().height : 0,
      numerHeight: frac ? frac.firstElementChild.getBoundingClientRect().height : 0,
      svgs: svgs.map((r) => [r.width, r.height]),
      tables: [...document.querySelectorAll("main table[id]")].map((t) => t.id),
    };
  });
  check(facts.title.startsWith("Verification of N. A. Lemos"), `title "${facts.title}"`);
  check(facts.claims === Number(claimCount), `${facts.claims} claims folded (expected ${claimCount})`);
  check(facts.open === 0, `all folded at first (${facts.open} open)`);
  check(facts.maths > 100, `${facts.maths} MathML formulas`);
  check(facts.numerHeight > 0 && facts.fracHeight > 1.8 * facts.numerHeight, `MathML laid out (a fraction ${facts.fracHeight.toFixed(1)} px tall, its numerator ${facts.numerHeight.toFixed(1)} px)`);
  check(facts.svgs.length === 3 && facts.svgs.every(([w, h]) => w > 300 && h > 200), `3 figures drawn ${JSON.stringify(facts.svgs)}`);
  check(JSON.stringify(facts.tables) === JSON.stringify(["T1", "T2", "T3", "T4", "T5"]), `tables ${facts.tables}`);
  await page.screenshot({ path: `${shots}/${name}-paper-top.png` });

  // The buttons, by keyboard: focus and press Enter.
  await page.focus("#unfold");
  await page.keyboard.press("Enter");
  check(await page.$$eval("details.claim", (ds) => ds.every((d) => d.open)), "Unfold opens every certificate");
  await page.focus("#fold");
  await page.keyboard.press("Enter");
  check(await page.$$eval("details.claim", (ds) => ds.every((d) => !d.open)), "Fold closes them");

  // A link to a claim opens it.
  await page.goto(`${url}#C15`, { waitUntil: "load" });
  const c15 = await page.$eval("#C15", (d) => ({ open: d.open, text: d.innerText }));
  check(c15.open && c15.text.includes("Identity certificate"), "#C15 opens C15's certificate");
  await page.screenshot({ path: `${shots}/${name}-paper-C15.png` });
  for (const id of ["T2", "figure1"]) {
    await page.evaluate((id) => document.getElementById(id).scrollIntoView(), id);
    await page.screenshot({ path: `${shots}/${name}-paper-${id}.png` });
  }

  // Print as shown (NEWCOMER M9): a folded certificate prints as its line, C15 unfolded.
  check((await openInPrint(page)) === 1, "printing leaves the folded certificates folded");
  const shown = await printed(page, `${shots}/${name}-paper.pdf`);
  if (shown.pages > 0) check(shown.pages < 30, `printed as shown on ${shown.pages} A4 pages`);
  // Ticked, the box unfolds every certificate for print, and folds them back after.
  await page.click("#print-all");
  check((await openInPrint(page)) === Number(claimCount), "with the box ticked, printing unfolds every certificate");
  const whole = await printed(page, `${shots}/${name}-paper-whole.pdf`);
  check(whole.pages > 60 || (whole.pages === 0 && whole.bytes > 2 * shown.bytes), `printed whole on ${whole.pages || "(compressed page tree)"} A4 pages, ${(whole.bytes / 1e6).toFixed(1)} MB (as shown: ${(shown.bytes / 1e6).toFixed(2)} MB)`);
  check(await page.$$eval("details.claim", (ds) => ds.filter((d) => d.open).map((d) => d.id).join(",")) === "C15", "after printing, only C15 is open again");

});

// The summary edition: a handout of a dozen pages, every verdict, the formulas, tables and figures.
await inBrowser("paper summary", summaryFile, { width: 1100, height: 1400 }, async ({ page, check, name }) => {
  const facts = await page.evaluate(() => ({
    claims: document.querySelectorAll("ul.verdicts li.claim").length,
    details: document.querySelectorAll("details").length,
    tables: [...document.querySelectorAll("main table[id]")].map((t) => t.id),
    figures: document.querySelectorAll("figure svg").length,
    formulas: document.querySelectorAll("table.formulas math").length,
  }));
  check(facts.claims === Number(claimCount) && facts.details === 0, `every claim's verdict on its line (${facts.claims}), no certificate`);
  check(JSON.stringify(facts.tables) === JSON.stringify(["T1", "T2", "T3", "T4", "T5"]) && facts.figures === 3 && facts.formulas > 10, `tables ${facts.tables}, ${facts.figures} figures, ${facts.formulas} formulas`);
  const handout = await printed(page, `${shots}/${name}-paper-summary.pdf`);
  if (handout.pages > 0) check(handout.pages <= 15, `the summary prints on ${handout.pages} A4 pages`);
  else check(handout.bytes > 10000, `the summary printed (${(handout.bytes / 1e6).toFixed(1)} MB of PDF)`);
  await page.screenshot({ path: `${shots}/${name}-paper-summary.png` });
});
