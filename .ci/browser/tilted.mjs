// The tilted-rod page of `rodimpact explore --scene tilted-rod` in a real browser, driven as a
// student would: the default scene (Newton's law creates energy, Poisson's and Stronge's do not),
// Routh's diagram, a sticking scene, a bad field, the link, the energy-gain map, and a phone.
// The exact values checked are `rodimpact impact`'s for examples/impacts/tilted-rod-rough-floor.toml
// and tilted-rod-sticks.toml (the same scenes: tan(theta/2) = 1/2, slip 1).
// Usage: node tilted.mjs PAGE.html SCREENSHOT_DIR
import { inBrowser } from "./common.mjs";

const [file, shots] = process.argv.slice(2);

/** The map drawn for the fields' mu and e (it is worked out a moment after they change). */
const mapReady = (page) => page.waitForFunction(() => {
  const caption = document.getElementById("map-caption").textContent;
  const mu = document.getElementById("mu").value.trim();
  const e = document.getElementById("e").value.trim();
  return document.querySelectorAll("#map rect.cell").length > 0 && caption.includes(`μ = ${mu}, e = ${e}`) && !caption.startsWith("Working");
}, { timeout: 120000 });

const type = async (page, id, value) => {
  await page.$eval(id, (e) => { e.value = ""; });
  await page.type(id, value);
};
const column = (page, law) => page.$eval(`#law-${law}`, (e) => e.textContent);

await inBrowser("tilted", file, { width: 1200, height: 1000 }, async ({ page, url, check, name }) => {
  const text = (sel) => page.$eval(sel, (e) => e.textContent);

  // The preset scene: tan(theta/2) = 1/2 (cos = 3/5, sin = 4/5), slip 1, mu = 1/3, e = 1.
  const fields = await page.evaluate(() => ["slip", "mu", "e"].map((id) => document.getElementById(id).value).concat(document.getElementById("angle").value));
  check(JSON.stringify(fields) === JSON.stringify(["1", "1/3", "1", "20"]), `the page opens on the preset scene: ${fields}`);
  check((await text("#angle-exact")).includes("cos θ = 3/5, sin θ = 4/5") && (await text("#angle-value")).includes("53.13"), `the angle shown exactly: "${await text("#angle-exact")}", ${await text("#angle-value")}`);

  // Newton's law creates energy, prominently and exactly; Poisson's and Stronge's do not.
  const newton = await column(page, "newton");
  check(newton.includes("creates energy: +197125/9435168"), `Newton's column: "creates energy: +197125/9435168" (${newton.slice(0, 90)}…)`);
  check(await page.$eval("#law-newton", (e) => e.classList.contains("gains")), "Newton's column is marked as creating energy");
  for (const law of ["poisson", "energetic"]) {
    const col = await column(page, law);
    check(!col.includes("creates energy") && !(await page.$eval(`#law-${law}`, (e) => e.classList.contains("gains"))), `${law}'s column does not create energy`);
  }
  check(newton.includes("725/724") && newton.includes("slides right until λ = 75/181, then left until λ = 725/724"), "Newton's end, λ = 725/724, and the slip's phases as a sentence");
  check((await column(page, "poisson")).includes("25/32") && (await column(page, "poisson")).includes("−87039275/603850752"), "Poisson's end λ = 25/32 and its loss −87039275/603850752");
  check((await column(page, "energetic")).includes("√20521"), "Stronge's end in Q(√20521)");
  check((await text("#summary")).startsWith("Newton's rule creates energy"), `the summary: "${(await text("#summary")).slice(0, 70)}…"`);

  // Routh's diagram: straight segments between the breakpoints, the phases, lam_c, each law's end.
  const routh = await page.evaluate(() => ({
    segments: document.querySelectorAll("#routh path.segment").length,
    phases: [...document.querySelectorAll("#routh rect.phase")].map((r) => r.getAttribute("class").replace("phase ", "")),
    lamC: document.querySelectorAll("#routh #lam-c-mark").length,
    ends: [...document.querySelectorAll("#routh text.end-label")].map((t) => t.textContent).sort(),
  }));
  check(routh.segments >= 4, `Routh's diagram has ${routh.segments} segments (u_n and u_t, two phases)`);
  check(JSON.stringify(routh.phases) === JSON.stringify(["slide-minus", "slide-plus"]), `its phases: ${routh.phases}`);
  check(routh.lamC === 1 && (await text("#routh")).includes("λc = 25/64"), "λc = 25/64 is marked");
  check(JSON.stringify(routh.ends) === JSON.stringify(["Newton", "Poisson", "Stronge"]), `each law's end is marked: ${routh.ends}`);
  check((await page.$$("#tau path.segment")).length >= 2, "the friction impulse τ against λ is drawn");
  check((await text("#toml")).includes("[[contact]]") && (await text("#file")).includes("rodimpact impact tilted.toml"), "scene.toml and the command to check it");
  check((await text("#scene-link")).endsWith("#tan_half=1/2&slip=1&mu=1/3&e=1"), `the scene's link: ${await text("#scene-link")}`);

  // The map: Newton's law gains energy somewhere at the defaults, and the scene is marked.
  await mapReady(page);
  const gains = await page.$$eval("#map rect.cell.gain", (r) => r.length);
  check(gains >= 1 && (await page.$$("#map .here-mark")).length === 1, `the map has ${gains} Newton-gain cells and marks the scene`);
  await page.screenshot({ path: `${shots}/${name}-tilted-default.png`, fullPage: true });
  for (const law of ["poisson", "energetic"]) {
    await page.click(`input[name=map-law][value=${law}]`);
    const cells = await page.$$eval("#map rect.cell.gain", (r) => r.length);
    const caption = await text("#map-caption");
    check(cells > 0 || caption.includes("in none of these"), `${law} on the map: ${cells} gain cells; "${caption}"`);
  }
  await page.click("input[name=map-law][value=newton]");

  // A rougher floor, less bounce: mu = 1/2 >= |W_nt|/W_tt = 36/73, the stopped end sticks.
  await type(page, "#mu", "1/2");
  await type(page, "#e", "1/2");
  const stick = await column(page, "newton");
  check(stick.includes("slides right until λ = 10/29, then sticks until λ = 147/200") && stick.includes("−139/800"), `mu = e = 1/2: Newton's end sticks, λ = 147/200, loses 139/800 (${stick.slice(0, 80)}…)`);
  check((await page.$$("#routh rect.phase.stick")).length === 1, "Routh's diagram shows the sticking phase");
  check(!(await column(page, "newton")).includes("creates energy") && (await text("#summary")).startsWith("No rule creates energy"), "no law creates energy at mu = e = 1/2");
  await mapReady(page);
  await page.evaluate(() => document.getElementById("routh-section").scrollIntoView());
  await page.screenshot({ path: `${shots}/${name}-tilted-sticks.png` });

  // A bad mu: its reason under the field, and no result of the last scene left standing.
  await type(page, "#mu", "-1");
  const error = await text("#mu-error");
  check(error.length > 0 && (await page.$eval("#mu", (e) => e.getAttribute("aria-invalid"))) === "true", `mu = -1 is refused: "${error}"`);
  const stale = await page.evaluate(() => [
    ...["newton", "poisson", "energetic"].map((l) => document.querySelector(`#law-${l} .law-body`).childElementCount),
    document.getElementById("routh").childElementCount, document.getElementById("tau").childElementCount, document.getElementById("toml").textContent.length,
  ]);
  check(stale.every((n) => n === 0) && (await text("#summary")).startsWith("Correct the highlighted field"), `while mu is wrong nothing of the last scene is shown (${stale})`);
  await page.waitForFunction(() => document.getElementById("map-caption").textContent.startsWith("No map"), { timeout: 30000 });
  check((await page.$$("#map rect.cell")).length === 0, "nor the last map");
  await page.screenshot({ path: `${shots}/${name}-tilted-bad-mu.png`, fullPage: true });
  await type(page, "#mu", "1/3");
  check((await text("#mu-error")) === "" && (await column(page, "newton")).length > 0, "a good mu again: the error goes, the answers come back");

  // The angle slider by keyboard: tan(theta/2) = 21/40.
  await type(page, "#e", "1");
  await page.focus("#angle");
  await page.keyboard.press("ArrowRight");
  check((await text("#angle-exact")).startsWith("tan(θ/2) = 21/40: cos θ = 1159/2041, sin θ = 1680/2041"), `ArrowRight on the angle: "${await text("#angle-exact")}"`);

  // A link opens the page on a scene (and the hash changing moves it).
  await page.goto(`${url.split("#")[0]}#tan_half=1/2&slip=1&mu=1/2&e=1/2`, { waitUntil: "load" });
  check((await column(page, "poisson")).includes("111/200"), "the link #tan_half=1/2&slip=1&mu=1/2&e=1/2 opens the sticking scene (Poisson at λ = 111/200)");
  await page.evaluate(() => { location.hash = "tan_half=1/2&slip=1&mu=1/3&e=1&colour=red"; });
  await page.waitForFunction(() => document.getElementById("mu").value === "1/3");
  check((await column(page, "newton")).includes("creates energy") && (await text("#link-error")).includes("colour"), `a new hash moves the page; its unknown key is named: "${await text("#link-error")}"`);
});

