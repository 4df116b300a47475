// Camera arithmetic of the playground, in model units as hider-render takes them: the model's bounding
// box from its `v` lines, hider-render's default framing (tools/common/scene.cpp: eye on +z, every box
// corner inside 95% of the view), and orbit/zoom about the target. Only the numbers passed to
// --eye/--target come from here; hider-render itself does all the rendering.

/** Bounding box {lo, hi} of the `v` lines of OBJ bytes, or null when none parse. */
export function boundingBox(bytes) {
  const text = new TextDecoder().decode(bytes);
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  let found = false;
  for (const line of text.split("\n")) {
    if (!/^[ \t]*v[ \t]/.test(line)) continue;
    const f = line.replace(/#.*/, "").trim().split(/[ \t]+/).slice(1).map(Number);
    if (f.length < 3 || !f.slice(0, 3).every(Number.isFinite)) continue;
    const w = f.length > 3 && Number.isFinite(f[3]) && f[3] !== 0 ? f[3] : 1;
    for (let i = 0; i < 3; ++i) {
      lo[i] = Math.min(lo[i], f[i] / w);
      hi[i] = Math.max(hi[i], f[i] / w);
    }
    found = true;
  }
  return found ? { lo, hi } : null;
}

/** hider-render's default distance of the eye from `target` along +z (scene.cpp, build_scene). */
export function defaultDistance(box, target, width, height, fovDeg = 60) {
  const halfFov = (fovDeg * Math.PI) / 360;
  const halfFovX = Math.atan(Math.tan(halfFov) * (width / height));
  const tx = 0.95 * Math.tan(halfFovX), ty = 0.95 * Math.tan(halfFov);
  const r = Math.hypot(box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]) / 2 || 1;
  let d = 0;
  for (let c = 0; c < 8; ++c) {
    const k = [c & 1 ? box.hi[0] : box.lo[0], c & 2 ? box.hi[1] : box.lo[1], c & 4 ? box.hi[2] : box.lo[2]];
    const dz = k[2] - target[2];
    d = Math.max(d, dz + Math.abs(k[0] - target[0]) / tx, dz + Math.abs(k[1] - target[1]) / ty, dz + r * 0.01);
  }
  return d;
}

export const centre = (box) => [0, 1, 2].map((i) => (box.lo[i] + box.hi[i]) / 2);

/** Orbit {az, el, dist} of an eye about a target (az about +y from +z, el above the xz plane). */
export function orbitOf(eye, target) {
  const d = [0, 1, 2].map((i) => eye[i] - target[i]);
  const dist = Math.hypot(...d) || 1;
  return { az: Math.atan2(d[0], d[2]), el: Math.asin(Math.max(-1, Math.min(1, d[1] / dist))), dist };
}

export function eyeOf(orbit, target) {
  const c = Math.cos(orbit.el);
  return [target[0] + orbit.dist * c * Math.sin(orbit.az), target[1] + orbit.dist * Math.sin(orbit.el),
          target[2] + orbit.dist * c * Math.cos(orbit.az)];
}

/** Elevation stays short of the poles, where the default up vector (0,1,0) would be parallel to the view. */
export const kMaxElevation = 1.5;

/** A number as the command line gets it: 6 significant digits, no exponent noise for round values. */
export const formatNumber = (x) => String(Number(x.toPrecision(6)));
export const formatVec = (v) => v.map(formatNumber).join(",");

/** Parses "x,y,z" into three finite numbers, or null. */
export function parseVec(text) {
  if (typeof text !== "string") return null;
  const v = text.split(",").map((s) => (s.trim() === "" ? NaN : Number(s)));
  return v.length === 3 && v.every(Number.isFinite) ? v : null;
}
