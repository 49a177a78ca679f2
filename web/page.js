// The page around shadelab.wasm: the canvas size, the keys and the mouse, the control panel as the
// browser's own controls, scene loading (bundled, file picker, drag and drop, ?scene=URL), S as a download,
// and the messages. All state lives in the C++ DemoState (web/main.cpp); the panel shows what
// shadelab_panel() returns (the scene's values and the shown object's material, never all its objects) and
// changes it through the same commands as the keys, or by the edited values handed back as JSON.
'use strict';

const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);
let api = null; // the shadelab_* functions, once the module has started
let tables = null; // the program's flags, levels and key codes (shadelab_tables), once it has started
let saved = 0;

// An error stays until the next action replaces it; a notice (`notice` true: the Esc note) goes after
// four seconds.
let noticeTimer = 0;
function showMessage(text, notice = false) {
  const box = $('message');
  clearTimeout(noticeTimer);
  box.textContent = text;
  box.hidden = !text;
  box.classList.toggle('notice', notice);
  if (notice && text) noticeTimer = setTimeout(() => showMessage(''), 4000);
}

// Called by main.cpp (and below) when the page cannot draw at all.
function shadelabFatal(text) {
  showMessage(text);
  window.shadelab.failed = text;
}

// ---- WebGL 2 first: without it the module is not even loaded ----
function hasWebGl2() {
  try {
    return !!document.createElement('canvas').getContext('webgl2');
  } catch (e) {
    return false;
  }
}

window.shadelab = {ready: false, failed: '', consoleErrors: []};

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
  if (!message) message = applyUrlFlags();
  // ?present (for a class): the presentation label on and larger panel text; ?ui-scale=S scales the panel.
  if (params.has('present')) press(291);
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

// The command-line flags, given as ?shading=flat&size=256x256…, through the CLI's own parser.
function applyUrlFlags() {
  const flags = {};
  for (const name of tables.flags)
    if (params.has(name)) flags[name] = params.get(name);
  return Object.keys(flags).length ? api.applyFlags(JSON.stringify(flags)) : '';
}

async function loadUrl(url, name) {
  let text;
  try {
    const response = await fetch(url);
    if (!response.ok) return url + ': cannot fetch the scene (HTTP ' + response.status + ')';
    text = await response.text();
  } catch (e) {
    return url + ': cannot fetch the scene (' + e.message + ')';
  }
  // A lesson's scene files are fetched beside it, as the command line reads them beside the lesson file.
  const base = new URL(url, location.href);
  return loadText(text, name || fileNameOf(url), (path) => fetchText(new URL(path, base)));
}

