#!/usr/bin/env python3
"""Serves the page (build-web/site/) on 127.0.0.1, as scripts/web.sh serve and web/driver.py do.

Only the page's own files: regular files under the site folder, never a folder listing, never a file that a
link leads outside the folder. Every response says no-store, so a rebuilt page is never stale. A path the
file system cannot name (a NUL byte) is a 400; a client that hangs up mid-answer is nobody's error.
    python3 web/serve.py SITE_FOLDER PORT
"""
import http.server
import os
import sys


class PageHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass

    def end_headers(self):
        self.send_header('Cache-Control', 'no-store')
        super().end_headers()

    def list_directory(self, path):
        self.send_error(404, 'Not found')
        return None

    def send_head(self):
        root = os.path.realpath(self.directory)
        try:
            real = os.path.realpath(self.translate_path(self.path))
        except ValueError:  # "embedded null byte": /%00 names no file; realpath's raise closed the connection
            self.send_error(400, 'Bad path: it holds a NUL byte (%00)')
            return None
        if os.path.commonpath([root, real]) != root or not os.path.exists(real):
            self.send_error(404, 'Not found')
            return None
        return super().send_head()


class PageServer(http.server.ThreadingHTTPServer):
    # A browser that closes a tab or cancels a download resets the connection while its answer is written:
    # that is the client's choice, not the server's failure, so no traceback on standard error. Anything
    # else is still printed by socketserver.
    def handle_error(self, request, client_address):
        if isinstance(sys.exc_info()[1], (BrokenPipeError, ConnectionResetError, ConnectionAbortedError)):
            return
        super().handle_error(request, client_address)


def main(argv):
    if len(argv) != 3:
        print('usage: serve.py SITE_FOLDER PORT', file=sys.stderr)
        return 2
    site, port = argv[1], argv[2]
    if not (port.isdigit() and 1 <= int(port) <= 65535):
        print("shadelab: serve: PORT must be a number in 1..65535, got '%s'" % port.encode('unicode_escape')
              .decode('ascii'), file=sys.stderr)
        return 2
    handler = lambda *args, **kwargs: PageHandler(*args, directory=site, **kwargs)  # noqa: E731
    try:
        server = PageServer(('127.0.0.1', int(port)), handler)
    except OSError as e:
        print('shadelab: serve: cannot listen on 127.0.0.1:%s: %s' % (port, e.strerror), file=sys.stderr)
        return 1
    print('shadelab: open http://127.0.0.1:%s/ (Ctrl-C stops the server)' % port, flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
