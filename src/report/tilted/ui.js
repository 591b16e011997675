"use strict";
// The tilted-rod page: reads the controls, asks rodimpact (`api`, built into the page) for the
// scene's exact answers, and shows and draws them. No physics and no arithmetic on physical
// quantities here: every number shown is one of the API's (its `pretty` and `approx` strings),
// and the charts map the API's `f64` values to pixels.

const $ = (id) => document.getElementById(id);
const LAWS = ["newton", "poisson", "energetic"];
const NAMES = { newton: "Newton", poisson: "Poisson", energetic: "Stronge" };
const FIELDS = ["tan_half", "slip", "mu", "e"];

// ---- the controls -------------------------------------------------------------------------
// The sliders step through simple exact values (their text is what the API is sent).
const gcd = (a, b) => (b ? gcd(b, a % b) : Math.abs(a));
/** The fraction n/d in lowest terms, as typed ("-9/10", "1/2", "2"). */
const fraction = (n, d) => {
  const g = gcd(n, d) || 1;
  return d / g === 1 ? `${n / g}` : `${n / g}/${d / g}`;
};
const MU_STOPS = ["0", "1/20", "1/10", "1/8", "1/6", "1/5", "1/4", "3/10", "1/3", "2/5", "1/2", "3/5", "2/3", "3/4", "4/5", "1", "6/5", "3/2", "2"];
const E_STOPS = ["0", "1/10", "1/5", "1/4", "3/10", "1/3", "2/5", "1/2", "3/5", "2/3", "7/10", "3/4", "4/5", "9/10", "1"];
const tanHalfOf = (k) => fraction(k, 40);
const slipOf = (i) => fraction(i, 10);
// The map's grid: the angle slider's 39 tilts across, 21 slips from -2 to 2 down.
const MAP_TAN_HALVES = Array.from({ length: 39 }, (_, i) => `${i + 1}/40`);
const MAP_SLIPS = ["-2", "-9/5", "-8/5", "-7/5", "-6/5", "-1", "-4/5", "-3/5", "-2/5", "-1/5", "0",
  "1/5", "2/5", "3/5", "4/5", "1", "6/5", "7/5", "8/5", "9/5", "2"];

/**
 * The number typed (a decimal or a fraction) as a float, read by the library, only to place its
 * slider or a mark on a chart: never shown, never computed with. NaN when it is not a number.
 */
function roughly(text) {
  const answer = api.call("number", { text: String(text) });
  return answer.value ? answer.value.f64 : NaN;
}
/** The stop of `stops` (exact strings) nearest the text typed: itself when it is one. */
function nearestStop(stops, text) {
  const at = stops.indexOf(text.trim());
  if (at >= 0) return at;
  const x = roughly(text);
  if (Number.isNaN(x)) return -1;
  let best = 0;
  stops.forEach((s, i) => { if (Math.abs(roughly(s) - x) < Math.abs(roughly(stops[best]) - x)) best = i; });
  return best;
}

// The angle: tan(theta/2) as the slider's k/40, or as a link gave it.
let tanHalf = "1/2";
const controls = {
  slip: { stops: Array.from({ length: 41 }, (_, i) => slipOf(i - 20)), offset: -20, name: "slip" },
  mu: { stops: MU_STOPS, offset: 0, name: "μ" },
  e: { stops: E_STOPS, offset: 0, name: "e" },
};
/** Puts the slider of field `id` at the stop nearest its text (left alone when unreadable). */
function follow(id) {
  const c = controls[id];
  const at = nearestStop(c.stops, $(id).value);
  if (at >= 0) $(`${id}-slider`).value = at + c.offset;
  $(`${id}-slider`).setAttribute("aria-valuetext", `${c.name} = ${$(id).value.trim()}`);
}
for (const id of Object.keys(controls)) {
  const c = controls[id];
  $(`${id}-slider`).addEventListener("input", () => {
    $(id).value = c.stops[Number($(`${id}-slider`).value) - c.offset];
    follow(id);
    update();
  });
  $(id).addEventListener("input", () => {
    follow(id);
    update();
  });
}
function followAngle() {
  const x = roughly(tanHalf);
  if (!Number.isNaN(x)) $("angle").value = Math.min(39, Math.max(1, Math.round(x * 40)));
}
$("angle").addEventListener("input", () => {
  tanHalf = tanHalfOf(Number($("angle").value));
  update();
});

