// The playground page: turns the controls (or URL parameters) into a hider-render command line, runs it
// in the worker (hider-render.wasm), and shows the PPM it writes on the canvas pixel for pixel, with the
// --stats text and any error exactly as hider-render prints them.
// URL parameters: model, algo, shade, size, depth, cull (0/1), eye, target ("x,y,z" in model units),
// timeout_ms (watchdog of one render, default 30000). The page keeps them up to date as you change things.
import * as cam from "./camera.js";

const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);
const timeoutMs = Number(params.get("timeout_ms")) > 0 ? Number(params.get("timeout_ms")) : 30000;

const state = {
  model: null,       // {name, bytes, box, shipped}
  eyeText: params.get("eye"),        // verbatim until the view is changed on the page
  targetText: params.get("target"),
  orbit: null,       // {az, el, dist} once the view is moved
  target: null,
};
let worker = null, ready = false, inFlight = null, pending = false, nextId = 1, frames = 0, watchdog = null;

function setBodyState(s) { document.body.dataset.state = s; }

function selectValue(select, value) {
  if (value !== null && [...select.options].some((o) => o.value === value)) select.value = value;
}

function currentArgs() {
  const m = state.model;
  const name = m.name.startsWith("-") ? "./" + m.name : m.name;
  const args = [name, "-o", "frame.ppm", "--size", $("size").value, "--algo", $("algo").value,
                "--shade", $("shade").value, "--depth-bits", $("depth").value];
  if (!$("cull").checked) args.push("--no-cull");
  if (state.eyeText) args.push("--eye", state.eyeText);
  if (state.targetText) args.push("--target", state.targetText);
  args.push("--stats");
  return args;
}

const shellQuote = (s) => (/^[A-Za-z0-9_./,=:+-]+$/.test(s) ? s : "'" + s.replace(/'/g, "'\\''") + "'");

function updateUrl() {
  const p = new URLSearchParams();
  if (state.model?.shipped) p.set("model", state.model.shipped);
  p.set("algo", $("algo").value);
  p.set("shade", $("shade").value);
  p.set("size", $("size").value);
  p.set("depth", $("depth").value);
  if (!$("cull").checked) p.set("cull", "0");
  if (state.eyeText) p.set("eye", state.eyeText);
  if (state.targetText) p.set("target", state.targetText);
  if (params.has("timeout_ms")) p.set("timeout_ms", params.get("timeout_ms"));
  history.replaceState(null, "", "?" + p.toString().replace(/%2C/g, ","));
}

function render() {
  if (!state.model) return;
  if (!ready || inFlight) { pending = true; return; }  // sent when the worker is free
  pending = false;
  const args = currentArgs();
  $("command").textContent = "hider-render " + args.map(shellQuote).join(" ");
  updateUrl();
  inFlight = { id: nextId++, args };
  setBodyState("rendering");
  $("busy").hidden = false;
  worker.postMessage({ type: "render", id: inFlight.id, name: state.model.name, bytes: state.model.bytes, args });
  watchdog = setTimeout(() => {  // a render that runs away: end the worker, keep the page
    const ms = timeoutMs;
    inFlight = null;
    worker.terminate();
    showResult({ code: -1, stdout: "", stderr: "", trap: null, ppm: null,
                 stopped: `render stopped after ${ms} ms (the worker was restarted; try a smaller frame, ` +
                          `another algorithm or another model)` });
    startWorker();
  }, timeoutMs);
}

function showFrame(ppm) {
  const bytes = new Uint8Array(ppm);
  const header = new TextDecoder().decode(bytes.subarray(0, 32)).match(/^P6\s+(\d+)\s+(\d+)\s+255\s/);
  if (!header) throw new Error("not a P6 file");
  const w = Number(header[1]), h = Number(header[2]), offset = header[0].length;
  const canvas = $("frame");
  canvas.width = w;
  canvas.height = h;
  const image = new ImageData(w, h);
  for (let i = 0, j = offset; i < w * h; ++i, j += 3) {  // RGB888 of the PPM, opaque
    image.data[4 * i] = bytes[j];
    image.data[4 * i + 1] = bytes[j + 1];
    image.data[4 * i + 2] = bytes[j + 2];
    image.data[4 * i + 3] = 255;
  }
  canvas.getContext("2d", { willReadFrequently: true }).putImageData(image, 0, 0);
}

function showResult(r) {
  clearTimeout(watchdog);
  $("busy").hidden = true;
  const error = $("error");
  let failed = r.code !== 0;
  if (!failed) {
    try {
      showFrame(r.ppm);
    } catch (e) {
      failed = true;
      r.stderr = `playground: hider-render wrote an unreadable frame (${e.message})\n`;
    }
  }
  $("stats").textContent = r.stdout;
  $("stats").hidden = r.stdout === "";
  const message = r.stopped ?? ((r.stderr || "").trimEnd() +
                                (r.trap ? `\nhider-render stopped: ${r.trap}` : "")).trim();
  error.textContent = failed ? message || `hider-render exited with status ${r.code}` : "";
  error.hidden = !failed;
  document.body.classList.toggle("failed", failed);
  window.hiderPlayground.lastResult = { code: r.code, stdout: r.stdout, stderr: r.stderr, ms: r.ms };
  document.body.dataset.frame = String(++frames);
  setBodyState(failed ? "error" : "done");
}

function startWorker() {
  ready = false;
  worker = new Worker("worker.js", { type: "module" });
  worker.onmessage = (event) => {
    const msg = event.data;
    if (msg.type === "ready") {
      const select = $("algo");
      const previous = select.value || params.get("algo");
      select.replaceChildren(...msg.algos.map((a) => new Option(a, a)));
      selectValue(select, previous);
      ready = true;
      // The first frame, or after a watchdog restart whatever was asked for meanwhile.
      if (pending) render();
    } else if (msg.type === "fatal") {
      $("error").textContent = "cannot load hider-render.wasm: " + msg.message;
      $("error").hidden = false;
      setBodyState("error");
    } else if (msg.type === "result" && inFlight && msg.id === inFlight.id) {
      inFlight = null;
      showResult(msg);
      if (pending) render();
    }
  };
  worker.onerror = (e) => {
    $("error").textContent = "playground worker failed: " + (e.message || e);
    $("error").hidden = false;
    setBodyState("error");
  };
}

function setModel(name, bytes, shipped) {
  state.model = { name, bytes, box: cam.boundingBox(bytes), shipped };
  render();
}

async function loadShipped(name) {
  const response = await fetch(`models/${name}.obj`);
  if (!response.ok) throw new Error(`models/${name}.obj: HTTP ${response.status}`);
  setModel(`${name}.obj`, new Uint8Array(await response.arrayBuffer()), name);
}

function resetView() {
  state.eyeText = state.targetText = null;
  state.orbit = null;
}

async function loadFile(file) {
  const name = (file.name || "dropped.obj").replace(/[\u0000-\u001f/\\]/g, "_");
  const bytes = new Uint8Array(await file.arrayBuffer());
  const select = $("model");
  select.querySelector("option[data-dropped]")?.remove();
  const option = new Option(`${name} (your file)`, "");
  option.dataset.dropped = "1";
  select.add(option, 0);
  select.value = "";
  resetView();
  setModel(name, bytes, null);
}

// Orbit and zoom: the first move starts from the current eye (hider-render's default framing if none).
function ensureOrbit() {
  if (state.orbit) return true;
  const box = state.model?.box;
  const target = cam.parseVec(state.targetText) ?? (box ? cam.centre(box) : null);
  if (!target) return false;
  let eye = cam.parseVec(state.eyeText);
  if (!eye) {
    if (!box) return false;
    const [w, h] = $("size").value.split("x").map(Number);
    eye = [target[0], target[1], target[2] + cam.defaultDistance(box, target, w, h)];
  }
  state.target = target;
  state.orbit = cam.orbitOf(eye, target);
  return true;
}

function moveCamera(change) {
  if (!ensureOrbit()) return;
  change(state.orbit);
  state.orbit.el = Math.max(-cam.kMaxElevation, Math.min(cam.kMaxElevation, state.orbit.el));
  state.eyeText = cam.formatVec(cam.eyeOf(state.orbit, state.target));
  state.targetText = cam.formatVec(state.target);
  render();
}

function setupPointer() {
  const canvas = $("frame");
  const pointers = new Map();
  let pinch = 0;
  const spread = () => {
    const [a, b] = [...pointers.values()];
    return Math.hypot(a.x - b.x, a.y - b.y);
  };
  canvas.addEventListener("pointerdown", (e) => {
    canvas.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    if (pointers.size === 2) pinch = spread();
  });
  canvas.addEventListener("pointermove", (e) => {
    const p = pointers.get(e.pointerId);
    if (!p) return;
    const dx = e.clientX - p.x, dy = e.clientY - p.y;
    p.x = e.clientX;
    p.y = e.clientY;
    if (pointers.size === 1) {
      moveCamera((o) => { o.az -= dx * 0.01; o.el += dy * 0.01; });
    } else if (pointers.size === 2 && pinch > 0) {
      const now = spread();
      if (now > 0) moveCamera((o) => { o.dist *= pinch / now; });
      pinch = now;
    }
  });
  const up = (e) => { pointers.delete(e.pointerId); pinch = pointers.size === 2 ? spread() : 0; };
  canvas.addEventListener("pointerup", up);
  canvas.addEventListener("pointercancel", up);
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    moveCamera((o) => { o.dist *= Math.exp(Math.max(-200, Math.min(200, e.deltaY)) * 0.002); });
  }, { passive: false });
}

