// The module's start (WebGL 2 first, then shadelab.js), the calls into C++, scene and lesson loading, and
// the canvas's size. Loaded last of the page's scripts (page_core.js says the order).
'use strict';

// ---- WebGL 2 first: without it the module is not even loaded ----
function hasWebGl2() {
  try {
    return !!document.createElement('canvas').getContext('webgl2');
  } catch (e) {
    return false;
  }
}


var Module = {
  canvas: $('canvas'),
  print: (text) => console.log(text),
  printErr: (text) => console.warn(text),
  onAbort: (what) => shadelabFatal('shadelab stopped: ' + what),
};

if (!hasWebGl2()) {
  shadelabFatal('This browser offers no WebGL 2, which shadelab needs to draw. Try a current Chrome, ' +
                'Firefox or Safari, and check that hardware acceleration (or WebGL) is not switched off.');
} else {
  const script = document.createElement('script');
  script.src = 'shadelab.js';
  script.onerror = () => shadelabFatal('shadelab.js could not be loaded: serve this folder over HTTP ' +
                                       '(scripts/web.sh serve); wasm cannot be fetched from file://');
  document.body.appendChild(script);
}

// ---- calls into C++ ----
// Text handed to the C++ through the heap (malloc, copy, free): cwrap copies a 'string' argument onto
// the wasm stack, which a scene over about 1.3 MB overflowed ("memory access out of bounds", the page
// dead until reloaded). The C++ refuses more than the command line's 16 MiB with the command line's
// message; what the heap cannot hold is said here.
function viaHeap(text, call) {
  const size = Module.lengthBytesUTF8(text) + 1;
  let pointer = 0;
  try {
    pointer = Module._malloc(size);
  } catch (e) {
    pointer = 0;
  }
  if (!pointer) return 'the page has no memory for ' + size + ' bytes of text';
  try {
    Module.stringToUTF8(text, pointer, size);
    return call(pointer);
  } finally {
    Module._free(pointer);
  }
}

function bind() {
  const c = (name, ret, args) => Module.cwrap(name, ret, args);
  const load = c('shadelab_load_scene', 'string', ['number', 'string']);
  const lesson = c('shadelab_load_lesson', 'string', ['number', 'string', 'number']);
  const flags = c('shadelab_apply_flags', 'string', ['number']);
  const edit = c('shadelab_edit_settings', 'string', ['number']);
  const material = c('shadelab_edit_material', 'string', ['number']);
  return {
    loadScene: (text, name) => viaHeap(text, (pointer) => load(pointer, name)),
    loadLesson: (text, name, files) =>
      viaHeap(text, (pointer) => viaHeap(JSON.stringify(files), (filesPointer) => lesson(pointer, name, filesPointer))),
    applyFlags: (text) => viaHeap(text, flags),
    editSettings: (text) => viaHeap(text, edit),
    editMaterial: (text) => viaHeap(text, material),
    chooseObject: c('shadelab_choose_object', null, ['number']),
    editScale: c('shadelab_edit_scale', 'string', ['number', 'number', 'number']),
    editViewVolume: c('shadelab_edit_view_volume', 'string', ['string']),
    key: c('shadelab_key', 'number', ['number']),
    drag: c('shadelab_drag', null, ['number', 'number']),
    zoom: c('shadelab_zoom', null, ['number']),
    dragLight: c('shadelab_drag_light', null, ['number', 'number']),
    probe: c('shadelab_probe', 'string', ['number', 'number']),
    pointer: c('shadelab_pointer', null, ['number', 'number', 'number']),
    setMatch: c('shadelab_set_match_highlight', null, ['number']),
    redraw: c('shadelab_redraw', null, []),
    // The panel's values without the scenes' objects (twice a second), and everything with them.
    panelText: () => Module.ccall('shadelab_panel', 'string', [], []),
    panel: () => JSON.parse(Module.ccall('shadelab_panel', 'string', [], [])),
    ui: () => JSON.parse(Module.ccall('shadelab_ui', 'string', [], [])),
    capture: c('shadelab_capture', 'number', ['number', 'number']),
    captureFloat: c('shadelab_capture_float', 'number', ['number', 'number']),
    captureWidth: c('shadelab_capture_width', 'number', []),
    captureHeight: c('shadelab_capture_height', 'number', []),
    tables: () => JSON.parse(Module.ccall('shadelab_tables', 'string', [], [])),
  };
}

