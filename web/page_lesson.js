// A lesson's scene files as the page reads them, held to the command line's rules (docs/students.md "In the browser"):
// fetches bounded in size and time, and every step's path checked before any request. Loaded before page.js,
// which calls lessonFiles, fetchBounded and tooLargeMessage; shares the page's one global scope.
'use strict';

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

