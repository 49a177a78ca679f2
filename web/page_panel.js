// The control panel: the program's values shown as the browser's own controls, and the edits they make
// (page_core.js says the order of the page's scripts).
'use strict';

// ---- colours: the scene's linear values shown as #rrggbb (clamped to [0, 1]; no sRGB conversion) ----
const toHex = (c) => '#' + c.map((v) => Math.round(Math.min(Math.max(v, 0), 1) * 255)
                                           .toString(16).padStart(2, '0')).join('');
const fromHex = (hex) => [1, 3, 5].map((i) => parseInt(hex.substr(i, 2), 16) / 255);

let ui = null;
let shownPanel = ''; // the panel's values that refresh last showed, as text

// The panel shows the state; a control sets one value (set). `ifChanged`:
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
  $('seeing').textContent = ui.seeing; // what is drawn, in which space, the formula (view_explanations.h)
  // The table keeps its columns (white-space: pre), so the hint is broken into short lines of its own.
  $('probe').textContent = ui.probe ||
      'Click a point of an object: its\nl, n, v and r or h are drawn there,\nand the terms of the current mode\n' +
      'show here beside the exact ones.\nRight-drag (or Shift + drag) moves\nthe light; W shows the mesh.';
  $('renderer').textContent = 'WebGL 2 (OpenGL ES 3.0 to the renderer): ' + ui.renderer;
  $('panel').hidden = !ui.showPanel;
  $('help').hidden = !ui.showHelp;
  $('help-text').textContent = ui.help;
  $('view-help').textContent = ui.viewHelp;
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
  // The shape of the object the panel edits (a model file's name for a mesh object, which no shape names).
  $('object-box').hidden = !ui.objectCount;
  setIfIdle('shape', ui.shownShape === 'mesh' ? '' : ui.shownShape);
  $('shape-out').textContent = ui.shownShape === 'mesh' ? 'mesh: ' + ui.shownMesh : '';
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
    const name = (key) => 'lights[' + i + '].' + key;
    const field = (label, input, key, value) => {
      input.addEventListener('change', () => set(name(key), value(input)));
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
        input.addEventListener('change', () => set(name(key), inputs.map((x) => x.value).join(' ')));
      row.append(...inputs, ' ' + label);
      group.append(row);
    };
    if (positional(light)) vector('position', 'position', 0.05);
    if (directed(light)) vector('direction', 'direction', 0.02);
    for (const [term, label] of [['ambient', 'I_a ambient'], ['diffuse', 'I_d diffuse'], ['specular', 'I_s specular']]) {
      if (!light[term] || (light.type === 'ambient' && term !== 'ambient')) continue;
      field(label, Object.assign(document.createElement('input'), {type: 'color', value: toHex(light[term])}),
            term, (input) => fromHex(input.value).join(' '));
    }
    if (positional(light)) vector('attenuation a b c', 'attenuation', 0.01);
    if (light.type === 'spot') {
      field('cutoff (deg)', Object.assign(document.createElement('input'),
                {type: 'range', min: 0, max: 90, step: 0.5, value: light.cutoff_deg}),
            'cutoff_deg', (input) => input.value);
      field('exponent', Object.assign(document.createElement('input'),
                {type: 'range', min: 0, max: 128, step: 1, value: light.exponent || 0}),
            'exponent', (input) => input.value);
    }
    box.append(group);
  });
}

// Sets one value through the setter every panel shares (src/app/demo/scene_setters.h: the window's panel
// calls the same); a refused value shows the check's message, as a scene file's would.
function set(name, value) {
  showMessage(api.set(name, value));
  refresh();
}

