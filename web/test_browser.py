#!/usr/bin/env python3
"""Headless-browser test of the playground: Debian's Chromium driven over the Chrome DevTools protocol
on a pipe (--remote-debugging-pipe), Python's standard library only (no npm, no WebSocket client).

For models x algorithms x cameras set through URL parameters, and for changes made through the page's
own controls (algorithm and model selects, mouse drag to orbit, wheel to zoom), the canvas pixels read
back from the page must be byte-identical to the PPM that native hider-render writes for the same
command line, and the statistics text identical to its --stats output. Malformed OBJ files dropped on
the page (and one chosen through the file input) must show exactly native hider-render's error
message; the page must survive a render stopped by its watchdog.

Usage: test_browser.py --site DIR --hider-render EXE --models DIR --work DIR [--screenshots DIR]
"""
import argparse
import base64
import fcntl
import json
import os
import queue
import shutil
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import serve  # noqa: E402

CHROMIUM_FLAGS = [
    "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--disable-extensions", "--disable-default-apps", "--mute-audio", "--remote-debugging-pipe",
]


class Failure(Exception):
    pass


class Browser:
    """Chromium with the DevTools protocol on fds 3 (commands in) and 4 (replies out), NUL-separated JSON."""

    def __init__(self, chromium, user_dir, log_path):
        to_child_r, self._to_child = os.pipe()
        self._from_child, from_child_w = os.pipe()
        # Move the child's ends above 4 first, so dup2 onto 3 and 4 cannot overwrite one another.
        high_r = fcntl.fcntl(to_child_r, fcntl.F_DUPFD_CLOEXEC, 10)
        high_w = fcntl.fcntl(from_child_w, fcntl.F_DUPFD_CLOEXEC, 10)
        os.close(to_child_r)
        os.close(from_child_w)

        def child_fds():
            os.dup2(high_r, 3)
            os.dup2(high_w, 4)

        self._log = open(log_path, "wb")
        self.proc = subprocess.Popen([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={user_dir}", "about:blank"],
                                     preexec_fn=child_fds, close_fds=False, stdin=subprocess.DEVNULL,
                                     stdout=self._log, stderr=subprocess.STDOUT)
        os.close(high_r)
        os.close(high_w)
        self._next = 1
        self._replies = {}
        self._cond = threading.Condition()
        self.events = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()
        self.session = None

    def _read(self):
        buf = b""
        while True:
            chunk = os.read(self._from_child, 1 << 16)
            if not chunk:
                break
            buf += chunk
            *messages, buf = buf.split(b"\0")
            for raw in messages:
                msg = json.loads(raw)
                if "id" in msg:
                    with self._cond:
                        self._replies[msg["id"]] = msg
                        self._cond.notify_all()
                else:
                    self.events.put(msg)
        with self._cond:
            self._replies[None] = {"error": {"message": "browser closed the pipe"}}
            self._cond.notify_all()

    def send(self, method, params=None, session=True, timeout=60):
        msg_id = self._next
        self._next += 1
        msg = {"id": msg_id, "method": method, "params": params or {}}
        if session and self.session:
            msg["sessionId"] = self.session
        os.write(self._to_child, json.dumps(msg).encode() + b"\0")
        deadline = time.monotonic() + timeout
        with self._cond:
            while msg_id not in self._replies and None not in self._replies:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise Failure(f"no reply to {method} within {timeout} s")
                self._cond.wait(left)
            reply = self._replies.pop(msg_id, None) or self._replies[None]
        if "error" in reply:
            raise Failure(f"{method}: {reply['error'].get('message')}")
        return reply.get("result", {})

    def open_page(self):
        target = self.send("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
        self.session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True},
                                 session=False)["sessionId"]
        for domain in ("Page", "Runtime"):
            self.send(f"{domain}.enable")
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": 1100, "height": 820, "deviceScaleFactor": 1, "mobile": False})

    def evaluate(self, expression, timeout=60):
        r = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True, "awaitPromise": True},
                      timeout=timeout)
        if "exceptionDetails" in r:
            raise Failure(f"page script failed: {r['exceptionDetails'].get('text')} "
                          f"{r['exceptionDetails'].get('exception', {}).get('description', '')}")
        return r["result"].get("value")

    def wait_for(self, expression, timeout=120, what=None):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.evaluate(expression):
                return
            time.sleep(0.05)
        raise Failure(f"timed out after {timeout} s waiting for {what or expression}")

    def page_errors(self):
        errors = []
        while not self.events.empty():
            e = self.events.get()
            if e.get("method") == "Runtime.exceptionThrown":
                d = e["params"]["exceptionDetails"]
                errors.append(f"{d.get('text')} {d.get('exception', {}).get('description', '')}")
        return errors

    def close(self):
        try:
            self.send("Browser.close", session=False, timeout=10)
        except Failure:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self._log.close()


