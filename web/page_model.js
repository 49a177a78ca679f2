// Models from files: a .obj, .gltf or .glb picked with the model input or dropped on the page, with the
// files it names (an OBJ's MTL, a glTF's .bin buffers) picked or dropped together with it; the chosen object
// becomes a mesh object of it (web/model_drop.cpp). The shape menu switches the chosen object between the
// sphere and the teapot through the setter every panel uses (page_panel.js). page_core.js says the order of
// the page's scripts.
'use strict';

// The files the loader reads a model from (scene/model.h loadModel: by the extension).
const kModelExtensions = ['.obj', '.gltf', '.glb'];
const extensionOf = (name) => {
  const dot = name.lastIndexOf('.');
  return dot < 0 ? '' : name.slice(dot).toLowerCase();
};
const isModelFile = (file) => kModelExtensions.includes(extensionOf(file.name));

// Whether a pick or a drop is a model rather than a scene or a lesson: one of its files is a model file.
const holdsModel = (files) => Array.from(files || []).some(isModelFile);

// Each file's bytes copied into the heap for the call, freed after it whatever happens; '' or the message.
function withFilesInHeap(files, buffers, call) {
  const placed = [];
  try {
    for (let i = 0; i < files.length; ++i) {
      const bytes = new Uint8Array(buffers[i]);
      let pointer = 0;
      try {
        pointer = Module._malloc(Math.max(1, bytes.length));
      } catch (e) {
        pointer = 0;
      }
      if (!pointer) return printable(files[i].name) + ': the page has no memory for its ' + bytes.length + ' bytes';
      Module.HEAPU8.set(bytes, pointer); // HEAPU8 read after malloc: a growing heap replaces it
      placed.push({name: files[i].name, pointer, size: bytes.length});
    }
    return call(JSON.stringify(placed));
  } finally {
    for (const file of placed) Module._free(file.pointer);
  }
}

// The model file of `files` (exactly one) with the others beside it; the message shows on the page's
// error line, and a refused model leaves the scene as it was.
async function loadModelFiles(files) {
  const all = Array.from(files || []);
  const models = all.filter(isModelFile);
  let message = '';
  if (models.length === 1) message = await loadModel(models[0], all);
  else message = 'pick or drop one model file (.obj, .gltf or .glb) with its .mtl or .bin files; got ' +
                 (models.length ? models.map((f) => printable(f.name)).join(', ') : 'none');
  showMessage(message);
  refresh();
  ++window.shadelab.modelLoads; // what web/driver.py waits for after a drop or a pick
  return message;
}

window.shadelab.modelLoads = 0;

// `model` read with the other files of `all` beside it; '' or the message.
async function loadModel(model, all) {
  const ordered = [model].concat(all.filter((file) => file !== model));
  try {
    const buffers = await Promise.all(ordered.map((file) => file.arrayBuffer()));
    return withFilesInHeap(ordered, buffers, api.loadModel);
  } catch (e) {
    return printable(model.name) + ': cannot read the file (' + e.message + ')';
  }
}