// The text at `url`, or null when it cannot be fetched (the lesson parser then names the step and file).
async function fetchText(url) {
  try {
    const response = await fetch(url);
    return response.ok ? await response.text() : null;
  } catch (e) {
    return null;
  }
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

// The scene files a lesson's steps name, each path as written → its text (or null), through `read`.
async function lessonFiles(lesson, read) {
  const files = {};
  for (const step of Array.isArray(lesson.steps) ? lesson.steps : [])
    if (step && typeof step.scene === 'string' && !(step.scene in files)) files[step.scene] = await read(step.scene);
  return files;
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
// files come through `read` (path as the lesson writes it → text or null).
async function loadText(text, name, read = async () => null) {
  const lesson = lessonOf(text);
  const message = lesson ? api.loadLesson(text, name, await lessonFiles(lesson, read)) : api.loadScene(text, name);
  showMessage(message);
  refresh();
  return message;
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

// ---- keys: the window's bindings (GLFW codes: printable keys are their upper-case ASCII; the others from
// the program's table, shadelab_tables) ----
function glfwKey(event) {
  if (event.code in tables.codes) return tables.codes[event.code];
  if (event.key in tables.keys) return tables.keys[event.key];
  if (event.key.length === 1) {
    const code = event.key.toUpperCase().charCodeAt(0);
    if (code > 32 && code < 127) return code;
  }
  return 0;
}

function press(code) {
  const result = api.key(code);
  if (result === 2) save();
  if (result === 3) showMessage('Esc closes the window version; in a browser, close the tab.', true);
  if (result === 4) {
    if (document.fullscreenElement) document.exitFullscreen().catch(() => {});
    else document.documentElement.requestFullscreen().catch(() => {});
  }
  refresh();
  return result;
}

document.addEventListener('keydown', (event) => {
  if (!api || event.ctrlKey || event.metaKey || event.altKey) return;
  if (event.target.closest && event.target.closest('input, select, textarea')) return;
  const code = glfwKey(event);
  if (!code) return;
  if (press(code)) event.preventDefault();
});

// ---- mouse: drag orbits, right-drag (or Shift + drag) moves the light, a click probes, the wheel zooms ----
function wireMouse() {
  const canvas = $('canvas');
  let last = null;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  // Every move and left-button change, in canvas pixels: the profile's row, the split's divider. Sent
  // before the drag, as the window does, so a press on the divider moves it instead of the camera.
  const toPointer = (e, held) => {
    const scale = canvas.width / canvas.clientWidth;
    api.pointer(e.offsetX * scale, e.offsetY * scale, held ? 1 : 0); // main.cpp maps them to the picture
  };
  canvas.addEventListener('pointerdown', (e) => {
    if (e.button === 0) toPointer(e, true);
    if (e.button !== 0 && e.button !== 2) return;
    last = {x: e.clientX, y: e.clientY, light: e.button === 2 || e.shiftKey, travelled: 0,
            downX: e.offsetX, downY: e.offsetY};
    canvas.setPointerCapture(e.pointerId);
    canvas.focus();
  });
  canvas.addEventListener('pointermove', (e) => {
    toPointer(e, last && !last.light);
    if (!last) {
      if (ui && (ui.view === 'profile' || ui.view.startsWith('split:'))) refresh();
      return;
    }
    const dx = e.clientX - last.x, dy = e.clientY - last.y;
    last.travelled += Math.abs(dx) + Math.abs(dy);
    (last.light ? api.dragLight : api.drag)(dx, dy);
    last.x = e.clientX;
    last.y = e.clientY;
    refresh();
  });
  const end = () => { last = null; };
  // A left press and release that moved less than 3 px is a click: probe the point, in canvas pixels.
  canvas.addEventListener('pointerup', (e) => {
    if (e.button === 0) toPointer(e, false);
    if (last && !last.light && last.travelled < 3) {
      const scale = canvas.width / canvas.clientWidth;
      const error = api.probe(last.downX * scale, last.downY * scale);
      if (error) showMessage(error);
      refresh();
    }
  });
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    api.zoom(e.deltaY < 0 ? 1 : -1);
    refresh();
  }, {passive: false});
}

// ---- colours: the scene's linear values shown as #rrggbb (clamped to [0, 1]; no sRGB conversion) ----
const toHex = (c) => '#' + c.map((v) => Math.round(Math.min(Math.max(v, 0), 1) * 255)
                                           .toString(16).padStart(2, '0')).join('');
const fromHex = (hex) => [1, 3, 5].map((i) => parseInt(hex.substr(i, 2), 16) / 255);

let ui = null;
let shownPanel = ''; // the panel's values that refresh last showed, as text

// The panel shows the state; a control changes it by a key's command or by an edited scene. `ifChanged`:
// nothing is written when the values are those shown (a draw error is shown again all the same: it stays
// until an action replaces it).
function refresh(ifChanged = false) {
  if (!api) return;
  const text = api.panelText();
  if (ifChanged && text === shownPanel && !ui.error) return;
  shownPanel = text;
  ui = JSON.parse(text);
  document.title = ui.title;
  $('status').textContent = ui.status;
  // The table keeps its columns (white-space: pre), so the hint is broken into short lines of its own.
  $('probe').textContent = ui.probe ||
      'Click a point of an object: its\nl, n, v and r or h are drawn there,\nand the terms of the current mode\n' +
      'show here beside the exact ones.\nRight-drag (or Shift + drag) moves\nthe light; W shows the mesh.';
  $('renderer').textContent = 'WebGL 2 (OpenGL ES 3.0 to the renderer): ' + ui.renderer;
  $('panel').hidden = !ui.showPanel;
  $('help').hidden = !ui.showHelp;
  $('help-text').textContent = ui.help;
  if (ui.error) showMessage(ui.error);
  const scene = ui.currentSettings;
  setIfIdle('shading', scene.shading);
  setIfIdle('lighting', scene.lighting);
  setIfIdle('term', scene.term);
  setIfIdle('normal-matrix', scene.normal_matrix);
  setIfIdle('perspective-matrix', scene.perspective_matrix);
  $('match').checked = ui.matchHighlight;
  setIfIdle('level', ui.level);
  $('level-out').textContent = ui.level + (ui.autoLevel ? ' (auto)' : '');
  $('auto').checked = ui.autoLevel;
  setIfIdle('projection', ui.orthographic ? 'orthographic' : 'perspective');
  setIfIdle('normals', scene.vertex_normals || 'averaged');
  setIfIdle('overlay', ui.overlay);
  setIfIdle('view-kind', viewName(ui.view));
  // The split option says what is drawn ("split: flat | gouraud"), or what V would draw.
  $('view-kind').querySelector('option[value="split"]').textContent = ui.view.startsWith('split:')
      ? 'split: ' + ui.view.slice(6).replace(',', ' | ') + ' (V)' : 'split: mode | exact (V)';
  // Every warning the command line prints for this scene (a colour given as 0..255, say).
  $('warnings').textContent = ui.warnings.map((w) => 'warning: ' + w).join('\n');
  $('warnings').hidden = !ui.warnings.length;
  // The material of the object the panel edits (the first when all are edited), as the window's panel.
  const material = ui.shownMaterial;
  $('material').hidden = !material;
  if (material) {
    const count = ui.objectCount;
    $('object-row').hidden = count < 2;
    $('object').max = count;
    setIfIdle('object', ui.editedObject);
    $('object-out').textContent = ui.editedObjectName;
    setIfIdle('ka', toHex(material.ambient));
    setIfIdle('kd', toHex(material.diffuse));
    setIfIdle('ks', toHex(material.specular));
    setIfIdle('shininess', Math.log10(material.shininess));
    $('shininess-out').textContent = material.shininess.toFixed(1);
    ['x', 'y', 'z'].forEach((axis, i) => setIfIdle('scale-' + axis, ui.shownScale[i]));
    $('scale-out').textContent = ui.shownScale.map((v) => v.toFixed(2)).join(' ');
  }
  // The view volume as drawn: fovy (perspective) or the window l, r, b, t, and near and far on a log scale.
  const volume = scene.projection;
  $('fovy-row').hidden = volume.type !== 'perspective';
  $('window-row').hidden = volume.type === 'perspective';
  if (volume.type === 'perspective') {
    setIfIdle('fovy', volume.fovy_deg);
    $('fovy-out').textContent = volume.fovy_deg.toFixed(1);
  } else {
    for (const side of ['left', 'right', 'bottom', 'top']) setIfIdle(side, Number(volume[side].toPrecision(4)));
  }
  setIfIdle('near', Math.log10(volume.near));
  setIfIdle('far', Math.log10(volume.far));
  $('near-out').textContent = Number(volume.near.toPrecision(3));
  $('far-out').textContent = Number(volume.far.toPrecision(3));
  $('matrices').textContent = ui.matrices;
  setIfIdle('bands', ui.settings.toon_bands);
  $('bands-out').textContent = ui.settings.toon_bands;
  showLights(ui.settings.lights);
  // The lesson, as the window's panel shows it.
  const lesson = ui.lesson;
  $('lesson').hidden = !lesson;
  if (lesson) {
    $('lesson-title').textContent = lesson.title;
    $('step-out').textContent = 'step ' + lesson.step + ' of ' + lesson.steps;
    $('step-title').textContent = lesson.stepTitle;
    $('step-caption').textContent = lesson.caption;
    $('step-previous').disabled = lesson.step === 1;
    $('step-next').disabled = lesson.step === lesson.steps;
  }
}

// "split:gouraud,exact" is the select's "split".
const viewName = (view) => (view.startsWith('split:') ? 'split' : view);

function setIfIdle(id, value) {
  const element = $(id);
  if (document.activeElement !== element) element.value = value;
}

// The window's light controls (src/app/shells/panel.cpp): position, direction, I_a, I_d, I_s, attenuation a b c,
// and a spot's cutoff and exponent. Rebuilt only when the lights change from outside the panel (L, a scene).
function showLights(lights) {
  const box = $('lights');
  const signature = JSON.stringify(lights);
  if (box.dataset.signature === signature) return;
  box.dataset.signature = signature;
  box.replaceChildren();
  const positional = (l) => l.type === 'point' || l.type === 'spot';
  const directed = (l) => l.type === 'directional' || l.type === 'spot';
  lights.forEach((light, i) => {
    const group = document.createElement('div');
    group.className = 'light';
    group.append(Object.assign(document.createElement('div'), {textContent: 'light ' + (i + 1) + ': ' + light.type}));
    // A range slider shows its number beside it (an <output> that follows the slider as it moves).
    const field = (label, input, change) => {
      input.addEventListener('change', () => edit((s) => change(s.lights[i], input)));
      const row = document.createElement('label');
      row.append(input);
      if (input.type === 'range') {
        const out = Object.assign(document.createElement('output'), {value: input.value});
        input.addEventListener('input', () => { out.value = input.value; });
        row.append(' ', out);
      }
      row.append(' ' + label);
      group.append(row);
    };
    const vector = (label, key, step) => {
      const row = document.createElement('label');
      const inputs = [0, 1, 2].map((k) => Object.assign(document.createElement('input'),
          {type: 'number', step, value: light[key][k], className: 'component'}));
      for (const input of inputs)
        input.addEventListener('change', () => edit((s) => { s.lights[i][key] = inputs.map((x) => Number(x.value)); }));
      row.append(...inputs, ' ' + label);
      group.append(row);
    };
    if (positional(light)) vector('position', 'position', 0.05);
    if (directed(light)) vector('direction', 'direction', 0.02);
    for (const [term, label] of [['ambient', 'I_a ambient'], ['diffuse', 'I_d diffuse'], ['specular', 'I_s specular']]) {
      if (!light[term] || (light.type === 'ambient' && term !== 'ambient')) continue;
      field(label, Object.assign(document.createElement('input'), {type: 'color', value: toHex(light[term])}),
            (l, input) => { l[term] = fromHex(input.value); });
    }
    if (positional(light)) vector('attenuation a b c', 'attenuation', 0.01);
    if (light.type === 'spot') {
      field('cutoff (deg)', Object.assign(document.createElement('input'),
                {type: 'range', min: 0, max: 90, step: 0.5, value: light.cutoff_deg}),
            (l, input) => { l.cutoff_deg = Number(input.value); });
      field('exponent', Object.assign(document.createElement('input'),
                {type: 'range', min: 0, max: 128, step: 1, value: light.exponent || 0}),
            (l, input) => { l.exponent = Number(input.value); });
    }
    box.append(group);
  });
}

// Edits the scene's values (not its objects, not the view) and hands them back; a refused edit shows its
// message.
function edit(change) {
  const settings = api.panel().settings;
  change(settings);
  showMessage(api.editSettings(JSON.stringify(settings)));
  refresh();
}

function pressUntil(code, done, limit = 12) {
  for (let i = 0; i < limit && !done(api.panel()); ++i) press(code);
  refresh();
}

function wireControls() {
  wireMouse();
  const keyOf = {flat: 49, gouraud: 50, phong: 51, toon: 52, exact: 53};
  $('shading').addEventListener('change', (e) => press(keyOf[e.target.value]));
  $('lighting').addEventListener('change', (e) => pressUntil(66, (u) => u.currentSettings.lighting === e.target.value, 1));
  $('term').addEventListener('change', (e) => pressUntil(75, (u) => u.currentSettings.term === e.target.value, 3));
  $('perspective-matrix').addEventListener('change',
      (e) => pressUntil(85, (u) => u.currentSettings.perspective_matrix === e.target.value, 1));
  $('normal-matrix').addEventListener('change',
      (e) => pressUntil(74, (u) => u.currentSettings.normal_matrix === e.target.value, 1));
  $('match').addEventListener('change', (e) => { api.setMatch(e.target.checked ? 1 : 0); refresh(); });
  $('level').addEventListener('input', (e) => {
    const target = Number(e.target.value);
    pressUntil(ui.level < target ? 61 : 45, (u) => u.level === target);
  });
  $('auto').addEventListener('change', (e) => pressUntil(65, (u) => u.autoLevel === e.target.checked, 1));
  // E, V, I, Y and Q each switch their view on (from any other) and off again, as in the window.
  $('view-kind').addEventListener('change', (e) => {
    const keyOf = {error: 69, split: 86, profile: 73, outside: 89, ndc: 81};
    const shown = viewName(ui.view);
    if (e.target.value !== shown) press(keyOf[e.target.value === 'scene' ? shown : e.target.value]);
    refresh();
  });
  $('overlay').addEventListener('change', (e) => pressUntil(87, (u) => u.overlay === e.target.value, 3));
  $('projection').addEventListener('change',
      (e) => pressUntil(79, (u) => u.orthographic === (e.target.value === 'orthographic'), 1));
  $('normals').addEventListener('change',
      (e) => pressUntil(78, (u) => (u.currentSettings.vertex_normals || 'averaged') === e.target.value, 1));
  // The material controls edit the chosen object (0: all objects; a probe click chooses the object it hits).
  const chooseObject = (e) => {
    if (e.target.value === '') return; // the field being retyped
    api.chooseObject(Math.round(Number(e.target.value)));
    refresh();
  };
  $('object').addEventListener('input', chooseObject);
  $('object').addEventListener('change', chooseObject);
  const editMaterial = (change) => {
    showMessage(api.editMaterial(JSON.stringify(change)));
    refresh();
  };
  for (const term of ['ka', 'kd', 'ks']) {
    const field = {ka: 'ambient', kd: 'diffuse', ks: 'specular'}[term];
    $(term).addEventListener('input', (e) => editMaterial({[field]: fromHex(e.target.value)}));
  }
  $('shininess').addEventListener('input', (e) =>
    editMaterial({shininess: Math.round(10 ** Number(e.target.value) * 10) / 10}));
  // The object's scale: x, y, z (an uneven one makes the ellipsoid of the normal-matrix lesson, J).
  for (const axis of ['x', 'y', 'z'])
    $('scale-' + axis).addEventListener('input', () => {
      showMessage(api.editScale(...['x', 'y', 'z'].map((a) => Number($('scale-' + a).value))));
      refresh();
    });
  // The view volume: the drawn projection with the one value changed (DemoState::editViewVolume).
  const editVolume = (change) => {
    const volume = Object.assign({}, ui.currentSettings.projection, change);
    showMessage(api.editViewVolume(JSON.stringify(volume)));
    refresh();
  };
  $('fovy').addEventListener('input', (e) => editVolume({fovy_deg: Number(e.target.value)}));
  for (const side of ['left', 'right', 'bottom', 'top'])
    $(side).addEventListener('change', (e) => editVolume({[side]: Number(e.target.value)}));
  for (const plane of ['near', 'far'])
    $(plane).addEventListener('input', (e) =>
      editVolume({[plane]: Number((10 ** Number(e.target.value)).toPrecision(3))}));
  $('bands').addEventListener('input', (e) => edit((s) => { s.toon_bands = Number(e.target.value); }));
  $('next-material').addEventListener('click', () => press(77));
  $('next-lights').addEventListener('click', () => press(76));
  $('reset').addEventListener('click', () => press(82));
  $('save').addEventListener('click', save);
  $('help-button').addEventListener('click', () => press(72));
  $('bundled').addEventListener('change', (e) => {
    const value = e.target.value;
    if (value.startsWith('lesson:')) loadUrl('lessons/' + value.slice(7), value.slice(7));
    else if (value) loadUrl('scenes/' + value, value);
  });
  // A scene or lesson from files is none of the bundled ones: the picker says so once it has loaded. Of
  // several files, a lesson is opened with the others as the scene files it names (by their names); what
  // it names and was not given is fetched beside the bundled lessons, so a bundled lesson saved and opened
  // again still finds ../scenes/.
  const loadOther = async (files) => {
    const all = Array.from(files || []);
    if (!all.length) return;
    const texts = await Promise.all(all.map((file) => file.text()));
    const index = Math.max(0, texts.findIndex((text) => lessonOf(text)));
    const read = async (path) => {
      const given = all.findIndex((file) => file.name === path.split('/').pop());
      return given >= 0 ? texts[given] : fetchText(new URL(path, new URL('lessons/', location.href)));
    };
    if (!(await loadText(texts[index], all[index].name, read))) $('bundled').value = '';
  };
  $('file').addEventListener('change', (e) => loadOther(e.target.files));
  document.addEventListener('dragover', (e) => e.preventDefault());
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    loadOther(e.dataTransfer.files);
  });
  $('step-previous').addEventListener('click', () => press(266));
  $('step-next').addEventListener('click', () => press(267));
}