READ_CANVAS = """(() => {
  const c = document.getElementById('frame');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const rgb = new Uint8Array(c.width * c.height * 3);
  let opaque = true;
  for (let i = 0, j = 0; i < d.length; i += 4) {
    rgb[j++] = d[i]; rgb[j++] = d[i + 1]; rgb[j++] = d[i + 2];
    if (d[i + 3] !== 255) opaque = false;
  }
  let bin = '';
  for (let i = 0; i < rgb.length; i += 0x8000) bin += String.fromCharCode.apply(null, rgb.subarray(i, i + 0x8000));
  return {width: c.width, height: c.height, opaque, rgb: btoa(bin)};
})()"""


def read_ppm(path):
    data = open(path, "rb").read()
    fields, pos = [], 0
    while len(fields) < 4:  # P6 width height maxval, separated by single whitespace bytes
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    assert fields[0] == b"P6" and fields[3] == b"255", path
    return int(fields[1]), int(fields[2]), data[pos + 1:]


class Suite:
    def __init__(self, opts, browser, base_url):
        self.o = opts
        self.b = browser
        self.url = base_url
        self.checked = 0
        self.frame = 0

    def native(self, args, cwd=None):
        out = os.path.join(self.o.work, "native.ppm")
        if os.path.exists(out):
            os.remove(out)
        run = subprocess.run([self.o.hider_render, *args, "-o", out], cwd=cwd or self.o.models,
                             capture_output=True, text=True, timeout=300)
        return run, out

    def wait_render(self):
        self.b.wait_for(f"window.hiderPlayground && hiderPlayground.idle() && "
                        f"Number(document.body.dataset.frame) > {self.frame}", what="a new frame")
        self.frame = int(self.b.evaluate("Number(document.body.dataset.frame)"))
        errors = self.b.page_errors()
        if errors:
            raise Failure("page threw: " + "; ".join(errors))
        return self.b.evaluate("document.body.dataset.state")

    def page_args(self):
        """hider-render's arguments as the page ran them, without the output file."""
        args = self.b.evaluate("hiderPlayground.args()")
        i = args.index("-o")
        return args[:i] + args[i + 2:]

    def compare_frame(self, label, expect_args=None, cwd=None):
        state = self.b.evaluate("document.body.dataset.state")
        page_error = self.b.evaluate("document.getElementById('error').textContent")
        if state != "done":
            raise Failure(f"{label}: page state {state}: {page_error}")
        args = self.page_args()
        if expect_args is not None and args != expect_args:
            raise Failure(f"{label}: page ran {args}, expected {expect_args}")
        run, out = self.native(args, cwd=cwd)
        if run.returncode != 0:
            raise Failure(f"{label}: native hider-render failed: {run.stderr}")
        width, height, rgb = read_ppm(out)
        canvas = self.b.evaluate(READ_CANVAS)
        got = base64.b64decode(canvas["rgb"])
        if (canvas["width"], canvas["height"]) != (width, height):
            raise Failure(f"{label}: canvas {canvas['width']}x{canvas['height']}, native {width}x{height}")
        if not canvas["opaque"]:
            raise Failure(f"{label}: canvas has non-opaque pixels")
        if got != rgb:
            diff = sum(1 for i in range(0, len(rgb), 3) if got[i:i + 3] != rgb[i:i + 3])
            raise Failure(f"{label}: {diff} of {width * height} pixels differ from native hider-render")
        stats = self.b.evaluate("document.getElementById('stats').textContent")
        if stats != run.stdout:
            raise Failure(f"{label}: statistics differ:\npage:\n{stats}\nnative:\n{run.stdout}")
        lit = sum(1 for i in range(0, len(rgb), 3) if rgb[i:i + 3] != rgb[0:3])
        if lit < 100:
            raise Failure(f"{label}: frame nearly empty ({lit} pixels differ from the corner)")
        self.checked += 1
        print(f"  ok  {label}: {width}x{height}, {lit} pixels lit, identical to native", flush=True)
        return got

    def navigate(self, query):
        self.frame = 0
        self.b.send("Page.navigate", {"url": self.url + "index.html?" + query})
        return self.wait_render()

    # --- the cases -----------------------------------------------------------------------------

    def algorithms(self):
        self.navigate("model=torus&size=160x128")
        algos = self.b.evaluate("[...document.getElementById('algo').options].map(o => o.value)")
        run = subprocess.run([self.o.hider_render, "x.obj", "-o", "x.ppm", "--algo", "?"],
                             capture_output=True, text=True)
        listed = run.stderr.split("(available: ")[-1].split(")")[0].split(", ")
        if algos != listed:
            raise Failure(f"page offers {algos}, native hider-render accepts {listed}")
        if len(algos) < 3:
            raise Failure(f"only {len(algos)} algorithms: {algos}")
        print(f"  ok  algorithms from the module: {', '.join(algos)}", flush=True)
        return algos

    def url_matrix(self, algos):
        cameras = {"torus": ("0.3,1.8,-2.4", "0,0,0"), "teapot": ("2,4,5", None), "suzanne": ("-1.5,1,3", None)}
        for model, (eye, target) in cameras.items():
            for algo in algos:
                query = f"model={model}&algo={algo}&size=160x128&eye={eye}" + (f"&target={target}" if target else "")
                self.navigate(query)
                expect = [f"{model}.obj", "--size", "160x128", "--algo", algo, "--shade", "headlight",
                          "--depth-bits", "16", "--eye", eye] + (["--target", target] if target else []) + ["--stats"]
                self.compare_frame(f"{model} {algo} eye {eye}", expect)
        self.navigate("model=teapot&algo=zbuffer&shade=depth&size=320x240&depth=32&cull=0&eye=-3,2,4")
        self.compare_frame("teapot zbuffer 320x240 depth-32 depth-shaded no-cull")
        self.navigate(f"model=spot&algo={algos[-1]}&shade=id&size=320x240")
        self.compare_frame(f"spot {algos[-1]} id-shaded 320x240 default camera")
        if self.o.screenshots:
            self.navigate("model=teapot&algo=newell&size=320x240&eye=2.4,3.2,5")
            self.compare_frame("teapot newell 320x240 (screenshot)")
            self.screenshot("playground.png")

    def controls(self, algos):
        self.navigate("model=cow&algo=zbuffer&size=160x128")
        self.compare_frame("cow zbuffer, default camera")
        other = algos[1]
        self.b.evaluate(f"(() => {{ const s = document.getElementById('algo'); s.value = '{other}'; "
                        f"s.dispatchEvent(new Event('change')); }})()")
        self.wait_render()
        self.compare_frame(f"cow {other} chosen in the algorithm select")
        self.b.evaluate("(() => { const s = document.getElementById('model'); s.value = 'beetle'; "
                        "s.dispatchEvent(new Event('change')); })()")
        self.wait_render()
        before = self.compare_frame(f"beetle {other} chosen in the model select")
        if "--eye" in self.page_args():
            raise Failure("a new model should start from hider-render's default camera")
        box = self.b.evaluate("(() => { const r = document.getElementById('frame').getBoundingClientRect(); "
                              "return [r.left + r.width / 2, r.top + r.height / 2]; })()")
        x, y = box
        self.b.send("Input.dispatchMouseEvent", {"type": "mousePressed", "x": x, "y": y, "button": "left",
                                                 "buttons": 1, "clickCount": 1})
        for step in range(1, 6):
            self.b.send("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x + 12 * step, "y": y + 5 * step,
                                                     "button": "left", "buttons": 1})
        self.b.send("Input.dispatchMouseEvent", {"type": "mouseReleased", "x": x + 60, "y": y + 25,
                                                 "button": "left", "buttons": 0, "clickCount": 1})
        self.wait_render()
        orbited = self.compare_frame("beetle after a mouse drag (orbit)")
        args = self.page_args()
        if "--eye" not in args or orbited == before:
            raise Failure(f"dragging did not move the camera: {args}")
        eye = [float(v) for v in args[args.index("--eye") + 1].split(",")]
        target = [float(v) for v in args[args.index("--target") + 1].split(",")]
        dist = sum((a - b) ** 2 for a, b in zip(eye, target)) ** 0.5
        self.b.send("Input.dispatchMouseEvent", {"type": "mouseWheel", "x": x, "y": y, "deltaX": 0, "deltaY": -200})
        self.wait_render()
        self.compare_frame("beetle after the mouse wheel (zoom in)")
        args = self.page_args()
        eye = [float(v) for v in args[args.index("--eye") + 1].split(",")]
        closer = sum((a - b) ** 2 for a, b in zip(eye, target)) ** 0.5
        if not closer < dist * 0.9:
            raise Failure(f"zoom did not bring the eye closer ({dist} -> {closer})")
        url = self.b.evaluate("location.search")
        if "eye=" not in url:
            raise Failure(f"the URL does not keep the camera: {url}")
        # Touch: a two-finger pinch apart zooms in, a one-finger drag orbits.
        self.b.send("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 2})
        touch = lambda kind, points: self.b.send("Input.dispatchTouchEvent", {  # noqa: E731
            "type": kind, "touchPoints": [{"x": px, "y": py, "id": i} for i, (px, py) in enumerate(points)]})
        touch("touchStart", [(x - 30, y), (x + 30, y)])
        touch("touchMove", [(x - 45, y), (x + 45, y)])
        touch("touchMove", [(x - 60, y), (x + 60, y)])
        touch("touchEnd", [])
        self.wait_render()
        self.compare_frame("beetle after a two-finger pinch (zoom in)")
        args = self.page_args()
        eye = [float(v) for v in args[args.index("--eye") + 1].split(",")]
        pinched = sum((a - b) ** 2 for a, b in zip(eye, target)) ** 0.5
        if not pinched < closer * 0.75:
            raise Failure(f"pinch did not bring the eye closer ({closer} -> {pinched})")
        touch("touchStart", [(x, y)])
        touch("touchMove", [(x - 40, y - 20)])
        touch("touchEnd", [])
        self.wait_render()
        self.compare_frame("beetle after a one-finger drag (orbit)")
        if self.page_args() == args:
            raise Failure("a one-finger drag did not move the camera")

    def drop(self, name, data):
        b64 = base64.b64encode(data).decode()
        self.b.evaluate(f"""(() => {{
            const bytes = Uint8Array.from(atob('{b64}'), c => c.charCodeAt(0));
            const dt = new DataTransfer();
            dt.items.add(new File([bytes], {json.dumps(name)}));
            document.body.dispatchEvent(new DragEvent('drop', {{dataTransfer: dt, bubbles: true, cancelable: true}}));
        }})()""")
        return self.wait_render()

    def expect_native_error(self, label, name, data, via_input=False):
        folder = os.path.join(self.o.work, "dropped")
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, name)
        with open(path, "wb") as f:
            f.write(data)
        if via_input:
            doc = self.b.send("DOM.getDocument")["root"]["nodeId"]
            node = self.b.send("DOM.querySelector", {"nodeId": doc, "selector": "#file"})["nodeId"]
            self.b.send("DOM.setFileInputFiles", {"nodeId": node, "files": [path]})
            state = self.wait_render()
        else:
            state = self.drop(name, data)
        shown = self.b.evaluate("document.getElementById('error').textContent")
        run, _ = self.native(self.page_args(), cwd=folder)
        if run.returncode != 2:
            raise Failure(f"{label}: native hider-render exited {run.returncode}, expected 2")
        if state != "error" or shown != run.stderr.strip():
            raise Failure(f"{label}: page shows {shown!r} (state {state}), hider-render prints {run.stderr.strip()!r}")
        self.checked += 1
        print(f"  ok  {label}: {shown}", flush=True)

    def errors(self):
        self.navigate("model=teapot&algo=zbuffer&size=160x128")
        self.expect_native_error("face index out of range", "broken.obj", b"v 0 0 0\nv 1 0 0\nf 1 2 7\n")
        self.expect_native_error("vertex with two coordinates", "two coords.obj", b"v 0 0 0\nv 1 2\nf 1 2 1\n")
        self.expect_native_error("number out of range", "tiny.obj", b"v 1e-400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
        # Hex numbers past double's range: musl's strtod sets no ERANGE for them (web/compat/from_chars.cpp).
        self.expect_native_error("hex overflow", "hexbig.obj", b"v 0x1p1024 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
        self.expect_native_error("hex overflow by rounding", "hexround.obj",
                                 b"v 0x1.fffffffffffff8p1023 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
        self.expect_native_error("hex underflow", "hexsmall.obj", b"v 0x1p-1080 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
        self.expect_native_error("binary garbage", "garbage.obj", bytes(range(256)) * 4)
        self.expect_native_error("no faces, chosen with the file input", "nofaces.obj", b"v 1 2 3\n", via_input=True)
        if self.o.screenshots:
            self.screenshot("playground_error.png")
        # A subnormal coordinate is accepted by the host's from_chars: the page must agree and render.
        state = self.drop("subnormal.obj", b"v 1e-310 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n")
        if state != "done":
            raise Failure("subnormal coordinate: " + self.b.evaluate("document.getElementById('error').textContent"))
        # Coordinates near the ends of double's range render (the model is scaled into the world), the
        # same as natively: libc++'s three-argument std::hypot squares, and overflowed or underflowed here.
        folder = os.path.join(self.o.work, "dropped")
        for name, text in (("huge.obj", b"v 0 0 0\nv 2e154 0 0\nv 0 2e154 0\nf 1 2 3\n"),
                           ("minute.obj", b"v 1e-170 0 0\nv 3e-170 0 0\nv 1e-170 2e-170 0\nf 1 2 3\n")):
            with open(os.path.join(folder, name), "wb") as f:
                f.write(text)
            self.drop(name, text)
            self.compare_frame(f"dropped {name} (coordinates near double's limits)", cwd=folder)
        # The page recovers: a shipped model chosen in the select renders again.
        self.b.evaluate("(() => { const s = document.getElementById('model'); s.value = 'torus'; "
                        "s.dispatchEvent(new Event('change')); })()")
        self.wait_render()
        self.compare_frame("torus after the errors")

    def watchdog(self):
        state = self.navigate("model=teapot&algo=newell&size=320x240&timeout_ms=1")
        shown = self.b.evaluate("document.getElementById('error').textContent")
        if state != "error" or not shown.startswith("render stopped after 1 ms"):
            raise Failure(f"watchdog: state {state}, message {shown!r}")
        self.b.evaluate("(() => { const s = document.getElementById('size'); s.value = '160x128'; "
                        "s.dispatchEvent(new Event('change')); })()")
        state = self.wait_render()
        if state != "error" or self.b.evaluate("1 + 1") != 2:
            raise Failure("the page did not keep handling input after a stopped render")
        print("  ok  watchdog: a runaway render is stopped, the page keeps working", flush=True)

    def screenshot(self, name):
        png = base64.b64decode(self.b.send("Page.captureScreenshot", {"format": "png"})["data"])
        path = os.path.join(self.o.screenshots, name)
        with open(path, "wb") as f:
            f.write(png)
        print(f"  wrote {path}", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--site", required=True)
    ap.add_argument("--hider-render", required=True)
    ap.add_argument("--models", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    ap.add_argument("--screenshots")
    opts = ap.parse_args()
    opts.hider_render = os.path.abspath(opts.hider_render)
    if not os.path.exists(opts.chromium):
        print(f"{opts.chromium} not found: bash scripts/install-deps.sh all installs Debian's chromium")
        return 1
    shutil.rmtree(opts.work, ignore_errors=True)
    os.makedirs(opts.work)
    server, base_url = serve.start(opts.site)
    browser = Browser(opts.chromium, os.path.join(opts.work, "profile"), os.path.join(opts.work, "chromium.log"))
    start = time.monotonic()
    suite = Suite(opts, browser, base_url)
    try:
        browser.open_page()
        algos = suite.algorithms()
        suite.url_matrix(algos)
        suite.controls(algos)
        suite.errors()
        suite.watchdog()
    except Failure as e:
        print(f"FAIL: {e}", flush=True)
        print(f"(chromium log: {os.path.join(opts.work, 'chromium.log')})")
        return 1
    finally:
        browser.close()
        server.shutdown()
    print(f"{suite.checked} passed, 0 failed ({time.monotonic() - start:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
