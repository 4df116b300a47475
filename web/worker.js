// The playground's worker: compiles hider-render.wasm once and runs it for each request, so a long
// render never blocks the page (the page can also terminate this worker and start a new one).
// Messages in:  {type: "render", id, name, bytes, args}
// Messages out: {type: "ready", algos} | {type: "fatal", message}
//               {type: "result", id, code, stdout, stderr, trap, ppm (ArrayBuffer or null), ms}
import { runWasi } from "./wasi.js";

const modulePromise = fetch("hider-render.wasm")
  .then((r) => {
    if (!r.ok) throw new Error(`hider-render.wasm: HTTP ${r.status}`);
    return r.arrayBuffer();
  })
  .then((buf) => WebAssembly.compile(buf));

modulePromise.then(
  (module) => {
    // The names --algo accepts, from the module itself (tools/common/render.cpp, algo_names()).
    const r = runWasi(module, { entry: "hider_algo_names" });
    const algos = r.stdout.split(",").map((s) => s.trim()).filter((s) => s !== "");
    postMessage({ type: "ready", algos });
  },
  (e) => postMessage({ type: "fatal", message: String(e.message || e) }),
);

onmessage = async (event) => {
  const msg = event.data;
  if (msg.type !== "render") return;
  const module = await modulePromise;
  const files = new Map([[msg.name, new Uint8Array(msg.bytes)]]);
  const start = performance.now();
  let result;
  try {
    result = runWasi(module, { args: ["hider-render", ...msg.args], files });
  } catch (e) {
    result = { code: 134, stdout: "", stderr: "", trap: String(e.message || e) };
  }
  const ppm = result.code === 0 && files.has("frame.ppm") ? files.get("frame.ppm").buffer : null;
  postMessage({ type: "result", id: msg.id, ...result, ppm, ms: performance.now() - start }, ppm ? [ppm] : []);
};
