// The corpus scenes (samples/corpus) as a user sees them in three.js, in Debian's headless
// Chromium: the display file in the stock GLTFLoader (no lights, three.js's defaults) and the engine
// file through the MOZ_lightmap plugin, from where corpus.json says a person would look (inside the
// house's largest room), else from outside the model (from the south-west, 30 degrees up, the
// bounding sphere filling the view). What is asserted is the exposure: few of the model's pixels
// clip to white, and its median pixel is not near black. Screenshots go to --work (./dev
// corpus-screenshots copies them into docs/corpus/).
// usage: node tests/corpus/three.test.mjs --corpus DIR --bakes DIR --work DIR
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { openRenderer } from '../../web/render/render.mjs';
import { pixelToLinear } from '../../web/render/expect.mjs';

function option(name) {
  const i = process.argv.indexOf(name);
  if (i < 0 || i + 1 >= process.argv.length) throw new Error(`usage: three.test.mjs --corpus DIR --bakes DIR --work DIR (no ${name})`);
  return process.argv[i + 1];
}
const corpus = option('--corpus'), bakes = option('--bakes'), work = option('--work');
mkdirSync(work, { recursive: true });
const scenes = JSON.parse(readFileSync(path.join(corpus, 'corpus.json'), 'utf8')).scenes;

const SIZE = 256;
const BACKGROUND = [1, 0, 1]; // magenta: no baked surface of the corpus shows it
// Bounds: the share of the model's pixels at 254 or more in some channel (pure white was 78-81% of
// the engine before issue 29); the median pixel's linear luminance at least 0.01 (about sRGB 25:
// a scene exposed for its highlights alone would sit there or below).
const MOST_CLIPPED = 0.05, LEAST_MEDIAN = 0.01;

function cameraFor(scene) {
  if (scene.eye) return { ...scene.eye, near: 0.05, far: 1000 };
  const { min, max } = scene.bounds_m;
  const centre = min.map((v, i) => (v + max[i]) / 2);
  const radius = Math.hypot(...max.map((v, i) => v - min[i])) / 2;
  const fov = 40, distance = radius / Math.sin(((fov / 2) * Math.PI) / 180);
  const elevation = (30 * Math.PI) / 180, azimuth = (225 * Math.PI) / 180; // from north (-Z) through east (+X)
  const dir = [Math.sin(azimuth) * Math.cos(elevation), Math.sin(elevation), -Math.cos(azimuth) * Math.cos(elevation)];
  return { position: centre.map((v, i) => v + dir[i] * distance), target: centre, fov, near: distance / 100, far: distance * 3 };
}

function exposureOf(image) {
  const lum = [];
  let clipped = 0;
  for (let i = 0; i < image.width * image.height; i++) {
    const [r, g, b] = image.rgba.subarray(4 * i, 4 * i + 3);
    if (r === 255 && g === 0 && b === 255) continue;
    if (Math.max(r, g, b) >= 254) clipped++;
    const [lr, lg, lb] = pixelToLinear([r, g, b]);
    lum.push(0.2126 * lr + 0.7152 * lg + 0.0722 * lb);
  }
  lum.sort((a, b) => a - b);
  return { pixels: lum.length, clipped: clipped / Math.max(lum.length, 1), median: lum.length ? lum[lum.length >> 1] : 0 };
}

let renderer;
before(async () => { renderer = await openRenderer(); });
after(async () => { if (renderer) await renderer.close(); });

for (const scene of scenes) {
  for (const [mode, file] of [['stock', `${scene.name}_display.glb`], ['plugin', `${scene.name}.gltf`]]) {
    test(`${scene.name}, ${mode === 'stock' ? 'display file, stock GLTFLoader' : 'engine file, MOZ_lightmap plugin'}`, async (t) => {
      const out = path.join(work, `${scene.name}_${mode}.png`);
      const r = await renderer.render({ file: path.join(bakes, scene.name, file), mode, camera: cameraFor(scene), width: SIZE, height: SIZE,
        background: BACKGROUND, out });
      assert.deepEqual(r.consoleErrors, [], 'the page logged errors');
      const e = exposureOf(r.image);
      t.diagnostic(`${scene.name} ${mode}: ${e.pixels} model pixels, ${(100 * e.clipped).toFixed(2)}% clipped, median linear luminance ${e.median.toFixed(4)}; ${out}`);
      assert.ok(e.pixels > 0.05 * SIZE * SIZE, `the model covers ${e.pixels} pixels: the camera misses it`);
      assert.ok(e.clipped <= MOST_CLIPPED, `${(100 * e.clipped).toFixed(1)}% of the model's pixels clip`);
      assert.ok(e.median >= LEAST_MEDIAN, `the median pixel's luminance is ${e.median.toFixed(4)}: too dark`);
    });
  }
}