/** The request of the controls, as typed. */
const request = () => ({ tan_half: tanHalf, slip: $("slip").value.trim(), mu: $("mu").value.trim(), e: $("e").value.trim() });

/** The API's answer; a failure of the call itself becomes an error without a field. */
function call(name, req) {
  try {
    return api.call(name, req);
  } catch (e) {
    return { error: { field: null, message: `rodimpact could not answer: ${e && e.message ? e.message : e}` } };
  }
}

// ---- a link that opens the page on a scene (tilted.html#tan_half=1/2&slip=1&mu=1/3&e=1) ------
function applyLink(text) {
  const { parts, wrong } = linkParts(text);
  for (const [key, value, given] of parts) {
    if (key === "tan_half" && given) {
      tanHalf = value.trim();
      followAngle();
    } else if (given && key in controls) {
      $(key).value = value;
      follow(key);
    } else wrong.push(key);
  }
  $("link-error").textContent = wrong.length
    ? `The link's ${wrong.join(", ")} is not understood: it takes tan_half, slip, mu and e (exact numbers such as 1/2 or 0.75).`
    : "";
  $("link-error").hidden = !wrong.length;
}
function sceneLink() {
  const value = (text) => encodeURIComponent(text.trim()).replace(/%2F/g, "/");
  const r = request();
  return FIELDS.map((k) => `${k}=${value(r[k])}`).join("&");
}
window.addEventListener("hashchange", () => {
  applyLink(location.hash.slice(1));
  update();
});

// ---- showing exact values -----------------------------------------------------------------
const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
const whole = (x) => /^[−-]?\d+$/.test(x.pretty);
/** An exact value for people: its pretty form, and its decimal unless it is a whole number. */
const exact = (x) => `<span class="exact">${esc(x.pretty)}</span>${whole(x) ? "" : ` <span class="approx">≈ ${esc(x.approx)}</span>`}`;
/** The same as plain text (captions, aria labels). */
const plain = (x) => `${x.pretty}${whole(x) ? "" : ` ≈ ${x.approx}`}`;
const positive = (x) => (x.pretty.startsWith("−") || x.pretty.startsWith("-") ? x.pretty : `+${x.pretty}`);

// The floor's tangent t is (−1, 0) (the API's scene.tangent): a slip u_t < 0 moves the end to
// the right (+x, the side the rod leans to), u_t > 0 to the left.
const MODE = {
  "slide-": { long: "slides right", short: "right", cls: "slide-minus", label: "slides right (u_t < 0)" },
  "slide+": { long: "slides left", short: "left", cls: "slide-plus", label: "slides left (u_t > 0)" },
  stick: { long: "sticks", short: "sticks", cls: "stick", label: "sticks (u_t = 0)" },
};
const mode = (m) => MODE[m] || { long: m, short: m, cls: "other", label: m };

/** The phases as a sentence: "slides right until λ = 75/181, then left until λ = 725/724". */
function phaseSentence(phases) {
  if (!phases.length) return "";
  const words = phases.map((p, i) => {
    const prev = i > 0 ? phases[i - 1].mode : null;
    const slideAfterSlide = prev && prev.startsWith("slide") && p.mode.startsWith("slide");
    const verb = slideAfterSlide ? mode(p.mode).short : mode(p.mode).long;
    return `${i > 0 ? "then " : ""}${verb} until λ = ${p.to.pretty}`;
  });
  const text = words.join(", ");
  return `The end ${text}.`;
}

/** The energy change as a share of the energy before, in per cent (for reading only). */
function percent(law, before) {
  if (law.energy_percent) return `${law.energy_percent.approx} %`;
  const share = (law.energy_change.f64 / before.f64) * 100;
  const text = Math.abs(share) < 0.005 ? share.toExponential(1) : share.toFixed(2);
  return `${share > 0 ? "+" : ""}${text.replace("-", "−")} %`;
}

// ---- the answer ---------------------------------------------------------------------------
let current = null;

function showErrors(error) {
  for (const f of FIELDS) {
    const message = error && error.field === f ? error.message : "";
    $(`${f}-error`).textContent = message;
    const input = f === "tan_half" ? $("angle") : $(f);
    input.setAttribute("aria-invalid", message ? "true" : "false");
  }
}

