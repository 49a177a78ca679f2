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
  const setValue = c('shadelab_set', 'string', ['string', 'string']);
  const model = c('shadelab_load_model', 'string', ['string']);
  return {
    loadScene: (text, name) => viaHeap(text, (pointer) => load(pointer, name)),
    loadLesson: (text, name, files) =>
      viaHeap(text, (pointer) => viaHeap(JSON.stringify(files), (filesPointer) => lesson(pointer, name, filesPointer))),
    applyFlags: (text) => viaHeap(text, flags),
    // Every control's value through the setter the window's panel uses (src/app/demo/scene_setters.h):
    // set('lighting', 'phong'), set('lights[0].cutoff_deg', '20'); '' or the refusal.
    set: (name, value) => setValue(name, String(value)),
    // The files' places in the heap as JSON, the model's main file first (page_model.js); '' or the message.
    loadModel: (files) => model(files),
    key: c('shadelab_key', 'number', ['number']),
    drag: c('shadelab_drag', null, ['number', 'number']),
    zoom: c('shadelab_zoom', null, ['number']),
    dragLight: c('shadelab_drag_light', null, ['number', 'number']),
    probe: c('shadelab_probe', 'string', ['number', 'number']),
    pointer: c('shadelab_pointer', null, ['number', 'number', 'number']),
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
  const own = await ownLessons();
  $('bundled').add(new Option('(another scene)', ''));
  for (const name of names) $('bundled').add(new Option(name, name));
  // The bundled lessons after the scenes, each as "lesson: NAME", then the lecturer's own (scripts/web.sh
  // serve --lessons DIR) as "own lesson: NAME". An option's text is text, never markup.
  for (const name of lessons) $('bundled').add(new Option('lesson: ' + name, 'lesson:' + name));
  for (const name of own) $('bundled').add(new Option('own lesson: ' + printable(name), 'own:' + name));
  const url = params.get('scene');
  const lessonUrl = params.get('lesson');
  let message = '';
  try {
    message = await loadStartingScene(url, lessonUrl, names, lessons, own);
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
  // The keys go to the picture from the start: the first click on it probes (a click that takes the keys
  // back from the panel only focuses it, page_input.js).
  $('canvas').focus({preventScroll: true});
  window.shadelab.ready = true;
  // The title's frame time, and what changed without a control (a draw error): twice a second, and only
  // when the panel's values changed, since rewriting unchanged text still repaints the page (an idle page
  // took 12 % of a core in headless Chromium doing that).
  setInterval(() => refresh(true), 500);
}

// The lessons of the folder `scripts/web.sh serve --lessons DIR` serves under own-lessons/ (web/serve.py
// lists them): names of files in that folder, each a plain name; [] when there is no such folder, or
// when the list is not one.
async function ownLessons() {
  const list = await fetch(kOwnLessons + 'index.json').then((r) => (r.ok ? r.json() : [])).catch(() => []);
  const plain = (name) => typeof name === 'string' && name.isWellFormed() && name !== '' &&
                          !name.includes('/') && !name.includes('\\') && !name.startsWith('.');
  return Array.isArray(list) ? list.filter(plain) : [];
}

// The scene or lesson the page opens with (?lesson=URL, ?scene=URL or the showcase), the picker set to it.
async function loadStartingScene(url, lessonUrl, names, lessons, own) {
  let message = '';
  if (lessonUrl) {
    message = await loadUrl(lessonUrl);
    const bundled = lessons.find((name) => lessonUrl === 'lessons/' + name || lessonUrl === './lessons/' + name);
    const mine = own.find((name) => lessonUrl === kOwnLessons + encodeURIComponent(name));
    $('bundled').value = bundled ? 'lesson:' + bundled : mine ? 'own:' + mine : '';
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

// ---- scenes and lessons from URLs (their bounded fetches and step paths: page_lesson.js) ----
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