function setupDrop() {
  const body = document.body;
  body.addEventListener("dragover", (e) => { e.preventDefault(); body.classList.add("dragging"); });
  body.addEventListener("dragleave", () => body.classList.remove("dragging"));
  body.addEventListener("drop", (e) => {
    e.preventDefault();
    body.classList.remove("dragging");
    const file = e.dataTransfer?.files?.[0];
    if (file) loadFile(file);
  });
  $("file").addEventListener("change", (e) => { if (e.target.files[0]) loadFile(e.target.files[0]); });
}

async function main() {
  window.hiderPlayground = {
    args: () => (state.model ? currentArgs() : null),
    idle: () => ready && !inFlight && !pending,
    lastResult: null,
  };
  selectValue($("shade"), params.get("shade"));
  selectValue($("size"), params.get("size"));
  selectValue($("depth"), params.get("depth"));
  $("cull").checked = params.get("cull") !== "0";
  for (const id of ["algo", "shade", "size", "depth", "cull"]) $(id).addEventListener("change", render);
  $("reset").addEventListener("click", () => { resetView(); render(); });
  $("model").addEventListener("change", (e) => {
    if (!e.target.value) return;
    resetView();
    loadShipped(e.target.value).catch(showLoadError);
  });
  setupPointer();
  setupDrop();
  startWorker();
  const models = await (await fetch("models.json")).json();
  $("model").replaceChildren(...models.map((m) => new Option(m, m)));
  const wanted = models.includes(params.get("model")) ? params.get("model") : models[0];
  $("model").value = wanted;
  await loadShipped(wanted);
}

function showLoadError(e) {
  $("error").textContent = String(e.message || e);
  $("error").hidden = false;
  setBodyState("error");
}

main().catch(showLoadError);