/** No scene (a field to correct): the last scene's answers are cleared, not left standing. */
function clearAnswer(message) {
  current = null;
  $("summary").textContent = message;
  $("summary").classList.remove("gains");
  for (const law of LAWS) {
    $(`law-${law}`).classList.remove("gains");
    $(`law-${law}`).querySelector(".law-body").replaceChildren();
  }
  for (const id of ["routh", "tau", "sketch", "routh-caption", "tau-caption", "sketch-caption", "scene-facts", "toml", "angle-exact"]) $(id).replaceChildren();
  $("angle-value").value = "";
  drawHere();
}

function update() {
  const req = request();
  scheduleMap(req);
  // The link holds the fields as typed, right or wrong (to be corrected after opening it).
  const file = decodeURIComponent(location.pathname.split("/").pop() || "") || "tilted.html";
  const link = sceneLink();
  $("scene-link").href = `#${link}`;
  $("scene-link").textContent = `${file}#${link}`;
  const res = call("tilted", req);
  showErrors(res.error);
  if (res.error) {
    const field = res.error.field ? "" : ` ${res.error.message}`;
    clearAnswer(`Correct the highlighted field to see the answer.${field}`);
    return;
  }
  current = { req, res };
  const s = res.scene;
  $("angle-value").value = `θ ≈ ${s.degrees.toFixed(2)}°`;
  $("angle-exact").textContent = `tan(θ/2) = ${tanHalf.replace("-", "−")}: cos θ = ${s.cos.pretty}, sin θ = ${s.sin.pretty}`;
  $("angle").setAttribute("aria-valuetext", `tan(θ/2) = ${tanHalf}, θ ≈ ${s.degrees.toFixed(1)} degrees`);
  $("scene-facts").innerHTML = `Before the impact the end meets the floor at <i>u</i><sub>n</sub> = ${exact(s.u0[0])}
    and slips at <i>u</i><sub>t</sub> = ${exact(s.u0[1])} (along the floor's tangent <i>t</i>); kinetic energy ${exact(s.energy_before)}.
    The contact's matrix <i>W</i> = [${s.W.nn.pretty}, ${s.W.nt.pretty}; ${s.W.nt.pretty}, ${s.W.tt.pretty}]
    couples the directions when <i>W</i><sub>nt</sub> ≠ 0. Once the slip stops the end sticks if
    <i>μ</i> ≥ |<i>W</i><sub>nt</sub>|/<i>W</i><sub>tt</sub> = ${exact(s.mu_stick)}; with less friction it slides back.`;
  $("toml").textContent = s.toml;
  showLaws(res);
  draw();
}

function showLaws(res) {
  const before = res.scene.energy_before;
  const gainers = [];
  const losers = [];
  for (const law of LAWS) {
    const L = res.laws.find((l) => l.law === law);
    const box = $(`law-${law}`);
    const body = box.querySelector(".law-body");
    box.querySelector("h3").textContent = L ? L.name : NAMES[law];
    if (!L || L.error) {
      box.classList.remove("gains");
      body.innerHTML = `<p class="error">${esc(L ? L.error : "no answer")}</p>`;
      continue;
    }
    const gain = L.energy_gain === true;
    (gain ? gainers : losers).push(L.name);
    box.classList.toggle("gains", gain);
    const badge = gain
      ? `<strong class="badge gain" role="status">creates energy: ${esc(positive(L.energy_change))} <span class="share">(${esc(percent(L, before))} of the energy before)</span></strong>`
      : `<span class="badge loss">${/^[−-]/.test(L.energy_change.pretty) ? "loses energy" : "keeps its energy exactly"}</span>`;
    const work = L.work;
    body.innerHTML = `<p class="kind">${esc(L.kind)}</p>${badge}
      <dl>
        <dt>impact ends at</dt><dd><i>λ</i> = ${exact(L.lam)}<br><i>τ</i> = ${exact(L.tau)}</dd>
        <dt>the slip</dt><dd class="phases">${esc(phaseSentence(L.phases))}</dd>
        <dt>end after</dt><dd><i>u</i><sub>n</sub> = ${exact(L.u_after[0])}<br><i>u</i><sub>t</sub> = ${exact(L.u_after[1])}</dd>
        <dt>rod after</dt><dd><i>v</i><sub>x</sub> = ${exact(L.rod.vx)}<br><i>v</i><sub>y</sub> = ${exact(L.rod.vy)}<br><i>ω</i> = ${exact(L.rod.omega)}</dd>
        <dt>energy</dt><dd>${exact(before)} → ${exact(L.energy_after)}</dd>
        <dt>change</dt><dd class="change">${exact(L.energy_change)}<br><span class="share">${esc(percent(L, before))} of the energy before</span></dd>
      </dl>
      <table><caption>Work done on the rod</caption><tbody>
        <tr><th scope="row">normal push, compression</th><td>${exact(work.compression)}</td></tr>
        <tr><th scope="row">normal push, restitution</th><td>${exact(work.restitution)}</td></tr>
        <tr><th scope="row">friction</th><td>${exact(work.friction)}</td></tr>
      </tbody></table>`;
  }
  const list = (names) => names.map((n) => `${n}'s`).join(names.length > 2 ? ", " : " and ").replace(/, ([^,]*)$/, " and $1");
  let summary;
  if (gainers.length) {
    summary = `${list(gainers)} ${gainers.length > 1 ? "rules create" : "rule creates"} energy in this scene: the rod leaves with more kinetic energy than it came with.`;
    if (losers.length) summary += ` ${list(losers)} ${losers.length > 1 ? "do" : "does"} not.`;
  } else {
    summary = "No rule creates energy in this scene.";
  }
  const ends = LAWS.map((law) => res.laws.find((l) => l.law === law)).filter((L) => L && !L.error).map((L) => L.lam.text);
  if (ends.length === 3 && ends.every((t) => t === ends[0])) summary += " All three rules end the impact at the same λ here.";
  $("summary").textContent = summary;
  $("summary").classList.toggle("gains", gainers.length > 0);
}