// Called by main.cpp once the WebGL 2 context and the renderer exist.
async function shadelabStarted() {
  api = bind();
  tables = api.tables(); // the flags, the levels and the keys, as the program has them
  $('level').max = tables.maxSubdivisions;
  fitCanvas();
  new ResizeObserver(fitCanvas).observe($('view'));
  wireControls();
  const names = await fetch('scenes/index.json').then((r) => r.json()).catch(() => []);
  const lessons = await fetch('lessons/index.json').then((r) => r.json()).catch(() => []);
  $('bundled').add(new Option('(another scene)', ''));
  for (const name of names) $('bundled').add(new Option(name, name));
  // The bundled lessons after the scenes, each as "lesson: NAME".
  for (const name of lessons) $('bundled').add(new Option('lesson: ' + name, 'lesson:' + name));
  const url = params.get('scene');
  const lessonUrl = params.get('lesson');
  let message = '';
  try {
    message = await loadStartingScene(url, lessonUrl, names, lessons);
  } catch (e) {
    // Whatever a URL did, the page starts and says it: an exception here left it never ready and silent.
    message = (lessonUrl || url) + ': cannot load it (' + e.message + ')';
  }
  if (!message) message = applyUrlFlags();
  // ?present (for a class): the presentation label on and larger panel text; ?ui-scale=S scales the panel.
  if (params.has('present')) press(tables.keys.F2);
  const scale = Number(params.get('ui-scale') || (params.has('present') ? 1.75 : 1));
  if (scale >= 0.5 && scale <= 4) $('panel').style.zoom = scale;
  showMessage(message);
  refresh();
  window.shadelab.ready = true;
  // The title's frame time, and what changed without a control (a draw error): twice a second, and only
  // when the panel's values changed, since rewriting unchanged text still repaints the page (an idle page
  // took 12 % of a core in headless Chromium doing that).
  setInterval(() => refresh(true), 500);
}

// The scene or lesson the page opens with (?lesson=URL, ?scene=URL or the showcase), the picker set to it.
async function loadStartingScene(url, lessonUrl, names, lessons) {
  let message = '';
  if (lessonUrl) {
    message = await loadUrl(lessonUrl);
    const bundled = lessons.find((name) => lessonUrl === 'lessons/' + name || lessonUrl === './lessons/' + name);
    $('bundled').value = bundled ? 'lesson:' + bundled : '';
  } else if (url) {
    message = await loadUrl(url);
    // The picker names the scene shown: a bundled one by its name, anything else as another scene.
    const bundled = names.find((name) => url === 'scenes/' + name || url === './scenes/' + name);
    $('bundled').value = bundled || '';
  } else {
    $('bundled').value = 'showcase.json';
    message = await loadUrl('scenes/showcase.json', 'showcase.json');
  }
  return message;
}

// The command-line flags, given as ?shading=flat&size=256x256…, through the CLI's own parser.
function applyUrlFlags() {
  const flags = {};
  for (const name of tables.flags)
    if (params.has(name)) flags[name] = params.get(name);
  return Object.keys(flags).length ? api.applyFlags(JSON.stringify(flags)) : '';
}

// ---- scenes and lessons from URLs ----
// The command line's bounds (include/shadelab/scene/scene.h kMaxSceneBytes, scene/lesson.h
// kMaxLessonSceneBytes): a scene file at most 16 MiB, and a lesson's steps at most 64 MiB of scene text in
// all, each step counting its whole scene — so its distinct files together too, as each is some step's.
// The page stops reading at them: a hostile lesson (15 steps of 40 MB each ended in a RangeError after
// 1.3 GB) costs at most what the command line would read.
const kMaxSceneBytes = 16 << 20;
const kMaxLessonSceneBytes = 64 << 20;
const kMiB = 1 << 20;

// The text at `url`, read at most to `limit` bytes: {text, bytes}, {tooLarge: true}, {status} for an HTTP
// error. A Content-Length over the limit is refused before the body is read (it is the size on the wire, so
// only when the body is not compressed); a body without one is read chunk by chunk and cancelled as soon as
// it passes the limit. Throws what fetch throws (no network, a URL fetch rejects), and gives up on a server
// that has not sent the whole body within kFetchSeconds: nothing waits without a deadline.
const kFetchSeconds = 60;
async function fetchBounded(url, limit) {
  const controller = new AbortController();
  const timer = setTimeout(
    () => controller.abort(new Error('no complete answer within ' + kFetchSeconds + ' s')), kFetchSeconds * 1000);
  try {
    return await readBounded(await fetch(url, {signal: controller.signal}), limit);
  } finally {
    clearTimeout(timer);
  }
}

async function readBounded(response, limit) {
  const stop = () => response.body && response.body.cancel().catch(() => {});
  if (!response.ok) {
    stop();
    return {status: response.status};
  }
  const encoding = (response.headers.get('Content-Encoding') || 'identity').toLowerCase();
  if (encoding === 'identity' && Number(response.headers.get('Content-Length')) > limit) {
    stop();
    return {tooLarge: true};
  }
  const chunks = [];
  let bytes = 0;
  if (response.body) {
    const reader = response.body.getReader();
    for (;;) {
      const {done, value} = await reader.read();
      if (done) break;
      bytes += value.byteLength;
      if (bytes > limit) {
        reader.cancel().catch(() => {});
        return {tooLarge: true};
      }
      chunks.push(value);
    }
  }
  const whole = new Uint8Array(bytes);
  let at = 0;
  for (const chunk of chunks) {
    whole.set(chunk, at);
    at += chunk.byteLength;
  }
  return {text: new TextDecoder().decode(whole), bytes}; // as response.text() decodes: UTF-8, BOM dropped
}

