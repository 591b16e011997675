// How long the pages take to show their first answer on a phone-class CPU: Chromium with its
// CPU slowed 4x (DevTools' "mid-tier mobile"), each page opened afresh three times; prints the
// median and the range, and the pages' size. Reported, not asserted: a check must not depend
// on the time a machine takes (the CI's load varies).
// Usage: node startup.mjs PAGE.html...
import puppeteer from "puppeteer-core";
import { statSync } from "node:fs";
import { basename } from "node:path";
import { pathToFileURL } from "node:url";

const browser = await puppeteer.launch({ executablePath: process.env.BROWSER_PATH, headless: true, args: ["--no-sandbox", "--disable-gpu"] });
try {
  for (const file of process.argv.slice(2)) {
    const times = [];
    for (let i = 0; i < 3; i++) {
      const page = await browser.newPage();
      await page.emulateCPUThrottling(4);
      await page.goto(pathToFileURL(file).href, { waitUntil: "load" });
      await page.waitForFunction(() => document.documentElement.dataset.firstAnswerMs, { timeout: 120000 });
      times.push(Number(await page.evaluate(() => document.documentElement.dataset.firstAnswerMs)));
      await page.close();
    }
    times.sort((a, b) => a - b);
    const kb = (statSync(file).size / 1024).toFixed(0);
    console.log(`info ${basename(file)}: ${kb} KB; first answer at 4x CPU throttling: median ${times[1].toFixed(0)} ms (${times[0].toFixed(0)}-${times[2].toFixed(0)} ms over 3 loads)`);
  }
} finally {
  await browser.close();
}