// ---- drawing ------------------------------------------------------------------------------
// SVG elements and label sizes: the pages' shared helpers (svgElement, textScale, LEAST_TEXT).
const el = svgElement;
/**
 * Sizes a chart's drawing to the width it is shown at: `wide` [width, height] in units, or on a
 * narrow screen (a phone) `narrow`, taller for its width, so that its labels need less enlarging.
 * Returns the size chosen.
 */
/** The width a chart is shown at: its figure's (an empty chart is not laid out). */
const shownWidth = (svg) => svg.parentElement.getBoundingClientRect().width;
function fit(svg, wide, narrow) {
  const shown = shownWidth(svg);
  const [w, h] = shown > 0 && shown < 560 ? narrow : wide;
  svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
  return [w, h];
}
/** The label scale of an SVG chart as drawn now (also set as its --text for the CSS). */
function scaleOf(svg) {
  const k = textScale(12, svg.viewBox.baseVal.width, shownWidth(svg));
  svg.style.setProperty("--text", k.toFixed(3));
  return k;
}
/** Round tick positions covering [lo, hi] (for the axes' labels only). */
function ticks(lo, hi, count) {
  const raw = (hi - lo) / count;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw);
  const out = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi + 1e-9; t += step) out.push(Math.abs(t) < 1e-12 ? 0 : t);
  return out;
}
const tickText = (t) => (Math.round(t * 1000) / 1000).toString().replace("-", "−");

/** A chart's frame, grid and labels; returns the pixel maps X, Y and the frame. */
function axes(svg, k, box, xs, ys, xlabel, ylabel, xticks, yticks) {
  const left = box[0] + 22 * (k - 1);
  const bottom = box[3] - 18 * (k - 1);
  const [x0, y0, w, h] = [left, box[1], box[2] - (left - box[0]), bottom];
  const X = (x) => x0 + ((x - xs[0]) / (xs[1] - xs[0])) * w;
  const Y = (y) => y0 + h - ((y - ys[0]) / (ys[1] - ys[0])) * h;
  const grid = el("g", {});
  const labels = el("g", {});
  for (const t of xticks) {
    grid.append(el("line", { x1: X(t), x2: X(t), y1: y0, y2: y0 + h, class: "grid" }));
    labels.append(el("text", { x: X(t), y: y0 + h + 4 + 12 * k, class: "tick", "text-anchor": "middle" }, typeof t === "number" ? tickText(t) : t));
  }
  for (const t of yticks) {
    grid.append(el("line", { x1: x0, x2: x0 + w, y1: Y(t), y2: Y(t), class: "grid" }));
    labels.append(el("text", { x: x0 - 6, y: Y(t) + 4 * k, class: "tick", "text-anchor": "end" }, tickText(t)));
  }
  labels.append(el("text", { x: x0 + w / 2, y: y0 + h + 8 + 26 * k, class: "label", "text-anchor": "middle" }, xlabel));
  const yl = 2 + 13 * k;
  labels.append(el("text", { x: yl, y: y0 + h / 2, class: "label", "text-anchor": "middle", transform: `rotate(-90 ${yl} ${y0 + h / 2})` }, ylabel));
  return { X, Y, x0, y0, w, h, grid, labels, frame: el("rect", { x: x0, y: y0, width: w, height: h, class: "frame" }) };
}

