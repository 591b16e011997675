"use strict";
// Unpacks rodimpact's library, compiled to WebAssembly and inlined in this page (zlib, base64,
// in the element #rodimpact-wasm), and runs the page's script with it: the page computes every
// number it shows by `api.call(name, request)`, which answers with the library's own code
// (rodimpact::report::pages::call). Nothing is fetched: the page works from a file, offline.

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