await inBrowser("tilted on a phone", file, { width: 390, height: 844 }, async ({ page, check, name }) => {
  await mapReady(page);
  const sideways = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  check(sideways <= 0, `no sideways scroll at 390 px (${sideways} px too wide)`);
  // Every chart label drawn at 11 px or more, inside its chart.
  const labels = await page.evaluate(() => [...document.querySelectorAll("#sketch text, #routh text, #tau text, #map text")].map((t) => {
    const svg = t.ownerSVGElement;
    const box = t.getBoundingClientRect();
    const frame = svg.getBoundingClientRect();
    return {
      text: t.textContent,
      px: parseFloat(getComputedStyle(t).fontSize) * (frame.width / svg.viewBox.baseVal.width),
      outside: box.left < frame.left - 1 || box.right > frame.right + 1,
    };
  }));
  const least = Math.min(...labels.map((l) => l.px));
  check(labels.length > 30 && least >= 10.95, `the charts' ${labels.length} labels are drawn at ${least.toFixed(1)} px or more`);
  const outside = labels.filter((l) => l.outside).map((l) => l.text);
  check(outside.length === 0, `every chart label inside its chart ${JSON.stringify(outside)}`);
  const small = await page.evaluate(() => [...document.querySelectorAll("main *")].filter((e) => e.childNodes.length && [...e.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim()) && !(e instanceof SVGElement) && parseFloat(getComputedStyle(e).fontSize) < 11).map((e) => e.tagName + ":" + e.textContent.slice(0, 20)));
  check(small.length === 0, `no text under 11 px ${JSON.stringify(small.slice(0, 5))}`);
  await page.screenshot({ path: `${shots}/${name}-tilted-phone.png`, fullPage: true });
});