function draw() {
  if (!current) return;
  drawSketch();
  drawRouth();
  drawTau();
  drawHere();
}

/** The rod at its angle over the floor, the centre's velocity before (drawn from the typed slip). */
function drawSketch() {
  const svg = $("sketch");
  svg.replaceChildren();
  const s = current.res.scene;
  const k = scaleOf(svg);
  const floor = 175;
  const foot = 70;
  const scale = 85; // px per unit length; the rod is 2 long
  const c = s.cos.f64;
  const sn = s.sin.f64;
  svg.append(el("line", { x1: 10, x2: 310, y1: floor, y2: floor, class: "floor" }));
  for (let x = 14; x < 310; x += 14) svg.append(el("line", { x1: x, x2: x - 8, y1: floor + 2, y2: floor + 10, class: "hatch" }));
  const top = [foot + 2 * scale * c, floor - 2 * scale * sn];
  svg.append(el("line", { x1: foot, y1: floor, x2: top[0], y2: top[1], class: "rod" }));
  const r = 32;
  svg.append(el("path", { d: `M${foot + r},${floor} A${r},${r} 0 0 0 ${foot + r * c},${floor - r * sn}`, class: "angle-arc" }));
  svg.append(el("text", { x: foot + r + 6, y: floor - 8, class: "note" }, `θ ≈ ${s.degrees.toFixed(1)}°`));
  const mid = [foot + scale * c, floor - scale * sn];
  svg.append(el("circle", { cx: mid[0], cy: mid[1], r: 4, fill: "#000" }));
  const slip = roughly(current.req.slip);
  if (!Number.isNaN(slip)) {
    const arrow = 40;
    const end = [mid[0] + arrow * Math.max(-3, Math.min(3, slip)), mid[1] + arrow];
    const len = Math.hypot(end[0] - mid[0], end[1] - mid[1]);
    const ux = (end[0] - mid[0]) / len;
    const uy = (end[1] - mid[1]) / len;
    svg.append(el("line", { x1: mid[0], y1: mid[1], x2: end[0] - 8 * ux, y2: end[1] - 8 * uy, class: "arrow" }));
    svg.append(el("path", { d: `M${end[0]},${end[1]} L${end[0] - 11 * ux - 5 * uy},${end[1] - 11 * uy + 5 * ux} L${end[0] - 11 * ux + 5 * uy},${end[1] - 11 * uy - 5 * ux} Z`, class: "arrow-head" }));
    const right = end[0] >= mid[0];
    svg.append(el("text", { x: end[0] + (right ? 6 : -6), y: end[1] + 4 * k, class: "note", "text-anchor": right ? "start" : "end" }, `v = (${current.req.slip.replace("-", "−")}, −1)`));
  }
  $("sketch-caption").textContent = `The rod (length 2, mass 1) just before its lower end meets the floor, at θ ≈ ${s.degrees.toFixed(2)}° (cos θ = ${s.cos.pretty}); its centre moves at (${current.req.slip}, −1), not spinning.`;
}

/** A vertical mark for each law's end, labelled with its name (staggered when close). */
function lawEnds(svg, k, a, laws, dots) {
  const ends = laws.filter((L) => !L.error).sort((p, q) => p.lam.f64 - q.lam.f64);
  let lastX = -Infinity;
  let row = 0;
  for (const L of ends) {
    const x = a.X(L.lam.f64);
    row = x - lastX < 70 * k ? row + 1 : 0;
    lastX = x;
    svg.append(el("line", { x1: x, x2: x, y1: a.y0, y2: a.y0 + a.h, class: `end-mark ${L.law}` }));
    // Left of its line when the name (about 7.5 units a letter) would pass the frame's right edge.
    const nearRight = x + 4 + 7.5 * k * L.name.length > a.x0 + a.w;
    const label = el("text", { x: x + (nearRight ? -4 : 4), y: a.y0 + 14 * k + row * 15 * k, class: `note end-label ${L.law}`, "text-anchor": nearRight ? "end" : "start" }, L.name);
    svg.append(label);
    for (const [y, what] of dots(L)) {
      const dot = el("circle", { cx: x, cy: a.Y(y.f64), r: 5, class: `end-dot ${L.law}` });
      dot.append(el("title", {}, `${L.name}: ${what} = ${plain(y)} at λ = ${plain(L.lam)}`));
      svg.append(dot);
    }
  }
}

