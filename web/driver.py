#!/usr/bin/env python3
"""Drives the browser build in Debian's headless Chromium (chromium-driver + python3-selenium).

  driver.py render [--shading S] [--lighting L] [--subdivisions N] [--size WxH] [--depth D] ... < SCENE.json
      draws the scene read from standard input through the WebGL 2 build and writes the canvas's pixels
      (read back from the GL framebuffer, not a screenshot of the page) as an opaque PNG to standard output.
      No files: which files may be read and written, and how, is the command line's (`shadelab render`,
      src/io/), so that its rules have one implementation; the shell opens the redirections;
  driver.py session
      reads one JSON request per line on standard input and answers one JSON line each (tests/web/).

The page is served from build-web/site/ on 127.0.0.1 (an ephemeral port) for the run: wasm cannot be fetched
from file://. Exit codes as shadelab's: 0 success, 2 bad input (the page's message), 1 anything else.
Input is data: scene text and names reach the page only as JavaScript arguments, never as code.
"""
import base64
import functools
import http.server
import json
import os
import struct
import sys
import threading
import time
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve import PageHandler, PageServer  # noqa: E402  (the page's files only, as scripts/web.sh serve)

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build-web', 'site')
CHROME_ARGS = ['--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
               '--disable-dev-shm-usage', '--window-size=1280,800', '--force-device-scale-factor=1']




REQUEST_TIMEOUT = 60  # seconds: one WebDriver request, page load or script (the tests allow 240 s a session)


class TestFilesHandler(PageHandler):
    """The page's files, and for the browser tests (a session's "files" folder) two more places on the same
    origin: /files/NAME, that folder's files, and /stream/N.json (/stream/N-declared.json), a scene of N MiB
    sent in 1 MiB chunks without a Content-Length (with one saying N MiB), counting what it could send before
    the page hung up. Every path asked for is logged, so a test can tell a request that was never made."""
    files = None
    requested = []
    streamed = {}

    def send_head(self):
        self.requested.append(self.path)
        if self.path.startswith('/files/'):
            self.directory = self.files
            self.path = self.path[len('/files'):]
        return super().send_head()

    def do_GET(self):
        name = self.path[len('/stream/'):] if self.path.startswith('/stream/') else ''
        size = name[:-len('-declared.json')] if name.endswith('-declared.json') else name[:-len('.json')]
        if not size.isdigit():
            return super().do_GET()
        self.requested.append(self.path)
        mib = int(size)
        self.send_response(200)
        self.send_header('Content-Type', 'application/json')
        if name.endswith('-declared.json'):
            self.send_header('Content-Length', str(mib << 20))
        self.end_headers()
        sent = 0
        try:
            for _ in range(mib):
                self.wfile.write(b' ' * (1 << 20))
                sent += 1 << 20
        except ConnectionError:
            pass  # the page hung up: what it took is the point
        self.streamed[self.path] = sent
        self.close_connection = True


