// The report page of `rodimpact paper --format html` in headless Chromium.
// Usage: node paper.mjs PAGE.html CLAIMS SCREENSHOT_DIR
import { inBrowser } from "./common.mjs";

const [file, claimCount, shots] = process.argv.slice(2);

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

  // Print: every certificate unfolded on paper, and folded back after.
  const pdf = Buffer.from(await page.pdf({ format: "A4", path: `${shots}/${name}-paper.pdf` }));
  // The page count from the PDF's page tree (Chromium writes it plainly; Firefox compresses it).
  const counts = [...pdf.toString("latin1").matchAll(/\/Type\s*\/Pages[^>]*?\/Count\s+(\d+)|\/Count\s+(\d+)[^>]*?\/Type\s*\/Pages/g)].map((m) => Number(m[1] || m[2]));
  const pages = counts.length ? Math.max(...counts) : 0;
  if (pages > 0) {
    check(pages > 60, `printed on ${pages} A4 pages, every certificate unfolded`);
  } else {
    check(pdf.length > 100000, `printed (${(pdf.length / 1e6).toFixed(1)} MB of PDF; its page tree is compressed)`);
    const unfolded = await page.evaluate(() => {
      window.dispatchEvent(new Event("beforeprint"));
      const all = [...document.querySelectorAll("details.claim")].every((d) => d.open);
      window.dispatchEvent(new Event("afterprint"));
      return all;
    });
    check(unfolded, "before printing every certificate is unfolded");
  }
  check(await page.$$eval("details.claim", (ds) => ds.filter((d) => d.open).map((d) => d.id).join(",")) === "C15", "after printing, only C15 is open again");

});
