#!/usr/bin/env python3
"""Serves the page (build-web/site/) on 127.0.0.1, as scripts/web.sh serve and web/driver.py do.

Only the page's own files: regular files under the site folder, never a folder listing, never a file that a
link leads outside the folder. Every response says no-store, so a rebuilt page is never stale.
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
        real = os.path.realpath(self.translate_path(self.path))
        if os.path.commonpath([root, real]) != root or not os.path.exists(real):
            self.send_error(404, 'Not found')
            return None
        return super().send_head()


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
        server = http.server.ThreadingHTTPServer(('127.0.0.1', int(port)), handler)
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
