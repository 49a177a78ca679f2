// pixelmatch itself, the independent implementation tests/compare/perceptual_test.cpp holds shadelab's
// perceptual delta to:
//   node pixelmatch.mjs ACTUAL.png EXPECTED.png THRESHOLD
// prints "differing=N", pixelmatch's return value (includeAA false, its defaults otherwise), then
// "map=" and one digit per pixel in reading order, read back from pixelmatch's own diff output: 2 where
// it drew a differing pixel (diffColor, red), 1 where it drew an anti-aliased one (aaColor, yellow), 0
// elsewhere (it draws those grey, r = g = b, which neither colour is). The file names are data: they are
// only opened. The packages are the ones package-lock.json pins (install.sh).
import fs from 'node:fs';
import pixelmatch from 'pixelmatch';
import {PNG} from 'pngjs';

if (process.argv.length !== 5) {
    console.error('usage: node pixelmatch.mjs ACTUAL.png EXPECTED.png THRESHOLD');
    process.exit(2);
}
const [actualPath, expectedPath, thresholdText] = process.argv.slice(2);
const actual = PNG.sync.read(fs.readFileSync(actualPath));
const expected = PNG.sync.read(fs.readFileSync(expectedPath));
const threshold = Number(thresholdText);
if (!(threshold >= 0 && threshold <= 1)) {
    console.error(`THRESHOLD must be 0..1, got ${thresholdText}`);
    process.exit(2);
}
const output = new Uint8Array(actual.data.length);
const differing = pixelmatch(actual.data, expected.data, output, actual.width, actual.height, {threshold});
const marks = [];
for (let pos = 0; pos < output.length; pos += 4) {
    const [r, g, b] = output.subarray(pos, pos + 3);
    marks.push(r === 255 && g === 0 && b === 0 ? '2' : r === 255 && g === 255 && b === 0 ? '1' : '0');
}
console.log(`differing=${differing}`);
console.log(`map=${marks.join('')}`);