// ---- pixels: what the canvas shows, drawn again into the program's own framebuffer ----
// width × height (0 × 0: the scene's image size) → {width, height, rgba} with rows top first: bytes, or
// for kind 'float' the bytes of 32-bit floats (little-endian, as wasm memory holds them).
let kept = null; // the last captureStart's picture

function capture(width, height, kind) {
  const float = kind === 'float';
  const pointer = float ? api.captureFloat(width, height) : api.capture(width, height);
  if (!pointer) throw new Error(api.panel().error || 'capture failed');
  const w = api.captureWidth(), h = api.captureHeight();
  const bytes = w * h * 4 * (float ? 4 : 1);
  return {width: w, height: h, rgba: Module.HEAPU8.slice(pointer, pointer + bytes)};
}

function download(blob, name) {
  const link = document.createElement('a');
  link.href = URL.createObjectURL(blob);
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

// S: the picture (at its size in the canvas, without the bars) as an opaque PNG (as `shadelab render`
// writes it) and the scene that draws it.
function save() {
  const picture = api.panel().picture;
  const shot = capture(picture.width, picture.height);
  for (let i = 3; i < shot.rgba.length; i += 4) shot.rgba[i] = 255;
  const out = document.createElement('canvas');
  out.width = shot.width;
  out.height = shot.height;
  out.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(shot.rgba.buffer), shot.width, shot.height), 0, 0);
  const stem = 'shadelab-' + String(++saved).padStart(3, '0');
  const scene = api.ui().current;
  download(new Blob([JSON.stringify(scene, null, 2) + '\n'], {type: 'application/json'}), stem + '.json');
  out.toBlob((blob) => download(blob, stem + '.png'), 'image/png');
}

// For scripts/web.sh render and the browser tests (tests/web/): the same calls the panel makes.
Object.assign(window.shadelab, {
  loadText: (text, name) => loadText(text, name),
  applyFlags: (flags) => { const m = api.applyFlags(JSON.stringify(flags)); showMessage(m); refresh(); return m; },
  press: (code) => press(code),
  ui: () => api.ui(),
  tables: () => tables,
  message: () => ($('message').hidden ? '' : $('message').textContent),
  // A capture read back in bands (web/driver.py): captureStart draws it and keeps it, captureRows gives
  // rows [y, y + count) as base64, so no one call carries hundreds of megabytes.
  captureStart: (width, height, kind) => {
    kept = capture(width, height, kind);
    return {width: kept.width, height: kept.height, rowBytes: kept.rgba.length / Math.max(1, kept.height)};
  },
  captureRows: (y, count) => {
    const rowBytes = kept.rgba.length / kept.height;
    const band = kept.rgba.subarray(y * rowBytes, (y + count) * rowBytes);
    let binary = '';
    for (let i = 0; i < band.length; i += 0x8000)
      binary += String.fromCharCode.apply(null, band.subarray(i, i + 0x8000));
    return btoa(binary);
  },
});