/** The phases shaded along λ between the path's breakpoints. */
function shadePhases(svg, a, path) {
  for (let i = 0; i + 1 < path.length; i++) {
    const x1 = a.X(path[i].lam.f64);
    const x2 = a.X(path[i + 1].lam.f64);
    const rect = el("rect", { x: x1, y: a.y0, width: Math.max(0, x2 - x1), height: a.h, class: `phase ${mode(path[i].mode).cls}` });
    rect.append(el("title", {}, `${mode(path[i].mode).label} from λ = ${path[i].lam.pretty} to ${path[i + 1].lam.pretty}`));
    svg.append(rect);
  }
}

/** Straight segments between the path's breakpoints of the quantity `key`. */
function segments(svg, a, path, key, cls) {
  for (let i = 0; i + 1 < path.length; i++) {
    const p = path[i];
    const q = path[i + 1];
    svg.append(el("path", { d: `M${a.X(p.lam.f64).toFixed(1)},${a.Y(p[key].f64).toFixed(1)} L${a.X(q.lam.f64).toFixed(1)},${a.Y(q[key].f64).toFixed(1)}`, class: `segment ${cls}` }));
  }
  for (const p of path) svg.append(el("circle", { cx: a.X(p.lam.f64), cy: a.Y(p[key].f64), r: 3, class: "breakpoint" }));
}

function lamRange(res) {
  const last = Math.max(...res.path.map((p) => p.lam.f64));
  return [0, last > 0 ? last * 1.04 : 1];
}
function valueRange(values) {
  let lo = Math.min(0, ...values);
  let hi = Math.max(0, ...values);
  if (hi - lo < 1e-9) hi = lo + 1;
  const pad = (hi - lo) * 0.12;
  return [lo - pad, hi + pad];
}

function drawRouth() {
  const svg = $("routh");
  svg.replaceChildren();
  const { res } = current;
  const path = res.path;
  const [W, H] = fit(svg, [640, 360], [420, 340]);
  const k = scaleOf(svg);
  const xs = lamRange(res);
  const ys = valueRange(path.flatMap((p) => [p.u_n.f64, p.u_t.f64]));
  const a = axes(svg, k, [58, 12, W - 74, H - 70], xs, ys, "normal impulse λ", "velocity of the end", ticks(xs[0], xs[1], 6), ticks(ys[0], ys[1], 6));
  shadePhases(svg, a, path);
  svg.append(a.grid);
  svg.append(el("line", { x1: a.x0, x2: a.x0 + a.w, y1: a.Y(0), y2: a.Y(0), class: "zero" }));
  // The end of compression, where u_n reaches 0.
  const xc = a.X(res.lam_c.f64);
  svg.append(el("line", { x1: xc, x2: xc, y1: a.y0, y2: a.y0 + a.h, class: "lam-c", id: "lam-c-mark" }));
  svg.append(el("text", { x: xc - 4, y: a.y0 + a.h - 8, class: "note", "text-anchor": "end" }, `λc = ${res.lam_c.pretty}`));
  segments(svg, a, path, "u_n", "un");
  segments(svg, a, path, "u_t", "ut");
  // The lines' names along the last segment, the upper one above its line, the lower below.
  const [p, q] = path.length > 1 ? path.slice(-2) : [path[0], path[0]];
  const along = (key) => [a.X(p.lam.f64 + 0.35 * (q.lam.f64 - p.lam.f64)), a.Y(p[key].f64 + 0.35 * (q[key].f64 - p[key].f64))];
  const [xn, yn] = along("u_n");
  const [xt, yt] = along("u_t");
  const unAbove = yn <= yt;
  svg.append(el("text", { x: xn, y: unAbove ? yn - 8 : yn + 16 * k, class: "note line-label un", "text-anchor": "middle" }, "u_n"));
  svg.append(el("text", { x: xt, y: unAbove ? yt + 16 * k : yt - 8, class: "note line-label ut", "text-anchor": "middle" }, "u_t"));
  lawEnds(svg, k, a, res.laws, (L) => [[L.u_after[0], "u_n"], [L.u_after[1], "u_t"]]);
  svg.append(a.frame);
  svg.append(a.labels);
  const phases = path.slice(0, -1).map((p, i) => `${mode(p.mode).label} to λ = ${path[i + 1].lam.pretty}`).join(", then ");
  const ends = res.laws.filter((L) => !L.error).map((L) => `${L.name} at λ = ${plain(L.lam)}`).join("; ");
  $("routh-caption").textContent = `The end's normal velocity u_n (solid) and slip u_t (dashed) against the normal impulse λ, straight between the breakpoints: the end ${phases}. Compression ends at λc = ${plain(res.lam_c)}. The rules end the impact at: ${ends}.`;
}