class Page:
    """One Chromium with the page loaded and ready (window.shadelab.ready)."""

    def __init__(self, root=ROOT, query='', extra_args=(), downloads=None, files=None, lessons=None):
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
        if not os.path.exists(os.path.join(root, 'shadelab.wasm')):
            raise RuntimeError(root + ' holds no browser build: run scripts/web.sh build')
        if files:
            handler_class = type('Handler', (TestFilesHandler,), {'files': os.path.abspath(files), 'requested': [],
                                                                  'streamed': {}})
            self.handler_class = handler_class
        else:
            handler_class = PageHandler
        if lessons:  # scripts/web.sh serve --lessons DIR: the folder under /own-lessons/
            handler_class = type('Handler', (handler_class,), {'lessons': os.path.realpath(lessons)})
        handler = functools.partial(handler_class, directory=root)
        self.server = PageServer(('127.0.0.1', 0), handler)
        threading.Thread(target=self.server.serve_forever, daemon=True).start()
        options = webdriver.ChromeOptions()
        options.binary_location = '/usr/bin/chromium'
        for arg in CHROME_ARGS + list(extra_args):
            options.add_argument(arg)
        options.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
        if downloads:
            options.add_experimental_option('prefs', {'download.default_directory': downloads,
                                                      'download.prompt_for_download': False})
        # Every request to chromedriver, every page load and every script has a deadline: a wedged browser
        # fails the call naming it instead of holding the test until its process is killed.
        from selenium.webdriver.remote.remote_connection import RemoteConnection
        RemoteConnection.set_timeout(REQUEST_TIMEOUT)
        self.browser = webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=options)
        self.browser.set_page_load_timeout(REQUEST_TIMEOUT)
        self.browser.set_script_timeout(REQUEST_TIMEOUT)
        if downloads:
            self.browser.execute_cdp_cmd('Browser.setDownloadBehavior',
                                         {'behavior': 'allow', 'downloadPath': downloads})
        self.console = []
        self.url = 'http://127.0.0.1:%d/index.html%s' % (self.server.server_address[1], query)
        self.browser.get(self.url)
        deadline = time.time() + 60
        while time.time() < deadline:
            state = self.js('return [window.shadelab.ready, window.shadelab.failed]')
            if state[0] or state[1]:
                break
            time.sleep(0.05)
        self.failed = self.js('return window.shadelab.failed || ""')
        if not self.failed and not self.js('return window.shadelab.ready'):
            raise RuntimeError('the page did not start within 60 s')

    def js(self, script, *args):
        return self.browser.execute_script(script, *args)

    def logs(self):
        self.console += [{'level': e['level'], 'message': e['message']} for e in self.browser.get_log('browser')]
        return self.console

    def close(self):
        try:
            self.browser.quit()
        finally:
            self.server.shutdown()

    def pointer(self, request):
        """A click, a move, or a drag by (dx, dy) in steps, at (x, y) CSS pixels from the canvas's centre, with
        Shift held when asked (Shift + drag moves the light)."""
        from selenium.webdriver.common.action_chains import ActionChains
        from selenium.webdriver.common.keys import Keys
        canvas = self.browser.find_element('id', 'canvas')
        chain = ActionChains(self.browser).move_to_element_with_offset(canvas, request.get('x', 0),
                                                                       request.get('y', 0))
        if request.get('shift'):
            chain = chain.key_down(Keys.SHIFT)
        if request['action'] == 'click':
            chain = chain.click()
        elif request['action'] == 'move':
            pass
        else:
            steps = request.get('steps', 8)
            chain = chain.click_and_hold()
            for _ in range(steps):
                chain = chain.move_by_offset(request['dx'] // steps, request['dy'] // steps)
            chain = chain.release()
        if request.get('shift'):
            chain = chain.key_up(Keys.SHIFT)
        chain.perform()
        time.sleep(0.2)

    def refitted(self):
        """The canvas once its drawing buffer matches its CSS size (the page refits it on a resize, which a
        loaded machine delivers late; at most 5 s): [width, height, clientWidth, clientHeight]. A page that
        never refits still fails the test that reads them."""
        measure = ('const c = document.getElementById("canvas"); const r = window.devicePixelRatio || 1;'
                   'return [c.width, c.height, c.clientWidth, c.clientHeight, r]')
        deadline = time.time() + 5
        time.sleep(0.3)
        canvas = self.js(measure)
        while time.time() < deadline and (canvas[0] != round(canvas[2] * canvas[4]) or
                                          canvas[1] != round(canvas[3] * canvas[4])):
            time.sleep(0.1)
            canvas = self.js(measure)
        return canvas[:4]

    def touch(self, request):
        """A gesture on the touch screen (Input.dispatchTouchEvent), at (x, y) CSS pixels from the canvas's
        centre: "tap"; "drag" by (dx, dy) in steps; "pinch": two fingers on a horizontal line about the
        point, from `from` to `to` pixels apart, in steps."""
        box = self.js('const r = document.getElementById("canvas").getBoundingClientRect();'
                      'return [r.left + r.width / 2, r.top + r.height / 2]')
        x, y = box[0] + request.get('x', 0), box[1] + request.get('y', 0)
        steps = request.get('steps', 4)

        def send(kind, points):
            self.browser.execute_cdp_cmd('Input.dispatchTouchEvent', {
                'type': kind, 'touchPoints': [{'x': px, 'y': py, 'id': i} for i, (px, py) in enumerate(points)]})

        if request['gesture'] == 'tap':
            send('touchStart', [(x, y)])
            send('touchEnd', [])
        elif request['gesture'] == 'drag':
            send('touchStart', [(x, y)])
            for k in range(1, steps + 1):
                send('touchMove', [(x + request['dx'] * k / steps, y + request['dy'] * k / steps)])
            send('touchEnd', [])
        else:
            half = lambda k: (request['from'] + (request['to'] - request['from']) * k / steps) / 2  # noqa: E731
            send('touchStart', [(x - half(0), y), (x + half(0), y)])
            for k in range(1, steps + 1):
                send('touchMove', [(x - half(k), y), (x + half(k), y)])
            send('touchEnd', [])
        time.sleep(0.2)

    def model_files(self, paths, drop):
        """The files at `paths` dropped on the canvas (a drop event carrying them, as a user's drag does) or
        picked with the model input (WebDriver types their paths into it, as a user picks them); returns the
        page's message once the page has loaded them (its count of model loads went up)."""
        before = self.js('return window.shadelab.modelLoads')
        if drop:
            files = []
            for path in paths:
                with open(path, 'rb') as f:
                    files.append([os.path.basename(path), base64.b64encode(f.read()).decode()])
            self.js('const transfer = new DataTransfer();'
                    'for (const [name, data] of arguments[0]) transfer.items.add(new File('
                    ' [Uint8Array.from(atob(data), (c) => c.charCodeAt(0))], name));'
                    'document.getElementById("canvas").dispatchEvent(new DragEvent("drop",'
                    ' {dataTransfer: transfer, bubbles: true, cancelable: true}));', files)
        else:
            self.browser.find_element('id', 'model-file').send_keys('\n'.join(os.path.abspath(p) for p in paths))
        deadline = time.time() + REQUEST_TIMEOUT
        while self.js('return window.shadelab.modelLoads') == before:
            if time.time() > deadline:
                raise RuntimeError('the page did not load the model files within %d s' % REQUEST_TIMEOUT)
            time.sleep(0.05)
        return self.js('return window.shadelab.message()')

    def quoted(self, text):
        """shadelab's quotedValue(), as the page has it (page_lesson.js)."""
        return self.js('return quotedValue(arguments[0])', text)

    def load(self, text, name):
        return self.js('return window.shadelab.loadText(arguments[0], arguments[1])', text, name)

    def flags(self, flags):
        return self.js('return window.shadelab.applyFlags(arguments[0])', flags) if flags else ''

    def capture(self, width=0, height=0, kind='rgba8'):
        """The picture drawn again into the program's own framebuffer, read back in bands of at most 8 MB
        each, so no single script call nears its timeout (8192x8192 is 268 MB of RGBA)."""
        from selenium.common.exceptions import JavascriptException
        try:
            shot = self.js('return window.shadelab.captureStart(arguments[0], arguments[1], arguments[2])',
                           width, height, kind)
            rows = max(1, (8 << 20) // max(1, shot['rowBytes']))
            data = bytearray()
            for y in range(0, shot['height'], rows):
                data += base64.b64decode(self.js('return window.shadelab.captureRows(arguments[0], arguments[1])',
                                                 y, min(rows, shot['height'] - y)))
        except JavascriptException as e:  # the renderer's own message (e.g. a feature WebGL 2 lacks)
            message = (e.msg or str(e)).split('\n')[0]
            raise RuntimeError(message.replace('javascript error: ', '', 1)) from None
        return shot['width'], shot['height'], bytes(data)


def png_bytes(width, height, rgba):
    """An opaque 8-bit RGB PNG (alpha dropped, as shadelab writes them)."""
    rgb = bytearray(width * height * 3)
    for c in range(3):
        rgb[c::3] = rgba[c::4]
    stride = width * 3
    rows = bytearray((stride + 1) * height)  # each row: filter type 0, then its samples
    for y in range(height):
        rows[y * (stride + 1) + 1:(y + 1) * (stride + 1)] = rgb[y * stride:(y + 1) * stride]

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))

    header = struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) + chunk(b'IDAT', zlib.compress(bytes(rows), 6)) +
            chunk(b'IEND', b''))


