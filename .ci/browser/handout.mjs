// The handout of `rodimpact handout` (one scene to print) in a headless browser: the answer,
// the working and the formulas in MathML, one figure and one table, printed on 2 to 5 A4 pages.
// Usage: node handout.mjs SCREENSHOT_DIR HANDOUT.html...
import { inBrowser } from "./common.mjs";
import { printed } from "./print.mjs";

const [shots, ...files] = process.argv.slice(2);

for (const [i, file] of files.entries()) {
  await inBrowser(`handout ${i + 1}`, file, { width: 900, height: 1300 }, async ({ page, check, name }) => {
    const facts = await page.evaluate(() => {
      const frac = document.querySelector("#working mfrac, #formulas mfrac");
      return {
        sections: [...document.querySelectorAll("main section[id]")].map((s) => s.id),
        answer: document.querySelector("#answer table.answer")?.textContent ?? "",
        maths: document.querySelectorAll("#working math, #formulas math").length,
        fracHeight: frac ? frac.getBoundingClientRect().height : 0,
        numerHeight: frac ? frac.firstElementChild.getBoundingClientRect().height : 0,
        svgs: [...document.querySelectorAll("figure svg")].map((s) => { const r = s.getBoundingClientRect(); return [r.width, r.height]; }),
        tables: [...document.querySelectorAll("#table table[id]")].map((t) => t.id),
      };
    });
    check(JSON.stringify(facts.sections) === JSON.stringify(["answer", "working", "formulas", "figure", "table"]), `sections ${facts.sections}`);
    check(facts.answer.includes("After the impact") && facts.answer.includes("Fastest spin"), "solve's exact answer");
    check(facts.maths > 20, `${facts.maths} MathML formulas in the working and the formulas`);
    check(facts.numerHeight > 0 && facts.fracHeight > 1.8 * facts.numerHeight, `MathML laid out (a fraction ${facts.fracHeight.toFixed(1)} px tall, its numerator ${facts.numerHeight.toFixed(1)} px)`);
    check(facts.svgs.length === 1 && facts.svgs.every(([w, h]) => w > 300 && h > 200), `one figure drawn ${JSON.stringify(facts.svgs)}`);
    check(facts.tables.length === 1, `one table (${facts.tables})`);
    await page.screenshot({ path: `${shots}/${name}-handout-${i + 1}.png`, fullPage: true });
    const pdf = await printed(page, `${shots}/${name}-handout-${i + 1}.pdf`);
    if (pdf.pages > 0) check(pdf.pages >= 2 && pdf.pages <= 5, `the handout prints on ${pdf.pages} A4 pages (2 to 5)`);
    else check(pdf.bytes > 10000, `the handout printed (${(pdf.bytes / 1e3).toFixed(0)} kB of PDF; the page count is in a compressed page tree)`);
  });
}