function wireControls() {
  wireMouse();
  // Each control sets its value by name; the keys (1-5, B, K, U, J, +, -, A, E, V, I, Y, Q, W, O, N) set the
  // same values through their commands.
  const selects = {shading: 'shading', lighting: 'lighting', term: 'term', 'perspective-matrix': 'perspective_matrix',
                   'normal-matrix': 'normal_matrix', 'view-kind': 'view', overlay: 'overlay', projection: 'projection',
                   normals: 'vertex_normals'};
  for (const [id, name] of Object.entries(selects))
    $(id).addEventListener('change', (e) => set(name, e.target.value));
  $('match').addEventListener('change', (e) => set('match_highlight', e.target.checked));
  // The chosen object's shape (the shape menu and its key set the same value), or a model from files.
  $('shape').addEventListener('change', (e) => set('shape', e.target.value));
  $('model-file').addEventListener('change', async (e) => {
    await loadModelFiles(e.target.files);
    e.target.value = ''; // the same files picked again load again
  });
  $('level').addEventListener('input', (e) => set('level', e.target.value));
  $('auto').addEventListener('change', (e) => set('auto_level', e.target.checked));
  // The material controls edit the chosen object (0: all objects; a probe click chooses the object it hits).
  const chooseObject = (e) => {
    if (e.target.value === '') return; // the field being retyped
    set('object', Math.round(Number(e.target.value)));
  };
  $('object').addEventListener('input', chooseObject);
  $('object').addEventListener('change', chooseObject);
  for (const [id, term] of [['ka', 'ambient'], ['kd', 'diffuse'], ['ks', 'specular']])
    $(id).addEventListener('input', (e) => set('material.' + term, fromHex(e.target.value).join(' ')));
  $('shininess').addEventListener('input', (e) =>
    set('material.shininess', Math.round(10 ** Number(e.target.value) * 10) / 10));
  // The object's scale: x, y, z (an uneven one makes the ellipsoid of the normal-matrix lesson, J).
  for (const axis of ['x', 'y', 'z'])
    $('scale-' + axis).addEventListener('input', () => set('scale', ['x', 'y', 'z'].map((a) => $('scale-' + a).value).join(' ')));
  // The view volume: the drawn projection with the one value changed (DemoState::editViewVolume).
  $('fovy').addEventListener('input', (e) => set('projection.fovy_deg', e.target.value));
  for (const side of ['left', 'right', 'bottom', 'top'])
    $(side).addEventListener('change', (e) => set('projection.' + side, e.target.value));
  for (const plane of ['near', 'far'])
    $(plane).addEventListener('input', (e) => set('projection.' + plane, (10 ** Number(e.target.value)).toPrecision(3)));
  $('bands').addEventListener('input', (e) => set('toon_bands', e.target.value));
  $('next-material').addEventListener('click', () => press(asciiKey('M')));
  $('next-lights').addEventListener('click', () => press(asciiKey('L')));
  $('reset').addEventListener('click', () => press(asciiKey('R')));
  $('save').addEventListener('click', save);
  $('help-button').addEventListener('click', () => press(asciiKey('H')));
  $('bundled').addEventListener('change', (e) => {
    const value = e.target.value;
    if (value.startsWith('lesson:')) loadUrl('lessons/' + value.slice(7), value.slice(7));
    else if (value.startsWith('own:')) loadUrl(kOwnLessons + encodeURIComponent(value.slice(4)), value.slice(4));
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
    const given = (path) => {
      const found = all.findIndex((file) => file.name === path.split('/').pop());
      return found >= 0 ? texts[found] : undefined;
    };
    const source = {base: new URL('lessons/', location.href).href, given};
    if (!(await loadText(texts[index], all[index].name, source))) $('bundled').value = '';
  };
  $('file').addEventListener('change', (e) => (holdsModel(e.target.files) ? loadModelFiles : loadOther)(e.target.files));
  document.addEventListener('dragover', (e) => e.preventDefault());
  // A drop holding a model file (.obj, .gltf, .glb) is a model with its files; any other, a scene or lesson.
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    const files = e.dataTransfer.files;
    if (holdsModel(files)) loadModelFiles(files);
    else loadOther(files);
  });
  $('step-previous').addEventListener('click', () => press(tables.keys.PageUp));
  $('step-next').addEventListener('click', () => press(tables.keys.PageDown));
}
