// Pixels (a capture drawn again into the program's own framebuffer), S as a download, and the calls the
// browser tests and web/driver.py make (page_core.js says the order of the page's scripts).
'use strict';

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
  loadUrl: (url, name) => loadUrl(url, name),
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
