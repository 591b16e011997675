"use strict";
// The page: reads the controls, asks the library (rodimpact compiled to WebAssembly: `api`)
// for the exact answer and the curves, shows them, draws the curve, the threshold and the
// motion, runs the predict-first mode, and checks the module against rodimpact's answers
// embedded when the page was written. Run by the loader as the body of `function (api)`:
// no physics is computed here.

  const $ = (id) => document.getElementById(id);
  // Asked for less motion (read at each frame: the setting may change while the page is open).
  const reducedMotion = window.matchMedia("(prefers-reduced-motion: reduce)");

  // ---- reading the controls ------------------------------------------------------------
  // The fields are read by the library (api.call): the page only gathers their text.
  const FIELDS = ["ratio", "a", "e", "rg", "pivot"];
  // The oblique tab's own fields (the fields above are shared by both tabs).
  const OBLIQUE_FIELDS = ["v0t", "mu", "radius", "spin"];

  function kind() {
    return document.querySelector("input[name=kind]:checked").value;
  }

  /** The request for the scene on the controls, as typed (the library reads and checks it). */
  function request(extra = {}) {
    return {
      ratio: $("ratio").value,
      a: $("a").value,
      e: $("e").value,
      kind: kind(),
      rg: $("rg").value,
      pivoted: $("pivoted").checked,
      pivot: $("pivot").value,
      ...extra,
    };
  }

  /** The oblique tab's request: the scene's fields and the sliding, the friction and the disc. */
  function obliqueRequest() {
    const disc = $("disc").checked;
    return request({ v0t: $("v0t").value, mu: $("mu").value, radius: disc ? $("radius").value : "", spin: disc ? $("spin").value : "" });
  }

  /** Shows each field's error (the library's message, naming the field), or clears it. */
  function showErrors(errors) {
    for (const id of [...FIELDS, ...OBLIQUE_FIELDS]) {
      const message = errors[id] || "";
      $(`${id}-error`).textContent = message;
      $(id).setAttribute("aria-invalid", message ? "true" : "false");
    }
  }

  /** A field's text as a float (for its slider), or null when it is not a number. */
  const numberOf = (text) => {
    const answer = api.call("number", { text });
    return answer.value ? answer.value.f64 : null;
  };

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
        const x = numberOf($(field).value);
        // An unfinished entry: the slider stays where it was.
        if (x !== null) $(slider).value = toSlider(x);
      } catch (_) {
        // A value the slider cannot take: it stays where it was.
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
  link("v0t-slider", "v0t", (s) => tidy(s, 2), (x) => x);
  link("mu-slider", "mu", (s) => tidy(s, 2), (x) => x);
  for (const id of ["rg", "pivot", "radius", "spin"]) $(id).addEventListener("input", update);
  $("disc").addEventListener("change", () => {
    $("radius").disabled = $("spin").disabled = !$("disc").checked;
    update();
  });
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
    guess = $("guess-value").value;
    revealed = true;
    update();
    $("summary").focus();
  });

  // ---- the tabs: the square-on impact (the paper) and the oblique one -----------------------
  // One scene: the fields of the rod and the impact (#shared-fields) go with the open tab.
  const TABS = ["square", "oblique"];
  let tab = "square";
  function showTab(name) {
    tab = name;
    for (const t of TABS) {
      const on = t === name;
      $(`tab-${t}`).setAttribute("aria-selected", on ? "true" : "false");
      $(`tab-${t}`).tabIndex = on ? 0 : -1;
      $(`panel-${t}`).hidden = !on;
    }
    if (name === "oblique") $("oblique-controls").prepend($("shared-fields"));
    else $("controls").insertBefore($("shared-fields"), $("controls").querySelector(".predict"));
    // The animation of the first tab stops while it is out of sight.
    if (name !== "square") setPlaying(false);
  }
  for (const t of TABS) {
    $(`tab-${t}`).addEventListener("click", () => {
      if (tab === t) return;
      showTab(t);
      update();
    });
  }
  // Arrow keys (and Home, End) move between the tabs, opening the one they reach.
  $("tab-square").parentElement.addEventListener("keydown", (event) => {
    const at = TABS.indexOf(tab);
    const next = { ArrowRight: at + 1, ArrowLeft: at - 1, Home: 0, End: TABS.length - 1 }[event.key];
    if (next === undefined) return;
    event.preventDefault();
    const name = TABS[(next + TABS.length) % TABS.length];
    if (name !== tab) {
      showTab(name);
      update();
    }
    $(`tab-${name}`).focus();
  });

  // ---- the oblique tab's guess ----------------------------------------------------------------
  // With predict first on, the answer (the spin, with and without friction) waits for a guess.
  let obliqueGuess = null;
  const GUESSES = { faster: "faster", same: "just as fast", slower: "slower" };
  const obliqueHidden = () => $("predict").checked && obliqueGuess === null;
  for (const button of document.querySelectorAll("#oblique-guess button")) {
    button.addEventListener("click", () => {
      obliqueGuess = button.dataset.guess;
      update();
      $("oblique-verdict").focus();
    });
  }

  // a* exactly (the field then reads `a*`, irrational or not), on the side already struck; the
  // end of that side when a* lies beyond it.
  $("hit-a-star").addEventListener("click", () => {
    if (!current) return;
    const { out } = current;
    const sign = out.side > 0 ? "" : "-";
    $("a").value = !out.inside ? `${sign}1` : out.pivoted ? `p${sign || "+"}a*` : `${sign}a*`;
    update();
  });

  // ---- the view of the motion ------------------------------------------------------------
  const frames = document.querySelectorAll("input[name=frame]");
  const frame = () => document.querySelector("input[name=frame]:checked").value;
  for (const r of frames) r.addEventListener("change", update);

  // ---- a link that opens the page on a scene (explore.html#M=1/2&a=1) --------------------------
  // The keys are those of `rodimpact explore`'s preset (the flags, in the page's units): the
  // values go into the controls as if typed, so a bad number is refused by its field.
  // The oblique tab's: tab (square or oblique), v0t, mu, radius (the disc's, or none) and spin.
  const LINK_KEYS = ["M", "a", "e", "rod", "pivot", "predict", "frame", "tab", "v0t", "mu", "radius", "spin"];
  /** Checks the radio button `choice` of the group `name`; false when there is none. */
  const pick = (name, choice) => {
    const radio = [...document.querySelectorAll(`input[name=${name}]`)].find((r) => r.value === choice);
    if (radio) radio.checked = true;
    return Boolean(radio);
  };
  function applyLink(text) {
    const { parts, wrong } = linkParts(text);
    for (const [key, value] of parts) {
      if (key === "M") $("ratio").value = value;
      else if (key === "a" || key === "e") $(key).value = value;
      else if (key === "rod") {
        const rg = /^rg=(.*)$/.exec(value);
        if (rg) $("rg").value = rg[1];
        if (!pick("kind", rg ? "gyration" : value === "gyration" ? "" : value)) wrong.push(`rod=${value}`);
      } else if (key === "pivot") {
        $("pivoted").checked = value !== "none";
        if (value !== "none") $("pivot").value = value;
      } else if (key === "predict" && (value === "1" || value === "0")) {
        setPredict(value === "1");
        obliqueGuess = null;
      } else if (key === "frame" && pick("frame", value)) continue;
      else if (key === "tab" && TABS.includes(value)) showTab(value);
      else if (key === "v0t" || key === "mu" || key === "spin") $(key).value = value;
      else if (key === "radius") {
        $("disc").checked = value !== "none";
        if (value !== "none") $("radius").value = value;
      }
      else wrong.push(LINK_KEYS.includes(key) ? `${key}=${value}` : key);
    }
    $("rg").disabled = kind() !== "gyration";
    $("pivot").disabled = !$("pivoted").checked;
    $("radius").disabled = $("spin").disabled = !$("disc").checked;
    for (const follow of followers) follow();
    $("link-error").textContent = wrong.length
      ? `The link's ${wrong.join(", ")} is not understood: it takes M, a, e, rod (uniform, dumbbell, rg=…), pivot (a position or none), predict (1 or 0), frame (centre-of-mass or lab), tab (square or oblique), and for the oblique tab v0t, mu, radius (a disc's, or none) and spin.`
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
    if (tab === "oblique") {
      // The oblique tab's scene: its tab first, then the same keys and its own.
      parts.unshift("tab=oblique");
      parts.push(`v0t=${value($("v0t").value)}`, `mu=${value($("mu").value)}`);
      if ($("disc").checked) parts.push(`radius=${value($("radius").value)}`, `spin=${value($("spin").value)}`);
    }
    return parts.join("&");
  }
  window.addEventListener("hashchange", () => {
    applyLink(location.hash.slice(1));
    update();
  });

  // ---- the answer ----------------------------------------------------------------------
  let current = null;

  /** `x unit` for people, a coefficient ±1 left out: `l`, `−l`, `2 l`, `√6/3 l`, `1/2 v0/l`. */
  const times = (x, unit) => {
    const shown = x.pretty;
    return shown === "1" ? unit : shown === "−1" ? `−${unit}` : `${shown} ${unit}`;
  };
  /** ` ≈ decimal` after an exact value, left out when the value is a whole number. */
  const approx = (x, unit = "") => (/^-?\d+$/.test(x.text) ? "" : ` ≈ ${x.approx}${unit}`);
  // A row of the table; an answer row says only "hidden" while the student has not guessed
  // (to a screen reader too).
  const row = (name, exact, decimal, meaning, answerOnly = false) => {
    const withheld = answerOnly && hidden();
    return `<tr${answerOnly ? ' class="answer-only"' : ""}><th scope="row">${name}</th><td class="exact">${withheld ? "hidden" : exact}</td><td class="decimal">${withheld ? "" : decimal}</td><td>${meaning}</td></tr>`;
  };

  function thresholdText(out) {
    if (out.pivoted) return "";
    const t = out.values.threshold;
    if (t.f64 <= 0) return "for this rod a* lies beyond the end whatever the masses";
    return `a* is on the rod exactly when M/m ≤ ${t.pretty}`;
  }

  /** No scene (a field to correct): the answer of the last one is cleared, not left standing. */
  function clearAnswer() {
    current = null;
    setPlaying(false);
    $("summary").textContent = "Correct the highlighted field to see the answer.";
    for (const id of ["curve", "threshold", "curve-caption", "threshold-caption", "values-body", "second", "bars"]) $(id).replaceChildren();
    ctx.clearRect(0, 0, canvas.width, canvas.height);
  }

  /** Shows the link to the scene on the controls in the anchor `id` (`explore.html#M=1&…`). */
  function showLink(id) {
    const link = sceneLink();
    const file = decodeURIComponent(location.pathname.split("/").pop() || "") || "explore.html";
    $(id).href = `#${link}`;
    $(id).textContent = `${file}#${link}`;
  }

  function update() {
    if (tab === "oblique") {
      updateOblique();
      return;
    }
    const out = api.call("explore", request(guess !== null && !hidden() ? { guess } : {}));
    showErrors(out.errors || {});
    $("a-note").textContent = out.note || "";
    if (out.errors) {
      clearAnswer();
      return;
    }
    current = { request: request(), out };
    const s = out.scene;
    const v = out.values;
    showLink("scene-link");
    for (const r of frames) r.disabled = out.pivoted;
    $("frame-note").textContent = out.pivoted ? "On a pivot the rod is seen from the table." : "";
    $("a-slider").value = s.a.f64;
    $("hit-a-star").hidden = hidden();
    $("guess").min = out.pivoted ? "-1" : "0";
    for (const [slider, value, label] of [["ratio-slider", s.ratio, "M/m"], ["a-slider", s.a, "a/l"], ["e-slider", s.e, "e"]]) {
      $(slider).setAttribute("aria-valuetext", `${label} = ${value.pretty}`);
    }
    const v0l = "<i>v</i><sub>0</sub>/<i>l</i>";
    const from = out.pivoted ? "from the pivot" : "from the centre";
    let rows = "";
    rows += row("<i>v</i>", v.v.pretty, v.v.decimal, "the puck after (× <i>v</i><sub>0</sub>; negative: it bounces back)");
    rows += row("<i>V</i>", v.V.pretty, v.V.decimal, "the rod's centre after (× <i>v</i><sub>0</sub>)");
    rows += row("<i>ω</i>", v.omega.pretty, v.omega.decimal, `the rod's spin (× ${v0l})`);
    rows += row("<i>J</i>", v.J.pretty, v.J.decimal, "impulse of the puck on the rod (× <i>m v</i><sub>0</sub>)");
    if (out.pivoted) rows += row("<i>J</i><sub>p</sub>", v.pivot_impulse.pretty, v.pivot_impulse.decimal, "impulse of the pivot on the rod (× <i>m v</i><sub>0</sub>)");
    if (!out.elastic) rows += row("Δ<i>K</i>/<i>K</i><sub>0</sub>", v.lost_fraction.pretty, v.lost_fraction.decimal, "fraction of the kinetic energy lost");
    const where = hidden() ? "" : out.at_end ? " (the end)" : out.inside ? "" : " (beyond the end)";
    rows += row("<i>a</i>*", times(v.a_star, "<i>l</i>"), v.a_star.decimal, `the fastest-spin point, ${from}${where}`, true);
    rows += row("<i>ω</i><sub>max</sub>", v.omega_max.pretty, v.omega_max.decimal, `fastest spin over the rod (× ${v0l})${hidden() ? "" : out.inside && !out.at_end ? ", at a*" : ", at the end"}`, true);
    if (v.ratio_to_max) rows += row("<i>ω</i>/<i>ω</i><sub>max</sub>", v.ratio_to_max.pretty, v.ratio_to_max.decimal, "this hit against the best one", true);
    $("values-body").innerHTML = rows;

    const aStar = `a* = ${times(v.a_star, "l")}${approx(v.a_star, " l")}`;
    const omegaMax = `ω_max = ${times(v.omega_max, "v0/l")}${approx(v.omega_max, " v0/l")}`;
    let summary;
    if (hidden()) {
      summary = `M/m = ${s.ratio.pretty}, a/l = ${s.a.pretty}, e = ${s.e.pretty}: ω = ${times(v.omega, "v0/l")}${approx(v.omega)}. Where is the fastest spin? Make your guess, then reveal.`;
    } else if (out.at_end) {
      // The threshold itself: a* is the end, which is then the best point (and no better one).
      const threshold = out.pivoted ? "the threshold" : `threshold M = ${times(v.threshold, "m")}`;
      summary = `${aStar} ${from}: the end is the best point (${threshold}), ${omegaMax}.`;
    } else if (out.inside) {
      summary = `${aStar} ${from} lies on the rod: hitting there spins it fastest, ${omegaMax}, faster than at the end (${times(v.omega_end, "v0/l")}).`;
    } else {
      summary = `${aStar} ${from} lies beyond the end: the end is the best place after all, ω_max = ω(end) = ${times(v.omega_max, "v0/l")}.`;
    }
    if (!out.pivoted && !hidden() && !out.at_end) summary += ` (${thresholdText(out)}.)`;
    if (out.guess && out.guess.share && !hidden()) {
      const share = out.guess.share;
      summary += ` Your guess a/l = ${out.guess.a.pretty} gives ${share.f64.toPrecision(3)} of ω_max (${(share.f64 * 100).toFixed(1)} %).`;
    }
    $("summary").textContent = summary;
    $("hidden-note").hidden = !hidden();
    document.body.classList.toggle("answer-hidden", hidden());
    // The motion after the impact, from the library at the times asked (floats for drawing).
    const states = (times) => api.call("explore_motion", { ...current.request, times }).states;
    motion = { ...out.motion, states, at: (t) => states([t])[0] };
    // The motion of one impact ends at the second: time stops there (on the slider's first step
    // at or after it), instead of drawing the puck through the rod.
    const min = Number($("time").min);
    const step = Number($("time").step);
    const end = motion.second !== null ? min + Math.ceil((motion.second - min) / step) * step : 6;
    $("time").max = end.toFixed(2);
    if (Number($("time").value) > end) $("time").value = end;
    view = out.pivoted || frame() === "lab" ? fitView(min, end) : null;
    let second;
    if (motion.second === null) {
      second = motion.stuck
        ? `At e = 0 the puck sticks to the rod: they turn together at ω = ${times(v.omega, "v0/l")} about ${out.pivoted ? "the pivot" : "their common centre of mass, which moves on at m v0/(M + m)"}.`
        : "The puck and the rod do not meet again (within 12 l/v0).";
    } else {
      second = `Second impact: the rod comes round and meets the puck again at t ≈ ${motion.second.toFixed(3)} l/v0`;
      // X19: a free rod struck elastically at a* exactly.
      const x19 = !out.pivoted && out.elastic && out.at_a_star;
      second += x19
        ? `, as X19 says: struck at a*, the puck moves on with v = V = ${v.v.pretty} v0, at rest relative to the rod's centre, and ω a* = ${v.omega_lever.text === "1" ? "" : `${v.omega_lever.pretty} `}v0; half a turn later the other arm hits it, at t = π a*/v0 = π·${v.a_star.pretty} l/v0 ≈ ${(Math.PI * v.a_star.f64).toFixed(3)} l/v0.`
        : ".";
    }
    $("second").textContent = second;
    draw();
  }

  // ---- the oblique tab ---------------------------------------------------------------------
  let oblique = null;

  /** No oblique answer (a field to correct): nothing of the last scene is left standing. */
  function clearOblique(message) {
    oblique = null;
    $("oblique-verdict").textContent = message;
    $("oblique-verdict").className = "summary";
    for (const id of ["oblique-contact", "oblique-body", "loss", "loss-caption"]) $(id).replaceChildren();
  }

  /** A typed number's exact value for the page ({pretty, f64, …}), or null. */
  const exactOf = (text) => api.call("number", { text }).value || null;

  function updateOblique() {
    const out = api.call("oblique", obliqueRequest());
    showErrors(out.errors || {});
    $("a-note").textContent = "";
    const hide = obliqueHidden();
    document.body.classList.toggle("oblique-hidden", hide);
    $("oblique-guess").hidden = !$("predict").checked;
    $("oblique-guess").querySelector(".choices").hidden = !hide;
    $("oblique-guessed").hidden = hide || !GUESSES[obliqueGuess];
    $("oblique-guessed").textContent = GUESSES[obliqueGuess] ? `Your guess: the rod spins ${GUESSES[obliqueGuess]}.` : "";
    if (out.errors) {
      clearOblique("Correct the highlighted field to see the answer.");
      return;
    }
    if (!out.values) {
      // A module that cannot answer (an older build): said, not hidden.
      clearOblique(`This page's computing module cannot answer the oblique impact: ${out.error ? out.error.message : "no answer"}.`);
      return;
    }
    oblique = { out, mu: exactOf($("mu").value) };
    showLink("oblique-link");
    for (const [slider, field, label] of [["v0t-slider", "v0t", "v0t"], ["mu-slider", "mu", "μ"]]) {
      const x = exactOf($(field).value);
      if (x) $(slider).setAttribute("aria-valuetext", `${label} = ${x.pretty}`);
    }
    const v = out.values;
    const disc = $("disc").checked;
    const v0 = "<i>v</i><sub>0</sub>";
    const v0l = `${v0}/<i>l</i>`;
    const withheld = (x) => (hide ? ["hidden", ""] : [x.pretty, x.decimal]);
    const answerRow = (name, x, meaning) => row(name, ...withheld(x), meaning).replace("<tr>", '<tr class="answer-only">');
    let rows = "";
    rows += row("<i>v</i>", v.v.pretty, v.v.decimal, `the puck across the rod after (× ${v0})`);
    rows += row("<i>V</i>", v.V.pretty, v.V.decimal, `the rod's centre across the rod after (× ${v0})`);
    rows += answerRow("<i>ω</i>", v.omega, `the rod's spin after (× ${v0l})`);
    rows += answerRow("<i>ω</i> (<i>μ</i> = 0)", v.omega_frictionless, `the rod's spin in the same scene without friction (× ${v0l})`);
    rows += row("<i>v</i><sub>t</sub>", v.vt.pretty, v.vt.decimal, `the puck along the rod after (× ${v0}; before: <i>v</i><sub>0t</sub>)`);
    rows += row("<i>V</i><sub>t</sub>", v.Vt.pretty, v.Vt.decimal, `the rod's centre along the rod after (× ${v0}; before: 0)`);
    rows += row("<i>J</i>", v.J.pretty, v.J.decimal, `normal impulse of the puck on the rod (× <i>m</i> ${v0})`);
    rows += row("<i>J</i><sub>t</sub>", v.Jt.pretty, v.Jt.decimal, `friction impulse on the rod, along it (× <i>m</i> ${v0})`);
    if (disc && v.spin_after) rows += row("<i>ω</i><sub>d</sub>", v.spin_after.pretty, v.spin_after.decimal, `the disc's spin after (× ${v0l}, counterclockwise)`);
    if (out.pivot_impulse) {
      const [across, along] = out.pivot_impulse;
      rows += row("<i>J</i><sub>p</sub>", `${across.pretty}, ${along.pretty}`, `${across.decimal}, ${along.decimal}`, `impulse of the pivot on the rod, across and along it (× <i>m</i> ${v0})`);
    }
    rows += v.mu_star
      ? row("<i>μ</i>*", v.mu_star.pretty, v.mu_star.decimal, "the friction needed to stop the sliding: the contact sticks when μ ≥ μ*")
      : row("<i>μ</i>*", "—", "", out.contact === "frictionless" ? "no friction to stop the sliding (μ = 0)" : "nothing slides at the contact: it sticks whatever μ");
    const contactWords = { stick: "sticks: the sliding stops during the impact", slide: "slides throughout the impact (|J<sub>t</sub>| = μ J)", frictionless: "frictionless (μ = 0)" };
    const contactShort = { stick: "sticks", slide: "slides", frictionless: "no friction" };
    rows += row("contact", contactShort[out.contact] || out.contact, "", contactWords[out.contact] || "");
    rows += row("<i>K</i><sub>0</sub>", v.energy_before.pretty, v.energy_before.decimal, `kinetic energy before (× <i>m</i> ${v0}²)`);
    rows += row("Δ<i>K</i><sub>e</sub>", v.lost_restitution.pretty, v.lost_restitution.decimal, `energy lost to restitution (× <i>m</i> ${v0}²; 0 when e = 1)`);
    rows += row("Δ<i>K</i><sub>μ</sub>", v.lost_friction.pretty, v.lost_friction.decimal, `energy lost to friction (× <i>m</i> ${v0}²)`);
    rows += row("Δ<i>K</i>", v.energy_lost.pretty, v.energy_lost.decimal, `energy lost in all (× <i>m</i> ${v0}²)`);
    $("oblique-body").innerHTML = rows;

    // The verdict, from the library's own comparison of the two spins (same_spin).
    const omega = `ω = ${times(v.omega, "v0/l")}${approx(v.omega)}`;
    const verdict = $("oblique-verdict");
    if (hide) {
      verdict.className = "summary";
      verdict.textContent = "Will friction change how fast the rod spins? Make your guess above: faster, just as fast, or slower than without friction.";
    } else if (out.same_spin) {
      verdict.className = "summary verdict-same";
      const right = obliqueGuess === "same" ? "Your guess is right: " : GUESSES[obliqueGuess] ? `Not ${GUESSES[obliqueGuess]}: ` : "";
      verdict.textContent = `${right}${omega}, exactly as without friction. Friction acts at the contact along the rod, and for a thin rod that line runs through the rod's centre: it has no lever arm, so it cannot change the spin. It changes only the motion along the rod, and it costs energy.`;
    } else {
      verdict.className = "summary verdict-differs";
      verdict.textContent = `${omega}, but without friction ω = ${times(v.omega_frictionless, "v0/l")}${approx(v.omega_frictionless)}: here friction changes the spin.`;
    }
    const mu = oblique.mu ? oblique.mu.pretty : $("mu").value;
    const lost = `friction takes ${times(v.lost_friction, "m v0²")}${approx(v.lost_friction)} of the energy (K0 = ${times(v.energy_before, "m v0²")})`;
    const contact = {
      slide: `The contact slides throughout: μ = ${mu} is less than μ* = ${v.mu_star ? v.mu_star.pretty : "?"}, the friction it would take to stop the sliding, so the friction impulse is μ J = ${v.Jt.pretty}; ${lost}.`,
      stick: v.mu_star
        ? `The contact sticks: μ = ${mu} is at least μ* = ${v.mu_star.pretty}, so the sliding stops during the impact and the friction impulse is only μ* J = ${v.Jt.pretty}; ${lost}, as much as any friction can take.`
        : `Nothing slides at the contact, so it sticks whatever μ and friction takes no energy.`,
      frictionless: `μ = 0: no friction, the puck keeps its ${times(v.vt, "v0")} along the rod and the rod does not move along itself.`,
    }[out.contact] || "";
    $("oblique-contact").textContent = contact;
    drawLoss();
  }

  /** A tick step for a range of `span`: 1, 2, 2.5 or 5 times a power of 10, 4 to 8 ticks. */
  const tickStep = (span) => {
    const power = 10 ** Math.floor(Math.log10(span / 4));
    return [1, 2, 2.5, 5, 10].map((k) => k * power).find((step) => span / step <= 8);
  };
  const ticks = (top, step) => Array.from({ length: Math.floor(top / step + 1e-9) + 1 }, (_, i) => i * step);

  /** The energy lost (to friction, and in all) against μ, with μ* and the chosen μ. */
  function drawLoss() {
    const svg = $("loss");
    svg.replaceChildren();
    if (!oblique) return;
    const { out } = oblique;
    const curve = out.loss_curve;
    const xs = [0, curve.mu_max];
    const peak = Math.max(...curve.total, ...curve.friction);
    const ystep = tickStep(Math.max(0.1, peak * 1.15));
    const ys = [0, Math.min(1, Math.ceil((Math.max(0.1, peak * 1.15)) / ystep) * ystep)];
    const xstep = tickStep(curve.mu_max);
    const digits = (step) => Math.max(0, -Math.floor(Math.log10(step) + 1e-9) + (String(step).includes("25") ? 1 : 0));
    const { X, Y } = axes(svg, [58, 18, 440, 220], xs, ys, "friction coefficient μ", "lost / K0", ticks(curve.mu_max, xstep), ticks(ys[1], ystep), (t) => tidy(t, digits(xstep)), (t) => tidy(t, digits(ystep)));
    const muStar = curve.mu_star;
    if (muStar !== null && muStar <= curve.mu_max) {
      // Where the contact sticks: from μ* on, friction takes no more.
      svg.append(el("rect", { x: X(muStar), y: Y(ys[1]), width: X(xs[1]) - X(muStar), height: Y(0) - Y(ys[1]), class: "stick-zone" }));
      svg.append(el("line", { x1: X(muStar), x2: X(muStar), y1: Y(0), y2: Y(ys[1]), class: "mustar" }));
      // Its name beside the line, on the side with more room; "sticks" in the shaded part.
      const right = muStar > xs[1] * 0.55;
      svg.append(el("text", { x: X(muStar) + (right ? -5 : 5), y: Y(ys[1]) + 16, class: "note mustar-label", "text-anchor": right ? "end" : "start" }, `μ* = ${out.values.mu_star ? out.values.mu_star.pretty : tidy(muStar, 3)}`));
      if (X(xs[1]) - X(muStar) > 70) svg.append(el("text", { x: (X(muStar) + X(xs[1])) / 2, y: Y(0) - 8, class: "note mustar-label", "text-anchor": "middle" }, "sticks"));
    }
    // The library's curves (its f64 backend), as polylines.
    const points = (ys) => curve.mu.map((m, i) => [X(m), Y(ys[i])]);
    const path = (pts) => pts.map(([x, y], i) => `${i ? "L" : "M"}${x.toFixed(1)},${y.toFixed(1)}`).join("");
    const friction = points(curve.friction);
    const total = points(curve.total);
    // The loss in all dashed over the loss to friction (they are one line when e = 1).
    svg.append(el("path", { d: path(friction), class: "curve friction" }));
    svg.append(el("path", { d: path(total), class: "curve total" }));
    // The legend, top left.
    svg.append(el("text", { x: X(0) + 8, y: Y(ys[1]) + 34, class: "note legend-total" }, "– – lost in all"));
    svg.append(el("text", { x: X(0) + 8, y: Y(ys[1]) + 50, class: "note legend-friction" }, "—— lost to friction"));
    // The chosen μ on each curve (at its pixel column; at the right edge when beyond the chart).
    if (oblique.mu) {
      const x = X(Math.min(oblique.mu.f64, curve.mu_max));
      const at = (pts) => {
        const i = pts.findIndex(([px]) => px >= x);
        if (i <= 0) return pts[Math.max(0, i)][1];
        const [[x0, y0], [x1, y1]] = [pts[i - 1], pts[i]];
        return x1 === x0 ? y1 : y0 + ((x - x0) / (x1 - x0)) * (y1 - y0);
      };
      svg.append(el("circle", { cx: x, cy: at(total), r: 4, class: "here" }));
      svg.append(el("circle", { cx: x, cy: at(friction), r: 6, class: "here friction" }));
      if (oblique.mu.f64 > curve.mu_max) svg.append(el("text", { x: x - 8, y: at(friction) - 10, class: "note", "text-anchor": "end" }, `μ = ${oblique.mu.pretty} →`));
    }
    const mu = oblique.mu ? oblique.mu.pretty : $("mu").value;
    $("loss-caption").textContent = muStar === null
      ? "The energy lost against μ: nothing slides at the contact, so friction takes none at any μ (the dashed line is the loss to restitution)."
      : `The energy lost to friction (solid) and in all (dashed), as a share of the energy before, against μ: friction takes more as μ grows while the contact slides, and no more from μ* = ${out.values.mu_star ? out.values.mu_star.pretty : tidy(muStar, 3)} on, where the contact sticks (shaded). The dots are μ = ${mu}.`;
  }

  // ---- drawing: the curve and the threshold ----------------------------------------------
  // SVG elements and label sizes: the pages' shared helpers (svgElement, textScale).
  const el = svgElement;

  function axes(svg, box, xs, ys, xlabel, ylabel, xticks, yticks, xfmt, yfmt = (t) => t.toFixed(1)) {
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
      svg.append(el("text", { x: x0 - 6, y: Y(t) + 4, class: "tick", "text-anchor": "end" }, yfmt(t)));
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
    const { out } = current;
    const curve = out.curve;
    const p = out.pivoted ? out.scene.pivot.f64 : 0;
    const xs = curve.range;
    const ys = [0, Math.ceil(curve.peak * 1.15 * 5) / 5];
    const yticks = [];
    for (let t = 0; t <= ys[1] + 1e-9; t += ys[1] > 1.2 ? 0.4 : 0.2) yticks.push(t);
    const xticks = out.pivoted ? [-1, -0.5, 0, 0.5, 1] : [0, 0.25, 0.5, 0.75, 1, ...(xs[1] > 1.2 ? [1.5] : []), ...(xs[1] > 1.9 ? [2] : [])];
    const { X, Y } = axes(svg, [58, 18, 440, 220], xs, ys, out.pivoted ? "impact point a/l (from the centre)" : "impact point a/l", "|ω| l/v0", xticks, yticks, (t) => tidy(t, 2));
    // The library's |omega| along the rod (its f64 backend), as a polyline.
    const path = (points) => points.map(([a, w], i) => `${i ? "L" : "M"}${X(a).toFixed(1)},${Y(w).toFixed(1)}`).join("");
    // While the student predicts, the curve (whose peak is the answer) is not drawn.
    if (hidden()) {
      svg.append(el("text", { x: X((xs[0] + xs[1]) / 2), y: Y(ys[1] * 0.12), class: "note", "text-anchor": "middle" }, "the curve appears when you reveal the answer"));
    } else {
      svg.append(el("path", { d: path(curve.on_rod), class: "curve" }));
      if (curve.beyond.length) svg.append(el("path", { d: path(curve.beyond), class: "curve beyond" }));
    }
    // The rod's end(s), and the pivot.
    svg.append(el("line", { x1: X(1), x2: X(1), y1: Y(ys[1]), y2: Y(0), class: "end" }));
    svg.append(el("text", { x: X(1) - 4, y: Y(ys[1]) + 14, class: "note", "text-anchor": "end" }, "end of the rod"));
    if (out.pivoted) svg.append(el("text", { x: X(p) + (p < -0.8 ? 4 : p > 0.8 ? -4 : 0), y: Y(0) - 6, class: "note", "text-anchor": p < -0.8 ? "start" : p > 0.8 ? "end" : "middle" }, "pivot"));
    if (!hidden()) {
      const omax = curve.omega_max;
      const omegaMax = out.values.omega_max;
      svg.append(el("line", { x1: X(xs[0]), x2: X(xs[1]), y1: Y(omax), y2: Y(omax), class: "max" }));
      svg.append(el("text", { x: X(xs[0]) + 6, y: Y(omax) - 5, class: "note max-label" }, `ω_max = ${omegaMax.pretty}${approx(omegaMax)}`));
      for (const { a: at, spin, side } of curve.a_star_marks) {
        svg.append(el("line", { x1: X(at), x2: X(at), y1: Y(0), y2: Y(spin), class: "astar" }));
        svg.append(el("circle", { cx: X(at), cy: Y(spin), r: 5, class: "astar-dot" }));
        // On a pivot a* is measured from the pivot: the mark is at p ± a*.
        const name = out.pivoted ? `p ${side > 0 ? "+" : "−"} a*` : `a* = ${out.values.a_star.pretty}`;
        svg.append(el("text", { x: X(at), y: Y(0) - 20, class: "note astar-label", "text-anchor": at > xs[1] - 0.15 ? "end" : "middle" }, name));
      }
    }
    const [a, spin] = curve.here;
    svg.append(el("circle", { cx: X(a), cy: Y(spin), r: 6, class: "here" }));
    if ($("predict").checked) {
      const g = Number($("guess").value);
      svg.append(el("line", { x1: X(g), x2: X(g), y1: Y(0), y2: Y(ys[1]), class: "guess" }));
      const nearRight = g > xs[1] - 0.2 * (xs[1] - xs[0]);
      svg.append(el("text", { x: X(g) + (nearRight ? -4 : 4), y: Y(ys[1]) + 30, class: "note guess-label", "text-anchor": nearRight ? "end" : "start" }, "my guess"));
    }
    const caption = hidden()
      ? `|ω| against the impact point; the dot is the chosen point, ω = ${times(out.values.omega, "v0/l")}.`
      : `|ω| against the impact point: the dot is the chosen point (ω = ${times(out.values.omega, "v0/l")}); a* = ${times(out.values.a_star, "l")}${approx(out.values.a_star, " l")} ${out.at_end ? "is the end" : out.inside ? "is on the rod" : "is beyond the end (dashed)"}; ω_max = ${times(out.values.omega_max, "v0/l")}.`;
    $("curve-caption").textContent = caption;
  }

  function drawThreshold() {
    const svg = $("threshold");
    svg.replaceChildren();
    const { out } = current;
    const arm = out.values.arm.f64;
    const xs = [-2, 2];
    const top = Math.max(2, arm * 1.25);
    const { X, Y } = axes(svg, [58, 18, 440, 220], xs, [0, top], "mass ratio M/m (log scale)", out.pivoted ? "a*/l from the pivot" : "a*/l", [-2, -1, 0, 1, 2], [0, 0.5, 1, 1.5, 2, ...(top > 2.4 ? [2.5, 3] : [])].filter((t) => t <= top), (t) => tidy(10 ** t, 2));
    // The curve up to the top of the frame (a* grows without bound with M/m); not drawn while
    // the student predicts (it shows a* for every M/m).
    if (!hidden()) {
      // The library's a* for M/m from 1/100 to 100 (its f64 backend).
      let d = "";
      for (const [i, [lx, y]] of out.threshold_curve.entries()) {
        d += `${i ? "L" : "M"}${X(lx).toFixed(1)},${Y(Math.min(top, y)).toFixed(1)}`;
        if (y > top) break;
      }
      svg.append(el("path", { d, class: "curve" }));
    }
    svg.append(el("line", { x1: X(-2), x2: X(2), y1: Y(arm), y2: Y(arm), class: "end" }));
    svg.append(el("text", { x: X(-2) + 6, y: Y(arm) - 5, class: "note" }, out.pivoted ? "end of the arm" : "end of the rod, a = l"));
    if (!out.pivoted && out.values.threshold.f64 > 0 && !hidden()) {
      const lt = Math.log10(out.values.threshold.f64);
      if (lt > -2 && lt < 2) {
        svg.append(el("line", { x1: X(lt), x2: X(lt), y1: Y(0), y2: Y(top), class: "threshold" }));
        // Written away from the right edge: to the left of the line when it is right of centre.
        const right = lt > 0;
        svg.append(el("text", { x: X(lt) + (right ? -5 : 5), y: Y(0) - 8, class: "note threshold-label", "text-anchor": right ? "end" : "start" }, `M = ${out.values.threshold.pretty} m: a* reaches the end`));
      }
    }
    const mu = out.scene.ratio.f64;
    if (!hidden() && mu >= 0.01 && mu <= 100) svg.append(el("circle", { cx: X(Math.log10(mu)), cy: Y(Math.min(top, out.values.a_star.f64)), r: 6, class: "here" }));
    $("threshold-caption").textContent = hidden()
      ? "Where the fastest-spin point lies for each mass ratio (hidden until you reveal)."
      : out.pivoted
        ? `The fastest-spin distance from the pivot, a* = √(M (I/M + p²)/m), against M/m; it is on the rod while below the end of the arm (${out.values.arm.pretty} l).`
        : `a*/l against M/m for this rod: ${thresholdText(out)}; the dot is the chosen M/m.`;
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
    const { out } = current;
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
    // The centre of mass moves at m v0/(m + M) = 1/(1 + M/m) (the library's, in the answer).
    const camera = view ? 0 : t * out.centre_of_mass_speed.f64;
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
    if (current.request.kind === "dumbbell") {
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
    if (out.pivoted) {
      const pv = out.scene.pivot.f64;
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
    const times = Array.from({ length: 301 }, (_, i) => from + ((to - from) * i) / 300);
    for (const state of motion.states(times)) {
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
    const { out } = current;
    const shares = out.energy;
    const parts = t < 0
      ? [["puck", shares.before_puck, "puck"], ["rod, moving", shares.before_rod, "move"], ["rod, turning", shares.before_rod, "turn"]]
      : [["puck", shares.puck, "puck"], ["rod, moving", shares.moving, "move"], ["rod, turning", shares.turning, "turn"]];
    if (t >= 0 && shares.lost) parts.push(["lost in the impact", shares.lost, "lost"]);
    let html = `<h3>Kinetic energy${t < 0 ? "" : " just after the impact"}, as a share of <i>K</i><sub>0</sub></h3>`;
    const label = [];
    for (const [name, share, cls] of parts) {
      // The exact share when it is short; its decimal (the exact one in the tooltip) otherwise.
      const exact = share.pretty;
      const shown = exact.length <= 9 ? exact : `≈ ${share.approx}`;
      label.push(`${name} ${exact.length <= 9 ? exact : share.approx}`);
      html += `<div class="bar"><span class="name">${name}</span><span class="track"><span class="fill ${cls}" style="width:${(share.f64 * 100).toFixed(2)}%"></span></span><span class="share" title="${exact}">${shown}</span></div>`;
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
  window.addEventListener("resize", () => (tab === "oblique" ? drawLoss() : draw()));

  // ---- the self-check against rodimpact ----------------------------------------------------
  function selfCheck() {
    const reference = JSON.parse($("reference").textContent);
    const wrong = [];
    for (const r of reference) {
      const { M, a, e, rod, pivot } = r.input;
      const gyration = rod.startsWith("rg=");
      const out = api.call("explore", {
        ratio: M, a, e, kind: gyration ? "gyration" : rod, rg: gyration ? rod.slice(3) : "",
        pivoted: pivot !== null, pivot: pivot ?? "",
      });
      const keys = ["v", "V", "omega", "energy_lost", "a_star", "omega_max", ...(pivot !== null ? ["pivot_impulse"] : [])];
      for (const key of keys) {
        const value = out.values ? out.values[key].text : JSON.stringify(out.errors);
        if (r[key] !== value) wrong.push(`${JSON.stringify(r.input)} ${key}: page ${value}, rodimpact ${r[key]}`);
      }
    }
    const line = $("self-check");
    if (wrong.length) {
      line.textContent = `Self-check FAILED: the page's computing module disagrees with rodimpact: ${wrong.join("; ")}`;
      line.classList.add("failed");
      console.error(line.textContent);
    } else {
      line.textContent = `Self-check: on opening, the page's computing module (rodimpact's library compiled to WebAssembly, ${(api.loadMs).toFixed(0)} ms to start) recomputed ${reference.length} scenes (free and pivoted, uniform, dumbbell and r_G rods, elastic to sticking) and agrees with the exact answers rodimpact wrote into the page on every value.`;
    }
  }

  // The preset `rodimpact explore` wrote, then the link's (explore.html#M=1/2&a=1).
  applyLink(JSON.parse($("preset").textContent));
  applyLink(location.hash.slice(1));
  update();
  // After the first answer is on the screen.
  setTimeout(selfCheck, 0);