def render(argv):
    # Every option takes a value; which names are flags the page says (the program's one table of them,
    # window.shadelab.tables().flags), once it has started. Anything else (a scene file, --out) is a file,
    # which only the command line reads and writes.
    flags = {}
    i = 0
    while i < len(argv):
        arg = argv[i]
        if not arg.startswith('--') or arg.split('=', 1)[0] == '--out':
            return fail(2, 'scripts/web.sh render reads the scene from standard input and writes the PNG to '
                        'standard output (scripts/web.sh render [flags] < SCENE.json > FILE.png); for files, '
                        'shadelab render SCENE.json --out FILE.png')
        name = arg[2:].split('=', 1)[0]
        if '=' in arg:
            flags[name] = arg.split('=', 1)[1]
        elif i + 1 < len(argv):
            i += 1
            flags[name] = argv[i]
        else:
            flags[name] = None
        i += 1
    page = Page()
    try:
        if page.failed:
            return fail(1, page.failed)
        tables = page.js('return window.shadelab.tables()')
        for name, value in flags.items():
            if name not in tables['flags']:
                return fail(2, 'unknown option %s; render takes --%s' % (page.quoted('--' + name),
                                                                          ', --'.join(tables['flags'])), page)
            if value is None:
                return fail(2, '%s needs a value' % page.quoted('--' + name), page)
        # At most one byte past the command line's bound; beyond it the page's message for a scene file too
        # large to read (page_lesson.js tooLargeMessage, naming standard input as the command line does
        # while it reads), without handing the page 16 MiB it would refuse.
        text = sys.stdin.buffer.read(tables['maxSceneBytes'] + 1)
        if len(text) > tables['maxSceneBytes']:
            return fail(2, page.js('return tooLargeMessage(arguments[0])', 'standard input'), page)
        message = page.load(text.decode('utf-8', errors='replace'), '-') or page.flags(flags)
        if message:
            return fail(2, message, page)
        width, height, rgba = page.capture()
        sys.stdout.buffer.write(png_bytes(width, height, rgba))
        sys.stdout.buffer.flush()
        return 0
    finally:
        page.close()


