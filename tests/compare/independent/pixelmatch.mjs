// pixelmatch itself, the independent implementation tests/compare/perceptual_test.cpp holds shadelab's
// perceptual delta to:
//   node pixelmatch.mjs ACTUAL.png EXPECTED.png THRESHOLD
// prints "differing=N", pixelmatch's return value (includeAA false, its defaults otherwise). The file names
// are data: they are only opened. The packages are the ones package-lock.json pins (install.sh).
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
const differing = pixelmatch(actual.data, expected.data, null, actual.width, actual.height, {threshold});
console.log(`differing=${differing}`);
