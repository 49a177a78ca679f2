#!/usr/bin/env python3
"""Serves the page (build-web/site/) on 127.0.0.1, as scripts/web.sh serve and web/driver.py do.

Only the page's own files: regular files under the site folder, never a folder listing, never a file that a
link leads outside the folder. Every response says no-store, so a rebuilt page is never stale. A path the
file system cannot name (a NUL byte) is a 400; a client that hangs up mid-answer is nobody's error.
With --lessons DIR, a lecturer's folder is served under /own-lessons/ by the same rules (nothing a link
leads outside DIR, no listing), and /own-lessons/index.json lists its lessons (the JSON files at its top
whose object has "steps"), read again at each request: a lesson put there shows in the page's picker on
the next load, without a rebuild.
    python3 web/serve.py SITE_FOLDER PORT [--lessons DIR]
"""
import http.server
import io
import json
import os
import sys

OWN_LESSONS = '/own-lessons/'  # the page's kOwnLessons (page_core.js)
MAX_LESSON_BYTES = 16 << 20  # a scene or lesson file's bound on the command line (scene.h kMaxSceneBytes)


def shown(text):
    """A name for the terminal: control characters and bytes that are no UTF-8 as escapes."""
    return text.encode('unicode_escape', errors='backslashreplace').decode('ascii')


def lesson_names(folder, warn=None):
    """The lessons at the top of `folder`: plain names (UTF-8, no leading dot) of regular files ending in
    .json, inside the folder once links are followed, at most 16 MiB, whose JSON is an object with
    "steps". `warn(text)` hears why a .json file is left out, when it may be a lesson gone wrong."""
    root = os.path.realpath(folder)
    names = []
    for name in sorted(os.listdir(root)):
        path = os.path.join(root, name)
        try:
            name.encode('utf-8')
        except UnicodeEncodeError:  # a name that is no UTF-8: the page could not ask for it by URL
            continue
        if name.startswith('.') or not name.endswith('.json') or name == 'index.json':
            continue
        real = os.path.realpath(path)
        if os.path.commonpath([root, real]) != root or not os.path.isfile(real):
            continue
        if os.path.getsize(real) > MAX_LESSON_BYTES:
            if warn:
                warn('%s: larger than 16 MiB, not listed' % shown(name))
            continue
        try:
            with open(real, 'rb') as f:
                parsed = json.loads(f.read().decode('utf-8-sig'))
        except (OSError, ValueError) as e:
            if warn:
                warn('%s: not listed: %s' % (shown(name), e))
            continue
        if isinstance(parsed, dict) and 'steps' in parsed:
            names.append(name)
    return names


class PageHandler(http.server.SimpleHTTPRequestHandler):
    lessons = None  # the folder served under /own-lessons/ (--lessons DIR), or None

    def log_message(self, *args):
        pass

    def end_headers(self):
        self.send_header('Cache-Control', 'no-store')
        super().end_headers()

    def list_directory(self, path):
        self.send_error(404, 'Not found')
        return None

    def send_head(self):
        # The list is there without --lessons too (empty): the page asks for it at every start.
        if self.path.split('?', 1)[0] == OWN_LESSONS + 'index.json':
            return self.send_lesson_list()
        if self.lessons is not None and self.path.startswith(OWN_LESSONS):
            # The rest is a path inside DIR: translate_path drops any .. and realpath follows the links.
            self.directory = self.lessons
            self.path = self.path[len(OWN_LESSONS) - 1:]
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


    def send_lesson_list(self):
        names = lesson_names(self.lessons) if self.lessons is not None else []
        body = (json.dumps(names) + '\n').encode('utf-8')
        self.send_response(200)
        self.send_header('Content-Type', 'application/json')
        self.send_header('Content-Length', str(len(body)))
        self.end_headers()
        return io.BytesIO(body)


class PageServer(http.server.ThreadingHTTPServer):
    # A browser that closes a tab or cancels a download resets the connection while its answer is written:
    # that is the client's choice, not the server's failure, so no traceback on standard error. Anything
    # else is still printed by socketserver.
    def handle_error(self, request, client_address):
        if isinstance(sys.exc_info()[1], (BrokenPipeError, ConnectionResetError, ConnectionAbortedError)):
            return
        super().handle_error(request, client_address)


def main(argv):
    lessons = None
    if len(argv) == 5 and argv[3] == '--lessons':
        lessons = argv[4]
        if not os.path.isdir(lessons):
            print("shadelab: serve: --lessons must name a folder of lesson files, got '%s' (%s); give the "
                  "folder that holds your lessons" % (shown(lessons),
                                                      'no such folder' if not os.path.exists(lessons)
                                                      else 'not a folder'), file=sys.stderr)
            return 2
        lessons = os.path.realpath(lessons)
    elif len(argv) != 3:
        print('usage: serve.py SITE_FOLDER PORT [--lessons DIR]', file=sys.stderr)
        return 2
    site, port = argv[1], argv[2]
    if not (port.isdigit() and 1 <= int(port) <= 65535):
        print("shadelab: serve: PORT must be a number in 1..65535, got '%s'" % port.encode('unicode_escape')
              .decode('ascii'), file=sys.stderr)
        return 2
    handler_class = type('Handler', (PageHandler,), {'lessons': lessons})
    handler = lambda *args, **kwargs: handler_class(*args, directory=site, **kwargs)  # noqa: E731
    try:
        server = PageServer(('127.0.0.1', int(port)), handler)
    except OSError as e:
        print('shadelab: serve: cannot listen on 127.0.0.1:%s: %s' % (port, e.strerror), file=sys.stderr)
        return 1
    if lessons is not None:
        warnings = []
        names = lesson_names(lessons, warnings.append)
        for warning in warnings:
            print('shadelab: serve: warning: %s' % warning, file=sys.stderr)
        print('shadelab: %d lesson(s) from %s in the picker as "own lesson: NAME" (%s)'
              % (len(names), shown(lessons), ', '.join(map(shown, names)) or 'none yet: put LESSON.json files there'), flush=True)
    print('shadelab: open http://127.0.0.1:%s/ (Ctrl-C stops the server)' % port, flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
