// The page around shadelab.wasm, in eight classic scripts that share one global scope, loaded in this order
// by index.html: page_core.js (the shared state and the message line), page_input.js (keys and mouse),
// page_menus.js (the panel's menus from the program's tables), page_model.js (model files and the shape),
// page_panel.js (the control panel), page_capture.js (pixels, S, and the calls the tests and web/driver.py
// make), page_lesson.js (a lesson's files: bounded fetches, step paths checked first), and page.js (the
// module's start and scene loading), which loads shadelab.js last.
// All state lives in the C++ DemoState (web/main.cpp, web/panel.cpp); the panel shows what shadelab_panel()
// returns (the scene's values and the shown object's material, never all its objects) and changes it
// through the same commands as the keys, or by the edited values handed back as JSON.
'use strict';

const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);
let api = null; // the shadelab_* functions, once the module has started
// The program's flags, levels, key codes and menus (shadelab_tables), once it has started: page.js sets
// `tables`, and the menus are filled from them then (page_menus.js), before the panel shows a value.
let programTables = null;
Object.defineProperty(globalThis, 'tables', {
  get: () => programTables,
  set: (value) => {
    programTables = value;
    fillMenus(value.menus);
  },
});
let saved = 0;
// Where scripts/web.sh serve --lessons DIR serves that folder (web/serve.py kOwnLessons).
const kOwnLessons = 'own-lessons/';

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

window.shadelab = {ready: false, failed: '', consoleErrors: []};
