// Keys and mouse: the window's bindings and gestures, through the same commands (page_core.js says the
// order of the page's scripts).
'use strict';

// ---- keys: the window's bindings (GLFW codes: printable keys are their upper-case ASCII; the others from
// the program's table, shadelab_tables) ----
// A printable key's GLFW code: its upper-case ASCII (what the window's bindings name, demo_keys.cpp).
const asciiKey = (letter) => letter.toUpperCase().charCodeAt(0);

function glfwKey(event) {
  if (event.code in tables.codes) return tables.codes[event.code];
  if (event.key in tables.keys) return tables.keys[event.key];
  if (event.key.length === 1) {
    const code = asciiKey(event.key);
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

// ---- mouse and touch: a drag orbits, right-drag (or Shift + drag) moves the light, a click or a tap
// probes, the wheel or a two-finger pinch zooms ----
// A pinch's zoom follows the fingers: spread to twice the distance, and the picture is twice as large
// (DemoState::zoom scales the distance by 0.9 per step).
const pinchSteps = (ratio) => Math.log(ratio) / -Math.log(0.9);

function wireMouse() {
  const canvas = $('canvas');
  let last = null;
  const fingers = new Map(); // pointerId → {x, y}: the touches on the canvas
  let pinch = null; // {distance} while two fingers are down; until the last lifts, no orbit and no tap
  const spread = () => {
    const [a, b] = Array.from(fingers.values());
    return Math.hypot(a.x - b.x, a.y - b.y);
  };
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  // Every move and left-button change, in canvas pixels: the profile's row, the split's divider. Sent
  // before the drag, as the window does, so a press on the divider moves it instead of the camera.
  const toPointer = (e, held) => {
    const scale = canvas.width / canvas.clientWidth;
    api.pointer(e.offsetX * scale, e.offsetY * scale, held ? 1 : 0); // main.cpp maps them to the picture
  };
  canvas.addEventListener('pointerdown', (e) => {
    if (e.pointerType === 'touch') {
      fingers.set(e.pointerId, {x: e.clientX, y: e.clientY});
      if (fingers.size >= 2 || pinch) {
        if (fingers.size === 2) pinch = {distance: spread()};
        last = null;
        return;
      }
    }
    if (e.button === 0) toPointer(e, true);
    if (e.button !== 0 && e.button !== 2) return;
    // A mouse click that takes the keys back from the panel only focuses the canvas: no probe (a tap has
    // no keys to take back, and probes).
    const focusing = e.pointerType === 'mouse' && document.activeElement !== canvas;
    last = {x: e.clientX, y: e.clientY, light: e.button === 2 || e.shiftKey, travelled: 0,
            downX: e.offsetX, downY: e.offsetY, focusing, slack: e.pointerType === 'touch' ? 10 : 3};
    canvas.setPointerCapture(e.pointerId);
    canvas.focus({preventScroll: true});
  });
  canvas.addEventListener('pointermove', (e) => {
    if (fingers.has(e.pointerId)) fingers.set(e.pointerId, {x: e.clientX, y: e.clientY});
    if (pinch) {
      if (fingers.size === 2) {
        const distance = spread();
        if (distance > 0 && pinch.distance > 0) api.zoom(pinchSteps(distance / pinch.distance));
        pinch.distance = distance;
        refresh();
      }
      return;
    }
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
  const end = (e) => {
    last = null;
    fingers.delete(e.pointerId);
    if (!fingers.size) pinch = null;
  };
  // A left press and release that moved less than 3 px (a finger: 10 px) is a click: probe the point, in
  // canvas pixels.
  canvas.addEventListener('pointerup', (e) => {
    if (e.button === 0 && !pinch) toPointer(e, false);
    if (last && !last.light && !last.focusing && last.travelled < last.slack) {
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