function drawTau() {
  const svg = $("tau");
  svg.replaceChildren();
  const { res } = current;
  const path = res.path;
  const [W, H] = fit(svg, [640, 260], [420, 240]);
  const k = scaleOf(svg);
  const xs = lamRange(res);
  const ys = valueRange(path.map((p) => p.tau.f64).concat(res.laws.filter((L) => !L.error).map((L) => L.tau.f64)));
  const a = axes(svg, k, [58, 10, W - 74, H - 70], xs, ys, "normal impulse λ", "friction τ", ticks(xs[0], xs[1], 6), ticks(ys[0], ys[1], 4));
  shadePhases(svg, a, path);
  svg.append(a.grid);
  svg.append(el("line", { x1: a.x0, x2: a.x0 + a.w, y1: a.Y(0), y2: a.Y(0), class: "zero" }));
  segments(svg, a, path, "tau", "tau");
  lawEnds(svg, k, a, res.laws, (L) => [[L.tau, "τ"]]);
  svg.append(a.frame);
  svg.append(a.labels);
  $("tau-caption").textContent = "The friction impulse τ along the same path: while the end slides, τ runs along the edge of Coulomb's cone, ±μλ (its slope is ±μ); while it sticks, τ stays inside the cone. The dots are each rule's end.";
}

// ---- the map -------------------------------------------------------------------------------
let map = null; // { key, mu, e, data } of the last map drawn
let mapTimer = null;
let mapKey = null;
const mapLaw = () => document.querySelector("input[name=map-law]:checked").value;
// The tilts of a few columns in degrees, from the map's answer (its tick labels).
const TICK_COLUMNS = [8, 16, 24, 32];

function scheduleMap(req) {
  const key = `${req.mu}|${req.e}`;
  if (key === mapKey) return;
  mapKey = key;
  clearTimeout(mapTimer);
  $("map-caption").classList.remove("none", "error");
  $("map-caption").textContent = `Working out the map at μ = ${req.mu}, e = ${req.e}…`;
  $("map").setAttribute("aria-busy", "true");
  mapTimer = setTimeout(() => computeMap(req.mu, req.e, key), map ? 300 : 0);
}

/**
 * The map, a row (one slip) per call and a pause between rows, so that the page answers the
 * controls while it works; abandoned when mu or e change meanwhile.
 */
function computeMap(mu, e, key, rows = 0, data = { newton: [], poisson: [], energetic: [], degrees: [] }) {
  if (key !== mapKey) return;
  const row = call("tilted_map", { mu, e, tan_halves: MAP_TAN_HALVES, slips: [MAP_SLIPS[rows]] });
  if (!row.error) {
    for (const law of ["newton", "poisson", "energetic"]) data[law].push(row[law][0]);
    data.degrees = row.degrees;
    if (rows + 1 < MAP_SLIPS.length) {
      $("map-caption").textContent = `Working out the map at μ = ${mu}, e = ${e}… (${rows + 1} of ${MAP_SLIPS.length} rows)`;
      mapTimer = setTimeout(() => computeMap(mu, e, key, rows + 1, data), 0);
      return;
    }
  } else {
    data = row;
  }
  $("map").setAttribute("aria-busy", "false");
  if (data.error) {
    map = null;
    $("map").replaceChildren();
    $("map-caption").textContent = `No map: ${data.error.message}`;
    $("map-caption").classList.add("error");
    return;
  }
  map = { mu, e, data };
  $("map-caption").classList.remove("error");
  drawMap();
}