// The command line's message for a scene file over 16 MiB (scene_json.cpp checkSceneTextSize).
function tooLargeMessage(name) {
  return printable(name) + ': cannot read scene file: larger than ' + (kMaxSceneBytes >> 20) + ' MiB; not a scene file';
}

// Loads the scene or lesson at `url`; "" or the message shown. A lesson's scene files are fetched beside it,
// as the command line reads them beside the lesson file.
async function loadUrl(url, name) {
  name = name || fileNameOf(url);
  let got;
  try {
    got = await fetchBounded(url, kMaxSceneBytes);
  } catch (e) {
    return showLoadMessage(url + ': cannot fetch the scene (' + e.message + ')');
  }
  if (got.status) return showLoadMessage(url + ': cannot fetch the scene (HTTP ' + got.status + ')');
  if (got.tooLarge) return showLoadMessage(tooLargeMessage(name));
  let base = null;
  try {
    base = new URL(url, location.href).href;
  } catch (e) {
    base = null; // fetched, yet no URL: the steps are named as unfetchable by lessonFiles
  }
  return loadText(got.text, name, {base});
}

// A message shown as loadText shows one, for a load that never reached the C++.
function showLoadMessage(message) {
  showMessage(message);
  refresh();
  return message;
}

// A lesson rather than a scene: a JSON object with "steps" (as isLessonText in C++ decides).
function lessonOf(text) {
  try {
    const parsed = JSON.parse(text);
    return parsed && typeof parsed === 'object' && !Array.isArray(parsed) && 'steps' in parsed ? parsed : null;
  } catch (e) {
    return null;
  }
}

// ---- a lesson's step paths: the command line's rule, and the page's own ----
// shadelab's printable() (src/io/text.cpp): control characters, format characters and line separators
// as the \xNN of their UTF-8 bytes.
function printable(text) {
  let out = '';
  for (const ch of text) {
    const code = ch.codePointAt(0);
    const unsafe = code < 0x20 || (code >= 0x7f && code <= 0x9f) || /[\p{Cf}\p{Zl}\p{Zp}]/u.test(ch);
    if (!unsafe) out += ch;
    else for (const b of new TextEncoder().encode(ch)) out += '\\x' + b.toString(16).padStart(2, '0');
  }
  return out;
}

// shadelab's quotedValue(): the first 40 bytes, JSON-quoted, "..." inside the quotes when cut.
function quotedValue(text) {
  const bytes = new TextEncoder().encode(text);
  const shown = JSON.stringify(new TextDecoder().decode(bytes.subarray(0, 40)));
  return bytes.length > 40 ? shown.slice(0, -1) + '..."' : shown;
}

// Why a step's "scene" path cannot be read beside the lesson at `base`, or "". The command line's own
// refusals first, word for word (src/scene/lesson.cpp checkStepPath); then the page's: a path the browser
// would take for another place — a scheme (http:, data:, javascript:), or anything resolving to another
// origin ("\\host", " //host": the URL parser turns \ into / and drops leading spaces) — where the command
// line reads only files beside the lesson.
function stepPathProblem(path, base) {
  if (path === '') return 'must name a scene file, got an empty string';
  if (path.includes('\0'))
    return 'must be a path without a NUL byte, got ' + quotedValue(path) +
           "; name the scene file relative to the lesson's folder";
  if (path === '-')
    return 'must name a scene file relative to the lesson\'s folder, got "-" (standard input is no step\'s ' +
           'scene); write "./-" for a file named -';
  const elsewhere = "must be a path relative to the lesson's folder, got " + quotedValue(path);
  if (path.startsWith('/') || /^[A-Za-z][A-Za-z0-9+.-]*:/.test(path)) return elsewhere;
  if (base === null) return '';
  let url;
  try {
    url = new URL(path, base);
  } catch (e) {
    // A data: or blob: lesson has no folder to resolve a step in.
    return 'the page cannot fetch it beside the lesson, whose URL ' + quotedValue(base) + ' has no folder; ' +
           'open the lesson by its http URL, or pick or drop its scene files together with it';
  }
  return url.origin === new URL(base).origin ? '' : elsewhere;
}

