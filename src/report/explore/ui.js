"use strict";
// The page: reads the controls into an exact scene, shows the exact answer, draws the curve,
// the threshold and the motion, runs the predict-first mode, and checks its own arithmetic
// against rodimpact's answers embedded in the page.

(() => {
  const { Q, Quad, parse } = Exact;
  const $ = (id) => document.getElementById(id);
  const SVG = "http://www.w3.org/2000/svg";
  // Asked for less motion (read at each frame: the setting may change while the page is open).
  const reducedMotion = window.matchMedia("(prefers-reduced-motion: reduce)");

  // ---- reading the controls ------------------------------------------------------------
  const fields = {
    ratio: { check: (q) => (q.sign() > 0 ? null : "must be > 0"), name: "M/m" },
    a: { check: (q) => (q.abs().cmp(Q.of(1)) <= 0 ? null : "must lie on the rod, −1 ≤ a/l ≤ 1"), name: "a/l" },
    e: { check: (q) => (q.sign() >= 0 && q.cmp(Q.of(1)) <= 0 ? null : "must lie in 0 ≤ e ≤ 1"), name: "e" },
    rg: { check: (q) => (q.sign() > 0 ? null : "must be > 0"), name: "r_G/l" },
    pivot: { check: (q) => (q.abs().cmp(Q.of(1)) <= 0 ? null : "must lie on the rod, −1 ≤ p/l ≤ 1"), name: "p/l" },
  };

  // What the a field's a* came to when it lies beyond the end (shown under the field).
  let impactNote = "";

  /**
   * The impact point typed in the a field: a fraction or decimal, or the scene's fastest-spin
   * point, exactly: `a*` or `-a*` (from the centre), and on a pivot `p+a*` or `p-a*` (a* is then
   * measured from the pivot; `a*` alone means `p+a*`). Returns a Q or a Quad. An a* beyond the
   * end of the rod is struck at that end instead (the fastest spin on that side), with a note:
   * sweeping M/m after "Hit at a*" keeps the field's a* and follows it.
   */
  function parseImpact(text, M, k, p) {
    const star = /^\s*(p\s*)?([+\-−]?)\s*a\s*\*\s*$/i.exec(text);
    if (!star) return parse(text);
    if (star[1] && p === null) throw new Error("'p' only on a pivot");
    const root = Quad.sqrt(Physics.aStarSquared(M, k, p));
    const signed = star[2] && star[2] !== "+" ? root.neg() : root;
    const at = p === null ? signed : signed.add(p);
    if (at.abs().cmp(Q.of(1)) <= 0) return at;
    const end = Q.of(at.sign());
    impactNote = `${text.trim()} = ${at.pretty()} ≈ ${at.decimal(4)} lies beyond the end of the rod: struck at the end, a/l = ${end.pretty()}, where the spin is fastest on that side.`;
    return end;
  }

  /** The field's exact value (read with `parser`), or null with its error shown. */
  function read(id, parser = parse) {
    const input = $(id);
    const error = $(`${id}-error`);
    let value = null;
    let message = "";
    try {
      value = parser(input.value);
      message = fields[id].check(value) || "";
      if (message) value = null;
    } catch (e) {
      message = e.message;
    }
    error.textContent = message ? `${fields[id].name}: ${message}` : "";
    input.setAttribute("aria-invalid", message ? "true" : "false");
    return value;
  }

  function kind() {
    return document.querySelector("input[name=kind]:checked").value;
  }

  /** The scene of the controls, or null when a field is invalid. */
  function scene() {
    const M = read("ratio");
    const e = read("e");
    const kindName = kind();
    const rg = kindName === "gyration" ? read("rg") : Q.of(1, 2);
    const pivoted = $("pivoted").checked;
    const p = pivoted ? read("pivot") : Q.of(0);
    if (!M || !e || !rg || !p) return null;
    const k = Physics.inertiaFactor(kindName, rg);
    const pivot = pivoted ? p : null;
    impactNote = "";
    const a = read("a", (text) => parseImpact(text, M, k, pivot));
    $("a-note").textContent = impactNote;
    if (!a) return null;
    return { M, a, e, k, kind: kindName, rg, pivot };
  }

  // ---- sliders and text fields, kept in step -------------------------------------------
  /** A slider's value as a short exact decimal string. */
  const tidy = (x, digits) => {
    const s = Number(x).toFixed(digits).replace(/\.?0+$/, "");
    return s === "-0" ? "0" : s;
  };
  const ratioFromSlider = (s) => {
    const x = 10 ** Number(s);
    const magnitude = Math.floor(Math.log10(x));
    const step = 10 ** (magnitude - 1); // two significant digits
    return tidy(Math.round(x / step) * step, Math.max(0, 1 - magnitude));
  };
  // Each slider follows its field (when the field is typed in, or preset by a link).
  const followers = [];
  const link = (slider, field, toText, toSlider) => {
    const follow = () => {
      try {
        $(slider).value = toSlider(parse($(field).value).toNumber());
      } catch (_) {
        // An unfinished entry: the slider stays where it was.
      }
    };
    followers.push(follow);
    $(slider).addEventListener("input", () => {
      $(field).value = toText($(slider).value);
      update();
    });
    $(field).addEventListener("input", () => {
      follow();
      update();
    });
  };
  link("ratio-slider", "ratio", ratioFromSlider, (x) => Math.log10(x));
  link("a-slider", "a", (s) => tidy(s, 2), (x) => x);
  link("e-slider", "e", (s) => tidy(s, 2), (x) => x);
  for (const id of ["rg", "pivot"]) $(id).addEventListener("input", update);
  for (const r of document.querySelectorAll("input[name=kind]")) {
    r.addEventListener("change", () => {
      $("rg").disabled = kind() !== "gyration";
      update();
    });
  }
  $("pivoted").addEventListener("change", () => {
    $("pivot").disabled = !$("pivoted").checked;
    update();
  });

  // ---- predict first -------------------------------------------------------------------
  // Predict first is on when the page opens: the student guesses before seeing the answer.
  let revealed = !$("predict").checked;
  let guess = null;
  const hidden = () => $("predict").checked && !revealed;
  function setPredict(on) {
    $("predict").checked = on;
    revealed = !on;
    guess = null;
    $("guess-box").hidden = !on;
  }
  $("predict").addEventListener("change", () => {
    setPredict($("predict").checked);
    update();
  });
  $("guess").addEventListener("input", () => {
    $("guess-value").value = tidy($("guess").value, 2);
    $("guess").setAttribute("aria-valuetext", `a/l = ${$("guess-value").value}`);
    draw();
  });
  $("reveal").addEventListener("click", () => {
    guess = parse($("guess-value").value);
    revealed = true;
    update();
    $("summary").focus();
  });

  // a* exactly (the field then reads `a*`, irrational or not), on the side already struck; the
  // end of that side when a* lies beyond it.
  $("hit-a-star").addEventListener("click", () => {
    if (!current) return;
    const { out, scene: s } = current;
    const sign = out.side > 0 ? "" : "-";
    $("a").value = !out.inside ? `${sign}1` : s.pivot ? `p${sign || "+"}a*` : `${sign}a*`;
    update();
  });

  // ---- the view of the motion ------------------------------------------------------------
  const frames = document.querySelectorAll("input[name=frame]");
  const frame = () => document.querySelector("input[name=frame]:checked").value;
  for (const r of frames) r.addEventListener("change", update);

  // ---- a link that opens the page on a scene (explore.html#M=1/2&a=1) --------------------------
  // The keys are those of `rodimpact explore`'s preset (the flags, in the page's units): the
  // values go into the controls as if typed, so a bad number is refused by its field.
  const LINK_KEYS = ["M", "a", "e", "rod", "pivot", "predict", "frame"];
  /** Checks the radio button `choice` of the group `name`; false when there is none. */
  const pick = (name, choice) => {
    const radio = [...document.querySelectorAll(`input[name=${name}]`)].find((r) => r.value === choice);
    if (radio) radio.checked = true;
    return Boolean(radio);
  };
  function applyLink(text) {
    const wrong = [];
    for (const part of text.split("&").filter((p) => p !== "")) {
      const at = part.indexOf("=");
      const key = at < 0 ? part : part.slice(0, at);
      let value = "";
      try {
        value = decodeURIComponent(at < 0 ? "" : part.slice(at + 1));
      } catch (_) {
        wrong.push(part);
        continue;
      }
      if (key === "M") $("ratio").value = value;
      else if (key === "a" || key === "e") $(key).value = value;
      else if (key === "rod") {
        const rg = /^rg=(.*)$/.exec(value);
        if (rg) $("rg").value = rg[1];
        if (!pick("kind", rg ? "gyration" : value === "gyration" ? "" : value)) wrong.push(`rod=${value}`);
      } else if (key === "pivot") {
        $("pivoted").checked = value !== "none";
        if (value !== "none") $("pivot").value = value;
      } else if (key === "predict" && (value === "1" || value === "0")) setPredict(value === "1");
      else if (key === "frame" && pick("frame", value)) continue;
      else wrong.push(LINK_KEYS.includes(key) ? `${key}=${value}` : key);
    }
    $("rg").disabled = kind() !== "gyration";
    $("pivot").disabled = !$("pivoted").checked;
    for (const follow of followers) follow();
    $("link-error").textContent = wrong.length
      ? `The link's ${wrong.join(", ")} is not understood: it takes M, a, e, rod (uniform, dumbbell, rg=…), pivot (a position or none), predict (1 or 0) and frame (centre-of-mass or lab).`
      : "";
    $("link-error").hidden = !wrong.length;
  }
  /** The link to the scene on the controls (what the fields hold, as typed). */
  function sceneLink() {
    const value = (text) => encodeURIComponent(text.trim()).replace(/%2F/g, "/");
    const parts = [`M=${value($("ratio").value)}`, `a=${value($("a").value)}`, `e=${value($("e").value)}`];
    const kindName = kind();
    parts.push(`rod=${kindName === "gyration" ? `rg=${value($("rg").value)}` : kindName}`);
    if ($("pivoted").checked) parts.push(`pivot=${value($("pivot").value)}`);
    if (!$("predict").checked) parts.push("predict=0");
    if (frame() === "lab") parts.push("frame=lab");
    return parts.join("&");
  }
  window.addEventListener("hashchange", () => {
    applyLink(location.hash.slice(1));
    update();
  });

  // ---- the answer ----------------------------------------------------------------------
  let current = null;

  const unicode = (q) => q.pretty();
  /** `x unit` for people, a coefficient ±1 left out: `l`, `−l`, `2 l`, `√6/3 l`, `1/2 v0/l`. */
  const times = (x, unit) => {
    const shown = x.pretty();
    return shown === "1" ? unit : shown === "−1" ? `−${unit}` : `${shown} ${unit}`;
  };
  /** ` ≈ decimal` after an exact value, left out when the value is a whole number. */
  const approx = (x, unit = "") => {
    const q = Quad.from(x);
    return q.isRational() && q.rational().d === 1n ? "" : ` ≈ ${q.decimal(4)}${unit}`;
  };
  // A row of the table; an answer row says only "hidden" while the student has not guessed
  // (to a screen reader too).
  const row = (name, exact, decimal, meaning, answerOnly = false) => {
    const withheld = answerOnly && hidden();
    return `<tr${answerOnly ? ' class="answer-only"' : ""}><th scope="row">${name}</th><td class="exact">${withheld ? "hidden" : exact}</td><td class="decimal">${withheld ? "" : decimal}</td><td>${meaning}</td></tr>`;
  };

  /** a* is exactly the end of the struck arm: the threshold, where the end is the best point. */
  const atEnd = (out) => out.A.cmp(out.arm.mul(out.arm)) === 0;

  function thresholdText(s, out) {
    if (s.pivot) return "";
    const t = out.threshold;
    if (t.sign() <= 0) return "for this rod a* lies beyond the end whatever the masses";
    return `a* is on the rod exactly when M/m ≤ ${unicode(t)}`;
  }

  /** No scene (a field to correct): the answer of the last one is cleared, not left standing. */
  function clearAnswer() {
    current = null;
    setPlaying(false);
    $("summary").textContent = "Correct the highlighted field to see the answer.";
    for (const id of ["curve", "threshold", "curve-caption", "threshold-caption", "values-body", "second", "bars"]) $(id).replaceChildren();
    ctx.clearRect(0, 0, canvas.width, canvas.height);
  }

  function update() {
    const s = scene();
    if (!s) {
      clearAnswer();
      return;
    }
    const out = Physics.solve(s);
    current = { scene: s, out };
    const link = sceneLink();
    const file = decodeURIComponent(location.pathname.split("/").pop() || "") || "explore.html";
    $("scene-link").href = `#${link}`;
    $("scene-link").textContent = `${file}#${link}`;
    for (const r of frames) r.disabled = Boolean(s.pivot);
    $("frame-note").textContent = s.pivot ? "On a pivot the rod is seen from the table." : "";
    $("a-slider").value = s.a.toNumber();
    $("hit-a-star").hidden = hidden();
    $("guess").min = s.pivot ? "-1" : "0";
    for (const [slider, value, label] of [["ratio-slider", s.M, "M/m"], ["a-slider", s.a, "a/l"], ["e-slider", s.e, "e"]]) {
      $(slider).setAttribute("aria-valuetext", `${label} = ${unicode(value)}`);
    }
    const v0l = "<i>v</i><sub>0</sub>/<i>l</i>";
    const ratioToMax = out.inside
      ? out.aStar.mul(out.omega.abs()).mul(Q.of(2).div(Q.of(1).add(s.e)))
      : out.omega.abs().div(out.omegaEnd);
    const from = s.pivot ? "from the pivot" : "from the centre";
    let rows = "";
    rows += row("<i>v</i>", unicode(out.v), out.v.decimal(), "the puck after (× <i>v</i><sub>0</sub>; negative: it bounces back)");
    rows += row("<i>V</i>", unicode(out.V), out.V.decimal(), "the rod's centre after (× <i>v</i><sub>0</sub>)");
    rows += row("<i>ω</i>", unicode(out.omega), out.omega.decimal(), `the rod's spin (× ${v0l})`);
    rows += row("<i>J</i>", unicode(out.J), out.J.decimal(), "impulse of the puck on the rod (× <i>m v</i><sub>0</sub>)");
    if (s.pivot) rows += row("<i>J</i><sub>p</sub>", unicode(out.pivotImpulse), out.pivotImpulse.decimal(), "impulse of the pivot on the rod (× <i>m v</i><sub>0</sub>)");
    if (s.e.cmp(Q.of(1)) < 0) {
      const lost = out.lost.div(out.K0);
      rows += row("Δ<i>K</i>/<i>K</i><sub>0</sub>", unicode(lost), lost.decimal(), "fraction of the kinetic energy lost");
    }
    const where = hidden() ? "" : atEnd(out) ? " (the end)" : out.inside ? "" : " (beyond the end)";
    rows += row("<i>a</i>*", times(out.aStar, "<i>l</i>"), out.aStar.decimal(), `the fastest-spin point, ${from}${where}`, true);
    rows += row("<i>ω</i><sub>max</sub>", out.omegaMax.pretty(), out.omegaMax.decimal(), `fastest spin over the rod (× ${v0l})${hidden() ? "" : out.inside && !atEnd(out) ? ", at a*" : ", at the end"}`, true);
    rows += row("<i>ω</i>/<i>ω</i><sub>max</sub>", ratioToMax.pretty(), ratioToMax.decimal(), "this hit against the best one", true);
    $("values-body").innerHTML = rows;

    const aStar = `a* = ${times(out.aStar, "l")}${approx(out.aStar, " l")}`;
    const omegaMax = `ω_max = ${times(out.omegaMax, "v0/l")}${approx(out.omegaMax, " v0/l")}`;
    let summary;
    if (hidden()) {
      summary = `M/m = ${unicode(s.M)}, a/l = ${unicode(s.a)}, e = ${unicode(s.e)}: ω = ${times(out.omega, "v0/l")}${approx(out.omega)}. Where is the fastest spin? Make your guess, then reveal.`;
    } else if (atEnd(out)) {
      // The threshold itself: a* is the end, which is then the best point (and no better one).
      const threshold = s.pivot ? "the threshold" : `threshold M = ${times(out.threshold, "m")}`;
      summary = `${aStar} ${from}: the end is the best point (${threshold}), ${omegaMax}.`;
    } else if (out.inside) {
      summary = `${aStar} ${from} lies on the rod: hitting there spins it fastest, ${omegaMax}, faster than at the end (${times(out.omegaEnd, "v0/l")}).`;
    } else {
      summary = `${aStar} ${from} lies beyond the end: the end is the best place after all, ω_max = ω(end) = ${times(out.omegaMax, "v0/l")}.`;
    }
    if (!s.pivot && !hidden() && !atEnd(out)) summary += ` (${thresholdText(s, out)}.)`;
    if (guess && !hidden()) {
      const lever = s.pivot ? guess.sub(s.pivot) : guess;
      const atGuess = Q.of(1).add(s.e).mul(lever.abs()).div(out.A.add(lever.mul(lever)));
      const share = out.inside ? out.aStar.mul(atGuess.mul(Q.of(2)).div(Q.of(1).add(s.e))) : Quad.from(atGuess.div(out.omegaEnd));
      summary += ` Your guess a/l = ${unicode(guess)} gives ${share.decimal(3).replace("−", "-")} of ω_max (${(share.toNumber() * 100).toFixed(1)} %).`;
    }
    $("summary").textContent = summary;
    $("hidden-note").hidden = !hidden();
    document.body.classList.toggle("answer-hidden", hidden());
    motion = Physics.motion(s, out);
    // The motion of one impact ends at the second: time stops there (on the slider's first step
    // at or after it), instead of drawing the puck through the rod.
    const min = Number($("time").min);
    const step = Number($("time").step);
    const end = motion.second !== null ? min + Math.ceil((motion.second - min) / step) * step : 6;
    $("time").max = end.toFixed(2);
    if (Number($("time").value) > end) $("time").value = end;
    view = s.pivot || frame() === "lab" ? fitView(min, end) : null;
    let second;
    if (motion.second === null) {
      second = motion.stuck
        ? `At e = 0 the puck sticks to the rod: they turn together at ω = ${times(out.omega, "v0/l")} about ${s.pivot ? "the pivot" : "their common centre of mass, which moves on at m v0/(M + m)"}.`
        : "The puck and the rod do not meet again (within 12 l/v0).";
    } else {
      second = `Second impact: the rod comes round and meets the puck again at t ≈ ${motion.second.toFixed(3)} l/v0`;
      // X19: a free rod struck elastically at a* exactly.
      const x19 = !s.pivot && s.e.cmp(Q.of(1)) === 0 && out.atAStar;
      second += x19
        ? `, as X19 says: struck at a*, the puck moves on with v = V = ${unicode(out.v)} v0, at rest relative to the rod's centre, and ω a* = ${out.omega.mul(out.x).cmp(Q.of(1)) === 0 ? "" : `${unicode(out.omega.mul(out.x))} `}v0; half a turn later the other arm hits it, at t = π a*/v0 = π·${out.aStar.pretty()} l/v0 ≈ ${(Math.PI * out.aStar.toNumber()).toFixed(3)} l/v0.`
        : ".";
    }
    $("second").textContent = second;
    draw();
  }

  // ---- drawing: the curve and the threshold ----------------------------------------------
  const el = (name, attrs, text) => {
    const e = document.createElementNS(SVG, name);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  };

  // The smallest size a label is drawn at on the screen, in CSS px: a chart or the stage drawn
  // narrower than its own width (a phone) scales its labels up by textScale to keep to it.
  const LEAST_TEXT = 11;
  /**
   * How much to enlarge text of `size` units in an element `units` wide, drawn `shown` px wide:
   * from 1 to 2 at most (narrower than a phone, or not laid out yet, the labels stay in).
   */
  const textScale = (size, units, shown) => (shown > 0 ? Math.min(2, Math.max(1, (LEAST_TEXT * units) / (size * shown))) : 1);

  function axes(svg, box, xs, ys, xlabel, ylabel, xticks, yticks, xfmt) {
    // The chart's labels (12 units and up) at LEAST_TEXT px at least, their offsets with them
    // (the frame moves right to make room for larger labels at its left).
    const k = textScale(12, svg.viewBox.baseVal.width, svg.getBoundingClientRect().width);
    svg.style.setProperty("--text", k.toFixed(3));
    const inset = 16 * (k - 1);
    const [x0, y0, w, h] = [box[0] + inset, box[1], box[2] - inset, box[3]];
    const X = (x) => x0 + ((x - xs[0]) / (xs[1] - xs[0])) * w;
    const Y = (y) => y0 + h - ((y - ys[0]) / (ys[1] - ys[0])) * h;
    for (const t of xticks) {
      svg.append(el("line", { x1: X(t), x2: X(t), y1: y0, y2: y0 + h, class: "grid" }));
      svg.append(el("text", { x: X(t), y: y0 + h + 4 + 12 * k, class: "tick", "text-anchor": "middle" }, xfmt(t)));
    }
    for (const t of yticks) {
      svg.append(el("line", { x1: x0, x2: x0 + w, y1: Y(t), y2: Y(t), class: "grid" }));
      svg.append(el("text", { x: x0 - 6, y: Y(t) + 4, class: "tick", "text-anchor": "end" }, t.toFixed(1)));
    }
    svg.append(el("rect", { x: x0, y: y0, width: w, height: h, class: "frame" }));
    svg.append(el("text", { x: x0 + w / 2, y: y0 + h + 8 + 26 * k, class: "label", "text-anchor": "middle" }, xlabel));
    const left = 2 + 13 * k; // the rotated label's baseline, its letters to the left of it
    svg.append(el("text", { x: left, y: y0 + h / 2, class: "label", "text-anchor": "middle", transform: `rotate(-90 ${left} ${y0 + h / 2})` }, ylabel));
    return { X, Y };
  }

  function drawCurve() {
    const svg = $("curve");
    svg.replaceChildren();
    const { scene: s, out } = current;
    const e = s.e.toNumber();
    const A = out.A.toNumber();
    const p = s.pivot ? s.pivot.toNumber() : 0;
    const aStar = out.aStar.toNumber();
    const xs = s.pivot ? [-1, 1] : [0, Math.max(1, Math.min(2, aStar * 1.15))];
    const omegaAt = (a) => ((1 + e) * Math.abs(a - p)) / (A + (a - p) ** 2);
    const peak = Math.max((1 + e) / (2 * Math.sqrt(A)), omegaAt(1), omegaAt(-1));
    const ys = [0, Math.ceil(peak * 1.15 * 5) / 5];
    const yticks = [];
    for (let t = 0; t <= ys[1] + 1e-9; t += ys[1] > 1.2 ? 0.4 : 0.2) yticks.push(t);
    const xticks = s.pivot ? [-1, -0.5, 0, 0.5, 1] : [0, 0.25, 0.5, 0.75, 1, ...(xs[1] > 1.2 ? [1.5] : []), ...(xs[1] > 1.9 ? [2] : [])];
    const { X, Y } = axes(svg, [58, 18, 440, 220], xs, ys, s.pivot ? "impact point a/l (from the centre)" : "impact point a/l", "|ω| l/v0", xticks, yticks, (t) => tidy(t, 2));
    const path = (from, to) => {
      let d = "";
      for (let i = 0; i <= 200; i++) {
        const a = from + ((to - from) * i) / 200;
        d += `${i ? "L" : "M"}${X(a).toFixed(1)},${Y(omegaAt(a)).toFixed(1)}`;
      }
      return d;
    };
    // While the student predicts, the curve (whose peak is the answer) is not drawn.
    if (hidden()) {
      svg.append(el("text", { x: X((xs[0] + xs[1]) / 2), y: Y(ys[1] * 0.12), class: "note", "text-anchor": "middle" }, "the curve appears when you reveal the answer"));
    } else {
      svg.append(el("path", { d: path(xs[0], Math.min(1, xs[1])), class: "curve" }));
      if (xs[1] > 1) svg.append(el("path", { d: path(1, xs[1]), class: "curve beyond" }));
    }
    // The rod's end(s), and the pivot.
    svg.append(el("line", { x1: X(1), x2: X(1), y1: Y(ys[1]), y2: Y(0), class: "end" }));
    svg.append(el("text", { x: X(1) - 4, y: Y(ys[1]) + 14, class: "note", "text-anchor": "end" }, "end of the rod"));
    if (s.pivot) svg.append(el("text", { x: X(p) + (p < -0.8 ? 4 : p > 0.8 ? -4 : 0), y: Y(0) - 6, class: "note", "text-anchor": p < -0.8 ? "start" : p > 0.8 ? "end" : "middle" }, "pivot"));
    if (!hidden()) {
      const omax = out.omegaMax.toNumber();
      svg.append(el("line", { x1: X(xs[0]), x2: X(xs[1]), y1: Y(omax), y2: Y(omax), class: "max" }));
      svg.append(el("text", { x: X(xs[0]) + 6, y: Y(omax) - 5, class: "note max-label" }, `ω_max = ${out.omegaMax.pretty()}${approx(out.omegaMax)}`));
      for (const side of s.pivot ? [-1, 1] : [1]) {
        const at = p + side * aStar;
        if (at < xs[0] - 1e-9 || at > xs[1] + 1e-9) continue;
        svg.append(el("line", { x1: X(at), x2: X(at), y1: Y(0), y2: Y(omegaAt(at)), class: "astar" }));
        svg.append(el("circle", { cx: X(at), cy: Y(omegaAt(at)), r: 5, class: "astar-dot" }));
        // On a pivot a* is measured from the pivot: the mark is at p ± a*.
        const name = s.pivot ? `p ${side > 0 ? "+" : "−"} a*` : `a* = ${out.aStar.pretty()}`;
        svg.append(el("text", { x: X(at), y: Y(0) - 20, class: "note astar-label", "text-anchor": at > xs[1] - 0.15 ? "end" : "middle" }, name));
      }
    }
    const a = s.a.toNumber();
    svg.append(el("circle", { cx: X(a), cy: Y(omegaAt(a)), r: 6, class: "here" }));
    if ($("predict").checked) {
      const g = Number($("guess").value);
      svg.append(el("line", { x1: X(g), x2: X(g), y1: Y(0), y2: Y(ys[1]), class: "guess" }));
      const nearRight = g > xs[1] - 0.2 * (xs[1] - xs[0]);
      svg.append(el("text", { x: X(g) + (nearRight ? -4 : 4), y: Y(ys[1]) + 30, class: "note guess-label", "text-anchor": nearRight ? "end" : "start" }, "my guess"));
    }
    const caption = hidden()
      ? `|ω| against the impact point; the dot is the chosen point, ω = ${times(out.omega, "v0/l")}.`
      : `|ω| against the impact point: the dot is the chosen point (ω = ${times(out.omega, "v0/l")}); a* = ${times(out.aStar, "l")}${approx(out.aStar, " l")} ${atEnd(out) ? "is the end" : out.inside ? "is on the rod" : "is beyond the end (dashed)"}; ω_max = ${times(out.omegaMax, "v0/l")}.`;
    $("curve-caption").textContent = caption;
  }

  function drawThreshold() {
    const svg = $("threshold");
    svg.replaceChildren();
    const { scene: s, out } = current;
    const k = s.k.toNumber();
    const p = s.pivot ? s.pivot.toNumber() : 0;
    const arm = out.arm.toNumber();
    const star = (mu) => (s.pivot ? Math.sqrt(mu * (k + p * p)) : Math.sqrt(k * (mu + 1)));
    const xs = [-2, 2];
    const top = Math.max(2, arm * 1.25);
    const { X, Y } = axes(svg, [58, 18, 440, 220], xs, [0, top], "mass ratio M/m (log scale)", s.pivot ? "a*/l from the pivot" : "a*/l", [-2, -1, 0, 1, 2], [0, 0.5, 1, 1.5, 2, ...(top > 2.4 ? [2.5, 3] : [])].filter((t) => t <= top), (t) => tidy(10 ** t, 2));
    // The curve up to the top of the frame (a* grows without bound with M/m); not drawn while
    // the student predicts (it shows a* for every M/m).
    if (!hidden()) {
      let d = "";
      for (let i = 0; i <= 400; i++) {
        const lx = -2 + (4 * i) / 400;
        const y = star(10 ** lx);
        d += `${i ? "L" : "M"}${X(lx).toFixed(1)},${Y(Math.min(top, y)).toFixed(1)}`;
        if (y > top) break;
      }
      svg.append(el("path", { d, class: "curve" }));
    }
    svg.append(el("line", { x1: X(-2), x2: X(2), y1: Y(arm), y2: Y(arm), class: "end" }));
    svg.append(el("text", { x: X(-2) + 6, y: Y(arm) - 5, class: "note" }, s.pivot ? "end of the arm" : "end of the rod, a = l"));
    if (!s.pivot && out.threshold.sign() > 0 && !hidden()) {
      const lt = Math.log10(out.threshold.toNumber());
      if (lt > -2 && lt < 2) {
        svg.append(el("line", { x1: X(lt), x2: X(lt), y1: Y(0), y2: Y(top), class: "threshold" }));
        // Written away from the right edge: to the left of the line when it is right of centre.
        const right = lt > 0;
        svg.append(el("text", { x: X(lt) + (right ? -5 : 5), y: Y(0) - 8, class: "note threshold-label", "text-anchor": right ? "end" : "start" }, `M = ${unicode(out.threshold)} m: a* reaches the end`));
      }
    }
    const mu = s.M.toNumber();
    if (!hidden() && mu >= 0.01 && mu <= 100) svg.append(el("circle", { cx: X(Math.log10(mu)), cy: Y(Math.min(top, out.aStar.toNumber())), r: 6, class: "here" }));
    $("threshold-caption").textContent = hidden()
      ? "Where the fastest-spin point lies for each mass ratio (hidden until you reveal)."
      : s.pivot
        ? `The fastest-spin distance from the pivot, a* = √(M (I/M + p²)/m), against M/m; it is on the rod while below the end of the arm (${unicode(out.arm)} l).`
        : `a*/l against M/m for this rod: ${thresholdText(s, out)}; the dot is the chosen M/m.`;
  }

  // ---- the motion ------------------------------------------------------------------------
  let motion = null;
  // The table's view (scale and origin of x) fitted to the whole motion, or null: the view
  // moving with the centre of mass.
  let view = null;
  let playing = false;
  let last = null;
  const canvas = $("stage");
  const ctx = canvas.getContext("2d");

  function drawStage() {
    const { scene: s, out } = current;
    const t = Number($("time").value);
    $("time-value").value = t.toFixed(2).replace("-", "−");
    const phase = t < 0 ? "before the impact" : motion.second !== null && t >= motion.second ? "the second impact" : "after the impact";
    $("time").setAttribute("aria-valuetext", `t = ${$("time-value").value} l/v0, ${phase}`);
    const state = motion.at(t);
    const W = canvas.width;
    const H = canvas.height;
    // From the system's centre of mass (it moves at m v0/(m + M)), or from the table, where
    // the view holds the whole motion (a pivoted rod is always seen from the table).
    const scale = view ? view.scale : 110;
    const camera = view ? 0 : t / (1 + s.M.toNumber());
    const origin = view ? view.origin : W * 0.42;
    const px = (x) => origin + (x - camera) * scale;
    const py = (y) => H / 2 - y * scale;
    ctx.clearRect(0, 0, W, H);
    ctx.fillStyle = "#f4efe4";
    ctx.fillRect(0, 0, W, H);
    // The rod.
    const [cx, cy] = state.centre;
    const dir = [-Math.sin(state.phi), Math.cos(state.phi)];
    ctx.lineCap = "round";
    ctx.strokeStyle = "#6b4423";
    ctx.lineWidth = 10;
    ctx.beginPath();
    ctx.moveTo(px(cx - dir[0]), py(cy - dir[1]));
    ctx.lineTo(px(cx + dir[0]), py(cy + dir[1]));
    ctx.stroke();
    if (s.kind === "dumbbell") {
      ctx.fillStyle = "#6b4423";
      for (const sgn of [-1, 1]) {
        ctx.beginPath();
        ctx.arc(px(cx + sgn * dir[0]), py(cy + sgn * dir[1]), 12, 0, 2 * Math.PI);
        ctx.fill();
      }
    }
    ctx.fillStyle = "#000";
    ctx.beginPath();
    ctx.arc(px(cx), py(cy), 4, 0, 2 * Math.PI);
    ctx.fill();
    if (s.pivot) {
      const pv = s.pivot.toNumber();
      ctx.strokeStyle = "#000";
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(px(0), py(pv), 8, 0, 2 * Math.PI);
      ctx.stroke();
    }
    // The puck.
    const [bx, by] = state.ball;
    ctx.fillStyle = "#0072b2";
    ctx.beginPath();
    // The puck's edge at its point of contact: it turns with the rod when stuck to it.
    const facing = motion.stuck ? state.phi : 0;
    ctx.arc(px(bx) - 9 * Math.cos(facing), py(by) + 9 * Math.sin(facing), 9, 0, 2 * Math.PI);
    ctx.fill();
    // Labels.
    ctx.fillStyle = "#222";
    const k = textScale(15, W, canvas.getBoundingClientRect().width);
    ctx.font = `${(15 * k).toFixed(1)}px sans-serif`;
    const atSecond = motion.second !== null && t >= motion.second;
    ctx.fillText(t < 0 ? "before the impact" : atSecond ? "second impact: the motion of one impact ends here" : "after the impact", 12, 7 + 15 * k);
    ctx.fillText(view ? "view: the table (lab frame)" : "view: moving with the centre of mass", 12, H - 12);
    if (atSecond) {
      ctx.strokeStyle = "#d55e00";
      ctx.lineWidth = 3;
      ctx.beginPath();
      ctx.arc(px(bx), py(by), 20, 0, 2 * Math.PI);
      ctx.stroke();
    }
    drawBars(t);
  }

  /** The table's view of the motion from time `from` to `to`: puck and rod in the picture throughout. */
  function fitView(from, to) {
    const margin = 30;
    let lo = Infinity;
    let hi = -Infinity;
    let high = 1;
    for (let i = 0; i <= 300; i++) {
      const state = motion.at(from + ((to - from) * i) / 300);
      // The rod's ends are at centre ± (−sin φ, cos φ); the puck is about 0.2 l across.
      const [dx, dy] = [Math.abs(Math.sin(state.phi)), Math.abs(Math.cos(state.phi))];
      lo = Math.min(lo, state.ball[0] - 0.2, state.centre[0] - dx);
      hi = Math.max(hi, state.ball[0] + 0.1, state.centre[0] + dx);
      high = Math.max(high, Math.abs(state.ball[1]), Math.abs(state.centre[1]) + dy);
    }
    const width = canvas.width - 2 * margin;
    const scale = Math.min(110, width / (hi - lo), (canvas.height / 2 - margin) / high);
    return { scale, origin: margin + (width - (hi - lo) * scale) / 2 - lo * scale };
  }

  function drawBars(t) {
    const { scene: s, out } = current;
    const K0 = out.K0;
    const parts = t < 0
      ? [["puck", K0, "puck"], ["rod, moving", Q.of(0), "move"], ["rod, turning", Q.of(0), "turn"]]
      : [["puck", out.projectile, "puck"], ["rod, moving", out.translation, "move"], ["rod, turning", out.rotation, "turn"]];
    if (t >= 0 && s.e.cmp(Q.of(1)) < 0) parts.push(["lost in the impact", out.lost, "lost"]);
    let html = `<h3>Kinetic energy${t < 0 ? "" : " just after the impact"}, as a share of <i>K</i><sub>0</sub></h3>`;
    const label = [];
    for (const [name, value, cls] of parts) {
      const share = Quad.from(value).div(K0);
      // The exact share when it is short; its decimal (the exact one in the tooltip) otherwise.
      const exact = share.pretty();
      const shown = exact.length <= 9 ? exact : `≈ ${share.decimal(4)}`;
      label.push(`${name} ${exact.length <= 9 ? exact : share.decimal(4)}`);
      html += `<div class="bar"><span class="name">${name}</span><span class="track"><span class="fill ${cls}" style="width:${(share.toNumber() * 100).toFixed(2)}%"></span></span><span class="share" title="${exact}">${shown}</span></div>`;
    }
    $("bars").innerHTML = html;
    $("bars").setAttribute("aria-label", `Kinetic energy as a share of the initial: ${label.join("; ")}`);
  }

  function draw() {
    if (!current) return;
    drawCurve();
    drawThreshold();
    drawStage();
  }

  const stepSize = 0.05;
  function tick(now) {
    if (!playing) return;
    const time = $("time");
    const dt = reducedMotion.matches ? 0.5 : ((now - (last ?? now)) / 1000) * 0.8;
    last = now;
    const next = Number(time.value) + dt;
    if (next >= Number(time.max)) {
      time.value = time.max;
      setPlaying(false);
    } else {
      time.value = next;
    }
    drawStage();
    if (playing) {
      if (reducedMotion.matches) setTimeout(() => requestAnimationFrame(tick), 600);
      else requestAnimationFrame(tick);
    }
  }
  function setPlaying(on) {
    playing = on;
    last = null;
    $("play").textContent = on ? "Pause" : "Play";
    $("play").setAttribute("aria-pressed", on ? "true" : "false");
    if (on) {
      if (Number($("time").value) >= Number($("time").max)) $("time").value = $("time").min;
      requestAnimationFrame(tick);
    }
  }
  $("play").addEventListener("click", () => setPlaying(!playing));
  $("step").addEventListener("click", () => {
    $("time").value = Math.min(Number($("time").max), Number($("time").value) + stepSize * 5);
    drawStage();
  });
  $("step-back").addEventListener("click", () => {
    $("time").value = Math.max(Number($("time").min), Number($("time").value) - stepSize * 5);
    drawStage();
  });
  $("time").addEventListener("input", drawStage);
  // A narrower or wider window: the labels are sized again.
  window.addEventListener("resize", draw);

  // ---- the self-check against rodimpact ----------------------------------------------------
  function selfCheck() {
    const reference = JSON.parse($("reference").textContent);
    const wrong = [];
    for (const r of reference) {
      const rod = r.input.rod;
      const rg = rod.startsWith("rg=") ? parse(rod.slice(3)) : Q.of(1, 2);
      const k = Physics.inertiaFactor(rod.startsWith("rg=") ? "gyration" : rod, rg);
      const M = parse(r.input.M);
      const pivot = r.input.pivot === null ? null : parse(r.input.pivot);
      const s = { M, a: parseImpact(r.input.a, M, k, pivot), e: parse(r.input.e), k, pivot };
      const out = Physics.solve(s);
      const mine = {
        v: out.v.toString(),
        V: out.V.toString(),
        omega: out.omega.toString(),
        energy_lost: out.lost.toString(),
        a_star: out.aStar.toString(),
        omega_max: out.omegaMax.toString(),
      };
      if (s.pivot) mine.pivot_impulse = out.pivotImpulse.toString();
      for (const [key, value] of Object.entries(mine)) {
        if (r[key] !== value) wrong.push(`${JSON.stringify(r.input)} ${key}: page ${value}, rodimpact ${r[key]}`);
      }
    }
    const line = $("self-check");
    if (wrong.length) {
      line.textContent = `Self-check FAILED: the page's arithmetic disagrees with rodimpact: ${wrong.join("; ")}`;
      line.classList.add("failed");
      console.error(line.textContent);
    } else {
      line.textContent = `Self-check: on opening, the page recomputed ${reference.length} scenes (free and pivoted, uniform, dumbbell and r_G rods, elastic to sticking) and agrees with rodimpact's exact answers on every value.`;
    }
  }

  selfCheck();
  // The preset `rodimpact explore` wrote, then the link's (explore.html#M=1/2&a=1).
  applyLink(JSON.parse($("preset").textContent));
  applyLink(location.hash.slice(1));
  update();
})();
