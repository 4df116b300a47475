#!/usr/bin/env python3
"""Serves the playground site on 127.0.0.1 (Python's standard library only).

Usage: serve.py SITE_DIR [PORT]   (absent: 8000; 0: a free port, printed; the test uses 0)
WebAssembly needs the application/wasm and JavaScript module types, which older Pythons do not map.
"""
import functools
import http.server
import sys
import threading


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".wasm": "application/wasm",
        ".js": "text/javascript",
        ".json": "application/json",
        ".obj": "text/plain",
    }

    def end_headers(self):
        self.send_header("Cache-Control", "no-store")  # a rebuilt module is picked up on reload
        super().end_headers()

    def log_message(self, *args):
        if not getattr(self.server, "quiet", False):
            super().log_message(*args)


def start(site_dir, port=0, quiet=True):
    """Starts a server thread; returns (server, base_url)."""
    handler = functools.partial(Handler, directory=site_dir)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", port), handler)
    server.quiet = quiet
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    port = int(sys.argv[2]) if len(sys.argv) == 3 else 8000
    server, url = start(sys.argv[1], port, quiet=False)
    print(f"hider playground: {url}index.html  (Ctrl-C stops)", flush=True)
    try:
        threading.Event().wait()
    except KeyboardInterrupt:
        server.shutdown()


if __name__ == "__main__":
    main()
