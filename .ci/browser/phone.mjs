// Both pages on a phone, 390 px wide (NEWCOMER m6, m9): nothing scrolls sideways, the
// explorer's chart and stage labels are drawn at 10 px or more, and its table of values is
// stacked; the report's wide tables and formulas scroll in their own boxes.
// Usage: node phone.mjs EXPLORE.html PAPER.html SCREENSHOT_DIR
import { inBrowser } from "./common.mjs";

const [explore, paper, shots] = process.argv.slice(2);
const phone = { width: 390, height: 844 };

/** The page's width beyond the screen's (0: nothing scrolls sideways). */
const sideways = (page) => page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);

await inBrowser("explore on a phone", explore, phone, async ({ page, url, check, name }) => {
  // Everything shown (predict first off, by the link), struck at a* for the longest labels.
  await page.goto(`${url}#predict=0&a=a*`, { waitUntil: "load" });
  check((await sideways(page)) <= 0, `no sideways scroll at 390 px (${await sideways(page)} px too wide)`);
  const sizes = await page.evaluate(() => {
    const svgText = [...document.querySelectorAll("#curve text, #threshold text")].map((t) => {
      const svg = t.ownerSVGElement;
      return parseFloat(getComputedStyle(t).fontSize) * (svg.getBoundingClientRect().width / svg.viewBox.baseVal.width);
    });
    const canvas = document.getElementById("stage");
    const stage = parseFloat(canvas.getContext("2d").font) * (canvas.getBoundingClientRect().width / canvas.width);
    return { charts: Math.min(...svgText), count: svgText.length, stage };
  });
  check(sizes.count > 20 && sizes.charts >= 10, `the charts' ${sizes.count} labels are drawn at ${sizes.charts.toFixed(1)} px or more`);
  check(sizes.stage >= 10, `the stage's labels at ${sizes.stage.toFixed(1)} px`);
  // Each label inside its chart.
  const outside = await page.evaluate(() => [...document.querySelectorAll("#curve text, #threshold text")].filter((t) => {
    const box = t.getBoundingClientRect();
    const frame = t.ownerSVGElement.getBoundingClientRect();
    return box.left < frame.left - 1 || box.right > frame.right + 1;
  }).map((t) => t.textContent));
  check(outside.length === 0, `every chart label inside its chart ${JSON.stringify(outside)}`);
  // The table stacked: a quantity's meaning under its value, not a column five lines tall.
  const table = await page.evaluate(() => {
    const rows = [...document.querySelectorAll("#values-body tr")];
    const line = parseFloat(getComputedStyle(document.body).lineHeight) || 23;
    return { rows: rows.length, tallest: Math.max(...rows.map((r) => r.lastElementChild.getBoundingClientRect().height)) / line, width: document.getElementById("values").getBoundingClientRect().width };
  });
  check(table.rows >= 7 && table.tallest <= 2.5 && table.width <= phone.width, `the table of values stacked: ${table.rows} rows, meanings at most ${table.tallest.toFixed(1)} lines`);
  await page.screenshot({ path: `${shots}/${name}-explore-phone.png`, fullPage: true });
});

await inBrowser("paper on a phone", paper, phone, async ({ page, check, name }) => {
  check((await sideways(page)) <= 0, `no sideways scroll at 390 px (${await sideways(page)} px too wide)`);
  // The wide tables scroll in their own boxes instead.
  const boxes = await page.evaluate(() => [...document.querySelectorAll(".wide")].map((b) => ({
    name: b.getAttribute("aria-label"),
    scrolls: b.scrollWidth > b.clientWidth,
    fits: b.getBoundingClientRect().right <= window.innerWidth,
  })));
  check(boxes.length === 6 && boxes.every((b) => b.fits), `the formulas and the 5 tables each in a box within the screen (${boxes.length})`);
  check(boxes.some((b) => b.scrolls), `a wide table scrolls in its box: ${boxes.filter((b) => b.scrolls).map((b) => b.name).join(", ")}`);
  // The formulas' case split in MathML, not ASCII (NEWCOMER m6).
  const meaning = await page.$eval("table.formulas tbody tr:last-child td:last-child", (td) => ({ text: td.textContent, maths: td.querySelectorAll("math").length }));
  check(meaning.maths === 2 && !meaning.text.includes("*m*"), `omega_max's case split in MathML (${meaning.maths} formulas): "${meaning.text.slice(0, 60)}…"`);
  await page.evaluate(() => document.getElementById("tables").scrollIntoView());
  await page.screenshot({ path: `${shots}/${name}-paper-phone-tables.png` });
});
