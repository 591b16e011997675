"use strict";
// What both pages share: the SVG and label helpers, a link's pairs, and the start: it unpacks
// rodimpact's library, compiled to WebAssembly and inlined in this page (zlib, base64,
// in the element #rodimpact-wasm), and runs the page's script with it: the page computes every
// number it shows by `api.call(name, request)`, which answers with the library's own code
// (rodimpact::app::pages::call). Nothing is fetched: the page works from a file, offline.

/** An SVG element `name` with the attributes `attrs` and, when given, the text `text`. */
function svgElement(name, attrs, text) {
  const e = document.createElementNS("http://www.w3.org/2000/svg", name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

// The smallest size a label is drawn at on the screen, in CSS px: a chart or a stage drawn
// narrower than its own width (a phone) scales its labels up by textScale to keep to it.
const LEAST_TEXT = 11;
/**
 * How much to enlarge text of `size` units in an element `units` wide, drawn `shown` px wide:
 * from 1 to 2 at most (narrower than a phone, or not laid out yet, the labels stay in).
 */
const textScale = (size, units, shown) => (shown > 0 ? Math.min(2, Math.max(1, (LEAST_TEXT * units) / (size * shown))) : 1);

/**
 * The pairs of a page's link after `#` (`M=1/2&a=1`): each `[key, value, hasValue]`, the value
 * decoded; `wrong` holds the parts that do not decode.
 */
function linkParts(text) {
  const parts = [];
  const wrong = [];
  for (const part of text.split("&").filter((p) => p !== "")) {
    const at = part.indexOf("=");
    try {
      parts.push([at < 0 ? part : part.slice(0, at), decodeURIComponent(at < 0 ? "" : part.slice(at + 1)), at >= 0]);
    } catch (_) {
      wrong.push(part);
    }
  }
  return { parts, wrong };
}

/** The bytes of a binary string (what atob returns). */
function bytesOf(binary) {
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/**
 * Starts the page: `run(api)` once the module is ready. On failure the page says so at its top
 * (a browser without WebAssembly or DecompressionStream).
 */
function rodimpactPage(run) {
  const started = performance.now();
  const unpack = async () => {
    const text = document.getElementById("rodimpact-wasm").textContent.trim();
    const packed = Uint8Array.fromBase64 ? Uint8Array.fromBase64(text) : bytesOf(atob(text));
    // Inflated as a stream and compiled as it arrives.
    const stream = new Blob([packed]).stream().pipeThrough(new DecompressionStream("deflate"));
    const module = await WebAssembly.compileStreaming(new Response(stream, { headers: { "Content-Type": "application/wasm" } }));
    const instance = await WebAssembly.instantiate(module, {});
    const wasm = instance.exports;
    const encoder = new TextEncoder();
    const decoder = new TextDecoder();
    return {
      /** The library's answer to `request` (an object) by the page function `name`. */
      call(name, request) {
        const message = encoder.encode(JSON.stringify({ name, request }));
        const at = wasm.alloc(message.length);
        new Uint8Array(wasm.memory.buffer, at, message.length).set(message);
        const length = wasm.call();
        const answer = new Uint8Array(wasm.memory.buffer, wasm.response_ptr(), length);
        return JSON.parse(decoder.decode(answer));
      },
    };
  };
  unpack()
    .then((api) => {
      api.loadMs = performance.now() - started;
      run(api);
      // The time from the script's start to the first answer on the page (the browser tests read it).
      document.documentElement.dataset.firstAnswerMs = (performance.now() - started).toFixed(1);
    })
    .catch((error) => {
      const line = document.createElement("p");
      line.className = "load-error";
      line.setAttribute("role", "alert");
      line.textContent = `This page could not start its computing module (${error}): it needs a browser with WebAssembly and DecompressionStream (Chrome 80, Firefox 113, Safari 16.4 or later).`;
      document.body.prepend(line);
      console.error(line.textContent);
    });
}
