// The corpus scenes (samples/corpus) as a user sees them in three.js, in Debian's headless
// Chromium: the display file in the stock GLTFLoader (no lights, three.js's defaults) and the engine
// file through the MOZ_lightmap plugin, both from the display file's camera, where a viewer opens it
// (the input's camera, or the one the bake adds: inside the largest room, or in front of an
// object). What is asserted is the exposure: few of the model's pixels
// clip to white, and its median pixel is not near black. Screenshots go to --work (./dev
// corpus-screenshots makes them into docs/corpus/).
// usage: node tests/corpus/three.test.mjs --corpus DIR --bakes DIR --work DIR
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { gltfCamera, openRenderer } from '../../web/render/render.mjs';
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
// Bounds: the share of the model's pixels at 254 or more in some channel: the 2% of what the display
// camera sees that the exposure lets clip, and 1% for what its grid of 128 rays a side does not see
// as the rendered pixels do (bilinear filtering, the pre-lit page's detail); pure white once
// covered 78-81% of the engine. The median pixel's linear luminance: within two stops of the key
// 0.18 (where highlights limit the exposure, the median sits below the key).
// The plugin shows base colour textures at their own resolution, finer than the pre-lit pages the
// meter reads, so their brightest texels clip more: 1% more allowed (the arena: 3.6% against 1.9%).
const MOST_CLIPPED = { stock: 0.03, plugin: 0.04 }, LEAST_MEDIAN = 0.045;

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
      // Where a viewer opens the bake: the display file's camera (the input's, or the one radbake adds).
      const camera = await gltfCamera(path.join(bakes, scene.name, `${scene.name}_display.glb`));
      const r = await renderer.render({ file: path.join(bakes, scene.name, file), mode, camera, width: SIZE, height: SIZE,
        background: BACKGROUND, out });
      assert.deepEqual(r.consoleErrors, [], 'the page logged errors');
      const e = exposureOf(r.image);
      t.diagnostic(`${scene.name} ${mode}: ${e.pixels} model pixels, ${(100 * e.clipped).toFixed(2)}% clipped, median linear luminance ${e.median.toFixed(4)}; ${out}`);
      assert.ok(e.pixels > 0.05 * SIZE * SIZE, `the model covers ${e.pixels} pixels: the camera misses it`);
      assert.ok(e.clipped <= MOST_CLIPPED[mode], `${(100 * e.clipped).toFixed(1)}% of the model's pixels clip`);
      assert.ok(e.median >= LEAST_MEDIAN, `the median pixel's luminance is ${e.median.toFixed(4)}: too dark`);
    });
  }
}