def session():
    """Requests: {"op": "open", "query": "?…", "args": [...], "lessons": DIR} first, then load, flags, key,
    pointer, touch, ui, capture, message, resize, phone, layout, screenshot, console, quit."""
    page = None
    for line in sys.stdin:
        request = json.loads(line)
        op = request['op']
        try:
            if op == 'open':
                if page:
                    page.close()
                page = Page(query=request.get('query', ''), extra_args=request.get('args', []),
                            downloads=request.get('downloads'), files=request.get('files'),
                            lessons=request.get('lessons'))
                answer = {'failed': page.failed}
            elif op == 'load':
                answer = {'message': page.load(request['text'], request['name'])}
            elif op == 'load-file':  # a scene too large for one request line (tests/web/)
                with open(request['path'], encoding='utf-8') as scene:
                    answer = {'message': page.load(scene.read(), request['name'])}
            elif op == 'load-url':  # as the picker loads a bundled scene: fetched by the page
                answer = {'message': page.js('return window.shadelab.loadUrl(arguments[0])', request['url'])}
            elif op == 'served':  # what the test files' server was asked for and sent (TestFilesHandler)
                answer = {'requested': page.handler_class.requested, 'streamed': page.handler_class.streamed}
            elif op == 'flags':
                answer = {'message': page.flags(request['flags'])}
            elif op == 'key':
                answer = {'result': page.js('return window.shadelab.press(arguments[0])', request['code'])}
            elif op == 'panel':  # a control of the panel set as a user would: value, then its event
                answer = {'found': page.js(
                    'const e = document.querySelector(arguments[0]); if (!e) return false;'
                    'e.value = arguments[1]; e.dispatchEvent(new Event(arguments[2])); return true;',
                    request['selector'], request['value'], request.get('event', 'change'))}
            elif op == 'element':  # what a user sees of one element: shown or not, its text, value, wrapping
                answer = {'element': page.js(
                    'const e = document.querySelector(arguments[0]);'
                    'return e ? {hidden: e.hidden, text: e.textContent, value: e.value === undefined ? null :'
                    ' String(e.value), whiteSpace: getComputedStyle(e).whiteSpace} : null;', request['selector'])}
            elif op == 'menus':  # every <select> of the panel: its id and its options' values and labels
                answer = {'menus': page.js(
                    'return Array.from(document.querySelectorAll("select")).map((s) => ({id: s.id,'
                    ' values: Array.from(s.options).map((o) => o.value),'
                    ' labels: Array.from(s.options).map((o) => o.textContent)}));')}
            elif op == 'sleep':  # lets the page's own timers run (a notice that goes away by itself)
                time.sleep(min(float(request['seconds']), 30))
                answer = {}
            elif op == 'pointer':  # real mouse input through WebDriver, offsets from the canvas's centre
                answer = {}
                page.pointer(request)
            elif op == 'touch':  # a tap, a one-finger drag or a pinch (Page.touch)
                answer = {}
                page.touch(request)
            elif op in ('drop-files', 'pick-files'):  # model files dropped on the canvas or picked
                answer = {'message': page.model_files(request['paths'], op == 'drop-files')}
            elif op == 'click-element':  # a real click on a control of the page (it takes the focus)
                from selenium.webdriver.common.action_chains import ActionChains
                ActionChains(page.browser).click(page.browser.find_element('css selector', request['selector'])) \
                    .perform()
                time.sleep(0.2)
                answer = {}
            elif op == 'layout':  # where things are: the viewport, the page's width, each element's box and
                # the box of the fieldset around it
                answer = {'layout': page.js(
                    'const box = (e) => { const r = e.getBoundingClientRect(); return {left: r.left, right: r.right,'
                    ' top: r.top, bottom: r.bottom, width: r.width, height: r.height, scrollWidth: e.scrollWidth,'
                    ' clientWidth: e.clientWidth}; };'
                    'const found = {}; for (const s of arguments[0]) { const e = document.querySelector(s);'
                    ' found[s] = e ? box(e) : null;'
                    ' if (e && e.closest("fieldset")) found[s].fieldset = box(e.closest("fieldset")); }'
                    'return {innerWidth: innerWidth, innerHeight: innerHeight, ratio: devicePixelRatio,'
                    ' scrollWidth: document.documentElement.scrollWidth, elements: found};',
                    request['selectors'])}
            elif op == 'mutate-shader':  # a test's mutation: every shader compiled from now on has `from`
                # replaced by `to` (WebGL's shaderSource); how many sources it changed is in "shaderMutations"
                page.js('const from = arguments[0], to = arguments[1]; window.shadelab.shaderMutations = 0;'
                        'const original = WebGL2RenderingContext.prototype.shaderSource;'
                        'WebGL2RenderingContext.prototype.shaderSource = function (shader, text) {'
                        ' if (text.includes(from)) { ++window.shadelab.shaderMutations; text = text.split(from).join(to); }'
                        ' return original.call(this, shader, text); };', request['from'], request['to'])
                answer = {}
            elif op == 'shader-mutations':
                answer = {'count': page.js('return window.shadelab.shaderMutations || 0')}
            elif op == 'wait-ui':  # until the page's state has `value` at `path` (keys), at most 20 s
                deadline = time.time() + 20
                while True:
                    found = page.js('let v = window.shadelab.ui(); for (const k of arguments[0])'
                                    ' v = v === null || v === undefined ? v : v[k]; return v === undefined ? null : v;',
                                    request['path'])
                    if found == request['value'] or time.time() > deadline:
                        break
                    time.sleep(0.1)
                answer = {'found': found}
            elif op == 'ui':
                answer = {'ui': page.js('return window.shadelab.ui()')}
            elif op == 'message':
                answer = {'message': page.js('return window.shadelab.message()')}
            elif op == 'capture':
                width, height, data = page.capture(request.get('width', 0), request.get('height', 0),
                                                   request.get('kind', 'rgba8'))
                answer = {'width': width, 'height': height, 'data': base64.b64encode(data).decode()}
            elif op == 'resize':
                page.browser.set_window_size(request['width'], request['height'])
                answer = {'canvas': page.refitted()}
            elif op == 'phone':  # Chromium's mobile emulation: the screen, its pixel ratio, a touch screen
                page.browser.execute_cdp_cmd('Emulation.setDeviceMetricsOverride', {
                    'width': request['width'], 'height': request['height'],
                    'deviceScaleFactor': request.get('scale', 1), 'mobile': True})
                page.browser.execute_cdp_cmd('Emulation.setTouchEmulationEnabled', {'enabled': True,
                                                                                    'maxTouchPoints': 5})
                answer = {'canvas': page.refitted()}
            elif op == 'wait-files':  # downloads land asynchronously
                deadline = time.time() + request.get('seconds', 20)
                paths = request['paths']
                while time.time() < deadline and not all(os.path.exists(p) for p in paths):
                    time.sleep(0.1)
                answer = {'present': [os.path.exists(p) for p in paths]}
            elif op == 'screenshot':
                page.browser.save_screenshot(request['path'])
                answer = {}
            elif op == 'console':
                answer = {'console': page.logs()}
            elif op == 'quit':
                break
            else:
                raise ValueError('unknown op ' + op)
            answer['ok'] = True
        except Exception as e:  # the test reads the reason
            answer = {'ok': False, 'error': '%s: %s' % (type(e).__name__, e)}
        sys.stdout.write(json.dumps(answer) + '\n')
        sys.stdout.flush()
    if page:
        page.close()
    return 0


def fail(code, message, page=None):
    """As shadelab's main: the message with control bytes escaped (newlines and tabs kept) by the page's
    printable() (shadelab's, in page_lesson.js); the driver's own messages name no input without a page."""
    if page is not None and not page.failed:
        message = page.js('return arguments[0].split("\\n").map((l) => l.split("\\t").map(printable)'
                          '.join("\\t")).join("\\n")', str(message))
    sys.stderr.write('shadelab: %s\n' % message)
    return code


def main():
    if len(sys.argv) >= 2 and sys.argv[1] == 'render':
        try:
            return render(sys.argv[2:])
        except Exception as e:
            return fail(1, '%s' % e)
    if len(sys.argv) == 2 and sys.argv[1] == 'session':
        return session()
    return fail(2, 'usage: driver.py render [flags] < SCENE.json > FILE.png | driver.py session')


if __name__ == '__main__':
    sys.exit(main())