function drawMap() {
  const svg = $("map");
  svg.replaceChildren();
  if (!map) return;
  const law = mapLaw();
  const grid = map.data[law];
  const [W, H] = fit(svg, [640, 362], [420, 330]);
  const k = scaleOf(svg);
  // Cell k (tan(θ/2) = k/40) spans k ± 1/2 across; slip s spans s ± 1/10 down.
  const a = axes(svg, k, [58, 10, W - 74, H - 62], [0.5 / 40, 39.5 / 40], [-2.1, 2.1], "tilt θ of the rod (tan(θ/2) = k/40)", "slip", [], [-2, -1, 0, 1, 2]);
  const cells = el("g", { id: "map-cells" });
  let gains = 0;
  let jams = 0;
  const cw = a.w / 39;
  const ch = a.h / 21;
  grid.forEach((row, i) => row.forEach((v, j) => {
    const cls = v === true ? "gain" : v === null ? "jam" : "loss";
    if (v === true) gains++;
    if (v === null) jams++;
    const rect = el("rect", { x: a.X((j + 1) / 40) - cw / 2, y: a.Y(roughly(MAP_SLIPS[i])) - ch / 2, width: cw, height: ch, class: `cell ${cls}` });
    rect.append(el("title", {}, `tan(θ/2) = ${MAP_TAN_HALVES[j]}, slip ${MAP_SLIPS[i]}: ${cls === "gain" ? "creates energy" : cls === "jam" ? "no answer" : "no energy created"}`));
    cells.append(rect);
  }));
  svg.append(cells);
  svg.append(a.frame);
  svg.append(a.labels);
  for (const kk of TICK_COLUMNS) {
    svg.append(el("text", { x: a.X(kk / 40), y: a.y0 + a.h + 4 + 12 * k, class: "tick", "text-anchor": "middle" }, `${Math.round(map.data.degrees[kk - 1])}°`));
  }
  svg.append(el("g", { id: "map-here" }));
  const total = MAP_TAN_HALVES.length * MAP_SLIPS.length;
  const name = NAMES[law];
  const at = `at μ = ${map.mu}, e = ${map.e}`;
  const caption = $("map-caption");
  caption.classList.toggle("none", gains === 0);
  caption.textContent = gains
    ? `${name}'s rule creates energy in ${gains} of these ${total} scenes ${at} (the red cells).`
    : `${name}'s rule creates energy in none of these ${total} scenes ${at}.`;
  if (jams) caption.textContent += ` In ${jams} it has no answer (the rule jams).`;
  svg.setAttribute("aria-label", caption.textContent);
  drawHere();
}

/** The current scene on the map (its slip placed roughly when between the rows). */
function drawHere() {
  const g = document.getElementById("map-here");
  if (!g) return;
  g.replaceChildren();
  if (!current || !map || current.req.mu !== map.mu || current.req.e !== map.e) return;
  const svg = $("map");
  const frame = svg.querySelector("rect.frame");
  const [x0, y0, w, h] = ["x", "y", "width", "height"].map((n) => Number(frame.getAttribute(n)));
  const t = roughly(current.req.tan_half);
  const s = roughly(current.req.slip);
  if (Number.isNaN(t) || Number.isNaN(s) || s < -2.1 || s > 2.1 || t < 0.5 / 40 || t > 39.5 / 40) return;
  const x = x0 + ((t - 0.5 / 40) / (39 / 40)) * w;
  const y = y0 + h - ((s + 2.1) / 4.2) * h;
  g.append(el("circle", { cx: x, cy: y, r: 9, class: "here-ring" }));
  g.append(el("circle", { cx: x, cy: y, r: 9, class: "here-mark" }, undefined));
  g.lastChild.append(el("title", {}, "this scene"));
}

for (const r of document.querySelectorAll("input[name=map-law]")) r.addEventListener("change", drawMap);
// A narrower or wider window: the labels are sized again.
let resizeTimer = null;
window.addEventListener("resize", () => {
  clearTimeout(resizeTimer);
  resizeTimer = setTimeout(() => {
    draw();
    drawMap();
  }, 100);
});

// The preset `rodimpact explore --scene tilted-rod` wrote, then the link's.
applyLink(JSON.parse($("preset").textContent));
applyLink(location.hash.slice(1));
update();
