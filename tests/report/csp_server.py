"""A static file server for the report's browser test: sends Jenkins' default
Content-Security-Policy with every response and logs every request as "STATUS PATH".

Usage: csp_server.py ROOT PORT_FILE LOG_FILE
Listens on 127.0.0.1 (a free port, written to PORT_FILE once listening) and stops by itself
after 120 s, so a test that dies cannot leave it running.
"""
import functools
import os
import http.server
import sys
import threading

CSP = "sandbox allow-same-origin; default-src 'none'; img-src 'self'; style-src 'self';"


class Handler(http.server.SimpleHTTPRequestHandler):
    log_file = None

    def end_headers(self):
        self.send_header("Content-Security-Policy", CSP)
        self.send_header("Cache-Control", "no-store")
        super().end_headers()

    def log_request(self, code="-", size="-"):
        with open(self.log_file, "a", encoding="utf-8") as log:
            log.write(f"{int(code) if str(code).isdigit() else code} {self.path}\n")

    def log_message(self, format, *args):  # noqa: A002 - keep stderr quiet
        pass


def main():
    root, port_file, log_file = sys.argv[1:4]
    Handler.log_file = log_file
    handler = functools.partial(Handler, directory=root)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Timer(120.0, server.shutdown).start()
    with open(port_file + ".tmp", "w", encoding="utf-8") as out:
        out.write(str(server.server_address[1]))
    os.replace(port_file + ".tmp", port_file)
    server.serve_forever()


if __name__ == "__main__":
    main()