// The scene files a lesson's steps name: {files} (each path as written → its text, or null where it
// could not be fetched, which the C++ then names) or {message} (the command line's form, "NAME:
// steps[i].scene ..."). `source.base` is the URL the steps are relative to (null: none, nothing is
// fetched), `source.given(path)` a text given with the lesson (picked or dropped files) or undefined.
// Every step's path is checked before anything is fetched. Then the steps are walked in order as the C++
// parser walks them (src/scene/lesson.cpp readStep), each distinct file fetched once and at most 16 MiB, and
// fetching stops where the parser will stop: past the 64 MiB of scene text the steps may parse in all (the
// C++ names that step itself, from the files fetched so far).
async function lessonFiles(lesson, name, source) {
  const given = source.given || (() => undefined);
  const steps = Array.isArray(lesson.steps) ? lesson.steps : [];
  const checked = new Set();
  for (let i = 0; i < steps.length; ++i) {
    const path = steps[i] && steps[i].scene;
    if (typeof path !== 'string' || checked.has(path)) continue;
    // A lone surrogate ("\ud800") is refused by the C++ JSON parser, which names it; nothing is fetched.
    const base = given(path) === undefined ? source.base : null;
    const problem = path.isWellFormed() ? stepPathProblem(path, base) : '';
    if (problem) return {message: name + ': steps[' + i + '].scene: ' + problem};
    checked.add(path);
  }
  const utf8Bytes = (text) => new TextEncoder().encode(text).length;
  const files = new Map(); // path → {text, bytes}; text null where it could not be had
  let stepBytes = 0;
  let sceneBytes = 2; // a first step without a scene starts from the defaults, "{}"
  for (let i = 0; i < steps.length; ++i) {
    const step = steps[i];
    if (!step || typeof step !== 'object' || Array.isArray(step)) break; // the C++ refuses this step
    const path = step.scene;
    if (typeof path === 'string') {
      if (!path.isWellFormed()) break;
      if (!files.has(path)) {
        const file = await stepFile(path, source, given);
        if (file.tooLarge)
          return {message: name + ': steps[' + i + '].scene (' + quotedValue(path) + '): ' + tooLargeMessage(path)};
        files.set(path, file);
      }
      if (files.get(path).text === null) break; // the C++ names the step and the file it could not have
      sceneBytes = files.get(path).bytes;
    } else if (path && typeof path === 'object' && !Array.isArray(path)) {
      sceneBytes = utf8Bytes(JSON.stringify(path)); // an inline scene, as nlohmann's dump() counts it
    } else if (path !== undefined) {
      break;
    }
    stepBytes += sceneBytes + utf8Bytes(JSON.stringify(step));
    // JSON.stringify and nlohmann's dump() may write a number differently (1.0 and 1): a MiB of slack, so
    // the C++, not the page, finds the step that passes its bound, with every file before it at hand.
    if (stepBytes > kMaxLessonSceneBytes + kMiB) break;
  }
  const texts = Array.from(files, ([path, file]) => [path, file.text]);
  return {files: Object.fromEntries(texts)}; // own keys: a step named "__proto__" or "constructor" is a file too
}

// A step's file: {text, bytes} ({text: null, bytes: 0} when it cannot be had), or {tooLarge: true}.
async function stepFile(path, source, given) {
  let text = given(path);
  if (text === undefined && source.base !== null) {
    try {
      const got = await fetchBounded(new URL(path, source.base), kMaxSceneBytes);
      if (got.tooLarge) return {tooLarge: true};
      text = got.text;
    } catch (e) {
      text = undefined; // no network, or a URL fetch refuses: the C++ says the page could not fetch it
    }
  }
  if (text === undefined) return {text: null, bytes: 0};
  const bytes = new TextEncoder().encode(text).length;
  return bytes > kMaxSceneBytes ? {tooLarge: true} : {text, bytes};
}

// The last part of a URL for messages, its %-escapes decoded; a % that is no escape stays as it is (a
// URIError here used to stop the page with nothing shown).
function fileNameOf(url) {
  const last = url.split('/').pop() || url;
  try {
    return decodeURIComponent(last);
  } catch (e) {
    return last;
  }
}

// "" or the message, which stays on the page; the previous scene stays drawn behind it. A lesson's scene
// files are read through `source` (lessonFiles says how); without one, none is fetched.
async function loadText(text, name, source = {base: null}) {
  const lesson = lessonOf(text);
  let message;
  if (lesson) {
    const got = await lessonFiles(lesson, name, source);
    message = got.message || api.loadLesson(text, name, got.files);
  } else {
    message = api.loadScene(text, name);
  }
  return showLoadMessage(message);
}

// ---- the canvas: its drawing buffer follows its CSS size and the device pixel ratio ----
function fitCanvas() {
  const canvas = $('canvas');
  const ratio = window.devicePixelRatio || 1;
  const width = Math.max(1, Math.round(canvas.clientWidth * ratio));
  const height = Math.max(1, Math.round(canvas.clientHeight * ratio));
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  if (api) api.redraw();
}
